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
    /// The top of the colour scale \[MPa\] shared with other maps (`None`: this map's
    /// maximum).
    pub color_max: Option<f64>,
    /// The stretch of the short axis shared with other maps of the same contact (`None`:
    /// the map's own, see [`kontakt_plot::map_stretch`]).
    pub stretch: Option<f64>,
}

impl MapNotes {
    /// Axes named by their direction in the bearing (see [`axis_name`]).
    pub fn in_bearing(axes: [[f64; 3]; 2], hertz_semi_axes_mm: Option<[f64; 2]>) -> Self {
        MapNotes {
            axes: (axis_name(axes[0]), axis_name(axes[1])),
            hertz_semi_axes_mm,
            color_max: None,
            stretch: None,
        }
    }

    /// Axes named as `x`, `y` in mm, no ellipse (a rough surface's periodic cell).
    pub fn plain() -> Self {
        MapNotes {
            axes: ("x [mm]".into(), "y [mm]".into()),
            hertz_semi_axes_mm: None,
            color_max: None,
            stretch: None,
        }
    }

    /// The same notes with a colour scale shared with other maps (top `color_max` MPa) and
    /// the short axis stretched `stretch` times, as on the other maps of the contact.
    pub fn shared(self, color_max: Option<f64>, stretch: Option<f64>) -> Self {
        MapNotes {
            color_max,
            stretch,
            ..self
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
            color_max: None,
            stretch: None,
        }
    }
}

/// The legend entry of the maximum-pressure marker.
pub fn max_label(pressure: &[f64]) -> String {
    let max = pressure.iter().copied().fold(0.0f64, f64::max);
    format!("maximum pressure {max:.0} MPa")
}

/// The unit of a power density \[W/mm²\] whose largest value is `max`: the factor to
/// multiply by and the name, chosen so that the maximum reads between 1 and 1000 (34.5
/// W/mm², not 34457 mW/mm²).
pub fn power_density_unit(max: f64) -> (f64, &'static str) {
    if max >= 1.0 {
        (1.0, "W/mm²")
    } else if max >= 1e-3 {
        (1e3, "mW/mm²")
    } else {
        (1e6, "µW/mm²")
    }
}

/// The stretch of the short axis that a pressure map of `pressure` on `grid` with the Hertz
/// ellipse `hertz_semi_axes_mm` gets by itself: the demo and `kontakt validate` draw every
/// map of a pairing with the factor of its PimP-corrected field at 400 N, so that the maps
/// of one pairing compare.
pub fn map_stretch(grid: &Grid2, pressure: &[f64], hertz_semi_axes_mm: Option<[f64; 2]>) -> f64 {
    let notes = MapNotes {
        hertz_semi_axes_mm,
        ..MapNotes::plain()
    };
    kontakt_plot::map_stretch(&pressure_map(grid, pressure, "", &[], &notes, ""))
}

/// A [`FieldMap`] of `values` on the cells of `grid` with the contact outline, the axes
/// labelled `axes`; no overlays, ellipse, marker, shared scale or fixed stretch (callers add
/// them by struct update).
pub fn grid_map<'a>(
    grid: &Grid2,
    values: &'a [f64],
    title: &'a str,
    axes: &'a (String, String),
    colorbar_label: &'a str,
) -> FieldMap<'a> {
    let g = grid;
    FieldMap {
        nx: g.nx(),
        ny: g.ny(),
        x_min: g.x(0) - 0.5 * g.dx(),
        y_min: g.y(0) - 0.5 * g.dy(),
        dx: g.dx(),
        dy: g.dy(),
        values,
        title,
        x_label: &axes.0,
        y_label: &axes.1,
        colorbar_label,
        outline: true,
        overlays: &[],
        ellipse: None,
        max_marker: None,
        color_max: None,
        stretch: None,
    }
}

/// The [`FieldMap`] of a pressure map (see [`write_map`]).
fn pressure_map<'a>(
    grid: &Grid2,
    pressure: &'a [f64],
    title: &'a str,
    overlays: &'a [kontakt_plot::Overlay<'a>],
    notes: &'a MapNotes,
    max: &'a str,
) -> FieldMap<'a> {
    FieldMap {
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
        max_marker: (!max.is_empty()).then_some(max),
        color_max: notes.color_max,
        stretch: notes.stretch,
        ..grid_map(grid, pressure, title, &notes.axes, "pressure [MPa]")
    }
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
    let max = max_label(pressure);
    let map = pressure_map(grid, pressure, title, overlays, notes, &max);
    kontakt_plot::field_map(path, &map, (900, 640))
        .with_context(|| format!("drawing {}", path.display()))
}

/// Colour of the Hertz ellipse on pressure maps (magenta: apart from viridis, the black
/// outline and the overlays' red and orange).
pub const HERTZ_COLOR: (u8, u8, u8) = (220, 0, 220);

/// One curve per pairing (solid and dashed in turn, the palette's colours) on one plot;
/// with `y_from_zero` the y axis starts at 0.
pub fn pairing_plot<S: AsRef<str>>(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    curves: &[(S, Vec<(f64, f64)>)],
    x_log: bool,
    y_from_zero: bool,
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
            y_from_zero,
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
    #![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message
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

    /// Issue 30, item 18: a roller/rib case's map (`kontakt solve --map`; a built-in pairing
    /// or a custom face and rib, which build the same gap) names its axes on the rib, as the
    /// demo's maps do, not by the Hertz ellipse's axes.
    #[test]
    fn a_roller_rib_case_map_names_its_axes_on_the_rib() {
        let case = kontakt_case::Case::from_toml_str(include_str!(
            "../../../examples/roller_rib_torus_torus.toml"
        ))
        .unwrap();
        let kontakt_case::Case::Pimp(c) = case else {
            panic!("not a pimp case")
        };
        let axes = kontakt_case::pimp_case::bearing_axes(&c.geometry)
            .unwrap()
            .unwrap();
        let notes = super::MapNotes::in_bearing(axes, None);
        assert_eq!(notes.axes.0, "along the rib (circumferential) [mm]");
        assert!(
            notes.axes.1.starts_with("across the rib"),
            "{}",
            notes.axes.1
        );
        // and the demo's map of the same pairing has the same axes
        let study = kontakt::bearing::demo_study(&[250.0]).unwrap();
        let demo = study
            .maps
            .iter()
            .find(|m| m.pairing == "torus-torus-14")
            .unwrap();
        assert_eq!(demo.axes, axes);
    }

    #[test]
    fn power_densities_read_between_1_and_1000() {
        use super::power_density_unit as unit;
        assert_eq!(unit(34.457), (1.0, "W/mm²"));
        assert_eq!(unit(0.5), (1e3, "mW/mm²"));
        assert_eq!(unit(2e-4), (1e6, "µW/mm²"));
    }
}
