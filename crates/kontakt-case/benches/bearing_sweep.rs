//! Criterion benchmark of a bearing sweep's cost per case (issue 28, "Speed": a sweep of
//! 100 000 bearing load cases on 2 cores in at most 60 s, i.e. at most 1.2 ms per case and
//! core): 1 000 load cases of the 32008 X class TRB (23 rollers × 31 slices, ISO/TS 16281
//! slice law, tilts held), radial 0 to 5 kN × axial 2 to 6 kN, through
//! `Sweep::chunk_table` — the sweep path of `kontakt sweep` and `kontakt.sweep` without
//! the Parquet file: parameters set on the planned bearing, warm starts in blocks of 256,
//! the Arrow table. One thread (the figure per case and core) and two.
//! The whole 100 000-case run through the CLI: tools/bearing-sweep-timing.sh.
//! Figures in docs/PERFORMANCE.md.

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt_case::sweep::Sweep;
use std::hint::black_box;
use std::path::Path;

fn bench_bearing_sweep(c: &mut Criterion) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/sweeps");
    let text = "base = \"../bearing_32008x.toml\"\nchunk_size = 1000\n\
                [[parameter]]\nkey = \"load.force_n[2]\"\nstart = 2000.0\nstop = 6000.0\ncount = 25\n\
                [[parameter]]\nkey = \"load.force_n[0]\"\nstart = 0.0\nstop = 5000.0\ncount = 40\n";
    let sweep = Sweep::from_toml_str(text, &dir).expect("valid sweep");
    assert_eq!(sweep.len(), 1000);
    let mut group = c.benchmark_group("bearing_sweep");
    group.sample_size(10);
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool");
        let t = pool.install(|| sweep.chunk_table(0)).expect("chunk");
        assert_eq!(t.num_rows(), 1000);
        group.bench_function(format!("trb_1000_cases_{threads}_threads"), |b| {
            b.iter(|| pool.install(|| sweep.chunk_table(black_box(0)).expect("chunk")))
        });
    }
    group.finish();
}

criterion_group!(benches, bench_bearing_sweep);
criterion_main!(benches);
