//! The pictures' shared pieces: axis names in the bearing frame, the pressure map with its
//! notes, the one-curve-per-pairing plot, and the list of files the demo writes. Below the
//! subcommands (`commands::*`), which all draw with them; it imports none of them.

use crate::error::InputError;
use anyhow::{Context, Result};
use kontakt::geometry::Grid2;
use kontakt_plot::{FieldMap, LinePlot, LineStyle, PALETTE, Series};
use std::path::Path;

/// The name of a grid axis by its direction `d` in the bearing frame (a unit vector; `X`
/// radial, `Y` circumferential at the contact point, `Z` the ring axis), with its unit: the
/// rib runs round the ring, so a circumferential axis is "along the rib" and an axis in the
/// axial section plane is "across the rib" (with its lean from radial).
pub fn axis_name(d: [f64; 3]) -> String {
    let circumferential = d[1].abs().min(1.0);
    let off = circumferential.acos().to_degrees();
    if off <= 15.0 {
        "along the rib (circumferential) [mm]".to_string()
    } else if off >= 75.0 {
        let from_radial = d[2].abs().atan2(d[0].abs()).to_degrees();
        if from_radial < 10.0 {
            "across the rib (radial) [mm]".to_string()
        } else {
            format!("across the rib ({from_radial:.0}° from radial) [mm]")
        }
    } else {
        format!("{off:.0}° from circumferential [mm]")
    }
}

/// How a pressure map is annotated: the names of its axes and the Hertz ellipse at the
/// contact point (semi-axes `[a, b]` in mm, `a` along the grid's `x`, centred at the origin).
pub struct MapNotes {
    /// Labels of the x and y axes.
    pub axes: (String, String),
    /// Hertz semi-axes, if the ellipse is to be drawn.
    pub hertz_semi_axes_mm: Option<[f64; 2]>,
}

impl MapNotes {
    /// Axes named by their direction in the bearing (see [`axis_name`]).
    pub fn in_bearing(axes: [[f64; 3]; 2], hertz_semi_axes_mm: Option<[f64; 2]>) -> Self {
        MapNotes {
            axes: (axis_name(axes[0]), axis_name(axes[1])),
            hertz_semi_axes_mm,
        }
    }

    /// Axes of the gap's principal frame (x along the Hertz major axis), for contacts that
    /// are not placed in a bearing; plain x, y for a gap map (no Hertz contact point).
    pub fn principal(hertz_semi_axes_mm: Option<[f64; 2]>) -> Self {
        let axes = if hertz_semi_axes_mm.is_some() {
            (
                "x, along the Hertz major axis [mm]".to_string(),
                "y, along the Hertz minor axis [mm]".to_string(),
            )
        } else {
            ("x [mm]".to_string(), "y [mm]".to_string())
        };
        MapNotes {
            axes,
            hertz_semi_axes_mm,
        }
    }
}

/// The legend entry of the maximum-pressure marker.
pub fn max_label(pressure: &[f64]) -> String {
    let max = pressure.iter().copied().fold(0.0f64, f64::max);
    format!("p_max = {max:.0} MPa")
}

/// Draw a pressure map with the contact outline, optional overlays, the Hertz ellipse at
/// the contact point and the maximum marked, its axes named as `notes` says.
pub fn write_map(
    path: &Path,
    grid: &Grid2,
    pressure: &[f64],
    title: &str,
    overlays: &[kontakt_plot::Overlay<'_>],
    notes: &MapNotes,
) -> Result<()> {
    kontakt_plot::Format::from_path(path).map_err(|e| InputError(e.to_string()))?;
    let g = grid;
    let max = max_label(pressure);
    let map = FieldMap {
        nx: g.nx(),
        ny: g.ny(),
        x_min: g.x(0) - 0.5 * g.dx(),
        y_min: g.y(0) - 0.5 * g.dy(),
        dx: g.dx(),
        dy: g.dy(),
        values: pressure,
        title,
        x_label: &notes.axes.0,
        y_label: &notes.axes.1,
        colorbar_label: "pressure [MPa]",
        outline: true,
        overlays,
        ellipse: notes
            .hertz_semi_axes_mm
            .map(|[a, b]| kontakt_plot::Ellipse {
                label: "Hertz ellipse at the contact point",
                centre: (0.0, 0.0),
                semi_axes: (a, b),
                angle: 0.0,
                color: HERTZ_COLOR,
            }),
        max_marker: Some(&max),
    };
    kontakt_plot::field_map(path, &map, (900, 640))
        .with_context(|| format!("drawing {}", path.display()))
}

/// Colour of the Hertz ellipse on pressure maps (magenta: apart from viridis, the black
/// outline and the overlays' red and orange).
pub const HERTZ_COLOR: (u8, u8, u8) = (220, 0, 220);

/// One curve per pairing (solid and dashed in turn, the palette's colours) on one plot.
pub fn pairing_plot<S: AsRef<str>>(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    curves: &[(S, Vec<(f64, f64)>)],
    x_log: bool,
) -> Result<()> {
    let series: Vec<Series> = curves
        .iter()
        .enumerate()
        .map(|(k, (name, pts))| Series {
            label: name.as_ref(),
            points: pts,
            color: PALETTE[k % PALETTE.len()],
            style: if k % 2 == 0 {
                LineStyle::Solid
            } else {
                LineStyle::Dashed
            },
        })
        .collect();
    kontakt_plot::line_plot(
        path,
        &LinePlot {
            title,
            x_label,
            y_label,
            series: &series,
            x_log,
        },
        (900, 600),
    )
    .with_context(|| format!("drawing {}", path.display()))
}

/// The files the demo writes besides report.md, by kind, in the order written: the summary
/// line counts these lists, so it cannot disagree with what is on disk.
#[derive(Debug, Default)]
pub struct Written {
    /// Pressure maps (PNG).
    pub maps: Vec<String>,
    /// Line plots (PNG).
    pub plots: Vec<String>,
    /// Maps of the friction study (PNG).
    pub friction_maps: Vec<String>,
    /// CSV tables.
    pub tables: Vec<String>,
}

impl Written {
    /// The demo's last line: the report and every file written with it, counted.
    pub fn summary(&self, report: &Path, results: usize) -> String {
        let pictures = self.maps.len() + self.plots.len() + self.friction_maps.len();
        format!(
            "Report written to {} with {pictures} pictures ({} pressure maps, {} plots, {} \
             friction maps) and {} tables ({}; {results} results in results.csv)",
            report.display(),
            self.maps.len(),
            self.plots.len(),
            self.friction_maps.len(),
            self.tables.len(),
            self.tables.join(", "),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::axis_name;

    #[test]
    fn axes_are_named_by_their_direction_on_the_rib() {
        assert_eq!(
            axis_name([0.0, -1.0, 0.0]),
            "along the rib (circumferential) [mm]"
        );
        assert_eq!(axis_name([1.0, 0.0, 0.0]), "across the rib (radial) [mm]");
        let (s, c) = 21f64.to_radians().sin_cos();
        assert_eq!(
            axis_name([-c, 0.0, s]),
            "across the rib (21° from radial) [mm]"
        );
        let (s, c) = 45f64.to_radians().sin_cos();
        assert_eq!(axis_name([c, s, 0.0]), "45° from circumferential [mm]");
    }
}
