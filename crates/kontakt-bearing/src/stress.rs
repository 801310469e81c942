//! The maximum Hertz pressure of every slice of a roller on its inner and its outer raceway.
//!
//! **Model.** Slice k of a roller (width `w = L_we/n`) carries the line load `q'_k = q_k/w`
//! (N/mm) on the outer raceway and `q'_k Q_i/Q_o` on the inner one (the two differ for a
//! tapered roller only, by the roller's force balance of [`crate::equilibrium`]). Each slice
//! is a Hertz line contact of two parallel cylinders ([`kontakt::hertz::line`], Johnson
//! 1985 §4.2): `p_0 = √(q' E*/(π R))` with `1/R = 1/R_roller + 1/R_raceway` in the plane
//! normal to the contact line.
//!
//! **Local radii** (mm) at the slice centre x (from the roller centre toward the small end
//! of a tapered roller), with the cup angle α, the cone angle α_i, the roller half-angle
//! `θ = (α − α_i)/2`, the roller axis angle `α_m = (α + α_i)/2`, the pitch radius
//! `R_p = d_m/2` and the local roller diameter `D(x) = D_we − 2 x tan θ`:
//!
//! ```text
//! roller        R_r(x) =  D(x) / (2 cos θ)                                (convex)
//! inner raceway R_i(x) =  [R_p − x sin α_m − (D(x)/2) cos α_i] / cos α_i   (convex)
//! outer raceway R_o(x) = −[R_p − x sin α_m + (D(x)/2) cos α ] / cos α     (concave)
//! ```
//!
//! The normal curvature of a cone of half-angle φ at the distance ρ from its axis, across
//! its generatrix, is `cos φ/ρ` (a cylinder's 1/ρ at φ = 0; a flat washer's 0 at φ = 90°).
//! For a cylindrical roller bearing they reduce to `D/2`, `(d_m − D)/2` and `−(d_m + D)/2`
//! (Harris & Kotzalas 2006, `R = D(1 ∓ γ)/2`, γ = D/d_m); for a thrust bearing (α = 90°) the
//! washers are flat. The radial position of the contact point uses the raceway normal
//! (cos α_i, cos α) instead of the normal of the roller's surface, exact to first order in
//! θ (a relative error of about `(D/d_m) θ sin α`, below 1e-3 for the examples). The
//! profiles (crowning) are drops along the roller and do not enter the radii across it:
//! the slice model resolves the pressure along the roller through the slice loads.
//!
//! **Materials.** The slice law of ISO/TS 16281 is for steel, so the pressures use steel
//! rollers and rings by default (E = 210 000 MPa, ν = 0.3); [`RollerStress::new`] takes
//! other materials for a caller that also changes the slice stiffness.

use crate::geometry::{RollerBearing, RollerBearingKind};
use kontakt::hertz::line::LineContact;
use kontakt::material::ElasticMaterial;
use kontakt::{Error, Result};

/// The local radii `(roller, inner raceway, outer raceway)` across the contact line at the
/// slice centre `x` (mm; see the module documentation), mm: the outer raceway's is
/// negative (concave), a thrust washer's infinite.
pub fn slice_radii(b: &RollerBearing, x: f64) -> (f64, f64, f64) {
    let (a, ai) = (b.contact_angle_rad, b.cone_angle_rad);
    let half = 0.5 * (a - ai);
    let axis = 0.5 * (a + ai);
    let d = b.roller_diameter_mm - 2.0 * x * half.tan();
    let roller = 0.5 * d / half.cos();
    if b.kind == RollerBearingKind::Thrust {
        return (roller, f64::INFINITY, f64::NEG_INFINITY);
    }
    let rho = 0.5 * b.pitch_diameter_mm - x * axis.sin();
    let inner = (rho - 0.5 * d * ai.cos()) / ai.cos();
    let outer = -(rho + 0.5 * d * a.cos()) / a.cos();
    (roller, inner, outer)
}

/// The Hertz line contacts of every slice of a roller on both raceways, planned once.
#[derive(Debug, Clone)]
pub struct RollerStress {
    /// Per slice: the contact on the inner and on the outer raceway.
    contacts: Vec<[LineContact; 2]>,
    width: f64,
}

impl RollerStress {
    /// Plan the slices of `bearing` (validated) with steel rollers and rings.
    ///
    /// # Errors
    /// As [`RollerStress::with_materials`].
    pub fn new(bearing: &RollerBearing) -> Result<Self> {
        Self::with_materials(bearing, ElasticMaterial::STEEL, ElasticMaterial::STEEL)
    }

    /// Plan the slices of `bearing` with the given roller and ring materials.
    ///
    /// # Errors
    /// [`RollerBearing::validate`]'s errors; [`Error::Geometry`] naming
    /// `roller_diameter_mm` when a slice's radii are not a convex contact (a roller larger
    /// than its raceway).
    pub fn with_materials(
        bearing: &RollerBearing,
        roller: ElasticMaterial,
        ring: ElasticMaterial,
    ) -> Result<Self> {
        bearing.validate()?;
        let contacts = bearing
            .slice_positions()
            .map(|x| {
                let (rr, ri, ro) = slice_radii(bearing, x);
                let plan = |r: f64| {
                    LineContact::new(rr, r, roller, ring).map_err(|e| Error::Geometry {
                        field: "roller_diameter_mm".into(),
                        reason: format!(
                            "the slice at x = {x} mm is no Hertz line contact (roller radius {rr} mm, raceway radius {r} mm): {e}"
                        ),
                    })
                };
                Ok([plan(ri)?, plan(ro)?])
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(RollerStress {
            contacts,
            width: bearing.effective_length_mm / bearing.slices as f64,
        })
    }

    /// The line contact of slice `k` on the inner (`ring = 0`) or outer (`ring = 1`)
    /// raceway.
    ///
    /// # Panics
    /// When `k` is not a slice or `ring > 1`.
    pub fn contact(&self, k: usize, ring: usize) -> &LineContact {
        &self.contacts[k][ring]
    }

    /// The slice width `L_we/n`, mm.
    pub fn slice_width(&self) -> f64 {
        self.width
    }

    /// The maximum Hertz pressure (MPa) of slice `k` under the slice load `load_n` (N) on
    /// the inner (`ring = 0`) or outer (`ring = 1`) raceway; 0 for no load.
    ///
    /// # Errors
    /// A non-finite load (the line contact's error).
    ///
    /// # Panics
    /// When `k` is not a slice or `ring > 1`.
    pub fn pressure(&self, k: usize, ring: usize, load_n: f64) -> Result<f64> {
        if load_n == 0.0 {
            return Ok(0.0);
        }
        Ok(self.contacts[k][ring]
            .solve(load_n / self.width)?
            .max_pressure)
    }

    /// The pressures of one roller's slices: `loads` (N, the outer raceway's slice loads),
    /// `inner_ratio = Q_i/Q_o`; fills `inner` and `outer` (MPa) and returns their largest
    /// values `[inner, outer]`. Allocates nothing.
    ///
    /// # Errors
    /// A non-finite slice load.
    ///
    /// # Panics
    /// When the slices lengths differ from the bearing's slice count.
    pub fn roller(
        &self,
        loads: &[f64],
        inner_ratio: f64,
        inner: &mut [f64],
        outer: &mut [f64],
    ) -> Result<[f64; 2]> {
        assert!(
            loads.len() == self.contacts.len()
                && inner.len() == loads.len()
                && outer.len() == loads.len()
        );
        let mut max = [0.0_f64; 2];
        for (k, &q) in loads.iter().enumerate() {
            inner[k] = self.pressure(k, 0, q * inner_ratio)?;
            outer[k] = self.pressure(k, 1, q)?;
            max[0] = max[0].max(inner[k]);
            max[1] = max[1].max(outer[k]);
        }
        Ok(max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn cylindrical_radii_are_harris() {
        let b = RollerBearing::cylindrical(60.0, 14, 10.0, 12.0);
        for x in [-5.0, 0.0, 3.0] {
            let (r, i, o) = slice_radii(&b, x);
            assert_eq!((r, i, o), (5.0, 25.0, -35.0));
        }
        let t = RollerBearing::thrust(43.5, 18, 5.0, 5.5);
        let (r, i, o) = slice_radii(&t, 1.0);
        assert!((r - 2.5).abs() < 1e-15 && i.is_infinite() && o.is_infinite());
    }

    /// Tapered: the roller's local radius shrinks toward the small end, and the roller
    /// radius over the inner raceway radius matches the closed form of a cone apex on the
    /// bearing axis: the effective radius at the mean diameter is `(D/2)(1 − D cos α_i/d_m)`
    /// to first order in the half-angle.
    #[test]
    fn tapered_radii() {
        let (a, ai) = (14.17_f64.to_radians(), 11.17_f64.to_radians());
        let b = RollerBearing::tapered(54.0, 23, 6.4885, 13.66, a, ai);
        let (r0, i0, o0) = slice_radii(&b, 0.0);
        let (r1, _, _) = slice_radii(&b, 5.0);
        assert!(r1 < r0);
        let half = 0.5 * (a - ai);
        assert!((r0 - 0.5 * 6.4885 / half.cos()).abs() < 1e-12);
        let eff = 1.0 / (1.0 / r0 + 1.0 / i0);
        let approx = 0.5 * 6.4885 * (1.0 - 6.4885 * ai.cos() / 54.0);
        assert!((eff / approx - 1.0).abs() < 5e-3, "{eff} {approx}");
        assert!(o0 < 0.0 && -o0 > 27.0);
    }

    /// A slice's pressure is Hertz's `√(q' E*/(π R))` with the slice's line load.
    #[test]
    fn pressure_is_hertz_line_contact() {
        let mut b = RollerBearing::cylindrical(60.0, 14, 10.0, 12.0);
        b.slices = 3;
        let s = RollerStress::new(&b).unwrap();
        let q = 1000.0; // N on a 4 mm slice
        let e = 210_000.0 / (2.0 * (1.0 - 0.09));
        let r_in = 1.0 / (1.0 / 5.0 + 1.0 / 25.0);
        let r_out = 1.0 / (1.0 / 5.0 - 1.0 / 35.0);
        let p_in = (q / 4.0 * e / (PI * r_in)).sqrt();
        let p_out = (q / 4.0 * e / (PI * r_out)).sqrt();
        assert!((s.pressure(1, 0, q).unwrap() / p_in - 1.0).abs() < 1e-12);
        assert!((s.pressure(1, 1, q).unwrap() / p_out - 1.0).abs() < 1e-12);
        assert_eq!(s.pressure(0, 0, 0.0).unwrap(), 0.0);
        let (mut i, mut o) = ([0.0; 3], [0.0; 3]);
        let m = s.roller(&[q, 2.0 * q, 0.0], 0.5, &mut i, &mut o).unwrap();
        assert!((o[1] / (p_out * 2f64.sqrt()) - 1.0).abs() < 1e-12);
        assert!((i[1] / p_in - 1.0).abs() < 1e-12); // 0.5 × 2q = q
        assert_eq!(m, [i[1], o[1]]);
        assert!(s.pressure(0, 1, f64::NAN).is_err());
    }
}
