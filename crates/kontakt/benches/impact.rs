//! Oblique-impact benchmarks (issue 16): the rigid-body rebound of a solid sphere, and the
//! elastic (Maw-Barber-Fawcett) integration at the default resolution (4000 steps, 400
//! cells) in partial slip and in gross sliding. Figures are recorded in docs/PERFORMANCE.md.

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt::impact::{
    ElasticImpactOptions, ElasticObliqueImpact, IncidentMotion, RigidObliqueImpact, SphereBody,
};
use kontakt::material::ElasticMaterial;
use std::hint::black_box;

fn bench_impact(c: &mut Criterion) {
    let mut group = c.benchmark_group("impact");
    let ball = SphereBody::solid_sphere(5.0, 4.11e-6).expect("ball");
    let steel = ElasticMaterial::STEEL;
    let rigid = RigidObliqueImpact::new(ball, 0.3, 0.9).expect("rigid");
    let elastic =
        ElasticObliqueImpact::new(ball, steel, steel, 0.3, ElasticImpactOptions::default())
            .expect("elastic");
    let partial = IncidentMotion::from_angle(1000.0, 30f64.to_radians(), 0.0).expect("motion");
    let sliding = IncidentMotion::from_angle(1000.0, 75f64.to_radians(), 0.0).expect("motion");
    group.bench_function("rigid_rebound", |b| {
        b.iter(|| rigid.rebound(black_box(&partial)).expect("rebound"))
    });
    group.bench_function("elastic_partial_slip_default", |b| {
        b.iter(|| elastic.rebound(black_box(&partial)).expect("rebound"))
    });
    group.bench_function("elastic_gross_sliding_default", |b| {
        b.iter(|| elastic.rebound(black_box(&sliding)).expect("rebound"))
    });
    group.finish();
}

criterion_group!(benches, bench_impact);
criterion_main!(benches);
