//! The heat map of a [`FieldMap`](crate::FieldMap).

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::colormap::viridis;
use crate::contour::contour_zero;
use crate::render::{
    DrawResultExt, Figure, Metrics, Target, draw_centered, draw_line_of_text, draw_title, rgb,
    text, text_size, title_height,
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

/// One entry of the outline legend.
struct LegendEntry<'a> {
    label: &'a str,
    color: RGBColor,
    dashed: bool,
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
        let mut top = map.values.iter().copied().fold(0.0f64, f64::max);
        if !(top > lo) {
            top = lo + 1.0;
        }
        let contact = map.values.iter().any(|&v| v > 0.0);

        let x_max = map.x_min + map.nx as f64 * map.dx;
        let y_max = map.y_min + map.ny as f64 * map.dy;
        let (lx, ly) = (x_max - map.x_min, y_max - map.y_min);

        let tick_style = text(m.tick);
        let desc_style = text(m.label);
        let desc_h = |s: &str| {
            if s.is_empty() {
                0
            } else {
                (m.label * 1.35).round() as i32
            }
        };
        let tick_h = (m.tick * 1.25).round() as i32;
        let label_dist = 2 * m.tick_len;
        let title_h = title_height(map.title, &m);
        let caption_h = if self.arrow_label.is_empty() {
            0
        } else {
            (m.tick * 1.5).round() as i32
        };
        // Title and caption above the figure.
        let head_h = title_h + caption_h;

        let width_of = |t: &Ticks| -> Result<i32, PlotError> {
            let mut wmax = 0;
            for s in t.labels() {
                wmax = wmax.max(text_size(root, &s, &tick_style)?.0);
            }
            Ok(wmax)
        };
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
        let x_tick_w = widest(map.x_min, x_max, 8)?;
        let c_tick_w = widest(lo, top, 6)?;

        let left_for = |tick_w: i32| tick_w + label_dist + desc_h(map.y_label) + m.tick_len;
        let bottom = tick_h + label_dist + desc_h(map.x_label) + m.tick_len;
        let gap = ((0.035 * f64::from(w)).round() as i32).max(8);
        let bar_w = ((0.035 * f64::from(w)).round() as i32).max(10);
        let bar_right = label_dist + c_tick_w + m.tick_len + desc_h(map.colorbar_label);

        let mut legend: Vec<LegendEntry> = Vec::new();
        if !map.overlays.is_empty() {
            if map.outline {
                legend.push(LegendEntry {
                    label: "contact boundary",
                    color: BLACK,
                    dashed: false,
                });
            }
            legend.extend(map.overlays.iter().map(|o| LegendEntry {
                label: o.label,
                color: rgb(o.color),
                dashed: true,
            }));
        }
        let legend_h = if legend.is_empty() {
            0
        } else {
            (m.tick * 2.2).round() as i32
        };

        // The plot box: as large as fits, with equal scales in x and y.
        let avail_h = (hi - 2 * m.margin - head_h - tick_h - bottom - legend_h).max(20);
        let fit = |left: i32| -> (i32, i32) {
            let avail_w = (wi - 2 * m.margin - left - gap - bar_w - bar_right).max(20);
            let scale = (f64::from(avail_w - 1) / lx).min(f64::from(avail_h - 1) / ly);
            let pw = ((lx * scale).round() as i32 + 1).clamp(2, avail_w);
            let ph = ((ly * scale).round() as i32 + 1).clamp(2, avail_h);
            (pw, ph)
        };
        let y_spacing = 1.6 * f64::from(tick_h);
        // Size the y labels for the ticks that fit the first guess of the plot height.
        let (_, ph) = fit(left_for(widest(map.y_min, y_max, 8)?));
        let y_ticks = ticks_fitting(map.y_min, y_max, f64::from(ph), y_spacing, 8);
        let left = left_for(width_of(&y_ticks)?);
        let (_, ph) = fit(left);
        let y_ticks = ticks_fitting(map.y_min, y_max, f64::from(ph), y_spacing, 8);
        let left = left.max(left_for(width_of(&y_ticks)?));
        let (pw, ph) = fit(left);
        let x_spacing = f64::from(x_tick_w) + 1.5 * m.tick;
        let x_ticks = ticks_fitting(map.x_min, x_max, f64::from(pw), x_spacing, 8);

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

        let area = root.clone().shrink((ox, oy), (left + pw, ph + bottom));
        let mut chart = ChartBuilder::on(&area)
            .set_label_area_size(LabelAreaPosition::Left, left.max(0) as u32)
            .set_label_area_size(LabelAreaPosition::Bottom, bottom.max(0) as u32)
            .build_cartesian_2d(
                TickAxis::new(map.x_min, x_max, x_ticks.clone()),
                TickAxis::new(map.y_min, y_max, y_ticks.clone()),
            )
            .de()?;

        // The map itself.
        let color_of = |v: f64| viridis((v - lo) / (top - lo));
        if target.raster {
            let (xr, yr) = chart.plotting_area().get_pixel_range();
            let (cw, ch) = ((xr.end - xr.start).max(0), (yr.end - yr.start).max(0));
            // Only the part inside the image is rasterised (plotters' blit does not clip).
            let (c0, c1) = ((-xr.start).max(0), cw.min(wi - xr.start));
            let (r0, r1) = ((-yr.start).max(0), ch.min(hi - yr.start));
            if c1 > c0 && r1 > r0 {
                let cell_of = |c: i32, n_px: i32, n: usize| -> usize {
                    let f = (f64::from(c) + 0.5) / f64::from(n_px);
                    ((f * n as f64).floor() as usize).min(n - 1)
                };
                let cols: Vec<usize> = (c0..c1).map(|c| cell_of(c, cw, map.nx)).collect();
                let mut buf = Vec::with_capacity(cols.len() * (r1 - r0) as usize * 3);
                for r in r0..r1 {
                    // Rows run downwards, y upwards.
                    let j = map.ny - 1 - cell_of(r, ch, map.ny);
                    let row = &map.values[j * map.nx..(j + 1) * map.nx];
                    for &i in &cols {
                        let v = row[i];
                        let (cr, cg, cb) = if v == 0.0 {
                            (255, 255, 255)
                        } else {
                            color_of(v)
                        };
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
                [(map.x_min, map.y_min), (x_max, y_max)],
                BLACK.stroke_width(1),
            )))
            .de()?;

        // Outlines.
        let lw = m.line.max(1) + u32::from(m.scale > 1.5);
        if map.outline {
            for line in contour_zero(
                map.nx, map.ny, map.x_min, map.y_min, map.dx, map.dy, map.values,
            ) {
                chart
                    .draw_series(std::iter::once(PathElement::new(
                        line,
                        BLACK.stroke_width(lw),
                    )))
                    .de()?;
            }
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

        // The vector field, clipped to the map.
        let window = ((map.x_min, x_max), (map.y_min, y_max));
        let segments: Vec<_> = self
            .arrows
            .iter()
            .filter_map(arrow_segments)
            .flatten()
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
            let y = oy + ph + bottom + legend_h / 2;
            draw_legend(root, &legend, centre, y, lw, &m)?;
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
fn draw_colorbar<DB: DrawingBackend>(
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
        if e.dashed {
            let third = sample / 3;
            root.draw(&PathElement::new(vec![(x, y), (x + third, y)], line))
                .de()?;
            root.draw(&PathElement::new(
                vec![(x + 2 * third, y), (x + sample, y)],
                line,
            ))
            .de()?;
        } else {
            root.draw(&PathElement::new(vec![(x, y), (x + sample, y)], line))
                .de()?;
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
