//! Line plots.

use plotters::coord::Shift;
use plotters::prelude::*;

use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::render::{
    DrawResultExt, Figure, Metrics, Target, desc_height, draw_title, labels_width, rgb, text,
    text_size, title_height,
};
use crate::ticks::{TickAxis, Ticks, log_ticks, nice_ticks, ticks_fitting};
use crate::{LinePlot, LineStyle, PlotError, Series};

/// A [`LinePlot`] as a drawable figure.
pub(crate) struct LineFigure<'a>(pub &'a LinePlot<'a>);

/// `[lo, hi]` widened by 4 % on each side; a single value gets a range around it.
fn padded(lo: f64, hi: f64) -> (f64, f64) {
    let span = hi - lo;
    if span > 0.0 {
        (lo - 0.04 * span, hi + 0.04 * span)
    } else {
        let d = if lo != 0.0 { 0.1 * lo.abs() } else { 1.0 };
        (lo - d, hi + d)
    }
}

/// The y range of data in `[lo, hi]` that starts at 0: `[0, hi + 4 %]` for data ≥ 0,
/// `[lo − 4 %, 0]` for data ≤ 0, both ends padded when the data change sign.
pub(crate) fn from_zero(lo: f64, hi: f64) -> (f64, f64) {
    let (a, b) = padded(lo.min(0.0), hi.max(0.0));
    (
        if lo >= 0.0 { 0.0 } else { a },
        if hi <= 0.0 { 0.0 } else { b },
    )
}

impl Figure for LineFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, target: &Target<DB>) -> Result<(), PlotError> {
        let m = Metrics::new(target.root.dim_in_pixel());
        draw_plot(self.0, &target.root, &m, None)
    }
}

/// Several [`LinePlot`]s stacked from top to bottom, each in an equal share of the height,
/// with the fonts of the whole image.
pub(crate) struct Panels<'a>(pub &'a [LinePlot<'a>]);

impl Figure for Panels<'_> {
    fn draw<DB: DrawingBackend>(&self, target: &Target<DB>) -> Result<(), PlotError> {
        let m = Metrics::new(target.root.dim_in_pixel());
        let root = &target.root;
        // one x range, and room left of each plot for the widest y labels of them all
        let (mut x0, mut x1, mut left, mut legend_w) = (f64::MAX, f64::MIN, 0, 0);
        let style = text(m.tick);
        for plot in self.0 {
            let e = extent(plot);
            x0 = x0.min(e.x.0);
            x1 = x1.max(e.x.1);
            let (y0, y1) = if plot.y_from_zero {
                from_zero(e.y.0, e.y.1)
            } else {
                padded(e.y.0, e.y.1)
            };
            let mut widest = 0;
            for n in 2..=13 {
                let t = nice_ticks(y0, y1, n);
                if t.values.len() <= 10 {
                    for label in t.labels() {
                        widest = widest.max(text_size(root, &label, &style)?.0);
                    }
                }
            }
            let desc = if plot.y_label.is_empty() {
                0
            } else {
                (m.label * 1.35).round() as i32
            };
            left = left.max(widest + 2 * m.tick_len + desc + m.tick_len);
            // the legend box as draw_plot sizes it
            let mut label_w = 0;
            for series in plot.series.iter().filter(|s| !s.label.is_empty()) {
                label_w = label_w.max(text_size(root, series.label, &style)?.0);
            }
            if label_w > 0 {
                let sample = (2.5 * m.tick).round() as i32;
                legend_w = legend_w.max(sample + label_w + 4 * m.tick_len + 2 * m.tick_len);
            }
        }
        let shared = Shared {
            x: (x0, x1),
            left,
            legend_w,
        };
        let areas = root.split_evenly((self.0.len().max(1), 1));
        for (plot, area) in self.0.iter().zip(&areas) {
            draw_plot(plot, area, &m, Some(shared))?;
        }
        Ok(())
    }
}

/// Where the bars of the bar series stand: the offset of each bar series' bars from their
/// x (in the order of the series; 0 for the others) and the bars' width, both in x units;
/// the bars of all bar series at one x take 80 % of the smallest spacing of their x values.
pub(crate) fn bar_slots(series: &[Series], data: &[Vec<(f64, f64)>]) -> (Vec<f64>, f64) {
    let bars: Vec<usize> = (0..series.len())
        .filter(|&k| series[k].style == LineStyle::Bars)
        .collect();
    let mut offsets = vec![0.0; series.len()];
    if bars.is_empty() {
        return (offsets, 0.0);
    }
    let mut xs: Vec<f64> = bars
        .iter()
        .flat_map(|&k| data[k].iter().map(|p| p.0))
        .collect();
    xs.sort_by(f64::total_cmp);
    let spacing = xs
        .windows(2)
        .map(|p| p[1] - p[0])
        .filter(|d| *d > 1e-12 * (1.0 + p_abs(&xs)))
        .fold(f64::INFINITY, f64::min);
    let spacing = if spacing.is_finite() { spacing } else { 1.0 };
    let group = 0.8 * spacing;
    let width = group / bars.len() as f64;
    for (slot, &k) in bars.iter().enumerate() {
        offsets[k] = -0.5 * group + (slot as f64 + 0.5) * width;
    }
    (offsets, width)
}

/// The largest magnitude of `xs` (for a relative spacing tolerance).
fn p_abs(xs: &[f64]) -> f64 {
    xs.iter().fold(0.0, |m: f64, x| m.max(x.abs()))
}

/// The data of a plot (over log10 x on a logarithmic axis), where its bars stand, and the
/// ranges it covers (bars included, which stand on 0), before padding.
struct Extent {
    data: Vec<Vec<(f64, f64)>>,
    bar_offsets: Vec<f64>,
    bar_w: f64,
    x: (f64, f64),
    y: (f64, f64),
}

fn extent(plot: &LinePlot) -> Extent {
    // On a logarithmic x axis the curves are drawn over log10 x.
    let tx = |x: f64| if plot.x_log { x.log10() } else { x };
    let data: Vec<Vec<(f64, f64)>> = plot
        .series
        .iter()
        .map(|s| s.points.iter().map(|&(x, y)| (tx(x), y)).collect())
        .collect();
    let (bar_offsets, bar_w) = bar_slots(plot.series, &data);
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for (k, pts) in data.iter().enumerate() {
        let half = if plot.series[k].style == LineStyle::Bars {
            0.5 * bar_w
        } else {
            0.0
        };
        for &(x, y) in pts {
            let x = x + bar_offsets[k];
            x0 = x0.min(x - half);
            x1 = x1.max(x + half);
            y0 = y0.min(y);
            y1 = y1.max(y);
            if half > 0.0 {
                // a bar stands on 0
                y0 = y0.min(0.0);
                y1 = y1.max(0.0);
            }
        }
    }
    Extent {
        data,
        bar_offsets,
        bar_w,
        x: (x0, x1),
        y: (y0, y1),
    }
}

/// What the panels of [`Panels`] share: the x range (before padding) and the smallest
/// width left of the plot area in pixels, so that their x axes line up.
#[derive(Debug, Clone, Copy)]
struct Shared {
    x: (f64, f64),
    left: i32,
    /// Room right of each plot for the widest legend of them all, with its gap.
    legend_w: i32,
}

/// Draw `plot` on `root` with the fonts and lines of `m`.
fn draw_plot<DB: DrawingBackend>(
    plot: &LinePlot,
    root: &DrawingArea<DB, Shift>,
    m: &Metrics,
    shared: Option<Shared>,
) -> Result<(), PlotError> {
    {
        let m = *m;
        root.fill(&WHITE).de()?;
        let (w, h) = root.dim_in_pixel();
        let (wi, hi) = (w as i32, h as i32);

        let Extent {
            data,
            bar_offsets,
            bar_w,
            x: (x0, x1),
            y: (y0, y1),
        } = extent(plot);
        let (x0, x1) = shared.map_or((x0, x1), |s| s.x);
        let (x0, x1) = padded(x0, x1);
        let (y0, y1) = if plot.y_from_zero {
            from_zero(y0, y1)
        } else {
            padded(y0, y1)
        };
        if !(x1 - x0).is_finite() || !(y1 - y0).is_finite() {
            return Err(PlotError::InvalidInput {
                field: "series".into(),
                value: format!("x in [{x0}, {x1}], y in [{y0}, {y1}]"),
                expected: "ranges whose width is a finite number".into(),
            });
        }

        draw_title(root, plot.title, &m, m.margin)?;
        let title_bottom = m.margin + title_height(plot.title, &m);
        let tick_style = text(m.tick);
        let desc_h = |s: &str| desc_height(s, &m);
        let tick_h = (m.tick * 1.25).round() as i32;
        let label_dist = 2 * m.tick_len;
        let width_of = |t: &Ticks| labels_width(root, t, &tick_style);
        // Widest x tick labels over the tick sets we may end up using.
        let mut x_tick_w = 0;
        if plot.x_log {
            x_tick_w = width_of(&log_ticks(x0, x1, 1e6, 1.0))?;
        } else {
            for n in 2..=13 {
                let t = nice_ticks(x0, x1, n);
                if t.values.len() <= 10 {
                    x_tick_w = x_tick_w.max(width_of(&t)?);
                }
            }
        }

        // The legend: its size, then where it goes (a free corner, or right of the plot).
        let sample = (2.5 * m.tick).round() as i32;
        let labelled: Vec<(usize, &Series)> = plot
            .series
            .iter()
            .enumerate()
            .filter(|(_, s)| !s.label.is_empty())
            .collect();
        let mut label_w = 0;
        for (_, s) in &labelled {
            label_w = label_w.max(text_size(root, s.label, &tick_style)?.0);
        }
        let pad = m.tick_len;
        let row_h = (m.tick * 1.4).round() as i32;
        let box_w = sample + pad + label_w + 3 * pad;
        let box_h = labelled.len() as i32 * row_h + 2 * pad;
        let gap = 2 * m.tick_len;

        let bottom = tick_h + label_dist + desc_h(plot.x_label) + m.tick_len;
        let top = title_bottom + tick_h / 2;
        let layout = |legend_right: i32| -> Result<(i32, i32, i32, i32, Ticks, Ticks), PlotError> {
            let right = m.margin.max(x_tick_w / 2 + 2) + legend_right;
            let area_w = (wi - m.margin - right).max(20);
            let area_h = (hi - top - m.margin).max(20);
            let ph = (area_h - bottom).max(2);
            let y_ticks = ticks_fitting(y0, y1, f64::from(ph), 1.6 * f64::from(tick_h), 10);
            let left = (width_of(&y_ticks)? + label_dist + desc_h(plot.y_label) + m.tick_len)
                .max(shared.map_or(0, |s| s.left));
            let pw = (area_w - left).max(2);
            let x_spacing = f64::from(x_tick_w) + 1.5 * m.tick;
            let x_ticks = if plot.x_log {
                log_ticks(x0, x1, f64::from(pw), x_spacing)
            } else {
                ticks_fitting(x0, x1, f64::from(pw), x_spacing, 10)
            };
            Ok((area_w, area_h, left, pw, x_ticks, y_ticks))
        };
        let (mut area_w, mut area_h, mut left, pw, mut x_ticks, mut y_ticks) = layout(0)?;
        let ph = (area_h - bottom).max(2);
        let mut place = LegendPlace::Corner(0);
        if let Some(s) = shared {
            // panels: every legend right of its plot, in room of one width for all, so
            // that the plot areas and x axes line up
            place = LegendPlace::Outside;
            (area_w, area_h, left, _, x_ticks, y_ticks) = layout(s.legend_w)?;
        } else if !labelled.is_empty() {
            let units: Vec<(LineStyle, Vec<(f64, f64)>)> = data
                .iter()
                .zip(plot.series)
                .zip(&bar_offsets)
                .map(|((pts, s), off)| {
                    let unit = |x: f64, y: f64| ((x - x0) / (x1 - x0), (y - y0) / (y1 - y0));
                    if s.style == LineStyle::Bars {
                        // the bar's area, sampled: its edges and middle from 0 up
                        let mut samples = Vec::new();
                        for &(x, y) in pts {
                            for k in 0..=20 {
                                let v = y * f64::from(k) / 20.0;
                                for dx in [-0.5, 0.0, 0.5] {
                                    samples.push(unit(x + off + dx * bar_w, v));
                                }
                            }
                        }
                        (LineStyle::Markers, samples)
                    } else {
                        (s.style, pts.iter().map(|&(x, y)| unit(x, y)).collect())
                    }
                })
                .collect();
            let margin_fraction = (
                f64::from(2 * gap) / f64::from(pw),
                f64::from(2 * gap) / f64::from(ph),
            );
            place = legend_place(
                &units,
                (
                    f64::from(box_w) / f64::from(pw) + margin_fraction.0,
                    f64::from(box_h) / f64::from(ph) + margin_fraction.1,
                ),
            );
            if place == LegendPlace::Outside {
                (area_w, area_h, left, _, x_ticks, y_ticks) = layout(box_w + gap)?;
            }
        }
        let ph = (area_h - bottom).max(2);

        let area = root.clone().shrink((m.margin, top), (area_w, area_h));
        let mut chart = ChartBuilder::on(&area)
            .set_label_area_size(LabelAreaPosition::Left, left.max(0) as u32)
            .set_label_area_size(LabelAreaPosition::Bottom, bottom.max(0) as u32)
            .build_cartesian_2d(
                TickAxis::new(x0, x1, x_ticks.clone()),
                TickAxis::new(y0, y1, y_ticks.clone()),
            )
            .de()?;
        chart
            .configure_mesh()
            .bold_line_style(BLACK.mix(0.12).stroke_width(1))
            .x_desc(plot.x_label)
            .y_desc(plot.y_label)
            .label_style(tick_style.clone())
            .axis_desc_style(text(m.label))
            .set_all_tick_mark_size(m.tick_len)
            .axis_style(BLACK.stroke_width(1))
            .draw()
            .de()?;

        let lw = m.line.max(1) + u32::from(m.scale > 1.5);
        let radius = ((3.5 * m.scale).round() as i32).max(3);
        let dash = ((9.0 * m.scale).round() as i32).max(5);
        let space = ((6.0 * m.scale).round() as i32).max(3);
        for (k, (series, pts)) in plot.series.iter().zip(&data).enumerate() {
            let color = rgb(series.color);
            let line = color.stroke_width(lw);
            let points = pts.iter().copied();
            match series.style {
                LineStyle::Solid => {
                    chart.draw_series(LineSeries::new(points, line)).de()?;
                }
                LineStyle::Dashed => {
                    chart
                        .draw_series(DashedLineSeries::new(points, dash, space, line))
                        .de()?;
                }
                LineStyle::Markers => {
                    chart
                        .draw_series(points.map(|p| Circle::new(p, radius, color.filled())))
                        .de()?;
                }
                LineStyle::Bars => {
                    let off = bar_offsets[k];
                    let base = 0.0f64.clamp(y0, y1);
                    chart
                        .draw_series(points.map(|(x, y)| {
                            Rectangle::new(
                                [(x + off - 0.5 * bar_w, base), (x + off + 0.5 * bar_w, y)],
                                color.filled(),
                            )
                        }))
                        .de()?;
                }
            }
        }

        // Frame around the plotting area.
        chart
            .draw_series(std::iter::once(Rectangle::new(
                [(x0, y0), (x1, y1)],
                BLACK.stroke_width(1),
            )))
            .de()?;

        if !labelled.is_empty() {
            // The plotting area's pixels are the image's; `root` draws relative to its own
            // corner, which is not the image's in a panel of [`Panels`].
            let (px, py) = {
                let (xr, yr) = chart.plotting_area().get_pixel_range();
                let (ox, oy) = root.get_base_pixel();
                (xr.start - ox..xr.end - ox, yr.start - oy..yr.end - oy)
            };
            let (bx, by) = match place {
                LegendPlace::Outside => (px.end + gap, py.start),
                LegendPlace::Corner(k) => {
                    // Horizontal: 0 left, 1 centre, 2 right; vertical: 0 top, 1 middle, 2 bottom.
                    const AT: [(u8, u8); 8] = [
                        (2, 0),
                        (0, 0),
                        (2, 2),
                        (0, 2),
                        (2, 1),
                        (0, 1),
                        (1, 0),
                        (1, 2),
                    ];
                    let (h, v) = AT[k.min(7)];
                    let x = match h {
                        0 => px.start + gap,
                        1 => (px.start + px.end - box_w) / 2,
                        _ => px.end - gap - box_w,
                    };
                    let y = match v {
                        0 => py.start + gap,
                        1 => (py.start + py.end - box_h) / 2,
                        _ => py.end - gap - box_h,
                    };
                    (x, y)
                }
            };
            root.draw(&Rectangle::new(
                [(bx, by), (bx + box_w, by + box_h)],
                WHITE.mix(0.85).filled(),
            ))
            .de()?;
            root.draw(&Rectangle::new(
                [(bx, by), (bx + box_w, by + box_h)],
                BLACK.mix(0.6).stroke_width(1),
            ))
            .de()?;
            let label_style = tick_style.pos(Pos::new(HPos::Left, VPos::Center));
            for (row, (_, s)) in labelled.iter().enumerate() {
                let y = by + pad + row as i32 * row_h + row_h / 2;
                let x = bx + pad;
                let color = rgb(s.color);
                let line = color.stroke_width(lw);
                match s.style {
                    LineStyle::Solid => {
                        root.draw(&PathElement::new(vec![(x, y), (x + sample, y)], line))
                            .de()?;
                    }
                    LineStyle::Dashed => {
                        let third = sample / 3;
                        root.draw(&PathElement::new(vec![(x, y), (x + third, y)], line))
                            .de()?;
                        root.draw(&PathElement::new(
                            vec![(x + 2 * third, y), (x + sample, y)],
                            line,
                        ))
                        .de()?;
                    }
                    LineStyle::Markers => {
                        root.draw(&Circle::new((x + sample / 2, y), radius, color.filled()))
                            .de()?;
                    }
                    LineStyle::Bars => {
                        let hh = row_h / 3;
                        root.draw(&Rectangle::new(
                            [(x + sample / 4, y - hh), (x + 3 * sample / 4, y + hh)],
                            color.filled(),
                        ))
                        .de()?;
                    }
                }
                root.draw_text(s.label, &label_style, (x + sample + pad, y))
                    .de()?;
            }
        }
        let _ = ph;
        Ok(())
    }
}

/// Where the legend of a line plot goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum LegendPlace {
    /// Inside the plot: 0 upper right, 1 upper left, 2 lower right, 3 lower left (the
    /// corners), then 4 middle right, 5 middle left, 6 upper centre, 7 lower centre.
    Corner(usize),
    /// Right of the plot area, outside it.
    Outside,
}

/// The first place in the plot (the corners upper right, upper left, lower right, lower
/// left, then the middles of the right and left sides and of the top and bottom) whose
/// legend box (its size `(fw, fh)` given as fractions of the plot, margins included) holds
/// no data, neither points nor samples along the lines; [`LegendPlace::Outside`] when every
/// place does. `series` are the styles and points in unit plot coordinates (0..1, y up).
pub(crate) fn legend_place(
    series: &[(LineStyle, Vec<(f64, f64)>)],
    (fw, fh): (f64, f64),
) -> LegendPlace {
    if fw > 0.6 || fh > 0.9 {
        return LegendPlace::Outside;
    }
    // Corners as (u range, v range) in unit plot coordinates, v upwards.
    let (mu0, mu1) = (0.5 - fw / 2.0, 0.5 + fw / 2.0);
    let (mv0, mv1) = (0.5 - fh / 2.0, 0.5 + fh / 2.0);
    let corners = [
        (1.0 - fw, 1.0, 1.0 - fh, 1.0),
        (0.0, fw, 1.0 - fh, 1.0),
        (1.0 - fw, 1.0, 0.0, fh),
        (0.0, fw, 0.0, fh),
        (1.0 - fw, 1.0, mv0, mv1),
        (0.0, fw, mv0, mv1),
        (mu0, mu1, 1.0 - fh, 1.0),
        (mu0, mu1, 0.0, fh),
    ];
    let mut counts = [0usize; 8];
    let mut add = |u: f64, v: f64| {
        for (k, c) in corners.iter().enumerate() {
            if (c.0..=c.1).contains(&u) && (c.2..=c.3).contains(&v) {
                counts[k] += 1;
            }
        }
    };
    for (style, pts) in series {
        for &(u, v) in pts {
            add(u, v);
        }
        if *style != LineStyle::Markers {
            for pair in pts.windows(2) {
                let (a, b) = (pair[0], pair[1]);
                let len = ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
                let n = ((len / 0.005).ceil() as usize).clamp(1, 400);
                for k in 1..n {
                    let t = k as f64 / n as f64;
                    add(a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
                }
            }
        }
    }
    (0..8)
        .find(|&k| counts[k] == 0)
        .map_or(LegendPlace::Outside, LegendPlace::Corner)
}

#[cfg(test)]
mod tests {
    #[test]
    fn y_from_zero_starts_the_axis_at_zero() {
        // the data's range is [0, 4600] padded by 4 % above, not [3000, 4600]
        let (a, b) = super::from_zero(3000.0, 4600.0);
        assert!(a == 0.0 && (b - 4784.0).abs() < 1e-9, "{a} {b}");
        let (a, b) = super::from_zero(-10.0, -5.0);
        assert!((a + 10.4).abs() < 1e-12 && b == 0.0, "{a} {b}");
        let (a, b) = super::from_zero(-1.0, 1.0);
        assert!(a < -1.0 && b > 1.0);
    }

    use super::*;

    #[test]
    fn legend_goes_to_a_corner_without_data_or_outside() {
        // A rising line from lower left to upper right: the upper left corner is free.
        let rising = vec![(LineStyle::Solid, vec![(0.04, 0.04), (0.96, 0.96)])];
        assert_eq!(legend_place(&rising, (0.3, 0.2)), LegendPlace::Corner(1));
        // A falling line: the upper right corner is free.
        let falling = vec![(LineStyle::Solid, vec![(0.04, 0.96), (0.96, 0.04)])];
        assert_eq!(legend_place(&falling, (0.3, 0.2)), LegendPlace::Corner(0));
        // A marker in each corner and in each middle: outside.
        let corners = vec![(
            LineStyle::Markers,
            vec![
                (0.05, 0.05),
                (0.95, 0.05),
                (0.05, 0.95),
                (0.95, 0.95),
                (0.95, 0.5),
                (0.05, 0.5),
                (0.5, 0.95),
                (0.5, 0.05),
            ],
        )];
        assert_eq!(legend_place(&corners, (0.2, 0.2)), LegendPlace::Outside);
        // A line that only passes through a corner (no point in it) still blocks it.
        let through = vec![
            (LineStyle::Dashed, vec![(0.0, 0.5), (1.0, 1.0)]),
            (LineStyle::Solid, vec![(0.0, 0.5), (1.0, 0.0)]),
            (LineStyle::Solid, vec![(0.0, 0.6), (0.5, 0.99)]),
            (LineStyle::Solid, vec![(0.0, 0.4), (0.5, 0.01)]),
            (LineStyle::Solid, vec![(0.0, 0.5), (1.0, 0.5)]),
        ];
        assert_eq!(legend_place(&through, (0.3, 0.3)), LegendPlace::Outside);
        // Data in all four corners but none in the middle of the right side: there.
        let band = vec![
            (LineStyle::Solid, vec![(0.0, 0.95), (1.0, 0.95)]),
            (LineStyle::Solid, vec![(0.0, 0.05), (1.0, 0.05)]),
        ];
        assert_eq!(legend_place(&band, (0.3, 0.3)), LegendPlace::Corner(4));
        // A legend larger than the plot's free space goes outside.
        assert_eq!(legend_place(&rising, (0.7, 0.2)), LegendPlace::Outside);
    }
}
