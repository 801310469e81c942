//! Renders sample figures into a directory and prints the rendering times.
//!
//! `cargo run --release -p kontakt-plot --example demo -- [OUT_DIR]` (default: `target/plot-demo`).

use std::path::PathBuf;
use std::time::Instant;

use kontakt_plot::{
    Arrow, FieldMap, LinePlot, LineStyle, Overlay, PALETTE, PlotError, Series, field_map,
    field_map_with_arrows, line_plot,
};

/// Hertz pressure p0 sqrt(1 - x²/a² - y²/b²) on an n×m grid over [-1.25a, 1.25a] × [-1.25b', 1.25b'].
fn hertz(nx: usize, ny: usize, a: f64, b: f64, half_w: f64, half_h: f64) -> Vec<f64> {
    let (dx, dy) = (2.0 * half_w / nx as f64, 2.0 * half_h / ny as f64);
    let mut v = Vec::with_capacity(nx * ny);
    for j in 0..ny {
        for i in 0..nx {
            let x = -half_w + (i as f64 + 0.5) * dx;
            let y = -half_h + (j as f64 + 0.5) * dy;
            v.push(1500.0 * (1.0 - (x / a).powi(2) - (y / b).powi(2)).max(0.0).sqrt());
        }
    }
    v
}

fn main() -> Result<(), PlotError> {
    let out = std::env::args()
        .nth(1)
        .map_or_else(|| PathBuf::from("target/plot-demo"), PathBuf::from);
    std::fs::create_dir_all(&out).map_err(|source| PlotError::Io {
        path: out.clone(),
        source,
    })?;

    // A ball-bearing-like contact ellipse a = 2.4 mm, b = 0.35 mm on a 128×128 grid.
    let (a, b) = (2.4, 0.35);
    let (hw, hh) = (1.2 * a, 1.5 * b);
    let n = 128;
    let p = hertz(n, n, a, b, hw, hh);
    let p_other = hertz(n, n, a * 0.95, b * 1.05, hw, hh);
    let overlays = [Overlay {
        label: "Hertz (a·0.95, b·1.05)",
        values: &p_other,
        color: (230, 30, 30),
    }];
    let map = FieldMap {
        nx: n,
        ny: n,
        x_min: -hw,
        y_min: -hh,
        dx: 2.0 * hw / n as f64,
        dy: 2.0 * hh / n as f64,
        values: &p,
        title: "Contact pressure, inner race, ball 3",
        x_label: "x (rolling) [mm]",
        y_label: "y [mm]",
        colorbar_label: "pressure [MPa]",
        outline: true,
        overlays: &overlays,
        ellipse: None,
        max_marker: None,
        color_max: None,
        stretch: None,
    };
    for ext in ["png", "svg"] {
        let path = out.join(format!("map128.{ext}"));
        let t = Instant::now();
        field_map(&path, &map, (1000, 700))?;
        println!(
            "128×128 map -> {}: {:.1} ms",
            path.display(),
            t.elapsed().as_secs_f64() * 1e3
        );
    }

    // The sliding velocity of the same contact (spin about its centre and a uniform drift),
    // at every 8th cell along x and 16th along y inside the contact: 1 mm of arrow = 2 m/s.
    let (spin, drift, mm_per_m_s) = (100.0, 0.3, 0.5); // rad/s, m/s, mm per m/s
    let mut arrows = Vec::new();
    for j in (8..n).step_by(16) {
        for i in (4..n).step_by(8) {
            if p[j * n + i] > 0.0 {
                let x = map.x_min + (i as f64 + 0.5) * map.dx;
                let y = map.y_min + (j as f64 + 0.5) * map.dy;
                // v = drift + spin × r, with r in m.
                let (vx, vy) = (drift - spin * y * 1e-3, spin * x * 1e-3);
                arrows.push(Arrow {
                    x,
                    y,
                    dx: mm_per_m_s * vx,
                    dy: mm_per_m_s * vy,
                });
            }
        }
    }
    let sliding = FieldMap {
        overlays: &[],
        ellipse: None,
        max_marker: None,
        ..map
    };
    for ext in ["png", "svg"] {
        let path = out.join(format!("sliding128.{ext}"));
        let t = Instant::now();
        field_map_with_arrows(
            &path,
            &sliding,
            &arrows,
            "sliding velocity, 1 mm = 2 m/s",
            (1000, 700),
        )?;
        println!(
            "128×128 map with {} arrows -> {}: {:.1} ms",
            arrows.len(),
            path.display(),
            t.elapsed().as_secs_f64() * 1e3
        );
    }

    // A round contact, 256×256, no overlays.
    let n = 256;
    let p = hertz(n, n, 1.0, 1.0, 1.3, 1.3);
    let round = FieldMap {
        nx: n,
        ny: n,
        x_min: -1.3,
        y_min: -1.3,
        dx: 2.6 / n as f64,
        dy: 2.6 / n as f64,
        values: &p,
        overlays: &[],
        ellipse: None,
        max_marker: None,
        title: "Point contact 256×256",
        ..map
    };
    for ext in ["png", "svg"] {
        let path = out.join(format!("map256.{ext}"));
        let t = Instant::now();
        field_map(&path, &round, (800, 600))?;
        println!(
            "256×256 map -> {}: {:.1} ms",
            path.display(),
            t.elapsed().as_secs_f64() * 1e3
        );
    }

    // No contact, smallest size.
    let zeros = vec![0.0; 20 * 10];
    let empty = FieldMap {
        nx: 20,
        ny: 10,
        x_min: 0.0,
        y_min: 0.0,
        dx: 0.1,
        dy: 0.1,
        values: &zeros,
        overlays: &[],
        ellipse: None,
        max_marker: None,
        title: "Unloaded roller",
        ..map
    };
    field_map(&out.join("empty.png"), &empty, (200, 150))?;

    // Line plot.
    let theory: Vec<(f64, f64)> = (0..=100)
        .map(|k| {
            let x = -3.0 + 0.06 * f64::from(k);
            (x, 1500.0 * (1.0 - (x / a).powi(2)).max(0.0).sqrt())
        })
        .collect();
    let fft: Vec<(f64, f64)> = theory.iter().map(|&(x, p)| (x, 0.97 * p)).collect();
    let measured: Vec<(f64, f64)> = (0..13)
        .map(|k| {
            let x = -2.4 + 0.4 * f64::from(k);
            (
                x,
                1500.0
                    * (1.0 - (x / a).powi(2)).max(0.0).sqrt()
                    * (1.0 + 0.03 * (f64::from(k)).sin()),
            )
        })
        .collect();
    let series = [
        Series {
            label: "Hertz",
            points: &theory,
            color: PALETTE[0],
            style: LineStyle::Solid,
        },
        Series {
            label: "half-space solver",
            points: &fft,
            color: PALETTE[1],
            style: LineStyle::Dashed,
        },
        Series {
            label: "measured",
            points: &measured,
            color: PALETTE[3],
            style: LineStyle::Markers,
        },
    ];
    let plot = LinePlot {
        title: "Pressure along the major axis",
        x_label: "x [mm]",
        y_label: "pressure [MPa]",
        series: &series,
        x_log: false,
        y_from_zero: false,
    };
    for (ext, size) in [
        ("png", (900, 600)),
        ("svg", (900, 600)),
        ("small.png", (200, 150)),
    ] {
        let path = out.join(format!("line.{ext}"));
        let t = Instant::now();
        line_plot(&path, &plot, size)?;
        println!(
            "line plot -> {}: {:.1} ms",
            path.display(),
            t.elapsed().as_secs_f64() * 1e3
        );
    }
    Ok(())
}
