#![allow(clippy::unwrap_used)]
//! Friction over a pressure field (issue 11, items 3 and 4): the constant-μ identity on a
//! PimP field of a roller/rib contact, the lever arm of a Hertz ellipse spinning about an
//! axis at distance e against its series expansion (and Houpert's fit), continuity through
//! zero slip, the fluid laws' closed forms and limits, and bad input.
//! Units: mm, N, MPa, mm/s; power in W.

use kontakt::bearing::{RollerRib, RollerRibSpec, TaperedKinematics};
use kontakt::friction::{
    FilmState, FluidShear, FrictionLaw, LoadSharing, contact_friction, grid_friction,
    power_density, pressure_sliding,
};
use kontakt::geometry::{ContactFrame, Grid2, VelocityField};
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::ElasticMaterial;
use kontakt::pimp::{Pimp, PimpOptions, SurfacePairGap};
use nalgebra::{Unit, Vector3};

fn exact_coulomb(mu: f64) -> FrictionLaw {
    FrictionLaw {
        regularisation_speed: 0.0,
        ..FrictionLaw::coulomb(mu).unwrap()
    }
}

/// A rigid spin `ω` about the contact normal through the in-plane point `(0, −e)`:
/// `v = ω n × (r − r_p) = ω (−(y + e), x)`.
fn spin_about(omega: f64, e: f64) -> VelocityField {
    VelocityField {
        sliding: [[-omega * e, 0.0], [0.0, omega], [-omega, 0.0]],
        entrainment: [[0.0; 2]; 3],
    }
}

/// Constant μ (exact Coulomb): the dissipated power equals μ ∫ p |v_s| dA (to 1e-12
/// relative) on a PimP field of the sphere-torus-57 roller/rib contact with the bearing's
/// own sliding field, and the friction force is at most μ N (equality only for uniform
/// sliding; the rib's field turns across the patch). The rib contact's power also equals
/// μ N |ω_rel| e_eff with e_eff within the patch's extent of the centre's height e.
#[test]
fn constant_mu_power_is_mu_times_pressure_sliding() {
    let rr = RollerRib::new(RollerRibSpec::builtin("sphere-torus-57").unwrap()).unwrap();
    let gap = SurfacePairGap::new(rr.face.clone(), rr.rib.clone(), rr.contact).unwrap();
    let steel = ElasticMaterial::STEEL;
    let pimp = Pimp::new(steel, steel, PimpOptions::default()).unwrap();
    let solution = pimp.solve_force(&gap, 300.0).unwrap();
    let k = TaperedKinematics::of_roller_rib(&rr, 150.0, 0.0).unwrap();
    let pair = k.rib_pair(0.0).unwrap();
    let frame = ContactFrame::of_gap(&gap);
    let mu = 0.12;
    let law = exact_coulomb(mu).with_film(&FilmState::dry()).unwrap();
    let f = contact_friction(&solution, &frame, &pair, &law).unwrap();
    let g = f.grid;
    let field = pair.velocity_field(&frame, solution.orientation).unwrap();
    let ps = pressure_sliding(&solution.grid, &solution.pressure, &field).unwrap();
    println!(
        "P = {:.6e} W, mu * int p|v| dA = {:.6e} W, |F| = {:.4} N, mu N = {:.4} N",
        g.power,
        mu * ps,
        f.force.norm(),
        mu * g.normal_force
    );
    assert!((g.power - mu * ps).abs() <= 1e-12 * g.power);
    assert!(f.force.norm() <= mu * g.normal_force * (1.0 + 1e-12));
    assert!((g.normal_force - solution.force).abs() <= 1e-9 * solution.force);
    // Height of the contact centre above the inner raceway contact line.
    let d = k.directions(0.0).inner_line;
    let r = rr.contact.point - k.apex;
    let e = (r - d * r.dot(&d)).norm();
    let e_eff = g.power * 1e3 / (mu * g.normal_force * k.relative_speed.abs());
    let reach = solution.semi_axes[0].max(solution.semi_axes[1]);
    println!("e = {e:.4} mm, e_eff = {e_eff:.4} mm, patch half-extent {reach:.3} mm");
    assert!((e_eff - e).abs() <= reach, "{e_eff} vs {e}");
    // The friction force is in the contact plane.
    assert!(f.force.dot(&frame.normal).abs() <= 1e-12 * f.force.norm());
}

/// Effective lever arm of a Hertz ellipse (semi-axes s across the offset, b along it)
/// spinning at ω about an axis normal to the plane at distance e from its centre, constant
/// μ: e_eff = P / (μ ω N) = ⟨√((e + y)² + x²)⟩_p. With the Hertz moments ⟨x²⟩ = s²/5,
/// ⟨x⁴⟩ = 3s⁴/35, ⟨x²y²⟩ = s²b²/35 (docs/friction.md §3):
/// e_eff / e = 1 + (s/e)²/10 − 3(s/e)⁴/280 + (s/e)²(b/e)²/70 + O(6).
/// Sampled on a 400 × 400 grid; the tolerance 2e-5 covers the sampling error (checked
/// against the grid-converged value: 200² → 400² changes e_eff by < 1e-5 e) and the sixth-
/// order rest ((s/e)⁶ ≤ 7e-4 · 1/100). The second-order coefficient fitted from the
/// samples is 0.1, which is √(1 + 0.2 (s/e)²) to that order; Houpert's fit
/// √(1 + 0.18 (s/e)²) gives 0.09 and is printed for comparison.
#[test]
fn lever_arm_of_a_spinning_hertz_ellipse_matches_its_series() {
    let steel = ElasticMaterial::STEEL;
    let geometry = PointGeometry::new([40.0, 8.0], [f64::INFINITY; 2], 0.0).unwrap();
    let hertz = HertzPointContact::new(geometry, steel, steel)
        .unwrap()
        .solve_force(100.0)
        .unwrap();
    let [s, b] = hertz.semi_axes;
    assert!(s > b);
    let grid = Grid2::centered(s * 1.01, b * 1.01, 400, 400).unwrap();
    let field = hertz.on_grid(grid).unwrap();
    let law = exact_coulomb(0.1).with_film(&FilmState::dry()).unwrap();
    let omega = 300.0;
    let mut fits = Vec::new();
    for q in [0.1, 0.2, 0.3] {
        let e = s / q;
        let g = grid_friction(&field.grid, &field.pressure, &spin_about(omega, e), &law).unwrap();
        let ratio = g.power * 1e3 / (0.1 * omega * g.normal_force) / e;
        let r = b / e;
        let series = 1.0 + q * q / 10.0 - 3.0 * q.powi(4) / 280.0 + q * q * r * r / 70.0;
        let houpert = (1.0 + 0.18 * q * q).sqrt();
        let fit = (ratio - 1.0) / (q * q);
        println!(
            "s/e = {q}: e_eff/e = {ratio:.7}, series {series:.7}, Houpert {houpert:.7}, \
             (e_eff/e - 1)/(s/e)^2 = {fit:.5}"
        );
        assert!((ratio - series).abs() < 2e-5, "{ratio} vs {series}");
        fits.push(fit);
    }
    // The second-order coefficient: 0.1 (Houpert's fit implies 0.09).
    assert!((fits[0] - 0.1).abs() < 2e-3, "{fits:?}");
}

/// The regularised Coulomb force is continuous and odd through zero slip (|ΔF| between
/// neighbouring speeds 1e-4 v_ε apart is below 1e-3 μN), reaches μN within v_ε²/(2v²) at
/// |v| = 100 v_ε, while the exact law (v_ε = 0) jumps from −μN to μN.
#[test]
fn regularised_force_is_continuous_through_zero_slip() {
    let grid = Grid2::centered(0.5, 0.5, 4, 4).unwrap();
    let pressure = vec![200.0; grid.len()];
    let mu = 0.15;
    let smooth = FrictionLaw::coulomb(mu).unwrap();
    let eps = smooth.regularisation_speed;
    let law = smooth.with_film(&FilmState::dry()).unwrap();
    let uniform = |v: f64| VelocityField {
        sliding: [[v, 0.0], [0.0; 2], [0.0; 2]],
        entrainment: [[0.0; 2]; 3],
    };
    let mu_n = mu * 200.0;
    let force = |v: f64, law| {
        grid_friction(&grid, &pressure, &uniform(v), law)
            .unwrap()
            .force[0]
    };
    let mut previous = force(-0.01, &law);
    for step in 1..=200 {
        let v = -0.01 + step as f64 * 1e-4;
        let f = force(v, &law);
        assert!(
            (f - previous).abs() < 1e-3 * mu_n,
            "jump at {v}: {previous} -> {f}"
        );
        assert!((f + force(-v, &law)).abs() < 1e-12 * mu_n);
        previous = f;
    }
    let far = force(100.0 * eps, &law);
    assert!((far + mu_n).abs() <= mu_n * 0.5e-4 * (1.0 + 1e-6), "{far}");
    let exact = exact_coulomb(mu).with_film(&FilmState::dry()).unwrap();
    assert!((force(1e-9, &exact) + mu_n).abs() < 1e-9);
    assert!((force(-1e-9, &exact) - mu_n).abs() < 1e-9);
    assert_eq!(force(0.0, &exact), 0.0);
}

/// The fluid laws at one cell, fully lubricated (φ = exp(−1.9·50^0.99) ≈ 0): Newtonian
/// Couette stress η₀ e^{αp} v/h; Eyring τ₀ asinh(ηγ̇/τ₀), its Newtonian limit at small
/// stress and τ₀ ln(2ηγ̇/τ₀) at large; limiting shear → τ_L = τ_L0 + γ_L p; no overflow at
/// α p = 1000 for the bounded laws, a clear error for the Newtonian one. Tolerance 1e-12
/// relative (closed forms).
#[test]
fn fluid_laws_match_their_closed_forms() {
    let (eta, alpha, h) = (5e-8, 0.02, 1e-3); // 50 mPa·s, 0.02 1/MPa, 1 µm
    let film = FilmState::new(h, 50.0, eta, alpha).unwrap();
    let law = |fluid| FrictionLaw {
        boundary_coefficient: 0.1,
        sharing: LoadSharing::Exponential { b: 1.9, c: 0.99 },
        fluid,
        regularisation_speed: 1.0,
    };
    let (p, v) = (100.0, 500.0);
    let newton = eta * (alpha * p).exp() * v / h;
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs().max(1e-300);
    let n = law(FluidShear::Newtonian).with_film(&film).unwrap();
    assert!(n.asperity_share() < 1e-30);
    assert!(
        close(n.shear_stress(p, v), newton),
        "{}",
        n.shear_stress(p, v)
    );
    let tau0 = 5.0;
    let ey = law(FluidShear::Eyring { tau0 }).with_film(&film).unwrap();
    assert!(close(ey.shear_stress(p, v), tau0 * (newton / tau0).asinh()));
    // small stress: Newtonian to (x/τ₀)²/6
    let slow = 1e-6;
    let small = eta * (alpha * p).exp() * slow / h;
    assert!((ey.shear_stress(p, slow) / small - 1.0).abs() < 1e-9);
    let lim = law(FluidShear::LimitingShear {
        tau_l0: 2.0,
        slope: 0.07,
    })
    .with_film(&film)
    .unwrap();
    let tau_l = 2.0 + 0.07 * p;
    assert!(close(
        lim.shear_stress(p, v),
        tau_l * (1.0 - (-newton / tau_l).exp())
    ));
    // α p = 1000: exp overflows; bounded laws stay finite and take their asymptotes.
    let p_big = 1000.0 / alpha;
    let ln_r = alpha * p_big + (eta * v / h / tau0).ln();
    assert!(close(ey.shear_stress(p_big, v), tau0 * (2f64.ln() + ln_r)));
    assert!(close(lim.shear_stress(p_big, v), 2.0 + 0.07 * p_big));
    let grid = Grid2::centered(0.1, 0.1, 2, 2).unwrap();
    let pressure = vec![p_big; 4];
    let field = VelocityField {
        sliding: [[v, 0.0], [0.0; 2], [0.0; 2]],
        entrainment: [[0.0; 2]; 3],
    };
    assert!(grid_friction(&grid, &pressure, &field, &lim).is_ok());
    let err = grid_friction(&grid, &pressure, &field, &n).unwrap_err();
    assert_eq!(err.field(), Some("fluid"));
}

/// The mixed law at one cell: τ = φ μ_b p ŝ(v) + (1 − φ) τ_f with φ = exp(−B Λ^C), against
/// the formula evaluated here (1e-12); the power is never negative over a field that
/// sweeps through zero slip, and the density map sums to the power.
#[test]
fn mixed_law_and_power_density() {
    let film = FilmState::new(0.4e-3, 1.2, 4e-8, 0.02).unwrap();
    let law = FrictionLaw::mixed(0.12).unwrap();
    let cell = law.with_film(&film).unwrap();
    let phi = (-1.90 * 1.2f64.powf(0.99)).exp();
    assert!((cell.asperity_share() - phi).abs() < 1e-15);
    let (p, v): (f64, f64) = (80.0, 300.0);
    let eta = 4e-8 * (0.02 * p).exp();
    let tau_l = 2.0 + 0.07 * p;
    let fluid = tau_l * (1.0 - (-eta * v / 0.4e-3 / tau_l).exp());
    let expected = phi * 0.12 * p * v / (v * v + 1.0).sqrt() + (1.0 - phi) * fluid;
    assert!((cell.shear_stress(p, v) - expected).abs() < 1e-12 * expected);
    // A spin field through the grid's middle: zero slip inside the patch.
    let grid = Grid2::centered(1.0, 0.5, 64, 32).unwrap();
    let pressure: Vec<f64> = grid
        .points()
        .map(|(x, y)| 100.0 * (1.0 - x * x - 4.0 * y * y).max(0.0).sqrt())
        .collect();
    let field = spin_about(50.0, 0.1);
    let g = grid_friction(&grid, &pressure, &field, &cell).unwrap();
    let mut density = vec![0.0; grid.len()];
    power_density(&grid, &pressure, &field, &cell, &mut density).unwrap();
    assert!(density.iter().all(|d| *d >= 0.0));
    let sum: f64 = density.iter().sum::<f64>() * grid.cell_area();
    println!("P = {:.6e} W, sum of density = {sum:.6e} W", g.power);
    assert!(g.power > 0.0 && (sum - g.power).abs() <= 1e-12 * g.power);
}

/// Moments: the moment about an axis through a point equals the axis component of
/// Σ (r − Q) × τ ΔA computed cell by cell in the world (1e-12 relative).
#[test]
fn moment_about_an_axis_matches_the_cell_sum() {
    let rr = RollerRib::new(RollerRibSpec::builtin("torus-cone-14").unwrap()).unwrap();
    let gap = SurfacePairGap::new(rr.face.clone(), rr.rib.clone(), rr.contact).unwrap();
    let steel = ElasticMaterial::STEEL;
    let s = Pimp::new(steel, steel, PimpOptions::default())
        .unwrap()
        .solve_force(&gap, 200.0)
        .unwrap();
    let k = TaperedKinematics::of_roller_rib(&rr, 100.0, 0.0).unwrap();
    let pair = k.rib_pair(0.0).unwrap();
    let frame = ContactFrame::of_gap(&gap);
    let law = FrictionLaw::coulomb(0.1)
        .unwrap()
        .with_film(&FilmState::dry())
        .unwrap();
    let f = contact_friction(&s, &frame, &pair, &law).unwrap();
    let (sn, c) = s.orientation.sin_cos();
    let gx = frame.ex.into_inner() * c + frame.ey.into_inner() * sn;
    let gy = frame.normal.cross(&gx);
    let axis = Unit::new_normalize(Vector3::new(0.2, -0.1, 1.0));
    let q = k.apex;
    let mut direct = Vector3::zeros();
    let mut force = Vector3::zeros();
    for (idx, (x, y)) in s.grid.points().enumerate() {
        let p = s.pressure[idx];
        if p <= 0.0 {
            continue;
        }
        let r = frame.origin + gx * x + gy * y;
        let v = pair.velocities(&r, &frame.normal).unwrap().sliding;
        let tau = -v.normalize() * 0.1 * p * v.norm() / (v.norm_squared() + 1.0).sqrt();
        force += tau * s.grid.cell_area();
        direct += (r - q).cross(&tau) * s.grid.cell_area();
    }
    let m = f.moment_about(&q, &axis);
    println!("moment {m:.6} N·mm, cell sum {:.6}", axis.dot(&direct));
    assert!((f.force - force).norm() <= 1e-12 * force.norm());
    assert!((m - axis.dot(&direct)).abs() <= 1e-11 * direct.norm());
}

/// Bad input: each error names its field.
#[test]
fn bad_input_names_the_field() {
    let field_of =
        |r: kontakt::error::Result<_>| r.map(|_: ()| ()).unwrap_err().field().unwrap().to_string();
    assert_eq!(
        field_of(FilmState::new(-1.0, 1.0, 1e-8, 0.02).map(|_| ())),
        "thickness"
    );
    assert_eq!(
        field_of(FilmState::new(1e-3, f64::NAN, 1e-8, 0.02).map(|_| ())),
        "lambda"
    );
    assert_eq!(
        field_of(FilmState::new(1e-3, 1.0, 0.0, 0.02).map(|_| ())),
        "viscosity"
    );
    assert_eq!(
        field_of(FilmState::new(1e-3, 1.0, 1e-8, -0.1).map(|_| ())),
        "alpha"
    );
    assert_eq!(
        field_of(FrictionLaw::coulomb(1.5).map(|_| ())),
        "boundary_coefficient"
    );
    assert_eq!(
        field_of(FrictionLaw::coulomb(f64::NAN).map(|_| ())),
        "boundary_coefficient"
    );
    let mut law = FrictionLaw::mixed(0.1).unwrap();
    law.regularisation_speed = -1.0;
    assert_eq!(field_of(law.check()), "regularisation_speed");
    law = FrictionLaw::mixed(0.1).unwrap();
    law.sharing = LoadSharing::Exponential { b: 0.0, c: 1.0 };
    assert_eq!(field_of(law.check()), "sharing.b");
    law.sharing = LoadSharing::Boundary;
    law.fluid = FluidShear::Eyring { tau0: -1.0 };
    assert_eq!(field_of(law.check()), "fluid.tau0");
    law.fluid = FluidShear::LimitingShear {
        tau_l0: 1.0,
        slope: f64::INFINITY,
    };
    assert_eq!(field_of(law.check()), "fluid.slope");
    let grid = Grid2::centered(1.0, 1.0, 4, 4).unwrap();
    let cell = FrictionLaw::coulomb(0.1)
        .unwrap()
        .with_film(&FilmState::dry())
        .unwrap();
    let good = VelocityField {
        sliding: [[1.0, 0.0], [0.0; 2], [0.0; 2]],
        entrainment: [[0.0; 2]; 3],
    };
    let short = vec![1.0; 15];
    assert_eq!(
        field_of(grid_friction(&grid, &short, &good, &cell).map(|_| ())),
        "pressure"
    );
    let mut nan = good;
    nan.sliding[1][0] = f64::NAN;
    let pressure = vec![1.0; 16];
    assert_eq!(
        field_of(grid_friction(&grid, &pressure, &nan, &cell).map(|_| ())),
        "sliding"
    );
    let mut bad_p = pressure.clone();
    bad_p[3] = f64::INFINITY;
    assert_eq!(
        field_of(grid_friction(&grid, &bad_p, &good, &cell).map(|_| ())),
        "pressure"
    );
    let mut out = vec![0.0; 3];
    assert_eq!(
        field_of(power_density(&grid, &pressure, &good, &cell, &mut out)),
        "density"
    );
}
