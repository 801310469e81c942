//! The pictures of a whole bearing (`kontakt bearing --plot/--element-plot/--slice-plot/--map`
//! and the demo): the load distribution as a polar diagram, every element's load (and rib
//! load or contact angle) as bars, a per-slice quantity along the most loaded roller, and
//! that quantity over every roller's slices as a map. The data of each picture is built by
//! a function of its own, so that the tests check what is drawn; the drawing is
//! kontakt-plot's.
//!
//! Azimuths ψ run from x toward y (degrees), as in the report; the polar diagram draws x to
//! the right and y up.

use anyhow::{Context, Result};
use kontakt_case::BearingReport;
use kontakt_case::bearing_case::{BearingElements, RollerPart};
use kontakt_plot::{
    CellMap, LinePlot, LineStyle, PALETTE, PolarArrow, PolarPlot, PolarSector, Series,
};
use std::path::Path;

/// Colour of the raceway (element) load, on every bearing picture.
const LOAD_COLOR: (u8, u8, u8) = PALETTE[0];
/// Colour of the rib load.
const RIB_COLOR: (u8, u8, u8) = PALETTE[1];
/// Colour of the contact angle.
const ANGLE_COLOR: (u8, u8, u8) = PALETTE[2];
/// Colour of the loaded arc's tint.
const ARC_COLOR: (u8, u8, u8) = PALETTE[2];
/// Colour of a reference line (the mean load per length, the free contact angle).
const REFERENCE_COLOR: (u8, u8, u8) = PALETTE[7];
/// Colour of the roller's ends on the slice plot.
const END_COLOR: (u8, u8, u8) = (0, 0, 0);

/// A quantity given per slice of every roller, with its name and unit: what the slice plot
/// and the map draw. Today the load per length; a per-slice pressure is one more
/// constructor.
#[derive(Debug, Clone, Copy)]
pub struct SliceQuantity<'a> {
    /// Its name, e.g. `"load per length"`.
    pub name: &'a str,
    /// Its unit, e.g. `"N/mm"`.
    pub unit: &'a str,
    /// Slice centres along the roller, mm (toward the small end of a tapered roller).
    pub position_mm: &'a [f64],
    /// The value of every slice of every roller: one row per roller, in the order of the
    /// report's `roller_loads`.
    pub every_roller: &'a [Vec<f64>],
    /// The roller whose slices the slice plot draws (the most loaded one).
    pub roller: usize,
}

impl<'a> SliceQuantity<'a> {
    /// The load per unit length of every slice, N/mm.
    pub fn load_per_length(p: &'a RollerPart) -> Self {
        SliceQuantity {
            name: "load per length",
            unit: "N/mm",
            position_mm: &p.most_loaded_roller.position_mm,
            every_roller: &p.slice_load_per_length_n_per_mm,
            roller: p.most_loaded_roller.roller,
        }
    }

    /// `"load per length [N/mm]"`.
    fn label(&self) -> String {
        format!("{} [{}]", self.name, self.unit)
    }
}

/// The quantity the slice plot and the map of a roller bearing draw.
fn slice_quantity(p: &RollerPart) -> SliceQuantity<'_> {
    SliceQuantity::load_per_length(p)
}

/// The rollers of `r`, or an input error naming `flag` for a ball bearing (it has no slices).
fn rollers_of<'a>(r: &'a BearingReport, flag: &str) -> Result<&'a RollerPart> {
    r.rollers().ok_or_else(|| {
        crate::commands::InputError(format!(
            "{flag}: a ball bearing has no slices (use --plot for the ball loads)"
        ))
        .into()
    })
}

/// The index and value of the largest of `values` (the first of equal ones).
fn largest(values: impl Iterator<Item = f64>) -> (usize, f64) {
    values
        .enumerate()
        .fold((0, f64::MIN), |b, (k, v)| if v > b.1 { (k, v) } else { b })
}

/// The bearing's name for titles.
fn bearing_name(r: &BearingReport) -> String {
    r.name
        .clone()
        .unwrap_or_else(|| format!("{} bearing", r.bearing_type.replace('_', " ")))
}

/// Check the format of a plot file before anything is drawn (an input error naming it).
fn check_format(path: &Path) -> Result<()> {
    kontakt_plot::Format::from_path(path)
        .map_err(|e| crate::commands::InputError(e.to_string()))?;
    Ok(())
}

/// (azimuth deg, load N) of every element: the outer raceway load of a roller, a ball's load.
fn element_loads(r: &BearingReport) -> Vec<(f64, f64)> {
    match &r.elements {
        BearingElements::Rollers(p) => p
            .roller_loads
            .iter()
            .map(|w| (w.azimuth_deg, w.outer_load_n))
            .collect(),
        BearingElements::Balls(p) => p
            .ball_loads
            .iter()
            .map(|w| (w.azimuth_deg, w.load_n))
            .collect(),
    }
}

/// `"roller"` or `"ball"`.
fn noun(r: &BearingReport) -> &'static str {
    match r.elements {
        BearingElements::Rollers(_) => "roller",
        BearingElements::Balls(_) => "ball",
    }
}

/// The data of the polar diagram: the elements' loads at their azimuths, the direction of
/// the radial load (none without one) and the loaded arc from ε around the direction of
/// the radial displacement (none without ε).
#[derive(Debug, Clone, PartialEq)]
pub struct PolarData {
    /// (azimuth deg, load N) per element (negative loads, which the model does not give,
    /// shown as 0).
    pub points: Vec<(f64, f64)>,
    /// Legend of the spokes, with the largest load and its azimuth.
    pub label: String,
    /// Direction of the radial load, deg, and its legend.
    pub arrow: Option<(f64, String)>,
    /// (centre deg, half width deg, legend) of the loaded arc.
    pub arc: Option<(f64, f64, String)>,
}

/// The half width of the loaded arc, degrees, from Sjövall's load-zone parameter ε: the
/// elements at `|ψ − ψ_r| < ψ_l` carry load, with `cos ψ_l = 1 − 2ε` (rigid rings, no tilt;
/// `ψ_r` the direction of the radial displacement); 180° (the whole ring) from ε = 1 up.
pub fn loaded_arc_half_width_deg(epsilon: f64) -> f64 {
    if epsilon >= 1.0 {
        180.0
    } else if epsilon <= 0.0 {
        0.0
    } else {
        (1.0 - 2.0 * epsilon).acos().to_degrees()
    }
}

/// The polar diagram's data of a report.
pub fn polar_data(r: &BearingReport) -> PolarData {
    let points: Vec<(f64, f64)> = element_loads(r)
        .into_iter()
        .map(|(a, q)| (a, q.max(0.0)))
        .collect();
    let (k, q_max) = largest(points.iter().map(|p| p.1));
    let a_max = points.get(k).map_or(0.0, |p| p.0);
    let label = format!(
        "{} load [N], largest {:.0} N at ψ = {:.1}°",
        noun(r),
        q_max,
        a_max
    );
    let [fx, fy, fz] = r.force_n;
    let scale = fx.abs().max(fy.abs()).max(fz.abs());
    let fr = fx.hypot(fy);
    let arrow = (fr > 1e-9 * scale).then(|| {
        let dir = fy.atan2(fx).to_degrees();
        let axial = if fz.abs() > 1e-9 * scale {
            format!(", axial load {:.0} N", fz)
        } else {
            String::new()
        };
        (
            dir,
            format!("radial load {fr:.0} N toward ψ = {dir:.1}°{axial}"),
        )
    });
    let [dx, dy, _] = r.displacement_mm;
    let arc = r.load_zone_epsilon.and_then(|e| {
        let half = loaded_arc_half_width_deg(e);
        let centre = dy.atan2(dx).to_degrees();
        (dx.hypot(dy) > 0.0).then(|| {
            let label = if half >= 180.0 {
                format!("loaded arc: the whole ring (ε = {e:.3} ≥ 1)")
            } else {
                format!("loaded arc ±{half:.1}° (Sjövall's ε = {e:.3})")
            };
            (centre, half, label)
        })
    });
    PolarData {
        points,
        label,
        arrow,
        arc,
    }
}

/// The load distribution as a polar diagram: every element's load as a spoke at its
/// azimuth, the radial load's direction and the loaded arc.
pub fn write_load_plot(path: &Path, r: &BearingReport) -> Result<()> {
    check_format(path)?;
    let d = polar_data(r);
    let count = d.points.len();
    let title = format!("{}: {count} {}s", bearing_name(r), noun(r));
    let caption = format!(
        "radius: {} load [N], 0 on the inner circle; angle: azimuth ψ [deg] from x toward y",
        noun(r)
    );
    let plot = PolarPlot {
        title: &title,
        caption: &caption,
        points: &d.points,
        label: &d.label,
        color: LOAD_COLOR,
        arrow: d.arrow.as_ref().map(|(a, label)| PolarArrow {
            angle_deg: *a,
            label,
        }),
        sector: d.arc.as_ref().map(|(c, h, label)| PolarSector {
            centre_deg: *c,
            half_width_deg: *h,
            label,
            color: ARC_COLOR,
        }),
    };
    kontakt_plot::polar_plot(path, &plot, (800, 820))
        .with_context(|| format!("drawing {}", path.display()))
}

/// Every element's load as a bar at its azimuth; below it the rib load of a tapered roller
/// bearing or the contact angle of every loaded ball of a ball bearing (with the free
/// contact angle).
pub fn write_element_plot(path: &Path, r: &BearingReport) -> Result<()> {
    check_format(path)?;
    let mut loads = element_loads(r);
    loads.sort_by(|a, b| a.0.total_cmp(&b.0));
    let n = noun(r);
    let title = format!("{}: {} loads", bearing_name(r), n);
    let load_label = format!("{n} load [N]");
    let raceway = if n == "roller" {
        "outer raceway load"
    } else {
        "ball load"
    };
    let top = [Series {
        label: raceway,
        points: &loads,
        color: LOAD_COLOR,
        style: LineStyle::Bars,
    }];
    let first = LinePlot {
        title: &title,
        x_label: "azimuth ψ [deg]",
        y_label: &load_label,
        series: &top,
        x_log: false,
        y_from_zero: true,
    };
    let (second, reference): (Vec<(f64, f64)>, Option<f64>) = match &r.elements {
        BearingElements::Rollers(p) if r.bearing_type == "tapered" => (
            p.roller_loads
                .iter()
                .map(|w| (w.azimuth_deg, w.rib_load_n))
                .collect(),
            None,
        ),
        BearingElements::Rollers(_) => (Vec::new(), None),
        // a ball without load touches neither raceway: it has no contact angle
        BearingElements::Balls(p) => (
            p.ball_loads
                .iter()
                .filter(|w| w.load_n > 0.0)
                .map(|w| (w.azimuth_deg, w.contact_angle_deg))
                .collect(),
            Some(p.free_contact_angle_deg),
        ),
    };
    let mut second = second;
    second.sort_by(|a, b| a.0.total_cmp(&b.0));
    let result = if second.is_empty() {
        kontakt_plot::line_plot(path, &first, (900, 600))
    } else if let Some(free) = reference {
        let x = (
            second.first().map_or(0.0, |p| p.0),
            second.last().map_or(0.0, |p| p.0),
        );
        let free_line = [(x.0, free), (x.1, free)];
        let series = [
            Series {
                label: "contact angle of a loaded ball",
                points: &second,
                color: ANGLE_COLOR,
                style: LineStyle::Markers,
            },
            Series {
                label: "free contact angle",
                points: &free_line,
                color: REFERENCE_COLOR,
                style: LineStyle::Dashed,
            },
        ];
        let lower = LinePlot {
            title: "",
            x_label: "azimuth ψ [deg]",
            y_label: "contact angle α [deg]",
            series: &series,
            x_log: false,
            y_from_zero: false,
        };
        kontakt_plot::line_plots(path, &[first, lower], (900, 1000))
    } else {
        let series = [Series {
            label: "rib load",
            points: &second,
            color: RIB_COLOR,
            style: LineStyle::Bars,
        }];
        let lower = LinePlot {
            title: "",
            x_label: "azimuth ψ [deg]",
            y_label: "rib load [N]",
            series: &series,
            x_log: false,
            y_from_zero: true,
        };
        kontakt_plot::line_plots(path, &[first, lower], (900, 1000))
    };
    result.with_context(|| format!("drawing {}", path.display()))
}

/// The slice plot's curve: (position mm, value) along the most loaded roller, and the
/// roller's mean value (the reference of a uniform distribution).
pub fn slice_curve(q: &SliceQuantity) -> (Vec<(f64, f64)>, f64) {
    let row = q.every_roller.get(q.roller).map_or(&[][..], Vec::as_slice);
    let pts: Vec<(f64, f64)> = q
        .position_mm
        .iter()
        .copied()
        .zip(row.iter().copied())
        .collect();
    let mean = row.iter().sum::<f64>() / row.len().max(1) as f64;
    (pts, mean)
}

/// A per-slice quantity (today the load per length) along the most loaded roller, slice by
/// slice, with the roller's mean as a dashed line: the edge peaks and the crowning show
/// against it.
pub fn write_slice_plot(path: &Path, r: &BearingReport) -> Result<()> {
    let p = rollers_of(r, "--slice-plot")?;
    check_format(path)?;
    let q = slice_quantity(p);
    let (points, mean) = slice_curve(&q);
    let ends = (
        points.first().map_or(0.0, |p| p.0),
        points.last().map_or(0.0, |p| p.0),
    );
    let mean_line = [(ends.0, mean), (ends.1, mean)];
    let mean_label = format!("mean over the roller {mean:.1} {}", q.unit);
    // the roller's ends: half a slice beyond the outer slices' centres
    let half = match q.position_mm {
        [a, b, ..] => 0.5 * (b - a),
        _ => 0.0,
    };
    let top = points.iter().fold(mean, |m, p| m.max(p.1));
    let left_end = [(ends.0 - half, 0.0), (ends.0 - half, top)];
    let right_end = [(ends.1 + half, 0.0), (ends.1 + half, top)];
    let series = [
        Series {
            label: "",
            points: &points,
            color: LOAD_COLOR,
            style: LineStyle::Solid,
        },
        Series {
            label: q.name,
            points: &points,
            color: LOAD_COLOR,
            style: LineStyle::Markers,
        },
        Series {
            label: &mean_label,
            points: &mean_line,
            color: REFERENCE_COLOR,
            style: LineStyle::Dashed,
        },
        Series {
            label: "ends of the roller",
            points: &left_end,
            color: END_COLOR,
            style: LineStyle::Solid,
        },
        Series {
            label: "",
            points: &right_end,
            color: END_COLOR,
            style: LineStyle::Solid,
        },
    ];
    let title = format!(
        "{}: most loaded roller, ψ = {:.1}°, Q = {:.0} N",
        bearing_name(r),
        p.roller_loads.get(q.roller).map_or(0.0, |w| w.azimuth_deg),
        p.max_roller_load_n
    );
    let x_label = if r.bearing_type == "tapered" {
        "position along the roller [mm], toward its small end"
    } else {
        "position along the roller [mm]"
    };
    let y_label = q.label();
    kontakt_plot::line_plot(
        path,
        &LinePlot {
            title: &title,
            x_label,
            y_label: &y_label,
            series: &series,
            x_log: false,
            y_from_zero: true,
        },
        (900, 600),
    )
    .with_context(|| format!("drawing {}", path.display()))
}

/// The map's data: the values row by row (one row per roller, sorted by azimuth within a
/// window of 360° centred on 0° or, when the most loaded roller lies beyond ±90°, on 180°,
/// so that the load zone is not cut in two), the lower edge of the first row and the row
/// height in degrees, the slice width in mm, and which roller each row holds.
#[derive(Debug, Clone, PartialEq)]
pub struct MapData {
    /// Slices (columns).
    pub nx: usize,
    /// Rollers (rows).
    pub ny: usize,
    /// Left edge of the first slice, mm.
    pub x_min: f64,
    /// Slice width, mm.
    pub dx: f64,
    /// Lower edge of the first row, deg.
    pub y_min: f64,
    /// Row height: 360°/Z.
    pub dy: f64,
    /// The values, row-major, slices fastest.
    pub values: Vec<f64>,
    /// The roller (index in `roller_loads`) of each row.
    pub rows: Vec<usize>,
}

/// The map of a per-slice quantity over every roller.
pub fn map_data(p: &RollerPart, q: &SliceQuantity) -> MapData {
    let nx = q.position_mm.len();
    let z = q.every_roller.len();
    let dx = match q.position_mm {
        [a, b, ..] => b - a,
        _ => 1.0,
    };
    let x_min = q.position_mm.first().map_or(0.0, |x| x - 0.5 * dx);
    let hot = p.roller_loads.get(q.roller).map_or(0.0, |w| w.azimuth_deg);
    let centre = if (-90.0..=90.0).contains(&((hot + 180.0).rem_euclid(360.0) - 180.0)) {
        0.0
    } else {
        180.0
    };
    // azimuth in (centre − 180, centre + 180]
    let shifted = |a: f64| {
        let s = (a - centre + 180.0).rem_euclid(360.0) - 180.0;
        centre + if s <= -180.0 { 180.0 } else { s }
    };
    let mut rows: Vec<usize> = (0..z).collect();
    rows.sort_by(|&a, &b| {
        shifted(p.roller_loads[a].azimuth_deg).total_cmp(&shifted(p.roller_loads[b].azimuth_deg))
    });
    let dy = 360.0 / z.max(1) as f64;
    let y_min = rows.first().map_or(-180.0, |&k| {
        shifted(p.roller_loads[k].azimuth_deg) - 0.5 * dy
    });
    let mut values = Vec::with_capacity(nx * z);
    for &k in &rows {
        let row = &q.every_roller[k];
        values.extend((0..nx).map(|i| row.get(i).copied().unwrap_or(0.0).max(0.0)));
    }
    MapData {
        nx,
        ny: z,
        x_min,
        dx,
        y_min,
        dy,
        values,
        rows,
    }
}

/// A per-slice quantity (today the load per length) over every roller's slices: position
/// along the roller × the roller's azimuth, with the largest value marked.
pub fn write_slice_map(path: &Path, r: &BearingReport) -> Result<()> {
    let p = rollers_of(r, "--map")?;
    check_format(path)?;
    let q = slice_quantity(p);
    let d = map_data(p, &q);
    let (k, v) = largest(d.values.iter().copied());
    let at_roller = d.rows.get(k / d.nx.max(1)).copied().unwrap_or(0);
    let marker = format!(
        "largest {} {v:.1} {}: roller at ψ = {:.1}°, {:.2} mm from its middle",
        q.name,
        q.unit,
        p.roller_loads.get(at_roller).map_or(0.0, |w| w.azimuth_deg),
        q.position_mm.get(k % d.nx.max(1)).copied().unwrap_or(0.0)
    );
    let title = format!("{}: {} of every slice", bearing_name(r), q.name);
    let x_label = if r.bearing_type == "tapered" {
        "position along the roller [mm], toward its small end"
    } else {
        "position along the roller [mm]"
    };
    let colorbar = q.label();
    let map = CellMap {
        nx: d.nx,
        ny: d.ny,
        x_min: d.x_min,
        y_min: d.y_min,
        dx: d.dx,
        dy: d.dy,
        values: &d.values,
        title: &title,
        caption: "one row per roller at its azimuth; white: no contact",
        x_label,
        y_label: "azimuth ψ [deg]",
        colorbar_label: &colorbar,
        max_marker: (v > 0.0).then_some(marker.as_str()),
    };
    kontakt_plot::cell_map(path, &map, (900, 700))
        .with_context(|| format!("drawing {}", path.display()))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message
    use super::*;
    use kontakt_case::{BearingCase, run_bearing_case};

    fn example(name: &str) -> BearingReport {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples")
            .join(name);
        let text = std::fs::read_to_string(path).unwrap();
        run_bearing_case(&BearingCase::from_toml_str(&text).unwrap()).unwrap()
    }

    /// The polar diagram's longest spoke is the most loaded roller, at its azimuth; the
    /// arrow points along the radial load; every loaded roller lies inside the loaded arc
    /// drawn from ε and every roller outside it carries nothing.
    #[test]
    fn polar_data_marks_the_most_loaded_roller_the_load_and_the_arc() {
        let mut partial_arcs = 0;
        for name in [
            "bearing_32008x.toml",
            "bearing_nu_crb.toml",
            "bearing_32216.toml",
        ] {
            let r = example(name);
            let p = r.rollers().unwrap();
            let d = polar_data(&r);
            assert_eq!(d.points.len(), p.rollers, "{name}");
            let (k, q) = largest(d.points.iter().map(|x| x.1));
            let a = d.points[k].0;
            assert_eq!(q, p.max_roller_load_n, "{name}");
            let hot = &p.roller_loads[p.most_loaded_roller.roller];
            assert_eq!(a, hot.azimuth_deg, "{name}");
            let (dir, label) = d.arrow.clone().unwrap();
            let f = r.force_n;
            assert!(
                (dir - f[1].atan2(f[0]).to_degrees()).abs() < 1e-12,
                "{name}"
            );
            assert!(
                label.contains(&format!("{:.0} N", f[0].hypot(f[1]))),
                "{label}"
            );
            let (c, half, _) = d.arc.clone().unwrap();
            let eps = r.load_zone_epsilon.unwrap();
            assert_eq!(half >= 180.0, eps >= 1.0, "{name}: ε = {eps}");
            let all_loaded = p.roller_loads.iter().all(|w| w.outer_load_n > 0.0);
            assert_eq!(half >= 180.0, all_loaded, "{name}: ε = {eps}");
            partial_arcs += usize::from(half < 180.0);
            for w in &p.roller_loads {
                let off = ((w.azimuth_deg - c + 180.0).rem_euclid(360.0) - 180.0).abs();
                // a roller 1° inside the arc carries load, 1° outside none
                if off < half - 1.0 {
                    assert!(w.outer_load_n > 0.0, "{name}: ψ = {}", w.azimuth_deg);
                } else if off > half + 1.0 {
                    assert!(w.outer_load_n == 0.0, "{name}: ψ = {}", w.azimuth_deg);
                }
            }
        }
        assert!(partial_arcs > 0, "no example with a partial loaded arc");
        assert_eq!(loaded_arc_half_width_deg(0.5), 90.0);
        assert!((loaded_arc_half_width_deg(0.25) - 60.0).abs() < 1e-12);
    }

    /// The map's hottest cell is the most loaded roller's most loaded slice; its rows run
    /// by azimuth upwards, one row height (360°/Z) apart, the load zone in the middle.
    #[test]
    fn the_map_is_hottest_at_the_most_loaded_slice() {
        for name in [
            "bearing_32008x.toml",
            "bearing_32216.toml",
            "bearing_nu_crb.toml",
        ] {
            let r = example(name);
            let p = r.rollers().unwrap();
            let q = slice_quantity(p);
            let d = map_data(p, &q);
            assert_eq!((d.nx, d.ny), (p.slices, p.rollers), "{name}");
            let k = largest(d.values.iter().copied()).0;
            let (i, j) = (k % d.nx, k / d.nx);
            let m = &p.most_loaded_roller;
            assert_eq!(d.rows[j], m.roller, "{name}");
            let slice = largest(m.load_per_length_n_per_mm.iter().copied()).0;
            assert_eq!(
                d.values[k], m.load_per_length_n_per_mm[slice],
                "{name}: the map's largest value"
            );
            assert_eq!(d.values[k], p.max_load_per_length_n_per_mm, "{name}");
            assert_eq!(
                m.load_per_length_n_per_mm[i], m.load_per_length_n_per_mm[slice],
                "{name}"
            );
            // row centres at the rollers' azimuths, increasing, the hot one near the middle
            for (row, &roller) in d.rows.iter().enumerate() {
                let centre = d.y_min + (row as f64 + 0.5) * d.dy;
                let a = p.roller_loads[roller].azimuth_deg;
                assert!(
                    ((centre - a + 180.0).rem_euclid(360.0) - 180.0).abs() < 1e-9,
                    "{name}: row {row} at {centre}°, roller at {a}°"
                );
            }
            let hot = d.y_min + (j as f64 + 0.5) * d.dy;
            assert!(
                hot > d.y_min + 90.0 && hot < d.y_min + 270.0,
                "{name}: {hot}"
            );
            // the slice columns cover the roller: the centres are the report's positions
            for (i, x) in m.position_mm.iter().enumerate() {
                assert!(
                    (d.x_min + (i as f64 + 0.5) * d.dx - x).abs() < 1e-9,
                    "{name}"
                );
            }
        }
    }

    /// The slice plot draws the most loaded roller's own slices; the mean line is its mean.
    #[test]
    fn the_slice_curve_is_the_most_loaded_roller() {
        let r = example("bearing_32008x.toml");
        let p = r.rollers().unwrap();
        let q = SliceQuantity::load_per_length(p);
        let (pts, mean) = slice_curve(&q);
        let m = &p.most_loaded_roller;
        assert_eq!(pts.len(), m.position_mm.len());
        for (k, (x, v)) in pts.iter().enumerate() {
            assert_eq!((*x, *v), (m.position_mm[k], m.load_per_length_n_per_mm[k]));
        }
        // the load per length integrates to the roller's load
        let w = m.position_mm[1] - m.position_mm[0];
        let total = mean * w * pts.len() as f64;
        assert!((total - p.max_roller_load_n).abs() < 1e-6 * p.max_roller_load_n);
        assert_eq!(q.label(), "load per length [N/mm]");
    }
}
