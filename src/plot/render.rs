//! Draws a [`Figure`] on a plotters backend; writes it as PNG and SVG.

use super::{power_of_two_text, BoxItem, Figure, LegendAt, Panel, Series, Style, Ticks};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::Once;

/// The font family every text uses.
const FONT: &str = "sans-serif";

/// Black, then the Tableau 10 colours.
const PALETTE: [RGBColor; 8] = [
    RGBColor(0, 0, 0),
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(23, 190, 207),
];

fn colour(index: usize) -> RGBColor {
    PALETTE[index % PALETTE.len()]
}

/// Registers DejaVu Sans as the family [`FONT`] with ab_glyph (plotters keeps one
/// process-wide font table; registering once is enough).
fn register_font() -> Result<(), String> {
    static REGISTER: Once = Once::new();
    let mut result = Ok(());
    REGISTER.call_once(|| {
        result = plotters::style::register_font(FONT, FontStyle::Normal, dejavu::sans::regular())
            .map_err(|_| "the embedded DejaVu Sans font cannot be read".to_string());
    });
    result
}

/// Writes `figure` to `stem.png` and `stem.svg`, each anew atomically (`files::replace`:
/// a kill never leaves a figure cut); returns the two paths.
pub fn write_figure(figure: &Figure, stem: &Path) -> Result<[PathBuf; 2], String> {
    register_font()?;
    let png = stem.with_extension("png");
    let svg = stem.with_extension("svg");
    let (width, height) = figure.size;
    let mut pixels = vec![0u8; 3 * width as usize * height as usize];
    {
        let root = BitMapBackend::with_buffer(&mut pixels, figure.size).into_drawing_area();
        draw(&root, figure).map_err(|e| format!("{}: {e}", png.display()))?;
        root.present()
            .map_err(|e| format!("{}: {e}", png.display()))?;
    }
    write_png(&png, figure.size, &pixels)?;
    let mut text = String::new();
    {
        let root = SVGBackend::with_string(&mut text, figure.size).into_drawing_area();
        draw(&root, figure).map_err(|e| format!("{}: {e}", svg.display()))?;
        root.present()
            .map_err(|e| format!("{}: {e}", svg.display()))?;
    }
    slowdrift::files::replace(&svg, |w| std::io::Write::write_all(w, text.as_bytes()))
        .map_err(|e| e.to_string())?;
    Ok([png, svg])
}

/// Writes 8-bit RGB `pixels` as a PNG with the encoder's best compression and adaptive
/// row filters (a third of the size of plotters' default encoding for these figures).
fn write_png(path: &Path, (width, height): (u32, u32), pixels: &[u8]) -> Result<(), String> {
    slowdrift::files::replace(path, |w| {
        let mut encoder = png::Encoder::new(w, width, height);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        encoder.set_compression(png::Compression::Best);
        encoder.set_adaptive_filter(png::AdaptiveFilterType::Adaptive);
        let mut writer = encoder.write_header().map_err(std::io::Error::other)?;
        writer
            .write_image_data(pixels)
            .map_err(std::io::Error::other)?;
        writer.finish().map_err(std::io::Error::other)
    })
    .map_err(|e| e.to_string())
}

type DrawResult<DB> = Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

fn draw<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, figure: &Figure) -> DrawResult<DB> {
    root.fill(&WHITE)?;
    let body = root.titled(&figure.title, (FONT, 24))?;
    let columns = figure.columns.max(1);
    let rows = figure.panels.len().div_ceil(columns).max(1);
    for (area, panel) in body
        .split_evenly((rows, columns))
        .iter()
        .zip(&figure.panels)
    {
        draw_panel(area, panel)?;
    }
    Ok(())
}

fn tick_text(ticks: Ticks, value: f64) -> String {
    match ticks {
        Ticks::Plain => {
            let text = format!("{value:.3}");
            let text = text.trim_end_matches('0').trim_end_matches('.');
            if text == "-0" {
                "0".into()
            } else {
                text.into()
            }
        }
        Ticks::PowerOfTwo => {
            let exponent = value.round();
            if (value - exponent).abs() > 1e-9 {
                return String::new();
            }
            power_of_two_text(exponent as i64)
        }
    }
}

fn draw_panel<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, panel: &Panel) -> DrawResult<DB> {
    let (x0, x1) = panel.x_range;
    let (y0, y1) = panel.y_range;
    let mut chart = ChartBuilder::on(area)
        .caption(&panel.title, (FONT, 17))
        .margin(10)
        .x_label_area_size(45)
        .y_label_area_size(65)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    let x_ticks = panel.x_ticks;
    let x_format = |v: &f64| tick_text(x_ticks, *v);
    let y_format = |v: &f64| tick_text(Ticks::Plain, *v);
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .label_style((FONT, 13))
        .axis_desc_style((FONT, 15))
        .x_label_formatter(&x_format)
        .y_label_formatter(&y_format)
        .light_line_style(TRANSPARENT)
        .bold_line_style(RGBColor(225, 225, 225));
    if x_ticks == Ticks::PowerOfTwo {
        mesh.x_labels(((x1 - x0).round() as usize + 1).max(2));
    }
    mesh.draw()?;

    for item in &panel.boxes {
        draw_box(&mut chart, item)?;
    }
    let mut labelled = false;
    for series in &panel.series {
        labelled |= draw_series(&mut chart, series)?;
    }
    if labelled {
        let position = match panel.legend {
            LegendAt::UpperRight => SeriesLabelPosition::UpperRight,
            LegendAt::LowerRight => SeriesLabelPosition::LowerRight,
        };
        chart
            .configure_series_labels()
            .position(position)
            .label_font((FONT, 13))
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(160, 160, 160))
            .draw()?;
    }
    Ok(())
}

type Chart<'a, DB> = ChartContext<
    'a,
    DB,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// Draws one series; true when it has a legend entry.
fn draw_series<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    series: &Series,
) -> Result<bool, DrawingAreaErrorKind<DB::ErrorType>> {
    let c = colour(series.colour);
    // Points beyond the y range are drawn on its edge (plotters does not clip lines).
    let (y0, y1) = (chart.y_range().start, chart.y_range().end);
    let points = series
        .points
        .iter()
        .map(move |&(x, y)| (x, y.clamp(y0, y1)));
    let annotation =
        match series.style {
            Style::Line => chart.draw_series(LineSeries::new(points, c.stroke_width(2)))?,
            Style::Trace => chart.draw_series(LineSeries::new(points, c.stroke_width(1)))?,
            Style::Dashed => {
                chart.draw_series(DashedLineSeries::new(points, 8, 5, c.stroke_width(2)))?
            }
            Style::Markers => {
                chart.draw_series(LineSeries::new(points.clone(), c.stroke_width(1)))?;
                chart.draw_series(series.points.iter().zip(&series.errors).map(
                    |(&(x, y), &e)| {
                        ErrorBar::new_vertical(x, y - e, y, y + e, c.stroke_width(2), 10)
                    },
                ))?;
                chart.draw_series(points.map(|p| Circle::new(p, 4, c.filled())))?
            }
        };
    if series.label.is_empty() {
        return Ok(false);
    }
    let dashed = series.style == Style::Dashed;
    annotation
        .label(series.label.as_str())
        .legend(move |(x, y)| {
            let style = c.stroke_width(2);
            if dashed {
                PathElement::new(vec![(x, y), (x + 7, y)], style)
            } else {
                PathElement::new(vec![(x, y), (x + 20, y)], style)
            }
        });
    Ok(true)
}

fn draw_box<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, item: &BoxItem) -> DrawResult<DB> {
    let s = &item.stats;
    let (x, half) = (item.x, 0.5 * item.width);
    let line = colour(1).stroke_width(2);
    chart.draw_series(std::iter::once(Rectangle::new(
        [(x - half, s.q1), (x + half, s.q3)],
        colour(1).mix(0.18).filled(),
    )))?;
    chart.draw_series(std::iter::once(Rectangle::new(
        [(x - half, s.q1), (x + half, s.q3)],
        line,
    )))?;
    let segments = [
        vec![(x - half, s.median), (x + half, s.median)],
        vec![(x, s.q3), (x, s.upper_whisker)],
        vec![(x, s.q1), (x, s.lower_whisker)],
        vec![
            (x - 0.5 * half, s.upper_whisker),
            (x + 0.5 * half, s.upper_whisker),
        ],
        vec![
            (x - 0.5 * half, s.lower_whisker),
            (x + 0.5 * half, s.lower_whisker),
        ],
    ];
    for (i, segment) in segments.into_iter().enumerate() {
        let style = if i == 0 {
            colour(2).stroke_width(3)
        } else {
            line
        };
        chart.draw_series(std::iter::once(PathElement::new(segment, style)))?;
    }
    chart.draw_series(
        s.outliers
            .iter()
            .map(|&y| Circle::new((x, y), 2, colour(1).mix(0.6).filled())),
    )?;
    Ok(())
}
