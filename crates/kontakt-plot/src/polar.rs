//! The polar diagram of a [`PolarPlot`](crate::PolarPlot): values at angles drawn as spokes
//! around a ring (e.g. the loads of a bearing's rolling elements at their azimuths).

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::render::{
    DrawResultExt, Figure, Metrics, Target, draw_line_of_text, draw_title, rgb, text, text_size,
    title_height,
};
use crate::ticks::{Ticks, nice_ticks};
use crate::{PlotError, PolarPlot};

/// Radius of the zero circle as a fraction of the outer circle's: the spokes start there, so
/// that an unloaded element still shows as a dot on it.
pub(crate) const ZERO_FRACTION: f64 = 0.3;

/// Grey of the grid lines and the labels of the angle ticks.
const GRID: RGBColor = RGBColor(200, 200, 200);
/// Grey of the zero circle and of an element without a value.
const ZERO: RGBColor = RGBColor(110, 110, 110);

/// Where the diagram sits in the image: its centre and the radii of the zero and outer
/// circles, in pixels (y downwards), and the radial ticks (the last one on the outer circle).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PolarLayout {
    pub centre: (f64, f64),
    pub zero_radius: f64,
    pub outer_radius: f64,
    pub ticks: Ticks,
    /// Top of the legend block, pixels.
    pub legend_top: i32,
}

impl PolarLayout {
    /// The value on the outer circle.
    pub fn top(&self) -> f64 {
        self.ticks.values.last().copied().unwrap_or(1.0)
    }

    /// The pixel of `value` at `angle_deg` (counter-clockwise from the right, as on paper).
    pub fn pixel(&self, angle_deg: f64, value: f64) -> (f64, f64) {
        let r = self.radius(value);
        let (s, c) = angle_deg.to_radians().sin_cos();
        (self.centre.0 + r * c, self.centre.1 - r * s)
    }

    /// The radius of `value` in pixels: the zero circle for 0, the outer circle for the top.
    pub fn radius(&self, value: f64) -> f64 {
        self.zero_radius + (self.outer_radius - self.zero_radius) * value / self.top()
    }
}

/// Radial ticks from 0 to a round value at or above `max` (at most 6 of them).
fn radial_ticks(max: f64) -> Ticks {
    let max = if max > 0.0 { max } else { 1.0 };
    let mut t = nice_ticks(0.0, max, 5);
    let step = match t.values[..] {
        [a, b, ..] => b - a,
        _ => max,
    };
    while t.values.last().is_none_or(|&v| v < max * (1.0 - 1e-9)) {
        let next = t.values.last().map_or(step, |v| v + step);
        t.values.push(next);
    }
    t
}

/// The number of legend rows of `plot`.
fn legend_rows(plot: &PolarPlot) -> i32 {
    1 + i32::from(plot.arrow.is_some()) + i32::from(plot.sector.is_some())
}

/// The layout of `plot` in an image of `size` pixels: title and caption on top, the legend
/// (one entry a row) at the bottom, the disc as large as fits between them with room for
/// the angle labels around it.
pub(crate) fn layout(plot: &PolarPlot, (w, h): (u32, u32)) -> PolarLayout {
    let m = Metrics::new((w, h));
    let (wf, hf) = (f64::from(w), f64::from(h));
    let head = f64::from(m.margin + title_height(plot.title, &m)) + caption_height(plot, &m);
    let row = (m.tick * 1.5).round();
    let legend_h = row * f64::from(legend_rows(plot)) + m.tick * 0.5;
    let rim = 2.6 * m.tick + f64::from(m.tick_len);
    let avail_h = (hf - head - legend_h - f64::from(m.margin) - 2.0 * rim).max(20.0);
    let avail_w = (wf - 2.0 * f64::from(m.margin) - 2.0 * rim).max(20.0);
    let outer = (avail_h.min(avail_w) / 2.0).floor();
    let centre = ((wf / 2.0).round(), (head + rim + outer).round());
    let max = plot.points.iter().map(|p| p.1).fold(0.0, f64::max);
    PolarLayout {
        centre,
        zero_radius: (ZERO_FRACTION * outer).round(),
        outer_radius: outer,
        ticks: radial_ticks(max),
        legend_top: (centre.1 + outer + rim) as i32,
    }
}

fn caption_height(plot: &PolarPlot, m: &Metrics) -> f64 {
    if plot.caption.is_empty() {
        0.0
    } else {
        (m.tick * 1.5).round()
    }
}

/// A [`PolarPlot`] as a drawable figure.
pub(crate) struct PolarFigure<'a>(pub &'a PolarPlot<'a>);

/// A closed polygon of the annulus sector between radii `r0` and `r1` (pixels) over
/// `[a0, a1]` degrees around `c`.
fn sector_polygon(c: (f64, f64), r0: f64, r1: f64, a0: f64, a1: f64) -> Vec<(i32, i32)> {
    let n = (((a1 - a0).abs() / 2.0).ceil() as usize).max(2);
    let at = |r: f64, a: f64| {
        let (s, co) = a.to_radians().sin_cos();
        ((c.0 + r * co).round() as i32, (c.1 - r * s).round() as i32)
    };
    let mut pts: Vec<(i32, i32)> = (0..=n)
        .map(|k| at(r1, a0 + (a1 - a0) * k as f64 / n as f64))
        .collect();
    pts.extend(
        (0..=n)
            .rev()
            .map(|k| at(r0, a0 + (a1 - a0) * k as f64 / n as f64)),
    );
    pts
}

/// A circle of radius `r` around `c` as a closed path.
fn circle_path(c: (f64, f64), r: f64) -> Vec<(i32, i32)> {
    sector_polygon(c, r, r, 0.0, 360.0)
        .into_iter()
        .take(181)
        .collect()
}

/// `color` mixed with white: `amount` 0 white, 1 the colour (a light tint without alpha, so
/// that PNG and SVG agree).
fn tint((r, g, b): (u8, u8, u8), amount: f64) -> RGBColor {
    let mix = |c: u8| (255.0 - amount * (255.0 - f64::from(c))).round() as u8;
    RGBColor(mix(r), mix(g), mix(b))
}

/// The angle of the ray that carries the radial tick labels: halfway between two
/// neighbouring points (so that no spoke runs under the labels), on the half away from the
/// largest value, the most nearly vertical such ray (the labels, written horizontally,
/// then stack without touching each other or the angle labels at the rim).
fn label_ray(points: &[(f64, f64)]) -> f64 {
    let (a_max, _) = points
        .iter()
        .copied()
        .fold((0.0, f64::MIN), |b, p| if p.1 > b.1 { p } else { b });
    let mut angles: Vec<f64> = points.iter().map(|p| p.0.rem_euclid(360.0)).collect();
    angles.sort_by(f64::total_cmp);
    angles.dedup();
    let from_max = |a: f64| {
        let d = (a - a_max).rem_euclid(360.0);
        d.min(360.0 - d)
    };
    let mids: Vec<f64> = if angles.len() < 2 {
        (0..12).map(|k| 15.0 + 30.0 * f64::from(k)).collect()
    } else {
        (0..angles.len())
            .map(|k| {
                let next = angles.get(k + 1).copied().unwrap_or(angles[0] + 360.0);
                0.5 * (angles[k] + next)
            })
            .collect()
    };
    // away from the maximum first, then as vertical as possible
    let score = |a: f64| {
        let back = if from_max(a) >= 90.0 { 1.0 } else { 0.0 };
        let below = if a.to_radians().sin() < 0.0 {
            1e-4
        } else {
            0.0
        };
        2.0 * back + a.to_radians().sin().abs() + 1e-3 * from_max(a) / 180.0 + below
    };
    mids.iter()
        .copied()
        .fold((f64::MIN, 0.0), |b, a| {
            if score(a) > b.0 { (score(a), a) } else { b }
        })
        .1
}

/// The label of an angle tick in (-180, 180] degrees.
fn angle_label(a: f64) -> String {
    let a = (a + 180.0).rem_euclid(360.0) - 180.0;
    let a = if a <= -180.0 + 1e-9 { 180.0 } else { a };
    format!("{}°", crate::ticks::format_fixed(a, 0))
}

impl Figure for PolarFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, target: &Target<DB>) -> Result<(), PlotError> {
        let plot = self.0;
        let root = &target.root;
        root.fill(&WHITE).de()?;
        let (w, h) = root.dim_in_pixel();
        let m = Metrics::new((w, h));
        let l = layout(plot, (w, h));
        let c = l.centre;
        let px = |p: (f64, f64)| (p.0.round() as i32, p.1.round() as i32);
        let lw = m.line.max(1);

        draw_title(root, plot.title, &m, m.margin)?;
        draw_line_of_text(
            root,
            plot.caption,
            m.tick,
            &m,
            m.margin + title_height(plot.title, &m),
        )?;

        // The shaded sector (e.g. the loaded arc) under everything else.
        if let Some(s) = &plot.sector {
            let (a0, a1) = (
                s.centre_deg - s.half_width_deg,
                s.centre_deg + s.half_width_deg,
            );
            let poly = sector_polygon(c, l.zero_radius, l.outer_radius, a0, a1);
            root.draw(&Polygon::new(poly, tint(s.color, 0.22).filled()))
                .de()?;
        }

        // Grid: circles at the radial ticks, rays every 30°, labels around the rim.
        for &v in &l.ticks.values {
            if v > 0.0 {
                let style = GRID.stroke_width(1);
                root.draw(&PathElement::new(circle_path(c, l.radius(v)), style))
                    .de()?;
            }
        }
        for k in 0..12 {
            let a = f64::from(k) * 30.0;
            let inner = l.pixel(a, 0.0);
            let outer = l.pixel(a, l.top());
            root.draw(&PathElement::new(
                vec![px(inner), px(outer)],
                GRID.stroke_width(1),
            ))
            .de()?;
            let (s, co) = a.to_radians().sin_cos();
            let r = l.outer_radius + f64::from(m.tick_len) + 1.3 * m.tick;
            let at = px((c.0 + r * co, c.1 - r * s));
            let style = text(m.tick).pos(Pos::new(HPos::Center, VPos::Center));
            root.draw_text(&angle_label(a), &style, at).de()?;
        }
        // The zero circle: the ring the spokes stand on.
        root.draw(&PathElement::new(
            circle_path(c, l.zero_radius),
            ZERO.stroke_width(lw),
        ))
        .de()?;

        // The spokes, the envelope through their tips, and a dot at each tip.
        let color = rgb(plot.color);
        let spoke_w = (3.0 * m.scale).round().max(2.0) as u32;
        let dot = ((3.5 * m.scale).round() as i32).max(3);
        let mut order: Vec<(f64, f64)> = plot.points.to_vec();
        order.sort_by(|a, b| a.0.rem_euclid(360.0).total_cmp(&b.0.rem_euclid(360.0)));
        if order.len() > 2 {
            let mut env: Vec<(i32, i32)> = order.iter().map(|&(a, v)| px(l.pixel(a, v))).collect();
            env.push(env[0]);
            root.draw(&PathElement::new(
                env,
                tint(plot.color, 0.55).stroke_width(1),
            ))
            .de()?;
        }
        for &(a, v) in &order {
            let base = px(l.pixel(a, 0.0));
            if v > 0.0 {
                let tip = px(l.pixel(a, v));
                root.draw(&PathElement::new(
                    vec![base, tip],
                    color.stroke_width(spoke_w),
                ))
                .de()?;
                root.draw(&Circle::new(tip, dot, color.filled())).de()?;
            } else {
                root.draw(&Circle::new(base, dot, WHITE.filled())).de()?;
                root.draw(&Circle::new(base, dot, ZERO.stroke_width(1)))
                    .de()?;
            }
        }

        // The radial scale along a ray without spokes, on white boxes.
        let ray = label_ray(plot.points);
        let label_style = text(m.tick * 0.9).pos(Pos::new(HPos::Center, VPos::Center));
        for (k, label) in l.ticks.labels().iter().enumerate() {
            let v = l.ticks.values[k];
            let at = px(l.pixel(ray, v));
            let (tw, th) = text_size(root, label, &label_style)?;
            let pad = 2;
            root.draw(&Rectangle::new(
                [
                    (at.0 - tw / 2 - pad, at.1 - th / 2 - pad),
                    (at.0 + tw / 2 + pad, at.1 + th / 2 + pad),
                ],
                WHITE.mix(0.9).filled(),
            ))
            .de()?;
            root.draw_text(label, &label_style, at).de()?;
        }

        // The arrow of the load direction, inside the zero circle.
        if let Some(arrow) = &plot.arrow {
            draw_arrow(root, c, 0.85 * l.zero_radius, arrow.angle_deg, &m)?;
        }

        // Legend, one entry a row, left-aligned in the middle.
        let row = (m.tick * 1.5).round() as i32;
        let sample = (2.5 * m.tick).round() as i32;
        let pad = (0.5 * m.tick).round() as i32;
        let style = text(m.tick).pos(Pos::new(HPos::Left, VPos::Center));
        let mut entries: Vec<(u8, &str)> = vec![(0, plot.label)];
        if let Some(s) = &plot.sector {
            entries.push((1, s.label));
        }
        if let Some(a) = &plot.arrow {
            entries.push((2, a.label));
        }
        let mut widest = 0;
        for (_, label) in &entries {
            widest = widest.max(text_size(root, label, &text(m.tick))?.0);
        }
        let x = ((w as i32 - sample - pad - widest) / 2).max(m.margin);
        for (k, (kind, label)) in entries.iter().enumerate() {
            let y = l.legend_top + (m.tick * 0.5).round() as i32 + k as i32 * row + row / 2;
            match kind {
                0 => {
                    root.draw(&PathElement::new(
                        vec![(x, y), (x + sample - dot, y)],
                        color.stroke_width(spoke_w),
                    ))
                    .de()?;
                    root.draw(&Circle::new((x + sample - dot, y), dot, color.filled()))
                        .de()?;
                }
                1 => {
                    let color = plot.sector.as_ref().map_or((0, 0, 0), |s| s.color);
                    root.draw(&Rectangle::new(
                        [(x, y - row / 3), (x + sample, y + row / 3)],
                        tint(color, 0.22).filled(),
                    ))
                    .de()?;
                }
                _ => {
                    let r = f64::from(sample) / 2.0;
                    let centre = (f64::from(x) + r, f64::from(y));
                    let mut small = m;
                    small.scale = m.scale.min(1.0);
                    draw_arrow(root, (centre.0 - r, centre.1), 2.0 * r, 0.0, &small)?;
                }
            }
            root.draw_text(label, &style, (x + sample + pad, y)).de()?;
        }
        Ok(())
    }
}

/// A black arrow from `from` of `length` pixels toward `angle_deg`.
fn draw_arrow<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    from: (f64, f64),
    length: f64,
    angle_deg: f64,
    m: &Metrics,
) -> Result<(), PlotError> {
    let (s, c) = angle_deg.to_radians().sin_cos();
    let tip = (from.0 + length * c, from.1 - length * s);
    let px = |p: (f64, f64)| (p.0.round() as i32, p.1.round() as i32);
    let head = (0.3 * length).min(14.0 * m.scale.max(0.6));
    let width = 0.45 * head;
    let back = (tip.0 - head * c, tip.1 + head * s);
    let left = (back.0 - width * s, back.1 - width * c);
    let right = (back.0 + width * s, back.1 + width * c);
    let lw = (2.5 * m.scale).round().max(2.0) as u32;
    root.draw(&PathElement::new(
        vec![px(from), px(back)],
        BLACK.stroke_width(lw),
    ))
    .de()?;
    root.draw(&Polygon::new(
        vec![px(tip), px(left), px(right)],
        BLACK.filled(),
    ))
    .de()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::{PolarArrow, PolarSector};

    #[test]
    fn radial_ticks_reach_the_largest_value() {
        let t = radial_ticks(5131.8);
        assert_eq!(t.values.first(), Some(&0.0));
        let top = *t.values.last().unwrap();
        assert!((5131.8..=7000.0).contains(&top), "{:?}", t.values);
        let t = radial_ticks(0.0);
        assert!(*t.values.last().unwrap() >= 1.0);
    }

    #[test]
    fn angle_labels_run_from_minus_150_to_180() {
        assert_eq!(angle_label(0.0), "0°");
        assert_eq!(angle_label(180.0), "180°");
        assert_eq!(angle_label(210.0), "-150°");
        assert_eq!(angle_label(330.0), "-30°");
    }

    #[test]
    fn the_scale_ray_lies_between_spokes_opposite_the_maximum() {
        let mut pts: Vec<(f64, f64)> = (0..12).map(|k| (30.0 * f64::from(k), 1.0)).collect();
        pts[2].1 = 9.0; // maximum at 60°: the labels on the far side, near vertical, at 255°
        assert_eq!(label_ray(&pts), 255.0);
        // 9 balls, the largest at 0°: not on the 180° ray (the rim's label is there), but
        // at 260°, between the balls at 240° and 280°
        let pts: Vec<(f64, f64)> = (0..9)
            .map(|k| (40.0 * f64::from(k), if k == 0 { 5.0 } else { 1.0 }))
            .collect();
        assert_eq!(label_ray(&pts), 260.0);
    }

    /// The picture is right in the image's own pixel frame: the spoke pixel farthest from
    /// the centre lies at the largest value's angle, counter-clockwise from the right (y
    /// up on the page, down in pixels), at that value's radius; the sector is tinted on
    /// its side only.
    #[test]
    fn the_longest_spoke_points_at_the_largest_value() {
        let dir = std::env::temp_dir().join(format!("kontakt-polar-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("polar.png");
        // 15 elements; the largest at 72°, its neighbours smaller, the far side empty
        let pts: Vec<(f64, f64)> = (0..15)
            .map(|k| {
                let a = 24.0 * f64::from(k);
                let d = ((a - 72.0 + 180.0).rem_euclid(360.0) - 180.0).abs();
                (a, (4000.0 * (1.0 - d / 100.0)).max(0.0))
            })
            .collect();
        let sector_color = (44, 160, 44);
        let plot = PolarPlot {
            title: "test",
            caption: "radius: load [N]",
            points: &pts,
            label: "element load [N]",
            color: (31, 119, 180),
            arrow: Some(PolarArrow {
                angle_deg: 72.0,
                label: "load direction",
            }),
            sector: Some(PolarSector {
                centre_deg: 72.0,
                half_width_deg: 100.0,
                label: "loaded arc",
                color: sector_color,
            }),
        };
        let size = (800, 800);
        crate::polar_plot(&path, &plot, size).unwrap();
        let img = image::open(&path).unwrap().to_rgb8();
        let l = layout(&plot, size);
        let near = |p: &image::Rgb<u8>, c: (u8, u8, u8)| {
            (i32::from(p[0]) - i32::from(c.0)).abs() <= 6
                && (i32::from(p[1]) - i32::from(c.1)).abs() <= 6
                && (i32::from(p[2]) - i32::from(c.2)).abs() <= 6
        };
        let mut far = (0.0, 0.0, 0.0);
        for (x, y, p) in img.enumerate_pixels() {
            if near(p, plot.color) && y < l.legend_top as u32 {
                let (dx, dy) = (f64::from(x) - l.centre.0, l.centre.1 - f64::from(y));
                let r = dx.hypot(dy);
                if r > far.0 {
                    far = (r, dx, dy);
                }
            }
        }
        let angle = far.2.atan2(far.1).to_degrees();
        assert!(
            (angle - 72.0).abs() < 2.0,
            "farthest spoke pixel at {angle}°"
        );
        let r_expected = l.radius(4000.0);
        assert!(
            (far.0 - r_expected).abs() < 6.0,
            "farthest spoke pixel at r = {} px, the value's radius is {r_expected} px",
            far.0
        );
        // the tint lies around 72°, not around -72° (a flipped y axis)
        let tinted = |a: f64| {
            let (x, y) = l.pixel(a, 0.85 * l.top());
            let p = img.get_pixel(x as u32, y as u32);
            near(p, {
                let t = tint(sector_color, 0.22);
                (t.0, t.1, t.2)
            })
        };
        assert!(tinted(72.0 + 36.0) && tinted(72.0 - 36.0));
        assert!(!tinted(-72.0 + 36.0) && !tinted(252.0));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
