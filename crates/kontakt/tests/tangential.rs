//! Tangential contact (issue 5, part 1): Cattaneo-Mindlin, Mindlin-Deresiewicz history,
//! Carter, Kalker's coefficients and linear theory, FASTSIM.
//!
//! Tolerances are stated per assertion: closed forms re-typed from the literature are
//! compared to ~1e-12 (same formula, other arithmetic); numerical oracles (quadrature of
//! the Cerruti kernel, loop areas) to their quadrature error; table values to the printed
//! digits; FASTSIM against the linear theory and the closed-form simplified theory to its
//! discretisation error, which is shown to fall with refinement.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

use kontakt::hertz::line::LineContact;
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::{ElasticMaterial, effective_modulus, effective_shear_modulus};
use kontakt::tangential::fastsim::longitudinal_simplified_theory;
use kontakt::tangential::kalker::{TABLE_A_OVER_B, TABLE_B_OVER_A};
use kontakt::tangential::{
    Carter, ContactEllipse, Creepage, EllipseAxis, Fastsim, FastsimOptions, KalkerLinear,
    KalkerMaterial, Mindlin, PressureShape, TractionCurve, creep_coefficients,
};
use kontakt::traction::{AsperityCurve, AsperityTraction, AsperityTractionParams, NominalContact};
use std::f64::consts::PI;

const STEEL: ElasticMaterial = ElasticMaterial::STEEL;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Sphere R = 10 mm on a flat, steel, 500 N, mu = 0.3.
fn sphere_contact() -> (Mindlin, f64) {
    let hertz =
        HertzPointContact::new(PointGeometry::sphere_on_flat(10.0).unwrap(), STEEL, STEEL).unwrap();
    let sol = hertz.solve_force(500.0).unwrap();
    let e = ContactEllipse::from_hertz(&sol, EllipseAxis::Major).unwrap();
    (
        Mindlin::new(e, STEEL, STEEL, 0.3).unwrap(),
        sol.semi_axes[0],
    )
}

// ---------------------------------------------------------------------------------------
// Cattaneo-Mindlin
// ---------------------------------------------------------------------------------------

/// Johnson (1982) eq. 32: a'/a = (1 - Q/(mu P))^(1/3), for the circle and for an ellipse (the
/// stick ellipse is similar: b'/b = a'/a). Tolerance 1e-12 (same formula).
#[test]
fn stick_radius_follows_the_cube_root_law() {
    let (m, a) = sphere_contact();
    let mp = m.limit_force();
    assert!((mp - 150.0).abs() < 1e-12);
    for x in [0.0, 0.1, 0.3, 0.5, 0.9, 0.999, 1.0] {
        let q = x * mp;
        let expected = (1.0 - x).cbrt();
        assert!(
            (m.stick_ratio(q).unwrap() - expected).abs() < 1e-12,
            "x={x}"
        );
        assert!((m.stick_ratio(-q).unwrap() - expected).abs() < 1e-12);
        let [sa, sb] = m.stick_semi_axes(q).unwrap();
        assert!((sa - a * expected).abs() < 1e-12 && (sb - a * expected).abs() < 1e-12);
    }
    let e = ContactEllipse::new(0.4, 0.2, 300.0).unwrap();
    let m = Mindlin::new(e, STEEL, STEEL, 0.2).unwrap();
    let [sa, sb] = m.stick_semi_axes(30.0).unwrap();
    assert!((sa - 0.4 * 0.5f64.cbrt()).abs() < 1e-12 && (sb - 0.2 * 0.5f64.cbrt()).abs() < 1e-12);
}

/// The traction of eq. 31 is bounded by mu p, equals it in the slip annulus, stays below
/// it in the stick zone, and integrates to Q (midpoint quadrature on a 400x400 grid:
/// relative error < 2e-3 from the square-root edges).
#[test]
fn mindlin_traction_is_admissible_and_carries_q() {
    let e = ContactEllipse::new(0.3, 0.15, 400.0).unwrap();
    let m = Mindlin::new(e, STEEL, STEEL, 0.25).unwrap();
    let q = 0.6 * m.limit_force();
    let r = m.stick_ratio(q).unwrap();
    let n = 400;
    let (dx, dy) = (2.0 * 0.3 / n as f64, 2.0 * 0.15 / n as f64);
    let mut total = 0.0;
    for i in 0..n {
        for j in 0..n {
            let x = -0.3 + (i as f64 + 0.5) * dx;
            let y = -0.15 + (j as f64 + 0.5) * dy;
            let t = m.traction_at(q, x, y).unwrap();
            let bound = 0.25 * e.pressure_at(x, y);
            assert!(t <= bound + 1e-9 && t >= -1e-12);
            let rho2 = (x / 0.3).powi(2) + (y / 0.15).powi(2);
            if rho2 > r * r && rho2 < 1.0 {
                assert!((t - bound).abs() < 1e-9, "slip annulus must carry mu p");
            } else if rho2 < 0.98 * r * r {
                assert!(t < bound - 1e-9, "stick zone must stay below mu p");
            }
            total += t * dx * dy;
        }
    }
    assert!(rel(total, q) < 2e-3, "{total} vs {q}");
    // Opposite force, opposite traction.
    assert_eq!(
        m.traction_at(-q, 0.01, 0.02).unwrap(),
        -m.traction_at(q, 0.01, 0.02).unwrap()
    );
}

/// Circular compliance: delta = 3 mu P/(16 a G*) [1 - (1 - Q/(mu P))^(2/3)] (Johnson
/// 1985 §7.2), initial slope 1/(8 a G*), and the thesis' eq. 2.18 (two identical
/// bodies, C = G): Q = [1 - (1 - 8 delta a G/(3 (2 - nu) mu P))^(3/2)] mu P. 1e-12.
#[test]
fn circular_compliance_against_closed_forms() {
    let (m, a) = sphere_contact();
    let gs = effective_shear_modulus(&STEEL, &STEEL);
    let (mu, p) = (0.3, 500.0);
    assert!(rel(m.no_slip_compliance(), 1.0 / (8.0 * a * gs)) < 1e-13);
    for x in [1e-6, 0.05, 0.4, 0.8, 1.0] {
        let q = x * mu * p;
        let johnson = 3.0 * mu * p / (16.0 * a * gs) * (1.0 - (1.0 - x).powf(2.0 / 3.0));
        let d = m.displacement(q).unwrap();
        assert!(rel(d, johnson) < 1e-9, "x={x}: {d} vs {johnson}");
        assert!(rel(m.displacement(-q).unwrap(), -johnson) < 1e-9);
        // Thesis eq. 2.18, inverted: back to Q.
        let g = STEEL.shear_modulus();
        let inner = (1.0 - 8.0 * d * a * g / (3.0 * (2.0 - 0.3) * mu * p)).max(0.0);
        let thesis = (1.0 - inner.powf(1.5)) * mu * p;
        assert!(rel(thesis, q) < 1e-8, "x={x}: {thesis} vs {q}");
        assert!(rel(m.force_from_displacement(d).unwrap(), q) < 1e-12);
    }
    assert!(
        m.force_from_displacement(1.01 * m.slip_displacement())
            .is_err()
    );
}

/// Mindlin's elliptical no-slip compliance against an independent oracle: the Cerruti
/// surface displacement of the traction q0 (1 - x²/a² - y²/b²)^(-1/2), integrated
/// numerically in polar coordinates about field points *off* the centre (the radial
/// integral in closed form, the angular one by the trapezoid rule, 4000 points). This
/// checks both the value and Mindlin's result that the displacement is uniform.
/// Tolerance 1e-6.
#[test]
fn elliptical_compliance_against_cerruti_quadrature() {
    let soft = ElasticMaterial::new(70_000.0, 0.33).unwrap();
    for (a, b) in [(0.5, 0.25), (0.2, 0.6), (0.3, 0.03)] {
        let e = ContactEllipse::new(a, b, 100.0).unwrap();
        let m = Mindlin::new(e, STEEL, soft, 0.3).unwrap();
        let [cx, cy] = m.axis_compliances();
        for (x0, y0) in [(0.0, 0.0), (0.3 * a, 0.2 * b), (-0.6 * a, 0.5 * b)] {
            for (dir, c_lib) in [(0, cx), (1, cy)] {
                let mut u = 0.0;
                for mat in [STEEL, soft] {
                    u += cerruti_inverse_sqrt(a, b, x0, y0, dir, &mat);
                }
                let c_num = u / (2.0 * PI * a * b); // q0 = 1 carries Q = 2 pi a b
                assert!(
                    rel(c_lib, c_num) < 1e-6,
                    "a={a} b={b} at ({x0},{y0}) dir {dir}: {c_lib} vs {c_num}"
                );
            }
        }
        // Oblique force: C = Cx cos² + Cy sin².
        let mo = m.with_load_direction(0.7).unwrap();
        assert!(
            rel(
                mo.no_slip_compliance(),
                cx * 0.7f64.cos().powi(2) + cy * 0.7f64.sin().powi(2)
            ) < 1e-14
        );
    }
}

/// Partial slip on an ellipse: the displacement of the Cattaneo traction (eq. 31),
/// integrated with the Cerruti kernel at points of the stick zone, is the uniform
/// 3 mu P C/2 [1 - (1 - x)^(2/3)] of the library. Tolerance 1e-6.
#[test]
fn elliptical_partial_slip_displacement_is_uniform_in_the_stick_zone() {
    let (a, b) = (0.4, 0.16);
    let e = ContactEllipse::new(a, b, 250.0).unwrap();
    let m = Mindlin::new(e, STEEL, STEEL, 0.2).unwrap();
    for frac in [0.3, 0.8] {
        let q = frac * m.limit_force();
        let r = m.stick_ratio(q).unwrap();
        let p0 = e.max_pressure();
        for (x0, y0) in [
            (0.0, 0.0),
            (0.5 * r * a, 0.3 * r * b),
            (-0.2 * r * a, -0.7 * r * b),
        ] {
            // mu p0 [H(a) - r H(r a)] with H the Hertz-like sqrt field; two steel bodies.
            let full = cerruti_sqrt(a, b, x0, y0, 0, &STEEL);
            let inner = cerruti_sqrt(r * a, r * b, x0, y0, 0, &STEEL);
            let u = 2.0 * 0.2 * p0 * (full - r * inner);
            let d = m.displacement(q).unwrap();
            assert!(rel(d, u) < 1e-6, "frac={frac} at ({x0},{y0}): {d} vs {u}");
        }
    }
}

/// Cerruti displacement along `dir` (0: x, 1: y) at (x0, y0) of one body with the traction
/// (1 - x²/a² - y²/b²)^(-1/2) along `dir`.
fn cerruti_inverse_sqrt(a: f64, b: f64, x0: f64, y0: f64, dir: usize, m: &ElasticMaterial) -> f64 {
    cerruti(a, b, x0, y0, dir, m, |c, mid, half| {
        (0.5 * PI + (mid / half).asin()) / c.sqrt()
    })
}

/// As [`cerruti_inverse_sqrt`] for the traction sqrt(1 - x²/a² - y²/b²).
fn cerruti_sqrt(a: f64, b: f64, x0: f64, y0: f64, dir: usize, m: &ElasticMaterial) -> f64 {
    cerruti(a, b, x0, y0, dir, m, |c, mid, half| {
        // ∫_0^R sqrt(C (R - r)(r - r-)) dr with r = mid + half sin(phi).
        let phi0 = (-mid / half).asin();
        let prim = |p: f64| 0.5 * p + 0.25 * (2.0 * p).sin();
        c.sqrt() * half * half * (prim(0.5 * PI) - prim(phi0))
    })
}

/// u_dir(x0, y0) = 1/(2 pi G) ∫ dθ [(1 - nu) + nu cos²(θ - θ_dir)] ∫_0^R q dr, the ray
/// integral given by `radial(C, mid, half)` for the quadratic 1 - X²/a² - Y²/b² =
/// C (R - r)(r - r-) along the ray (mid = (R + r-)/2, half = (R - r-)/2).
fn cerruti(
    a: f64,
    b: f64,
    x0: f64,
    y0: f64,
    dir: usize,
    m: &ElasticMaterial,
    radial: impl Fn(f64, f64, f64) -> f64,
) -> f64 {
    let (g, nu) = (m.shear_modulus(), m.poisson_ratio());
    let n = 4000;
    let mut sum = 0.0;
    for k in 0..n {
        let th = 2.0 * PI * k as f64 / n as f64;
        let (s, c) = th.sin_cos();
        let cc = c * c / (a * a) + s * s / (b * b);
        let bb = x0 * c / (a * a) + y0 * s / (b * b);
        let a0 = 1.0 - x0 * x0 / (a * a) - y0 * y0 / (b * b);
        let disc = (bb * bb + a0 * cc).sqrt();
        let (rp, rm) = ((-bb + disc) / cc, (-bb - disc) / cc);
        let (mid, half) = (0.5 * (rp + rm), 0.5 * (rp - rm));
        let along = if dir == 0 { c } else { s };
        sum += ((1.0 - nu) + nu * along * along) * radial(cc, mid, half);
    }
    sum * (2.0 * PI / n as f64) / (2.0 * PI * g)
}

/// Energy per cycle: W = 9 mu² P²/(10 a G*) [1 - (1-x)^(5/3) - (5x/6)(1 + (1-x)^(2/3))]
/// (Johnson 1985 §7.3, eq. 7.67 of the issue), typed here in its textbook form (1e-9 where it does not
/// cancel), and the small-amplitude limit Q*³/(36 a G* mu P) (Johnson (1982) eq. 33: W ∝ P*³).
#[test]
fn dissipated_energy_against_closed_form() {
    let (m, a) = sphere_contact();
    let gs = effective_shear_modulus(&STEEL, &STEEL);
    let mp = 150.0;
    for x in [0.2f64, 0.5, 0.8, 1.0] {
        let textbook = 9.0 * mp * mp / (10.0 * a * gs)
            * (1.0 - (1.0 - x).powf(5.0 / 3.0) - 5.0 * x / 6.0 * (1.0 + (1.0 - x).powf(2.0 / 3.0)));
        let w = m.dissipated_energy_per_cycle(x * mp).unwrap();
        assert!(rel(w, textbook) < 1e-9, "x={x}: {w} vs {textbook}");
    }
    for x in [1e-6, 1e-4, 1e-3] {
        let q = x * mp;
        let small = q.powi(3) / (36.0 * a * gs * mp);
        let w = m.dissipated_energy_per_cycle(q).unwrap();
        // Next term of the series is O(x): relative 1.2 x.
        assert!(rel(w, small) < 1.5 * x + 1e-12, "x={x}: {w} vs {small}");
    }
    assert_eq!(m.dissipated_energy_per_cycle(0.0).unwrap(), 0.0);
}

/// The hysteresis loop of the loading-history type, integrated numerically
/// (∮ Q d delta, trapezoid rule with 20 000 steps per cycle: relative error < 1e-6), has
/// the closed-form area, in the first cycle and in later ones (Masing loops are stable).
#[test]
fn hysteresis_loop_area_equals_closed_form() {
    let (m, _) = sphere_contact();
    for amp_frac in [0.1, 0.5, 0.95, 1.0] {
        let amp = amp_frac * m.limit_force();
        let mut h = m.history();
        h.apply_force(amp).unwrap();
        let n = 20_000;
        for cycle in 0..2 {
            let (mut area, mut last) = (0.0, (h.force(), h.displacement()));
            for i in 1..=n {
                let q = amp * (2.0 * PI * i as f64 / n as f64).cos();
                let d = h.apply_force(q).unwrap();
                area += 0.5 * (q + last.0) * (d - last.1);
                last = (q, d);
            }
            let w = m.dissipated_energy_per_cycle(amp).unwrap();
            assert!(
                rel(area, w) < 1e-6,
                "amp={amp_frac} cycle {cycle}: {area} vs {w}"
            );
        }
    }
}

/// Masing branches, reversal memory and the stick zone of a history.
#[test]
fn history_follows_masing_rules_with_memory() {
    let (m, _) = sphere_contact();
    let mp = m.limit_force();
    let mut h = m.history();
    let d1 = h.apply_force(0.6 * mp).unwrap();
    assert_eq!(d1, m.displacement(0.6 * mp).unwrap());
    // Unloading branch: delta = d1 - 2 f((Q1 - Q)/2).
    let d2 = h.apply_force(-0.2 * mp).unwrap();
    let masing = d1 - 2.0 * m.displacement(0.4 * mp).unwrap();
    assert!((d2 - masing).abs() < 1e-15);
    assert_eq!(h.reversal_points().len(), 1);
    // New stick zone after the reversal: (1 - |dQ|/(2 mu P))^(1/3).
    assert!((h.stick_ratio() - 0.6f64.cbrt()).abs() < 1e-12);
    // Traction: mu p in the outer annulus with the sign of the unloading.
    let a = m.ellipse().a();
    let t_out = h.traction_at(0.95 * a, 0.0);
    assert!((t_out + 0.3 * m.ellipse().pressure_at(0.95 * a, 0.0)).abs() < 1e-9);
    // A minor loop -0.2 -> 0.3 -> -0.2 closes: back on the unloading branch.
    h.apply_force(0.3 * mp).unwrap();
    assert_eq!(h.reversal_points().len(), 2);
    let d_back = h.apply_force(-0.2 * mp).unwrap();
    assert!((d_back - d2).abs() < 1e-15);
    assert_eq!(h.reversal_points().len(), 1, "the minor loop is forgotten");
    // Continuing past -0.6 mu P rejoins the virgin curve.
    let d3 = h.apply_force(-0.7 * mp).unwrap();
    assert!((d3 - m.displacement(-0.7 * mp).unwrap()).abs() < 1e-15);
    assert!(h.reversal_points().is_empty());
    // Force beyond mu P is refused and leaves the state unchanged.
    let err = h.apply_force(1.01 * mp).unwrap_err();
    assert_eq!(err.field(), Some("tangential_force"));
    assert_eq!(h.force(), -0.7 * mp);
}

/// Displacement control with gross slip: the loop of amplitude delta* > delta_s is the
/// full Masing loop plus the sliding parallelogram, W = (6/5) mu² P² C + 4 mu P
/// (delta* - delta_s). Trapezoid rule, 40 000 steps: 1e-5.
#[test]
fn displacement_control_with_gross_slip() {
    let (m, _) = sphere_contact();
    let ds = m.slip_displacement();
    let mp = m.limit_force();
    let amp = 1.8 * ds;
    let mut h = m.history();
    let q = h.apply_displacement(amp).unwrap();
    assert_eq!(q, mp);
    assert!(h.is_sliding());
    let n = 40_000;
    let (mut area, mut last) = (0.0, (h.force(), h.displacement()));
    for i in 1..=n {
        let d = amp * (2.0 * PI * i as f64 / n as f64).cos();
        let q = h.apply_displacement(d).unwrap();
        assert!(q.abs() <= mp * (1.0 + 1e-12));
        area += 0.5 * (q + last.0) * (d - last.1);
        last = (q, d);
    }
    let w = 1.2 * mp * mp * m.no_slip_compliance() + 4.0 * mp * (amp - ds);
    assert!(rel(area, w) < 1e-5, "{area} vs {w}");
    // Below the slip limit, displacement control is the inverse of force control.
    let mut h = m.history();
    let q = h.apply_displacement(0.5 * ds).unwrap();
    assert!(rel(m.displacement(q).unwrap(), 0.5 * ds) < 1e-12);
    assert!(!h.is_sliding());
}

// ---------------------------------------------------------------------------------------
// Carter
// ---------------------------------------------------------------------------------------

/// Carter's curve F/(mu P') = 1 - (1 - xi/xi_s)², xi_s = mu a/R (Johnson 1985 §8.3),
/// and the worked table of the thesis "Study of the traction curves" (Fig. 3-5, normalized creepage, 4 digits).
#[test]
fn carter_curve_against_closed_form() {
    let c = Carter::from_line_contact(
        &LineContact::new(20.0, 30.0, STEEL, STEEL).unwrap(),
        600.0,
        0.08,
    )
    .unwrap();
    let r = 1.0 / (1.0 / 20.0 + 1.0 / 30.0);
    let a = c.semi_width();
    let xs = c.saturation_creepage();
    assert!(rel(xs, 0.08 * a / r) < 1e-12, "xi_s = mu a/R");
    for (s, f) in [
        (0.25, 0.4375),
        (0.5, 0.75),
        (0.75, 0.9375),
        (1.0, 1.0),
        (2.0, 1.0),
    ] {
        assert!((c.normalized_force(s * xs).unwrap() - f).abs() < 1e-12);
        assert!((c.normalized_force(-s * xs).unwrap() + f).abs() < 1e-12);
    }
    // The thesis "Study of the traction curves", table of Fig. 3-5: (xi, F_T/(mu F_N)) with xi already normalized.
    let unit = Carter::new(1.0, 1.0, 2.0, 1.0).unwrap(); // xi_s = 2 mu p0/E* = 1
    for (xi, f) in [
        (0.07, 0.1351),
        (0.14, 0.2604),
        (0.35, 0.5775),
        (0.56, 0.8064),
        (0.9, 0.99),
    ] {
        assert!(
            (unit.normalized_force(xi).unwrap() - f).abs() < 5e-5,
            "xi={xi}"
        );
    }
    // Initial slope pi a E*/2 per unit length (central difference, 1e-6).
    let h = 1e-6 * xs;
    let slope = (c.force_per_length(-h).unwrap() - c.force_per_length(h).unwrap()) / (2.0 * h);
    assert!(rel(slope, c.creep_coefficient()) < 1e-6);
    assert!(
        rel(
            c.creep_coefficient(),
            0.5 * PI * a * effective_modulus(&STEEL, &STEEL)
        ) < 1e-14
    );
    // Inverse.
    assert!(rel(c.creepage_from_force(0.75).unwrap(), 0.5 * xs) < 1e-12);
    assert!(c.creepage_from_force(1.0).is_err());
}

/// Carter's traction: equals mu p in the rear slip zone, is below it in the leading
/// adhesion zone of width 2c = 2a (1 - xi/xi_s), and integrates to the force
/// (midpoint rule, 20 000 points: 1e-5).
#[test]
fn carter_traction_integrates_to_the_force() {
    let c = Carter::new(0.2, 1200.0, 115_384.6, 0.1).unwrap();
    let a = 0.2;
    for s in [0.2, 0.6, 0.95] {
        let xi = s * c.saturation_creepage();
        let half = c.stick_half_width(xi).unwrap();
        assert!(rel(half, a * (1.0 - s)) < 1e-12);
        let n = 20_000;
        let dx = 2.0 * a / n as f64;
        let mut f = 0.0;
        for i in 0..n {
            let x = -a + (i as f64 + 0.5) * dx;
            let q = c.traction_at(xi, x).unwrap();
            let bound = 0.1 * 1200.0 * (1.0 - (x / a).powi(2)).sqrt();
            assert!(
                q <= 1e-12 && -q <= bound + 1e-9,
                "opposes the creepage, |q| <= mu p"
            );
            if x < a - 2.0 * half - 1e-9 {
                assert!((q + bound).abs() < 1e-9, "rear slip zone");
            } else if x > a - 2.0 * half + 1e-3 * a && x < a - 1e-3 * a {
                assert!(-q < bound - 1e-9, "leading adhesion zone");
            }
            f += q * dx;
        }
        assert!(rel(f, c.force_per_length(xi).unwrap()) < 1e-5, "s={s}");
    }
}

// ---------------------------------------------------------------------------------------
// Kalker
// ---------------------------------------------------------------------------------------

/// Published points of Kalker's Table E.3, at the table's columns (printed digits:
/// tolerance half a unit of the last printed digit).
#[test]
fn kalker_coefficients_match_the_published_table() {
    // (a/b, nu, C11, C22, C23, printed-digit tolerance)
    let points = [
        (1.0, 0.25, 4.12, 3.67, 1.47, 5e-3),
        (0.5, 0.0, 2.88, 2.88, 0.827, 5e-4),
        (0.2, 0.5, 4.81, 2.66, 0.809, 5e-4),
        (1.0 / 0.3, 0.25, 6.34, 6.40, 4.32, 5e-3),
        (10.0, 0.5, 12.9, 16.0, 18.0, 5e-2),
        (1.0 / 0.8, 0.25, 4.36, 3.99, 1.75, 5e-3),
    ];
    for (g, nu, c11, c22, c23, tol) in points {
        let c = creep_coefficients(g, nu).unwrap();
        assert!((c.c11 - c11).abs() <= tol, "a/b={g} nu={nu}: C11 {}", c.c11);
        assert!((c.c22 - c22).abs() <= tol, "a/b={g} nu={nu}: C22 {}", c.c22);
        assert!((c.c23 - c23).abs() <= tol, "a/b={g} nu={nu}: C23 {}", c.c23);
    }
    // The typo of one public port (C23 at g = 0.8, nu = 0.25 typed as 1.15) is not ours.
    assert_eq!(TABLE_A_OVER_B[7][2][1], 1.25);
}

/// Checksum of the typed table: the sum of all 180 entries, computed from the reference
/// markdown file by a script (not by this code), and of each half.
#[test]
fn kalker_table_checksum() {
    let sum = |t: &[[[f64; 3]; 3]; 10]| t.iter().flatten().flatten().sum::<f64>();
    assert!(
        (sum(&TABLE_A_OVER_B) - 238.07).abs() < 1e-9,
        "{}",
        sum(&TABLE_A_OVER_B)
    );
    assert!(
        (sum(&TABLE_B_OVER_A) - 477.66).abs() < 1e-9,
        "{}",
        sum(&TABLE_B_OVER_A)
    );
    // Both halves meet at the circle.
    assert_eq!(TABLE_A_OVER_B[9], TABLE_B_OVER_A[9]);
}

/// The interpolation rule: linear in g between rows (exact mean at a mid-row point), the
/// 1/C parabola in nu, and the worked values of the reference file (3 decimals).
#[test]
fn kalker_interpolation_rule() {
    // Linear in g at nu = 0 (a column, so no nu interpolation): g = 0.55 is the mean.
    let c = creep_coefficients(0.55, 0.0).unwrap();
    assert!((c.c11 - 0.5 * (2.88 + 2.98)).abs() < 1e-12);
    assert!((c.c23 - 0.5 * (0.827 + 0.930)).abs() < 1e-12);
    let c = creep_coefficients(1.0 / 0.45, 0.5).unwrap();
    assert!((c.c22 - 0.5 * (5.48 + 4.90) * 1.0).abs() > 0.0); // g = b/a = 0.45
    assert!((c.c22 - 0.5 * (6.31 + 5.56)).abs() < 1e-12);
    // The 1/C parabola at nu = 0.3, circle.
    let inv = |c0: f64, c1: f64, c2: f64| {
        let nu: f64 = 0.3;
        1.0 / (8.0 * (nu - 0.25) * (nu - 0.5) / c0 - 16.0 * nu * (nu - 0.5) / c1
            + 8.0 * nu * (nu - 0.25) / c2)
    };
    let c = creep_coefficients(1.0, 0.3).unwrap();
    assert!((c.c11 - inv(3.40, 4.12, 5.20)).abs() < 1e-12);
    // Worked values (reference file), 3 decimals.
    for (g, nu, w) in [
        (0.5, 0.28, [3.734, 3.026, 0.943]),
        (1.0, 0.28, [4.226, 3.705, 1.488]),
        (2.0, 0.28, [5.204, 4.971, 2.657]),
        (1.0, 0.3, [4.300, 3.729, 1.500]),
    ] {
        let c = creep_coefficients(g, nu).unwrap();
        for (v, e) in [c.c11, c.c22, c.c23].into_iter().zip(w) {
            assert!((v - e).abs() < 5e-4 + 1e-12, "a/b={g} nu={nu}: {v} vs {e}");
        }
    }
    // Monotone in g between and across rows (C11 grows as the contact gets longer).
    let mut last = 0.0;
    for k in 1..=100 {
        let g = 0.1 + 9.9 * k as f64 / 100.0;
        let c = creep_coefficients(g, 0.3).unwrap();
        assert!(c.c11 > last);
        last = c.c11;
    }
}

/// Below g = 0.1 the asymptotes of the reference file take over; they join the table
/// within 6 % (the accuracy of the asymptotes there) and have the published limits.
#[test]
fn kalker_asymptotes() {
    for nu in [0.0, 0.25, 0.5] {
        for g in [0.1, 10.0] {
            let t = creep_coefficients(g, nu).unwrap();
            let s = creep_coefficients(if g < 1.0 { 0.099_999_9 } else { 10.000_01 }, nu).unwrap();
            for (x, y) in [(t.c11, s.c11), (t.c22, s.c22), (t.c23, s.c23)] {
                assert!(rel(y, x) < 0.065, "g={g} nu={nu}: {y} vs {x}");
            }
        }
    }
    let c = creep_coefficients(1e-3, 0.25).unwrap();
    assert!((c.c11 - PI * PI / (4.0 * 0.75)).abs() < 1e-12);
    assert!((c.c22 - PI * PI / 4.0).abs() < 1e-12);
}

/// Linear creep forces with c = sqrt(a b), and Kalker's combined material.
#[test]
fn kalker_linear_forces() {
    let e = ContactEllipse::new(0.6, 0.3, 800.0).unwrap();
    let k = KalkerLinear::new(e, &STEEL, &STEEL, 0.25).unwrap();
    let coef = creep_coefficients(2.0, 0.3).unwrap();
    let g = STEEL.shear_modulus();
    let c = (0.18f64).sqrt();
    let cr = Creepage {
        longitudinal: 1e-4,
        lateral: -2e-4,
        spin: 0.01,
    };
    let [fx, fy] = k.forces(&cr).unwrap();
    assert!(rel(fx, -g * c * c * coef.c11 * 1e-4) < 1e-14);
    assert!(rel(fy, -g * c * c * (coef.c22 * -2e-4 + c * coef.c23 * 0.01)) < 1e-14);
    assert!(
        rel(
            k.saturation_creepage(),
            0.25 * 800.0 / (g * 0.18 * coef.c11)
        ) < 1e-14
    );
    assert!((k.normalized_force(k.saturation_creepage()).unwrap() - 1.0).abs() < 1e-14);
    assert!(
        k.normalized_force(3.0 * k.saturation_creepage()).unwrap() > 2.9,
        "unclipped"
    );
    // Dissimilar: 2/G = 1/G1 + 1/G2, nu = G/2 (nu1/G1 + nu2/G2).
    let al = ElasticMaterial::new(70_000.0, 0.33).unwrap();
    let km = KalkerMaterial::new(&STEEL, &al).unwrap();
    let (g1, g2) = (STEEL.shear_modulus(), al.shear_modulus());
    assert!(rel(km.shear_modulus, 2.0 / (1.0 / g1 + 1.0 / g2)) < 1e-14);
    assert!(
        rel(
            km.poisson_ratio,
            0.5 * km.shear_modulus * (0.3 / g1 + 0.33 / g2)
        ) < 1e-14
    );
}

// ---------------------------------------------------------------------------------------
// FASTSIM
// ---------------------------------------------------------------------------------------

fn fastsim(a: f64, b: f64, n: [usize; 2]) -> Fastsim {
    let e = ContactEllipse::new(a, b, 1000.0).unwrap();
    let o = FastsimOptions {
        elements: n,
        ..FastsimOptions::default()
    };
    Fastsim::new(e, &STEEL, &STEEL, 0.3, o).unwrap()
}

/// Small-creepage slope: FASTSIM's flexibilities L1, L2, L3 reproduce Kalker's linear
/// theory. Discretisation error of the slope (pure creepage): +1/(2 ny²) from the
/// midpoint rule in y (0.02 % at 50 strips); spin: O(1/nx²) as well. Tolerance 0.1 % at
/// 50x50, and the error falls with refinement.
#[test]
fn fastsim_slope_equals_kalker_linear() {
    for (a, b) in [(0.5, 0.5), (0.3, 0.6), (0.8, 0.2)] {
        let f = fastsim(a, b, [50, 50]);
        let k = KalkerLinear::new(*f.ellipse(), &STEEL, &STEEL, 0.3).unwrap();
        let tiny = 1e-9;
        for cr in [
            Creepage {
                longitudinal: tiny,
                ..Creepage::default()
            },
            Creepage {
                lateral: tiny,
                ..Creepage::default()
            },
            Creepage {
                spin: tiny,
                ..Creepage::default()
            },
        ] {
            let s = f.solve(&cr).unwrap();
            let [kx, ky] = k.forces(&cr).unwrap();
            let (num, reference) = if cr.longitudinal != 0.0 {
                (s.forces[0], kx)
            } else {
                (s.forces[1], ky)
            };
            assert!(
                rel(num, reference) < 1e-3,
                "a={a} b={b} {cr:?}: {num} vs {reference}"
            );
            assert_eq!(s.adhesion_fraction, 1.0);
        }
    }
    // Convergence of the longitudinal slope error: 1/(2 ny²).
    let mut last = f64::INFINITY;
    for n in [5, 10, 20, 50, 100] {
        let f = fastsim(0.5, 0.5, [n, n]);
        let k = KalkerLinear::new(*f.ellipse(), &STEEL, &STEEL, 0.3).unwrap();
        let cr = Creepage::longitudinal(1e-9);
        let err = rel(f.solve(&cr).unwrap().forces[0], k.forces(&cr).unwrap()[0]);
        assert!((err - 0.5 / (n * n) as f64).abs() < 1e-9, "n={n}: {err}");
        assert!(err < last);
        last = err;
    }
}

/// Against the closed-form simplified theory (pure longitudinal creepage, parabolic
/// bound): the FASTSIM error at 50x50 is below 0.05 % of mu P over the whole curve
/// (measured 2.5e-4) and falls with refinement at second order (20: 1.6e-3, 200: 1e-5).
/// The normalized curve does not depend on a/b.
#[test]
fn fastsim_converges_to_the_simplified_theory() {
    let us = [0.2, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.3];
    let max_err = |f: &Fastsim| {
        let k = KalkerLinear::new(*f.ellipse(), &STEEL, &STEEL, 0.3).unwrap();
        let sat = k.saturation_creepage(); // u = xi/sat
        us.iter()
            .map(|&u| {
                let num = f.normalized_force(u * sat).unwrap();
                (num - longitudinal_simplified_theory(u).unwrap()).abs()
            })
            .fold(0.0, f64::max)
    };
    let e20 = max_err(&fastsim(0.5, 0.5, [20, 20]));
    let e50 = max_err(&fastsim(0.5, 0.5, [50, 50]));
    let e200 = max_err(&fastsim(0.5, 0.5, [200, 200]));
    assert!(e50 < 5e-4, "50x50: {e50}");
    assert!(e200 < e50 && e50 < e20, "{e20} {e50} {e200}");
    assert!(e200 < e50 / 10.0, "second order: {e50} -> {e200}");
    for (a, b) in [(0.3, 0.6), (0.8, 0.2)] {
        assert!(max_err(&fastsim(a, b, [50, 50])) < 5e-4, "a/b = {}", a / b);
    }
}

/// Saturation: at large creepage the whole contact slides and |F| = mu P exactly (the
/// cell pressures carry exactly P); with spin |F| stays <= mu P.
#[test]
fn fastsim_saturates_at_mu_p() {
    let f = fastsim(0.4, 0.25, [50, 50]);
    let mp = 0.3 * 1000.0;
    for cr in [
        Creepage::longitudinal(0.05),
        Creepage {
            lateral: -0.05,
            ..Creepage::default()
        },
    ] {
        let s = f.solve(&cr).unwrap();
        let ft = s.forces[0].hypot(s.forces[1]);
        assert!((ft - mp).abs() < 1e-9 * mp, "{cr:?}: {ft}");
        assert_eq!(s.adhesion_fraction, 0.0);
    }
    for spin in [0.0, 0.5, 2.0, 10.0] {
        let s = f
            .solve(&Creepage {
                longitudinal: 0.004,
                lateral: 0.002,
                spin,
            })
            .unwrap();
        assert!(s.forces[0].hypot(s.forces[1]) <= mp * (1.0 + 1e-12));
    }
    // Elliptic (Hertz) bound saturates at mu P too.
    let e = *f.ellipse();
    let o = FastsimOptions {
        pressure: PressureShape::Elliptic,
        ..FastsimOptions::default()
    };
    let fe = Fastsim::new(e, &STEEL, &STEEL, 0.3, o).unwrap();
    assert!((fe.solve(&Creepage::longitudinal(-1.0)).unwrap().forces[0] - mp).abs() < 1e-9 * mp);
}

/// The adhesion area shrinks monotonically as the creepage grows, from 1 to 0, and the
/// force grows monotonically (pure longitudinal and pure lateral creepage).
#[test]
fn fastsim_adhesion_area_shrinks_monotonically() {
    let f = fastsim(0.5, 0.35, [50, 50]);
    let k = KalkerLinear::new(*f.ellipse(), &STEEL, &STEEL, 0.3).unwrap();
    let coef = k.coefficients();
    for lateral in [false, true] {
        // Up to 4 times the linear saturation creepage (full slip at 3.4 times).
        let span = 4.0 * k.saturation_creepage() * if lateral { coef.c11 / coef.c22 } else { 1.0 };
        let (mut last_area, mut last_force) = (f64::INFINITY, -1.0);
        for k in 0..=60 {
            let xi = span * k as f64 / 60.0;
            let cr = if lateral {
                Creepage {
                    lateral: xi,
                    ..Creepage::default()
                }
            } else {
                Creepage::longitudinal(xi)
            };
            let s = f.solve(&cr).unwrap();
            let force = -(if lateral { s.forces[1] } else { s.forces[0] });
            assert!(s.adhesion_fraction <= last_area, "xi={xi}");
            assert!(force >= last_force - 1e-12, "xi={xi}");
            last_area = s.adhesion_fraction;
            last_force = force;
        }
        assert_eq!(last_area, 0.0);
    }
}

/// Circular contact, pure longitudinal creepage, the published FASTSIM behaviour
/// (Kalker 1982): slope G c² C11 at the origin, adhesion at the leading edge and slip at
/// the trailing edge, saturation of the parabolic-bound theory at u = G c² C11 xi/(mu P)
/// = 32/(3 pi) = 3.395 (outer strips first), never above mu P. Values at 50x50 within
/// 0.05 % of mu P of the closed form.
#[test]
fn fastsim_circular_longitudinal_behaviour() {
    let f = fastsim(0.5, 0.5, [50, 50]);
    let k = KalkerLinear::new(*f.ellipse(), &STEEL, &STEEL, 0.3).unwrap();
    let sat = k.saturation_creepage();
    let mut field = f.new_field();
    let s = f
        .solve_field(&Creepage::longitudinal(sat), &mut field)
        .unwrap(); // u = 1
    assert!((-s.forces[0] / 300.0 - longitudinal_simplified_theory(1.0).unwrap()).abs() < 5e-4);
    // Along the central strip: adhesion from the leading edge, then slip to the rear.
    let nx = 50;
    let centre = 25 * nx;
    assert!(field.adhesion[centre]);
    assert!(!field.adhesion[centre + nx - 1]);
    let switch = (0..nx).filter(|&i| field.adhesion[centre + i]).count();
    assert!(
        (0..switch).all(|i| field.adhesion[centre + i]),
        "one adhesion zone at the front"
    );
    // Traction opposes the creepage and is bounded by mu p.
    for (idx, q) in field.traction.iter().enumerate() {
        assert!(q[0] <= 0.0 && q[1].abs() < 1e-12);
        let [x, y] = f.cell_centre(idx);
        assert!(x.abs() <= 0.5 && y.abs() <= 0.5);
    }
    // Just below and above the full-slip creepage.
    assert!(
        f.solve(&Creepage::longitudinal(3.3 * sat))
            .unwrap()
            .adhesion_fraction
            > 0.0
    );
    let full = f.solve(&Creepage::longitudinal(3.45 * sat)).unwrap();
    assert_eq!(full.adhesion_fraction, 0.0);
    assert!((-full.forces[0] - 300.0).abs() < 1e-9);
    // The curve is below Kalker's line and above the Vermeulen-Johnson cubic near u = 2.
    let u = 2.0;
    let fu = f.normalized_force(u * sat).unwrap();
    let vj = 1.0 - (1.0 - u / 3.0f64).powi(3);
    assert!(
        fu < u && fu < vj,
        "{fu} vs linear {u} and Vermeulen-Johnson {vj}"
    );
}

/// Carter, Kalker linear and FASTSIM (μ = 0.05) on the ellipse of a 1500 N Hertz contact
/// (R 20 / 20 against 20 / 200 mm), rolling along the minor axis.
fn carter_kalker_fastsim() -> (ContactEllipse, Vec<Box<dyn TractionCurve>>) {
    let hertz = HertzPointContact::new(
        PointGeometry::new([20.0, 20.0], [20.0, 200.0], 0.0).unwrap(),
        STEEL,
        STEEL,
    )
    .unwrap();
    let e = ContactEllipse::from_hertz(&hertz.solve_force(1500.0).unwrap(), EllipseAxis::Minor)
        .unwrap();
    let models: Vec<Box<dyn TractionCurve>> = vec![
        Box::new(Carter::from_ellipse(&e, &STEEL, &STEEL, 0.05).unwrap()),
        Box::new(KalkerLinear::new(e, &STEEL, &STEEL, 0.05).unwrap()),
        Box::new(Fastsim::new(e, &STEEL, &STEEL, 0.05, FastsimOptions::default()).unwrap()),
    ];
    (e, models)
}

/// The traction-curve interface: all three models start at 0, are odd, and Carter and
/// FASTSIM end at 1.
#[test]
fn traction_curves_share_one_interface() {
    let (_, models) = carter_kalker_fastsim();
    let xs: Vec<f64> = (0..=100).map(|i| 0.01 * i as f64 / 100.0).collect();
    for m in &models {
        let curve = m.traction_curve(&xs).unwrap();
        assert_eq!(curve[0], 0.0, "{}", m.name());
        assert!(
            (m.normalized_force(-0.003).unwrap() + m.normalized_force(0.003).unwrap()).abs()
                < 1e-12
        );
        if m.name() != "kalker_linear" {
            assert!((curve[100] - 1.0).abs() < 1e-9, "{}", m.name());
            assert!(curve.windows(2).all(|w| w[1] >= w[0] - 1e-12));
        }
    }
    assert_eq!(
        models.iter().map(|m| m.name()).collect::<Vec<_>>(),
        ["carter", "kalker_linear", "fastsim"]
    );
}

/// Creepages over the whole f64 range, both signs: zero, subnormal, tiny, the curves'
/// working range, and huge up to `f64::MAX` (issue 14).
fn creepages_over_the_f64_range() -> Vec<f64> {
    let mut xs = vec![0.0, 5e-324, 1e-310, 1e-300, 1e-200, 1e-100, 1e-20, 1e-10];
    xs.extend((0..=60).map(|i| 1e-6 * 10f64.powf(i as f64 / 10.0)));
    xs.extend([10.0, 1e3, 1e10, 1e100, 1e200, 1e300, f64::MAX]);
    let mut all: Vec<f64> = xs.iter().rev().map(|x| -x).collect();
    all.extend(xs);
    all
}

/// Every traction curve over the full f64 range of creepage: finite, odd, monotone
/// non-decreasing; Carter, FASTSIM and the asperity model bounded by 1 and saturated at 1
/// (to 1e-12) far out; Kalker's linear theory finite (an error, not inf, where its
/// unclipped line would overflow). Infinite and NaN creepages are errors naming `creepage`.
/// FASTSIM with all three creepages huge slides everywhere, finite and unchanged in force.
#[test]
fn traction_curves_are_monotone_and_bounded_over_the_f64_range() {
    let (e, mut models) = carter_kalker_fastsim();
    models.push(Box::new(AsperityCurve::new(
        AsperityTraction::new(AsperityTractionParams::new(
            NominalContact::Circular {
                half_width: 0.4,
                max_pressure: None,
            },
            680.0,
            0.3,
            STEEL,
            [0.02, 0.02],
            0.05,
        ))
        .unwrap(),
    )));
    let xs = creepages_over_the_f64_range();
    for m in &models {
        let mut last = f64::NEG_INFINITY;
        for &x in &xs {
            let f = match m.normalized_force(x) {
                Ok(f) => f,
                // Only the linear theory may refuse, and only where its line leaves f64.
                Err(e) if m.name() == "kalker_linear" && x.abs() > 1e300 => {
                    assert_eq!(e.field(), Some("creepage"), "{e}");
                    continue;
                }
                Err(e) => panic!("{} at {x:e}: {e}", m.name()),
            };
            assert!(f.is_finite(), "{} at {x:e}: {f}", m.name());
            assert!(
                f >= last,
                "{} not monotone at {x:e}: {f} < {last}",
                m.name()
            );
            last = f;
            assert_eq!(
                m.normalized_force(-x).unwrap(),
                -f,
                "{} odd at {x:e}",
                m.name()
            );
            if m.name() != "kalker_linear" {
                assert!(f.abs() <= 1.0, "{} at {x:e}: |{f}| > 1", m.name());
                if x.abs() >= 10.0 {
                    // Saturated: mu F_N up to the rounding of the cells' sum.
                    assert!(
                        1.0 - f.abs() <= 1e-12,
                        "{} saturates at {x:e}: {f}",
                        m.name()
                    );
                }
            }
        }
        for bad in [f64::INFINITY, f64::NEG_INFINITY, f64::NAN] {
            let e = m.normalized_force(bad).unwrap_err();
            assert_eq!(e.field(), Some("creepage"), "{} at {bad}: {e}", m.name());
        }
    }
    // Spin turns the slip across the contact, so |F| < mu P in full slip; the result is
    // the same at every huge magnitude (only the creepages' ratios matter).
    let fastsim = Fastsim::new(e, &STEEL, &STEEL, 0.05, FastsimOptions::default()).unwrap();
    let at = |c: f64| {
        fastsim
            .solve(&Creepage {
                longitudinal: c,
                lateral: -c,
                spin: c,
            })
            .unwrap()
    };
    let reference = at(1e20);
    assert_eq!(reference.adhesion_area, 0.0);
    for c in [f64::MAX, 1e300, 1e60] {
        let s = at(c);
        for (got, want) in s.forces.iter().zip(reference.forces) {
            assert!(
                (got - want).abs() <= 1e-12 * 75.0,
                "{s:?} vs {reference:?} at {c:e}"
            );
        }
        assert!((s.spin_moment - reference.spin_moment).abs() <= 1e-12 * 75.0);
        assert!(s.forces[0].hypot(s.forces[1]) <= 0.05 * 1500.0 * (1.0 + 1e-12));
    }
}

// ---------------------------------------------------------------------------------------
// Bad input
// ---------------------------------------------------------------------------------------

#[test]
fn bad_input_names_the_field() {
    let e = ContactEllipse::new(0.5, 0.5, 1000.0).unwrap();
    for mu in [0.0, -0.1, f64::NAN, f64::INFINITY] {
        assert_eq!(
            Mindlin::new(e, STEEL, STEEL, mu).unwrap_err().field(),
            Some("friction_coefficient")
        );
        assert_eq!(
            KalkerLinear::new(e, &STEEL, &STEEL, mu)
                .unwrap_err()
                .field(),
            Some("friction_coefficient")
        );
        assert_eq!(
            Fastsim::new(e, &STEEL, &STEEL, mu, FastsimOptions::default())
                .unwrap_err()
                .field(),
            Some("friction_coefficient")
        );
        assert_eq!(
            Carter::new(0.2, 1000.0, 1e5, mu).unwrap_err().field(),
            Some("friction_coefficient")
        );
    }
    // Zero or NaN load.
    assert_eq!(
        ContactEllipse::new(0.5, 0.5, 0.0).unwrap_err().field(),
        Some("normal_force")
    );
    assert_eq!(
        ContactEllipse::new(0.5, 0.5, f64::NAN).unwrap_err().field(),
        Some("normal_force")
    );
    let line = LineContact::new(10.0, 10.0, STEEL, STEEL).unwrap();
    assert!(Carter::from_line_contact(&line, 0.0, 0.1).is_err());
    // NaN creepage.
    let f = Fastsim::new(e, &STEEL, &STEEL, 0.3, FastsimOptions::default()).unwrap();
    let k = KalkerLinear::new(e, &STEEL, &STEEL, 0.3).unwrap();
    let c = Carter::new(0.2, 1000.0, 1e5, 0.3).unwrap();
    assert_eq!(
        f.normalized_force(f64::NAN).unwrap_err().field(),
        Some("creepage")
    );
    assert_eq!(
        k.normalized_force(f64::NAN).unwrap_err().field(),
        Some("creepage")
    );
    assert_eq!(
        c.normalized_force(f64::NAN).unwrap_err().field(),
        Some("creepage")
    );
    let nan = Creepage {
        lateral: f64::NAN,
        ..Creepage::default()
    };
    assert_eq!(f.solve(&nan).unwrap_err().field(), Some("creepage.lateral"));
    assert_eq!(
        k.forces(&nan).unwrap_err().field(),
        Some("creepage.lateral")
    );
    // Tangential force beyond mu P, negative amplitude.
    let m = Mindlin::new(e, STEEL, STEEL, 0.3).unwrap();
    assert_eq!(
        m.stick_ratio(301.0).unwrap_err().field(),
        Some("tangential_force")
    );
    assert_eq!(
        m.displacement(f64::NAN).unwrap_err().field(),
        Some("tangential_force")
    );
    assert_eq!(
        m.dissipated_energy_per_cycle(-1.0).unwrap_err().field(),
        Some("tangential_force")
    );
    let mut h = m.history();
    assert_eq!(
        h.apply_displacement(f64::INFINITY).unwrap_err().field(),
        Some("displacement")
    );
    // Grid and table ranges.
    let o = FastsimOptions {
        elements: [50, 0],
        ..FastsimOptions::default()
    };
    assert_eq!(
        Fastsim::new(e, &STEEL, &STEEL, 0.3, o).unwrap_err().field(),
        Some("elements[1]")
    );
    let cork = ElasticMaterial::new(30.0, -0.2).unwrap();
    assert_eq!(
        KalkerLinear::new(e, &cork, &cork, 0.3).unwrap_err().field(),
        Some("poisson_ratio")
    );
    // Error messages carry value and range.
    let msg = m.stick_ratio(301.0).unwrap_err().to_string();
    assert!(msg.contains("301") && msg.contains("mu P = 300"), "{msg}");
}
