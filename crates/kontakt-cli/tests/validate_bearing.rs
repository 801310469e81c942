//! `kontakt validate --bearing`: it runs on every dataset of validation/measured/, writes
//! the CSV with its documented columns, draws a plot per dataset, and the plot is right:
//! each measured point, and each contact-based value, is a filled marker where its value
//! says in the plot's pixel frame, and not beside it.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

mod support;

use std::collections::HashMap;
use std::path::Path;
use support::{kontakt, read_csv, tempdir};

const COLUMNS: &str = "dataset,status,speed_rpm,axial_load_n,radial_load_n,temperature_c,viscosity_mm2_s,measured_nmm,band_pct,skf_nmm,skf_rolling_nmm,skf_sliding_nmm,skf_drag_nmm,skf_deviation_pct,aihara_nmm,aihara_deviation_pct,contact_nmm,contact_deviation_pct,quantity,contact_total_nmm,contact_cone_nmm,contact_cup_nmm,contact_rib_nmm,contact_drag_nmm";

const DATASETS: [&str; 6] = [
    "manjunath2023_fig13",
    "manjunath2023_fig13_alt",
    "wingertszahn2023_axial",
    "wingertszahn2023_combined",
    "wingertszahn2023_radial",
    "zhou_hoeprich1991_fig9",
];

fn run(dir: &Path) -> String {
    let out = kontakt()
        .args(["validate", "--bearing", "--out", dir.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn validate_bearing_runs_on_every_dataset() {
    let dir = tempdir("validate-bearing", "all");
    let stdout = run(&dir);
    for id in DATASETS {
        assert!(stdout.contains(id), "{id} missing in\n{stdout}");
        assert!(
            dir.join(format!("bearing_{id}.png")).is_file(),
            "plot of {id}"
        );
    }
    assert!(stdout.contains("SKF against measured: mean |dev|"));
    let text = std::fs::read_to_string(dir.join("bearing_torque.csv")).unwrap();
    assert_eq!(text.lines().next().unwrap(), COLUMNS);
    let rows = read_csv(&dir.join("bearing_torque.csv"));
    assert_eq!(rows.len(), 14 + 14 + 4 + 8 + 5 + 8);
    for r in &rows {
        // no model value where there is no model: Aihara's inputs, and the contact model
        // without the internal geometry (Manjunath's TRB has Liu 2022's, Wingertszahn's
        // 32216 its assumed raceway angles)
        assert_eq!(r["aihara_nmm"], "", "{r:?}");
        let manjunath = r["dataset"].starts_with("manjunath2023");
        let has_contact = manjunath || r["dataset"].starts_with("wingertszahn2023");
        // Manjunath's Fig. 13 is the rolling-resistance torque (its caption): the models'
        // raceway parts are compared with it
        let rolling = r["quantity"] == "rolling_resistance";
        assert_eq!(rolling, manjunath, "{r:?}");
        assert!(rolling || r["quantity"] == "total", "{r:?}");
        for k in [
            "contact_nmm",
            "contact_deviation_pct",
            "contact_total_nmm",
            "contact_cone_nmm",
            "contact_cup_nmm",
            "contact_rib_nmm",
            "contact_drag_nmm",
        ] {
            assert_eq!(!r[k].is_empty(), has_contact, "{k} of {r:?}");
        }
        if has_contact {
            let g = |k: &str| r[k].parse::<f64>().unwrap();
            let (m, c) = (g("measured_nmm"), g("contact_nmm"));
            let d = g("contact_deviation_pct");
            assert!(c > 0.0 && (d - 100.0 * (c / m - 1.0)).abs() < 0.01, "{r:?}");
            assert!((c - g("contact_cone_nmm") - g("contact_cup_nmm")).abs() < 0.01);
            let parts = [
                "contact_cone_nmm",
                "contact_cup_nmm",
                "contact_rib_nmm",
                "contact_drag_nmm",
            ]
            .iter()
            .map(|k| g(k))
            .sum::<f64>();
            assert!((parts - g("contact_total_nmm")).abs() < 0.01, "{r:?}");
            assert!(g("contact_rib_nmm") > 0.0, "the rib is in: {r:?}");
        }
        assert_eq!(r["status"], "unverified");
        let has_skf = r["dataset"] != "zhou_hoeprich1991_fig9";
        assert_eq!(!r["skf_nmm"].is_empty(), has_skf, "{r:?}");
        if has_skf {
            let (m, s): (f64, f64) = (
                r["measured_nmm"].parse().unwrap(),
                r["skf_nmm"].parse().unwrap(),
            );
            let d: f64 = r["skf_deviation_pct"].parse().unwrap();
            let compared: f64 = if rolling {
                r["skf_rolling_nmm"].parse().unwrap()
            } else {
                s
            };
            assert!((d - 100.0 * (compared / m - 1.0)).abs() < 0.01, "{r:?}");
            let parts: f64 = ["skf_rolling_nmm", "skf_sliding_nmm", "skf_drag_nmm"]
                .iter()
                .map(|k| r[*k].parse::<f64>().unwrap())
                .sum();
            assert!((parts - s).abs() < 0.01, "{r:?}");
        }
    }
    let curves = read_csv(&dir.join("bearing_skf_curves.csv"));
    assert!(curves.iter().any(|c| c["x_name"] == "radial_load_n"));
    let report = std::fs::read_to_string(dir.join("bearing_report.md")).unwrap();
    assert!(report.contains("Y = 1.6") && report.contains("Y = 1.4"));
    assert!(report.contains("Liu (2022)") && report.contains("stated by no source"));
    assert!(report.contains("rolling-resistance torque"));
    assert!(stdout.contains("contact-based against measured: mean |dev|"));
    // the rib study: a breakdown plot per temperature of each dataset with a contact-based
    // model, the breakdown and sensitivity tables
    for id in ["manjunath2023_fig13", "manjunath2023_fig13_alt"] {
        for t in [55, 65] {
            let f = format!("bearing_{id}_breakdown_{t}C.png");
            assert!(dir.join(&f).is_file(), "{f}");
            assert!(report.contains(&f), "{f} in the report");
        }
    }
    let sens = read_csv(&dir.join("bearing_rib_sensitivity.csv"));
    assert_eq!(
        sens.len(),
        2 * 15 * 2,
        "2 datasets × 15 variations × 2 temperatures"
    );
    assert!(stdout.contains("rib and oil sensitivity"));
    let b = read_csv(&dir.join("bearing_breakdown.csv"));
    assert_eq!(
        b.len(),
        2 * 2 * 23 + 3 * 23,
        "Manjunath 2 × 2 curves, LM12700 3 loads"
    );
    assert!(
        dir.join("bearing_zhou_hoeprich1991_fig9_breakdown_80C.png")
            .is_file()
    );
    assert!(stdout.contains(
        "zhou_hoeprich1991_fig9: contact-based, 3600 N axial, 80 °C: the raceways' torque exceeds the rib's above"
    ));
    // JSON
    let out = kontakt()
        .args([
            "validate",
            "--bearing",
            "--json",
            "--out",
            dir.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["datasets"].as_array().unwrap().len(), 6);
    assert_eq!(v["unit_torque"], "N·mm");
    assert!(
        v["datasets"][0]["contact_deviation_mean_abs_pct"]
            .as_f64()
            .unwrap()
            > 0.0
    );
    // the 32216 lists its assumed raceway angles; Zhou & Hoeprich's has no contact model
    let assumed = v["datasets"][2]["contact_assumptions"].to_string();
    assert!(assumed.contains("cup angle 16.0°"), "{assumed}");
    assert!(v["datasets"][5]["contact_assumptions"].is_null());
    assert_eq!(
        v["rib_study"].as_array().unwrap().len(),
        3,
        "2 Manjunath, LM12700"
    );
    assert_eq!(v["rib_study"][2]["dataset"], "zhou_hoeprich1991_fig9");
    assert_eq!(
        v["rib_study"][0]["sensitivity"].as_array().unwrap().len(),
        15
    );
}

/// `--cells` belongs to the rib-contact study: with `--bearing` it is an input error.
#[test]
fn validate_bearing_refuses_cells() {
    let out = kontakt()
        .args(["validate", "--bearing", "--cells", "32"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--cells"));
}

fn near(p: &image::Rgb<u8>, c: (u8, u8, u8), tol: i32) -> bool {
    (i32::from(p[0]) - i32::from(c.0)).abs() <= tol
        && (i32::from(p[1]) - i32::from(c.1)).abs() <= tol
        && (i32::from(p[2]) - i32::from(c.2)).abs() <= tol
}

/// The plot frame (left, top, right, bottom) in pixels: the outermost rows and columns
/// that are black over more than half the image.
fn frame(img: &image::RgbImage) -> (u32, u32, u32, u32) {
    let (w, h) = img.dimensions();
    let dark = |x: u32, y: u32| near(img.get_pixel(x, y), (0, 0, 0), 60);
    let rows: Vec<u32> = (0..h)
        .filter(|&y| (0..w).filter(|&x| dark(x, y)).count() as u32 > w / 2)
        .collect();
    let top = *rows.first().unwrap();
    let bottom = *rows.last().unwrap();
    let cols: Vec<u32> = (0..w)
        .filter(|&x| {
            (top..=bottom).filter(|&y| dark(x, y)).count() as u32 > (bottom - top) * 9 / 10
        })
        .collect();
    (*cols.first().unwrap(), top, *cols.last().unwrap(), bottom)
}

/// The plot image at `path` and its data-to-pixel map: the axes span the data's x range
/// `x0..x1` padded by 4 % and 0 to `y1` + 4 %, as kontakt-plot draws a line plot with y
/// from zero, inside the frame (at least `min_width` pixels wide).
fn open_plot(
    path: &Path,
    (x0, x1, y1): (f64, f64, f64),
    min_width: u32,
) -> (image::RgbImage, impl Fn(f64, f64) -> (f64, f64) + use<>) {
    let span = x1 - x0;
    let (x0, x1) = (x0 - 0.04 * span, x1 + 0.04 * span);
    let (y0, y1) = (0.0, 1.04 * y1);
    let img = image::open(path).unwrap().to_rgb8();
    let (left, top, right, bottom) = frame(&img);
    assert!(
        right > left + min_width && bottom > top + 300,
        "{left} {top} {right} {bottom}"
    );
    let pixel = move |x: f64, y: f64| {
        (
            f64::from(left) + (x - x0) / (x1 - x0) * f64::from(right - left),
            f64::from(bottom) - (y - y0) / (y1 - y0) * f64::from(bottom - top),
        )
    };
    (img, pixel)
}

/// A marker of colour `c` fills its place (at least 21 of the 25 pixels there) and is not
/// drawn 12 px off in any direction.
fn assert_marker_at(img: &image::RgbImage, (px, py): (f64, f64), c: (u8, u8, u8), what: &str) {
    let cover = marker_cover(img, (px, py), c);
    assert!(
        cover >= 21,
        "{what}: {cover}/25 marker pixels at ({px:.1}, {py:.1})"
    );
    for (dx, dy) in [(0.0, -12.0), (0.0, 12.0), (12.0, 0.0), (-12.0, 0.0)] {
        let beside = marker_cover(img, (px + dx, py + dy), c);
        assert!(
            beside < 21,
            "{what}: a marker {dx},{dy} px off ({beside}/25)"
        );
    }
}

/// How many of the 5 × 5 pixels around (x, y) have colour `c`: a filled marker covers all
/// 25, a line (the error bar, a dashed curve) at most a stripe.
fn marker_cover(img: &image::RgbImage, (x, y): (f64, f64), c: (u8, u8, u8)) -> usize {
    let (cx, cy) = (x.round() as i64, y.round() as i64);
    let mut n = 0;
    for dy in -2..=2 {
        for dx in -2..=2 {
            let (px, py) = (cx + dx, cy + dy);
            if px >= 0
                && py >= 0
                && let Some(p) = img.get_pixel_checked(px as u32, py as u32)
            {
                n += usize::from(near(p, c, 40));
            }
        }
    }
    n
}

/// The measured points of the Manjunath plot land where their values say: the axes span the
/// data padded by 4 % (x) and 0 to the largest value + 4 % (y, from zero), as kontakt-plot
/// draws a line plot; the data are the measured points, their error bars and the SKF
/// curves, all read back from the CSV files the command wrote. At each point's pixel there
/// is a filled marker of its temperature's colour; 12 pixels beside it (still on its error
/// bar, vertically) there is none. The same for the contact-based torque (the `contact_nmm`
/// column) at the measured speeds, in its own colours. A marker that another one partly
/// hides is skipped.
#[test]
fn measured_points_land_where_their_values_say() {
    let dir = tempdir("validate-bearing", "pixels");
    run(&dir);
    let id = "manjunath2023_fig13";
    let rows: Vec<_> = read_csv(&dir.join("bearing_torque.csv"))
        .into_iter()
        .filter(|r| r["dataset"] == id)
        .collect();
    let curves: Vec<_> = read_csv(&dir.join("bearing_skf_curves.csv"))
        .into_iter()
        .filter(|r| r["dataset"] == id)
        .collect();
    let f = |r: &HashMap<String, String>, k: &str| r[k].parse::<f64>().unwrap();
    let (mut x0, mut x1, mut y1) = (f64::MAX, f64::MIN, f64::MIN);
    for r in &rows {
        let (x, y, band) = (f(r, "speed_rpm"), f(r, "measured_nmm"), f(r, "band_pct"));
        x0 = x0.min(x);
        x1 = x1.max(x);
        y1 = y1.max(y * (1.0 + band / 100.0)).max(f(r, "contact_nmm"));
    }
    for c in &curves {
        x0 = x0.min(f(c, "x"));
        x1 = x1.max(f(c, "x"));
        y1 = y1.max(f(c, "skf_nmm"));
    }
    let (img, pixel) = open_plot(&dir.join(format!("bearing_{id}.png")), (x0, x1, y1), 400);
    // the temperatures take the palette's colours in order of appearance: 55 °C, 65 °C
    let colour = |t: f64| {
        if t == 55.0 {
            kontakt_plot::PALETTE[0]
        } else {
            kontakt_plot::PALETTE[1]
        }
    };
    let at: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| pixel(f(r, "speed_rpm"), f(r, "measured_nmm")))
        .collect();
    let mut checked = 0;
    for (k, r) in rows.iter().enumerate() {
        let c = colour(f(r, "temperature_c"));
        let (px, py) = at[k];
        // a marker partly hidden under another one (55 and 65 °C close together) is skipped
        let hidden = at
            .iter()
            .enumerate()
            .any(|(j, q)| j != k && (q.0 - px).hypot(q.1 - py) < 16.0);
        if hidden {
            continue;
        }
        checked += 1;
        assert_marker_at(&img, (px, py), c, &format!("{r:?}: measured"));
    }
    assert!(
        checked >= 10,
        "only {checked} of {} points free of overlap",
        rows.len()
    );
    // the contact-based torque at the measured speeds: markers in the colours after the
    // temperatures' (55 °C, 65 °C), skipped where a measured or another contact-based
    // marker is near
    let contact_colour = |t: f64| {
        if t == 55.0 {
            kontakt_plot::PALETTE[2]
        } else {
            kontakt_plot::PALETTE[3]
        }
    };
    let on: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| pixel(f(r, "speed_rpm"), f(r, "contact_nmm")))
        .collect();
    let mut checked = 0;
    for (k, r) in rows.iter().enumerate() {
        let c = contact_colour(f(r, "temperature_c"));
        let (px, py) = on[k];
        let hidden = at.iter().any(|q| (q.0 - px).hypot(q.1 - py) < 16.0)
            || on
                .iter()
                .enumerate()
                .any(|(j, q)| j != k && (q.0 - px).hypot(q.1 - py) < 16.0);
        if hidden {
            continue;
        }
        checked += 1;
        assert_marker_at(&img, (px, py), c, &format!("{r:?}: contact-based"));
    }
    assert!(
        checked >= 5,
        "only {checked} of {} contact-based points free of overlap",
        rows.len()
    );
}

/// The breakdown plot of the README: the measured points (black) land where their values
/// say, and the stacked "+ rib = total" line passes through its values at the breakdown's
/// speeds, in the plot's pixel frame; the axes span every series of the plot (the breakdown
/// and SKF curves of `bearing_breakdown.csv`, the measured points with their bars) padded as
/// kontakt-plot pads them.
#[test]
fn breakdown_plot_lands_where_its_values_say() {
    let dir = tempdir("validate-bearing", "breakdown");
    run(&dir);
    let id = "manjunath2023_fig13";
    let f = |r: &HashMap<String, String>, k: &str| r[k].parse::<f64>().unwrap();
    let rows: Vec<_> = read_csv(&dir.join("bearing_torque.csv"))
        .into_iter()
        .filter(|r| r["dataset"] == id && f(r, "temperature_c") == 55.0)
        .collect();
    let curve: Vec<_> = read_csv(&dir.join("bearing_breakdown.csv"))
        .into_iter()
        .filter(|r| r["dataset"] == id && f(r, "temperature_c") == 55.0)
        .collect();
    assert_eq!((rows.len(), curve.len()), (7, 23));
    let (mut x0, mut x1, mut y1) = (f64::MAX, f64::MIN, f64::MIN);
    for r in &rows {
        let (x, y, band) = (f(r, "speed_rpm"), f(r, "measured_nmm"), f(r, "band_pct"));
        x0 = x0.min(x);
        x1 = x1.max(x);
        y1 = y1.max(y * (1.0 + band / 100.0));
    }
    for c in &curve {
        x0 = x0.min(f(c, "speed_rpm"));
        x1 = x1.max(f(c, "speed_rpm"));
        for k in ["total_nmm", "skf_nmm", "skf_rolling_nmm"] {
            y1 = y1.max(f(c, k));
        }
    }
    let (img, pixel) = open_plot(
        &dir.join(format!("bearing_{id}_breakdown_55C.png")),
        (x0, x1, y1),
        300,
    );
    for r in &rows {
        let at = pixel(f(r, "speed_rpm"), f(r, "measured_nmm"));
        assert_marker_at(&img, at, (0, 0, 0), &format!("{r:?}: measured"));
    }
    // the "+ rib = total" line (the third stacked line) at every other breakdown speed: a
    // pixel of its colour within 2 px of its value
    let green = kontakt_plot::PALETTE[2];
    let mut checked = 0;
    for c in curve.iter().step_by(2) {
        let (px, py) = pixel(f(c, "speed_rpm"), f(c, "total_nmm"));
        let hit = (-2..=2).any(|dy| {
            (-2..=2).any(|dx| {
                let (x, y) = (px.round() as i64 + dx, py.round() as i64 + dy);
                x >= 0
                    && y >= 0
                    && img
                        .get_pixel_checked(x as u32, y as u32)
                        .is_some_and(|p| near(p, green, 40))
            })
        });
        assert!(hit, "no total line at {c:?} ({px:.1}, {py:.1})");
        checked += 1;
    }
    assert_eq!(checked, 12);
    // and not where the raceways alone would put it at the lowest speed, where the rib is
    // the difference (40 N·mm or more, well over 5 px here)
    let c0 = &curve[0];
    let gap = pixel(0.0, 0.0).1 - pixel(0.0, f(c0, "rib_nmm")).1;
    assert!(gap > 8.0, "{gap}");
}
