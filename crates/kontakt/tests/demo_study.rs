#![allow(clippy::unwrap_used)]
//! The roller-end/rib demo study (`bearing::demo`, run by `kontakt demo`): its size and
//! order, Hertz's exact load scaling, and the claims of docs/VALIDATION.md ("PimP against
//! Hertz", issue 3 tolerance 1 %) on the pairings where the gap is Hertzian.

use kontakt::bearing::{STUDY_FORCES, TABLE1, demo_study};

#[test]
fn demo_study_rows_and_agreement_with_hertz() {
    let study = demo_study(&STUDY_FORCES).unwrap();
    // 8 pairings x 2 bedding laws x 7 forces, in that nesting order.
    assert_eq!(study.rows.len(), 112);
    let mut k = 0;
    for &(name, ..) in TABLE1.iter() {
        for mode in ["corrected", "published"] {
            for &f in STUDY_FORCES.iter() {
                let r = &study.rows[k];
                assert_eq!((r.pairing, r.mode, r.force_n), (name, mode, f));
                k += 1;
            }
        }
    }
    // One corrected map per pairing at the largest force.
    assert_eq!(study.maps.len(), 8);
    for (m, &(name, ..)) in study.maps.iter().zip(TABLE1.iter()) {
        assert_eq!((m.pairing, m.force_n), (name, 400.0));
        assert_eq!(m.pressure.len(), m.grid.len());
        let corrected = study
            .rows
            .iter()
            .find(|r| r.pairing == name && r.mode == "corrected" && r.force_n == 400.0)
            .unwrap();
        let peak = m.pressure.iter().copied().fold(0.0, f64::max);
        assert_eq!(peak, corrected.max_pressure_mpa, "{name}: map peak");
    }
    for r in &study.rows {
        // Hertz p0 ∝ F^(1/3), area ∝ F^(2/3) exactly (relative 1e-12) against 100 N.
        let base = study
            .rows
            .iter()
            .find(|b| b.pairing == r.pairing && b.force_n == 100.0)
            .unwrap();
        let s = (r.force_n / 100.0).cbrt();
        let rel = |a: f64, b: f64| (a / b - 1.0).abs();
        assert!(rel(r.hertz_max_pressure_mpa, s * base.hertz_max_pressure_mpa) < 1e-12);
        assert!(
            rel(
                r.hertz_contact_area_mm2,
                s * s * base.hertz_contact_area_mm2
            ) < 1e-12
        );

        let dp = r.max_pressure_mpa / r.hertz_max_pressure_mpa - 1.0;
        let da = r.contact_area_mm2 / r.hertz_contact_area_mm2 - 1.0;
        let what = format!(
            "{} {} {} N: p {dp:+.4}, area {da:+.4}",
            r.pairing, r.mode, r.force_n
        );
        let sphere = r.pairing.starts_with("sphere");
        let torus_14 = r.pairing.ends_with("-14");
        match r.mode {
            // Sphere faces: the gap is Hertzian; corrected PimP within 1 % (issue 3).
            "corrected" if sphere => assert!(dp.abs() < 0.01 && da.abs() < 0.01, "{what}"),
            // 14 mm toroidal faces: nearly Hertzian (observed <= 1.0 % and 1.6 %); 2 %.
            "corrected" if torus_14 => assert!(dp.abs() < 0.02 && da.abs() < 0.02, "{what}"),
            // 28 mm toroidal faces: curved zones, Hertz does not apply (> 10 % off).
            "corrected" => assert!(dp.abs() > 0.1 && da.abs() > 0.1, "{what}"),
            // Published bedding on the Hertzian faces: near its circle closed form,
            // p +10 %, area +21 % (docs/pimp.md).
            _ if sphere || torus_14 => assert!(
                (0.06..0.11).contains(&dp) && (0.19..0.27).contains(&da),
                "{what}"
            ),
            _ => {}
        }
    }
}

#[test]
fn an_empty_force_list_is_an_error() {
    let e = demo_study(&[]).unwrap_err();
    assert_eq!(e.field(), Some("forces"));
    assert!(demo_study(&[-1.0]).is_err());
}
