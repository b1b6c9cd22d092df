//! `slowdrift study waves`: the elevation's pdf against the Gaussian and its spectrum against
//! the input for record lengths 2^11 .. 2^17 s (E&S Figs 7, 8).

use super::{report, sea_text, write_text, WavesArgs};
use crate::cli::args::all_cores;
use crate::plot::{
    padded_range, power_of_two_text, write_figure, Figure, LegendAt, Panel, Series, Style, Ticks,
};
use slowdrift::stats::welch_spectrum;
use slowdrift::studies::distribution::{gaussian_pdf, histogram_pdf};
use slowdrift::studies::parallel_map;
use slowdrift::studies::waves::elevation_record;
use slowdrift::Problem;
use std::fmt::Write as _;

/// Welch segment of the elevation spectra, s (a resolution of 2 pi / 2048 = 0.003 rad/s).
const SPECTRUM_SEGMENT: f64 = 2048.0;

/// Histogram bins of the elevation pdf over +-4 standard deviations.
const PDF_BINS: usize = 40;

const PDF_HALF_WIDTH: f64 = 4.0;

/// The integral of S(omega)^power over the simulated band by the trapezoidal rule on 20 000
/// intervals; power 1 is the variance the synthesis targets (E&S 5-6), m^2.
fn band_integral(problem: &Problem, power: i32) -> f64 {
    const INTERVALS: usize = 20_000;
    let (lo, hi) = problem.sea.band();
    let h = (hi - lo) / INTERVALS as f64;
    let s = |i: usize| problem.sea.spectrum.density(lo + i as f64 * h).powi(power);
    h * ((1..INTERVALS).map(s).sum::<f64>() + 0.5 * (s(0) + s(INTERVALS)))
}

/// The relative standard deviation of a record's variance from its spectrum: the record of
/// length L has variance sum |a_n|^2 / 2 with |a_n|^2 exponentially distributed of mean
/// 2 S(w_n) dw (E&S 5), so sd / mean = sqrt(dw sum S^2 dw) / m0 -> sqrt((2 pi / L)
/// integral S^2 dw) / integral S dw.
fn variance_relative_sd(problem: &Problem, length: f64) -> f64 {
    (2.0 * std::f64::consts::PI / length * band_integral(problem, 2)).sqrt()
        / band_integral(problem, 1)
}

fn length_label(exponent: u32) -> String {
    format!("{} s", power_of_two_text(exponent.into()))
}

/// Figs 7 and 8: elevation pdf against the Gaussian and Welch spectrum against the input,
/// one panel per record length 2^A .. 2^B s, and a last panel of the convergence.
pub(super) fn waves(base: &Problem, args: &WavesArgs) -> Result<(), String> {
    let exponents = &args.exponents.0;
    let out = args.out.as_path();
    let variance = band_integral(base, 1);
    let sigma = variance.sqrt();
    let (band_lo, band_hi) = base.sea.band();
    let wp = base.sea.spectrum.peak_frequency();
    let records = parallel_map(exponents.len(), all_cores(), |i| {
        elevation_record(base, 2f64.powi(exponents[i] as i32))
    });
    let mut pdf_panels = Vec::new();
    let mut spectrum_panels = Vec::new();
    let (mut variance_ratio, mut spectrum_error) = (Vec::new(), Vec::new());
    let mut csv = String::from("record_length_s,samples,variance_m2,band_variance_m2,variance_ratio,excess_kurtosis,spectrum_rms_relative_error\n");
    let s_max = (0..400)
        .map(|i| {
            base.sea
                .spectrum
                .density(band_lo + i as f64 * (band_hi - band_lo) / 400.0)
        })
        .fold(0.0, f64::max);
    for (&k, record) in exponents.iter().zip(records) {
        let record = record.map_err(|e| e.to_string())?;
        let n = record.samples.len() as f64;
        let mean = record.samples.iter().sum::<f64>() / n;
        let var = record
            .samples
            .iter()
            .map(|x| (x - mean).powi(2))
            .sum::<f64>()
            / n;
        let kurtosis = record
            .samples
            .iter()
            .map(|x| (x - mean).powi(4))
            .sum::<f64>()
            / n
            / (var * var)
            - 3.0;
        let histogram = histogram_pdf(
            &record.samples,
            -PDF_HALF_WIDTH * sigma,
            PDF_HALF_WIDTH * sigma,
            PDF_BINS,
        )
        .map_err(|e| e.to_string())?;
        let mut steps = Vec::new();
        for (b, d) in histogram.density.iter().enumerate() {
            steps.push((histogram.edges[b], *d));
            steps.push((histogram.edges[b + 1], *d));
        }
        let gauss: Vec<(f64, f64)> = (0..=200)
            .map(|i| {
                let x = -PDF_HALF_WIDTH * sigma + i as f64 * 2.0 * PDF_HALF_WIDTH * sigma / 200.0;
                (x, gaussian_pdf(x, 0.0, sigma))
            })
            .collect();
        let peak = gaussian_pdf(0.0, 0.0, sigma);
        pdf_panels.push(Panel {
            title: format!("record {}", length_label(k)),
            x_label: "elevation η [m]".into(),
            y_label: "probability density [1/m]".into(),
            x_range: (-PDF_HALF_WIDTH * sigma, PDF_HALF_WIDTH * sigma),
            y_range: (0.0, 1.3 * peak),
            x_ticks: Ticks::Plain,
            series: vec![
                Series::new("simulated", steps, Style::Line, 1),
                Series::new(
                    format!("Gaussian, σ = {sigma:.2} m"),
                    gauss,
                    Style::Dashed,
                    0,
                ),
            ],
            boxes: Vec::new(),
            legend: LegendAt::UpperRight,
        });

        let segment = ((SPECTRUM_SEGMENT / record.dt).round() as usize).min(record.samples.len());
        let welch =
            welch_spectrum(&record.samples, record.dt, segment).map_err(|e| e.to_string())?;
        let shown: Vec<(f64, f64)> = welch
            .omega
            .iter()
            .zip(&welch.density)
            .filter(|(w, _)| **w <= 3.0 * wp)
            .map(|(w, s)| (*w, *s))
            .collect();
        let input: Vec<(f64, f64)> = (0..=300)
            .map(|i| {
                let w = i as f64 * 3.0 * wp / 300.0;
                (
                    w,
                    if (band_lo..=band_hi).contains(&w) {
                        base.sea.spectrum.density(w)
                    } else {
                        0.0
                    },
                )
            })
            .collect();
        // rms relative error of the estimate against the input over 0.8 .. 1.5 wp, where the
        // spectrum holds most of its energy.
        let errors: Vec<f64> = welch
            .omega
            .iter()
            .zip(&welch.density)
            .filter(|(w, _)| (0.8 * wp..=1.5 * wp).contains(*w))
            .map(|(w, s)| s / base.sea.spectrum.density(*w) - 1.0)
            .collect();
        let rms_error =
            (errors.iter().map(|e| e * e).sum::<f64>() / errors.len().max(1) as f64).sqrt();
        spectrum_panels.push(Panel {
            title: format!(
                "record {} ({} Welch segment{})",
                length_label(k),
                record.samples.len() / segment.max(1) * 2 - 1,
                if record.samples.len() / segment > 1 {
                    "s"
                } else {
                    ""
                }
            ),
            x_label: "ω [rad/s]".into(),
            y_label: "S(ω) [m² s/rad]".into(),
            x_range: (0.0, 3.0 * wp),
            y_range: (0.0, 2.0 * s_max),
            x_ticks: Ticks::Plain,
            series: vec![
                Series::new("simulated (Welch)", shown, Style::Trace, 1),
                Series::new("input JONSWAP", input, Style::Dashed, 0),
            ],
            boxes: Vec::new(),
            legend: LegendAt::UpperRight,
        });
        variance_ratio.push((k as f64, var / variance));
        spectrum_error.push((k as f64, rms_error.log2()));
        writeln!(
            csv,
            "{},{},{var},{variance},{},{kurtosis},{rms_error}",
            2u64.pow(k),
            record.samples.len(),
            var / variance
        )
        .ok();
    }
    let (k0, k1) = (
        exponents[0] as f64 - 0.5,
        *exponents.last().unwrap_or(&17) as f64 + 0.5,
    );
    let band = |sign: f64| -> Vec<(f64, f64)> {
        (0..=40)
            .map(|i| {
                let k = k0 + i as f64 * (k1 - k0) / 40.0;
                (k, 1.0 + sign * 2.0 * variance_relative_sd(base, k.exp2()))
            })
            .collect()
    };
    let (band_upper, band_lower) = (band(1.0), band(-1.0));
    pdf_panels.push(Panel {
        title: "record variance / band variance of S".into(),
        x_label: "record length [s]".into(),
        y_label: "variance ratio [-]".into(),
        x_range: (k0, k1),
        y_range: padded_range(
            variance_ratio
                .iter()
                .map(|p| p.1)
                .chain(band_upper.iter().chain(&band_lower).map(|p| p.1)),
            0.1,
        ),
        x_ticks: Ticks::PowerOfTwo,
        series: vec![
            Series::new("expected ± 2 sd", band_upper, Style::Dashed, 0),
            Series::new("", band_lower, Style::Dashed, 0),
            Series::new("simulated", variance_ratio, Style::Markers, 1),
        ],
        boxes: Vec::new(),
        legend: LegendAt::UpperRight,
    });
    let last = spectrum_error.last().copied().unwrap_or((k1, 0.0));
    let reference: Vec<(f64, f64)> = [k0, k1]
        .iter()
        .map(|&k| (k, last.1 - 0.5 * (k - last.0)))
        .collect();
    spectrum_panels.push(Panel {
        title: "rms relative error, 0.8-1.5 ωp (log₂)".into(),
        x_label: "record length [s]".into(),
        y_label: "log₂ rms relative error [-]".into(),
        x_range: (k0, k1),
        y_range: padded_range(
            spectrum_error
                .iter()
                .map(|p| p.1)
                .chain(reference.iter().map(|p| p.1)),
            0.1,
        ),
        x_ticks: Ticks::PowerOfTwo,
        series: vec![
            Series::new("∝ length^-1/2", reference, Style::Dashed, 0),
            Series::new("Welch vs input", spectrum_error, Style::Markers, 1),
        ],
        boxes: Vec::new(),
        legend: LegendAt::UpperRight,
    });
    let sea = sea_text(base);
    let fig7 = Figure {
        title: format!("Elevation pdf vs Gaussian (E&S Fig. 7): {sea}"),
        panels: pdf_panels,
        columns: 4,
        size: (1600, 820),
    };
    let fig8 = Figure {
        title: format!("Elevation spectrum vs input (E&S Fig. 8): {sea}, Welch segments of {SPECTRUM_SEGMENT} s, Hann, 50 % overlap"),
        panels: spectrum_panels,
        columns: 4,
        size: (1600, 820),
    };
    let csv_path = out.join("fig7_fig8_waves.csv");
    write_text(&csv_path, &csv)?;
    let mut written = vec![csv_path];
    written.extend(write_figure(&fig7, &out.join("fig7_elevation_pdf"))?);
    written.extend(write_figure(&fig8, &out.join("fig8_elevation_spectrum"))?);
    print!("{csv}");
    report(&written);
    Ok(())
}
