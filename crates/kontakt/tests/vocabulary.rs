//! The shared vocabulary of the field solvers: load control, termination status, the one
//! adaptive-domain loop, and the results PimP and the half-space solver share.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use kontakt::Error;
use kontakt::field::domain::{self, MIN_CELLS_ACROSS, Policy, Shrink, Trial};
use kontakt::field::{ContactZone, NormalSolution};
use kontakt::gap::{GapSource, QuadraticGap};
use kontakt::geometry::{Grid2, RelativeCurvature};
use kontakt::halfspace::{Bem, BemOptions};
use kontakt::load::LoadControl;
use kontakt::material::ElasticMaterial;
use kontakt::pimp::{Pimp, PimpOptions};
use kontakt::solve::{SolveStatus, Termination};

const STEEL: ElasticMaterial = ElasticMaterial::STEEL;

#[test]
fn a_status_that_did_not_converge_becomes_an_error_that_says_why() {
    let ok = SolveStatus::new(Termination::Converged, 12, 3e-9);
    assert_eq!(ok.require_converged("x").unwrap(), ok);
    for (t, word) in [
        (Termination::MaxIterations, "max iterations"),
        (Termination::Stagnated, "stagnated"),
        (Termination::Diverged, "diverged"),
    ] {
        let err = SolveStatus::new(t, 200, 1.5e-6)
            .require_converged("the solve")
            .unwrap_err();
        let msg = err.to_string();
        assert!(
            matches!(
                err,
                Error::NotConverged {
                    iterations: 200,
                    ..
                }
            ),
            "{msg}"
        );
        assert!(
            msg.contains(word) && msg.contains("200") && msg.contains("1.5e-6"),
            "{msg}"
        );
    }
    assert_eq!(Termination::MaxIterations.as_str(), "max_iterations");
    #[cfg(feature = "serde")]
    assert_eq!(
        serde_json::to_value(Termination::Stagnated).unwrap(),
        serde_json::json!("stagnated")
    );
}

#[test]
fn point_solvers_take_a_positive_force_or_approach_only() {
    assert!(LoadControl::Force(10.0).point().is_ok());
    assert!(LoadControl::Approach(1e-3).point().is_ok());
    for (c, field) in [
        (LoadControl::Force(-1.0), "force"),
        (LoadControl::Force(f64::NAN), "force"),
        (LoadControl::Approach(0.0), "approach"),
        (LoadControl::Approach(f64::INFINITY), "approach"),
        (LoadControl::LineLoad(100.0), "line_load"),
    ] {
        assert_eq!(c.point().unwrap_err().field(), Some(field), "{c:?}");
    }
    // Both field solvers refuse a line load with the same named field.
    let k = RelativeCurvature::from_radii([10.0, 10.0], [f64::INFINITY; 2], 0.0).unwrap();
    let gap = QuadraticGap::new(k);
    let pimp = Pimp::new(STEEL, STEEL, PimpOptions::default()).unwrap();
    let e = pimp.solve(&gap, LoadControl::LineLoad(5.0)).unwrap_err();
    assert_eq!(e.field(), Some("line_load"));
}

/// A synthetic "solver": the elliptical pressure `1 - (x-cx)²/a² - (y-cy)²/b²` on any grid.
fn ellipse(grid: &Grid2, c: [f64; 2], ab: [f64; 2]) -> Trial<()> {
    let p: Vec<f64> = grid
        .points()
        .map(|(x, y)| {
            let (u, v) = ((x - c[0]) / ab[0], (y - c[1]) / ab[1]);
            (1.0 - u * u - v * v).max(0.0)
        })
        .collect();
    Trial {
        result: (),
        zone: ContactZone::analyse(grid, &p).unwrap(),
    }
}

const BEM_POLICY: Policy = Policy {
    max_domains: 8,
    shrink: Shrink::AboutZone {
        trigger: 0.6,
        margin: 1.2,
    },
};

#[test]
fn the_adaptive_domain_grows_onto_an_off_centre_zone_and_zooms_in_on_it() {
    let (c, ab) = ([0.3, -0.2], [1.0, 0.25]);
    // Start far too small: the loop must grow (x and y), then zoom in about the zone.
    let mut seen = Vec::new();
    let out = domain::adapt(
        [[-0.2, 0.2], [-0.1, 0.1]],
        false,
        [64, 64],
        BEM_POLICY,
        |g, k| {
            seen.push(k);
            Ok(ellipse(g, c, ab))
        },
    )
    .unwrap();
    assert!(out.domains >= 3, "domains {}", out.domains);
    assert_eq!(seen, (0..out.domains).collect::<Vec<_>>());
    let z = out.zone;
    assert_eq!(z.touches_border, [false, false]);
    // The zone is the ellipse to within one cell at each edge.
    let (dx, dy) = (out.grid.dx(), out.grid.dy());
    for (e, want, d) in [
        (z.extents[0], [c[0] - ab[0], c[0] + ab[0]], dx),
        (z.extents[1], [c[1] - ab[1], c[1] + ab[1]], dy),
    ] {
        assert!(
            (e[0] - want[0]).abs() <= d && (e[1] - want[1]).abs() <= d,
            "{e:?} vs {want:?}"
        );
    }
    // Zoomed about the zone's centre: the domain is centred on it within a cell, and the
    // zone fills at least 1/margin - 2 cells of it.
    let xr = [out.grid.x(0) - 0.5 * dx, out.grid.x(63) + 0.5 * dx];
    assert!((0.5 * (xr[0] + xr[1]) - c[0]).abs() < dx, "{xr:?}");
    assert!(2.0 * ab[0] / (xr[1] - xr[0]) > 1.0 / 1.2 - 2.0 / 64.0);
}

#[test]
fn pimp_policy_zooms_about_the_contact_point() {
    let policy = Policy {
        max_domains: 12,
        shrink: Shrink::AboutOrigin {
            trigger: 0.6,
            factor: 1.15,
        },
    };
    let out = domain::adapt(
        [[-5.0, 5.0], [-5.0, 5.0]],
        false,
        [64, 64],
        policy,
        |g, _| Ok(ellipse(g, [0.0, 0.0], [1.0, 0.5])),
    )
    .unwrap();
    assert_eq!(out.domains, 2, "one zoom");
    let half = 0.5 * out.grid.dx() * 64.0;
    // 1.15 times the first grid's reach (cell edges), which is 1 mm within a cell (10/64 mm).
    let cell = 10.0 / 64.0;
    assert!(
        half > 1.15 * (1.0 - cell) && half < 1.15 * (1.0 + cell),
        "{half}"
    );
}

#[test]
fn the_adaptive_domain_refuses_what_it_cannot_resolve() {
    // A fixed domain that cuts the zone off.
    let e = domain::adapt(
        [[-0.5, 0.5], [-0.5, 0.5]],
        true,
        [32, 32],
        BEM_POLICY,
        |g, _| Ok(ellipse(g, [0.0, 0.0], [1.0, 1.0])),
    )
    .unwrap_err();
    assert_eq!(e.field(), Some("extent"));
    assert!(e.to_string().contains("border"), "{e}");
    // A fixed domain on which the zone spans fewer than MIN_CELLS_ACROSS cells.
    let e = domain::adapt(
        [[-5.0, 5.0], [-5.0, 5.0]],
        true,
        [32, 32],
        BEM_POLICY,
        |g, _| Ok(ellipse(g, [0.0, 0.0], [0.5, 0.5])),
    )
    .unwrap_err();
    assert_eq!(e.field(), Some("cells"));
    assert!(e.to_string().contains(&MIN_CELLS_ACROSS.to_string()), "{e}");
    // No loaded cell at all.
    let e = domain::adapt(
        [[-5.0, 5.0], [-5.0, 5.0]],
        false,
        [16, 16],
        BEM_POLICY,
        |g, _| Ok(ellipse(g, [0.0, 0.0], [1e-3, 1e-3])),
    )
    .unwrap_err();
    assert!(e.to_string().contains("no grid cell"), "{e}");
    // A zone that runs away (always at the border): gives up after max_domains grids.
    let mut n = 0;
    let e = domain::adapt(
        [[-1.0, 1.0], [-1.0, 1.0]],
        false,
        [16, 16],
        BEM_POLICY,
        |g, _| {
            n += 1;
            Ok(ellipse(g, [0.0, 0.0], [1e9, 1e9]))
        },
    )
    .unwrap_err();
    assert_eq!(n, BEM_POLICY.max_domains);
    assert!(e.to_string().contains("did not settle"), "{e}");
}

/// PimP and the half-space solver return the same type; both carry a status.
#[test]
fn both_field_solvers_return_one_solution_type_with_a_status() {
    let k = RelativeCurvature::from_radii([10.0, 10.0], [f64::INFINITY; 2], 0.0).unwrap();
    let gap = QuadraticGap::new(k);
    let pimp = Pimp::new(STEEL, STEEL, PimpOptions::default()).unwrap();
    let p = pimp.solve_force(&gap, 100.0).unwrap();
    assert_eq!(p.status.termination, Termination::Converged);
    assert!(p.status.iterations > 0 && p.status.residual <= 1e-7);
    let a = pimp.solve_approach(&gap, p.approach).unwrap();
    assert_eq!(a.status.iterations, 0);
    let bem = Bem::new(STEEL, STEEL, BemOptions::default()).unwrap();
    let b = bem.solve_force(&gap, 100.0).unwrap();
    assert_eq!(b.status.termination, Termination::Converged);
    assert!(b.status.residual <= 1e-8);
    assert_eq!(b.status, b.detail.report.status);
    fn headline<D>(s: &NormalSolution<D>) -> [f64; 3] {
        [s.force, s.max_pressure, s.contact_area]
    }
    let (hp, hb) = (headline(&p), headline(&b));
    assert!((hp[1] / hb[1] - 1.0).abs() < 0.01, "{hp:?} {hb:?}");
}

/// Without PimP's estimate the half-space solver starts from the Hertz ellipse of the
/// gap; with it, from PimP's zone. Both settle on the same contact (the start only
/// moves the domain by less than a cell's worth of answer).
#[test]
fn the_half_space_solver_does_not_need_pimp_to_place_its_domain() {
    let k = RelativeCurvature::from_radii([20.0, 5.0], [f64::INFINITY; 2], 0.0).unwrap();
    let gap = QuadraticGap::new(k);
    let plain = Bem::new(STEEL, STEEL, BemOptions::default()).unwrap();
    let with = plain
        .clone()
        .with_estimate(kontakt::pimp::zone_estimate(STEEL, STEEL).unwrap());
    let (a, b) = (
        plain.solve_force(&gap, 200.0).unwrap(),
        with.solve_force(&gap, 200.0).unwrap(),
    );
    assert!((a.max_pressure / b.max_pressure - 1.0).abs() < 2e-3);
    assert!((a.approach / b.approach - 1.0).abs() < 2e-3);
}

#[test]
fn shared_types_cross_threads() {
    fn send_sync<T: Send + Sync>() {}
    send_sync::<Box<dyn GapSource>>();
    send_sync::<Box<dyn kontakt::tangential::TractionCurve>>();
    send_sync::<Bem>();
    send_sync::<Pimp>();
    send_sync::<kontakt::pimp::PimpSolution>();
    send_sync::<kontakt::halfspace::BemSolution>();
}

/// Hertz on a grid returns the same type as the field solvers; its sampled numbers
/// converge on the closed form as the cells shrink.
#[test]
fn hertz_on_a_grid_is_a_normal_solution_that_matches_the_closed_form() {
    use kontakt::hertz::{HertzPointContact, PointGeometry};
    // An ellipse turned against the grid (orientation != 0), 400 N.
    let g = PointGeometry::new([8.0, 30.0], [15.0, -90.0], 0.4).unwrap();
    let exact = HertzPointContact::new(g, STEEL, STEEL)
        .unwrap()
        .solve_force(400.0)
        .unwrap();
    let h = 1.1 * exact.semi_axes[0];
    let mut errors = Vec::new();
    for n in [101, 401] {
        let s = exact.on_grid(Grid2::centered(h, h, n, n).unwrap()).unwrap();
        assert_eq!(s.status.termination, Termination::Converged);
        assert_eq!((s.force, s.approach), (exact.force, exact.approach));
        assert_eq!(s.detail, exact);
        assert_eq!(s.zone.patches, 1);
        let area = std::f64::consts::PI * exact.semi_axes[0] * exact.semi_axes[1];
        let e = [
            (s.contact_area / area - 1.0).abs(),
            (s.zone.force / exact.force - 1.0).abs(),
            1.0 - s.max_pressure / exact.max_pressure,
        ];
        // Counted-cell area and midpoint-rule force: within a few cells' worth.
        let cell = 2.0 * h / n as f64;
        let tol = 4.0 * cell / exact.semi_axes[1];
        assert!(
            e.iter().all(|&x| x < tol && x >= 0.0),
            "n = {n}: {e:?} vs {tol}"
        );
        errors.push(e[0].max(e[1]));
    }
    // Finer cells, smaller error.
    assert!(errors[1] < 0.5 * errors[0], "{errors:?}");
    // A grid whose cells miss the ellipse is an error, not an empty result.
    let coarse = Grid2::new([5.0, 6.0], [5.0, 6.0], 4, 4).unwrap();
    assert_eq!(exact.on_grid(coarse).unwrap_err().field(), Some("grid"));
}
