//! Backends, the bundled font, output files and layout helpers shared by the plot kinds.

use std::path::Path;
use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{FontFamily, FontStyle, register_font};

use crate::{Format, PlotError};

/// DejaVu Sans (Bitstream Vera licence, see `assets/LICENSE-DejaVu.txt`).
static FONT: &[u8] = include_bytes!("../assets/DejaVuSans.ttf");

/// Register the bundled font as plotters' "sans-serif" family (once per process).
fn ensure_font() -> Result<(), PlotError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok =
        *REGISTERED.get_or_init(|| register_font("sans-serif", FontStyle::Normal, FONT).is_ok());
    if ok {
        Ok(())
    } else {
        Err(PlotError::Drawing(
            "the bundled DejaVu Sans font could not be loaded".into(),
        ))
    }
}

/// The characters of `s` that the bundled font has no glyph for (drawn as blanks), in
/// order of first appearance. Labels such as `"μ = |Fₜ| / Q"` can be checked with it.
pub fn missing_glyphs(s: &str) -> Vec<char> {
    use ab_glyph::{Font, FontRef};
    let Ok(font) = FontRef::try_from_slice(FONT) else {
        return s.chars().collect();
    };
    let mut missing = Vec::new();
    for c in s.chars() {
        if !c.is_whitespace() && font.glyph_id(c).0 == 0 && !missing.contains(&c) {
            missing.push(c);
        }
    }
    missing
}

/// The drawing target handed to a figure: the root area and whether it is a raster image.
pub(crate) struct Target<DB: DrawingBackend> {
    pub root: DrawingArea<DB, Shift>,
    pub raster: bool,
}

/// Something that draws itself on any backend.
pub(crate) trait Figure {
    fn draw<DB: DrawingBackend>(&self, target: &Target<DB>) -> Result<(), PlotError>;
}

/// Render a figure to `path` in `format`.
pub(crate) fn render<F: Figure>(
    path: &Path,
    format: Format,
    size: (u32, u32),
    figure: F,
) -> Result<(), PlotError> {
    ensure_font()?;
    let bytes = match format {
        Format::Png => {
            let (w, h) = size;
            let mut buf = vec![255u8; w as usize * h as usize * 3];
            {
                let root = BitMapBackend::with_buffer(&mut buf, size).into_drawing_area();
                let target = Target { root, raster: true };
                figure.draw(&target)?;
                target.root.present().de()?;
            }
            encode_png(&buf, size)?
        }
        Format::Svg => {
            let mut svg = String::new();
            {
                let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
                let target = Target {
                    root,
                    raster: false,
                };
                figure.draw(&target)?;
                target.root.present().de()?;
            }
            svg.into_bytes()
        }
    };
    std::fs::write(path, bytes).map_err(|source| PlotError::Io {
        path: path.to_path_buf(),
        source,
    })
}

fn encode_png(rgb: &[u8], (w, h): (u32, u32)) -> Result<Vec<u8>, PlotError> {
    let fail = |e: png::EncodingError| PlotError::Drawing(format!("PNG encoding failed: {e}"));
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, w, h);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(fail)?;
    writer.write_image_data(rgb).map_err(fail)?;
    writer.finish().map_err(fail)?;
    Ok(out)
}

/// Converts plotters' drawing errors into [`PlotError::Drawing`].
pub(crate) trait DrawResultExt<T> {
    fn de(self) -> Result<T, PlotError>;
}

impl<T, E: std::error::Error + Send + Sync> DrawResultExt<T>
    for Result<T, plotters::drawing::DrawingAreaErrorKind<E>>
{
    fn de(self) -> Result<T, PlotError> {
        self.map_err(|e| PlotError::Drawing(e.to_string()))
    }
}

/// Font sizes and line widths in pixels, scaled with the image size.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Metrics {
    /// Scale relative to an 800×600 figure.
    pub scale: f64,
    pub title: f64,
    pub label: f64,
    pub tick: f64,
    pub margin: i32,
    pub tick_len: i32,
    pub line: u32,
}

impl Metrics {
    pub fn new((w, h): (u32, u32)) -> Self {
        let scale = (f64::from(w) / 800.0).min(f64::from(h) / 600.0);
        Metrics {
            scale,
            title: (24.0 * scale).max(10.0),
            label: (19.0 * scale).max(9.0),
            tick: (16.0 * scale).max(8.0),
            margin: (16.0 * scale).round().max(5.0) as i32,
            tick_len: (6.0 * scale).round().max(3.0) as i32,
            line: (2.0 * scale).round().max(1.0) as u32,
        }
    }
}

/// Black sans-serif text of `size` pixels.
pub(crate) fn text(size: f64) -> TextStyle<'static> {
    TextStyle::from(FontDesc::new(
        FontFamily::SansSerif,
        size,
        FontStyle::Normal,
    ))
    .color(&BLACK)
}

/// Width and height of `s` in `style` on `area`, in pixels.
pub(crate) fn text_size<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    s: &str,
    style: &TextStyle,
) -> Result<(i32, i32), PlotError> {
    if s.is_empty() {
        return Ok((0, 0));
    }
    let (w, h) = area.estimate_text_size(s, style).de()?;
    Ok((w as i32, h as i32))
}

/// Height of an axis description (label) line in pixels; 0 for an empty one.
pub(crate) fn desc_height(s: &str, m: &Metrics) -> i32 {
    if s.is_empty() {
        0
    } else {
        (m.label * 1.35).round() as i32
    }
}

/// Width in pixels of the widest label of `ticks` in `style`.
pub(crate) fn labels_width<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    ticks: &crate::ticks::Ticks,
    style: &TextStyle,
) -> Result<i32, PlotError> {
    let mut wmax = 0;
    for s in ticks.labels() {
        wmax = wmax.max(text_size(area, &s, style)?.0);
    }
    Ok(wmax)
}

/// Height taken by the title, including the space below it.
pub(crate) fn title_height(title: &str, m: &Metrics) -> i32 {
    if title.is_empty() {
        0
    } else {
        (m.title * 1.45).round() as i32
    }
}

/// Draw the title centred horizontally with its top at `y` (shrunk to fit the width).
pub(crate) fn draw_title<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
    m: &Metrics,
    y: i32,
) -> Result<(), PlotError> {
    draw_line_of_text(root, title, m.title, m, y)
}

/// Draw a line of text of `size` pixels centred horizontally with its top at `y`, shrunk to
/// fit the width between the margins. An empty string draws nothing.
pub(crate) fn draw_line_of_text<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    s: &str,
    size: f64,
    m: &Metrics,
    y: i32,
) -> Result<(), PlotError> {
    if s.is_empty() {
        return Ok(());
    }
    let (w, _) = root.dim_in_pixel();
    let w = w as i32;
    let mut size = size;
    let (tw, _) = text_size(root, s, &text(size))?;
    let avail = w - 2 * m.margin;
    if tw > avail && tw > 0 {
        size = (size * f64::from(avail) / f64::from(tw)).max(7.0);
    }
    let style = text(size).pos(Pos::new(HPos::Center, VPos::Top));
    root.draw_text(s, &style, (w / 2, y)).de()
}

/// Draw text centred at a point.
pub(crate) fn draw_centered<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    s: &str,
    size: f64,
    at: (i32, i32),
) -> Result<(), PlotError> {
    let style = text(size).pos(Pos::new(HPos::Center, VPos::Center));
    root.draw_text(s, &style, at).de()
}

/// Plotters colour of an (r, g, b) triple.
pub(crate) fn rgb((r, g, b): (u8, u8, u8)) -> RGBColor {
    RGBColor(r, g, b)
}
