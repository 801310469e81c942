#![allow(clippy::unwrap_used)]
//! Rendering, outline and validation tests of kontakt-plot.

use std::path::{Path, PathBuf};

use kontakt_plot::{
    Arrow, FieldMap, Format, LinePlot, LineStyle, Overlay, PALETTE, PlotError, Series,
    contour_zero, field_map, field_map_with_arrows, line_plot,
};

/// A fresh, empty directory for one test.
fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("kontakt-plot-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The test ellipse: semi-axes along x and y in mm.
const A: f64 = 2.0;
const B: f64 = 1.2;
const NX: usize = 64;
const NY: usize = 48;

/// Cell-centred grid over [-1.25 A, 1.25 A] × [-1.25 B, 1.25 B]: (x_min, y_min, dx, dy).
fn grid() -> (f64, f64, f64, f64) {
    let (hw, hh) = (1.25 * A, 1.25 * B);
    (-hw, -hh, 2.0 * hw / NX as f64, 2.0 * hh / NY as f64)
}

/// p = 1000 sqrt(1 - x²/a² - y²/b²) centred at (cx, cy), 0 outside.
fn hertz(a: f64, b: f64, cx: f64, cy: f64) -> Vec<f64> {
    let (x_min, y_min, dx, dy) = grid();
    let mut v = Vec::with_capacity(NX * NY);
    for j in 0..NY {
        for i in 0..NX {
            let x = x_min + (i as f64 + 0.5) * dx - cx;
            let y = y_min + (j as f64 + 0.5) * dy - cy;
            v.push(1000.0 * (1.0 - (x / a).powi(2) - (y / b).powi(2)).max(0.0).sqrt());
        }
    }
    v
}

fn map<'a>(values: &'a [f64], overlays: &'a [Overlay<'a>]) -> FieldMap<'a> {
    let (x_min, y_min, dx, dy) = grid();
    FieldMap {
        nx: NX,
        ny: NY,
        x_min,
        y_min,
        dx,
        dy,
        values,
        title: "Hertz contact 64x48",
        x_label: "x [mm]",
        y_label: "y [mm]",
        colorbar_label: "pressure [MPa]",
        outline: true,
        overlays,
        ellipse: None,
        max_marker: None,
        color_max: None,
        stretch: None,
    }
}

fn near(p: &image::Rgb<u8>, c: (u8, u8, u8), tol: i32) -> bool {
    (i32::from(p[0]) - i32::from(c.0)).abs() <= tol
        && (i32::from(p[1]) - i32::from(c.1)).abs() <= tol
        && (i32::from(p[2]) - i32::from(c.2)).abs() <= tol
}

fn file_len(path: &Path) -> u64 {
    std::fs::metadata(path).unwrap().len()
}

#[test]
fn field_map_png_and_svg() {
    let dir = temp_dir("field");
    let p = hertz(A, B, 0.0, 0.0);
    let other = hertz(0.9 * A, 1.1 * B, 0.0, 0.0);
    let overlays = [Overlay {
        label: "other solver",
        values: &other,
        color: PALETTE[3],
    }];
    let m = map(&p, &overlays);
    let size = (800, 600);

    let png = dir.join("map.png");
    field_map(&png, &m, size).unwrap();
    assert!(file_len(&png) > 5_000);
    let img = image::open(&png).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), size);
    // The peak of the ellipse (not only the colour bar at the right) has viridis' top colour.
    let top = (253, 231, 37);
    let peak = img
        .enumerate_pixels()
        .filter(|(x, _, p)| *x < size.0 * 3 / 4 && near(p, top, 8))
        .count();
    assert!(
        peak > 500,
        "only {peak} pixels of the top colour in the map"
    );
    let white = img.pixels().filter(|p| near(p, (255, 255, 255), 0)).count();
    assert!(
        white > (size.0 * size.1 / 5) as usize,
        "{white} white pixels"
    );
    // The red overlay is drawn.
    let red = img.pixels().filter(|p| near(p, PALETTE[3], 10)).count();
    assert!(red > 100, "{red} overlay pixels");

    let svg = dir.join("map.svg");
    field_map(&svg, &m, size).unwrap();
    assert!(file_len(&svg) > 10_000);
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg"));
    assert!(text.contains("Hertz contact 64x48"));
    assert!(text.contains("pressure [MPa]"));
    assert!(text.contains("other solver"));
    assert!(text.contains("x [mm]") && text.contains("y [mm]"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A rigid rotation v = (-y, x) sampled at x in {-2, ..., 2} mm, y in {-1, 0, 1} mm and
/// scaled by 0.2: 15 arrows, all inside the test map, the one at the centre of zero length.
fn rotation_arrows() -> Vec<Arrow> {
    let mut arrows = Vec::new();
    for j in -1..=1 {
        for i in -2..=2 {
            let (x, y) = (f64::from(i), f64::from(j));
            arrows.push(Arrow {
                x,
                y,
                dx: -0.2 * y,
                dy: 0.2 * x,
            });
        }
    }
    arrows
}

fn count(text: &str, pattern: &str) -> usize {
    text.matches(pattern).count()
}

fn dark_pixels(path: &Path) -> usize {
    let img = image::open(path).unwrap().to_rgb8();
    img.pixels().filter(|p| near(p, (0, 0, 0), 40)).count()
}

#[test]
fn arrows_png_and_svg() {
    let dir = temp_dir("arrows");
    let p = hertz(A, B, 0.0, 0.0);
    let m = map(&p, &[]);
    let size = (800, 600);
    let mut arrows = rotation_arrows();
    // One arrow pokes out at the right edge (x_max = 2.5 mm): only its shaft is drawn, up to
    // the edge; one lies entirely outside the map and is not drawn at all.
    arrows.push(Arrow {
        x: 2.3,
        y: 0.0,
        dx: 1.0,
        dy: 0.0,
    });
    arrows.push(Arrow {
        x: 5.0,
        y: 5.0,
        dx: 0.5,
        dy: 0.5,
    });
    let label = "sliding velocity, 1 mm = 5 m/s";

    let plain_svg = dir.join("plain.svg");
    field_map(&plain_svg, &m, size).unwrap();
    let plain = std::fs::read_to_string(&plain_svg).unwrap();
    let svg = dir.join("arrows.svg");
    field_map_with_arrows(&svg, &m, &arrows, label, size).unwrap();
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg"));
    assert!(text.contains("Hertz contact 64x48") && text.contains(label));
    // Each arrow is a shaft and two head strokes, one polyline each: 14 whole arrows (the
    // zero-length one is skipped) and the clipped shaft of the one poking out.
    let extra = count(&text, "<polyline") - count(&plain, "<polyline");
    assert_eq!(extra, 14 * 3 + 1, "{extra} arrow strokes");

    let plain_png = dir.join("plain.png");
    field_map(&plain_png, &m, size).unwrap();
    let png = dir.join("arrows.png");
    field_map_with_arrows(&png, &m, &arrows, label, size).unwrap();
    let img = image::open(&png).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), size);
    // The arrows are 0.2 to 0.45 mm long, some 20 to 45 pixels, at least a pixel wide.
    let (before, after) = (dark_pixels(&plain_png), dark_pixels(&png));
    assert!(
        after > before + 14 * 20,
        "{before} dark pixels without arrows, {after} with"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn no_arrows_or_zero_length_arrows_draw_the_plain_map() {
    let dir = temp_dir("arrows-zero");
    let p = hertz(A, B, 0.0, 0.0);
    let m = map(&p, &[]);
    let zero: Vec<Arrow> = rotation_arrows()
        .into_iter()
        .map(|a| Arrow {
            dx: 0.0,
            dy: 0.0,
            ..a
        })
        .collect();
    for ext in ["svg", "png"] {
        let plain = dir.join(format!("plain.{ext}"));
        field_map(&plain, &m, (640, 480)).unwrap();
        let plain = std::fs::read(&plain).unwrap();
        for (name, arrows) in [("none", &[][..]), ("zero", &zero[..])] {
            let out = dir.join(format!("{name}.{ext}"));
            field_map_with_arrows(&out, &m, arrows, "", (640, 480)).unwrap();
            assert!(std::fs::read(&out).unwrap() == plain, "{name}.{ext}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn arrow_validation() {
    let dir = temp_dir("arrows-validation");
    let out = dir.join("map.svg");
    let p = hertz(A, B, 0.0, 0.0);
    let m = map(&p, &[]);
    let good = rotation_arrows();
    let bad_values = [
        (2, "x", f64::NAN),
        (0, "y", f64::INFINITY),
        (7, "dx", f64::NEG_INFINITY),
        (14, "dy", f64::NAN),
    ];
    for (i, name, v) in bad_values {
        let mut arrows = good.clone();
        let a = &mut arrows[i];
        *match name {
            "x" => &mut a.x,
            "y" => &mut a.y,
            "dx" => &mut a.dx,
            _ => &mut a.dy,
        } = v;
        let result = field_map_with_arrows(&out, &m, &arrows, "v", (800, 600));
        let Err(PlotError::InvalidInput { value, .. }) = &result else {
            panic!("expected an invalid arrow, got {result:?}");
        };
        assert!(value.contains(&format!("{name}: {v}")), "{value}");
        expect_invalid(result, &format!("arrows[{i}]"), &out);
    }
    // Finite parts whose tip is not finite.
    let mut arrows = good.clone();
    arrows[3] = Arrow {
        x: 1e308,
        y: 0.0,
        dx: 1e308,
        dy: 0.0,
    };
    expect_invalid(
        field_map_with_arrows(&out, &m, &arrows, "", (800, 600)),
        "arrows[3]",
        &out,
    );
    // The map is still validated first.
    expect_invalid(
        field_map_with_arrows(&out, &FieldMap { nx: 1, ..m }, &arrows, "", (800, 600)),
        "nx",
        &out,
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn all_zero_field_draws_an_empty_map() {
    let dir = temp_dir("zero");
    let zeros = vec![0.0; NX * NY];
    let m = map(&zeros, &[]);
    field_map(&dir.join("zero.png"), &m, (640, 480)).unwrap();
    let svg = dir.join("zero.svg");
    field_map(&svg, &m, (640, 480)).unwrap();
    assert!(
        std::fs::read_to_string(&svg)
            .unwrap()
            .contains("no contact")
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn extreme_shapes_and_sizes_render() {
    let dir = temp_dir("extreme");
    let p = hertz(A, B, 0.0, 0.0);
    let m = map(&p, &[]);
    for (k, size) in [(200, 150), (8000, 150), (200, 1200)]
        .into_iter()
        .enumerate()
    {
        field_map(&dir.join(format!("m{k}.png")), &m, size).unwrap();
    }
    // A very thin strip: 2 × 300 cells of 1 mm × 0.001 mm, negative values too.
    let v: Vec<f64> = (0..600).map(|k| f64::from(k % 7) - 2.0).collect();
    let strip = FieldMap {
        nx: 2,
        ny: 300,
        dx: 1.0,
        dy: 0.001,
        values: &v,
        title: "",
        x_label: "",
        y_label: "",
        colorbar_label: "",
        ..m
    };
    field_map(&dir.join("strip.png"), &strip, (300, 200)).unwrap();
    field_map(&dir.join("strip.svg"), &strip, (300, 200)).unwrap();
    // A large grid goes through the SVG down-sampling.
    let big = vec![1.0; 300 * 200];
    let big_map = FieldMap {
        nx: 300,
        ny: 200,
        dx: 0.01,
        dy: 0.01,
        values: &big,
        ..m
    };
    field_map(&dir.join("big.svg"), &big_map, (600, 400)).unwrap();
    field_map(&dir.join("big.png"), &big_map, (600, 400)).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Shortest distance from a point to the ellipse x²/a² + y²/b² = 1 (dense sampling).
fn distance_to_ellipse((x, y): (f64, f64), a: f64, b: f64, c: (f64, f64)) -> f64 {
    (0..20_000)
        .map(|k| {
            let t = f64::from(k) / 20_000.0 * std::f64::consts::TAU;
            (c.0 + a * t.cos() - x).hypot(c.1 + b * t.sin() - y)
        })
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn outline_of_the_ellipse_follows_it() {
    let (x_min, y_min, dx, dy) = grid();
    let p = hertz(A, B, 0.0, 0.0);
    let lines = contour_zero(NX, NY, x_min, y_min, dx, dy, &p);
    assert_eq!(lines.len(), 1);
    let line = &lines[0];
    assert!(line.len() > 100, "{} points", line.len());
    assert_eq!(line.first(), line.last(), "closed");
    let cell = dx.min(dy);
    let worst = line
        .iter()
        .map(|&q| distance_to_ellipse(q, A, B, (0.0, 0.0)))
        .fold(0.0, f64::max);
    eprintln!("outline: worst distance {worst:.5} mm, cell {cell:.5} mm");
    assert!(worst < cell, "outline up to {worst} mm off, cell {cell} mm");
    // The p² extrapolation at the edge makes it much better than that for a Hertz field.
    assert!(
        worst < 0.1 * cell,
        "outline up to {worst} mm off, cell {cell} mm"
    );
    // It goes all the way round.
    let xs = line.iter().map(|q| q.0);
    let ys = line.iter().map(|q| q.1);
    let (x_lo, x_hi) = (
        xs.clone().fold(f64::MAX, f64::min),
        xs.fold(f64::MIN, f64::max),
    );
    let (y_lo, y_hi) = (
        ys.clone().fold(f64::MAX, f64::min),
        ys.fold(f64::MIN, f64::max),
    );
    assert!((x_lo + A).abs() < cell && (x_hi - A).abs() < cell);
    assert!((y_lo + B).abs() < cell && (y_hi - B).abs() < cell);
}

#[test]
fn two_blobs_give_two_outlines() {
    let (x_min, y_min, dx, dy) = grid();
    let left = hertz(0.6, 0.5, -1.2, 0.0);
    let right = hertz(0.6, 0.5, 1.2, 0.3);
    let both: Vec<f64> = left.iter().zip(&right).map(|(a, b)| a + b).collect();
    let lines = contour_zero(NX, NY, x_min, y_min, dx, dy, &both);
    assert_eq!(lines.len(), 2);
    for line in &lines {
        assert_eq!(line.first(), line.last());
        let cx = line.iter().map(|q| q.0).sum::<f64>() / line.len() as f64;
        let (c, a, b) = if cx < 0.0 {
            ((-1.2, 0.0), 0.6, 0.5)
        } else {
            ((1.2, 0.3), 0.6, 0.5)
        };
        for &q in line {
            assert!(distance_to_ellipse(q, a, b, c) < dx.min(dy));
        }
    }
}

#[test]
fn outline_at_the_grid_edge_is_closed_along_it() {
    // Contact over the whole grid: the outline is the grid boundary.
    let (x_min, y_min, dx, dy) = grid();
    let ones = vec![1.0; NX * NY];
    let lines = contour_zero(NX, NY, x_min, y_min, dx, dy, &ones);
    assert_eq!(lines.len(), 1);
    let x_max = x_min + NX as f64 * dx;
    let y_max = y_min + NY as f64 * dy;
    for &(x, y) in &lines[0] {
        let on_edge = (x - x_min).abs() < 1e-12
            || (x - x_max).abs() < 1e-12
            || (y - y_min).abs() < 1e-12
            || (y - y_max).abs() < 1e-12;
        assert!(
            on_edge || (x - x_min).abs() < dx || (x_max - x).abs() < dx,
            "({x}, {y})"
        );
    }
}

/// Points of one curve.
type Curve = Vec<(f64, f64)>;

fn series_data() -> (Curve, Curve, Curve) {
    let theory: Vec<(f64, f64)> = (0..=80)
        .map(|k| {
            let x = -2.5 + 0.0625 * f64::from(k);
            (x, 1000.0 * (1.0 - (x / A).powi(2)).max(0.0).sqrt())
        })
        .collect();
    let numeric: Vec<(f64, f64)> = theory.iter().map(|&(x, p)| (x, 0.95 * p)).collect();
    let measured: Vec<(f64, f64)> = (0..9)
        .map(|k| {
            let x = -1.6 + 0.4 * f64::from(k);
            (x, 1010.0 * (1.0 - (x / A).powi(2)).sqrt())
        })
        .collect();
    (theory, numeric, measured)
}

#[test]
fn line_plot_png_and_svg() {
    let dir = temp_dir("line");
    let (theory, numeric, measured) = series_data();
    let series = [
        Series {
            label: "Hertz",
            points: &theory,
            color: PALETTE[0],
            style: LineStyle::Solid,
        },
        Series {
            label: "half-space",
            points: &numeric,
            color: PALETTE[1],
            style: LineStyle::Dashed,
        },
        Series {
            label: "measured",
            points: &measured,
            color: PALETTE[2],
            style: LineStyle::Markers,
        },
    ];
    let plot = LinePlot {
        title: "Pressure along x",
        x_label: "x [mm]",
        y_label: "p [MPa]",
        series: &series,
        x_log: false,
        y_from_zero: false,
    };
    let size = (900, 600);
    let png = dir.join("line.PNG");
    line_plot(&png, &plot, size).unwrap();
    let img = image::open(&png).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), size);
    for (k, c) in PALETTE[..3].iter().enumerate() {
        let n = img.pixels().filter(|p| near(p, *c, 6)).count();
        assert!(n > 100, "series {k}: {n} pixels");
    }
    let svg = dir.join("line.svg");
    line_plot(&svg, &plot, size).unwrap();
    let text = std::fs::read_to_string(&svg).unwrap();
    for s in [
        "Pressure along x",
        "x [mm]",
        "p [MPa]",
        "Hertz",
        "half-space",
        "measured",
    ] {
        assert!(text.contains(s), "{s} missing");
    }
    assert!(text.contains("<circle"));

    // Degenerate ranges: a single point, a constant curve; smallest size.
    let one = [(1.0, 2.0)];
    let flat = [(0.0, 5.0), (1.0, 5.0)];
    let series = [
        Series {
            label: "",
            points: &one,
            color: PALETTE[4],
            style: LineStyle::Markers,
        },
        Series {
            label: "flat",
            points: &flat,
            color: PALETTE[5],
            style: LineStyle::Solid,
        },
    ];
    let plot = LinePlot {
        title: "",
        x_label: "",
        y_label: "",
        series: &series,
        x_log: false,
        y_from_zero: false,
    };
    line_plot(&dir.join("small.png"), &plot, (200, 150)).unwrap();
    line_plot(&dir.join("small.svg"), &plot, (200, 150)).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The error of an invalid input, which names `field`; nothing is written.
fn expect_invalid(result: Result<(), PlotError>, field: &str, path: &Path) {
    match result {
        Err(e @ PlotError::InvalidInput { .. }) => {
            let PlotError::InvalidInput { field: f, .. } = &e else {
                unreachable!()
            };
            assert_eq!(f, field, "{e}");
            assert!(e.to_string().contains(field), "{e}");
        }
        other => panic!("expected invalid {field}, got {other:?}"),
    }
    assert!(!path.exists());
}

#[test]
fn format_from_extension() {
    assert_eq!(
        Format::from_path(Path::new("a/b.png")).unwrap(),
        Format::Png
    );
    assert_eq!(Format::from_path(Path::new("b.SVG")).unwrap(), Format::Svg);
    for bad in ["plot.jpg", "plot", "png", "plot.png.txt"] {
        let err = Format::from_path(Path::new(bad)).unwrap_err();
        assert!(matches!(err, PlotError::UnsupportedFormat { .. }));
        let msg = err.to_string();
        assert!(
            msg.contains(bad) && msg.contains(".png") && msg.contains(".svg"),
            "{msg}"
        );
    }
}

#[test]
fn field_map_validation() {
    let dir = temp_dir("field-validation");
    let out = dir.join("map.png");
    let p = hertz(A, B, 0.0, 0.0);
    let m = map(&p, &[]);

    let jpg = dir.join("map.jpg");
    assert!(matches!(
        field_map(&jpg, &m, (800, 600)),
        Err(PlotError::UnsupportedFormat { .. })
    ));
    assert!(!jpg.exists());

    let short = &p[..p.len() - 1];
    expect_invalid(
        field_map(&out, &FieldMap { values: short, ..m }, (800, 600)),
        "values.len()",
        &out,
    );
    let mut nan = p.clone();
    nan[17] = f64::NAN;
    expect_invalid(
        field_map(&out, &FieldMap { values: &nan, ..m }, (800, 600)),
        "values[17]",
        &out,
    );
    let mut inf = p.clone();
    inf[5] = f64::INFINITY;
    expect_invalid(
        field_map(&out, &FieldMap { values: &inf, ..m }, (800, 600)),
        "values[5]",
        &out,
    );
    for size in [(199, 600), (800, 149), (8001, 600), (800, 8001), (0, 0)] {
        expect_invalid(field_map(&out, &m, size), "size", &out);
    }
    expect_invalid(
        field_map(&out, &FieldMap { nx: 1, ..m }, (800, 600)),
        "nx",
        &out,
    );
    expect_invalid(
        field_map(&out, &FieldMap { ny: 0, ..m }, (800, 600)),
        "ny",
        &out,
    );
    for dx in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        expect_invalid(
            field_map(&out, &FieldMap { dx, ..m }, (800, 600)),
            "dx",
            &out,
        );
        expect_invalid(
            field_map(&out, &FieldMap { dy: dx, ..m }, (800, 600)),
            "dy",
            &out,
        );
    }
    expect_invalid(
        field_map(
            &out,
            &FieldMap {
                x_min: f64::NAN,
                ..m
            },
            (800, 600),
        ),
        "x_min",
        &out,
    );
    expect_invalid(
        field_map(
            &out,
            &FieldMap {
                y_min: f64::NEG_INFINITY,
                ..m
            },
            (800, 600),
        ),
        "y_min",
        &out,
    );
    expect_invalid(
        field_map(&out, &FieldMap { dx: 1e307, ..m }, (800, 600)),
        "grid extent",
        &out,
    );

    // Overlays are checked too.
    let overlays = [Overlay {
        label: "fft",
        values: &p[..10],
        color: (0, 0, 0),
    }];
    expect_invalid(
        field_map(&out, &map(&p, &overlays), (800, 600)),
        "overlays[0] (\"fft\").values.len()",
        &out,
    );
    let overlays = [
        Overlay {
            label: "ok",
            values: &p,
            color: (0, 0, 0),
        },
        Overlay {
            label: "bad",
            values: &nan,
            color: (0, 0, 0),
        },
    ];
    expect_invalid(
        field_map(&out, &map(&p, &overlays), (800, 600)),
        "overlays[1] (\"bad\").values[17]",
        &out,
    );

    // A missing directory is an io error naming the path; it is not created.
    let missing = dir.join("no-such-dir").join("map.svg");
    let err = field_map(&missing, &m, (800, 600)).unwrap_err();
    assert!(matches!(err, PlotError::Io { .. }), "{err:?}");
    assert!(err.to_string().contains("no-such-dir"), "{err}");
    assert!(!missing.parent().unwrap().exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn line_plot_validation() {
    let dir = temp_dir("line-validation");
    let out = dir.join("line.svg");
    let good = [(0.0, 1.0), (1.0, 2.0), (2.0, 1.5)];
    let ok = Series {
        label: "a",
        points: &good,
        color: PALETTE[0],
        style: LineStyle::Solid,
    };
    let plot = |series: &[Series]| -> Result<(), PlotError> {
        line_plot(
            &out,
            &LinePlot {
                title: "t",
                x_label: "x",
                y_label: "y",
                series,
                x_log: false,
                y_from_zero: false,
            },
            (800, 600),
        )
    };

    expect_invalid(plot(&[]), "series", &out);
    expect_invalid(
        plot(&[
            ok,
            Series {
                label: "empty",
                points: &[],
                ..ok
            },
        ]),
        "series[1] (\"empty\").points",
        &out,
    );
    let bad = [(0.0, 1.0), (1.0, 2.0), (f64::NAN, 1.5)];
    expect_invalid(
        plot(&[
            ok,
            Series {
                label: "b",
                points: &bad,
                ..ok
            },
        ]),
        "series[1] (\"b\").points[2]",
        &out,
    );
    let bad = [(0.0, f64::INFINITY)];
    expect_invalid(
        plot(&[Series {
            label: "c",
            points: &bad,
            ..ok
        }]),
        "series[0] (\"c\").points[0]",
        &out,
    );
    let huge = [(-1e308, 0.0), (1e308, 1.0)];
    expect_invalid(
        plot(&[Series {
            points: &huge,
            ..ok
        }]),
        "series",
        &out,
    );
    expect_invalid(
        line_plot(
            &out,
            &LinePlot {
                title: "t",
                x_label: "x",
                y_label: "y",
                series: &[ok],
                x_log: false,
                y_from_zero: false,
            },
            (100, 100),
        ),
        "size",
        &out,
    );
    let err = line_plot(
        &dir.join("line.pdf"),
        &LinePlot {
            title: "t",
            x_label: "x",
            y_label: "y",
            series: &[ok],
            x_log: false,
            y_from_zero: false,
        },
        (800, 600),
    )
    .unwrap_err();
    assert!(err.to_string().contains("line.pdf"), "{err}");
    plot(&[ok]).unwrap();
    assert!(out.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn odd_shapes_and_ranges_do_not_panic() {
    let dir = temp_dir("odd");
    let long_title = "A very long title that will not fit into the width of a small figure at all";
    let mut k = 0;
    for (nx, ny) in [(2, 2), (3, 17), (200, 3)] {
        for (dx, dy) in [
            (1.0, 1.0),
            (1e-3, 1.0),
            (1.0, 1e-3),
            (1e-9, 1e-9),
            (1e4, 1e4),
        ] {
            for size in [(200, 150), (1500, 160), (210, 1400)] {
                let v: Vec<f64> = (0..nx * ny)
                    .map(|i| if i % 3 == 0 { 0.0 } else { i as f64 * 1e-7 })
                    .collect();
                let m = FieldMap {
                    nx,
                    ny,
                    x_min: -1e3,
                    y_min: 5.0,
                    dx,
                    dy,
                    values: &v,
                    title: long_title,
                    x_label: "x [mm]",
                    y_label: "y [mm]",
                    colorbar_label: "pressure [MPa]",
                    outline: true,
                    overlays: &[Overlay {
                        label: "other",
                        values: &v,
                        color: (1, 2, 3),
                    }],
                    ellipse: None,
                    max_marker: Some("max"),
                    color_max: None,
                    stretch: None,
                };
                let ext = if k % 2 == 0 { "png" } else { "svg" };
                field_map(&dir.join(format!("f{k}.{ext}")), &m, size).unwrap();
                k += 1;
            }
        }
    }
    let cases: [&[(f64, f64)]; 4] = [
        &[(1e300, -1e300), (-1e300, 1e300)],
        &[(1.0, 1.0), (1.0 + 1e-12, 1.0 + 1e-12)],
        &[(0.0, 0.0)],
        &[(-5.0, 3.0), (-5.0, 3.0), (-5.0, 3.0)],
    ];
    for (k, points) in cases.into_iter().enumerate() {
        let series = [Series {
            label: long_title,
            points,
            color: PALETTE[7],
            style: LineStyle::Dashed,
        }];
        let plot = LinePlot {
            title: long_title,
            x_label: "x",
            y_label: "y",
            series: &series,
            x_log: false,
            y_from_zero: false,
        };
        for size in [(200, 150), (3000, 150)] {
            line_plot(&dir.join(format!("l{k}-{}.png", size.0)), &plot, size).unwrap();
            line_plot(&dir.join(format!("l{k}-{}.svg", size.0)), &plot, size).unwrap();
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The symbols the CLI's labels use are in the bundled font (no blank boxes).
#[test]
fn the_bundled_font_has_the_label_symbols() {
    let labels = "Fₜ / (μ Fₙ) [-]; μ = |Fₜ| / Q_f; Fₐ = 15000 N; τ · v_s [mW/mm²]; \
                  10⁻³ 5·10⁷ ×4 ° ≈ −";
    assert_eq!(kontakt_plot::missing_glyphs(labels), Vec::<char>::new());
    assert_eq!(kontakt_plot::missing_glyphs("a漢b"), vec!['漢']);
}

/// A logarithmic x axis draws, and rejects x <= 0 before writing anything.
#[test]
fn log_x_axis() {
    let dir = temp_dir("log_x_axis");
    let pts: Vec<(f64, f64)> = [50.0, 130.0, 339.0, 884.0, 2303.0, 6000.0]
        .iter()
        .map(|&n: &f64| (n, 1.0 / n.ln()))
        .collect();
    let series = [Series {
        label: "curve",
        points: &pts,
        color: (31, 119, 180),
        style: LineStyle::Solid,
    }];
    let plot = LinePlot {
        title: "log axis",
        x_label: "speed [r/min] (log scale)",
        y_label: "y",
        series: &series,
        x_log: true,
        y_from_zero: false,
    };
    let out = dir.join("log.svg");
    line_plot(&out, &plot, (800, 600)).unwrap();
    let svg = std::fs::read_to_string(&out).unwrap();
    let texts: Vec<&str> = svg.lines().map(str::trim).collect();
    for label in ["50", "100", "1000", "5000"] {
        assert!(texts.contains(&label), "{label} missing");
    }
    let bad = [(0.0, 1.0), (10.0, 2.0)];
    let series = [Series {
        points: &bad,
        ..series[0]
    }];
    let out = dir.join("bad.svg");
    let e = line_plot(
        &out,
        &LinePlot {
            series: &series,
            ..plot
        },
        (800, 600),
    )
    .unwrap_err();
    assert!(e.to_string().contains("logarithmic"), "{e}");
    assert!(!out.exists());
}

/// Stacked panels: each panel's legend is drawn inside its own panel (the lower one's
/// was once drawn a panel's height too low, outside the image), and bars stand on 0.
#[test]
fn stacked_panels_keep_their_legends() {
    let dir = temp_dir("panels");
    let loads: Vec<(f64, f64)> = (0..12)
        .map(|k| (30.0 * f64::from(k) - 180.0, 100.0 + f64::from(k)))
        .collect();
    let ribs: Vec<(f64, f64)> = loads.iter().map(|&(x, y)| (x, 0.1 * y)).collect();
    let upper = [Series {
        label: "raceway load",
        points: &loads,
        color: PALETTE[0],
        style: LineStyle::Bars,
    }];
    let lower = [Series {
        label: "rib load",
        points: &ribs,
        color: PALETTE[1],
        style: LineStyle::Bars,
    }];
    let plot = |title, y_label, series| LinePlot {
        title,
        x_label: "azimuth [deg]",
        y_label,
        series,
        x_log: false,
        y_from_zero: true,
    };
    let plots = [
        plot("loads", "load [N]", &upper[..]),
        plot("", "rib load [N]", &lower[..]),
    ];
    let svg = dir.join("panels.svg");
    kontakt_plot::line_plots(&svg, &plots, (800, 1000)).unwrap();
    let text = std::fs::read_to_string(&svg).unwrap();
    let y_of = |label: &str| -> f64 {
        let at = text
            .find(&format!(">\n{label}\n</text>"))
            .unwrap_or_else(|| panic!("no {label}"));
        let head = &text[..at];
        let y = head.rfind(" y=\"").unwrap() + 4;
        let end = head[y..].find('"').unwrap() + y;
        head[y..end].parse().unwrap()
    };
    let (a, b) = (y_of("raceway load"), y_of("rib load"));
    assert!(a < 500.0, "upper legend at y = {a}");
    assert!((500.0..1000.0).contains(&b), "lower legend at y = {b}");
    // bars: the PNG has large filled areas of both colours
    let png = dir.join("panels.png");
    kontakt_plot::line_plots(&png, &plots, (800, 1000)).unwrap();
    let img = image::open(&png).unwrap().to_rgb8();
    for (c, half) in [(PALETTE[0], 0..500), (PALETTE[1], 500..1000)] {
        let n = img
            .enumerate_pixels()
            .filter(|(_, y, p)| half.contains(y) && near(p, c, 4))
            .count();
        assert!(n > 20_000, "{n} bar pixels of {c:?}");
    }
    // one x axis: the first bar starts at the same pixel column in both panels (the y
    // labels "100" and "10" once gave the panels different left edges)
    let first_column = |c: (u8, u8, u8), rows: std::ops::Range<u32>| {
        img.enumerate_pixels()
            .filter(|(_, y, p)| rows.contains(y) && near(p, c, 4))
            .map(|(x, _, _)| x)
            .min()
            .unwrap()
    };
    assert_eq!(
        first_column(PALETTE[0], 0..500),
        first_column(PALETTE[1], 500..1000)
    );
    // no panels: an error naming the argument
    let e = kontakt_plot::line_plots(&png, &[], (800, 600)).unwrap_err();
    assert!(e.to_string().contains("plots"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}
