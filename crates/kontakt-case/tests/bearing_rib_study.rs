//! scratch
#![allow(clippy::unwrap_used)]
use kontakt_case::bearing_validation::{compare, datasets, rib_study};

#[test]
fn scratch_numbers() {
    for d in datasets().unwrap().into_iter().take(2) {
        let c = compare(&d).unwrap();
        println!("{}", d.id);
        for r in &c.rows {
            let p = r.contact_parts.unwrap();
            println!(
                "{} {} meas {} | cone {:.0} cup {:.0} rib {:.0} total {:.0} | race dev {:+.1} total dev {:+.1} | skf tot {:.0} rr {:.0} dev {:+.1} tot dev {:+.1}",
                r.measured.speed_rpm, r.measured.temperature_c, r.measured.torque_nmm,
                p.cone_nmm, p.cup_nmm, p.rib_nmm, p.total_nmm,
                r.contact_deviation_pct().unwrap(),
                100.0 * (p.total_nmm / r.measured.torque_nmm - 1.0),
                r.skf.unwrap().total_nmm, r.skf.unwrap().rolling_nmm, r.skf_deviation_pct().unwrap(),
                100.0 * (r.skf.unwrap().total_nmm / r.measured.torque_nmm - 1.0),
            );
        }
        println!("contact stats {:?} skf stats {:?}", c.contact_deviation_stats(), c.skf_deviation_stats());
        let t0 = std::time::Instant::now();
        for s in rib_study::sensitivity(&d).unwrap() {
            println!("{:40} {:22} race {:5.1} total {:5.1} | race0 {:?} total0 {:?} rib0 {:?}",
                s.parameter, s.value, s.raceways_mean_abs_pct, s.total_mean_abs_pct,
                s.raceways_start_pct, s.total_start_pct, s.rib_start_nmm);
        }
        println!("sens {:?}", t0.elapsed());
    }
}
