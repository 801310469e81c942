//! Issue 29, "Speed": the per-slice raceway losses allocate nothing per call (the model
//! owns its quadrature rule; every result is `Copy`), so that summing them over the slices
//! and rollers of a bearing costs no allocation.

#[path = "../../kontakt/tests/support/counting_alloc.rs"]
mod counting_alloc;

use counting_alloc::allocations;
use kontakt::friction::FrictionLaw;
use kontakt::lubrication::RollingResistanceModel;
use kontakt_bearing::friction::raceway::{RacewayLosses, RacewayLubrication, RacewaySlice};

#[test]
fn raceway_slice_losses_allocate_nothing() {
    for rolling in [
        RollingResistanceModel::BibouletHoupert,
        RollingResistanceModel::ZhouHoeprich,
    ] {
        let model = RacewayLosses::new(RacewayLubrication {
            viscosity: 0.03e-6,
            alpha: 0.02,
            viscosity_slope: Some(-1.7e-9),
            conductivity: 0.134,
            film_starvation: 1.0,
            starvation_degree: Some(10.0),
            roughness: 0.2e-3,
            law: FrictionLaw::mixed(0.12).expect("valid law"),
            rolling,
        })
        .expect("valid lubrication");
        let (power, n) = allocations(|| {
            let mut p = 0.0;
            for k in 0..200 {
                let slice = RacewaySlice {
                    load_per_length: 5.0 * k as f64,
                    width: 1.0,
                    radius: 6.0,
                    entrainment_speed: 4_000.0,
                    sliding_speed: 20.0 - 0.2 * k as f64,
                    reduced_modulus: 115_000.0,
                };
                p += model.slice(&slice).expect("valid slice").power();
            }
            p
        });
        assert!(power.is_finite() && power > 0.0);
        assert_eq!(n, 0, "{rolling:?}");
    }
}
