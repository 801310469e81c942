//! The bearing element (`kontakt_case::bearing_model::BearingElement`, issue 28 §4): a whole
//! bearing as one force element. Its reaction is minus the load of a `BearingModel` solve
//! with the same five displacements prescribed (to 1e-12), its stiffness the central
//! differences of that reaction, its damping `−β K v`; a lifted-off bearing is a status,
//! not an error; bad input is refused naming the argument.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message
#![allow(clippy::needless_range_loop)] // matrix entries by their indices, as in the formulas

use kontakt_case::bearing_model::{BearingElement, BearingElementStatus, prescribed_load};
use kontakt_case::{BearingCase, BearingModel, run_bearing_case};
use std::path::PathBuf;

/// Every example bearing: its file name and text.
fn examples() -> Vec<(String, String)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut out: Vec<(String, String)> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|entry| entry.unwrap().path())
        .filter_map(|p| {
            let name = p.file_name()?.to_string_lossy().into_owned();
            (name.starts_with("bearing_") && name.ends_with(".toml"))
                .then(|| (name, std::fs::read_to_string(&p).unwrap()))
        })
        .collect();
    out.sort();
    assert!(out.len() >= 6, "the example bearings: {out:?}");
    out
}

/// A loaded displacement of the example: its own equilibrium, 2 % further, with a small
/// tilt where the bearing is stiff in tilt (so that no entry of K is trivially zero).
fn loaded_displacement(text: &str) -> [f64; 5] {
    let case = BearingCase::from_toml_str(text).unwrap();
    let r = run_bearing_case(&case).unwrap();
    let u = [
        r.displacement_mm[0],
        r.displacement_mm[1],
        r.displacement_mm[2],
        r.tilt_rad[0],
        r.tilt_rad[1],
    ];
    let k = r.stiffness_matrix;
    std::array::from_fn(|i| {
        if i >= 3 && k[i][i] > 0.0 && u[i] == 0.0 {
            // a tilt of a tenth of the translation over the pitch radius scale (~25 mm)
            let t = u[0].abs().max(u[2].abs()) / 250.0;
            if i == 3 { t } else { -0.5 * t }
        } else {
            1.02 * u[i]
        }
    })
}

/// The load of a `BearingModel` solve with all five degrees of freedom prescribed at `u`:
/// `(Fx, Fy, Fz, Mx, My)` and the stiffness.
fn prescribed(model: &mut BearingModel, u: [f64; 5]) -> ([f64; 5], [[f64; 5]; 5]) {
    let r = model.solve(&prescribed_load(u)).unwrap();
    let (f, m) = (r.force_n, r.moment_nmm);
    ([f[0], f[1], f[2], m[0], m[1]], r.stiffness_matrix)
}

fn reaction(o: &kontakt_case::bearing_model::BearingElementOutput) -> [f64; 5] {
    [
        o.force_n[0],
        o.force_n[1],
        o.force_n[2],
        o.moment_nmm[0],
        o.moment_nmm[1],
    ]
}

/// |a − b| <= tol · scale, per component, with the scale the largest |entry| of forces
/// (0..3) and of moments (3..5) separately.
fn assert_close(what: &str, a: &[f64; 5], b: &[f64; 5], tol: f64) {
    for range in [0..3, 3..5] {
        let scale = a[range.clone()]
            .iter()
            .chain(&b[range.clone()])
            .fold(0.0_f64, |m, x| m.max(x.abs()));
        for i in range {
            assert!(
                (a[i] - b[i]).abs() <= tol * scale,
                "{what}[{i}]: {a:?} vs {b:?}"
            );
        }
    }
}

#[test]
fn reaction_is_minus_the_prescribed_displacement_solution() {
    for (name, text) in examples() {
        let u = loaded_displacement(&text);
        let case = BearingCase::from_toml_str(&text).unwrap();
        let mut model = BearingModel::new(&case).unwrap();
        let (load, k) = prescribed(&mut model, u);
        let mut e = BearingElement::from_toml(&text).unwrap();
        // twice: cold, then warm from the first call
        for call in 0..2 {
            let o = e.evaluate(u, [0.0; 5]).unwrap();
            assert_eq!(o.status, BearingElementStatus::Loaded, "{name}");
            assert!(o.max_element_load_n > 0.0, "{name}");
            // Mz is the friction moment (tests/bearing_element_friction.rs): 0 without a
            // lubricant
            assert_eq!(o.moment_nmm[2], o.friction.inner_ring_nmm, "{name}");
            if !text.contains("[lubricant]") {
                assert_eq!(o.moment_nmm[2], 0.0, "{name}");
            }
            assert_eq!(o.damping, [0.0; 5]);
            let minus = load.map(|f| -f);
            assert_close(&format!("{name} call {call}"), &reaction(&o), &minus, 1e-12);
            let kmax = k.iter().flatten().fold(0.0_f64, |m, x| m.max(x.abs()));
            for i in 0..5 {
                for j in 0..5 {
                    assert!(
                        (o.stiffness[i][j] - k[i][j]).abs() <= 1e-12 * kmax,
                        "{name} K[{i}][{j}]"
                    );
                }
            }
            assert!(o.message.is_empty(), "{name}: {}", o.message);
        }
        assert_eq!(e.model().warm_start(), Some(u), "{name}");
    }
}

/// `K[i][j] = −∂R_i/∂u_j` by central differences of the reaction: the step h is 1e-7 mm
/// (tilts 1e-7 mm over the pitch radius); the difference error is O(h²) but for slices
/// at the edge of contact (`q ∝ δ^(10/9)`), so the tolerance is 1e-6 (measured 2.7e-8) of
/// `sqrt(K_ii K_jj)` (floored at 1e-9 of the largest diagonal entry, tilts over a 25 mm
/// radius, for directions without stiffness).
#[test]
fn stiffness_is_the_central_difference_of_the_reaction() {
    let mut worst: f64 = 0.0;
    for (name, text) in examples() {
        let u = loaded_displacement(&text);
        let mut e = BearingElement::from_toml(&text).unwrap();
        let k = e.evaluate(u, [0.0; 5]).unwrap().stiffness;
        // the scale of K in N/mm: tilts times a nominal pitch radius of 25 mm; entries of
        // directions without stiffness are round-off below 1e-9 of it
        let d = [1.0, 1.0, 1.0, 1.0 / 25.0, 1.0 / 25.0];
        let k_ref = (0..5).map(|i| k[i][i] * d[i] * d[i]).fold(0.0, f64::max);
        assert!(k_ref > 0.0, "{name}");
        for j in 0..5 {
            let h = if j < 3 { 1e-7 } else { 1e-7 / 25.0 };
            let mut up = u;
            up[j] += h;
            let mut down = u;
            down[j] -= h;
            let rp = reaction(&e.evaluate(up, [0.0; 5]).unwrap());
            let rm = reaction(&e.evaluate(down, [0.0; 5]).unwrap());
            for i in 0..5 {
                let fd = -(rp[i] - rm[i]) / (2.0 * h);
                let scale = (k[i][i] * k[j][j]).sqrt().max(1e-9 * k_ref / (d[i] * d[j]));
                let err = (fd - k[i][j]).abs() / scale;
                worst = worst.max(err);
                assert!(
                    err <= 1e-6,
                    "{name} K[{i}][{j}] = {} vs central difference {fd}: {err:e}",
                    k[i][j]
                );
            }
        }
    }
    println!("largest central-difference error of K: {worst:e} of sqrt(K_ii K_jj)");
}

#[test]
fn damping_is_beta_times_stiffness_times_velocity() {
    let (_, text) = examples()
        .into_iter()
        .find(|(n, _)| n == "bearing_32008x.toml")
        .unwrap();
    let u = loaded_displacement(&text);
    let mut e = BearingElement::from_toml(&text).unwrap();
    let v = [3.0, -1.0, 2.0, 0.05, -0.02];
    let still = e.evaluate(u, [0.0; 5]).unwrap();
    // undamped: the velocity has no effect
    assert_eq!(e.evaluate(u, v).unwrap(), still);
    let beta = 1e-4;
    e.set_damping(beta).unwrap();
    assert_eq!(e.damping_s(), beta);
    let o = e.evaluate(u, v).unwrap();
    for i in 0..5 {
        let kv: f64 = (0..5).map(|j| still.stiffness[i][j] * v[j]).sum();
        let want = -beta * kv;
        assert!((o.damping[i] - want).abs() <= 1e-12 * want.abs().max(1e-300));
        let total = reaction(&o)[i];
        let elastic = reaction(&still)[i];
        assert!((total - (elastic + want)).abs() <= 1e-12 * total.abs().max(elastic.abs()));
    }
    assert!(o.damping.iter().any(|d| d.abs() > 1.0), "{:?}", o.damping);
    // refused: negative or non-finite, naming the argument; β is kept
    for bad in [-1.0, f64::NAN, f64::INFINITY] {
        let err = e.set_damping(bad).unwrap_err().to_string();
        assert!(err.contains("damping_s"), "{err}");
    }
    assert_eq!(e.damping_s(), beta);
}

#[test]
fn lifted_off_is_a_status_with_zero_force() {
    for (name, text) in examples() {
        let mut e = BearingElement::from_toml(&text).unwrap();
        // pulled 0.2 mm out of every contact: axially for a thrust, tapered or angular
        // bearing, radially for the others is not enough (the opposite side loads), so
        // use the axis for the axial types and a zero displacement with clearance for
        // none: every example has a direction that opens all its elements
        let u = if e.model().bearing_type() == "cylindrical" || name.contains("6205") {
            // an unloaded ring: zero displacement (with clearance or zero preload)
            [0.0; 5]
        } else {
            [0.0, 0.0, -0.2, 0.0, 0.0]
        };
        e.set_damping(1e-3).unwrap();
        let o = e.evaluate(u, [1.0, 2.0, 3.0, 0.1, 0.1]).unwrap();
        if text.contains("[speed]")
            && text.contains("roller_model = \"rib_contact\"")
            && e.model().bearing_type() == "tapered"
        {
            // at speed the centrifugal force drives every tapered roller along the cup into
            // the wedge against the cone's rib: the cone pulled out is followed, not freed
            assert_eq!(o.status, BearingElementStatus::Loaded, "{name}");
            assert!(reaction(&o)[2] < 0.0, "{name}: {:?}", reaction(&o));
            continue;
        }
        assert_eq!(o.status, BearingElementStatus::LiftedOff, "{name}");
        assert_eq!(reaction(&o), [0.0; 5], "{name}");
        assert_eq!(o.stiffness, [[0.0; 5]; 5], "{name}");
        assert!(o.message.contains("lifted off"), "{name}: {}", o.message);
        assert_eq!(e.model().warm_start(), None, "{name}");
    }
}

#[test]
fn bad_input_names_the_argument() {
    let (_, text) = examples()
        .into_iter()
        .find(|(n, _)| n == "bearing_7205.toml")
        .unwrap();
    let mut e = BearingElement::from_toml(&text).unwrap();
    let u = [0.001, 0.0, 0.01, 0.0, 0.0];
    let ok = e.evaluate(u, [0.0; 5]).unwrap();
    let expect_err = |e: &mut BearingElement, u: [f64; 5], v: [f64; 5], field: &str| {
        let err = e.evaluate(u, v).unwrap_err().to_string();
        assert!(err.contains(field), "{field}: {err}");
        err
    };
    let mut nan = u;
    nan[3] = f64::NAN;
    expect_err(&mut e, nan, [0.0; 5], "displacement[3] = NaN");
    let mut inf = [0.0; 5];
    inf[1] = f64::INFINITY;
    expect_err(&mut e, u, inf, "velocity[1] = inf");
    // beyond validity: a translation above the ball diameter 7.938 mm, a tilt moving the
    // ring by more than that at the pitch radius 19.25 mm
    let mut far = u;
    far[0] = 8.0;
    let err = expect_err(&mut e, far, [0.0; 5], "displacement[0] = 8");
    assert!(
        err.contains("7.938") && err.contains("bearing.ball_diameter_mm"),
        "{err}"
    );
    let mut tilt = u;
    tilt[4] = 0.5;
    let err = expect_err(&mut e, tilt, [0.0; 5], "displacement[4] = 0.5");
    assert!(err.contains("0.41236"), "{err}");
    // finite but overflowing: a damping force beyond f64 is refused, never inf
    e.set_damping(1e300).unwrap();
    let err = expect_err(&mut e, u, [1e300, 0.0, 0.0, 0.0, 0.0], "velocity");
    assert!(err.contains("overflows"), "{err}");
    e.set_damping(0.0).unwrap();
    // the element still works, from the same warm start
    assert_eq!(e.evaluate(u, [0.0; 5]).unwrap(), ok);
    // a case that is no bearing case, and an invalid bearing
    let err = BearingElement::from_toml("method = \"bearing\"\n")
        .unwrap_err()
        .to_string();
    assert!(err.contains("bearing"), "{err}");
    let bad = text.replace("balls = 12", "balls = 0");
    let err = BearingElement::from_toml(&bad).unwrap_err().to_string();
    assert!(err.contains("bearing.balls"), "{err}");
}
