//! The exported fmi2 functions, called as a host calls them (instantiate from a resources
//! folder with the case, set inputs, get outputs): the outputs equal the library's
//! elements bit for bit, the directional derivatives equal the stiffness and the
//! difference quotients of the outputs, bad input and illegal calls give `fmi2Error` or
//! `fmi2Discard` with a message naming the variable, FMU states restore the outputs.

#![allow(unsafe_code)] // calling the C API
#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt_case::bearing_model::BearingElement;
use kontakt_fmi::description::guid;
use kontakt_fmi::fmi2::*;
use kontakt_fmi::model::Model;
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
use std::ffi::c_void;

mod support;
use std::path::PathBuf;

const OK: i32 = 0;
const DISCARD: i32 = 2;
const ERROR: i32 = 3;

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn bearing_case() -> String {
    std::fs::read_to_string(repo().join("examples/bearing_32008x.toml")).unwrap()
}

fn contact_case() -> String {
    std::fs::read_to_string(repo().join("crates/kontakt-capi/examples/element_ball_on_flat.toml"))
        .unwrap()
}

/// An instance of the FMU of `case` (0: model exchange, 1: co-simulation), its case in a
/// resources folder of its own.
struct Fmu {
    c: *mut c_void,
    names: Vec<&'static str>,
}

impl Fmu {
    fn new(case: &str, fmu_type: i32, tag: &str) -> Self {
        let c = instantiate(case, fmu_type, tag, &guid(case));
        assert!(!c.is_null(), "instantiation of {tag} failed");
        let names = Model::from_case(case)
            .unwrap()
            .variables()
            .iter()
            .map(|v| v.name)
            .collect();
        Fmu { c, names }
    }

    fn vr(&self, name: &str) -> u32 {
        self.names.iter().position(|n| *n == name).unwrap() as u32
    }

    fn set(&self, names: &[&str], values: &[f64]) -> i32 {
        let vr: Vec<u32> = names.iter().map(|n| self.vr(n)).collect();
        // SAFETY: an instance; arrays of nvr elements.
        unsafe { fmi2SetReal(self.c, vr.as_ptr(), vr.len(), values.as_ptr()) }
    }

    fn get(&self, names: &[&str]) -> (i32, Vec<f64>) {
        let vr: Vec<u32> = names.iter().map(|n| self.vr(n)).collect();
        let mut v = vec![f64::NAN; vr.len()];
        // SAFETY: as above.
        let s = unsafe { fmi2GetReal(self.c, vr.as_ptr(), vr.len(), v.as_mut_ptr()) };
        (s, v)
    }

    fn derivative(&self, unknown: &[&str], known: &[&str], seed: &[f64]) -> (i32, Vec<f64>) {
        let u: Vec<u32> = unknown.iter().map(|n| self.vr(n)).collect();
        let k: Vec<u32> = known.iter().map(|n| self.vr(n)).collect();
        let mut out = vec![f64::NAN; u.len()];
        // SAFETY: as above.
        let s = unsafe {
            fmi2GetDirectionalDerivative(
                self.c,
                u.as_ptr(),
                u.len(),
                k.as_ptr(),
                k.len(),
                seed.as_ptr(),
                out.as_mut_ptr(),
            )
        };
        (s, out)
    }

    fn message(&self) -> String {
        // SAFETY: the component is an Instance of this library.
        unsafe { &*self.c.cast::<Instance>() }
            .last_message()
            .to_string()
    }

    /// Setup, initialization, and on to continuous-time mode (ME) or step complete (CS).
    fn start(&self, fmu_type: i32) {
        // SAFETY: an instance.
        unsafe {
            assert_eq!(fmi2SetupExperiment(self.c, 0, 0.0, 0.0, 0, 0.0), OK);
            assert_eq!(fmi2EnterInitializationMode(self.c), OK);
            assert_eq!(fmi2ExitInitializationMode(self.c), OK);
            if fmu_type == 0 {
                let mut info = std::mem::zeroed::<EventInfo>();
                assert_eq!(fmi2NewDiscreteStates(self.c, &mut info), OK);
                assert_eq!(info.new_discrete_states_needed, 0);
                assert_eq!(fmi2EnterContinuousTimeMode(self.c), OK);
            }
        }
    }
}

impl Drop for Fmu {
    fn drop(&mut self) {
        // SAFETY: from fmi2Instantiate, freed once.
        unsafe { fmi2FreeInstance(self.c) }
    }
}

/// `fmi2Instantiate` of `case` in a folder of the test's own.
fn instantiate(case: &str, fmu_type: i32, tag: &str, guid: &str) -> *mut c_void {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("fmi2")
        .join(tag);
    support::instantiate(case, fmu_type, &dir, guid)
}

const U: [&str; 5] = ["dx", "dy", "dz", "theta_x", "theta_y"];
const V: [&str; 5] = ["vx", "vy", "vz", "omega_x", "omega_y"];
const R: [&str; 5] = ["Fx", "Fy", "Fz", "Mx", "My"];

/// A displacement path of the 32008 X: radial and axial, a tilt, through lift-off.
fn path() -> Vec<[f64; 5]> {
    (0..12)
        .map(|k| {
            let t = k as f64 / 11.0;
            [
                0.005 * t,
                -0.002 + 0.004 * t,
                -0.03 + 0.06 * t,
                2e-4 * (t - 0.5),
                -1e-4 * t,
            ]
        })
        .collect()
}

#[test]
fn bearing_outputs_equal_the_element_bit_for_bit() {
    let case = bearing_case();
    for fmu_type in [0, 1] {
        let fmu = Fmu::new(&case, fmu_type, &format!("bearing-equal-{fmu_type}"));
        fmu.start(fmu_type);
        let mut element = BearingElement::from_toml(&case).unwrap();
        let mut lifted = 0;
        for (k, u) in path().into_iter().enumerate() {
            let v = [1.0, -2.0, 0.5, 1e-3, 0.0];
            assert_eq!(fmu.set(&U, &u), OK);
            assert_eq!(fmu.set(&V, &v), OK);
            if fmu_type == 1 {
                // SAFETY: an instance.
                assert_eq!(unsafe { fmi2DoStep(fmu.c, k as f64, 1.0, 1) }, OK);
            }
            let names = [
                "Fx",
                "Fy",
                "Fz",
                "Mx",
                "My",
                "Mz",
                "max_element_load",
                "status",
            ];
            let (s, got) = fmu.get(&names);
            assert_eq!(s, OK, "{}", fmu.message());
            let r = element.evaluate(u, v).unwrap();
            let want = [
                r.force_n[0],
                r.force_n[1],
                r.force_n[2],
                r.moment_nmm[0],
                r.moment_nmm[1],
                r.moment_nmm[2],
                r.max_element_load_n,
                if r.max_element_load_n > 0.0 && r.force_n.iter().any(|f| *f != 0.0) {
                    1.0
                } else {
                    0.0
                },
            ];
            // the same calls in the same order: the same bits
            assert_eq!(got, want, "step {k}");
            lifted += usize::from(got[7] == 0.0);
        }
        // the path loads the bearing and lifts it off
        assert!(lifted > 0 && lifted < 12, "{lifted} lifted-off steps");
    }
}

#[test]
fn bearing_derivatives_are_minus_the_stiffness_and_the_difference_quotients() {
    let case = bearing_case();
    let fmu = Fmu::new(&case, 0, "bearing-derivative");
    fmu.start(0);
    let u = [0.01, 0.003, 0.02, 1e-4, -5e-5];
    assert_eq!(fmu.set(&U, &u), OK);
    let k = BearingElement::from_toml(&case)
        .unwrap()
        .evaluate(u, [0.0; 5])
        .unwrap()
        .stiffness;
    for j in 0..5 {
        // the column j of −K, from the stiffness
        let (s, d) = fmu.derivative(&R, &[U[j]], &[1.0]);
        assert_eq!(s, OK, "{}", fmu.message());
        for i in 0..5 {
            assert_eq!(d[i], -k[i][j], "dR{i}/du{j}");
        }
        // and the difference quotient of the outputs the host gets
        let h = 1e-7 * if j < 3 { 1.0 } else { 1e-2 };
        let mut up = u;
        up[j] += h;
        fmu.set(&U, &up);
        let plus = fmu.get(&R).1;
        up[j] -= 2.0 * h;
        fmu.set(&U, &up);
        let minus = fmu.get(&R).1;
        fmu.set(&U, &u);
        let scale = (0..5).map(|i| k[i][j].abs()).fold(0.0, f64::max);
        for i in 0..5 {
            let q = (plus[i] - minus[i]) / (2.0 * h);
            assert!(
                (q - d[i]).abs() <= 1e-5 * scale,
                "dR{i}/du{j}: quotient {q}, derivative {}",
                d[i]
            );
        }
    }
    // a combined seed is the sum of the columns; the damping part is beta times the
    // stiffness (no velocity, so the stiffness path is exact)
    // SAFETY: an instance (parameters change in event mode).
    unsafe { assert_eq!(fmi2EnterEventMode(fmu.c), OK) };
    assert_eq!(fmu.set(&["damping_s"], &[0.01]), OK);
    // SAFETY: as above.
    unsafe { assert_eq!(fmi2EnterContinuousTimeMode(fmu.c), OK) };
    let (s, d) = fmu.derivative(&R, &["dx", "vx"], &[1.0, 2.0]);
    assert_eq!(s, OK);
    for i in 0..5 {
        let want = -k[i][0] - 0.01 * 2.0 * k[i][0];
        assert!((d[i] - want).abs() <= 1e-12 * k[0][0].abs(), "{i}");
    }
    // with a velocity and damping the derivative includes beta (dK/du) v: central
    // differences, checked against the difference quotient of the host's outputs
    assert_eq!(fmu.set(&V, &[100.0, 0.0, 0.0, 0.0, 0.0]), OK);
    let (s, d) = fmu.derivative(&["Fx"], &["dx"], &[1.0]);
    assert_eq!(s, OK);
    let h = 1e-7;
    fmu.set(&["dx"], &[u[0] + h]);
    let plus = fmu.get(&["Fx"]).1[0];
    fmu.set(&["dx"], &[u[0] - h]);
    let minus = fmu.get(&["Fx"]).1[0];
    let q = (plus - minus) / (2.0 * h);
    assert!((q - d[0]).abs() <= 1e-5 * k[0][0].abs(), "{q} vs {}", d[0]);
    assert!(
        (d[0] + k[0][0] * 1.0).abs() > 1e-4 * k[0][0].abs(),
        "no velocity term?"
    );
    // the derivative does not move the element's warm start: same outputs after it
    fmu.set(&["dx"], &[u[0]]);
    let before = fmu.get(&R).1;
    fmu.derivative(&R, &U, &[1.0, 1.0, 1.0, 1e-3, 1e-3]);
    fmu.set(&["dx"], &[u[0]]);
    assert_eq!(fmu.get(&R).1, before);
}

#[test]
fn bearing_friction_outputs_follow_the_ring_speed_inputs() {
    let case =
        std::fs::read_to_string(repo().join("examples/bearing_32008x_friction.toml")).unwrap();
    let fmu = Fmu::new(&case, 0, "bearing-friction");
    fmu.start(0);
    let mut element = BearingElement::from_toml(&case).unwrap();
    // the speed inputs start at the case's [speed]
    let start = fmu.get(&["omega_inner", "omega_outer"]).1;
    assert_eq!(start, element.speeds().to_vec());
    assert!(start[0] != start[1], "{start:?}");
    let u = [0.01, -0.002, 0.015, 1e-4, 5e-5];
    let out = ["Mz", "friction_torque", "friction_power", "Fx"];
    for w in [[100.0, 0.0], [-50.0, 20.0], [10.0, 10.0]] {
        fmu.set(&U, &u);
        assert_eq!(fmu.set(&["omega_inner", "omega_outer"], &w), OK);
        let (s, got) = fmu.get(&out);
        assert_eq!(s, OK, "{}", fmu.message());
        element.set_speeds(w[0], w[1]).unwrap();
        let r = element.evaluate(u, [0.0; 5]).unwrap();
        let want = [
            r.moment_nmm[2],
            r.friction.torque_nmm,
            r.friction.power_w,
            r.force_n[0],
        ];
        assert_eq!(got, want, "{w:?}");
        // M > 0 against the relative rotation; the power is 1e-3 M |Δω| W
        let dw = w[0] - w[1];
        assert!(got[1] > 0.0);
        assert_eq!(
            got[0],
            -got[1] * dw.signum() * f64::from(u8::from(dw != 0.0))
        );
        assert!((got[2] - 1e-3 * got[1] * dw.abs()).abs() <= 1e-12 * got[2].abs().max(1.0));
    }
    // the ring speeds do not move the reaction: zero derivative of Fx, the torque's by
    // differences
    let (s, d) = fmu.derivative(&["Fx", "friction_torque"], &["omega_inner"], &[1.0]);
    assert_eq!(s, OK);
    assert_eq!(d[0], 0.0);
    assert!(d[1].is_finite());
    // a ring speed beyond 100 000 r/min: discard naming the input
    fmu.set(&["omega_inner"], &[1e5]);
    assert_eq!(fmu.get(&["Fx"]).0, DISCARD);
    assert!(fmu.message().contains("omega_inner"), "{}", fmu.message());
}

#[test]
fn bad_input_is_an_error_naming_the_variable_and_never_a_crash() {
    let case = bearing_case();
    let fmu = Fmu::new(&case, 0, "bearing-bad");
    fmu.start(0);
    assert_eq!(fmu.set(&["dz"], &[f64::NAN]), ERROR);
    assert!(fmu.message().contains("dz = NaN"), "{}", fmu.message());
    assert_eq!(fmu.set(&["omega_y"], &[f64::INFINITY]), ERROR);
    assert!(fmu.message().contains("omega_y"), "{}", fmu.message());
    // the refused value was not taken: the outputs are those of the start values
    assert_eq!(fmu.get(&["Fx"]).0, OK);
    // beyond the model's validity (a translation above the roller diameter): discard,
    // the message names the input and the limit
    assert_eq!(fmu.set(&["dx"], &[7.0]), OK);
    let (s, v) = fmu.get(&["Fx"]);
    assert_eq!(s, DISCARD, "{}", fmu.message());
    assert!(v[0].is_nan(), "no output written on discard");
    let m = fmu.message();
    assert!(
        m.contains("invalid dx = 7") && m.contains("roller_diameter_mm"),
        "{m}"
    );
    // back within validity: OK again
    assert_eq!(fmu.set(&["dx"], &[0.01]), OK);
    assert_eq!(fmu.get(&["Fx"]).0, OK);
    // a negative damping: error naming the parameter, the old value kept
    assert_eq!(fmu.set(&["damping_s"], &[-1.0]), ERROR);
    assert!(fmu.message().contains("damping_s"), "{}", fmu.message());
    assert_eq!(fmu.get(&["damping_s"]).1, vec![0.0]);
    // outputs cannot be set, unknown references are refused
    assert_eq!(fmu.set(&["Fx"], &[1.0]), ERROR);
    let mut x = 0.0;
    // SAFETY: an instance, one reference and value.
    assert_eq!(unsafe { fmi2GetReal(fmu.c, &999, 1, &mut x) }, ERROR);
    assert!(fmu.message().contains("999"));
    // SAFETY: null pointers with a count: refused, not read.
    assert_eq!(
        unsafe { fmi2GetReal(fmu.c, std::ptr::null(), 2, std::ptr::null_mut()) },
        ERROR
    );
    // SAFETY: a null instance is refused.
    assert_eq!(
        unsafe { fmi2GetReal(std::ptr::null_mut(), &0, 1, &mut x) },
        ERROR
    );
}

#[test]
fn illegal_calls_and_mismatched_fmus_are_refused() {
    let case = bearing_case();
    // a model description of another case
    assert!(
        instantiate(
            &case,
            0,
            "bearing-guid",
            "{00000000-0000-0000-0000-000000000000}"
        )
        .is_null()
    );
    // a host that passes the FMU's folder instead of resources/
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("fmi2")
        .join("unzipped");
    let resources = support::instantiate(&case, 0, &dir, &guid(&case));
    // SAFETY: from fmi2Instantiate, freed once.
    unsafe { fmi2FreeInstance(resources) };
    let c = support::instantiate_at(&dir, 0, &guid(&case));
    assert!(!c.is_null());
    // SAFETY: from fmi2Instantiate, freed once.
    unsafe { fmi2FreeInstance(c) };
    // a method that is no element
    assert!(
        instantiate(
            "method = \"hertz\"",
            0,
            "hertz",
            &guid("method = \"hertz\"")
        )
        .is_null()
    );
    let fmu = Fmu::new(&case, 0, "bearing-sequence");
    let mut x = 0.0;
    // SAFETY: an instance; one value.
    unsafe {
        assert_eq!(
            fmi2GetReal(fmu.c, &11, 1, &mut x),
            ERROR,
            "before initialization"
        );
        assert_eq!(fmi2ExitInitializationMode(fmu.c), ERROR);
        assert_eq!(fmi2DoStep(fmu.c, 0.0, 0.1, 1), ERROR, "a CS call on ME");
    }
    fmu.start(0);
    // SAFETY: as above; no states, so nx = 0 is all that is accepted.
    unsafe {
        assert_eq!(fmi2GetDerivatives(fmu.c, std::ptr::null_mut(), 0), OK);
        assert_eq!(fmi2GetContinuousStates(fmu.c, &mut x, 1), ERROR);
        assert_eq!(
            fmu.set(&["damping_s"], &[0.1]),
            ERROR,
            "parameter in continuous time"
        );
        assert!(fmu.message().contains("damping_s"));
        assert_eq!(fmi2EnterEventMode(fmu.c), OK);
        assert_eq!(fmu.set(&["damping_s"], &[0.1]), OK, "tunable in event mode");
        assert_eq!(fmi2Terminate(fmu.c), OK);
        assert_eq!(fmu.set(&["dx"], &[0.1]), ERROR, "after terminate");
        assert_eq!(fmi2Reset(fmu.c), OK);
        assert_eq!(fmi2SetupExperiment(fmu.c, 0, 0.0, 0.0, 0, 0.0), OK);
    }
}

#[test]
fn fmu_state_restores_the_outputs_and_the_warm_start() {
    let case = bearing_case();
    let fmu = Fmu::new(&case, 1, "bearing-state");
    fmu.start(1);
    fmu.set(&U, &[0.01, 0.0, 0.02, 0.0, 0.0]);
    let saved_outputs = fmu.get(&R).1;
    let mut state = std::ptr::null_mut();
    // SAFETY: an instance and a state pointer.
    unsafe {
        assert_eq!(fmi2GetFMUstate(fmu.c, &mut state), OK);
        fmu.set(&U, &[0.02, 0.01, 0.0, 1e-4, 0.0]);
        let other = fmu.get(&R).1;
        assert_ne!(other, saved_outputs);
        assert_eq!(fmi2SetFMUstate(fmu.c, state), OK);
        assert_eq!(fmu.get(&U).1, vec![0.01, 0.0, 0.02, 0.0, 0.0]);
        assert_eq!(fmu.get(&R).1, saved_outputs);
        // reusing the state object overwrites it
        assert_eq!(fmi2GetFMUstate(fmu.c, &mut state), OK);
        assert_eq!(fmi2FreeFMUstate(fmu.c, &mut state), OK);
        assert!(state.is_null());
        let mut size = 0usize;
        assert_eq!(
            fmi2SerializedFMUstateSize(fmu.c, std::ptr::null_mut(), &mut size),
            ERROR
        );
    }
}

/// A pose: a translation and the rotation about the axis `axis` by `angle`.
fn pose(t: [f64; 3], angle: f64) -> [f64; 7] {
    let q = UnitQuaternion::from_scaled_axis(Vector3::new(0.3, -0.2, 1.0).normalize() * angle);
    [t[0], t[1], t[2], q.w, q.i, q.j, q.k]
}

const CONTACT_IN: [&str; 26] = [
    "pose1.x",
    "pose1.y",
    "pose1.z",
    "pose1.qw",
    "pose1.qx",
    "pose1.qy",
    "pose1.qz",
    "pose2.x",
    "pose2.y",
    "pose2.z",
    "pose2.qw",
    "pose2.qx",
    "pose2.qy",
    "pose2.qz",
    "twist1.vx",
    "twist1.vy",
    "twist1.vz",
    "twist1.wx",
    "twist1.wy",
    "twist1.wz",
    "twist2.vx",
    "twist2.vy",
    "twist2.vz",
    "twist2.wx",
    "twist2.wy",
    "twist2.wz",
];

#[test]
fn contact_outputs_equal_the_element_bit_for_bit() {
    let case = contact_case();
    let fmu = Fmu::new(&case, 0, "contact-equal");
    fmu.start(0);
    let mut element = kontakt_case::element_case::element_from_toml(&case).unwrap();
    let out = [
        "force1.x",
        "force1.y",
        "force1.z",
        "moment1.x",
        "moment1.y",
        "moment1.z",
        "friction_force.x",
        "friction_power",
        "point.z",
        "normal.z",
        "approach",
        "normal_force",
        "status",
    ];
    for k in 0..8 {
        let z = 10.01 - 0.003 * k as f64;
        let p1 = pose([0.1 * k as f64, 0.0, z], 0.2 * k as f64);
        let p2 = pose([0.0, 0.0, 0.0], 0.0);
        let t1 = [10.0, 0.0, -1.0, 0.0, 2.0, 0.5];
        let t2 = [0.0; 6];
        let x: Vec<f64> = p1
            .iter()
            .chain(&p2)
            .chain(&t1)
            .chain(&t2)
            .copied()
            .collect();
        assert_eq!(fmu.set(&CONTACT_IN, &x), OK);
        let (s, got) = fmu.get(&out);
        assert_eq!(s, OK, "{}", fmu.message());
        let iso = |p: [f64; 7]| {
            let q = nalgebra::Quaternion::new(p[3], p[4], p[5], p[6]);
            Isometry3::from_parts(
                Translation3::new(p[0], p[1], p[2]),
                UnitQuaternion::new_unchecked(q / q.norm()),
            )
        };
        let tw = |t: [f64; 6]| {
            kontakt::geometry::Twist::new(
                Vector3::new(t[0], t[1], t[2]),
                Vector3::new(t[3], t[4], t[5]),
            )
        };
        let r = element
            .evaluate(&iso(p1), &iso(p2), &tw(t1), &tw(t2))
            .unwrap();
        let want = [
            r.force1.x,
            r.force1.y,
            r.force1.z,
            r.moment1.x,
            r.moment1.y,
            r.moment1.z,
            r.friction_force.x,
            r.friction_power,
            r.point.z,
            r.normal.z,
            r.approach,
            r.normal_force,
            if r.approach > 0.0 { 1.0 } else { 0.0 },
        ];
        assert_eq!(got, want, "step {k}");
    }
}

#[test]
fn contact_derivative_of_the_force_is_the_hertz_stiffness() {
    let case = contact_case();
    let fmu = Fmu::new(&case, 0, "contact-derivative");
    fmu.start(0);
    let delta = 0.004;
    fmu.set(&["pose1.z"], &[10.0 - delta]);
    let (s, f) = fmu.get(&["force1.z"]);
    assert_eq!(s, OK);
    let (s, d) = fmu.derivative(&["force1.z", "status"], &["pose1.z"], &[1.0]);
    assert_eq!(s, OK, "{}", fmu.message());
    // Hertz: F ∝ δ^(3/2), so dF/dz = −dF/dδ = −(3/2) F/δ
    let want = -1.5 * f[0] / delta;
    assert!(
        (d[0] - want).abs() <= 1e-6 * want.abs(),
        "{} vs {want}",
        d[0]
    );
    assert_eq!(d[1], 0.0);
    // a quaternion far from unit: an error naming it; NaN: an error naming the input
    assert_eq!(fmu.set(&["pose1.qw"], &[1.5]), OK);
    assert_eq!(fmu.get(&["force1.z"]).0, DISCARD);
    assert!(fmu.message().contains("pose1.qw..qz"), "{}", fmu.message());
    assert_eq!(fmu.set(&["pose1.qw"], &[1.0]), OK);
    assert_eq!(fmu.set(&["twist2.wz"], &[f64::NAN]), ERROR);
    assert!(fmu.message().contains("twist2.wz"), "{}", fmu.message());
    // beyond the validity limit (approach > 1 % of the radius): discard, outputs written
    fmu.set(&["pose1.z"], &[10.0 - 0.2]);
    let (s, v) = fmu.get(&["normal_force", "status"]);
    assert_eq!(s, DISCARD);
    assert!(v[0] > f[0] && v[1] == 2.0, "{v:?}");
}

#[test]
fn contact_parameters_replan_the_element() {
    let case = contact_case();
    let fmu = Fmu::new(&case, 1, "contact-parameters");
    // SAFETY: an instance.
    unsafe {
        assert_eq!(fmi2EnterInitializationMode(fmu.c), OK);
    }
    assert_eq!(
        fmu.get(&["damping_coefficient", "damping_ramp", "mu"]).1,
        vec![0.0, 1e-3, 0.1],
        "start values from the case"
    );
    fmu.set(&["pose1.z", "twist1.vx"], &[10.0 - 0.004, 100.0]);
    let f1 = fmu.get(&["friction_force.x", "normal_force"]).1;
    assert_eq!(fmu.set(&["mu"], &[0.2]), OK);
    let f2 = fmu.get(&["friction_force.x", "normal_force"]).1;
    assert_eq!(f2[1], f1[1]);
    assert!((f2[0] / f1[0] - 2.0).abs() < 1e-12, "{f1:?} {f2:?}");
    // damping: approaching at 1 mm/s through the ramp adds c·δ̇ with c = 50 at full ramp
    assert_eq!(
        fmu.set(&["damping_coefficient", "twist1.vz"], &[50.0, -1.0]),
        OK
    );
    let d = fmu.get(&["damping_force"]).1[0];
    assert!((d - 50.0).abs() < 1e-9, "{d}");
    assert_eq!(fmu.set(&["mu"], &[-1.0]), ERROR);
    assert!(fmu.message().contains("mu"), "{}", fmu.message());
    assert_eq!(fmu.set(&["damping_ramp"], &[0.0]), ERROR);
    assert!(fmu.message().contains("damping_ramp"), "{}", fmu.message());
}

#[test]
fn the_resource_uri_forms_hosts_send() {
    const SCHEME: &str = "file:";
    for (uri, path) in [
        ("///srv/a%20b/resources/", "/srv/a b/resources/"),
        ("/srv/x", "/srv/x"),
        ("//localhost/srv/x", "/srv/x"),
    ] {
        let uri = format!("{SCHEME}{uri}");
        assert_eq!(uri_to_path(&uri), Some(PathBuf::from(path)), "{uri}");
    }
    assert_eq!(uri_to_path("http://x/y"), None);
    assert_eq!(uri_to_path(&format!("{SCHEME}///bad%2")), None);
}

#[test]
fn crc32_and_zip_layout() {
    use kontakt_fmi::archive::{crc32, zip};
    // the check value of CRC-32/ISO-HDLC
    assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
    let z = zip(&[("a.txt", b"hello"), ("b/c.txt", b"")]).unwrap();
    assert_eq!(&z[..4], b"PK\x03\x04");
    // the end record names two entries and where the central directory starts
    let end = &z[z.len() - 22..];
    assert_eq!(&end[..4], b"PK\x05\x06");
    assert_eq!(u16::from_le_bytes([end[10], end[11]]), 2);
    let start = u32::from_le_bytes([end[16], end[17], end[18], end[19]]) as usize;
    assert_eq!(&z[start..start + 4], b"PK\x01\x02");
}
