//! Figures as data ([`Figure`], [`Panel`], [`Series`], [`BoxItem`]) and their rendering to
//! PNG and SVG with `plotters`: no physics here, and nothing the machine must provide.
//!
//! Text in the PNG is rasterised by ab_glyph from DejaVu Sans compiled into the binary (the
//! `dejavu` crate; the DejaVu/Bitstream Vera licence allows embedding); the SVG names the
//! family `sans-serif` and leaves the text to the viewer.

mod render;

pub use render::write_figure;

/// A figure: a title over a grid of panels, filled row by row.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    pub title: String,
    pub panels: Vec<Panel>,
    /// Panels per row.
    pub columns: usize,
    /// Size in pixels (PNG) and user units (SVG).
    pub size: (u32, u32),
}

/// How tick values on an axis are written.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Ticks {
    /// The value itself.
    Plain,
    /// The axis holds log2 of the quantity: the tick at 14 reads "2^14" (superscript).
    PowerOfTwo,
}

/// Where a panel's legend goes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LegendAt {
    UpperRight,
    LowerRight,
}

/// One chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    pub title: String,
    /// Axis descriptions with their units, e.g. "surge mean [m]".
    pub x_label: String,
    pub y_label: String,
    pub x_range: (f64, f64),
    pub y_range: (f64, f64),
    pub x_ticks: Ticks,
    pub series: Vec<Series>,
    pub boxes: Vec<BoxItem>,
    pub legend: LegendAt,
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Style {
    /// A solid line through the points.
    Line,
    /// A 1-pixel line through many noisy points (a wide line's mitred joins would spike
    /// beyond the data at sharp turns).
    Trace,
    /// A dashed line through the points (references: the Gaussian, the input spectrum).
    Dashed,
    /// Markers at the points, joined by a thin line, with vertical error bars when given.
    Markers,
}

/// A named set of points.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text (empty: not in the legend).
    pub label: String,
    pub points: Vec<(f64, f64)>,
    /// Half-height of each point's error bar (same length as `points`), or empty.
    pub errors: Vec<f64>,
    pub style: Style,
    /// Index into the palette; 0 is black (references).
    pub colour: usize,
}

/// A Tukey box at x: box q1-q3, median line, whiskers, outliers as dots.
#[derive(Debug, Clone, PartialEq)]
pub struct BoxItem {
    pub x: f64,
    /// Box width in x units.
    pub width: f64,
    pub stats: slowdrift::studies::distribution::BoxStats,
}

impl Series {
    pub fn new(
        label: impl Into<String>,
        points: Vec<(f64, f64)>,
        style: Style,
        colour: usize,
    ) -> Self {
        Series {
            label: label.into(),
            points,
            errors: Vec::new(),
            style,
            colour,
        }
    }

    /// The same series with error bars of half-height `errors`.
    pub fn with_errors(mut self, errors: Vec<f64>) -> Self {
        self.errors = errors;
        self
    }
}

/// "2" with `exponent` in superscript digits, e.g. 2¹⁴.
pub fn power_of_two_text(exponent: i64) -> String {
    const SUPERSCRIPT: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let digits: String = exponent
        .to_string()
        .chars()
        .map(|c| c.to_digit(10).map_or('⁻', |d| SUPERSCRIPT[d as usize]))
        .collect();
    format!("2{digits}")
}

/// A range that holds every value in `values` with `pad` of its span added on each side
/// (a unit span around a single value).
pub fn padded_range(values: impl IntoIterator<Item = f64>, pad: f64) -> (f64, f64) {
    let (lo, hi) = values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let span = if hi > lo { hi - lo } else { lo.abs().max(1.0) };
    (lo - pad * span, hi + pad * span)
}
