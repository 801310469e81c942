use super::*;
use crate::equilibrium::RingLoad;
use crate::geometry::RollerBearing;
use crate::roller_equilibrium::{CylindricalRibs, RibArrangement, RibContactSolver};
use kontakt::friction::{FluidShear, LoadSharing};
use kontakt::lubrication::{FilmFormula, Lubricant};

/// The crate's CRB (14 rollers 10 × 12 mm on a 60 mm pitch circle) with spherical ends
/// r_R = 60 mm touching the ribs 3.5 mm from the roller axis, NJ, 3 kN axial.
fn nj(arrangement: RibArrangement, fa: f64) -> RibContactSolver {
    let ribs = CylindricalRibs {
        face_radius_mm: 60.0,
        contact_height_mm: 3.5,
        end_play_mm: 0.02,
    };
    let b = RollerBearing::cylindrical(60.0, 14, 10.0, 12.0);
    let mut s = RibContactSolver::cylindrical(b, arrangement, ribs).unwrap();
    s.solve(&RingLoad::forces([2000.0, 0.0, fa, 0.0, 0.0]).with_tilts_held())
        .unwrap();
    s
}

fn lubricated(law: FrictionLaw) -> CylindricalRibFriction {
    let lub = RibLubrication {
        lubricant: Lubricant::iso_vg(68, 860.0, 0.02).unwrap(),
        temperature: 70.0,
        roughness: [0.2e-3, 0.2e-3],
        formula: FilmFormula::HamrockDowson,
    };
    CylindricalRibFriction::new(60.0, 10.0, law, Some(lub)).unwrap()
}

fn coulomb(mu: f64) -> FrictionLaw {
    FrictionLaw {
        boundary_coefficient: mu,
        sharing: LoadSharing::Boundary,
        fluid: FluidShear::None,
        regularisation_speed: 0.0,
    }
}

/// The sliding speed of a cylindrical roller's end against a straight rib: from the
/// rigid-body velocities of roller and ring, `v_s = −Ω_ρ R (1 − h/r)` on both rings with
/// `Ω_ρ = ω_ρ − ω_c`, `ω_c = (ω_i R_i + ω_o R_o)/(2R)` (docs/bearing-friction.md), for
/// contact heights from the axis to the raceway, and both rings turning either way; the
/// roller rolls without sliding on both raceways.
#[test]
fn rib_sliding_speed_is_the_closed_form() {
    let m = CylindricalRibFriction::new(60.0, 10.0, coulomb(0.1), None).unwrap();
    let (big_r, r) = (30.0, 5.0);
    let mut worst: f64 = 0.0;
    for (wi, wo) in [(100.0, 0.0), (0.0, 80.0), (-50.0, 30.0), (157.0, 157.0)] {
        let cage = (wi * (big_r - r) + wo * (big_r + r)) / (2.0 * big_r);
        for h in [0.0, 1.0, 3.5, 5.0] {
            for (inner, side, ring) in [(true, -1.0, wi - cage), (false, 1.0, wo - cage)] {
                let lean = (h / 60.0_f64).asin();
                let point = Vector2::new(side * h, 6.0 - 60.0 + 60.0 * lean.cos());
                let normal = -Vector2::new(side * lean.sin(), lean.cos());
                let k = m.kinematics(inner, point, normal, wi, wo);
                let want = -ring * big_r * (1.0 - h / r);
                let scale = (wi - wo).abs().max(1.0) * big_r;
                worst = worst.max((k.sliding - want).abs() / scale);
                assert_eq!(k.cage_speed, cage);
                // pure rolling on both raceways: ω_R r = −Ω_i R_i = Ω_o R_o
                let (om_i, om_o) = (wi - cage, wo - cage);
                assert!((k.roller_speed * r + om_i * (big_r - r)).abs() <= 1e-12 * scale);
                assert!((k.roller_speed * r - om_o * (big_r + r)).abs() <= 1e-12 * scale);
                // the spin about the normal: (ω_R − Ω_ρ) n_z
                assert!((k.spin - (k.roller_speed - ring) * normal.y).abs() <= 1e-12 * scale);
            }
        }
    }
    eprintln!("rib sliding speed against −Ω R (1 − h/r): worst {worst:.2e} of |Δω| R");
    assert!(worst <= 1e-14, "{worst:e}");
}

/// Power balance of each loaded rib contact of an NJ bearing under 2 kN radial + 3 kN
/// axial at 1500 r/min: the dissipated power (the friction integral over the Hertz ellipse
/// with the sliding and spin of the kinematics) equals the power the roller and the ring
/// lose through the friction's torques about their axes,
/// `P = −(T_roller ω_R + T_ring Ω_ρ)`, to 1e-12; the force lies in the tangent plane and
/// opposes the sliding; P lies between μ Q |v_s| (Jensen: the norm is convex) and
/// μ Q (|v_s| + |ω_n| a) for the Coulomb law.
#[test]
fn rib_contact_power_balances_the_ring_and_roller_torques() {
    let s = nj(RibArrangement::Nj, 3000.0);
    let w = 1500.0 * std::f64::consts::PI / 30.0;
    let mut checked = 0;
    for (label, m) in [
        ("mixed", lubricated(FrictionLaw::mixed(0.12).unwrap())),
        ("coulomb", lubricated(coulomb(0.1))),
    ] {
        for j in 0..14 {
            for (r, &q) in s.roller_rib_loads(j).iter().enumerate() {
                let f = m.rib_contact(&s, j, r, w, 0.0).unwrap();
                let k = f.kinematics;
                if q == 0.0 {
                    assert_eq!(f.power, 0.0);
                    continue;
                }
                checked += 1;
                let z = Vector3::z();
                let centre = Vector3::new(30.0, 0.0, 0.0);
                let t_roller =
                    (k.point - centre).cross(&f.force).dot(&z) + f.spin_moment * k.normal.z;
                let t_ring = k.point.cross(&-f.force).dot(&z) - f.spin_moment * k.normal.z;
                let balance = -1e-3 * (t_roller * k.roller_speed + t_ring * k.ring_speed);
                assert!(
                    (f.power - balance).abs() <= 1e-12 * f.power,
                    "{label} roller {j}: P {} W, torques {balance} W",
                    f.power
                );
                assert!(f.force.dot(&k.normal).abs() <= 1e-12 * f.force.norm());
                assert!(f.force.y * k.sliding < 0.0);
                if label == "coulomb" {
                    let a = s.rib_hertz_of(r).solve_force(q).unwrap().semi_axes[0];
                    let low = 1e-3 * 0.1 * q * k.sliding.abs();
                    let high = 1e-3 * 0.1 * q * (k.sliding.abs() + k.spin.abs() * a);
                    assert!(
                        f.power >= low * (1.0 - 1e-12) && f.power <= high,
                        "{low} <= {} <= {high}",
                        f.power
                    );
                }
            }
        }
    }
    // NJ under axial load: one inner and one outer rib per roller carry it
    assert_eq!(checked, 2 * 2 * 14);
}

/// At rest a roller's value is its starting torque μ_b Σ Q |v_s(Δω = 1)|, and it needs no
/// lubricant; running it is the sum of its contacts' powers.
#[test]
fn roller_value_running_and_starting() {
    let s = nj(RibArrangement::Nup, 3000.0);
    let m = lubricated(FrictionLaw::mixed(0.12).unwrap());
    let start = m.roller_value(&s, 0, 0.0, 0.0).unwrap();
    let cage: f64 = 25.0 / 60.0;
    // the loaded contacts are an inner and an outer rib; both slide at R (1 − h/r) per
    // unit relative speed of their ring
    let q: f64 = s.roller_rib_loads(0).iter().sum();
    let per = 30.0 * (1.0 - 3.5 / 5.0);
    let loads = s.roller_rib_loads(0);
    let inner_q: f64 = s
        .rib_contacts()
        .zip(loads)
        .filter(|(c, _)| c.0)
        .map(|(_, q)| q)
        .sum();
    let want = 0.12 * per * (inner_q * (1.0 - cage) + (q - inner_q) * cage);
    assert!((start - want).abs() <= 1e-12 * want, "{start} vs {want}");
    let w = 100.0;
    let running = m.roller_value(&s, 0, w, 0.0).unwrap();
    let sum: f64 = (0..s.rib_contacts().count())
        .map(|r| m.rib_contact(&s, 0, r, w, 0.0).unwrap().power)
        .sum();
    assert_eq!(running, sum);
    assert!(running > 0.0);
}
