//! The heat map of a [`FieldMap`](crate::FieldMap).

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::colormap::viridis;
use crate::contour::contour_zero;
use crate::render::{
    DrawResultExt, Figure, Metrics, Target, desc_height, draw_centered, draw_line_of_text,
    draw_title, labels_width, rgb, text, text_size, title_height,
};
use crate::ticks::{TickAxis, Ticks, nice_ticks, ticks_fitting};
use crate::{Arrow, FieldMap, PlotError};

/// SVG maps are drawn with at most this many cells along each axis.
const SVG_MAX_CELLS: usize = 128;

/// Colour of the arrows of a vector field: black reads on white and on all of viridis.
const ARROW_COLOR: RGBColor = BLACK;
/// Length of an arrow head's strokes relative to the length of the arrow.
const HEAD_FRACTION: f64 = 0.3;
/// Angle between an arrow head's strokes and the shaft, in degrees.
const HEAD_ANGLE_DEG: f64 = 25.0;

/// A [`FieldMap`] as a drawable figure, optionally with a vector field on top.
pub(crate) struct FieldFigure<'a> {
    pub map: &'a FieldMap<'a>,
    /// Arrows drawn over the map (none for a plain heat map).
    pub arrows: &'a [Arrow],
    /// Caption under the title giving the arrows' meaning and scale (empty: none).
    pub arrow_label: &'a str,
}

/// One entry of the legend under the map.
#[derive(Clone)]
struct LegendEntry<'a> {
    label: &'a str,
    color: RGBColor,
    kind: EntryKind,
}

/// How a legend entry's sample is drawn.
#[derive(Clone, Copy, PartialEq, Eq)]
enum EntryKind {
    Solid,
    Dashed,
    Dotted,
    Marker,
}

/// The largest slenderness (long side over short side) drawn to scale.
const MAX_ASPECT: f64 = 2.5;

/// The part of the plane a map shows and the stretch of its axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Frame {
    /// x range in mm.
    pub x: (f64, f64),
    /// y range in mm.
    pub y: (f64, f64),
    /// Scale factors (x, y) of the axes relative to each other: (1, 1) to scale, (1, k)
    /// for y stretched k times, (k, 1) for x stretched.
    pub stretch: (f64, f64),
}

impl Frame {
    /// The note on a stretched axis (empty when drawn to scale).
    pub fn note(&self) -> String {
        let (sx, sy) = self.stretch;
        let (axis, k) = if sy > 1.0 { ("y", sy) } else { ("x", sx) };
        if k <= 1.0 {
            return String::new();
        }
        format!(
            "{axis} axis stretched ×{}: the zone is {}× more slender than drawn",
            crate::ticks::format_fixed(k, 0),
            crate::ticks::format_fixed(k, 0)
        )
    }
}

/// The frame of a map: the bounding box of its cells with values, its overlays' regions and
/// its ellipse, with a margin of 8 % of its size (at least one cell) on each side and kept
/// within the grid and the ellipse; the whole grid when there is nothing to show. When that
/// box is more slender than [`MAX_ASPECT`], its short axis is stretched by the smallest
/// whole factor that brings it to at most [`MAX_ASPECT`].
pub(crate) fn frame(map: &FieldMap) -> Frame {
    let x_max = map.x_min + map.nx as f64 * map.dx;
    let y_max = map.y_min + map.ny as f64 * map.dy;
    let (mut bx0, mut bx1, mut by0, mut by1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    let mut grow = |x0: f64, x1: f64, y0: f64, y1: f64| {
        bx0 = bx0.min(x0);
        bx1 = bx1.max(x1);
        by0 = by0.min(y0);
        by1 = by1.max(y1);
    };
    let fields = std::iter::once(map.values).chain(map.overlays.iter().map(|o| o.values));
    for values in fields {
        for (k, v) in values.iter().enumerate() {
            if *v != 0.0 {
                let (i, j) = ((k % map.nx) as f64, (k / map.nx) as f64);
                let x = map.x_min + i * map.dx;
                let y = map.y_min + j * map.dy;
                grow(x, x + map.dx, y, y + map.dy);
            }
        }
    }
    let (mut gx0, mut gx1, mut gy0, mut gy1) = (map.x_min, x_max, map.y_min, y_max);
    // The ellipse lies wholly inside the frame, with a margin (its dotted line's tips
    // were cut at the frame's edge).
    let mut ellipse_box = None;
    if let Some(e) = &map.ellipse {
        let (s, c) = e.angle.sin_cos();
        let (a, b) = e.semi_axes;
        let hx = (a * c).hypot(b * s);
        let hy = (a * s).hypot(b * c);
        let (ex0, ex1, ey0, ey1) = (
            e.centre.0 - hx,
            e.centre.0 + hx,
            e.centre.1 - hy,
            e.centre.1 + hy,
        );
        grow(ex0, ex1, ey0, ey1);
        ellipse_box = Some((ex0, ex1, ey0, ey1));
    }
    if !(bx1 > bx0) || !(by1 > by0) {
        return Frame {
            x: (map.x_min, x_max),
            y: (map.y_min, y_max),
            stretch: (1.0, 1.0),
        };
    }
    let px = (0.08 * (bx1 - bx0)).max(map.dx);
    let py = (0.08 * (by1 - by0)).max(map.dy);
    if let Some((ex0, ex1, ey0, ey1)) = ellipse_box {
        gx0 = gx0.min(ex0 - px);
        gx1 = gx1.max(ex1 + px);
        gy0 = gy0.min(ey0 - py);
        gy1 = gy1.max(ey1 + py);
    }
    let x = ((bx0 - px).max(gx0), (bx1 + px).min(gx1));
    let y = ((by0 - py).max(gy0), (by1 + py).min(gy1));
    let aspect = (x.1 - x.0) / (y.1 - y.0);
    let factor = |r: f64| (r / MAX_ASPECT - 1e-9).ceil().max(1.0);
    let wide = aspect >= 1.0;
    let k = match map.stretch {
        Some(k) => k,
        None if aspect > MAX_ASPECT => factor(aspect),
        None if aspect < 1.0 / MAX_ASPECT => factor(1.0 / aspect),
        None => 1.0,
    };
    let stretch = if wide { (1.0, k) } else { (k, 1.0) };
    Frame { x, y, stretch }
}

/// The x intervals inside the closed polylines `lines` along the horizontal line at `y`
/// (even-odd rule: holes are outside), sorted.
pub(crate) fn row_intervals(lines: &[Vec<(f64, f64)>], y: f64) -> Vec<(f64, f64)> {
    let mut xs = Vec::new();
    for line in lines {
        let n = line.len();
        for k in 0..n {
            let (a, b) = (line[k], line[(k + 1) % n]);
            if (a.1 > y) != (b.1 > y) {
                xs.push(a.0 + (y - a.1) * (b.0 - a.0) / (b.1 - a.1));
            }
        }
    }
    xs.sort_by(f64::total_cmp);
    xs.chunks_exact(2).map(|p| (p[0], p[1])).collect()
}

/// The value of the cell at `(x, y)` (0 outside the grid). With `fill_edge`, a zero cell
/// takes the value of the nearest of its eight neighbours that has one: inside the outline,
/// which runs between the last loaded cell centre and the next, the map is then coloured up
/// to the outline instead of leaving white slivers.
fn cell_value(map: &FieldMap, x: f64, y: f64, fill_edge: bool) -> f64 {
    let fi = ((x - map.x_min) / map.dx).floor();
    let fj = ((y - map.y_min) / map.dy).floor();
    let (nx, ny) = (map.nx as i64, map.ny as i64);
    let (i, j) = (fi as i64, fj as i64);
    let at = |i: i64, j: i64| -> f64 {
        if i < 0 || j < 0 || i >= nx || j >= ny {
            0.0
        } else {
            map.values[(j * nx + i) as usize]
        }
    };
    let v = at(i, j);
    if v != 0.0 || !fill_edge || !fi.is_finite() || !fj.is_finite() {
        return v;
    }
    let mut best = (f64::MAX, 0.0);
    for dj in -1..=1 {
        for di in -1..=1 {
            let w = at(i + di, j + dj);
            if w != 0.0 {
                let cx = map.x_min + ((i + di) as f64 + 0.5) * map.dx;
                let cy = map.y_min + ((j + dj) as f64 + 0.5) * map.dy;
                let d = ((x - cx) / map.dx).powi(2) + ((y - cy) / map.dy).powi(2);
                if d < best.0 {
                    best = (d, w);
                }
            }
        }
    }
    best.1
}

/// The index of the largest of `values` (the first of equal ones), if any is > 0.
pub(crate) fn argmax_positive(values: &[f64]) -> Option<usize> {
    let (k, v) =
        values.iter().enumerate().fold(
            (0, f64::MIN),
            |best, (k, &v)| if v > best.1 { (k, v) } else { best },
        );
    (v > 0.0).then_some(k)
}

/// Centre of the cell with the largest value (the first of equal ones), if any is > 0.
pub(crate) fn argmax_centre(map: &FieldMap) -> Option<(f64, f64)> {
    argmax_positive(map.values).map(|k| {
        (
            map.x_min + ((k % map.nx) as f64 + 0.5) * map.dx,
            map.y_min + ((k / map.nx) as f64 + 0.5) * map.dy,
        )
    })
}

/// `n` + 1 points around the ellipse (closed).
fn ellipse_points(e: &crate::Ellipse, n: usize) -> Vec<(f64, f64)> {
    let (s, c) = e.angle.sin_cos();
    (0..=n)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / n as f64;
            let (u, v) = (e.semi_axes.0 * t.cos(), e.semi_axes.1 * t.sin());
            (e.centre.0 + c * u - s * v, e.centre.1 + s * u + c * v)
        })
        .collect()
}

/// The maximum's marker at pixel `at`: a black dot in a white disc with a black ring.
pub(crate) fn draw_marker<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    at: (i32, i32),
    m: &Metrics,
) -> Result<(), PlotError> {
    let r = ((7.0 * m.scale).round() as i32).max(5);
    root.draw(&Circle::new(at, r + 1, WHITE.filled())).de()?;
    root.draw(&Circle::new(at, r, BLACK.stroke_width(m.line.max(2))))
        .de()?;
    root.draw(&Circle::new(at, (r / 3).max(2), BLACK.filled()))
        .de()?;
    Ok(())
}

/// The legend's entries broken into rows that fit `width` pixels.
fn legend_layout<'a, DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    entries: &[LegendEntry<'a>],
    width: i32,
    m: &Metrics,
) -> Result<Vec<Vec<LegendEntry<'a>>>, PlotError> {
    let style = text(m.tick);
    let sample = (2.5 * m.tick).round() as i32;
    let pad = (0.5 * m.tick).round() as i32;
    let sep = (1.5 * m.tick).round() as i32;
    let mut rows: Vec<Vec<LegendEntry>> = Vec::new();
    let mut used = 0;
    for e in entries {
        let w = sample + pad + text_size(root, e.label, &style)?.0;
        match rows.last_mut() {
            Some(row) if used + sep + w <= width => {
                row.push(e.clone());
                used += sep + w;
            }
            _ => {
                rows.push(vec![e.clone()]);
                used = w;
            }
        }
    }
    Ok(rows)
}

impl Figure for FieldFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, target: &Target<DB>) -> Result<(), PlotError> {
        let map = self.map;
        let root = &target.root;
        root.fill(&WHITE).de()?;
        let (w, h) = root.dim_in_pixel();
        let (wi, hi) = (w as i32, h as i32);
        let m = Metrics::new((w, h));

        // Colour range: from min(0, min) to max(0, max).
        let lo = map.values.iter().copied().fold(0.0f64, f64::min);
        let mut top = map
            .color_max
            .unwrap_or_else(|| map.values.iter().copied().fold(0.0f64, f64::max));
        if !(top > lo) {
            top = lo + 1.0;
        }
        let contact = map.values.iter().any(|&v| v > 0.0);

        let frame = frame(map);
        let ((vx0, vx1), (vy0, vy1)) = (frame.x, frame.y);
        let (lx, ly) = (vx1 - vx0, vy1 - vy0);
        let contour = if map.outline {
            contour_zero(
                map.nx, map.ny, map.x_min, map.y_min, map.dx, map.dy, map.values,
            )
        } else {
            Vec::new()
        };

        let tick_style = text(m.tick);
        let desc_style = text(m.label);
        let desc_h = |s: &str| desc_height(s, &m);
        let tick_h = (m.tick * 1.25).round() as i32;
        let label_dist = 2 * m.tick_len;
        let title_h = title_height(map.title, &m);
        let caption_h = if self.arrow_label.is_empty() {
            0
        } else {
            (m.tick * 1.5).round() as i32
        };
        let note = frame.note();
        let note_h = if note.is_empty() {
            0
        } else {
            (m.tick * 1.5).round() as i32
        };
        // Title and captions above the figure.
        let head_h = title_h + caption_h + note_h;

        let width_of = |t: &Ticks| labels_width(root, t, &tick_style);
        // Widest tick labels over the tick sets we may end up using.
        let widest = |lo: f64, hi: f64, max_count: usize| -> Result<i32, PlotError> {
            let mut wmax = 0;
            for n in 2..=max_count + 3 {
                let t = nice_ticks(lo, hi, n);
                if t.values.len() <= max_count {
                    wmax = wmax.max(width_of(&t)?);
                }
            }
            Ok(wmax)
        };
        let x_tick_w = widest(vx0, vx1, 8)?;
        let c_tick_w = widest(lo, top, 6)?;

        let left_for = |tick_w: i32| tick_w + label_dist + desc_h(map.y_label) + m.tick_len;
        let bottom = tick_h + label_dist + desc_h(map.x_label) + m.tick_len;
        let gap = ((0.035 * f64::from(w)).round() as i32).max(8);
        let bar_w = ((0.035 * f64::from(w)).round() as i32).max(10);
        let bar_right = label_dist + c_tick_w + m.tick_len + desc_h(map.colorbar_label);

        let mut legend: Vec<LegendEntry> = Vec::new();
        let any_extra =
            !map.overlays.is_empty() || map.ellipse.is_some() || map.max_marker.is_some();
        if any_extra {
            if map.outline {
                legend.push(LegendEntry {
                    label: "contact boundary",
                    color: BLACK,
                    kind: EntryKind::Solid,
                });
            }
            legend.extend(map.overlays.iter().map(|o| LegendEntry {
                label: o.label,
                color: rgb(o.color),
                kind: EntryKind::Dashed,
            }));
            if let Some(e) = &map.ellipse {
                legend.push(LegendEntry {
                    label: e.label,
                    color: rgb(e.color),
                    kind: EntryKind::Dotted,
                });
            }
            if let Some(label) = map.max_marker.filter(|_| contact) {
                legend.push(LegendEntry {
                    label,
                    color: BLACK,
                    kind: EntryKind::Marker,
                });
            }
        }
        let legend_rows = legend_layout(root, &legend, wi - 2 * m.margin, &m)?;
        let legend_h = if legend.is_empty() {
            0
        } else {
            (m.tick * 0.7).round() as i32 + legend_rows.len() as i32 * (m.tick * 1.5).round() as i32
        };

        // The plot box: as large as fits, with equal scales in x and y.
        let avail_h = (hi - 2 * m.margin - head_h - tick_h - bottom - legend_h).max(20);
        let fit = |left: i32| -> (i32, i32) {
            let avail_w = (wi - 2 * m.margin - left - gap - bar_w - bar_right).max(20);
            let (sx, sy) = frame.stretch;
            let scale =
                (f64::from(avail_w - 1) / (lx * sx)).min(f64::from(avail_h - 1) / (ly * sy));
            let pw = ((lx * sx * scale).round() as i32 + 1).clamp(2, avail_w);
            let ph = ((ly * sy * scale).round() as i32 + 1).clamp(2, avail_h);
            (pw, ph)
        };
        let y_spacing = 1.6 * f64::from(tick_h);
        // Size the y labels for the ticks that fit the first guess of the plot height.
        let (_, ph) = fit(left_for(widest(vy0, vy1, 8)?));
        let y_ticks = ticks_fitting(vy0, vy1, f64::from(ph), y_spacing, 8);
        let left = left_for(width_of(&y_ticks)?);
        let (_, ph) = fit(left);
        let y_ticks = ticks_fitting(vy0, vy1, f64::from(ph), y_spacing, 8);
        let left = left.max(left_for(width_of(&y_ticks)?));
        let (pw, ph) = fit(left);
        let x_spacing = f64::from(x_tick_w) + 1.5 * m.tick;
        let x_ticks = ticks_fitting(vx0, vx1, f64::from(pw), x_spacing, 8);

        // The colour bar is as tall as the map, but tall enough for its ticks.
        let bar_h = ph.max((12 * tick_h).min(avail_h));
        let c_ticks = ticks_fitting(lo, top, f64::from(bar_h), y_spacing, 6);

        // Centre the whole figure; the title and the caption sit right above it.
        let block_w = left + pw + gap + bar_w + bar_right;
        let ox = ((wi - block_w) / 2).max(0);
        let above = ph.max(bar_h) / 2 + tick_h / 2 + head_h;
        let below = (ph / 2 + bottom + legend_h).max(bar_h / 2 + tick_h / 2);
        let start = ((hi - above - below) / 2).max(m.margin);
        let centre_y = start + above;
        let oy = centre_y - ph / 2;
        draw_title(root, map.title, &m, start)?;
        draw_line_of_text(root, self.arrow_label, m.tick, &m, start + title_h)?;
        draw_line_of_text(root, &note, m.tick, &m, start + title_h + caption_h)?;

        let area = root.clone().shrink((ox, oy), (left + pw, ph + bottom));
        let mut chart = ChartBuilder::on(&area)
            .set_label_area_size(LabelAreaPosition::Left, left.max(0) as u32)
            .set_label_area_size(LabelAreaPosition::Bottom, bottom.max(0) as u32)
            .build_cartesian_2d(
                TickAxis::new(vx0, vx1, x_ticks.clone()),
                TickAxis::new(vy0, vy1, y_ticks.clone()),
            )
            .de()?;

        // The map itself, inside the outline only.
        let value_at = |x: f64, y: f64| -> f64 { cell_value(map, x, y, map.outline) };
        let color_of = |v: f64| viridis((v - lo) / (top - lo));
        if target.raster {
            let (xr, yr) = chart.plotting_area().get_pixel_range();
            let (cw, ch) = ((xr.end - xr.start).max(0), (yr.end - yr.start).max(0));
            // Only the part inside the image is rasterised (plotters' blit does not clip).
            let (c0, c1) = ((-xr.start).max(0), cw.min(wi - xr.start));
            let (r0, r1) = ((-yr.start).max(0), ch.min(hi - yr.start));
            if c1 > c0 && r1 > r0 {
                let x_of = |c: i32| vx0 + (f64::from(c) + 0.5) / f64::from(cw) * lx;
                let mut buf = Vec::with_capacity((c1 - c0) as usize * (r1 - r0) as usize * 3);
                for r in r0..r1 {
                    // Rows run downwards, y upwards.
                    let y = vy1 - (f64::from(r) + 0.5) / f64::from(ch) * ly;
                    let inside = map.outline.then(|| row_intervals(&contour, y));
                    for c in c0..c1 {
                        let x = x_of(c);
                        let v = value_at(x, y);
                        let shown = v != 0.0
                            && inside
                                .as_ref()
                                .is_none_or(|iv| iv.iter().any(|&(a, b)| a <= x && x <= b));
                        let (cr, cg, cb) = if shown { color_of(v) } else { (255, 255, 255) };
                        buf.extend_from_slice(&[cr, cg, cb]);
                    }
                }
                let image = BitMapElement::with_owned_buffer(
                    (xr.start + c0, yr.start + r0),
                    ((c1 - c0) as u32, (r1 - r0) as u32),
                    buf,
                )
                .ok_or_else(|| PlotError::Drawing("heat map buffer too small".into()))?;
                root.draw(&image).de()?;
            }
        } else {
            // One rectangle per run of equally coloured cells in a row.
            let cells = Blocks::new(map, SVG_MAX_CELLS);
            let mut rects: Vec<Run> = Vec::new();
            let mut run: Option<Run> = None;
            for c in cells.iter() {
                let color = (c.value != 0.0).then(|| color_of(c.value));
                match (&mut run, color) {
                    (Some(r), Some(col)) if r.color == col && r.x.1 == c.x0 && r.y.0 == c.y0 => {
                        r.x.1 = c.x1;
                    }
                    _ => {
                        rects.extend(run.take());
                        run = color.map(|color| Run {
                            x: (c.x0, c.x1),
                            y: (c.y0, c.y1),
                            color,
                        });
                    }
                }
            }
            rects.extend(run);
            // Only the parts inside the outline, taken at the middle of each row.
            if map.outline {
                rects = rects
                    .into_iter()
                    .flat_map(|r| {
                        let iv = row_intervals(&contour, 0.5 * (r.y.0 + r.y.1));
                        iv.into_iter().filter_map(move |(a, b)| {
                            let (x0, x1) = (r.x.0.max(a), r.x.1.min(b));
                            (x1 > x0).then_some(Run {
                                x: (x0, x1),
                                y: r.y,
                                color: r.color,
                            })
                        })
                    })
                    .collect();
            }
            let window = ((vx0, vx1), (vy0, vy1));
            rects.retain(|r| r.x.1 > vx0 && r.x.0 < vx1 && r.y.1 > vy0 && r.y.0 < vy1);
            for r in &mut rects {
                r.x = (r.x.0.max(window.0.0), r.x.1.min(window.0.1));
                r.y = (r.y.0.max(window.1.0), r.y.1.min(window.1.1));
            }
            chart
                .draw_series(rects.into_iter().map(|r| {
                    Rectangle::new([(r.x.0, r.y.0), (r.x.1, r.y.1)], rgb(r.color).filled())
                }))
                .de()?;
        }

        // Axes, ticks and frame.
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(map.x_label)
            .y_desc(map.y_label)
            .label_style(tick_style.clone())
            .axis_desc_style(desc_style.clone())
            .set_all_tick_mark_size(m.tick_len)
            .axis_style(BLACK.stroke_width(1))
            .draw()
            .de()?;
        chart
            .draw_series(std::iter::once(Rectangle::new(
                [(vx0, vy0), (vx1, vy1)],
                BLACK.stroke_width(1),
            )))
            .de()?;

        // Outlines.
        let lw = m.line.max(1) + u32::from(m.scale > 1.5);
        for line in &contour {
            chart
                .draw_series(std::iter::once(PathElement::new(
                    line.clone(),
                    BLACK.stroke_width(lw),
                )))
                .de()?;
        }
        let dash = ((8.0 * m.scale).round() as i32).max(4);
        let space = ((5.0 * m.scale).round() as i32).max(3);
        for overlay in map.overlays {
            let style = rgb(overlay.color).stroke_width(lw);
            for line in contour_zero(
                map.nx,
                map.ny,
                map.x_min,
                map.y_min,
                map.dx,
                map.dy,
                overlay.values,
            ) {
                chart
                    .draw_series(DashedLineSeries::new(line, dash, space, style))
                    .de()?;
            }
        }

        // The ellipse, dotted, and the maximum's marker.
        if let Some(e) = &map.ellipse {
            let dot = ((2.0 * m.scale).round() as i32).max(2);
            let space = ((4.0 * m.scale).round() as i32).max(3);
            chart
                .draw_series(DashedLineSeries::new(
                    ellipse_points(e, 180),
                    dot,
                    space,
                    rgb(e.color).stroke_width(lw),
                ))
                .de()?;
        }
        if map.max_marker.is_some()
            && contact
            && let Some(at) = argmax_centre(map)
        {
            let (px, py) = chart.backend_coord(&at);
            draw_marker(root, (px, py), &m)?;
        }

        // The vector field, clipped to the map.
        let window = ((vx0, vx1), (vy0, vy1));
        // On a stretched axis the arrows keep their true direction and the length scale of
        // the unstretched axis: they are built where the map is to scale and mapped back.
        let (sx, sy) = frame.stretch;
        let segments: Vec<_> = self
            .arrows
            .iter()
            .filter_map(|a| {
                arrow_segments(&Arrow {
                    x: a.x * sx,
                    y: a.y * sy,
                    ..*a
                })
            })
            .flatten()
            .map(|(a, b)| ((a.0 / sx, a.1 / sy), (b.0 / sx, b.1 / sy)))
            .filter_map(|(a, b)| clip_segment(a, b, window))
            .collect();
        let arrow_style = ARROW_COLOR.stroke_width(m.line.max(1));
        chart
            .draw_series(
                segments
                    .into_iter()
                    .map(|(a, b)| PathElement::new(vec![a, b], arrow_style)),
            )
            .de()?;

        if !contact {
            draw_centered(
                root,
                "no contact",
                m.label,
                (ox + left + pw / 2, oy + ph / 2),
            )?;
        }

        // Colour bar.
        let bar_y = centre_y - bar_h / 2;
        let bar_x = ox + left + pw + gap;
        draw_colorbar(
            root,
            (bar_x, bar_y, bar_w, bar_h, bar_right),
            (lo, top),
            &c_ticks,
            map.colorbar_label,
            &m,
        )?;

        // Legend under the map.
        if !legend.is_empty() {
            let centre = ox + left + pw / 2;
            let row_h = (m.tick * 1.5).round() as i32;
            let y = oy + ph + bottom + (m.tick * 0.7).round() as i32 + row_h / 2;
            for (k, row) in legend_rows.iter().enumerate() {
                draw_legend(root, row, centre, y + k as i32 * row_h, lw, &m)?;
            }
        }
        Ok(())
    }
}

/// A line segment (start, end) in mm.
type Segment = ((f64, f64), (f64, f64));

/// The strokes of an arrow in mm: the shaft from tail to tip and the two strokes of the head,
/// each as (start, end). `None` for an arrow of zero length.
fn arrow_segments(a: &Arrow) -> Option<[Segment; 3]> {
    if a.dx == 0.0 && a.dy == 0.0 {
        return None;
    }
    let tip = (a.x + a.dx, a.y + a.dy);
    // A head stroke is the reversed vector, shortened and turned by ± the head angle.
    let (bx, by) = (-HEAD_FRACTION * a.dx, -HEAD_FRACTION * a.dy);
    let (s, c) = HEAD_ANGLE_DEG.to_radians().sin_cos();
    let left = (tip.0 + c * bx + s * by, tip.1 - s * bx + c * by);
    let right = (tip.0 + c * bx - s * by, tip.1 + s * bx + c * by);
    Some([((a.x, a.y), tip), (left, tip), (right, tip)])
}

/// The part of the segment from `p0` to `p1` inside the window `((x0, x1), (y0, y1))`
/// (Liang-Barsky), or `None` if nothing (or only a point) of it is inside.
fn clip_segment(
    p0: (f64, f64),
    p1: (f64, f64),
    ((x0, x1), (y0, y1)): ((f64, f64), (f64, f64)),
) -> Option<Segment> {
    let (dx, dy) = (p1.0 - p0.0, p1.1 - p0.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, p0.0 - x0),
        (dx, x1 - p0.0),
        (-dy, p0.1 - y0),
        (dy, y1 - p0.1),
    ] {
        if !p.is_finite() || !q.is_finite() {
            return None;
        }
        if p == 0.0 {
            // Parallel to this edge: inside or outside entirely.
            if q < 0.0 {
                return None;
            }
        } else if p < 0.0 {
            t0 = t0.max(q / p);
        } else {
            t1 = t1.min(q / p);
        }
    }
    (t0 < t1).then_some({
        (
            (p0.0 + t0 * dx, p0.1 + t0 * dy),
            (p0.0 + t1 * dx, p0.1 + t1 * dy),
        )
    })
}

/// Colour bar with its ticks on the right and its label (rotated) beyond them.
pub(crate) fn draw_colorbar<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    (x, y, bar_w, bar_h, right): (i32, i32, i32, i32, i32),
    (lo, top): (f64, f64),
    ticks: &Ticks,
    label: &str,
    m: &Metrics,
) -> Result<(), PlotError> {
    let area = root.clone().shrink((x, y), (bar_w + right, bar_h));
    let mut bar = ChartBuilder::on(&area)
        .set_label_area_size(LabelAreaPosition::Right, right.max(0) as u32)
        .build_cartesian_2d(0f64..1f64, TickAxis::new(lo, top, ticks.clone()))
        .de()?;
    let strips = bar_h.clamp(1, 256);
    let step = (top - lo) / f64::from(strips);
    bar.draw_series((0..strips).map(|k| {
        let v0 = lo + f64::from(k) * step;
        let v1 = if k + 1 == strips { top } else { v0 + step };
        let t = (f64::from(k) + 0.5) / f64::from(strips);
        Rectangle::new([(0.0, v0), (1.0, v1)], rgb(viridis(t)).filled())
    }))
    .de()?;
    let fmt = |v: &f64| ticks.format(*v);
    let mut mesh = bar.configure_mesh();
    mesh.disable_mesh()
        .disable_x_axis()
        .y_label_formatter(&fmt)
        .label_style(text(m.tick))
        .axis_desc_style(text(m.label))
        .set_all_tick_mark_size(m.tick_len)
        .axis_style(BLACK.stroke_width(1));
    if !label.is_empty() {
        mesh.y_desc(label);
    }
    mesh.draw().de()?;
    bar.draw_series(std::iter::once(Rectangle::new(
        [(0.0, lo), (1.0, top)],
        BLACK.stroke_width(1),
    )))
    .de()?;
    Ok(())
}

/// One-row legend of line samples and labels, centred at `centre`.
fn draw_legend<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    entries: &[LegendEntry],
    centre: i32,
    y: i32,
    lw: u32,
    m: &Metrics,
) -> Result<(), PlotError> {
    let style = text(m.tick);
    let sample = (2.5 * m.tick).round() as i32;
    let pad = (0.5 * m.tick).round() as i32;
    let sep = (1.5 * m.tick).round() as i32;
    let mut widths = Vec::with_capacity(entries.len());
    for e in entries {
        widths.push(sample + pad + text_size(root, e.label, &style)?.0);
    }
    let total: i32 = widths.iter().sum::<i32>() + sep * (entries.len() as i32 - 1);
    let (w, _) = root.dim_in_pixel();
    let mut x = (centre - total / 2)
        .max(m.margin)
        .min((w as i32 - total).max(0));
    for (e, width) in entries.iter().zip(widths) {
        let line = e.color.stroke_width(lw);
        match e.kind {
            EntryKind::Dashed => {
                let third = sample / 3;
                root.draw(&PathElement::new(vec![(x, y), (x + third, y)], line))
                    .de()?;
                root.draw(&PathElement::new(
                    vec![(x + 2 * third, y), (x + sample, y)],
                    line,
                ))
                .de()?;
            }
            EntryKind::Dotted => {
                let step = (sample / 5).max(2);
                let dot = (step / 2).max(1);
                let mut sx = x;
                while sx < x + sample {
                    root.draw(&PathElement::new(vec![(sx, y), (sx + dot, y)], line))
                        .de()?;
                    sx += step;
                }
            }
            EntryKind::Solid => {
                root.draw(&PathElement::new(vec![(x, y), (x + sample, y)], line))
                    .de()?;
            }
            EntryKind::Marker => draw_marker(root, (x + sample / 2, y), m)?,
        }
        let label_style = style.pos(Pos::new(HPos::Left, VPos::Center));
        root.draw_text(e.label, &label_style, (x + sample + pad, y))
            .de()?;
        x += width + sep;
    }
    Ok(())
}

/// A horizontal run of equally coloured cells: x and y extents in mm and the colour.
struct Run {
    x: (f64, f64),
    y: (f64, f64),
    color: (u8, u8, u8),
}

/// A rectangle of the (possibly coarsened) grid with its value.
struct Block {
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
    value: f64,
}

/// The grid coarsened by averaging blocks of cells to at most `max` cells per axis (a block is
/// 0, i.e. background, only if all its cells are).
struct Blocks {
    blocks: Vec<Block>,
}

impl Blocks {
    fn new(map: &FieldMap, max: usize) -> Self {
        let fx = map.nx.div_ceil(max).max(1);
        let fy = map.ny.div_ceil(max).max(1);
        let (bnx, bny) = (map.nx.div_ceil(fx), map.ny.div_ceil(fy));
        let mut blocks = Vec::with_capacity(bnx * bny);
        for bj in 0..bny {
            let (j0, j1) = (bj * fy, ((bj + 1) * fy).min(map.ny));
            for bi in 0..bnx {
                let (i0, i1) = (bi * fx, ((bi + 1) * fx).min(map.nx));
                let mut sum = 0.0;
                let mut any = false;
                for j in j0..j1 {
                    for &v in &map.values[j * map.nx + i0..j * map.nx + i1] {
                        sum += v;
                        any |= v != 0.0;
                    }
                }
                let n = ((i1 - i0) * (j1 - j0)) as f64;
                let mean = sum / n;
                // Keep a block with contact visible even if its mean rounds to 0.
                let value = if any && mean == 0.0 {
                    f64::MIN_POSITIVE
                } else if any {
                    mean
                } else {
                    0.0
                };
                blocks.push(Block {
                    x0: map.x_min + i0 as f64 * map.dx,
                    x1: map.x_min + i1 as f64 * map.dx,
                    y0: map.y_min + j0 as f64 * map.dy,
                    y1: map.y_min + j1 as f64 * map.dy,
                    value,
                });
            }
        }
        Blocks { blocks }
    }

    fn iter(&self) -> impl Iterator<Item = &Block> {
        self.blocks.iter()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: (f64, f64), b: (f64, f64)) -> bool {
        (a.0 - b.0).abs() < 1e-12 && (a.1 - b.1).abs() < 1e-12
    }

    fn map_of<'a>(nx: usize, ny: usize, values: &'a [f64]) -> FieldMap<'a> {
        FieldMap {
            nx,
            ny,
            x_min: -1.0,
            y_min: -1.0,
            dx: 2.0 / nx as f64,
            dy: 2.0 / ny as f64,
            values,
            title: "",
            x_label: "",
            y_label: "",
            colorbar_label: "",
            outline: true,
            overlays: &[],
            ellipse: None,
            max_marker: None,
            color_max: None,
            stretch: None,
        }
    }

    #[test]
    fn framing_is_tight_and_stretches_slender_zones() {
        // A 1.0 x 0.12 mm zone in the middle of a 2 x 2 mm grid of 100 x 100 cells.
        let n = 100;
        let values: Vec<f64> = (0..n * n)
            .map(|k| {
                let (x, y) = (
                    -1.0 + ((k % n) as f64 + 0.5) * 0.02,
                    -1.0 + ((k / n) as f64 + 0.5) * 0.02,
                );
                if x.abs() < 0.5 && y.abs() < 0.06 {
                    1.0
                } else {
                    0.0
                }
            })
            .collect();
        let map = map_of(n, n, &values);
        let f = frame(&map);
        // 8 % of the zone's size on each side, at least a cell: x ±0.58, y ±0.08.
        assert!(
            (f.x.0 + 0.58).abs() < 1e-9 && (f.x.1 - 0.58).abs() < 1e-9,
            "{f:?}"
        );
        assert!(
            (f.y.0 + 0.08).abs() < 1e-9 && (f.y.1 - 0.08).abs() < 1e-9,
            "{f:?}"
        );
        // 1.16 / 0.16 = 7.25:1 is stretched by 3 to 2.4:1 (at most 2.5:1), and the note says so.
        assert_eq!(f.stretch, (1.0, 3.0));
        assert!(f.note().starts_with("y axis stretched ×3"), "{}", f.note());
        // A round zone filling half the grid: to scale, no note.
        let round: Vec<f64> = (0..n * n)
            .map(|k| {
                let (x, y) = (
                    -1.0 + ((k % n) as f64 + 0.5) * 0.02,
                    -1.0 + ((k / n) as f64 + 0.5) * 0.02,
                );
                if x * x + y * y < 0.25 { 1.0 } else { 0.0 }
            })
            .collect();
        let f = frame(&map_of(n, n, &round));
        assert_eq!(f.stretch, (1.0, 1.0));
        assert!(f.note().is_empty());
        assert!(f.x.1 - f.x.0 < 1.2 && f.y.1 - f.y.0 < 1.2, "{f:?}");
        // The ellipse widens the frame; nothing at all shows the whole grid.
        let mut with_ellipse = map_of(n, n, &round);
        with_ellipse.ellipse = Some(crate::Ellipse {
            label: "",
            centre: (0.0, 0.0),
            semi_axes: (0.8, 0.1),
            angle: 0.0,
            color: (0, 0, 0),
        });
        let f = frame(&with_ellipse);
        // the whole ellipse with a margin: its tips are not cut at the frame (issue 30)
        assert!(f.x.0 < -0.8 - 0.05 && f.x.1 > 0.8 + 0.05, "{f:?}");
        assert!(f.y.0 < -0.1 && f.y.1 > 0.1, "{f:?}");
        // A given stretch is used as it is, on the short axis.
        let fixed = FieldMap {
            stretch: Some(2.0),
            ..map_of(n, n, &values)
        };
        assert_eq!(frame(&fixed).stretch, (1.0, 2.0));
        assert_eq!(crate::map_stretch(&fixed), 3.0);
        let zero = vec![0.0; n * n];
        let f = frame(&map_of(n, n, &zero));
        assert_eq!(
            (f.x, f.y, f.stretch),
            ((-1.0, 1.0), (-1.0, 1.0), (1.0, 1.0))
        );
    }

    #[test]
    fn no_cell_is_drawn_outside_the_outline() {
        // A Hertz-like disc: every cell colour drawn lies inside the outline's intervals, and
        // the outer corners of the boundary cells (which a cell-by-cell drawing would show)
        // are outside.
        let n = 24;
        let h = 2.0 / n as f64;
        let c = |k: usize| -1.0 + (k as f64 + 0.5) * h;
        let values: Vec<f64> = (0..n * n)
            .map(|k| {
                (1.0 - (c(k % n).powi(2) + c(k / n).powi(2)) / 0.64)
                    .max(0.0)
                    .sqrt()
            })
            .collect();
        let lines = contour_zero(n, n, -1.0, -1.0, h, h, &values);
        let mut poking = 0;
        for j in 0..n {
            let iv = row_intervals(&lines, c(j));
            for i in 0..n {
                if values[j * n + i] > 0.0 {
                    // The cell centre is inside.
                    assert!(iv.iter().any(|&(a, b)| a <= c(i) && c(i) <= b));
                    let outer = c(i) + 0.5 * h * c(i).signum();
                    if !iv.iter().any(|&(a, b)| a <= outer && outer <= b) {
                        poking += 1;
                    }
                }
            }
        }
        assert!(poking > 0, "the masking has nothing to cut");
        // Holes are outside (even-odd).
        let ring = vec![
            vec![(-2.0, -2.0), (2.0, -2.0), (2.0, 2.0), (-2.0, 2.0)],
            vec![(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)],
        ];
        assert_eq!(row_intervals(&ring, 0.0), vec![(-2.0, -1.0), (1.0, 2.0)]);
    }

    #[test]
    fn the_marker_is_at_the_maximum() {
        let mut values = vec![0.0; 16];
        values[9] = 5.0;
        values[10] = 7.0;
        values[6] = 7.0;
        // The first of the two equal maxima: cell 6 = (i 2, j 1).
        let map = map_of(4, 4, &values);
        assert_eq!(argmax_centre(&map), Some((0.25, -0.25)));
        assert_eq!(argmax_centre(&map_of(4, 4, &[0.0; 16])), None);
    }

    #[test]
    fn arrow_head_is_symmetric_and_short() {
        let a = Arrow {
            x: 1.0,
            y: 2.0,
            dx: 3.0,
            dy: 4.0,
        };
        let [shaft, left, right] = arrow_segments(&a).unwrap();
        assert_eq!(shaft, ((1.0, 2.0), (4.0, 6.0)));
        let len = |(p, q): ((f64, f64), (f64, f64))| (q.0 - p.0).hypot(q.1 - p.1);
        for stroke in [left, right] {
            assert_eq!(stroke.1, (4.0, 6.0));
            assert!((len(stroke) - HEAD_FRACTION * 5.0).abs() < 1e-12);
            assert!(len(stroke) <= 5.0 / 3.0);
        }
        // The barbs lie on either side of the shaft, mirrored about it.
        let side = |p: (f64, f64)| 3.0 * (p.1 - 2.0) - 4.0 * (p.0 - 1.0);
        assert!(side(left.0) > 0.0 && side(right.0) < 0.0);
        assert!((side(left.0) + side(right.0)).abs() < 1e-12);
        let zero = Arrow {
            dx: 0.0,
            dy: -0.0,
            ..a
        };
        assert!(arrow_segments(&zero).is_none());
    }

    #[test]
    fn segments_are_clipped_to_the_window() {
        let w = ((0.0, 2.0), (0.0, 1.0));
        // Inside: unchanged.
        let s = clip_segment((0.5, 0.5), (1.5, 0.25), w).unwrap();
        assert!(close(s.0, (0.5, 0.5)) && close(s.1, (1.5, 0.25)));
        // Poking out at the right and at the top.
        let s = clip_segment((1.0, 0.5), (3.0, 0.5), w).unwrap();
        assert!(close(s.0, (1.0, 0.5)) && close(s.1, (2.0, 0.5)));
        let s = clip_segment((1.0, 1.5), (1.0, 0.5), w).unwrap();
        assert!(close(s.0, (1.0, 1.0)) && close(s.1, (1.0, 0.5)));
        // Crossing the whole window diagonally.
        let s = clip_segment((-1.0, -0.5), (3.0, 1.5), w).unwrap();
        assert!(close(s.0, (0.0, 0.0)) && close(s.1, (2.0, 1.0)));
        // Outside, or touching a corner only.
        assert!(clip_segment((3.0, 0.0), (4.0, 1.0), w).is_none());
        assert!(clip_segment((-1.0, 0.5), (-0.5, 0.5), w).is_none());
        assert!(clip_segment((-1.0, 0.0), (0.0, 1.0), w).is_none());
        assert!(clip_segment((3.0, 0.0), (2.5, 2.0), w).is_none());
    }
}
