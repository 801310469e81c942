use super::*;
use kontakt::friction::{FluidShear, FrictionLaw, LoadSharing};
use kontakt::lubrication::RollingResistanceModel;

/// ISO VG 68 at 40 °C (η₀ ≈ 0.058 Pa·s), isothermal, σ = 0.2 µm.
fn lub(law: FrictionLaw, rolling: RollingResistanceModel) -> RacewayLosses {
    let oil = kontakt::lubrication::Lubricant::iso_vg(68, 860.0, 0.02).unwrap();
    RacewayLosses::new(raceway_lubrication(&oil, 40.0, false, 0.2e-3, law, rolling).unwrap())
        .unwrap()
}

fn boundary(mu: f64) -> FrictionLaw {
    FrictionLaw {
        boundary_coefficient: mu,
        sharing: LoadSharing::Boundary,
        fluid: FluidShear::None,
        regularisation_speed: 0.0,
    }
}

/// A tapered roller bearing whose cup, cone and roller lines meet on the axis:
/// D/2 = (d_m/2) tan β / sin α_m (docs/bearing-friction.md §1).
fn common_apex_trb(mismatch: f64) -> RollerBearing {
    let (a, ai) = (16.0_f64.to_radians(), 11.7_f64.to_radians());
    let (am, beta) = (0.5 * (a + ai), 0.5 * (a - ai));
    let dm = 108.5;
    let d = dm * beta.tan() / am.sin() * (1.0 + mismatch);
    let mut b = RollerBearing::tapered(dm, 17, d, 20.7, a, ai);
    b.slices = 15;
    b
}

fn crb() -> RollerBearing {
    let mut b = RollerBearing::cylindrical(60.0, 14, 10.0, 12.0);
    b.slices = 15;
    b
}

/// Slice loads: roller j carries `q0 (1 + 0.1 k) cos²(ψ_j/2)` on slice k, both raceways.
fn loads(b: &RollerBearing, q0: f64) -> Vec<f64> {
    let (z, n) = (b.rollers, b.slices);
    (0..z * n)
        .map(|i| {
            let (j, k) = (i / n, i % n);
            let psi = 2.0 * std::f64::consts::PI * j as f64 / z as f64;
            q0 * (1.0 + 0.1 * k as f64) * (0.5 * psi).cos().powi(2)
        })
        .collect()
}

fn op<'a>(wi: f64, wo: f64, q: &'a [f64]) -> FrictionOperating<'a> {
    FrictionOperating {
        inner_speed: wi,
        outer_speed: wo,
        cup_slices: q,
        cone_slices: q,
        tilts: None,
        rib: None,
        drag: DragModel::None,
        coefficient_basis: None,
    }
}

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

/// Common apex, no tilt: the sliding speed vanishes on every slice (pure rolling on the
/// whole line); a roller diameter 1 % off the common apex gives sliding linear in x, zero
/// at the midpoint, with the slope Ω (R⁰ r′/r⁰ − R′) of the derivation.
#[test]
fn sliding_vanishes_with_a_common_apex_and_grows_linearly_without() {
    let m = BearingFrictionModel::new(
        common_apex_trb(0.0),
        lub(boundary(0.1), RollingResistanceModel::ZhouHoeprich),
    )
    .unwrap();
    let (cage, spin) = m.speeds(100.0, 0.0);
    let t_m = axis(m.alpha_m, 0.0);
    for g in &m.slices {
        for cup in [false, true] {
            let ring = if cup {
                cage.abs()
            } else {
                (100.0 - cage).abs()
            };
            let s = m.slice(g, cup, &t_m, ring, spin, 100.0);
            assert!(s.sliding_speed.abs() < 1e-12 * s.entrainment_speed, "{s:?}");
        }
    }
    let m = BearingFrictionModel::new(
        common_apex_trb(0.01),
        lub(boundary(0.1), RollingResistanceModel::ZhouHoeprich),
    )
    .unwrap();
    let (cage, spin) = m.speeds(100.0, 0.0);
    let b = m.bearing().clone();
    let (a, ai) = (b.contact_angle_rad, b.cone_angle_rad);
    let beta = 0.5 * (a - ai);
    let (ri0, ro0, r0) = m.pitch_radii();
    for (k, g) in m.slices.iter().enumerate() {
        let x = m.slice_position(k);
        // R = R⁰ − x sin α_ρ and r = r⁰ − x sin β on both lines (x toward the small end)
        let cone = m
            .slice(g, false, &t_m, 100.0 - cage, spin, 1.0)
            .sliding_speed;
        let want_i = (100.0 - cage) * x * (-ri0 * beta.sin() / r0 + ai.sin());
        let cup = m.slice(g, true, &t_m, cage, spin, 1.0).sliding_speed;
        let want_o = cage * x * (a.sin() - ro0 * beta.sin() / r0);
        assert!(
            (cone - want_i).abs() < 1e-9 * (1.0 + want_i.abs()),
            "{k}: {cone} vs {want_i}"
        );
        assert!(
            (cup - want_o).abs() < 1e-9 * (1.0 + want_o.abs()),
            "{k}: {cup} vs {want_o}"
        );
    }
}

/// Σ power of every contact (the per-roller table plus drag) = M_inner ω_inner +
/// M_outer ω_outer, both rings turning, to 1e-12; the torque is the sum of its shares.
#[test]
fn power_balance_of_all_contacts() {
    let b = common_apex_trb(0.004);
    let q = loads(&b, 60.0);
    let tilts: Vec<f64> = (0..b.rollers).map(|j| 1e-4 * (j as f64 - 7.0)).collect();
    let rib: Vec<f64> = (0..b.rollers).map(|j| 0.3 + 0.01 * j as f64).collect();
    let mut m = BearingFrictionModel::new(
        b,
        lub(
            FrictionLaw::mixed(0.12).unwrap(),
            RollingResistanceModel::BibouletHoupert,
        ),
    )
    .unwrap();
    for (wi, wo) in [(150.0, 0.0), (150.0, -40.0), (-80.0, 30.0)] {
        let f = m
            .evaluate(&FrictionOperating {
                tilts: Some(&tilts),
                rib: Some(&rib),
                drag: DragModel::Torque { nmm: 25.0 },
                ..op(wi, wo, &q)
            })
            .unwrap();
        let contacts: f64 =
            m.rollers().iter().map(RollerFriction::power_w).sum::<f64>() + f.power.drag_w;
        let rings = (f.inner_ring_nmm * wi + f.outer_ring_nmm * wo) * 1e-3;
        assert!(rel(contacts, rings) < 1e-12, "{contacts} vs {rings}");
        assert!(rel(f.power.total_w, contacts) < 1e-12);
        let shares = f.cone.total_nmm() + f.cup.total_nmm() + f.rib_nmm + f.drag_nmm;
        assert!(rel(shares, f.total_nmm) < 1e-12);
        let rollers: f64 = m.rollers().iter().map(|r| r.torque_nmm).sum::<f64>() + f.drag_nmm;
        assert!(rel(rollers, f.total_nmm) < 1e-12);
        assert!(f.power.sliding_w > 0.0 && f.power.rolling_w > 0.0);
        println!("ω_i {wi}, ω_o {wo}: {:?}", f);
    }
}

/// The Zhou-Hoeprich rolling force is F ∝ (R/α)(GU)^0.648 W^0.246 per length, so with
/// zero sliding (common apex) and isothermal oil the bearing torque scales exactly as
/// η₀^0.648, (ring speed)^0.648 and (load)^0.246.
#[test]
fn rolling_torque_follows_the_zhou_hoeprich_exponents() {
    let b = common_apex_trb(0.0);
    let q = loads(&b, 60.0);
    let q2: Vec<f64> = q.iter().map(|v| 2.0 * v).collect();
    let law = FrictionLaw::mixed(0.12).unwrap();
    let mut m =
        BearingFrictionModel::new(b.clone(), lub(law, RollingResistanceModel::ZhouHoeprich))
            .unwrap();
    let base = m.evaluate(&op(100.0, 0.0, &q)).unwrap();
    assert!(base.power.sliding_w.abs() < 1e-12 * base.power.rolling_w);
    let fast = m.evaluate(&op(200.0, 0.0, &q)).unwrap();
    assert!(rel(fast.total_nmm / base.total_nmm, 2f64.powf(0.648)) < 1e-12);
    let heavy = m.evaluate(&op(100.0, 0.0, &q2)).unwrap();
    assert!(rel(heavy.total_nmm / base.total_nmm, 2f64.powf(0.246)) < 1e-12);
    let mut l = *m.losses().lubrication();
    l.viscosity *= 2.0;
    let mut thick = BearingFrictionModel::new(b, RacewayLosses::new(l).unwrap()).unwrap();
    let t = thick.evaluate(&op(100.0, 0.0, &q)).unwrap();
    assert!(rel(t.total_nmm / base.total_nmm, 2f64.powf(0.648)) < 1e-12);
    // Speed of the outer ring alone, same relative speed: same torque (Zhou-Hoeprich is
    // a function of the rolling speed, which depends on ω_i − ω_o only).
    let outer = m.evaluate(&op(0.0, -100.0, &q)).unwrap();
    assert!(rel(outer.total_nmm, base.total_nmm) < 1e-12);
}

/// Zero sliding, rolling resistance only: each slice's share is 2 F u/Δω with u the same on
/// cone and cup at the same apex distance. For a cylindrical roller it is Zhou &
/// Hoeprich's (1991) F_i (R_i + R_e,i) and F_o (R_o − R_e,o); for a common-apex tapered
/// roller 2 F R sin α_o/(sin α_i + sin α_o) (cone) and 2 F R sin α_i/(…) (cup), the
/// levers from the angles alone. Each to 1e-12.
#[test]
fn cone_and_cup_torques_follow_the_kinematics() {
    for (b, tapered) in [(crb(), false), (common_apex_trb(0.0), true)] {
        let q = loads(&b, 60.0);
        let losses = lub(boundary(0.1), RollingResistanceModel::ZhouHoeprich);
        let mut m = BearingFrictionModel::new(b.clone(), losses.clone()).unwrap();
        let w = 120.0;
        let f = m.evaluate(&op(w, 0.0, &q)).unwrap();
        let (a, ai) = (b.contact_angle_rad, b.cone_angle_rad);
        let am = 0.5 * (a + ai);
        let (cage, spin) = m.speeds(w, 0.0);
        let t_m = axis(am, 0.0);
        let (mut cone, mut cup) = (0.0, 0.0);
        for j in 0..b.rollers {
            for (k, g) in m.slices.iter().enumerate() {
                let qk = q[j * b.slices + k];
                if qk == 0.0 {
                    continue;
                }
                for is_cup in [false, true] {
                    let ring = if is_cup { cage } else { w - cage };
                    let s = m.slice(g, is_cup, &t_m, ring, spin, qk / m.width);
                    let fr = losses.slice(&s).unwrap().rolling_force;
                    let big_r = m.half_pitch + if is_cup { g.p_o.x } else { g.p_i.x };
                    // Cylindrical: Zhou & Hoeprich's levers R_i + R_e,i and R_o − R_e,o.
                    // Tapered: 2 R (sin α_o or sin α_i)/(sin α_i + sin α_o), from the
                    // angles alone (common apex: the cage speed ratio).
                    let lever = if !tapered {
                        if is_cup {
                            big_r - s.radius
                        } else {
                            big_r + s.radius
                        }
                    } else {
                        2.0 * big_r * if is_cup { ai.sin() } else { a.sin() } / (a.sin() + ai.sin())
                    };
                    if is_cup {
                        cup += fr * lever
                    } else {
                        cone += fr * lever
                    }
                }
            }
        }
        assert!(
            rel(f.cone.rolling_nmm, cone) < 1e-12,
            "{tapered}: {} vs {cone}",
            f.cone.rolling_nmm
        );
        assert!(
            rel(f.cup.rolling_nmm, cup) < 1e-12,
            "{tapered}: {} vs {cup}",
            f.cup.rolling_nmm
        );
        println!(
            "tapered {tapered}: cone {:.4} cup {:.4} N·mm",
            f.cone.rolling_nmm, f.cup.rolling_nmm
        );
    }
}

/// Standstill: no NaN, the starting torque is the boundary friction of the sliding
/// contacts per unit Δω plus the rib's starting torque, and the running torque tends to it
/// as the speed goes to zero (Coulomb sliding, rolling resistance ∝ ω^0.648).
#[test]
fn zero_speed_gives_the_starting_torque() {
    let b = common_apex_trb(0.01);
    let q = loads(&b, 60.0);
    let mut m = BearingFrictionModel::new(
        b.clone(),
        lub(boundary(0.1), RollingResistanceModel::ZhouHoeprich),
    )
    .unwrap();
    let rib = vec![2.0; b.rollers];
    let s = m
        .evaluate(&FrictionOperating {
            rib: Some(&rib),
            ..op(5.0, 5.0, &q)
        })
        .unwrap();
    assert!(s.warnings.starting && s.total_nmm.is_finite() && s.total_nmm > 0.0);
    assert!(rel(s.rib_nmm, 2.0 * b.rollers as f64) < 1e-12);
    assert_eq!(s.power.total_w, 0.0);
    let start = s.total_nmm - s.rib_nmm;
    let slow = m.evaluate(&op(1e-9, 0.0, &q)).unwrap();
    assert!(
        rel(slow.total_nmm, start) < 1e-4,
        "{} vs {start}",
        slow.total_nmm
    );
    // a common apex has no sliding: only the rib starts
    let mut c = BearingFrictionModel::new(
        common_apex_trb(0.0),
        lub(boundary(0.1), RollingResistanceModel::ZhouHoeprich),
    )
    .unwrap();
    let s = c.evaluate(&op(0.0, 0.0, &q)).unwrap();
    assert!(s.total_nmm.abs() < 1e-9, "{}", s.total_nmm);
}

#[test]
fn bad_input_names_the_field() {
    let b = crb();
    let q = loads(&b, 10.0);
    let mut m =
        BearingFrictionModel::new(b, lub(boundary(0.1), RollingResistanceModel::ZhouHoeprich))
            .unwrap();
    let field = |e: Error| e.field().unwrap_or_default().to_string();
    assert_eq!(
        field(m.evaluate(&op(f64::NAN, 0.0, &q)).unwrap_err()),
        "inner_speed"
    );
    assert_eq!(
        field(m.evaluate(&op(1.0, 0.0, &q[1..])).unwrap_err()),
        "cup_slices"
    );
    let bad = vec![f64::NAN; 3];
    assert_eq!(
        field(
            m.evaluate(&FrictionOperating {
                tilts: Some(&bad),
                ..op(1.0, 0.0, &q)
            })
            .unwrap_err()
        ),
        "tilts"
    );
    assert_eq!(
        field(
            m.evaluate(&FrictionOperating {
                drag: DragModel::Torque { nmm: -1.0 },
                ..op(1.0, 0.0, &q)
            })
            .unwrap_err()
        ),
        "drag"
    );
}
