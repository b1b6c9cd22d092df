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

#[cfg(test)]
mod tests {
    use super::*;
    use slowdrift::studies::distribution::box_stats;

    /// A figure with every element: lines, dashed references, markers with error bars,
    /// boxes with outliers, power-of-two ticks.
    fn figure() -> Figure {
        let line = Series::new("line", vec![(0.0, 0.0), (1.0, 1.0)], Style::Line, 1);
        let dashed = Series::new("reference", vec![(0.0, 1.0), (1.0, 0.0)], Style::Dashed, 0);
        let trace = Series::new(
            "",
            vec![(0.0, 0.5), (0.5, 9.0), (1.0, 0.5)],
            Style::Trace,
            3,
        );
        let markers = Series::new("mean ± se", vec![(0.2, 0.4), (0.8, 0.6)], Style::Markers, 2)
            .with_errors(vec![0.1, 0.05]);
        let boxes = vec![BoxItem {
            x: 12.0,
            width: 0.5,
            stats: box_stats(&[1.0, 2.0, 3.0, 4.0, 5.0, 30.0]).unwrap(),
        }];
        Figure {
            title: "Test figure η σ ω²".into(),
            panels: vec![
                Panel {
                    title: "lines".into(),
                    x_label: "time t [s]".into(),
                    y_label: "surge X [m]".into(),
                    x_range: (0.0, 1.0),
                    y_range: (0.0, 1.0),
                    x_ticks: Ticks::Plain,
                    series: vec![line, dashed, trace, markers],
                    boxes: Vec::new(),
                    legend: LegendAt::UpperRight,
                },
                Panel {
                    title: "boxes".into(),
                    x_label: "record length [s]".into(),
                    y_label: "surge mean [m]".into(),
                    x_range: (11.0, 13.0),
                    y_range: padded_range([1.0, 30.0], 0.05),
                    x_ticks: Ticks::PowerOfTwo,
                    series: Vec::new(),
                    boxes,
                    legend: LegendAt::LowerRight,
                },
            ],
            columns: 2,
            size: (640, 300),
        }
    }

    /// The PNG has the PNG signature and decodes to the declared size with drawn (non-white)
    /// pixels, among them text; the SVG is well-formed XML holding the axis labels, the
    /// titles and the tick text as text.
    #[test]
    fn writes_a_valid_png_and_svg() {
        let dir = std::env::temp_dir().join(format!("slowdrift-plot-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let [png_path, svg_path] = write_figure(&figure(), &dir.join("figure")).unwrap();

        let bytes = std::fs::read(&png_path).unwrap();
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
        let mut reader = png::Decoder::new(std::io::Cursor::new(&bytes))
            .read_info()
            .unwrap();
        let mut pixels = vec![0; reader.output_buffer_size()];
        let info = reader.next_frame(&mut pixels).unwrap();
        assert_eq!((info.width, info.height), (640, 300));
        assert_eq!(info.color_type, png::ColorType::Rgb);
        let pixels = &pixels[..info.buffer_size()];
        let drawn = pixels.chunks(3).filter(|p| p != &[255, 255, 255]).count();
        assert!(drawn > 2000, "only {drawn} drawn pixels");
        // The title row (top 20 px) holds anti-aliased glyphs: grey levels, not only
        // black and white, so the font was rasterised.
        let title_row = &pixels[..20 * 640 * 3];
        let greys = title_row
            .chunks(3)
            .filter(|p| p[0] == p[1] && p[0] > 20 && p[0] < 235)
            .count();
        assert!(greys > 50, "no anti-aliased text in the title: {greys}");

        let text = std::fs::read_to_string(&svg_path).unwrap();
        // Well-formed: quick-xml reads every event to the end without an error. A text
        // element's content may arrive in pieces (text and entity references).
        use quick_xml::events::Event;
        let mut reader = quick_xml::Reader::from_str(&text);
        let (mut texts, mut elements, mut current) = (Vec::new(), 0, String::new());
        loop {
            match reader.read_event().unwrap() {
                Event::Eof => break,
                Event::Start(_) | Event::Empty(_) => elements += 1,
                Event::Text(t) => current.push_str(&t.xml10_content()),
                Event::GeneralRef(r) => match r.resolve_char_ref().unwrap() {
                    Some(c) => current.push(c),
                    None => current.push_str(match r.as_ref() {
                        "amp" => "&",
                        "lt" => "<",
                        "gt" => ">",
                        "quot" => "\"",
                        other => panic!("unknown entity {other}"),
                    }),
                },
                Event::End(_) => texts.push(std::mem::take(&mut current).trim().to_string()),
                _ => {}
            }
        }
        assert!(elements > 50, "{elements} elements");
        for label in [
            "time t [s]",
            "surge X [m]",
            "record length [s]",
            "surge mean [m]",
            "Test figure η σ ω²",
            "mean ± se",
            "2¹²",
        ] {
            assert!(
                texts.iter().any(|t| t == label),
                "'{label}' not in the SVG text: {texts:?}"
            );
        }
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn power_of_two_labels_and_padded_ranges() {
        assert_eq!(power_of_two_text(17), "2¹⁷");
        assert_eq!(power_of_two_text(-3), "2⁻³");
        assert_eq!(padded_range([1.0, 3.0], 0.5), (0.0, 4.0));
        assert_eq!(padded_range([2.0], 0.5), (1.0, 3.0));
        assert_eq!(padded_range([f64::NAN], 0.5), (0.0, 1.0));
    }
}
