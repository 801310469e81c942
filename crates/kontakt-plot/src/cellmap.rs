//! The heat map of a [`CellMap`](crate::CellMap): cells over two independent axes (e.g. the
//! slices of every roller: position along the roller in mm × the roller's azimuth in
//! degrees), filling the plot area, with a colour bar and a marker at the largest value.

use std::cell::Cell;

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::colormap::viridis;
use crate::field::{draw_colorbar, draw_marker};
use crate::render::{
    DrawResultExt, Figure, Metrics, Target, desc_height, draw_line_of_text, draw_title,
    labels_width, rgb, text, text_size, title_height,
};
use crate::ticks::{TickAxis, Ticks, nice_ticks, ticks_fitting};
use crate::{CellMap, PlotError};

/// A [`CellMap`] as a drawable figure; after drawing, `frame` holds the plot area's pixel
/// ranges `(x0, x1, y0, y1)` (y downwards), for tests.
pub(crate) struct CellFigure<'a> {
    pub map: &'a CellMap<'a>,
    pub frame: Cell<Option<(i32, i32, i32, i32)>>,
}

/// The index and the centre of the cell with the largest value (the first of equal ones),
/// if any is > 0.
pub(crate) fn hottest(map: &CellMap) -> Option<(usize, (f64, f64))> {
    crate::field::argmax_positive(map.values).map(|k| {
        (
            k,
            (
                map.x_min + ((k % map.nx) as f64 + 0.5) * map.dx,
                map.y_min + ((k / map.nx) as f64 + 0.5) * map.dy,
            ),
        )
    })
}

impl Figure for &CellFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, target: &Target<DB>) -> Result<(), PlotError> {
        let map = self.map;
        let root = &target.root;
        root.fill(&WHITE).de()?;
        let (w, h) = root.dim_in_pixel();
        let (wi, hi) = (w as i32, h as i32);
        let m = Metrics::new((w, h));
        let lo = map.values.iter().copied().fold(0.0f64, f64::min);
        let mut top = map.values.iter().copied().fold(0.0f64, f64::max);
        if !(top > lo) {
            top = lo + 1.0;
        }
        let (x0, x1) = (map.x_min, map.x_min + map.nx as f64 * map.dx);
        let (y0, y1) = (map.y_min, map.y_min + map.ny as f64 * map.dy);

        let tick_style = text(m.tick);
        let desc_h = |s: &str| desc_height(s, &m);
        let tick_h = (m.tick * 1.25).round() as i32;
        let label_dist = 2 * m.tick_len;
        let title_h = title_height(map.title, &m);
        let caption_h = if map.caption.is_empty() {
            0
        } else {
            (m.tick * 1.5).round() as i32
        };
        let width_of = |t: &Ticks| labels_width(root, t, &tick_style);
        let legend_h = if map.max_marker.is_some() {
            (m.tick * 2.2).round() as i32
        } else {
            0
        };
        let top_y = m.margin + title_h + caption_h + tick_h / 2;
        let bottom = tick_h + label_dist + desc_h(map.x_label) + m.tick_len;
        let ph = (hi - top_y - bottom - legend_h - m.margin).max(20);
        let y_spacing = 1.6 * f64::from(tick_h);
        let y_ticks = ticks_fitting(y0, y1, f64::from(ph), y_spacing, 10);
        let c_ticks = ticks_fitting(lo, top, f64::from(ph), y_spacing, 6);
        let left = width_of(&y_ticks)? + label_dist + desc_h(map.y_label) + m.tick_len;
        let gap = ((0.035 * f64::from(w)).round() as i32).max(8);
        let bar_w = ((0.035 * f64::from(w)).round() as i32).max(10);
        let mut c_w = 0;
        for n in 2..=9 {
            c_w = c_w.max(width_of(&nice_ticks(lo, top, n))?);
        }
        let bar_right = label_dist + c_w + m.tick_len + desc_h(map.colorbar_label);
        let pw = (wi - 2 * m.margin - left - gap - bar_w - bar_right).max(20);
        let mut x_tick_w = 0;
        for n in 2..=10 {
            x_tick_w = x_tick_w.max(width_of(&nice_ticks(x0, x1, n))?);
        }
        let x_ticks = ticks_fitting(
            x0,
            x1,
            f64::from(pw),
            f64::from(x_tick_w) + 1.5 * m.tick,
            10,
        );

        draw_title(root, map.title, &m, m.margin)?;
        draw_line_of_text(root, map.caption, m.tick, &m, m.margin + title_h)?;
        let area = root
            .clone()
            .shrink((m.margin, top_y), (left + pw, ph + bottom));
        let mut chart = ChartBuilder::on(&area)
            .set_label_area_size(LabelAreaPosition::Left, left.max(0) as u32)
            .set_label_area_size(LabelAreaPosition::Bottom, bottom.max(0) as u32)
            .build_cartesian_2d(
                TickAxis::new(x0, x1, x_ticks.clone()),
                TickAxis::new(y0, y1, y_ticks.clone()),
            )
            .de()?;
        let color_of = |v: f64| viridis((v - lo) / (top - lo));
        chart
            .draw_series(map.values.iter().enumerate().filter_map(|(k, &v)| {
                if v == 0.0 {
                    return None;
                }
                let (i, j) = ((k % map.nx) as f64, (k / map.nx) as f64);
                let (cx0, cy0) = (map.x_min + i * map.dx, map.y_min + j * map.dy);
                Some(Rectangle::new(
                    [(cx0, cy0), (cx0 + map.dx, cy0 + map.dy)],
                    rgb(color_of(v)).filled(),
                ))
            }))
            .de()?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(map.x_label)
            .y_desc(map.y_label)
            .label_style(tick_style.clone())
            .axis_desc_style(text(m.label))
            .set_all_tick_mark_size(m.tick_len)
            .axis_style(BLACK.stroke_width(1))
            .draw()
            .de()?;
        chart
            .draw_series(std::iter::once(Rectangle::new(
                [(x0, y0), (x1, y1)],
                BLACK.stroke_width(1),
            )))
            .de()?;
        let (xr, yr) = chart.plotting_area().get_pixel_range();
        self.frame.set(Some((xr.start, xr.end, yr.start, yr.end)));
        draw_colorbar(
            root,
            (xr.end + gap, yr.start, bar_w, yr.end - yr.start, bar_right),
            (lo, top),
            &c_ticks,
            map.colorbar_label,
            &m,
        )?;
        if let (Some(label), Some((_, at))) = (map.max_marker, hottest(map)) {
            let p = chart.backend_coord(&at);
            draw_marker(root, p, &m)?;
            let y = yr.end + bottom + (m.tick * 1.1).round() as i32;
            let sample = (2.5 * m.tick).round() as i32;
            let pad = (0.5 * m.tick).round() as i32;
            let tw = text_size(root, label, &tick_style)?.0;
            let x = ((wi - sample - pad - tw) / 2).max(m.margin);
            draw_marker(root, (x + sample / 2, y), &m)?;
            let style = tick_style.pos(Pos::new(HPos::Left, VPos::Center));
            root.draw_text(label, &style, (x + sample + pad, y)).de()?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    /// The hottest cell is drawn where it belongs in the image's pixel frame: x to the
    /// right, y upwards (row 0 at the bottom), and the marker sits on it.
    #[test]
    fn the_hottest_cell_is_drawn_at_its_place() {
        let (nx, ny) = (31, 16);
        let (hi, hj) = (27, 11); // near the right end, in the upper part
        let values: Vec<f64> = (0..nx * ny)
            .map(|k| {
                let (i, j) = (k % nx, k / nx);
                if (i, j) == (hi, hj) {
                    500.0
                } else if j < 3 {
                    0.0 // lifted off: white
                } else {
                    100.0 + i as f64
                }
            })
            .collect();
        let map = CellMap {
            nx,
            ny,
            x_min: -6.0,
            y_min: -180.0,
            dx: 12.0 / nx as f64,
            dy: 360.0 / ny as f64,
            values: &values,
            title: "slices",
            caption: "",
            x_label: "position along the roller [mm]",
            y_label: "azimuth ψ [deg]",
            colorbar_label: "load per length [N/mm]",
            max_marker: Some("largest 500 N/mm"),
        };
        assert_eq!(hottest(&map).unwrap().0, hj * nx + hi);
        let dir = std::env::temp_dir().join(format!("kontakt-cellmap-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("map.png");
        let fig = CellFigure {
            map: &map,
            frame: Cell::new(None),
        };
        crate::render::render(&path, crate::Format::Png, (900, 650), &fig).unwrap();
        let (fx0, fx1, fy0, fy1) = fig.frame.get().unwrap();
        let img = image::open(&path).unwrap().to_rgb8();
        let top = viridis(1.0);
        let (mut n, mut sx, mut sy) = (0.0, 0.0, 0.0);
        for (x, y, p) in img.enumerate_pixels() {
            let (x, y) = (x as i32, y as i32);
            if x > fx0 && x < fx1 && y > fy0 && y < fy1 && (p[0], p[1], p[2]) == top {
                n += 1.0;
                sx += f64::from(x);
                sy += f64::from(y);
            }
        }
        assert!(n > 20.0, "{n} pixels of the top colour in the map");
        let (cx, cy) = (sx / n, sy / n);
        let ex = f64::from(fx0) + (hi as f64 + 0.5) / nx as f64 * f64::from(fx1 - fx0);
        let ey = f64::from(fy1) - (hj as f64 + 0.5) / ny as f64 * f64::from(fy1 - fy0);
        let cell_w = f64::from(fx1 - fx0) / nx as f64;
        let cell_h = f64::from(fy1 - fy0) / ny as f64;
        assert!(
            (cx - ex).abs() < 0.5 * cell_w && (cy - ey).abs() < 0.5 * cell_h,
            "hottest cell drawn at ({cx:.0}, {cy:.0}) px, belongs at ({ex:.0}, {ey:.0})"
        );
        // the lifted-off rows (the bottom three) are white
        let (x, y) = (
            ((fx0 + fx1) / 2) as u32,
            (f64::from(fy1) - 1.5 * cell_h) as u32,
        );
        assert_eq!(img.get_pixel(x, y).0, [255, 255, 255]);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
