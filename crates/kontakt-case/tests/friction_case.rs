//! Friction cases: the speeds of a range are exact (issue 30, item 16), and the maps lie
//! in the bearing frame whichever pressure model drew them.
//!
//! The maps of a friction case (`FrictionOutcome::map`) lie in the bearing frame whichever
//! pressure model drew them (issue 30, item 1): the Hertz field used to be sampled on a grid
//! of the contact frame while its axes were named as the gap's principal frame, so the
//! sphere-torus-57 zone came out 0.2 mm along the rib and 0.7 mm across it, with the
//! sliding arrows across the rib; PimP and the half-space solver drew it 0.7 mm along and
//! 0.2 mm across, with the sliding along the rib (the physics).
//!
//! Compared here for hertz, pimp and halfspace on `examples/rib_friction.toml` at one speed:
//! the second moments of the pressure and of the power density along the rib
//! (circumferential, the bearing frame's `Y`) and across it (the axial section), and the
//! pressure-weighted mean sliding direction, each mapped into the bearing frame through
//! the map's `axes`.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt::bearing::PressureModel;
use kontakt_case::Case;
use kontakt_case::friction_case::{FrictionCase, FrictionMap, SpeedSpec, run_friction_case};

fn map_of(model: PressureModel) -> FrictionMap {
    let text = include_str!("../../../examples/rib_friction.toml");
    let Case::Friction(case) = Case::from_toml_str(text).unwrap() else {
        panic!("not a friction case")
    };
    let mut case: FrictionCase = *case;
    case.models = vec![model];
    case.speed = toml::from_str("rpm = [900.0]").unwrap();
    run_friction_case(&case).unwrap().map
}

/// A grid point `(x, y)` of the map in the bearing frame.
fn world(m: &FrictionMap, x: f64, y: f64) -> [f64; 3] {
    let [ex, ey] = m.axes;
    [0, 1, 2].map(|k| x * ex[k] + y * ey[k])
}

/// Second moments `[along, across]` of `weights` over the map's cells \[mm²\]: along the
/// rib is the circumferential component, across it the rest (the axial section plane).
fn moments(m: &FrictionMap, weights: &[f64]) -> [f64; 2] {
    let g = &m.field.grid;
    let (mut along, mut across, mut total) = (0.0, 0.0, 0.0);
    for j in 0..g.ny() {
        for i in 0..g.nx() {
            let w = weights[j * g.nx() + i];
            let r = world(m, g.x(i), g.y(j));
            along += w * r[1] * r[1];
            across += w * (r[0] * r[0] + r[2] * r[2]);
            total += w;
        }
    }
    assert!(total > 0.0, "{}: an empty field", m.model.as_str());
    [along / total, across / total]
}

/// The pressure-weighted mean sliding velocity in the bearing frame, as a unit vector.
fn mean_sliding(m: &FrictionMap) -> [f64; 3] {
    let g = &m.field.grid;
    let mut sum = [0.0; 3];
    for j in 0..g.ny() {
        for i in 0..g.nx() {
            let p = m.field.pressure[j * g.nx() + i];
            let [vx, vy] = m.sliding.sliding_at(g.x(i), g.y(j));
            let v = world(m, vx, vy);
            for k in 0..3 {
                sum[k] += p * v[k];
            }
        }
    }
    let n = sum.iter().map(|v| v * v).sum::<f64>().sqrt();
    sum.map(|v| v / n)
}

#[test]
fn the_three_models_draw_their_maps_in_the_same_orientation() {
    let maps = PressureModel::ALL.map(map_of);
    let reference = mean_sliding(&maps[1]);
    for m in &maps {
        let name = m.model.as_str();
        let [along, across] = moments(m, &m.field.pressure);
        // the zone is about 0.7 mm along the rib and 0.2 mm across: (0.7 / 0.2)² ≈ 12
        assert!(
            along > 5.0 * across,
            "{name}: pressure moments along {along:.3e}, across {across:.3e} mm²: the zone \
             must be long along the rib"
        );
        let [along, across] = moments(m, &m.power_density);
        assert!(
            along > 5.0 * across,
            "{name}: power-density moments along {along:.3e}, across {across:.3e} mm²"
        );
        let v = mean_sliding(m);
        assert!(
            v[1].abs() > 0.95,
            "{name}: the mean sliding direction {v:?} must run along the rib (Y)"
        );
        let cos: f64 = (0..3).map(|k| v[k] * reference[k]).sum();
        assert!(
            cos > 0.999,
            "{name}: mean sliding direction {v:?}, PimP's {reference:?} (cos {cos})"
        );
    }
    // The grids of all three lie in the gap's principal frame.
    assert_eq!(maps[0].axes, maps[1].axes);
    assert_eq!(maps[0].field.orientation, maps[1].field.orientation);
    assert_eq!(maps[0].field.orientation, maps[2].field.orientation);
}

/// A linear range's speeds are exact multiples of its step, its ends as given, and the
/// report's `speed_rpm` is the case's speed (not converted back from rad/s).
#[test]
fn speeds_of_a_range_and_in_the_rows_are_exact() {
    let linear: SpeedSpec =
        toml::from_str("min_rpm = 100.0\nmax_rpm = 3000.0\npoints = 30\nspacing = \"linear\"")
            .unwrap();
    let speeds = linear.speeds().unwrap();
    let want: Vec<f64> = (0..30).map(|i| 100.0 + 100.0 * f64::from(i)).collect();
    // (lo + (hi - lo) * (i / (n - 1)) gave 1799.9999999999998 for 1800)
    assert_eq!(speeds, want);
    let log: SpeedSpec = toml::from_str("min_rpm = 50.0\nmax_rpm = 6000.0\npoints = 7").unwrap();
    let speeds = log.speeds().unwrap();
    assert_eq!((speeds[0], speeds[6]), (50.0, 6000.0));
    let one: SpeedSpec = toml::from_str("rpm = 1500.0").unwrap();
    assert_eq!(one.speeds().unwrap(), [1500.0]);

    let text = include_str!("../../../examples/rib_friction.toml");
    let Case::Friction(case) = Case::from_toml_str(text).unwrap() else {
        panic!("not a friction case")
    };
    let mut case: FrictionCase = *case;
    case.models = vec![PressureModel::Hertz];
    case.speed = toml::from_str("rpm = [1500.0, 2100.0]").unwrap();
    let report = run_friction_case(&case).unwrap().report;
    let got: Vec<f64> = report.rows.iter().map(|r| r.speed_rpm).collect();
    // 1500 r/min through rad/s and back is 1500.0000000000002
    assert_eq!(got, [1500.0, 2100.0]);
}
