//! The friction hot paths allocate nothing per call: the integral over a solved field
//! (`contact_friction`, Coulomb and the mixed law), the power density into a caller's
//! buffer, and the whole-bearing evaluation at one speed on a solved contact
//! (`RibFrictionModel::friction_on`: kinematics, loads, film, integral, totals).
#![allow(clippy::unwrap_used)]

use kontakt::bearing::{
    Operating, PressureModel, RibFrictionModel, RibLubrication, RollerRibSpec, RollerSet,
    TaperedKinematics,
};
use kontakt::friction::{FrictionLaw, contact_friction, power_density};
use kontakt::lubrication::{FilmFormula, Lubricant};

#[path = "support/counting_alloc.rs"]
mod counting_alloc;

use counting_alloc::allocations;

#[test]
fn friction_hot_paths_do_not_allocate() {
    let spec = RollerRibSpec::builtin("torus-cone-28").unwrap();
    let lub = RibLubrication {
        lubricant: Lubricant::iso_vg(68, 860.0, 0.02).unwrap(),
        temperature: 70.0,
        roughness: [0.2e-3, 0.2e-3],
        formula: FilmFormula::Chittenden,
    };
    let model = RibFrictionModel::new(
        spec,
        RollerSet::default(),
        FrictionLaw::mixed(0.12).unwrap(),
        Some(lub),
        true,
    )
    .unwrap();
    let op = Operating {
        axial_load: 15_000.0,
        inner_speed: 150.0,
        outer_speed: 0.0,
    };
    let (k, loads) = model.loads(&op).unwrap();
    let field = model.solve(PressureModel::Pimp, loads.rib).unwrap();
    let (r, n) = allocations(|| {
        let (k, loads) = model.loads(&op).unwrap();
        model
            .friction_on(PressureModel::Pimp, &field, &op, &k, &loads)
            .unwrap()
    });
    assert_eq!(n, 0, "friction_on allocated {n} times");
    assert!(r.bearing_torque > 0.0);
    let pair = TaperedKinematics::rib_pair(&k, 0.0).unwrap();
    let mut density = vec![0.0; field.grid.len()];
    for law in [
        FrictionLaw::coulomb(0.1).unwrap(),
        FrictionLaw::mixed(0.12).unwrap(),
    ] {
        let cell = law.with_film(&r.film).unwrap();
        let (f, n) = allocations(|| contact_friction(&field, model.frame(), &pair, &cell).unwrap());
        assert_eq!(n, 0, "contact_friction allocated {n} times");
        assert!(f.grid.power > 0.0);
        let sliding = pair
            .velocity_field(model.frame(), field.orientation)
            .unwrap();
        let (_, n) = allocations(|| {
            power_density(&field.grid, &field.pressure, &sliding, &cell, &mut density).unwrap()
        });
        assert_eq!(n, 0, "power_density allocated {n} times");
    }
}
