//! Random self-affine (fractal) rough surfaces on a periodic grid, by Fourier synthesis
//! with random phases.
//!
//! # Model
//! The isotropic power spectrum of a self-affine surface with Hurst exponent `H`
//! (`0 < H < 1`, fractal dimension `D = 3 - H`) is, in the usual form of Persson (2006)
//! and Jacobs, Junge and Pastewka (2017),
//!
//! $$C(q) = C_0 \begin{cases} 1 & q_L \le q < q_r \\ (q/q_r)^{-2(1+H)} & q_r \le q \le q_s \\
//!   0 & \text{otherwise} \end{cases}$$
//!
//! with the wavenumbers `q = 2π/λ` of the long-wavelength cut-off `λ_L` (at most the
//! grid's size), the roll-off `λ_r` (`λ_s < λ_r <= λ_L`; `λ_r = λ_L`: no plateau) and the
//! short-wavelength cut-off `λ_s` (at least two cells). Each Fourier mode `k` of the
//! periodic grid gets the amplitude `sqrt(C(|q_k|))` and a phase uniform in `[0, 2π)`
//! drawn from a ChaCha8 generator seeded with `seed`, with the Hermitian symmetry that
//! makes the heights real; an inverse FFT gives the heights. `C_0` is then fixed by the
//! requested rms height or rms slope, both computed from the spectrum (exact for the
//! band-limited periodic surface: `h_rms² = Σ|h_k|²`, `h'_rms² = Σ q_k²|h_k|²`, Parseval).
//!
//! Because the amplitudes are not random, every realisation has the target spectrum
//! exactly, mode by mode; the heights are Gaussian only in the limit of many modes (by the
//! central limit theorem). The mean height is zero.
//!
//! # Units
//! mm for lengths and heights, rms slope dimensionless.
//!
//! # References
//! - Persson, Albohr, Tartaglino, Volokitin and Tosatti (2005), J. Phys.: Condens. Matter
//!   17, R1-R62 (the spectrum and Fourier synthesis).
//! - Jacobs, Junge and Pastewka (2017), Surf. Topogr.: Metrol. Prop. 5, 013001.

use crate::error::{Error, Result};
use crate::gap::{GapMap, MapKind};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use realfft::RealFftPlanner;
use rustfft::FftPlanner;
use rustfft::num_complex::Complex64;
use std::f64::consts::PI;

/// How the amplitude of a [`SelfAffineSpec`] is fixed.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Amplitude {
    /// Root-mean-square height \[mm\], > 0.
    RmsHeight(f64),
    /// Root-mean-square slope \[-\], > 0.
    RmsSlope(f64),
}

/// The parameters of a random self-affine surface (module docs). Lengths in mm.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
pub struct SelfAffineSpec {
    /// Grid points `[nx, ny]`, each 4..=16384 and even.
    pub points: [usize; 2],
    /// Size of the periodic cell `[Lx, Ly]` \[mm\], > 0.
    pub size: [f64; 2],
    /// Hurst exponent `H`, `0 < H < 1`.
    pub hurst: f64,
    /// Long-wavelength cut-off `λ_L` \[mm\], `<= max(Lx, Ly)`.
    pub long_cutoff: f64,
    /// Roll-off wavelength `λ_r` \[mm\], `λ_s < λ_r <= λ_L` (`λ_L`: no plateau).
    pub rolloff: f64,
    /// Short-wavelength cut-off `λ_s` \[mm\], at least two cells: `>= 2 max(dx, dy)`.
    pub short_cutoff: f64,
    /// The rms height or rms slope.
    pub amplitude: Amplitude,
    /// Seed of the random phases: the same seed gives the same surface on every platform.
    pub seed: u64,
}

/// A generated surface: heights on the periodic grid \[mm\], row-major with `x` fastest.
#[derive(Debug, Clone, PartialEq)]
pub struct SelfAffineSurface {
    /// Grid points `[nx, ny]`.
    pub points: [usize; 2],
    /// Cell size `[dx, dy]` \[mm\].
    pub spacing: [f64; 2],
    /// Heights \[mm\], `nx·ny` of them, mean zero.
    pub heights: Vec<f64>,
    /// Rms height \[mm\] (spectral, equal to the heights' rms to rounding).
    pub rms_height: f64,
    /// Rms slope \[-\] (spectral: of the band-limited periodic surface).
    pub rms_slope: f64,
}

impl SelfAffineSurface {
    /// The surface as a height map for the half-space solver (its gap is `max(z) - z`).
    ///
    /// # Errors
    /// None for a generated surface (the map's checks pass); kept as a `Result` because
    /// [`GapMap::new`] checks its input.
    pub fn height_map(&self) -> Result<GapMap> {
        GapMap::new(
            self.points[0],
            self.points[1],
            self.spacing,
            self.heights.clone(),
            MapKind::Height,
        )
    }
}

impl SelfAffineSpec {
    /// Check every parameter.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `points`, `size`, `hurst`, `long_cutoff`, `rolloff`,
    /// `short_cutoff` or `amplitude` with the valid range.
    pub fn validate(&self) -> Result<()> {
        for (i, &n) in self.points.iter().enumerate() {
            if !(4..=16_384).contains(&n) || n % 2 != 0 {
                return Err(Error::invalid(
                    if i == 0 { "points[0]" } else { "points[1]" },
                    n,
                    "an even number of grid points, 4..=16384",
                ));
            }
        }
        for (i, &l) in self.size.iter().enumerate() {
            if !(l.is_finite() && l > 0.0) {
                return Err(Error::invalid(
                    if i == 0 { "size[0]" } else { "size[1]" },
                    l,
                    "a finite size > 0 mm",
                ));
            }
        }
        if !(self.hurst > 0.0 && self.hurst < 1.0) {
            return Err(Error::invalid(
                "hurst",
                self.hurst,
                "0 < H < 1 (self-affine surfaces)",
            ));
        }
        let lmax = self.size[0].max(self.size[1]);
        if !(self.long_cutoff.is_finite() && self.long_cutoff > 0.0 && self.long_cutoff <= lmax) {
            return Err(Error::invalid(
                "long_cutoff",
                self.long_cutoff,
                format!("0 < λ_L <= the larger size, {lmax} mm"),
            ));
        }
        let cell = (self.size[0] / self.points[0] as f64).max(self.size[1] / self.points[1] as f64);
        if !(self.short_cutoff.is_finite() && self.short_cutoff >= 2.0 * cell) {
            return Err(Error::invalid(
                "short_cutoff",
                self.short_cutoff,
                format!("λ_s >= two cells, {} mm", 2.0 * cell),
            ));
        }
        if !(self.rolloff > self.short_cutoff && self.rolloff <= self.long_cutoff) {
            return Err(Error::invalid(
                "rolloff",
                self.rolloff,
                format!(
                    "λ_s = {} < λ_r <= λ_L = {} mm (cut-offs in the order short < roll-off <= long)",
                    self.short_cutoff, self.long_cutoff
                ),
            ));
        }
        let (field, v) = match self.amplitude {
            Amplitude::RmsHeight(h) => ("amplitude.rms_height", h),
            Amplitude::RmsSlope(s) => ("amplitude.rms_slope", s),
        };
        if !(v.is_finite() && v > 0.0) {
            return Err(Error::invalid(field, v, "a finite value > 0"));
        }
        Ok(())
    }

    /// The spectrum's shape `C(q)/C_0` \[-\] at the wavenumber `q` \[1/mm\].
    pub fn spectrum_shape(&self, q: f64) -> f64 {
        let (ql, qr, qs) = (
            2.0 * PI / self.long_cutoff,
            2.0 * PI / self.rolloff,
            2.0 * PI / self.short_cutoff,
        );
        // A relative tolerance keeps modes exactly at a cut-off inside the band.
        let eps = 1e-12;
        if q < ql * (1.0 - eps) || q > qs * (1.0 + eps) {
            0.0
        } else if q < qr {
            1.0
        } else {
            (q / qr).powf(-2.0 * (1.0 + self.hurst))
        }
    }

    /// Generate the surface.
    ///
    /// # Errors
    /// As [`SelfAffineSpec::validate`]; [`Error::InvalidInput`] naming `long_cutoff` when
    /// no mode of the grid lies between the cut-offs.
    pub fn generate(&self) -> Result<SelfAffineSurface> {
        self.validate()?;
        let [nx, ny] = self.points;
        let [lx, ly] = self.size;
        let hx = nx / 2 + 1;
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        // Half spectrum: columns kx = 0..=nx/2, rows ky = 0..ny (ky > ny/2 negative).
        // Fallible: a grid too large for the memory is an error naming `points`.
        let mut spec = crate::error::try_filled("points", hx * ny, Complex64::new(0.0, 0.0))?;
        let (mut power, mut slope2) = (0.0, 0.0);
        for ky in 0..ny {
            let ky_signed = if ky <= ny / 2 {
                ky as f64
            } else {
                ky as f64 - ny as f64
            };
            for kx in 0..hx {
                // Phases are drawn for every mode in a fixed order, so that the surface
                // depends on the seed and the grid only.
                let phase = 2.0 * PI * rng.random::<f64>();
                let (qx, qy) = (2.0 * PI * kx as f64 / lx, 2.0 * PI * ky_signed / ly);
                let q = qx.hypot(qy);
                let nyquist = kx == nx / 2 || ky == ny / 2;
                if q == 0.0 || nyquist {
                    continue;
                }
                let a = self.spectrum_shape(q).sqrt();
                if a == 0.0 {
                    continue;
                }
                spec[ky * hx + kx] = Complex64::from_polar(a, phase);
                // Modes with 0 < kx < nx/2 stand for themselves and their conjugates.
                let weight = if kx == 0 { 1.0 } else { 2.0 };
                power += weight * a * a;
                slope2 += weight * a * a * q * q;
            }
        }
        // The kx = 0 column must be Hermitian along y: mode -ky is the conjugate of ky.
        for ky in 1..ny / 2 {
            let c = spec[ky * hx].conj();
            spec[(ny - ky) * hx] = c;
        }
        if power == 0.0 {
            return Err(Error::invalid(
                "long_cutoff",
                self.long_cutoff,
                "cut-offs with at least one mode of the grid between them",
            ));
        }
        // Column (kx = 0) power was counted once for +ky and once for -ky: both rows hold
        // a mode; the doubling for kx > 0 counts the conjugates in the other half plane.
        let scale = match self.amplitude {
            Amplitude::RmsHeight(h) => h / power.sqrt(),
            Amplitude::RmsSlope(s) => s / slope2.sqrt(),
        };
        for c in &mut spec {
            *c *= scale;
        }
        let (rms_height, rms_slope) = (scale * power.sqrt(), scale * slope2.sqrt());

        // Inverse transform: complex along y for each column, then complex-to-real along x.
        let mut planner = FftPlanner::<f64>::new();
        let fft_y = planner.plan_fft_inverse(ny);
        let mut column = vec![Complex64::new(0.0, 0.0); ny];
        for kx in 0..hx {
            for ky in 0..ny {
                column[ky] = spec[ky * hx + kx];
            }
            fft_y.process(&mut column);
            for ky in 0..ny {
                spec[ky * hx + kx] = column[ky];
            }
        }
        let mut real_planner = RealFftPlanner::<f64>::new();
        let c2r = real_planner.plan_fft_inverse(nx);
        let mut heights = crate::error::try_filled("points", nx * ny, 0.0)?;
        let mut scratch = c2r.make_scratch_vec();
        for j in 0..ny {
            let row = &mut spec[j * hx..(j + 1) * hx];
            // The DC and Nyquist bins of a real row must be real: they are, up to
            // rounding of the y transform; drop the rounding.
            row[0].im = 0.0;
            row[hx - 1].im = 0.0;
            c2r.process_with_scratch(row, &mut heights[j * nx..(j + 1) * nx], &mut scratch)
                .map_err(|e| {
                    Error::invalid(
                        "points",
                        format!("{nx} x {ny}"),
                        format!("a grid the FFT accepts ({e})"),
                    )
                })?;
        }
        Ok(SelfAffineSurface {
            points: self.points,
            spacing: [lx / nx as f64, ly / ny as f64],
            heights,
            rms_height,
            rms_slope,
        })
    }
}
