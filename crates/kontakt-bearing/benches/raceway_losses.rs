//! Criterion benchmark of the per-slice raceway losses (issue 29, "Speed", first step): the
//! losses of 20 rollers × 2 raceways × 31 slices = 1240 slices (a TRB's raceway contacts at
//! one operating point), with the mixed law (limiting-shear fluid), the Zhu-Cheng thermal
//! factor and both rolling-resistance fits, each also from the slices' speed-independent
//! parts (`RacewayLosses::plan_slice`, made outside the timed closure: the cost per speed of
//! a planned sweep). The model is built once outside the timed closure. Run by the lead: `cargo bench -p kontakt-bearing --bench raceway_losses`.

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt::friction::FrictionLaw;
use kontakt::lubrication::RollingResistanceModel;
use kontakt_bearing::friction::raceway::{RacewayLosses, RacewayLubrication, RacewaySlice};
use std::hint::black_box;

fn slices() -> Vec<RacewaySlice> {
    let mut out = Vec::with_capacity(1240);
    for roller in 0..20 {
        let load = 400.0 * (1.0 + (roller as f64 * 0.314).cos()).max(0.05);
        for raceway in 0..2 {
            for k in 0..31 {
                let x = (k as f64 - 15.0) / 15.0;
                out.push(RacewaySlice {
                    load_per_length: load * (1.0 - 0.3 * x * x),
                    width: 0.55,
                    radius: if raceway == 0 { 5.5 } else { 7.5 },
                    entrainment_speed: 4_000.0,
                    sliding_speed: 10.0 * x,
                    reduced_modulus: 115_000.0,
                });
            }
        }
    }
    out
}

fn bench_raceway_losses(c: &mut Criterion) {
    let slices = slices();
    let mut group = c.benchmark_group("raceway_losses");
    for (name, rolling) in [
        (
            "trb_1240_slices_biboulet_houpert",
            RollingResistanceModel::BibouletHoupert,
        ),
        (
            "trb_1240_slices_zhou_hoeprich",
            RollingResistanceModel::ZhouHoeprich,
        ),
    ] {
        let model = RacewayLosses::new(RacewayLubrication {
            viscosity: 0.03e-6,
            alpha: 0.02,
            viscosity_slope: Some(-1.7e-9),
            conductivity: 0.134,
            film_starvation: 1.0,
            starvation_degree: None,
            roughness: 0.2e-3,
            law: FrictionLaw::mixed(0.12).expect("valid law"),
            rolling,
        })
        .expect("valid lubrication");
        group.bench_function(name, |b| {
            b.iter(|| {
                let mut p = 0.0;
                for s in &slices {
                    p += model.slice(black_box(s)).expect("valid slice").power();
                }
                p
            })
        });
        // The same slices from their speed-independent parts (`plan_slice`, made once
        // outside the timed closure): what each speed of a planned sweep costs.
        let plans: Vec<_> = slices
            .iter()
            .map(|s| model.plan_slice(s).expect("plan").expect("loaded"))
            .collect();
        group.bench_function(format!("{name}_planned"), |b| {
            b.iter(|| {
                let mut p = 0.0;
                for (s, plan) in slices.iter().zip(&plans) {
                    p += model
                        .slice_planned(black_box(s), plan)
                        .expect("valid slice")
                        .power();
                }
                p
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench_raceway_losses);
criterion_main!(benches);
