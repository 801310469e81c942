//! Issue 29 "Speed": the shortcuts of the whole-bearing friction change no number. The rib
//! friction of a roller whose rib load equals an earlier roller's is that roller's
//! (`RibFrictionModel::evaluate_rollers` solves the friction integral once per distinct rib
//! load): checked bit for bit against a solve per roller, on the bench's bearing (20 rollers
//! under axial load, rib loads equal to the last bits) and on rollers that share a rib load
//! but differ in their raceway loads.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

#[path = "support/friction.rs"]
#[allow(dead_code)]
mod support;

use kontakt::bearing::{
    Operating, PressureModel, RibFriction, RibFrictionModel, RollerRibLoad, TaperedKinematics,
};
use kontakt_bearing::friction::torque::roller_cups;

/// Every roller's rib friction solved on its own: the field at the first roller's rib load
/// within `evaluate_rollers`' reuse tolerance (1e-10, as there), the friction integral
/// for every roller.
fn one_by_one(
    rib: &RibFrictionModel,
    model: PressureModel,
    k: &TaperedKinematics,
    rollers: &[RollerRibLoad],
) -> Vec<Option<RibFriction>> {
    let ao = k.outer_raceway_angle();
    let op = Operating {
        axial_load: rollers
            .iter()
            .map(|r| r.loads.outer_raceway * ao.sin())
            .sum(),
        inner_speed: k.inner_speed,
        outer_speed: k.outer_speed,
    };
    let mut fields: Vec<(f64, _)> = Vec::new();
    rollers
        .iter()
        .map(|r| {
            let q = r.loads.rib;
            if q == 0.0 {
                return None;
            }
            let i = match fields.iter().position(|(l, _)| (l - q).abs() <= 1e-10 * q) {
                Some(i) => i,
                None => {
                    fields.push((q, rib.solve(model, q).unwrap()));
                    fields.len() - 1
                }
            };
            Some(
                rib.friction_share(model, &fields[i].1, &op, k, &r.loads, 1.0)
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
    println!("{} rollers, {} distinct rib loads", loads.len(), distinct.len());
    assert!(distinct.len() < loads.len());
    for model in [PressureModel::Hertz, PressureModel::Pimp] {
        let got = rib.evaluate_rollers(model, &k, &loads).unwrap();
        let want = one_by_one(&rib, model, &k, &loads);
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
    let want = one_by_one(&rib, PressureModel::Hertz, &k, &loads);
    for (j, (g, w)) in got.rollers.iter().zip(&want).enumerate() {
        assert_eq!(g.loads, loads[j].loads, "roller {j}: loads");
        assert_eq!(&g.friction, w, "roller {j}");
    }
    assert!(got.rollers[1].loads.rib > 0.0 && got.rollers[1].loads.inner_raceway == 0.0);
    assert_ne!(got.rollers[2].loads, got.rollers[0].loads);
}
