//! Friction benchmarks (issue 11): the friction integral over a 64 × 64 PimP pressure map of
//! a roller/rib contact including its sliding field (Coulomb and the mixed law), the whole
//! bearing's rib friction at one speed from an already solved contact (kinematics, rib load,
//! film, integral), the Hamrock-Dowson film alone, and — what a user would otherwise
//! pick — Houpert's closed-form lever arm M = μ Q e √(1 + 0.18 (a/e)²) for one contact.
//! Figures are recorded in docs/PERFORMANCE.md.

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt::bearing::{
    Operating, PressureModel, RibFrictionModel, RibLubrication, RollerRib, RollerRibSpec,
    RollerSet, TaperedKinematics,
};
use kontakt::friction::{FilmState, FrictionLaw, contact_friction};
use kontakt::geometry::ContactFrame;
use kontakt::lubrication::{FilmContact, FilmFormula, Lubricant, film_thickness};
use kontakt::material::ElasticMaterial;
use kontakt::pimp::{Pimp, PimpOptions, SurfacePairGap};
use std::hint::black_box;

fn bench_friction(c: &mut Criterion) {
    let mut group = c.benchmark_group("friction");
    let rr = RollerRib::new(RollerRibSpec::builtin("torus-cone-28").expect("pairing")).expect("rr");
    let gap = SurfacePairGap::new(rr.face.clone(), rr.rib.clone(), rr.contact).expect("gap");
    let steel = ElasticMaterial::STEEL;
    let pimp = Pimp::new(
        steel,
        steel,
        PimpOptions {
            cells: [64, 64],
            ..PimpOptions::default()
        },
    )
    .expect("pimp");
    let field = pimp.solve_force(&gap, 220.0).expect("solve");
    assert_eq!(field.grid.len(), 64 * 64);
    let k = TaperedKinematics::of_roller_rib(&rr, 150.0, 0.0).expect("kinematics");
    let pair = k.rib_pair(0.0).expect("pair");
    let frame = ContactFrame::of_gap(&gap);
    let film = FilmState::new(0.4e-3, 1.4, 1.7e-8, 0.02).expect("film");
    let coulomb = FrictionLaw::coulomb(0.1)
        .expect("law")
        .with_film(&FilmState::dry())
        .expect("cell law");
    let mixed = FrictionLaw::mixed(0.12)
        .expect("law")
        .with_film(&film)
        .expect("cell law");
    group.bench_function("map_64x64_coulomb", |b| {
        b.iter(|| {
            contact_friction(black_box(&field), &frame, black_box(&pair), &coulomb)
                .expect("friction")
        })
    });
    group.bench_function("map_64x64_mixed", |b| {
        b.iter(|| {
            contact_friction(black_box(&field), &frame, black_box(&pair), &mixed).expect("friction")
        })
    });
    // The case of bench/friction/friction_numpy.py: a Hertz ellipse spinning about a pivot.
    {
        use kontakt::friction::grid_friction;
        use kontakt::geometry::{Grid2, VelocityField};
        let (p0, a, b, omega, e) = (700.0f64, 1.2f64, 0.3f64, 300.0f64, 2.76f64);
        let grid = Grid2::centered(1.05 * a, 1.05 * b, 64, 64).expect("grid");
        let pressure: Vec<f64> = grid
            .points()
            .map(|(x, y)| p0 * (1.0 - (x / a).powi(2) - (y / b).powi(2)).max(0.0).sqrt())
            .collect();
        let spin = VelocityField {
            sliding: [[-omega * e, 0.0], [0.0, omega], [-omega, 0.0]],
            entrainment: [[0.0; 2]; 3],
        };
        let g = grid_friction(&grid, &pressure, &spin, &coulomb).expect("friction");
        eprintln!(
            "kontakt case: F = [{:.6}, {:.6}] N, M = {:.6} N mm, P = {:.6} W",
            g.force[0], g.force[1], g.moment, g.power
        );
        group.bench_function("map_64x64_coulomb_ellipse", |bn| {
            bn.iter(|| {
                grid_friction(&grid, black_box(&pressure), black_box(&spin), &coulomb)
                    .expect("friction")
            })
        });
    }
    // The contact element's PimP friction (issue 12): the loaded box of the torus/torus
    // roller end at about 250 N (50 × 52 cells of 28.3 × 6.37 µm), spinning at 9.43 rad/s
    // about a pole 40 mm away, by the blocks of `grid_friction_binned` and cell by cell.
    {
        use kontakt::friction::{binning_blocks, grid_friction, grid_friction_binned};
        use kontakt::geometry::{Grid2, VelocityField};
        let (p0, a, b, omega) = (1500.0f64, 0.70f64, 0.164f64, 9.43f64);
        let grid = Grid2::centered(25.0 * 0.02832, 26.0 * 0.00637, 50, 52).expect("grid");
        let pressure: Vec<f64> = grid
            .points()
            .map(|(x, y)| p0 * (1.0 - (x / a).powi(2) - (y / b).powi(2)).max(0.0).sqrt())
            .collect();
        let spin = VelocityField {
            sliding: [[-omega * 40.0, 0.0], [0.0, -omega], [omega, 0.0]],
            entrainment: [[0.0; 2]; 3],
        };
        eprintln!("element box: blocks {:?}", binning_blocks(&grid, &spin));
        group.bench_function("element_box_binned", |bn| {
            bn.iter(|| {
                grid_friction_binned(&grid, black_box(&pressure), black_box(&spin), &coulomb)
                    .expect("friction")
            })
        });
        group.bench_function("element_box_cells", |bn| {
            bn.iter(|| {
                grid_friction(&grid, black_box(&pressure), black_box(&spin), &coulomb)
                    .expect("friction")
            })
        });
    }
    // Houpert's closed form for one contact: the estimate a designer uses without a map.
    let (q, e, a, mu) = (220.0f64, 2.76f64, 1.2f64, 0.1f64);
    group.bench_function("houpert_closed_form", |b| {
        b.iter(|| {
            let (q, e, a) = (black_box(q), black_box(e), black_box(a));
            mu * q * e * (1.0 + 0.18 * (a / e).powi(2)).sqrt()
        })
    });
    // Film alone.
    let contact = FilmContact {
        rx: 60.0,
        ry: 4.0,
        entrainment_angle: 0.1,
        entrainment_speed: 1500.0,
        load: 220.0,
        reduced_modulus: 115_000.0,
    };
    group.bench_function("film_hamrock_dowson", |b| {
        b.iter(|| {
            film_thickness(
                black_box(&contact),
                1.7e-8,
                0.02,
                FilmFormula::HamrockDowson,
            )
            .expect("film")
        })
    });
    // Whole bearing at one speed from a solved contact: kinematics, loads (with the
    // centrifugal force), film at the contact point, the integral over the map, totals.
    let model = RibFrictionModel::new(
        rr.spec,
        RollerSet::default(),
        FrictionLaw::mixed(0.12).expect("law"),
        Some(RibLubrication {
            lubricant: Lubricant::iso_vg(68, 860.0, 0.02).expect("oil"),
            temperature: 70.0,
            roughness: [0.2e-3, 0.2e-3],
            formula: FilmFormula::HamrockDowson,
        }),
        true,
    )
    .expect("model");
    let op = Operating {
        axial_load: 15_000.0,
        inner_speed: 150.0,
        outer_speed: 0.0,
    };
    let (k0, loads0) = model.loads(&op).expect("loads");
    let solved = model.solve(PressureModel::Pimp, loads0.rib).expect("solve");
    group.bench_function("bearing_one_speed_from_solved_contact", |b| {
        b.iter(|| {
            let (k, loads) = model.loads(black_box(&op)).expect("loads");
            model
                .friction_on(PressureModel::Pimp, &solved, &op, &k, &loads)
                .expect("friction")
        })
    });
    let _ = k0;
    group.finish();

    // The demo's friction study for one pairing: 3 pressure models × 10 speeds, each speed
    // re-solving the contact at its rib load (the centrifugal force changes it).
    let mut slow = c.benchmark_group("friction_study");
    slow.sample_size(10);
    let speeds: Vec<f64> = (0..10)
        .map(|i| 50.0 * (120.0f64).powf(i as f64 / 9.0) * std::f64::consts::PI / 30.0)
        .collect();
    slow.bench_function("one_pairing_3_models_10_speeds", |b| {
        b.iter(|| {
            for m in PressureModel::ALL {
                model.sweep(m, 15_000.0, black_box(&speeds)).expect("sweep");
            }
        })
    });
    slow.finish();
}

criterion_group!(benches, bench_friction);
criterion_main!(benches);
