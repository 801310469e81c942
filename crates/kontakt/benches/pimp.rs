//! PimP benchmarks: the multi-body path (force for an approach on a sampled gap), the
//! ray-cast sampling of a torus/torus roller-rib pair, and the full equilibrium solve.
//! Figures are recorded in docs/PERFORMANCE.md.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use kontakt::bearing::{RollerRib, RollerRibSpec};
use kontakt::geometry::{Grid2, RelativeCurvature};
use kontakt::material::ElasticMaterial;
use kontakt::pimp::{GapSource, Mode, Pimp, PimpOptions, QuadraticGap, SurfacePairGap};
use std::hint::black_box;

fn roller_rib(name: &str) -> SurfacePairGap {
    let pair = RollerRib::new(RollerRibSpec::builtin(name).expect("built-in")).expect("pair");
    SurfacePairGap::new(pair.face, pair.rib, pair.contact).expect("gap")
}

fn bench_pimp(c: &mut Criterion) {
    let steel = ElasticMaterial::STEEL;
    let mut group = c.benchmark_group("pimp");
    let tt = roller_rib("torus-torus-14");
    for n in [64usize, 128] {
        for mode in [Mode::Corrected, Mode::Published] {
            let options = PimpOptions {
                mode,
                cells: [n, n],
                ..Default::default()
            };
            let pimp = Pimp::new(steel, steel, options).expect("options");
            // Full solve: adaptive grid from the Hertz estimate, ray casting, equilibrium.
            group.bench_with_input(
                BenchmarkId::new(format!("solve_torus_torus_{}", mode.as_str()), n),
                &n,
                |b, _| {
                    b.iter(|| {
                        pimp.solve_force(black_box(&tt), black_box(250.0))
                            .expect("solve")
                    })
                },
            );
            let s = pimp.solve_force(&tt, 250.0).expect("solve");
            let sampled = pimp.sample(&tt, s.grid).expect("sample");
            // The multi-body path: force for a given approach on the sampled gap.
            group.bench_with_input(
                BenchmarkId::new(format!("force_at_approach_{}", mode.as_str()), n),
                &n,
                |b, _| b.iter(|| sampled.force(black_box(s.approach))),
            );
            // Equilibrium on an already sampled gap (the pose did not change).
            group.bench_with_input(
                BenchmarkId::new(format!("equilibrium_{}", mode.as_str()), n),
                &n,
                |b, _| {
                    b.iter(|| {
                        sampled
                            .approach_for_force(black_box(250.0), &options)
                            .expect("eq")
                    })
                },
            );
        }
        // Ray casting both surfaces on the grid (the set-up of a new pose).
        let grid = Grid2::centered(0.6, 0.3, n, n).expect("grid");
        let mut out = vec![0.0; grid.len()];
        group.bench_with_input(BenchmarkId::new("sample_torus_torus", n), &n, |b, _| {
            b.iter(|| tt.sample(black_box(&grid), 0.0, &mut out).expect("sample"))
        });
    }
    // The Hertz gap: solver cost without ray casting.
    let k = RelativeCurvature::from_radii([20.0, 20.0], [f64::INFINITY; 2], 0.0).expect("k");
    let pimp = Pimp::new(steel, steel, PimpOptions::default()).expect("options");
    group.bench_function("solve_sphere_plane_quadratic_64", |b| {
        b.iter(|| {
            pimp.solve_force(black_box(&QuadraticGap::new(k)), black_box(250.0))
                .expect("solve")
        })
    });
    group.finish();
}

criterion_group!(benches, bench_pimp);
criterion_main!(benches);
