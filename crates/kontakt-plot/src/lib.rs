//! Report-quality plots for kontakt: pressure maps and line plots, written as PNG or SVG.
//!
//! The crate is independent of the `kontakt` solver crate: it takes plain slices.
//!
//! * [`field_map`] draws a scalar field on a uniform cell-centred grid (e.g. a contact
//!   pressure in MPa over x, y in mm) as a heat map framed tightly round the region with
//!   values (equal axis scales, or a stretched short axis with a note for a slender region),
//!   a colour bar and the outline of the contact region, optionally with the outlines of
//!   other fields, an [`Ellipse`] (e.g. Hertz's) and a marker at the maximum.
//! * [`field_map_with_arrows`] draws the same heat map with a vector field of [`Arrow`]s on
//!   top (e.g. the sliding velocity over the pressure or the friction-power density).
//! * [`line_plot`] draws curves and measured points, on a linear or logarithmic x axis, with a
//!   legend where it hides no data.
//! * [`line_plots`] stacks several line plots in one image (e.g. two quantities of
//!   different units over one x axis).
//! * [`polar_plot`] draws values at angles as spokes around a ring (e.g. the loads of a
//!   bearing's rolling elements at their azimuths), with a shaded sector and an arrow.
//! * [`cell_map`] draws a heat map of cells over two independent axes (e.g. the slice loads
//!   of every roller: position along the roller × azimuth).
//! * [`contour_zero`] returns the boundary of the region `values > 0` as closed polylines.
//!
//! The output format follows the file extension (see [`Format`]). Text is rendered with a
//! bundled DejaVu Sans font (Bitstream Vera licence, `assets/LICENSE-DejaVu.txt`), so PNG
//! plots look the same on machines without any system fonts; SVG text names the
//! `sans-serif` family and is laid out with the same font metrics.
//!
//! ```no_run
//! use std::path::Path;
//! use kontakt_plot::{FieldMap, field_map};
//!
//! let (nx, ny) = (64, 48);
//! let values: Vec<f64> = (0..nx * ny)
//!     .map(|k| {
//!         let x = -1.2 + ((k % nx) as f64 + 0.5) * 2.4 / nx as f64;
//!         let y = -0.6 + ((k / nx) as f64 + 0.5) * 1.2 / ny as f64;
//!         1000.0 * (1.0 - x * x - 4.0 * y * y).max(0.0).sqrt()
//!     })
//!     .collect();
//! let map = FieldMap {
//!     nx,
//!     ny,
//!     x_min: -1.2,
//!     y_min: -0.6,
//!     dx: 2.4 / nx as f64,
//!     dy: 1.2 / ny as f64,
//!     values: &values,
//!     title: "Contact pressure",
//!     x_label: "x [mm]",
//!     y_label: "y [mm]",
//!     colorbar_label: "pressure [MPa]",
//!     outline: true,
//!     overlays: &[],
//!     ellipse: None,
//!     max_marker: Some("maximum pressure 1000 MPa"),
//!     color_max: None,
//!     stretch: None,
//! };
//! field_map(Path::new("pressure.png"), &map, (1000, 700))?;
//! # Ok::<(), kontakt_plot::PlotError>(())
//! ```

#![forbid(unsafe_code)]

mod cellmap;
mod colormap;
mod contour;
mod field;
mod line;
mod polar;
mod render;
mod ticks;

use std::path::{Path, PathBuf};

pub use contour::contour_zero;
pub use render::missing_glyphs;

/// Smallest accepted image size in pixels (width, height).
pub const MIN_SIZE: (u32, u32) = (200, 150);
/// Largest accepted image size in pixels along either axis.
pub const MAX_SIZE: u32 = 8000;

/// A fixed palette of distinct colours for series (the "tab10" colours of matplotlib:
/// blue, orange, green, red, purple, brown, pink, grey).
pub const PALETTE: [(u8, u8, u8); 8] = [
    (31, 119, 180),
    (255, 127, 14),
    (44, 160, 44),
    (214, 39, 40),
    (148, 103, 189),
    (140, 86, 75),
    (227, 119, 194),
    (127, 127, 127),
];

/// Output format, chosen from the file extension (`.png` / `.svg`, any letter case).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// Raster image (8-bit RGB PNG).
    Png,
    /// Vector image (SVG 1.1; text as `<text>` elements with the `sans-serif` family).
    Svg,
}

impl Format {
    /// The format for a file name: `.png` or `.svg` (case-insensitive). Any other or a
    /// missing extension is a [`PlotError::UnsupportedFormat`] naming the path and the valid
    /// extensions.
    pub fn from_path(path: &Path) -> Result<Format, PlotError> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("png") => Ok(Format::Png),
            Some("svg") => Ok(Format::Svg),
            _ => Err(PlotError::UnsupportedFormat {
                path: path.to_path_buf(),
            }),
        }
    }
}

/// Errors of the plotting functions. Invalid input is reported before anything is written.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// An input value is out of its valid range.
    #[error("invalid {field} = {value}: expected {expected}")]
    InvalidInput {
        /// The offending input, e.g. `values[17]` or `series[1] ("measured").points[3]`.
        field: String,
        /// The value that was given.
        value: String,
        /// What would have been accepted.
        expected: String,
    },
    /// The output file name has no supported extension.
    #[error("cannot tell the plot format of {}: the file name must end in .png or .svg", path.display())]
    UnsupportedFormat {
        /// The output path as given.
        path: PathBuf,
    },
    /// Writing the output file failed (e.g. its directory does not exist).
    #[error("cannot write plot file {}: {source}", path.display())]
    Io {
        /// The output path.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// The drawing backend, the bundled font or the PNG encoder failed.
    #[error("drawing failed: {0}")]
    Drawing(String),
}

impl PlotError {
    fn invalid(
        field: impl Into<String>,
        value: impl ToString,
        expected: impl Into<String>,
    ) -> Self {
        PlotError::InvalidInput {
            field: field.into(),
            value: value.to_string(),
            expected: expected.into(),
        }
    }
}

/// A scalar field on a uniform cell-centred grid.
///
/// Value `(i, j)` belongs to the cell centred at `x = x_min + (i + 0.5) dx`,
/// `y = y_min + (j + 0.5) dy`, and is stored row-major with x fastest (index `j*nx + i`).
/// The grid covers `[x_min, x_min + nx dx] × [y_min, y_min + ny dy]`.
#[derive(Debug, Clone, Copy)]
pub struct FieldMap<'a> {
    /// Number of cells along x (at least 2).
    pub nx: usize,
    /// Number of cells along y (at least 2).
    pub ny: usize,
    /// Left edge of the grid in mm.
    pub x_min: f64,
    /// Lower edge of the grid in mm.
    pub y_min: f64,
    /// Cell size along x in mm (finite, > 0).
    pub dx: f64,
    /// Cell size along y in mm (finite, > 0).
    pub dy: f64,
    /// The values, `nx*ny` of them, all finite (e.g. pressure in MPa); 0 means "no contact"
    /// and is drawn as background.
    pub values: &'a [f64],
    /// Title at the top of the figure.
    pub title: &'a str,
    /// Label of the x axis, e.g. `"x [mm]"`.
    pub x_label: &'a str,
    /// Label of the y axis, e.g. `"y [mm]"`.
    pub y_label: &'a str,
    /// Label of the colour bar, e.g. `"pressure [MPa]"`.
    pub colorbar_label: &'a str,
    /// Draw the outline of the region `values > 0` (the contact boundary, see
    /// [`contour_zero`]) as a closed black line.
    pub outline: bool,
    /// Extra outlines to overlay (e.g. another solver's contact boundary), each drawn as the
    /// boundary of its `values > 0` in its colour (dashed), with a legend entry.
    pub overlays: &'a [Overlay<'a>],
    /// An ellipse to draw over the map (e.g. the Hertz contact ellipse at the contact
    /// point), dotted, with a legend entry.
    pub ellipse: Option<Ellipse<'a>>,
    /// Mark the cell of the largest value with a ringed dot, with this legend entry (e.g.
    /// `"maximum 458 MPa"`).
    pub max_marker: Option<&'a str>,
    /// The top of the colour scale (finite, > 0), e.g. one value shared by several maps so
    /// that a colour means the same pressure on each; larger values take the top colour.
    /// `None`: the largest value of this map.
    pub color_max: Option<f64>,
    /// The stretch of the frame's short axis (a whole number ≥ 1; 1: to scale), e.g. one
    /// factor for all maps of a contact so that they compare; `None`: the smallest whole
    /// factor that brings the frame to at most 2.5:1 (see [`field_map`], [`map_stretch`]).
    pub stretch: Option<f64>,
}

/// The stretch [`field_map`] gives the short axis of `map` when its `stretch` is `None`: 1
/// when its frame is at most 2.5:1, else the smallest whole factor that brings it there.
/// Several maps drawn with one factor (e.g. the largest of theirs) compare at a glance.
pub fn map_stretch(map: &FieldMap) -> f64 {
    let auto = FieldMap {
        stretch: None,
        ..*map
    };
    let (sx, sy) = field::frame(&auto).stretch;
    sx.max(sy)
}

/// An ellipse drawn over a [`FieldMap`] in the map's coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipse<'a> {
    /// Legend entry.
    pub label: &'a str,
    /// Centre (x, y) in mm.
    pub centre: (f64, f64),
    /// Semi-axes in mm (finite, > 0): the first along the direction `angle`, the second
    /// perpendicular to it.
    pub semi_axes: (f64, f64),
    /// Angle from the x axis to the first semi-axis, counter-clockwise, in radians.
    pub angle: f64,
    /// Line colour as (r, g, b).
    pub color: (u8, u8, u8),
}

/// The contact boundary of another field on the same grid, overlaid on a [`FieldMap`].
#[derive(Debug, Clone, Copy)]
pub struct Overlay<'a> {
    /// Legend entry.
    pub label: &'a str,
    /// Field values on the same grid as the map (`nx*ny`, finite); its region `> 0` is outlined.
    pub values: &'a [f64],
    /// Line colour as (r, g, b).
    pub color: (u8, u8, u8),
}

/// Draw a heat map of the field into `path` (`.png` or `.svg`, see [`Format`]) with the
/// image size `size` = (width, height) in pixels.
///
/// The figure has the title at the top, the map with ticked axes in mm, a colour bar
/// (viridis) with its label and tick values to the right, and the outline(s) of the contact
/// region; the cells are drawn inside the outline only, so that none pokes through it. Zero
/// cells are left white. An all-zero field is allowed: the map is empty, with "no contact" in
/// its centre.
///
/// The map is framed tightly around what it shows (the cells with values, the overlays'
/// regions and the ellipse) with a margin of 8 % (at least one cell) on each side, not
/// around the whole grid. Both axes have the same scale (1 mm is the same length in x and
/// y) unless the framed region is more slender than 2.5:1: then the short axis is stretched
/// by a whole factor so that it is at most 2.5:1, and a note under the title says so (e.g.
/// "y axis stretched ×4: the zone is 4× more slender than drawn"). The outline, overlays,
/// the ellipse and the maximum marker have a legend under the map.
///
/// For PNG the map is rasterised at the pixel resolution of the plotting area; for SVG each
/// cell becomes a rectangle, after averaging blocks of cells down to at most 128×128 cells.
///
/// Errors: an unsupported extension, invalid input (see [`FieldMap`]; `size` must lie within
/// [`MIN_SIZE`] and [`MAX_SIZE`]), or a file that cannot be written (a missing parent
/// directory is not created).
pub fn field_map(path: &Path, map: &FieldMap, size: (u32, u32)) -> Result<(), PlotError> {
    field_map_with_arrows(path, map, &[], "", size)
}

/// An arrow of a vector field drawn over a [`FieldMap`], in the map's coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arrow {
    /// x of the tail in mm.
    pub x: f64,
    /// y of the tail in mm.
    pub y: f64,
    /// x component of the vector, already scaled to mm by the caller (the tip is at `x + dx`).
    pub dx: f64,
    /// y component of the vector, already scaled to mm by the caller (the tip is at `y + dy`).
    pub dy: f64,
}

/// Draw the heat map of `map` as [`field_map`] does, with the vector field `arrows` on top
/// (e.g. the sliding velocity of a contact over its pressure or friction-power map).
///
/// Each arrow is a dark line from its tail `(x, y)` to its tip `(x + dx, y + dy)` with a
/// two-stroke head whose length is 30 % of the arrow's; arrows are drawn after the outlines,
/// clipped to the map (they may poke out of it), and arrows of zero length are skipped. The
/// caller scales the vectors to mm; a non-empty `arrow_label` (e.g.
/// `"sliding velocity, 1 mm = 2 m/s"`) is printed under the title to give that scale.
///
/// Errors: those of [`field_map`], and an arrow with a non-finite coordinate or tip (the
/// error names `arrows[i]` and its values).
///
/// ```no_run
/// use std::path::Path;
/// use kontakt_plot::{Arrow, FieldMap, field_map_with_arrows};
///
/// let n = 32;
/// let h = 2.0 / n as f64;
/// let centre = |k: usize| -1.0 + (k as f64 + 0.5) * h;
/// let values: Vec<f64> = (0..n * n)
///     .map(|k| 1000.0 * (1.0 - centre(k % n).powi(2) - centre(k / n).powi(2)).max(0.0).sqrt())
///     .collect();
/// let map = FieldMap {
///     nx: n,
///     ny: n,
///     x_min: -1.0,
///     y_min: -1.0,
///     dx: h,
///     dy: h,
///     values: &values,
///     title: "Contact pressure",
///     x_label: "x [mm]",
///     y_label: "y [mm]",
///     colorbar_label: "pressure [MPa]",
///     outline: true,
///     overlays: &[],
///     ellipse: None,
///     max_marker: None,
///     color_max: None,
///     stretch: None,
/// };
/// // A rigid rotation about the centre: v = omega × r in mm/s, drawn 0.1 mm per mm/s.
/// let (omega, scale) = (2.0, 0.1);
/// let mut arrows = Vec::new();
/// for j in (2..n).step_by(4) {
///     for i in (2..n).step_by(4) {
///         let (x, y) = (centre(i), centre(j));
///         let (vx, vy) = (-omega * y, omega * x);
///         arrows.push(Arrow { x, y, dx: scale * vx, dy: scale * vy });
///     }
/// }
/// field_map_with_arrows(
///     Path::new("sliding.svg"),
///     &map,
///     &arrows,
///     "sliding velocity, 1 mm = 10 mm/s",
///     (1000, 800),
/// )?;
/// # Ok::<(), kontakt_plot::PlotError>(())
/// ```
pub fn field_map_with_arrows(
    path: &Path,
    map: &FieldMap,
    arrows: &[Arrow],
    arrow_label: &str,
    size: (u32, u32),
) -> Result<(), PlotError> {
    let format = Format::from_path(path)?;
    validate_size(size)?;
    validate_field(map)?;
    validate_ellipse(map.ellipse.as_ref())?;
    validate_arrows(arrows)?;
    let figure = field::FieldFigure {
        map,
        arrows,
        arrow_label,
    };
    render::render(path, format, size, figure)
}

/// How the points of a [`Series`] are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineStyle {
    /// Solid line through the points.
    Solid,
    /// Dashed line through the points.
    Dashed,
    /// Points only, as filled circles (measurements).
    Markers,
    /// A vertical bar from 0 to each point (e.g. one value per rolling element); the bars
    /// of several bar series at the same x stand side by side, and together take 80 % of
    /// the smallest x spacing.
    Bars,
}

/// One curve of a [`LinePlot`].
#[derive(Debug, Clone, Copy)]
pub struct Series<'a> {
    /// Legend entry (an empty label gets no entry).
    pub label: &'a str,
    /// The (x, y) points, in drawing order; at least one, all finite.
    pub points: &'a [(f64, f64)],
    /// Colour as (r, g, b), e.g. from [`PALETTE`].
    pub color: (u8, u8, u8),
    /// Line or markers.
    pub style: LineStyle,
}

/// A line plot: several series over common axes.
#[derive(Debug, Clone, Copy)]
pub struct LinePlot<'a> {
    /// Title at the top of the figure.
    pub title: &'a str,
    /// Label of the x axis.
    pub x_label: &'a str,
    /// Label of the y axis.
    pub y_label: &'a str,
    /// The curves (at least one).
    pub series: &'a [Series<'a>],
    /// A logarithmic x axis (every x must then be > 0): decade ticks labelled with the value
    /// (`0.1`, `1`, `10`, ... from 0.001 to 100000, `10ᵏ` beyond), with 2 and 5 times each
    /// decade where fewer than three decades are in range.
    pub x_log: bool,
    /// The y axis starts at 0 (ends there for negative data): for magnitudes such as a
    /// torque, whose size matters, not only its variation.
    pub y_from_zero: bool,
}

/// Draw a line plot into `path` (`.png` or `.svg`, see [`Format`]) with the image size
/// `size` = (width, height) in pixels.
///
/// The ranges cover all points with a small margin; there is a light grid at the ticks and a
/// legend that never hides data: in the first place in the plot that holds neither points
/// nor lines (the corners upper right, upper left, lower right, lower left, then the middles
/// of the right and left sides, of the top and of the bottom), or else to the right of the
/// plot, outside it.
///
/// Errors: an unsupported extension, `size` outside [`MIN_SIZE`]..[`MAX_SIZE`], no series, a
/// series without points, a non-finite coordinate (the error names the series and the point
/// index), an x ≤ 0 on a logarithmic axis, or a file that cannot be written.
pub fn line_plot(path: &Path, plot: &LinePlot, size: (u32, u32)) -> Result<(), PlotError> {
    let format = Format::from_path(path)?;
    validate_size(size)?;
    validate_series(plot.series)?;
    if plot.x_log {
        for (s, item) in plot.series.iter().enumerate() {
            if let Some(k) = item.points.iter().position(|(x, _)| !(*x > 0.0)) {
                return Err(PlotError::invalid(
                    format!("series[{s}] ({:?}).points[{k}].x", item.label),
                    item.points[k].0,
                    "x > 0 on a logarithmic x axis",
                ));
            }
        }
    }
    render::render(path, format, size, line::LineFigure(plot))
}

/// Draw several line plots stacked from top to bottom in one image (`.png` or `.svg`) of
/// `size` = (width, height) pixels, each in an equal share of the height, with the fonts of
/// the whole image: e.g. two quantities of different units over the same x values, each on
/// its own y axis. Each plot is drawn as [`line_plot`] draws it (give the lower ones an empty
/// title).
///
/// Errors: those of [`line_plot`] for any of the plots (the error names `plots[k]`), or no
/// plots at all.
pub fn line_plots(path: &Path, plots: &[LinePlot], size: (u32, u32)) -> Result<(), PlotError> {
    let format = Format::from_path(path)?;
    validate_size(size)?;
    if plots.is_empty() {
        return Err(PlotError::invalid(
            "plots",
            "an empty list",
            "at least one plot",
        ));
    }
    for (k, plot) in plots.iter().enumerate() {
        validate_series(plot.series).map_err(|e| match e {
            PlotError::InvalidInput {
                field,
                value,
                expected,
            } => PlotError::InvalidInput {
                field: format!("plots[{k}].{field}"),
                value,
                expected,
            },
            other => other,
        })?;
    }
    render::render(path, format, size, line::Panels(plots))
}

/// A polar diagram: one value at each of several angles, drawn as a spoke from a zero circle
/// outwards (e.g. the load of every rolling element at its azimuth).
///
/// The angle runs counter-clockwise from the right (the x axis, as on paper: y up), labelled
/// every 30° in (-180°, 180°] around the rim. The radius of a value is linear from the zero
/// circle (30 % of the outer radius, so that an element without a value still shows as a
/// hollow dot on it) to the outer circle, which is the first round value at or above the
/// largest value; the grid circles carry their values along the ray opposite the largest
/// value. A thin line joins the spokes' tips.
#[derive(Debug, Clone, Copy)]
pub struct PolarPlot<'a> {
    /// Title at the top of the figure.
    pub title: &'a str,
    /// A line under the title, e.g. what the radius and the angle are, with their units.
    pub caption: &'a str,
    /// The (angle in degrees, value ≥ 0) of each spoke; at least one, all finite.
    pub points: &'a [(f64, f64)],
    /// Legend entry of the spokes, e.g. `"roller load [N]"`.
    pub label: &'a str,
    /// Colour of the spokes as (r, g, b).
    pub color: (u8, u8, u8),
    /// An arrow from the centre (e.g. the direction of the radial load), with its legend.
    pub arrow: Option<PolarArrow<'a>>,
    /// A sector shaded between the zero and the outer circle (e.g. the loaded arc), with its
    /// legend.
    pub sector: Option<PolarSector<'a>>,
}

/// An arrow of a [`PolarPlot`]: from the centre towards `angle_deg`, inside the zero circle.
#[derive(Debug, Clone, Copy)]
pub struct PolarArrow<'a> {
    /// Direction in degrees, counter-clockwise from the right.
    pub angle_deg: f64,
    /// Legend entry, e.g. `"radial load 5000 N"`.
    pub label: &'a str,
}

/// A shaded sector of a [`PolarPlot`]: `centre_deg ± half_width_deg`.
#[derive(Debug, Clone, Copy)]
pub struct PolarSector<'a> {
    /// Middle of the sector in degrees, counter-clockwise from the right.
    pub centre_deg: f64,
    /// Half its angular width in degrees, 0 to 180 (180: the whole circle).
    pub half_width_deg: f64,
    /// Legend entry, e.g. `"loaded arc ±97°"`.
    pub label: &'a str,
    /// Colour as (r, g, b); drawn as a light tint of it.
    pub color: (u8, u8, u8),
}

/// Draw a [`PolarPlot`] into `path` (`.png` or `.svg`, see [`Format`]) with the image size
/// `size` = (width, height) in pixels; the legend (the spokes, the sector, the arrow) goes
/// under the disc, one entry a row.
///
/// Errors: an unsupported extension, `size` outside [`MIN_SIZE`]..[`MAX_SIZE`], no points, a
/// non-finite angle, a value that is negative or not finite (the error names `points[k]`), a
/// non-finite arrow angle, a sector whose centre is not finite or whose half width is not
/// within 0..=180°, or a file that cannot be written.
pub fn polar_plot(path: &Path, plot: &PolarPlot, size: (u32, u32)) -> Result<(), PlotError> {
    let format = Format::from_path(path)?;
    validate_size(size)?;
    if plot.points.is_empty() {
        return Err(PlotError::invalid(
            "points",
            "an empty list",
            "at least one point",
        ));
    }
    if let Some(k) = plot
        .points
        .iter()
        .position(|&(a, v)| !(a.is_finite() && v.is_finite() && v >= 0.0))
    {
        let (a, v) = plot.points[k];
        return Err(PlotError::invalid(
            format!("points[{k}]"),
            format!("({a}, {v})"),
            "a finite angle in degrees and a finite value ≥ 0",
        ));
    }
    if let Some(a) = &plot.arrow
        && !a.angle_deg.is_finite()
    {
        return Err(PlotError::invalid(
            "arrow.angle_deg",
            a.angle_deg,
            "a finite angle in degrees",
        ));
    }
    if let Some(s) = &plot.sector
        && !(s.centre_deg.is_finite() && (0.0..=180.0).contains(&s.half_width_deg))
    {
        return Err(PlotError::invalid(
            "sector",
            format!("{} ± {} deg", s.centre_deg, s.half_width_deg),
            "a finite centre and a half width from 0 to 180 deg",
        ));
    }
    render::render(path, format, size, polar::PolarFigure(plot))
}

/// A heat map of cells over two independent axes, each with its own unit (e.g. position
/// along a roller in mm × the roller's azimuth in degrees). Unlike [`FieldMap`] the axes
/// are not drawn to one scale: the cells fill the plot area.
///
/// Value `(i, j)` belongs to the cell `[x_min + i dx, x_min + (i + 1) dx] × [y_min + j dy,
/// y_min + (j + 1) dy]` and is stored row-major with x fastest (index `j*nx + i`); y runs
/// upwards.
#[derive(Debug, Clone, Copy)]
pub struct CellMap<'a> {
    /// Number of cells along x (at least 1).
    pub nx: usize,
    /// Number of cells along y (at least 1).
    pub ny: usize,
    /// Left edge of the grid, in the x axis' unit.
    pub x_min: f64,
    /// Lower edge of the grid, in the y axis' unit.
    pub y_min: f64,
    /// Cell width (finite, > 0).
    pub dx: f64,
    /// Cell height (finite, > 0).
    pub dy: f64,
    /// The values, `nx*ny` of them, all finite; 0 is drawn white (e.g. a lifted-off roller).
    pub values: &'a [f64],
    /// Title at the top of the figure.
    pub title: &'a str,
    /// A line under the title (empty: none).
    pub caption: &'a str,
    /// Label of the x axis with its unit.
    pub x_label: &'a str,
    /// Label of the y axis with its unit.
    pub y_label: &'a str,
    /// Label of the colour bar with its unit.
    pub colorbar_label: &'a str,
    /// Mark the cell of the largest value with a ringed dot, with this legend entry.
    pub max_marker: Option<&'a str>,
}

/// Draw a [`CellMap`] into `path` (`.png` or `.svg`, see [`Format`]) with the image size
/// `size` = (width, height) in pixels: the cells in viridis from min(0, min) to the largest
/// value, zero cells white, a colour bar to the right and the maximum's marker with its
/// legend under the map.
///
/// Errors: an unsupported extension, `size` outside [`MIN_SIZE`]..[`MAX_SIZE`], no cells, a
/// cell size or origin that is not finite (or not > 0), a value count other than `nx*ny` or
/// a non-finite value (the error names `values[k]`), or a file that cannot be written.
pub fn cell_map(path: &Path, map: &CellMap, size: (u32, u32)) -> Result<(), PlotError> {
    let format = Format::from_path(path)?;
    validate_size(size)?;
    if map.nx == 0 || map.ny == 0 {
        return Err(PlotError::invalid(
            "nx, ny",
            format!("{}, {}", map.nx, map.ny),
            "at least one cell along each axis",
        ));
    }
    for (name, v) in [("dx", map.dx), ("dy", map.dy)] {
        if !(v > 0.0 && v.is_finite()) {
            return Err(PlotError::invalid(name, v, "a finite cell size > 0"));
        }
    }
    let x_max = map.x_min + map.nx as f64 * map.dx;
    let y_max = map.y_min + map.ny as f64 * map.dy;
    if !(x_max.is_finite() && y_max.is_finite() && map.x_min.is_finite() && map.y_min.is_finite()) {
        return Err(PlotError::invalid(
            "grid extent",
            format!(
                "x from {} to {x_max}, y from {} to {y_max}",
                map.x_min, map.y_min
            ),
            "a finite grid",
        ));
    }
    let n = map
        .nx
        .checked_mul(map.ny)
        .ok_or_else(|| PlotError::invalid("nx*ny", "overflow", "a grid that fits in memory"))?;
    check_values("values", map.values, n)?;
    let figure = cellmap::CellFigure {
        map,
        frame: std::cell::Cell::new(None),
    };
    render::render(path, format, size, &figure)
}

fn validate_size(size: (u32, u32)) -> Result<(), PlotError> {
    let (w, h) = size;
    if w < MIN_SIZE.0 || h < MIN_SIZE.1 || w > MAX_SIZE || h > MAX_SIZE {
        return Err(PlotError::invalid(
            "size",
            format!("{w}×{h}"),
            format!(
                "at least {}×{} and at most {MAX_SIZE}×{MAX_SIZE} pixels",
                MIN_SIZE.0, MIN_SIZE.1
            ),
        ));
    }
    Ok(())
}

fn validate_field(map: &FieldMap) -> Result<(), PlotError> {
    if map.nx < 2 {
        return Err(PlotError::invalid("nx", map.nx, "at least 2 cells"));
    }
    if map.ny < 2 {
        return Err(PlotError::invalid("ny", map.ny, "at least 2 cells"));
    }
    for (name, v) in [("dx", map.dx), ("dy", map.dy)] {
        if !(v > 0.0) || !v.is_finite() {
            return Err(PlotError::invalid(name, v, "a finite cell size > 0 mm"));
        }
    }
    for (name, v) in [("x_min", map.x_min), ("y_min", map.y_min)] {
        if !v.is_finite() {
            return Err(PlotError::invalid(name, v, "a finite coordinate in mm"));
        }
    }
    // The far edges must be finite too (huge nx*dx).
    let x_max = map.x_min + map.nx as f64 * map.dx;
    let y_max = map.y_min + map.ny as f64 * map.dy;
    if !x_max.is_finite() || !y_max.is_finite() {
        return Err(PlotError::invalid(
            "grid extent",
            format!("x up to {x_max}, y up to {y_max}"),
            "a finite grid",
        ));
    }
    let n = map
        .nx
        .checked_mul(map.ny)
        .ok_or_else(|| PlotError::invalid("nx*ny", "overflow", "a grid that fits in memory"))?;
    check_values("values", map.values, n)?;
    for (k, overlay) in map.overlays.iter().enumerate() {
        check_values(
            &format!("overlays[{k}] ({:?}).values", overlay.label),
            overlay.values,
            n,
        )?;
    }
    if let Some(c) = map.color_max
        && !(c.is_finite() && c > 0.0)
    {
        return Err(PlotError::invalid("color_max", c, "a finite value > 0"));
    }
    if let Some(k) = map.stretch
        && !(k.is_finite() && (1.0..=1000.0).contains(&k) && k.fract() == 0.0)
    {
        return Err(PlotError::invalid(
            "stretch",
            k,
            "a whole number from 1 to 1000",
        ));
    }
    Ok(())
}

fn validate_ellipse(ellipse: Option<&Ellipse>) -> Result<(), PlotError> {
    let Some(e) = ellipse else {
        return Ok(());
    };
    let finite = [e.centre.0, e.centre.1, e.angle]
        .iter()
        .all(|v| v.is_finite());
    let positive = [e.semi_axes.0, e.semi_axes.1]
        .iter()
        .all(|v| v.is_finite() && *v > 0.0);
    if !finite || !positive {
        return Err(PlotError::invalid(
            "ellipse",
            format!(
                "centre ({}, {}), semi-axes ({}, {}), angle {}",
                e.centre.0, e.centre.1, e.semi_axes.0, e.semi_axes.1, e.angle
            ),
            "a finite centre and angle and semi-axes > 0 mm",
        ));
    }
    Ok(())
}

fn validate_arrows(arrows: &[Arrow]) -> Result<(), PlotError> {
    for (i, a) in arrows.iter().enumerate() {
        let finite = [a.x, a.y, a.dx, a.dy, a.x + a.dx, a.y + a.dy]
            .iter()
            .all(|v| v.is_finite());
        if !finite {
            return Err(PlotError::invalid(
                format!("arrows[{i}]"),
                format!(
                    "Arrow {{ x: {}, y: {}, dx: {}, dy: {} }}",
                    a.x, a.y, a.dx, a.dy
                ),
                "finite coordinates in mm (and a finite tip x + dx, y + dy)",
            ));
        }
    }
    Ok(())
}

fn check_values(name: &str, values: &[f64], n: usize) -> Result<(), PlotError> {
    if values.len() != n {
        return Err(PlotError::invalid(
            format!("{name}.len()"),
            values.len(),
            format!("nx*ny = {n}"),
        ));
    }
    if let Some(k) = values.iter().position(|v| !v.is_finite()) {
        return Err(PlotError::invalid(
            format!("{name}[{k}]"),
            values[k],
            "a finite number",
        ));
    }
    Ok(())
}

fn validate_series(series: &[Series]) -> Result<(), PlotError> {
    if series.is_empty() {
        return Err(PlotError::invalid(
            "series",
            "an empty list",
            "at least one series",
        ));
    }
    for (s, item) in series.iter().enumerate() {
        if item.points.is_empty() {
            return Err(PlotError::invalid(
                format!("series[{s}] ({:?}).points", item.label),
                "no points",
                "at least one point",
            ));
        }
        if let Some(k) = item
            .points
            .iter()
            .position(|(x, y)| !x.is_finite() || !y.is_finite())
        {
            let (x, y) = item.points[k];
            return Err(PlotError::invalid(
                format!("series[{s}] ({:?}).points[{k}]", item.label),
                format!("({x}, {y})"),
                "finite coordinates",
            ));
        }
    }
    Ok(())
}
