//! The friction torque of the bearing element (issue 29 §5,
//! `kontakt_case::bearing_model::BearingElement`, module `bearing_model::friction`): with a
//! `[lubricant]` in its case every evaluation returns the bearing's friction torque, power
//! and breakdown from the loads it solved. Checked against the case's own friction report
//! for the same displacement and ring speeds (a case with all five degrees of freedom
//! prescribed at the element's displacement), to 1e-12: the ISO slice model of the 32008 X
//! (Manjunath et al. 2023 conditions) at rest, running, with the outer ring turning, and a
//! rib-contact tapered bearing with its rib share; power = torque × Δω; the sign of
//! `moment_nmm[2]`; ball bearings against their report; friction off without a lubricant and
//! "not built" for a thrust roller bearing; bad speeds refused naming the argument.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

#[path = "support/bearing_run.rs"]
mod bearing_run;

use bearing_run::{example, run};
use kontakt_bearing::friction::RPM_PER_RAD_S;
use kontakt_case::bearing_friction::FrictionReport;
use kontakt_case::bearing_model::{
    BearingElement, BearingElementOutput, ElementFriction, ElementFrictionStatus,
};

/// The `[lubricant]` table of `text` (up to the next table).
fn lubricant(text: &str) -> String {
    let start = text.find("[lubricant]").unwrap();
    let rest = &text[start..];
    let end = rest[1..].find("\n[").map_or(rest.len(), |i| i + 2);
    rest[..end].to_string()
}

/// The rib-contact bearing's oil, operating point and speed: the 32008 X example's oil
/// (FVA 3A at 55 °C), circulating, 1500 r/min.
fn rib_oil() -> String {
    format!(
        "\n{}\n[operating]\nsupply = \"circulating\"\n\n[speed]\ninner_rpm = 1500.0\n",
        lubricant(&example("bearing_32008x_friction.toml"))
    )
}

/// The equilibrium displacement `(δx, δy, δz, θx, θy)` of a case under its own `[load]`.
fn equilibrium(text: &str) -> [f64; 5] {
    let r = run(text).unwrap();
    let (d, t) = (r.displacement_mm, r.tilt_rad);
    [d[0], d[1], d[2], t[0], t[1]]
}

/// `text` with its `[load]` (and `[load.*]`) replaced by all five degrees of freedom
/// prescribed at `u` and its operating speed sweep removed.
fn prescribed(text: &str, u: [f64; 5]) -> String {
    let mut out = String::new();
    let mut in_load = false;
    for line in text.lines() {
        let t = line.trim_start();
        if t.starts_with('[') {
            in_load = t.starts_with("[load]") || t.starts_with("[load.");
        }
        if !in_load && !t.starts_with("sweep_inner_rpm") {
            out.push_str(line);
            out.push('\n');
        }
    }
    out.push_str(&format!(
        "\n[load]\nforce_n = [0.0, 0.0, 0.0]\nmoment_nmm = [0.0, 0.0]\n\n[load.prescribed]\n\
         dx_mm = {:e}\ndy_mm = {:e}\ndz_mm = {:e}\ntilt_x_rad = {:e}\ntilt_y_rad = {:e}\n",
        u[0], u[1], u[2], u[3], u[4]
    ));
    out
}

/// `text` with the ring speeds of its `[speed]` table set to `rpm` (r/min).
fn at_speed(text: &str, rpm: [f64; 2]) -> String {
    let mut out: String = text
        .lines()
        .filter(|l| {
            !l.trim_start().starts_with("inner_rpm") && !l.trim_start().starts_with("outer_rpm")
        })
        .map(|l| format!("{l}\n"))
        .collect();
    out = out.replace(
        "[speed]\n",
        &format!(
            "[speed]\ninner_rpm = {:e}\nouter_rpm = {:e}\n",
            rpm[0], rpm[1]
        ),
    );
    out
}

/// The example `name` with [`rib_oil`]: the text, its equilibrium displacement and the
/// text with the five degrees of freedom prescribed there.
fn with_oil(name: &str) -> (String, [f64; 5], String) {
    let base = format!("{}\n{}", example(name), rib_oil());
    let u = equilibrium(&base);
    let text = prescribed(&base, u);
    (base, u, text)
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / a.abs().max(b.abs())
    }
}

/// The element's friction equals the report's, every field to 1e-12.
fn assert_same(what: &str, e: &ElementFriction, r: &FrictionReport) {
    let pairs = [
        ("torque", e.torque_nmm, r.total_nmm),
        ("cone", e.cone_nmm, r.cone_rolling_nmm + r.cone_sliding_nmm),
        ("cup", e.cup_nmm, r.cup_rolling_nmm + r.cup_sliding_nmm),
        ("rib", e.rib_nmm, r.rib_nmm),
        ("drag", e.drag_nmm, r.drag_nmm),
        ("power", e.power_w, r.power_w),
        // the report's inner-ring torque is the drive's, the element's the bearing's
        (
            "inner ring",
            e.inner_ring_nmm,
            if r.starting { 0.0 } else { -r.inner_ring_nmm },
        ),
    ];
    for (name, a, b) in pairs {
        assert!(
            rel(a, b) <= 1e-12 && a.is_finite(),
            "{what} {name}: element {a}, report {b}"
        );
    }
    assert_eq!(
        e.status,
        if r.starting {
            ElementFrictionStatus::Starting
        } else {
            ElementFrictionStatus::Running
        },
        "{what}"
    );
}

/// Power = torque × Δω, and `moment_nmm[2]` is the friction moment opposing Δω.
fn assert_balanced(what: &str, o: &BearingElementOutput) {
    let f = &o.friction;
    let dw = f.inner_speed_rad_s - f.outer_speed_rad_s;
    assert_eq!(o.moment_nmm[2], f.inner_ring_nmm, "{what}");
    if dw == 0.0 {
        assert_eq!((f.power_w, f.inner_ring_nmm), (0.0, 0.0), "{what}");
    } else {
        assert!(
            rel(f.power_w, 1e-3 * f.torque_nmm * dw.abs()) <= 1e-12,
            "{what}: P = {} W, M Δω = {} W",
            f.power_w,
            1e-3 * f.torque_nmm * dw.abs()
        );
        assert_eq!(f.inner_ring_nmm, -f.torque_nmm * dw.signum(), "{what}");
    }
    let shares = f.cone_nmm + f.cup_nmm + f.rib_nmm + f.drag_nmm;
    assert!(rel(shares, f.torque_nmm) <= 1e-12, "{what}: {f:?}");
}

/// The 32008 X (ISO slice model, 12.85 kN axial, FVA 3A at 55 °C): the element at the
/// case's equilibrium equals the report of the case prescribed there, at the case's
/// 1000 r/min, and after `set_speeds` at rest (starting torque), at 200 and 2200 r/min
/// and with the outer ring turning.
#[test]
fn iso_element_friction_is_the_case_report() {
    let base = example("bearing_32008x_friction.toml");
    let u = equilibrium(&base);
    let text = prescribed(&base, u);
    let mut e = BearingElement::from_toml(&text).unwrap();
    assert_eq!(e.speeds(), [1000.0 / RPM_PER_RAD_S, 0.0]);
    for rpm in [
        [1000.0, 0.0],
        [0.0, 0.0],
        [200.0, 0.0],
        [2200.0, 0.0],
        [300.0, 1200.0],
    ] {
        e.set_speeds(rpm[0] / RPM_PER_RAD_S, rpm[1] / RPM_PER_RAD_S)
            .unwrap();
        let o = e.evaluate(u, [0.0; 5]).unwrap();
        let report = run(&at_speed(&text, rpm)).unwrap();
        let f = report.friction.as_ref().unwrap();
        assert_eq!((f.inner_rpm, f.outer_rpm), (rpm[0], rpm[1]));
        let what = format!("32008 X at {rpm:?} r/min");
        assert_same(&what, &o.friction, f);
        assert_balanced(&what, &o);
        assert!(o.friction.torque_nmm > 0.0, "{what}");
        println!(
            "{what}: M = {:.3} N·mm (cone {:.3}, cup {:.3}), Mz = {:.3}, P = {:.4} W",
            o.friction.torque_nmm,
            o.friction.cone_nmm,
            o.friction.cup_nmm,
            o.moment_nmm[2],
            o.friction.power_w
        );
    }
    // the outer ring turning faster: the moment on the inner ring drives it forward
    e.set_speeds(0.0, 100.0).unwrap();
    let o = e.evaluate(u, [0.0; 5]).unwrap();
    assert!(o.moment_nmm[2] > 0.0, "{:?}", o.friction);
    // and the element's forces are those without friction (friction is about z only)
    let mut plain =
        BearingElement::from_toml(&prescribed(&example("bearing_32008x.toml"), u)).unwrap();
    let p = plain.evaluate(u, [0.0; 5]).unwrap();
    assert_eq!(p.friction.status, ElementFrictionStatus::Off);
    assert_eq!(p.moment_nmm[2], 0.0);
    assert_eq!(
        p.friction,
        ElementFriction::none(ElementFrictionStatus::Off, [0.0; 2])
    );
}

/// The rib-contact TRB of the rib study (15 kN axial + 6 kN radial, 1500 r/min, FVA 3A at
/// 55 °C): the rib share too; and at rest the starting torque with its rib share.
#[test]
fn rib_contact_element_friction_is_the_case_report() {
    let (_, u, text) = with_oil("bearing_rib_contact_60mm.toml");
    let mut e = BearingElement::from_toml(&text).unwrap();
    let o = e.evaluate(u, [0.0; 5]).unwrap();
    let report = run(&text).unwrap();
    let f = report.friction.as_ref().unwrap();
    assert_same("rib contact, 1500 r/min", &o.friction, f);
    assert_balanced("rib contact, 1500 r/min", &o);
    assert!(o.friction.rib_nmm > 0.0);
    println!("rib-contact TRB at 1500 r/min: {:?}", o.friction);
    // at rest (the load distribution planned at 1500 r/min: compare with the report of
    // the case at 1500 r/min whose friction speeds are set to rest is not possible; the
    // starting torque is finite, positive, with its rib share, and not applied)
    e.set_speeds(0.0, 0.0).unwrap();
    let s = e.evaluate(u, [0.0; 5]).unwrap();
    assert_eq!(s.friction.status, ElementFrictionStatus::Starting);
    assert!(s.friction.torque_nmm > 0.0 && s.friction.rib_nmm > 0.0);
    assert_balanced("rib contact at rest", &s);
}

/// Ball bearings: the element's friction is the case report's at the case's speed, to
/// 1e-12 — the 6205 (deep groove, oil bath, 3000 r/min) and the 7205 (angular contact, the
/// 32008 X's oil, 1500 r/min), both at speed (centrifugal forces in the loads); the inner
/// race is the breakdown's cone, the outer race its cup, no rib; at rest the starting
/// torque, reported and not applied.
#[test]
fn ball_bearing_element_friction_is_the_case_report() {
    for (what, base) in [
        ("6205", example("bearing_6205_friction.toml")),
        (
            "7205",
            format!("{}\n{}", example("bearing_7205.toml"), rib_oil()),
        ),
    ] {
        let u = equilibrium(&base);
        let text = prescribed(&base, u);
        let mut e = BearingElement::from_toml(&text).unwrap();
        let o = e.evaluate(u, [0.0; 5]).unwrap();
        let report = run(&text).unwrap();
        let f = report.friction.as_ref().unwrap();
        assert_same(what, &o.friction, f);
        assert_balanced(what, &o);
        assert!(
            o.friction.torque_nmm > 0.0 && o.friction.rib_nmm == 0.0,
            "{what}"
        );
        assert!(
            o.friction.cone_nmm > 0.0 && o.friction.cup_nmm > 0.0,
            "{what}"
        );
        println!("{what}: {:?}", o.friction);
        e.set_speeds(0.0, 0.0).unwrap();
        let s = e.evaluate(u, [0.0; 5]).unwrap();
        assert_eq!(s.friction.status, ElementFrictionStatus::Starting, "{what}");
        assert!(s.friction.torque_nmm > 0.0, "{what}");
        assert_balanced(&format!("{what} at rest"), &s);
    }
}

/// A thrust roller bearing with a lubricant: friction "not built" (zeros), the forces as
/// ever.
#[test]
fn thrust_bearing_friction_is_not_built() {
    let text = format!(
        "{}\n{}",
        example("bearing_81107_thrust.toml"),
        lubricant(&example("bearing_32008x_friction.toml"))
    );
    let u = equilibrium(&text);
    let mut e = BearingElement::from_toml(&text).unwrap();
    let o = e.evaluate(u, [0.0; 5]).unwrap();
    assert_eq!(o.friction.status, ElementFrictionStatus::NotBuilt);
    assert_eq!((o.friction.torque_nmm, o.moment_nmm[2]), (0.0, 0.0));
    assert!(o.max_element_load_n > 0.0);
}

/// Bad speeds: one line naming the argument, the value and the range; the element keeps
/// its speeds. A bad lubricant is refused at creation naming the case key.
#[test]
fn bad_speeds_name_the_argument() {
    let mut e = BearingElement::from_toml(&example("bearing_32008x_friction.toml")).unwrap();
    let before = e.speeds();
    for (w, name, value) in [
        ([f64::NAN, 0.0], "inner_rad_s", "NaN"),
        ([0.0, f64::INFINITY], "outer_rad_s", "inf"),
        ([2e4, 0.0], "inner_rad_s", "20000"),
    ] {
        let err = e.set_speeds(w[0], w[1]).unwrap_err().to_string();
        assert!(
            err.contains(&format!("{name} = {value}")) && err.contains("rad/s"),
            "{err}"
        );
        assert!(!err.contains('\n'), "{err}");
        assert_eq!(e.speeds(), before);
    }
    let bad = example("bearing_32008x_friction.toml")
        .replace("temperature_c = 55.0", "temperature_c = 500.0");
    let err = BearingElement::from_toml(&bad).unwrap_err().to_string();
    assert!(err.contains("lubricant.temperature_c"), "{err}");
    let bad = example("bearing_32008x_friction.toml")
        .replace("supply = \"circulating\"", "drag = \"schaeffler_m0\"");
    let err = BearingElement::from_toml(&bad).unwrap_err().to_string();
    assert!(err.contains("operating.drag"), "{err}");
}

/// The NJ cylindrical roller bearing with its roller ends on the ribs (10 kN radial +
/// 1.5 kN axial, 1500 r/min, FVA 3A at 55 °C): the report's torque now has the roller
/// end/rib share (`kontakt_bearing::friction::crb_rib`), and the element equals the report
/// to 1e-12, running and at rest (each from the case at that speed: the centrifugal
/// forces); under pure radial load the ribs, 10 µm away on each side, carry (next to)
/// nothing and the rib share vanishes.
#[test]
fn nj_cylindrical_element_friction_has_the_rib_share_of_the_report() {
    let (base, u, text) = with_oil("bearing_nj_crb_rib_contact.toml");
    for rpm in [[1500.0, 0.0], [0.0, 0.0]] {
        // the rib-contact model's load distribution carries the centrifugal force of the
        // case's [speed]: element and report from the same case
        let text = at_speed(&text, rpm);
        let mut e = BearingElement::from_toml(&text).unwrap();
        let o = e.evaluate(u, [0.0; 5]).unwrap();
        let report = run(&text).unwrap();
        let f = report.friction.as_ref().unwrap();
        let what = format!("NJ at {rpm:?} r/min");
        assert_same(&what, &o.friction, f);
        assert_balanced(&what, &o);
        assert!(o.friction.rib_nmm > 0.0, "{what}: {:?}", o.friction);
        assert!(
            f.warnings
                .iter()
                .all(|w| !w.contains("rib friction not computed")),
            "{:?}",
            f.warnings
        );
        println!(
            "{what}: M = {:.3} N·mm (rib {:.3}, cone {:.3}, cup {:.3}), P = {:.4} W",
            o.friction.torque_nmm,
            o.friction.rib_nmm,
            o.friction.cone_nmm,
            o.friction.cup_nmm,
            o.friction.power_w
        );
    }
    let radial = run(&base.replace(
        "force_n = [10000.0, 0.0, 1500.0]",
        "force_n = [10000.0, 0.0, 0.0]",
    ))
    .unwrap();
    let f = radial.friction.unwrap();
    assert!(f.total_nmm > 0.0);
    // (the solver leaves rib loads of the order of its tolerance: 2e-11 of the torque)
    assert!(
        f.rib_nmm <= 1e-9 * f.total_nmm,
        "{} of {}",
        f.rib_nmm,
        f.total_nmm
    );
}
