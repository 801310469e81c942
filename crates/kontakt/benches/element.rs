//! Contact-element benchmarks (issue 12): one evaluation from poses and twists of the
//! torus/torus roller-end/rib pairing at about 250 N (approach 4.2 µm), each call moving the
//! roller by 0.1 % of the contact width from the last pose (the situation of a multi-body
//! time step), with the Hertz, PimP (64 × 64) and half-space (64 × 64) back-ends; and the
//! contact-point search alone. Figures are recorded in docs/PERFORMANCE.md.

use criterion::{Criterion, criterion_group, criterion_main};
use kontakt::bearing::{RollerRib, RollerRibSpec};
use kontakt::element::{Backend, ContactElement, ElementSpec};
use kontakt::geometry::{Twist, find_contact};
use kontakt::halfspace::BemOptions;
use kontakt::pimp::PimpOptions;
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
use std::hint::black_box;

fn bench_element(c: &mut Criterion) {
    let rr =
        RollerRib::new(RollerRibSpec::builtin("torus-torus-14").expect("pairing")).expect("rr");
    let n = rr.contact.normal.into_inner();
    // Across the contact: the contact is about 1.4 mm wide; 0.1 % of it is 1.4 µm.
    let across = n.cross(&Vector3::z()).normalize();
    let step = 1.4e-3;
    let pose = |k: u64| {
        let wiggle = ((k % 200) as f64 - 100.0) * step;
        Isometry3::from_parts(
            Translation3::from(-n * 0.0042 + across * wiggle * 1e-2),
            UnitQuaternion::identity(),
        )
    };
    let id = Isometry3::identity();
    let spin = Twist::new(Vector3::zeros(), Vector3::new(0.0, 0.0, 10.0));
    let mut group = c.benchmark_group("element");
    for (name, backend) in [
        ("hertz", Backend::Hertz),
        ("pimp_64", Backend::Pimp(PimpOptions::default())),
        (
            "halfspace_64",
            Backend::HalfSpace(BemOptions {
                threads: Some(1),
                ..BemOptions::default()
            }),
        ),
    ] {
        let mut spec = ElementSpec::new(rr.face.clone(), rr.rib.clone()).expect("spec");
        spec.backend = backend;
        let mut e = ContactElement::new(spec).expect("element");
        let mut k = 0u64;
        group.bench_function(format!("evaluate_{name}"), |b| {
            b.iter(|| {
                k += 1;
                e.evaluate(black_box(&pose(k)), &id, &spin, &Twist::zero())
                    .expect("evaluate")
            })
        });
    }
    // The half-space back-end warm after a 1 % load change: the approach alternates
    // between two values whose Hertz forces differ by 1 % (δ ∝ F^(2/3)).
    {
        let mut spec = ElementSpec::new(rr.face.clone(), rr.rib.clone()).expect("spec");
        spec.backend = Backend::HalfSpace(BemOptions {
            threads: Some(1),
            ..BemOptions::default()
        });
        let mut e = ContactElement::new(spec).expect("element");
        let depth = [0.0042, 0.0042 * 1.01f64.powf(2.0 / 3.0)];
        let mut k = 0usize;
        group.bench_function("evaluate_halfspace_64_load_step", |b| {
            b.iter(|| {
                k += 1;
                let pose = Isometry3::from_parts(
                    Translation3::from(-n * depth[k % 2]),
                    UnitQuaternion::identity(),
                );
                e.evaluate(black_box(&pose), &id, &spin, &Twist::zero())
                    .expect("evaluate")
            })
        });
    }
    let placed = |p: &Isometry3<f64>| {
        kontakt::geometry::PlacedSurface::new(rr.face.surface.clone(), p * rr.face.pose)
            .expect("placed")
    };
    let guess = rr.contact.point;
    let mut k = 0u64;
    group.bench_function("contact_point_search", |b| {
        b.iter(|| {
            k += 1;
            let p1 = placed(&pose(k));
            find_contact(black_box(&p1), &rr.rib, Some(guess)).expect("contact")
        })
    });
    group.finish();
}

criterion_group!(benches, bench_element);
criterion_main!(benches);
