//! Issue 29 "Speed": the shortcuts of the whole-bearing friction change no number. The rib
//! friction of a roller whose rib load equals an earlier roller's is that roller's
//! (`RibFrictionModel::evaluate_rollers` solves the friction integral once per distinct rib
//! load): checked bit for bit against a solve per roller, on the bench's bearing (20 rollers
//! under axial load, rib loads equal to the last bits) and on rollers that share a rib load
//! but differ in their raceway loads. A planned load distribution
//! (`BearingFrictionModel::plan_loads`) gives every speed's friction bit for bit as the
//! unplanned evaluation, and allocates nothing per operating point.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

#[path = "../../kontakt/tests/support/counting_alloc.rs"]
mod counting_alloc;
#[path = "support/friction.rs"]
#[allow(dead_code)]
mod support;

use counting_alloc::allocations;

use kontakt::bearing::{
    Operating, PressureModel, RibFriction, RibFrictionModel, RollerRibLoad, TaperedKinematics,
};
use kontakt_bearing::friction::torque::{
    BearingFriction, BearingFrictionModel, DragModel, FrictionOperating, RollerFriction,
    roller_cups,
};

/// Every roller's rib friction solved on its own at the operating point `op` (the one
/// `evaluate_rollers` reports: its axial load is the cups' sum): the field at the first
/// roller's rib load within `evaluate_rollers`' reuse tolerance (1e-10, as there), the
/// friction integral for every roller.
fn one_by_one(
    rib: &RibFrictionModel,
    model: PressureModel,
    k: &TaperedKinematics,
    op: &Operating,
    rollers: &[RollerRibLoad],
) -> Vec<Option<RibFriction>> {
    let mut first_loads: Vec<f64> = Vec::new();
    rollers
        .iter()
        .map(|r| {
            let q = r.loads.rib;
            if q == 0.0 {
                return None;
            }
            // the field of the first rib load within 1e-10 of this one
            let at = match first_loads.iter().find(|&&l| (l - q).abs() <= 1e-10 * q) {
                Some(&l) => l,
                None => {
                    first_loads.push(q);
                    q
                }
            };
            let field = rib.solve(model, at).unwrap();
            Some(
                rib.friction_share(model, &field, op, k, &r.loads, 1.0)
                    .unwrap(),
            )
        })
        .collect()
}

/// The bench's bearing (the rib study's TRB with 20 rollers, 15 kN axial, 157 rad/s): its
/// rollers' rib loads take two values that differ in the last bits; `evaluate_rollers`
/// gives every roller exactly the friction of a solve of its own, loads included, with
/// Hertz and PimP fields.
#[test]
fn rollers_with_one_rib_load_share_their_friction_bit_for_bit() {
    let (rib, mut bearing) = support::rib_study(20);
    bearing.slices = 31;
    let (_, _, solver) = support::solved(&bearing, 15_000.0);
    let cups = roller_cups(solver.roller_loads());
    let k = rib.kinematics(157.0, 0.0).unwrap();
    let loads = rib.roller_loads_on_cups(&k, &cups).unwrap();
    let mut distinct: Vec<u64> = loads.iter().map(|r| r.loads.rib.to_bits()).collect();
    distinct.sort_unstable();
    distinct.dedup();
    println!(
        "{} rollers, {} distinct rib loads",
        loads.len(),
        distinct.len()
    );
    assert!(distinct.len() < loads.len());
    for model in [PressureModel::Hertz, PressureModel::Pimp] {
        let got = rib.evaluate_rollers(model, &k, &loads).unwrap();
        let op = got.rollers[0].friction.as_ref().unwrap().operating;
        let want = one_by_one(&rib, model, &k, &op, &loads);
        for (j, (g, w)) in got.rollers.iter().zip(&want).enumerate() {
            assert_eq!(g.loads, loads[j].loads, "{model:?} roller {j}: loads");
            assert_eq!(&g.friction, w, "{model:?} roller {j}");
            assert!(g.friction.is_some());
        }
    }
}

/// Rollers that share a rib load but not their raceway loads (and, between them, a roller
/// outside the load zone that its centrifugal force holds against the rib): each keeps its
/// own loads, and its friction is that of its own solve.
#[test]
fn a_shared_rib_load_keeps_each_rollers_own_loads() {
    let (rib, _) = support::rib_study(17);
    let k = rib.kinematics(120.0, 0.0).unwrap();
    let cups: Vec<_> = [1500.0, 0.0, 1500.0, 900.0]
        .iter()
        .enumerate()
        .map(|(j, &q)| kontakt::bearing::RollerCup {
            azimuth: j as f64,
            outer_raceway: q,
        })
        .collect();
    let mut loads = rib.roller_loads_on_cups(&k, &cups).unwrap();
    // the third roller: the first one's rib load, other raceway loads
    loads[2].loads.outer_raceway *= 1.1;
    loads[2].loads.inner_raceway *= 0.9;
    assert_eq!(loads[2].loads.rib, loads[0].loads.rib);
    let got = rib
        .evaluate_rollers(PressureModel::Hertz, &k, &loads)
        .unwrap();
    let op = got.rollers[0].friction.as_ref().unwrap().operating;
    let want = one_by_one(&rib, PressureModel::Hertz, &k, &op, &loads);
    for (j, (g, w)) in got.rollers.iter().zip(&want).enumerate() {
        assert_eq!(g.loads, loads[j].loads, "roller {j}: loads");
        assert_eq!(&g.friction, w, "roller {j}");
    }
    assert!(got.rollers[1].loads.rib > 0.0 && got.rollers[1].loads.inner_raceway == 0.0);
    assert_ne!(got.rollers[2].loads, got.rollers[0].loads);
}

/// The bench's bearing (20 rollers, 31 slices, 15 kN axial; thermal film, mixed law), its
/// model, cup and cone slice loads.
fn bench_bearing() -> (BearingFrictionModel, Vec<f64>, Vec<f64>) {
    let (_, mut bearing) = support::rib_study(20);
    bearing.slices = 31;
    let (cup, cone, _) = support::solved(&bearing, 15_000.0);
    let model =
        BearingFrictionModel::new(bearing, support::losses(&support::vg68(), 70.0, true)).unwrap();
    (model, cup, cone)
}

/// The friction and every roller's losses at the ring speeds `(wi, wo)`.
fn friction_at(
    m: &mut BearingFrictionModel,
    (wi, wo): (f64, f64),
    cup: &[f64],
    cone: &[f64],
    tilts: Option<&[f64]>,
) -> (BearingFriction, Vec<RollerFriction>) {
    let rib: Vec<f64> = (0..20).map(|j| 0.1 + 0.01 * j as f64).collect();
    let f = m
        .evaluate(&operating((wi, wo), (cup, cone), tilts, &rib))
        .unwrap();
    (f, m.rollers().to_vec())
}

/// The operating point at the ring speeds `(wi, wo)` with the slice loads, tilts and rib
/// powers given, drag 3 N·mm, the coefficient's basis 15 kN on a 40 mm bore.
fn operating<'a>(
    (wi, wo): (f64, f64),
    (cup, cone): (&'a [f64], &'a [f64]),
    tilts: Option<&'a [f64]>,
    rib: &'a [f64],
) -> FrictionOperating<'a> {
    FrictionOperating {
        inner_speed: wi,
        outer_speed: wo,
        cup_slices: cup,
        cone_slices: cone,
        tilts,
        rib: Some(rib),
        drag: DragModel::Torque { nmm: 3.0 },
        coefficient_basis: Some((15_000.0, 40.0)),
    }
}

/// A speed sweep over one planned load distribution (untilted: sliding at round-off; tilted:
/// real sliding on every slice) gives, at every speed (inner or outer ring turning,
/// standstill), the unplanned friction and roller losses bit for bit; a plan of another
/// load distribution falls back to the full computation (still the same numbers); a
/// cleared plan too.
#[test]
fn a_planned_sweep_is_the_unplanned_sweep_bit_for_bit() {
    let (mut plain, cup, cone) = bench_bearing();
    let mut planned = plain.clone();
    let tilted: Vec<f64> = (0..20).map(|j| 2e-4 * (j as f64 - 9.5)).collect();
    let speeds = [
        (6.0, 0.0),
        (157.0, 0.0),
        (300.0, 0.0),
        (0.0, -80.0),
        (40.0, 40.0),
    ];
    let mut compared = 0;
    for tilts in [None, Some(tilted.as_slice())] {
        planned.plan_loads(&cup, &cone, tilts).unwrap();
        for &w in &speeds {
            let want = friction_at(&mut plain, w, &cup, &cone, tilts);
            let got = friction_at(&mut planned, w, &cup, &cone, tilts);
            assert_eq!(got, want, "tilts {} speeds {w:?}", tilts.is_some());
            assert_eq!(got.0.total_nmm.to_bits(), want.0.total_nmm.to_bits());
            compared += 1;
        }
        let f = friction_at(&mut planned, (157.0, 0.0), &cup, &cone, tilts).0;
        println!(
            "tilted {}: cone sliding {:.3e} N·mm, rolling {:.4} N·mm, total {:.4} N·mm",
            tilts.is_some(),
            f.cone.sliding_nmm,
            f.cone.rolling_nmm,
            f.total_nmm
        );
    }
    // the plan of other loads (the tilted plan is current; now untilted and 10 % more load)
    let heavier: Vec<f64> = cup.iter().map(|q| q * 1.1).collect();
    for (c, t) in [(&cup, None), (&heavier, Some(tilted.as_slice()))] {
        let want = friction_at(&mut plain, (157.0, 0.0), c, &cone, t);
        assert_eq!(friction_at(&mut planned, (157.0, 0.0), c, &cone, t), want);
    }
    planned.clear_plan();
    let want = friction_at(&mut plain, (157.0, 0.0), &cup, &cone, None);
    assert_eq!(
        friction_at(&mut planned, (157.0, 0.0), &cup, &cone, None),
        want
    );
    assert_eq!(compared, 10);
}

/// Planning checks its input as `evaluate` does (the field named), and leaves no plan
/// behind on an error.
#[test]
fn planning_bad_loads_names_the_field() {
    let (mut m, cup, cone) = bench_bearing();
    let field = |e: kontakt::Error| e.field().unwrap_or_default().to_string();
    assert_eq!(
        field(m.plan_loads(&cup[1..], &cone, None).unwrap_err()),
        "cup_slices"
    );
    let mut bad = cone.clone();
    bad[40] = f64::NAN;
    assert_eq!(
        field(m.plan_loads(&cup, &bad, None).unwrap_err()),
        "cone_slices"
    );
    assert_eq!(
        field(m.plan_loads(&cup, &cone, Some(&[0.0; 3])).unwrap_err()),
        "tilts"
    );
}

/// After planning, every operating point allocates nothing (a sweep of four speeds with
/// tilts, rib powers and drag, standstill included); re-planning the same model allocates
/// nothing either.
#[test]
fn planned_operating_points_allocate_nothing() {
    let (mut m, cup, cone) = bench_bearing();
    let tilts = vec![1e-4; 20];
    m.plan_loads(&cup, &cone, Some(&tilts)).unwrap();
    let rib = vec![1.0; 20];
    let (r, n) = allocations(|| {
        let mut total = 0.0;
        for w in [0.0, 10.0, 100.0, 300.0] {
            let op = operating((w, 0.0), (&cup, &cone), Some(&tilts), &rib);
            total += m.evaluate(&op).unwrap().total_nmm;
        }
        m.plan_loads(&cup, &cone, None).unwrap();
        total
    });
    assert!(r.is_finite());
    assert_eq!(n, 0, "allocations per planned operating point");
}

/// Rollers with the same slice loads and tilt share their raceway losses (`evaluate`
/// computes one of them and copies it): every roller's losses equal those of the same
/// roller loaded alone (the others unloaded), bit for bit, on the bench's bearing (its 20
/// rollers' loads take three values that differ in the last bits) untilted and with tilts
/// in two groups, at a speed where some slices' films leave their fit (6 rad/s) and at
/// 157 rad/s; the film warnings add up to the rollers' own.
#[test]
fn rollers_with_one_load_share_their_raceway_losses_bit_for_bit() {
    let (mut m, cup, cone) = bench_bearing();
    let n = cup.len() / 20;
    let mut distinct: Vec<Vec<u64>> = (0..20)
        .map(|j| {
            cup[j * n..(j + 1) * n]
                .iter()
                .map(|q| q.to_bits())
                .collect()
        })
        .collect();
    distinct.sort();
    distinct.dedup();
    assert!(distinct.len() < 20, "{} distinct rollers", distinct.len());
    let grouped: Vec<f64> = (0..20)
        .map(|j| if j % 2 == 0 { 1e-3 } else { 0.0 })
        .collect();
    let mut warned = 0;
    for tilts in [None, Some(grouped.as_slice())] {
        for w in [(6.0, 0.0), (157.0, 0.0)] {
            let (all, rollers) = friction_at(&mut m, w, &cup, &cone, tilts);
            let mut films = 0;
            for j in 0..20 {
                let alone = |v: &[f64]| -> Vec<f64> {
                    (0..v.len())
                        .map(|i| if i / n == j { v[i] } else { 0.0 })
                        .collect()
                };
                let (c, k) = (alone(&cup), alone(&cone));
                let (f, own) = friction_at(&mut m, w, &c, &k, tilts);
                assert_eq!(own[j], rollers[j], "roller {j} at {w:?}");
                films += f.warnings.film_out_of_range_slices;
            }
            assert_eq!(films, all.warnings.film_out_of_range_slices);
            warned += films;
        }
    }
    println!(
        "{} distinct rollers, {warned} film warnings",
        distinct.len()
    );
    assert!(warned > 0, "the warnings' copy is not exercised");
}
