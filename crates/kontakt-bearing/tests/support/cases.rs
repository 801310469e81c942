//! The bearings and loads of issue 28's speed targets, shared by benches/bearing.rs and
//! tests/solve_alloc.rs. Include with `#[path = "…/support/cases.rs"] mod cases;`.

use kontakt_bearing::equilibrium::RingLoad;
use kontakt_bearing::geometry::{BallBearing, RollerBearing};
use kontakt_bearing::speed::RingSpeeds;

/// The 32216 geometry of examples/bearing_32216.toml (d_m 108.5 mm, rollers 17 × 20.7 mm,
/// cup 16.0°, cone 11.7°, ISO profile, zero clearance) with issue 28's 20 rollers
/// (20 · 17 mm ≤ π d_m = 340.9 mm) and 31 slices.
pub fn trb() -> RollerBearing {
    let mut b = RollerBearing::tapered(
        108.5,
        20,
        17.0,
        20.7,
        16.0_f64.to_radians(),
        11.7_f64.to_radians(),
    );
    b.slices = 31;
    b
}

/// 20 kN radial and 10 kN axial (above F_r tan α = 5.7 kN) times `scale`, tilts held.
pub fn trb_load(scale: f64) -> RingLoad {
    RingLoad::forces([20_000.0 * scale, 0.0, 10_000.0 * scale, 0.0, 0.0]).with_tilts_held()
}

/// A 6210-class deep-groove ball bearing: d_m 70 mm, 10 balls of 12.7 mm, osculations
/// 0.52/0.53, 10 µm diametral clearance.
pub fn dgbb() -> BallBearing {
    let mut b = BallBearing::deep_groove(70.0, 10, 12.7, [0.52, 0.53]);
    b.clearance_mm = 0.01;
    b
}

/// 5 kN radial and 2 kN axial times `scale`.
pub fn dgbb_load(scale: f64) -> RingLoad {
    RingLoad::forces([5_000.0 * scale, 0.0, 2_000.0 * scale, 0.0, 0.0])
}

/// The ring speeds of the ball bearing at speed: the inner ring at 10 000 r/min (about the
/// oil-lubricated limit of a 6210), the outer ring fixed.
pub fn dgbb_speeds() -> RingSpeeds {
    RingSpeeds::from_rpm(10_000.0, 0.0)
}

/// A cylindrical roller bearing of 14 rollers 10 × 12 mm on a 60 mm pitch circle (the
/// crate's example), ISO profile, 10 µm clearance, 31 slices.
pub fn crb() -> RollerBearing {
    let mut b = RollerBearing::cylindrical(60.0, 14, 10.0, 12.0);
    b.clearance_mm = 0.01;
    b.slices = 31;
    b
}

/// 10 kN radial.
pub fn crb_load() -> RingLoad {
    RingLoad::forces([10_000.0, 0.0, 0.0, 0.0, 0.0])
}

/// The roller end/rib pair of the rib-contact model on [`trb`]: a spherical face of
/// 80 mm radius on a conical rib, contact 4.5 mm above the roller axis (about half the
/// large-end radius, as in the rib study's 2.75 of 5.5 mm). Representative, not a
/// manufacturer's drawing.
#[allow(dead_code)] // not every includer uses every case
pub fn trb_rib() -> kontakt_bearing::roller_equilibrium::RibContact {
    kontakt_bearing::roller_equilibrium::RibContact {
        face: kontakt::bearing::FaceShape::Sphere { radius: 80.0 },
        rib: kontakt::bearing::RibShape::Cone,
        contact_height_mm: 4.5,
    }
}
