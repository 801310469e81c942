//! Contact-element benchmarks (issue 12): one evaluation from poses and twists of the
//! torus/torus roller-end/rib pairing at about 250 N (approach 4.2 µm), each call moving the
//! roller by 0.1 % of the contact width (1.4 µm) from the last pose (the situation of a
//! multi-body time step), with the Hertz, PimP (32², 64², 128²) and half-space (64 × 64)
//! back-ends; the contact-point search alone; the PimP tracker alone on a fixed gap
//! (interpolated and exact gap sampling, by grid size); and a 10 000-step trajectory
//! (evaluations per second). Figures are recorded in docs/PERFORMANCE.md.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use kontakt::bearing::{RollerRib, RollerRibSpec};
use kontakt::element::{Backend, ContactElement, ElementSpec};
use kontakt::geometry::{Twist, find_contact};
use kontakt::halfspace::BemOptions;
use kontakt::pimp::{GapSampling, Pimp, PimpOptions, PimpTracker, SurfacePairGap};
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
use std::hint::black_box;

fn bench_element(c: &mut Criterion) {
    let rr =
        RollerRib::new(RollerRibSpec::builtin("torus-torus-14").expect("pairing")).expect("rr");
    let n = rr.contact.normal.into_inner();
    // Across the contact: the contact is about 1.4 mm wide; 0.1 % of it is 1.4 µm. Each call
    // moves the roller by that much, back and forth over ±70 µm.
    let across = n.cross(&Vector3::z()).normalize();
    let step = 1.4e-3;
    let pose = |k: u64| {
        let m = k % 200;
        let tri = if m < 100 { m } else { 200 - m } as f64 - 50.0;
        Isometry3::from_parts(
            Translation3::from(-n * 0.0042 + across * tri * step),
            UnitQuaternion::identity(),
        )
    };
    let id = Isometry3::identity();
    let spin = Twist::new(Vector3::zeros(), Vector3::new(0.0, 0.0, 10.0));
    let mut group = c.benchmark_group("element");
    for (name, backend) in [
        ("hertz", Backend::Hertz),
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
    // The PimP tracker alone on a fixed gap (gap sampling, pressure, zone statistics), by
    // grid size and sampling.
    let steel = kontakt::material::ElasticMaterial::STEEL;
    let pressed = |delta: f64| {
        let shift =
            Isometry3::from_parts(Translation3::from(-n * delta), UnitQuaternion::identity());
        let face =
            kontakt::geometry::PlacedSurface::new(rr.face.surface.clone(), shift * rr.face.pose)
                .expect("placed");
        let contact = find_contact(&face, &rr.rib, Some(rr.contact.point)).expect("contact");
        SurfacePairGap::new(face, rr.rib.clone(), contact).expect("gap")
    };
    let gap = pressed(0.0042);
    for cells in [32, 64, 128] {
        for (label, sampling) in [
            ("interpolated", GapSampling::Interpolated),
            ("exact", GapSampling::Exact),
        ] {
            let pimp = Pimp::new(
                steel,
                steel,
                PimpOptions {
                    cells: [cells, cells],
                    ..PimpOptions::default()
                },
            )
            .expect("pimp");
            let mut t = PimpTracker::new(pimp, sampling).expect("tracker");
            group.bench_function(format!("tracker_{label}_{cells}"), |b| {
                b.iter(|| t.evaluate(black_box(&gap), 0.0042).expect("evaluate").force)
            });
        }
        // The whole element at this grid size (contact search, gap, pressure, friction).
        let mut spec = ElementSpec::new(rr.face.clone(), rr.rib.clone()).expect("spec");
        spec.backend = Backend::Pimp(PimpOptions {
            cells: [cells, cells],
            ..PimpOptions::default()
        });
        let mut e = ContactElement::new(spec).expect("element");
        let mut k = 0u64;
        group.bench_function(format!("evaluate_pimp_{cells}"), |b| {
            b.iter(|| {
                k += 1;
                e.evaluate(black_box(&pose(k)), &id, &spin, &Twist::zero())
                    .expect("evaluate")
            })
        });
    }
    group.finish();

    // A 10 000-step trajectory: the roller slides 0.14 mm across the contact and back, the
    // approach breathes between 3.6 and 4.8 µm and the roller tilts by ±0.05°, each step
    // about 0.1 % of the contact width; throughput in evaluations per second.
    let mut group = c.benchmark_group("element_trajectory");
    group.sample_size(10);
    group.throughput(Throughput::Elements(10_000));
    let tilt_axis = nalgebra::Unit::new_normalize(across.cross(&n));
    let trajectory: Vec<Isometry3<f64>> = (0..10_000)
        .map(|i| {
            let s = i as f64 / 10_000.0 * std::f64::consts::TAU;
            let delta = 0.0042 + 0.0006 * s.sin();
            let slide = 0.07 * (1.0 - s.cos());
            let tilt = 0.05f64.to_radians() * (2.0 * s).sin();
            let rot = UnitQuaternion::from_axis_angle(&tilt_axis, tilt);
            let c = rr.contact.point.coords;
            // Tilt about the contact point, then shift.
            Isometry3::from_parts(
                Translation3::from(c - rot * c - n * delta + across * slide),
                rot,
            )
        })
        .collect();
    let mut spec = ElementSpec::new(rr.face.clone(), rr.rib.clone()).expect("spec");
    spec.backend = Backend::Pimp(PimpOptions::default());
    let mut e = ContactElement::new(spec).expect("element");
    group.bench_function("pimp_64_10000_steps", |b| {
        b.iter(|| {
            let mut total = 0.0;
            for p in &trajectory {
                total += e
                    .evaluate(black_box(p), &id, &spin, &Twist::zero())
                    .expect("evaluate")
                    .normal_force;
            }
            total
        })
    });
    group.finish();
}

criterion_group!(benches, bench_element);
criterion_main!(benches);
