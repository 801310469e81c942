//! Shared set-up of the whole-bearing friction tests and bench: raceway losses of an oil,
//! the rib study's rib friction model with its bearing, and a solved ISO load distribution
//! under axial load.

use kontakt::bearing::{RibFrictionModel, RibLubrication, RollerRibSpec, RollerSet};
use kontakt::friction::FrictionLaw;
use kontakt::lubrication::{FilmFormula, Lubricant, RollingResistanceModel};
use kontakt_bearing::equilibrium::{RingLoad, RollerBearingSolver};
use kontakt_bearing::friction::raceway::RacewayLosses;
use kontakt_bearing::friction::torque::{iso_slice_loads, raceway_lubrication};
use kontakt_bearing::geometry::RollerBearing;

/// Raceway losses of `oil` at `temperature` °C, σ = 0.2 µm, mixed law μ_b = 0.12,
/// Biboulet-Houpert rolling resistance.
pub fn losses(oil: &Lubricant, temperature: f64, thermal: bool) -> RacewayLosses {
    let law = FrictionLaw::mixed(0.12).expect("law");
    RacewayLosses::new(
        raceway_lubrication(
            oil,
            temperature,
            thermal,
            0.2e-3,
            law,
            RollingResistanceModel::BibouletHoupert,
        )
        .expect("lubrication"),
    )
    .expect("losses")
}

/// ISO VG 68 (860 kg/m³, α = 0.02 1/MPa).
pub fn vg68() -> Lubricant {
    Lubricant::iso_vg(68, 860.0, 0.02).expect("oil")
}

/// The rib study's sphere-torus-57 pair with `count` rollers, ISO VG 68 at 70 °C, mixed law
/// μ_b = 0.12, centrifugal force on; and its bearing with 15 slices.
pub fn rib_study(count: usize) -> (RibFrictionModel, RollerBearing) {
    let set = RollerSet {
        count,
        ..RollerSet::default()
    };
    let rib = RibFrictionModel::new(
        RollerRibSpec::builtin("sphere-torus-57").expect("pair"),
        set,
        FrictionLaw::mixed(0.12).expect("law"),
        Some(RibLubrication {
            lubricant: vg68(),
            temperature: 70.0,
            roughness: [0.2e-3, 0.2e-3],
            formula: FilmFormula::Chittenden,
        }),
        true,
    )
    .expect("rib model");
    let mut bearing = RollerBearing::of_roller_rib(rib.pair(), &set).expect("bearing");
    bearing.slices = 15;
    (rib, bearing)
}

/// The cup and cone slice loads of `bearing` under the axial force `axial` \[N\] (tilts
/// held), and the solver.
pub fn solved(bearing: &RollerBearing, axial: f64) -> (Vec<f64>, Vec<f64>, RollerBearingSolver) {
    solved_combined(bearing, 0.0, axial)
}

/// [`solved`] under the radial force `radial` (x) \[N\] with the axial force `axial`.
pub fn solved_combined(
    bearing: &RollerBearing,
    radial: f64,
    axial: f64,
) -> (Vec<f64>, Vec<f64>, RollerBearingSolver) {
    let mut solver = RollerBearingSolver::new(bearing.clone()).expect("solver");
    let s = solver
        .solve(&RingLoad::forces([radial, 0.0, axial, 0.0, 0.0]).with_tilts_held())
        .expect("solve");
    assert!(s.status.converged());
    let n = bearing.rollers * bearing.slices;
    let (mut cup, mut cone) = (vec![0.0; n], vec![0.0; n]);
    iso_slice_loads(
        solver.slice_loads(),
        solver.roller_loads(),
        &mut cup,
        &mut cone,
    )
    .expect("slices");
    (cup, cone, solver)
}
