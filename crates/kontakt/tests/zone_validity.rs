//! The size check of PimP and half-space results (`kontakt::field::validity`, docs/pimp.md
//! §5 and docs/halfspace.md §10): a ten-times overload warns, a groove conforming to within a
//! micrometre and a contact running over a roller's end face are refused, naming the
//! quantity; the nominal cases pass plainly.

#![allow(clippy::unwrap_used)]

use kontakt::Error;
use kontakt::bearing::{RollerRib, RollerRibSpec};
use kontakt::field::NormalSolution;
use kontakt::field::validity::{
    MAX_EDGE_RATIO, MAX_SIZE_RATIO, WARN_EDGE_RATIO, WARN_SIZE_RATIO, ellipse_size_check,
    zone_size_check,
};
use kontakt::gap::{GapSource, QuadraticGap, SurfacePairGap};
use kontakt::geometry::surface::{Material, PlacedSurface, Surface};
use kontakt::halfspace::{Bem, BemOptions};
use kontakt::hertz::{HertzPointContact, PointGeometry};
use kontakt::material::ElasticMaterial;
use kontakt::pimp::{Pimp, PimpOptions};
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};

fn steel() -> ElasticMaterial {
    ElasticMaterial::new(210_000.0, 0.3).unwrap()
}

fn pimp() -> Pimp {
    let options = PimpOptions {
        cells: [48, 48],
        ..PimpOptions::default()
    };
    Pimp::new(steel(), steel(), options).unwrap()
}

fn bem() -> Bem {
    let options = BemOptions {
        cells: [64, 64],
        threads: Some(1),
        ..BemOptions::default()
    };
    Bem::new(steel(), steel(), options)
        .unwrap()
        .with_estimate(kontakt::pimp::zone_estimate(steel(), steel()).unwrap())
}

/// Both methods' check on one source and force: `Ok(warnings)` or the error.
fn check_both(source: &dyn GapSource, force: f64) -> [Result<Vec<String>, Error>; 2] {
    let run = |s: Result<NormalSolution<()>, Error>| {
        s.and_then(|s| zone_size_check(source, &s).map(|c| c.warnings()))
    };
    [
        run(pimp()
            .solve_force(source, force)
            .map(|s| s.map_detail(|_| ()))),
        run(bem()
            .solve_force(source, force)
            .map(|s| s.map_detail(|_| ()))),
    ]
}

/// The 6205 inner-race contact (ball 3.969 mm in a groove of -4.128 mm on a race of
/// 15.281 mm, as examples/ball_inner_race.toml): plain at 1000 N, a warning naming body 1
/// (the ball) at ten times the load, for PimP and the half-space solver alike.
#[test]
fn ten_times_overload_warns() {
    assert_eq!(WARN_SIZE_RATIO, kontakt::hertz::validity::WARN_SIZE_RATIO);
    assert_eq!(MAX_SIZE_RATIO, kontakt::hertz::validity::MAX_SIZE_RATIO);
    let groove = QuadraticGap::of_bodies([3.969, 3.969], [15.281, -4.128], 0.0).unwrap();
    for r in check_both(&groove, 1000.0) {
        assert_eq!(r.unwrap(), Vec::<String>::new());
    }
    for r in check_both(&groove, 10_000.0) {
        let w = r.unwrap();
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(
            w[0].starts_with("contact size:")
                && w[0].contains("of body 1's radius of curvature 3.969 mm"),
            "{w:?}"
        );
    }
}

/// The same groove conforming to the ball to within 1 µm (-3.970 mm): the zone would be
/// far wider than the ball's radius; refused with the field `body1.radii`, whichever
/// method solved it.
#[test]
fn groove_conforming_within_a_micrometre_is_refused() {
    let groove = QuadraticGap::of_bodies([3.969, 3.969], [15.281, -3.970], 0.0).unwrap();
    for r in check_both(&groove, 1000.0) {
        let e = r.unwrap_err();
        assert!(
            matches!(&e, Error::Geometry { field, .. } if field == "body1.radii"),
            "{e}"
        );
        assert!(e.to_string().contains("near-conformal"), "{e}");
    }
}

/// A ball placed in a toroidal groove (the surfaces themselves, ray-cast): the same
/// verdicts as the quadratic gap, plain at the nominal load and refused when the groove
/// conforms to within 1 µm.
#[test]
fn placed_ball_in_groove() {
    let ball_radius = 3.969;
    let ball_in = |groove_radius: f64| {
        // Groove: a torus about z with the tube through the ball's centre, material
        // outside the tube (the ring's groove); the ball touches its bottom at x = 15.281.
        let race = 15.281;
        let major = race + groove_radius;
        let ring = PlacedSurface::new(
            Surface::torus(major, groove_radius, Material::Outside).unwrap(),
            Isometry3::identity(),
        )
        .unwrap();
        let ball = PlacedSurface::new(
            Surface::sphere(ball_radius, Material::Inside).unwrap(),
            Isometry3::from_parts(
                Translation3::new(race + ball_radius, 0.0, 0.0),
                UnitQuaternion::identity(),
            ),
        )
        .unwrap();
        SurfacePairGap::from_poses(ball, ring, None).unwrap()
    };
    let nominal = ball_in(4.128);
    for r in check_both(&nominal, 1000.0) {
        assert_eq!(r.unwrap(), Vec::<String>::new());
    }
    // Conformal to 1 µm: the zone, several millimetres along the groove and a few cells
    // across, is more than the solvers' grids resolve; the check on the predicted (Hertz)
    // ellipse refuses it before a solve, naming the ball.
    let conformal = ball_in(3.970);
    let hertz = HertzPointContact::new(
        PointGeometry::from_curvature(conformal.curvature()),
        steel(),
        steel(),
    )
    .unwrap()
    .solve_force(1000.0)
    .unwrap();
    let e = ellipse_size_check(&conformal, hertz.semi_axes, hertz.orientation).unwrap_err();
    assert!(
        matches!(&e, Error::Geometry { field, .. } if field == "body1.radii"),
        "{e}"
    );
    for r in check_both(&conformal, 1000.0) {
        assert!(r.is_err(), "{r:?}");
    }
    // The prediction passes the nominal groove, as the solutions do.
    let hertz = HertzPointContact::new(
        PointGeometry::from_curvature(nominal.curvature()),
        steel(),
        steel(),
    )
    .unwrap()
    .solve_force(1000.0)
    .unwrap();
    let ok = ellipse_size_check(&nominal, hertz.semi_axes, hertz.orientation).unwrap();
    assert!(ok.warnings().is_empty());
}

/// The roller end face ends at the roller's large end, 2.75 mm from the contact point of
/// the built-in pairings: plain at the study's 250 N, refused at a load whose zone runs
/// over that edge, naming `bearing.roller_large_end_radius`.
#[test]
fn roller_end_face_edge() {
    const { assert!(WARN_EDGE_RATIO < MAX_EDGE_RATIO) };
    let pair = RollerRib::new(RollerRibSpec::builtin("torus-torus-14").unwrap()).unwrap();
    let gap = pair.gap().unwrap();
    let edge = gap.bodies().unwrap()[0].edges[0].unwrap();
    assert!((edge.distance - 2.75).abs() < 0.05, "{edge:?}");
    assert!(gap.bodies().unwrap()[1].edges.iter().all(Option::is_none));
    let s = pimp().solve_force(&gap, 250.0).unwrap();
    let check = zone_size_check(&gap, &s).unwrap();
    assert!(check.warnings().is_empty(), "{:?}", check.warnings());
    let e = check.edge.unwrap();
    assert!(e.ratio > 0.05 && e.ratio < WARN_EDGE_RATIO, "{e:?}");
    // Contact heights closer to the edge (0.3 mm, then 0.1 mm from it): a warning, then
    // the zone reaches past it.
    let at_height = |h: f64| {
        let mut spec = RollerRibSpec::builtin("torus-torus-14").unwrap();
        spec.contact_height = h;
        let gap = RollerRib::new(spec).unwrap().gap().unwrap();
        let s = pimp().solve_force(&gap, 250.0).unwrap();
        zone_size_check(&gap, &s)
    };
    let w = at_height(5.2).unwrap().warnings();
    assert!(
        w.len() == 1 && w[0].starts_with("face edge:") && w[0].contains("roller's large end"),
        "{w:?}"
    );
    let e = at_height(5.4).unwrap_err();
    assert!(
        matches!(&e, Error::Geometry { field, .. } if field == "bearing.roller_large_end_radius"),
        "{e}"
    );
}

/// A crowned roller on a plane, the contact 1 mm from the roller's end: its profile ends
/// there, and the contact ellipse, long along the roller, reaches past it.
#[test]
fn crowned_roller_end() {
    use kontakt::geometry::surface::Profile;
    let roller = Surface::revolution(
        Profile::Crowned {
            radius: 5.0,
            crown_radius: 500.0,
            half_length: 8.0,
        },
        Material::Inside,
    )
    .unwrap();
    // Axis along x; the roller turned so that the plane touches it at z = 7 of its profile:
    // tilt the axis by the profile's slope there.
    let slope = (7.0f64 / 500.0).asin();
    let axis = Vector3::new(slope.cos(), 0.0, slope.sin());
    let pose = kontakt::bearing::roller_rib::frame_along(
        nalgebra::Point3::new(0.0, 0.0, 5.0),
        &nalgebra::Unit::new_normalize(axis),
    );
    let roller = PlacedSurface::new(roller, pose).unwrap();
    let plane =
        PlacedSurface::new(Surface::plane(Material::Inside), Isometry3::identity()).unwrap();
    let gap = SurfacePairGap::from_poses(roller, plane, None).unwrap();
    let edges = gap.bodies().unwrap()[0].edges;
    let nearest = edges
        .iter()
        .flatten()
        .map(|e| e.distance)
        .fold(f64::INFINITY, f64::min);
    assert!((nearest - 1.0).abs() < 0.05, "{edges:?}");
    let light = pimp().solve_force(&gap, 20.0).unwrap();
    assert!(zone_size_check(&gap, &light).is_ok());
    let heavy = pimp().solve_force(&gap, 20_000.0).unwrap();
    let e = zone_size_check(&gap, &heavy).unwrap_err();
    assert!(
        matches!(&e, Error::Geometry { field, .. } if field == "body1.half_length"),
        "{e}"
    );
}

/// A source that does not know its bodies is not checked.
#[test]
fn unknown_bodies_are_not_checked() {
    let k = kontakt::geometry::RelativeCurvature::from_radii([3.969, 3.969], [15.281, -3.970], 0.0)
        .unwrap();
    let gap = QuadraticGap::new(k);
    let s = pimp().solve_force(&gap, 1000.0).unwrap();
    assert_eq!(zone_size_check(&gap, &s).unwrap(), Default::default());
}
