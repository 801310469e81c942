//! Line plots.

use plotters::prelude::*;

use crate::render::{
    DrawResultExt, Figure, Metrics, Target, draw_title, rgb, text, text_size, title_height,
};
use crate::ticks::{TickAxis, Ticks, nice_ticks, ticks_fitting};
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

impl Figure for LineFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, target: &Target<DB>) -> Result<(), PlotError> {
        let plot = self.0;
        let root = &target.root;
        root.fill(&WHITE).de()?;
        let (w, h) = root.dim_in_pixel();
        let (wi, hi) = (w as i32, h as i32);
        let m = Metrics::new((w, h));

        let all = || plot.series.iter().flat_map(|s| s.points.iter().copied());
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for (x, y) in all() {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        let (x0, x1) = padded(x0, x1);
        let (y0, y1) = padded(y0, y1);
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
        let desc_h = |s: &str| {
            if s.is_empty() {
                0
            } else {
                (m.label * 1.35).round() as i32
            }
        };
        let tick_h = (m.tick * 1.25).round() as i32;
        let label_dist = 2 * m.tick_len;
        let width_of = |t: &Ticks| -> Result<i32, PlotError> {
            let mut wmax = 0;
            for s in t.labels() {
                wmax = wmax.max(text_size(root, &s, &tick_style)?.0);
            }
            Ok(wmax)
        };
        // Widest x tick labels over the tick sets we may end up using.
        let mut x_tick_w = 0;
        for n in 2..=13 {
            let t = nice_ticks(x0, x1, n);
            if t.values.len() <= 10 {
                x_tick_w = x_tick_w.max(width_of(&t)?);
            }
        }

        let bottom = tick_h + label_dist + desc_h(plot.x_label) + m.tick_len;
        let right = m.margin.max(x_tick_w / 2 + 2);
        let top = title_bottom + tick_h / 2;
        let area_w = (wi - m.margin - right).max(20);
        let area_h = (hi - top - m.margin).max(20);
        let ph = (area_h - bottom).max(2);
        let y_ticks = ticks_fitting(y0, y1, f64::from(ph), 1.6 * f64::from(tick_h), 10);
        let left = width_of(&y_ticks)? + label_dist + desc_h(plot.y_label) + m.tick_len;
        let pw = (area_w - left).max(2);
        let x_spacing = f64::from(x_tick_w) + 1.5 * m.tick;
        let x_ticks = ticks_fitting(x0, x1, f64::from(pw), x_spacing, 10);

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
        let sample = (2.5 * m.tick).round() as i32;
        for series in plot.series {
            let color = rgb(series.color);
            let line = color.stroke_width(lw);
            let fill = color.filled();
            let points = series.points.iter().copied();
            let anno = match series.style {
                LineStyle::Solid => {
                    let anno = chart.draw_series(LineSeries::new(points, line)).de()?;
                    if !series.label.is_empty() {
                        anno.label(series.label).legend(move |(x, y)| {
                            PathElement::new(vec![(x, y), (x + sample, y)], line)
                        });
                    }
                    continue;
                }
                LineStyle::Dashed => chart
                    .draw_series(DashedLineSeries::new(points, dash, space, line))
                    .de()?,
                LineStyle::Markers => chart
                    .draw_series(points.map(|p| Circle::new(p, radius, fill)))
                    .de()?,
            };
            if series.label.is_empty() {
                continue;
            }
            let third = sample / 3;
            match series.style {
                LineStyle::Markers => {
                    anno.label(series.label)
                        .legend(move |(x, y)| Circle::new((x + sample / 2, y), radius, fill));
                }
                _ => {
                    anno.label(series.label).legend(move |(x, y)| {
                        EmptyElement::at((x, y))
                            + PathElement::new(vec![(0, 0), (third, 0)], line)
                            + PathElement::new(vec![(2 * third, 0), (sample, 0)], line)
                    });
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

        if plot.series.iter().any(|s| !s.label.is_empty()) {
            let mut label_w = 0;
            let mut rows = 0;
            for s in plot.series.iter().filter(|s| !s.label.is_empty()) {
                label_w = label_w.max(text_size(root, s.label, &tick_style)?.0);
                rows += 1;
            }
            let box_w = f64::from(label_w + sample + 3 * m.tick_len + 10);
            let box_h = f64::from(rows) * m.tick * 1.4 + 10.0;
            let corner = legend_corner(
                plot.series,
                (x0, x1, y0, y1),
                (box_w / f64::from(pw), box_h / f64::from(ph)),
            );
            chart
                .configure_series_labels()
                .position(corner)
                .margin(m.tick_len.max(0) as u32 * 2)
                .legend_area_size(sample + m.tick_len)
                .label_font(tick_style.clone())
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK.mix(0.6).stroke_width(1))
                .draw()
                .de()?;
        }
        Ok(())
    }
}

/// The corner of the plot whose legend box (given as fractions of the plot size) covers the
/// fewest data: points, and samples along the lines.
fn legend_corner(
    series: &[Series],
    (x0, x1, y0, y1): (f64, f64, f64, f64),
    (fw, fh): (f64, f64),
) -> SeriesLabelPosition {
    let (fw, fh) = (fw.min(1.0) + 0.03, fh.min(1.0) + 0.03);
    // Corners as (u range, v range) in unit plot coordinates, v upwards.
    let corners = [
        (
            SeriesLabelPosition::UpperRight,
            1.0 - fw,
            1.0,
            1.0 - fh,
            1.0,
        ),
        (SeriesLabelPosition::UpperLeft, 0.0, fw, 1.0 - fh, 1.0),
        (SeriesLabelPosition::LowerRight, 1.0 - fw, 1.0, 0.0, fh),
        (SeriesLabelPosition::LowerLeft, 0.0, fw, 0.0, fh),
    ];
    let mut counts = [0usize; 4];
    let mut add = |u: f64, v: f64| {
        for (k, c) in corners.iter().enumerate() {
            if (c.1..=c.2).contains(&u) && (c.3..=c.4).contains(&v) {
                counts[k] += 1;
            }
        }
    };
    let unit = |(x, y): (f64, f64)| ((x - x0) / (x1 - x0), (y - y0) / (y1 - y0));
    for s in series {
        let pts: Vec<(f64, f64)> = s.points.iter().map(|&p| unit(p)).collect();
        for &(u, v) in &pts {
            add(u, v);
        }
        if s.style != LineStyle::Markers {
            for pair in pts.windows(2) {
                let (a, b) = (pair[0], pair[1]);
                let len = ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
                let n = ((len / 0.02).ceil() as usize).min(50);
                for k in 1..n {
                    let t = k as f64 / n as f64;
                    add(a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
                }
            }
        }
    }
    let best = (0..4).min_by_key(|&k| counts[k]).unwrap_or(0);
    corners[best].0.clone()
}
