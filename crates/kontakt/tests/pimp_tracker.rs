#![allow(clippy::unwrap_used)]
//! The PimP back-end of the contact element along trajectories (issue 12): the interpolated
//! gap against exact ray casting on the same grid for all eight built-in roller/rib pairings
//! (gap error relative to the approach, force and maximum pressure), the tracked field
//! against the full adaptive solve `Pimp::solve_approach`, smoothness along a 10 000-step
//! sweep through a grid resize, and no allocation per evaluation. Units: mm, N, MPa.

#[path = "support/counting_alloc.rs"]
mod counting_alloc;

use kontakt::bearing::{RollerRib, RollerRibSpec, TABLE1};
use kontakt::element::{Backend, ContactElement, ElementSpec};
use kontakt::geometry::{PlacedSurface, Twist, find_contact};
use kontakt::material::ElasticMaterial;
use kontakt::pimp::{GapSampling, Pimp, PimpOptions, PimpTracker, SurfacePairGap};
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};

const STEEL: ElasticMaterial = ElasticMaterial::STEEL;

fn roller_rib(name: &str) -> RollerRib {
    RollerRib::new(RollerRibSpec::builtin(name).unwrap()).unwrap()
}

/// The gap of a pairing with the roller pushed `approach` \[mm\] along the normal into the rib.
fn pressed_gap(rr: &RollerRib, approach: f64) -> SurfacePairGap {
    let n = rr.contact.normal.into_inner();
    let shift = Isometry3::from_parts(
        Translation3::from(-n * approach),
        UnitQuaternion::identity(),
    );
    let face = PlacedSurface::new(rr.face.surface.clone(), shift * rr.face.pose).unwrap();
    let contact = find_contact(&face, &rr.rib, Some(rr.contact.point)).unwrap();
    SurfacePairGap::new(face, rr.rib.clone(), contact).unwrap()
}

fn pimp() -> Pimp {
    Pimp::new(STEEL, STEEL, PimpOptions::default()).unwrap()
}

/// The approach \[mm\] at which the (interpolated) tracked PimP field of the pairing carries
/// `force` to about 1e-4: from the Hertz approach of the contact point's curvature, steps
/// δ (F/F(δ))^(2/3). (A translation along the normal leaves the gap unchanged, so the gap of
/// the touching pose serves every approach; cheap, so the debug build stays fast.)
fn approach_for(rr: &RollerRib, force: f64) -> f64 {
    use kontakt::gap::GapSource;
    use kontakt::hertz::{HertzPointContact, PointGeometry};
    let gap = pressed_gap(rr, 0.0);
    let mut delta =
        HertzPointContact::new(PointGeometry::from_curvature(gap.curvature()), STEEL, STEEL)
            .unwrap()
            .approach_from_force(force)
            .unwrap();
    for _ in 0..8 {
        let mut t = PimpTracker::new(pimp(), GapSampling::Interpolated).unwrap();
        let f = t.evaluate(&gap, delta).unwrap().force;
        delta *= (force / f).powf(2.0 / 3.0);
    }
    delta
}

/// Interpolated against exact gap, per pairing and load, on the same 64 × 64 grid.
#[test]
fn interpolated_gap_matches_exact_ray_casting_on_all_pairings() {
    let (mut worst_gap, mut worst_f, mut worst_p) = (0.0f64, 0.0f64, 0.0f64);
    println!("pairing           F [N]  delta [um]  max|dg| [nm]  max|dg|/delta  dF/F      dp/p");
    for (name, ..) in TABLE1 {
        let rr = roller_rib(name);
        for force in [100.0, 250.0, 400.0] {
            let delta = approach_for(&rr, force);
            let gap = pressed_gap(&rr, delta);
            let mut fast = PimpTracker::new(pimp(), GapSampling::Interpolated).unwrap();
            let mut exact = PimpTracker::new(pimp(), GapSampling::Exact).unwrap();
            let (ff, fp) = {
                let f = fast.evaluate(&gap, delta).unwrap();
                (f.force, f.max_pressure)
            };
            exact.set_grid_factor(fast.grid_factor().unwrap()).unwrap();
            let (ef, ep) = {
                let f = exact.evaluate(&gap, delta).unwrap();
                (f.force, f.max_pressure)
            };
            assert_eq!(fast.grid(), exact.grid(), "{name} {force}");
            // Over the zone and a margin: where the exact (corrected) gap is below 2 cut levels.
            let cut_band = 2.0 * delta;
            let zone = fast
                .effective_gap()
                .iter()
                .zip(exact.effective_gap())
                .filter(|(_, e)| **e < delta)
                .map(|(a, e)| (a - e).abs())
                .fold(0.0, f64::max);
            let err = fast
                .effective_gap()
                .iter()
                .zip(exact.effective_gap())
                .filter(|(_, e)| **e < cut_band)
                .map(|(a, e)| (a - e).abs())
                .fold(0.0, f64::max);
            let (df, dp) = ((ff / ef - 1.0).abs(), (fp / ep - 1.0).abs());
            println!(
                "{name:16} {force:6.0} {:11.4} {:13.4} {:14.2e} {df:9.2e} {dp:9.2e} zone {:.2e}",
                delta * 1e3,
                err * 1e6,
                err / delta,
                zone / delta,
            );
            worst_gap = worst_gap.max(err / delta);
            worst_f = worst_f.max(df);
            worst_p = worst_p.max(dp);
        }
    }
    println!("worst: gap {worst_gap:.2e} delta, force {worst_f:.2e}, p_max {worst_p:.2e}");
    assert!(worst_gap < 1e-4, "{worst_gap}");
    assert!(worst_f < 1e-4, "{worst_f}");
    assert!(worst_p < 1e-4, "{worst_p}");
}

/// Smoothness through a grid resize: the torus/torus pairing with 28 mm face radius, the
/// roller pushed along the contact normal from 0.5 to 4.7 µm (about 20 to 365 N) in 10 000
/// steps of 0.42 nm on 64 × 64 cells. A translation along the normal leaves the contact
/// point, the normal and the gap unchanged, so the element's PimP path at each of these
/// poses is the tracker at the new approach on the gap of the first pose (evaluated so to
/// keep the debug build at a few seconds; `roller_rib_from_poses` and the element sweeps
/// cover the pose-to-gap step). The zone's curved, non-Hertzian shape makes the grid shrink
/// along its long axis on the way (checked: one resize, faded over `FADE_TRAVEL` of motion). The
/// second difference of the force stays below 1e-4 of the force at every step (a jump of
/// 1e-4 F would show as one of that size; a cell entering the zone gives a kink of a few
/// 1e-5), and the fade's own contribution is measured against the steps before it.
#[test]
fn force_is_smooth_through_a_grid_resize_over_10000_steps() {
    let rr = roller_rib("torus-torus-28");
    let gap = pressed_gap(&rr, 0.0);
    let mut t = PimpTracker::new(pimp(), GapSampling::Interpolated).unwrap();
    let steps = 10_000;
    let mut forces = Vec::with_capacity(steps);
    let mut fading = Vec::new();
    for i in 0..steps {
        let delta = 0.0005 + 0.0042 * i as f64 / steps as f64;
        forces.push(t.evaluate(&gap, delta).unwrap().force);
        if t.fading() {
            fading.push(i);
        }
    }
    let second: Vec<f64> = forces
        .windows(3)
        .map(|w| (w[2] - 2.0 * w[1] + w[0]).abs() / w[1])
        .collect();
    let worst = second.iter().copied().fold(0.0, f64::max);
    let (f0, f1) = (fading[0], fading[fading.len() - 1]);
    let in_fade = second[f0 - 1..=f1].iter().copied().fold(0.0, f64::max);
    let before = second[f0 - 200..f0 - 1].iter().copied().fold(0.0, f64::max);
    println!(
        "{} resize(s), fade over steps {f0}..={f1}; F {:.2} .. {:.2} N; largest second \
         difference / F: {worst:.3e} overall, {in_fade:.3e} during the fade, {before:.3e} in \
         the 200 steps before it",
        t.resizes(),
        forces[0],
        forces[steps - 1]
    );
    assert_eq!(t.resizes(), 1);
    assert!(worst < 1e-4, "{worst}");
}

/// The fade between grids moves with the contact, not with the calls: on the load ramp
/// above, inside the fade, a call repeated at the same approach returns the same weight bit
/// for bit and the same force to 2e-11 (a fade counted in calls moved the weight on by up to
/// 1/20 and the force by about 1e-7), a call
/// with travel moves the weight on, and a negative travel is refused naming `travel`.
#[test]
fn a_repeated_call_inside_a_fade_gives_the_same_result() {
    let rr = roller_rib("torus-torus-28");
    let gap = pressed_gap(&rr, 0.0);
    let mut t = PimpTracker::new(pimp(), GapSampling::Interpolated).unwrap();
    let steps = 10_000;
    let mut checked = 0;
    for i in 0..steps {
        let delta = 0.0005 + 0.0042 * i as f64 / steps as f64;
        t.evaluate(&gap, delta).unwrap();
        if t.fading() && i % 50 == 0 {
            let first = t.evaluate(&gap, delta).unwrap();
            let (f1, w1) = (first.force, first.fade_weight);
            let again = t.evaluate(&gap, delta).unwrap();
            // The weight bit for bit; the force to the warm starts' rounding (the row
            // windows and the stencil's rays start from the last call: 2e-11, as above).
            assert_eq!(again.fade_weight, w1, "step {i}");
            assert!(
                (again.force / f1 - 1.0).abs() < 2e-11,
                "step {i}: {} vs {f1}",
                again.force
            );
            assert!(w1 > 0.0 && w1 < 1.0, "step {i}: weight {w1}");
            let moved = t.evaluate_moved(&gap, delta, 1e-3).unwrap();
            assert!(
                moved.fade_weight > w1,
                "step {i}: {} vs {w1}",
                moved.fade_weight
            );
            checked += 1;
        }
    }
    assert!(checked >= 5, "{checked} checks inside the fade");
    let err = t.evaluate_moved(&gap, 0.004, -1e-3).unwrap_err();
    assert!(err.to_string().contains("travel"), "{err}");
}

/// Along a trajectory (the roller sliding 0.1 mm across the contact and tilting ±0.05°,
/// 400 steps), the tracker that evaluates only the rows' windows about the last zone gives
/// the same force, maximum pressure and area as a tracker that evaluates every cell on each
/// call (reset before each call), to 2e-11 relative (measured 6.4e-12: the tracker's Hertz
/// ellipse, which sets the grid's extent, is warm-started from the last call and lands within
/// a few ulps of the cold root the reset tracker finds; the windows themselves agree to
/// 1e-12).
#[test]
fn row_windows_match_the_full_evaluation_along_a_trajectory() {
    let rr = roller_rib("torus-torus-14");
    let n = rr.contact.normal.into_inner();
    let across = n.cross(&Vector3::z()).normalize();
    let axis = nalgebra::Unit::new_normalize(across.cross(&n));
    let mut windowed = PimpTracker::new(pimp(), GapSampling::Interpolated).unwrap();
    let mut full = PimpTracker::new(pimp(), GapSampling::Interpolated).unwrap();
    let mut guess = Some(rr.contact.point);
    let mut worst = 0.0f64;
    for i in 0..400 {
        let s = i as f64 / 400.0 * std::f64::consts::TAU;
        let rot = UnitQuaternion::from_axis_angle(&axis, 0.05f64.to_radians() * s.sin());
        let c = rr.contact.point.coords;
        let pose = Isometry3::from_parts(
            Translation3::from(
                c - rot * c - n * (0.0042 + 0.0005 * s.cos()) + across * 0.05 * (1.0 - s.cos()),
            ),
            rot,
        );
        let face = PlacedSurface::new(rr.face.surface.clone(), pose * rr.face.pose).unwrap();
        let contact = find_contact(&face, &rr.rib, guess).unwrap();
        guess = Some(contact.point);
        let delta = -contact.separation;
        let gap = SurfacePairGap::new(face, rr.rib.clone(), contact).unwrap();
        let a = windowed.evaluate(&gap, delta).unwrap();
        let (fa, pa, aa) = (a.force, a.max_pressure, a.contact_area);
        full.reset();
        let b = full.evaluate(&gap, delta).unwrap();
        for (x, y) in [(fa, b.force), (pa, b.max_pressure), (aa, b.contact_area)] {
            worst = worst.max((x / y - 1.0).abs());
        }
    }
    println!("largest relative difference windowed/full: {worst:.2e}");
    assert_eq!(windowed.resizes(), 0);
    assert!(worst < 2e-11, "{worst}");
}

/// The tracked field against the full adaptive solve `Pimp::solve_approach` (its own grid,
/// exact ray casting) for all eight pairings at the approaches of 100, 250 and 400 N: the
/// force within 0.2 % and the maximum pressure within 0.1 % (measured: 8.3e-4 and 1.1e-4,
/// on the curved zones of the 28 mm faces, where the two grids differ: the adaptive solve
/// zooms in once, the tracker keeps the zone within 50-90 % of its grid; elsewhere the
/// grids are the same and the difference is the interpolation's, ≤ 1.1e-6).
#[test]
fn tracked_field_matches_the_full_adaptive_solve() {
    let (mut worst_f, mut worst_p) = (0.0f64, 0.0f64);
    for (name, ..) in TABLE1 {
        let rr = roller_rib(name);
        for force in [100.0, 250.0, 400.0] {
            let delta = approach_for(&rr, force);
            let gap = pressed_gap(&rr, delta);
            let full = pimp().solve_approach(&gap, delta).unwrap();
            let mut t = PimpTracker::new(pimp(), GapSampling::Interpolated).unwrap();
            let f = t.evaluate(&gap, delta).unwrap();
            let (df, dp) = (
                f.force / full.force - 1.0,
                f.max_pressure / full.max_pressure - 1.0,
            );
            println!("{name:16} {force:5.0} N: force {df:+.2e}, p_max {dp:+.2e}");
            worst_f = worst_f.max(df.abs());
            worst_p = worst_p.max(dp.abs());
        }
    }
    println!("worst: force {worst_f:.2e}, p_max {worst_p:.2e}");
    assert!(worst_f < 2e-3, "{worst_f}");
    assert!(worst_p < 1e-3, "{worst_p}");
}

/// No allocation per evaluation: the PimP element along 200 steps of a sliding, tilting
/// roller (after two warm-up calls that size the buffers) allocates nothing; nor does the
/// Hertz element (its friction quadrature and the shape inversion's warm start) on the
/// same steps, nor the half-space element's warm calls on its kept grid (its solve, gap
/// interpolation and zone analysis).
#[test]
fn pimp_element_evaluation_allocates_nothing() {
    let rr = roller_rib("torus-torus-14");
    for backend in [
        Backend::Pimp(PimpOptions::default()),
        Backend::Hertz,
        Backend::HalfSpace(Default::default()),
    ] {
        let mut spec = ElementSpec::new(rr.face.clone(), rr.rib.clone()).unwrap();
        spec.backend = backend;
        let mut e = ContactElement::new(spec).unwrap();
        let n = rr.contact.normal.into_inner();
        let across = n.cross(&Vector3::z()).normalize();
        let axis = nalgebra::Unit::new_normalize(across.cross(&n));
        let pose = |i: usize| {
            let s = i as f64 / 200.0 * std::f64::consts::TAU;
            let rot = UnitQuaternion::from_axis_angle(&axis, 0.02f64.to_radians() * s.sin());
            let c = rr.contact.point.coords;
            Isometry3::from_parts(
                Translation3::from(c - rot * c - n * 0.0042 + across * 0.02 * s.sin()),
                rot,
            )
        };
        let id = Isometry3::identity();
        let spin = Twist::new(Vector3::zeros(), Vector3::new(0.0, 0.0, 10.0));
        for i in 0..2 {
            e.evaluate(&pose(i), &id, &spin, &Twist::zero()).unwrap();
        }
        let (force, count) = counting_alloc::allocations(|| {
            let mut total = 0.0;
            for i in 2..202 {
                total += e
                    .evaluate(&pose(i), &id, &spin, &Twist::zero())
                    .unwrap()
                    .normal_force;
            }
            total
        });
        println!(
            "{backend:?}: 200 evaluations, mean force {:.2} N: {count} allocations",
            force / 200.0
        );
        assert!(force > 0.0);
        assert_eq!(count, 0);
    }
}

/// Tiny approaches (a round-off touch up to 1 nm) give a small positive force on a loaded
/// grid, not an error: the grid scales with the footprint of the approach.
#[test]
fn tiny_approaches_give_a_small_force() {
    for name in ["torus-torus-14", "sphere-cone-29", "torus-cone-28"] {
        let rr = roller_rib(name);
        let gap = pressed_gap(&rr, 0.0);
        for delta in [1e-14, 1e-12, 1e-9, 1e-6] {
            let mut t = PimpTracker::new(pimp(), GapSampling::Interpolated).unwrap();
            let f = t.evaluate(&gap, delta).unwrap().force;
            println!("{name} delta {delta:e}: F = {f:e}");
            assert!(f > 0.0 && f.is_finite());
        }
    }
}
