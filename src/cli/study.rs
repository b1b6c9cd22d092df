//! `slowdrift study <waves|boxplots|transient|sensitivity>`: the paper's studies (E&S 1996
//! Figs 7-15) for a platform, each written as data (CSV) and as a figure (PNG and SVG) in
//! `--out DIR`. The computations are [`slowdrift::studies`] and the Monte Carlo campaign
//! of `slowdrift montecarlo` (resumable: the per-run files in DIR are read back and only
//! missing runs are made); the drawing is [`crate::plot`].

use crate::cli::montecarlo::run_campaign;
use crate::plot::{
    padded_range, power_of_two_text, write_figure, BoxItem, Figure, LegendAt, Panel, Series, Style,
    Ticks,
};
use slowdrift::config::default_platform::{default_config, DEFAULT_DRIFT_LABEL};
use slowdrift::config::{file, Config, TRANSIENT_CYCLES};
use slowdrift::montecarlo::cases::read_case_table;
use slowdrift::montecarlo::runs_file::RunRow;
use slowdrift::montecarlo::{seed_statistics, simulate_positions, Case, Job, SeedStatistics};
use slowdrift::stats::welch_spectrum;
use slowdrift::studies::blocks::block_summaries;
use slowdrift::studies::distribution::{
    box_stats, gaussian_pdf, histogram_pdf, log_log_slope, sample_std,
};
use slowdrift::studies::parallel_map;
use slowdrift::studies::waves::elevation_record;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

pub const USAGE: &str = "slowdrift study waves [--config FILE.toml] [--exponents 11..17] --out DIR
       slowdrift study boxplots [--config FILE.toml] [--exponents 11..17] [--samples N,N,...]
                                [--transient SECONDS] [--threads T] --out DIR
       slowdrift study transient [--config FILE.toml] [--runs 200] [--blocks 8] [--block-cycles 10]
                                 [--offsets 0,15]
                                 [--threads T] --out DIR
       slowdrift study sensitivity [--config FILE.toml] --cases CASES.csv --x COLUMN [--seeds 100]
                                   [--threads T] --out DIR";

/// Default sample counts of `boxplots` for record lengths 2^11 .. 2^17 s: 1000 where runs
/// are cheap, fewer for the long records (about 4 minutes on 2 cores for the default
/// platform with drag).
const DEFAULT_SAMPLES: [usize; 7] = [1000, 1000, 1000, 400, 200, 200, 200];
/// Welch segment of the elevation spectra, s (a resolution of 2 pi / 2048 = 0.003 rad/s).
const SPECTRUM_SEGMENT: f64 = 2048.0;
/// Histogram bins of the elevation pdf over +-4 standard deviations.
const PDF_BINS: usize = 40;
const PDF_HALF_WIDTH: f64 = 4.0;

/// Runs `slowdrift study` with the arguments after `study`.
pub fn run(args: &[String]) -> Result<(), String> {
    let kind = args.first().map(String::as_str);
    let allowed: &[&str] = match kind {
        Some("waves") => &["--config", "--exponents", "--out"],
        Some("boxplots") => &[
            "--config",
            "--exponents",
            "--samples",
            "--transient",
            "--threads",
            "--out",
        ],
        Some("transient") => &[
            "--config",
            "--runs",
            "--blocks",
            "--block-cycles",
            "--offsets",
            "--threads",
            "--out",
        ],
        Some("sensitivity") => &[
            "--config",
            "--cases",
            "--x",
            "--seeds",
            "--threads",
            "--out",
        ],
        _ => {
            return Err(format!(
                "study needs one of waves, boxplots, transient, sensitivity\nusage: {USAGE}"
            ))
        }
    };
    let options = Options::parse(&args[1..], allowed)?;
    let out = PathBuf::from(options.required("--out")?);
    std::fs::create_dir_all(&out).map_err(|e| format!("{}: {e}", out.display()))?;
    let base = match options.get("--config") {
        Some(path) => file::load(Path::new(path)).map_err(|e| e.to_string())?,
        None => {
            println!("embedded default platform; drift: {DEFAULT_DRIFT_LABEL}");
            default_config().map_err(|e| e.to_string())?
        }
    };
    match kind {
        Some("waves") => waves(&base, &options, &out),
        Some("boxplots") => boxplots(&base, &options, &out),
        Some("transient") => transient(&base, &options, &out),
        _ => sensitivity(&base, &options, &out),
    }
}

/// `--flag value` pairs, each flag at most once and from an allowed list.
struct Options(BTreeMap<String, String>);

impl Options {
    fn parse(args: &[String], allowed: &[&str]) -> Result<Self, String> {
        let mut map = BTreeMap::new();
        let mut rest = args.iter();
        while let Some(flag) = rest.next() {
            if !allowed.contains(&flag.as_str()) {
                return Err(format!(
                    "unknown option '{flag}' (this study takes {})\nusage: {USAGE}",
                    allowed.join(", ")
                ));
            }
            let value = rest.next().ok_or_else(|| format!("{flag} needs a value"))?;
            if map.insert(flag.clone(), value.clone()).is_some() {
                return Err(format!("{flag} given twice"));
            }
        }
        Ok(Options(map))
    }

    fn get(&self, flag: &str) -> Option<&str> {
        self.0.get(flag).map(String::as_str)
    }

    fn required(&self, flag: &str) -> Result<&str, String> {
        self.get(flag)
            .ok_or_else(|| format!("{flag} is required\nusage: {USAGE}"))
    }

    fn whole(&self, flag: &str, default: usize, least: usize) -> Result<usize, String> {
        self.get(flag)
            .map_or(Ok(default), |v| parse_whole(flag, v, least))
    }

    fn threads(&self) -> Result<usize, String> {
        let cores = std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get);
        self.whole("--threads", cores, 1)
    }

    /// `--exponents A..B`: record lengths 2^A .. 2^B s (inclusive), 4 <= A <= B <= 20.
    fn exponents(&self) -> Result<Vec<u32>, String> {
        let text = self.get("--exponents").unwrap_or("11..17");
        let parsed = text
            .split_once("..")
            .and_then(|(a, b)| Some((a.parse::<u32>().ok()?, b.parse::<u32>().ok()?)));
        match parsed {
            Some((a, b)) if (4..=b).contains(&a) && b <= 20 => Ok((a..=b).collect()),
            _ => Err(format!("--exponents {text}: must be A..B with 4 <= A <= B <= 20 (record lengths 2^A .. 2^B s)")),
        }
    }
}

fn parse_whole(flag: &str, value: &str, least: usize) -> Result<usize, String> {
    match value.parse::<usize>() {
        Ok(n) if n >= least => Ok(n),
        _ => Err(format!(
            "{flag} {value}: must be a whole number of at least {least}"
        )),
    }
}

fn parse_numbers(flag: &str, text: &str) -> Result<Vec<f64>, String> {
    text.split(',')
        .map(|v| match v.trim().parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(format!("{flag} {text}: '{v}' is not a finite number")),
        })
        .collect()
}

fn write_text(path: &Path, text: &str) -> Result<(), String> {
    std::fs::write(path, text).map_err(|e| format!("{}: {e}", path.display()))
}

fn report(paths: &[PathBuf]) {
    for p in paths {
        println!("wrote {}", p.display());
    }
}

/// The integral of S(omega)^power over the simulated band by the trapezoidal rule on 20 000
/// intervals; power 1 is the variance the synthesis targets (E&S 5-6), m^2.
fn band_integral(config: &Config, power: i32) -> f64 {
    const INTERVALS: usize = 20_000;
    let (lo, hi) = config.sea.band();
    let h = (hi - lo) / INTERVALS as f64;
    let s = |i: usize| config.sea.spectrum.density(lo + i as f64 * h).powi(power);
    h * ((1..INTERVALS).map(s).sum::<f64>() + 0.5 * (s(0) + s(INTERVALS)))
}

/// The relative standard deviation of a record's variance from its spectrum: the record of
/// length L has variance sum |a_n|^2 / 2 with |a_n|^2 exponentially distributed of mean
/// 2 S(w_n) dw (E&S 5), so sd / mean = sqrt(dw sum S^2 dw) / m0 -> sqrt((2 pi / L)
/// integral S^2 dw) / integral S dw.
fn variance_relative_sd(config: &Config, length: f64) -> f64 {
    (2.0 * std::f64::consts::PI / length * band_integral(config, 2)).sqrt()
        / band_integral(config, 1)
}

fn length_label(exponent: u32) -> String {
    format!("{} s", power_of_two_text(exponent.into()))
}

/// Figs 7 and 8: elevation pdf against the Gaussian and Welch spectrum against the input,
/// one panel per record length 2^A .. 2^B s, and a last panel of the convergence.
fn waves(base: &Config, options: &Options, out: &Path) -> Result<(), String> {
    let exponents = options.exponents()?;
    let variance = band_integral(base, 1);
    let sigma = variance.sqrt();
    let (band_lo, band_hi) = base.sea.band();
    let wp = base.sea.spectrum.peak_frequency();
    let records = parallel_map(exponents.len(), options.threads()?, |i| {
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

fn sea_text(config: &Config) -> String {
    use slowdrift::sea_state::Spectrum;
    let spectrum = match &config.sea.spectrum {
        Spectrum::Jonswap { hs, tp, .. } => format!("JONSWAP Hs {hs} m, Tp {tp} s"),
        Spectrum::PiersonMoskowitz { hs, tp } => format!("PM Hs {hs} m, Tp {tp} s"),
        Spectrum::Tabulated { .. } => "tabulated spectrum".into(),
    };
    format!("{spectrum}, seed {}", config.sea.seed)
}

/// The undamped surge natural period times [`TRANSIENT_CYCLES`] (ten slow-drift cycles), s.
fn ten_cycles(config: &Config) -> Result<f64, String> {
    config
        .surge_natural_period()
        .map(|p| TRANSIENT_CYCLES * p)
        .ok_or_else(|| "the platform has no surge stiffness: no slow-drift period".to_string())
}

/// The surge (mean, rms) of each successful run of `case` with a seed in 1..=seeds.
fn surge_values(runs: &[RunRow], case: &Case, seeds: usize) -> (Vec<f64>, Vec<f64>) {
    let mut mine: Vec<&RunRow> = runs
        .iter()
        .filter(|r| r.case == case.name && (1..=seeds as u64).contains(&r.seed))
        .collect();
    mine.sort_by_key(|r| r.seed);
    mine.iter()
        .filter_map(|r| r.result.as_ref().ok())
        .map(|s| (s[0].mean, s[0].rms))
        .unzip()
}

/// Fig. 10: box plots of the surge mean and rms over many seeds for record lengths
/// 2^A .. 2^B s (analysed after the transient), and their scatter against length.
fn boxplots(base: &Config, options: &Options, out: &Path) -> Result<(), String> {
    let exponents = options.exponents()?;
    let samples: Vec<usize> = match options.get("--samples") {
        Some(text) => text
            .split(',')
            .map(|v| parse_whole("--samples", v.trim(), 2))
            .collect::<Result<_, _>>()?,
        None if exponents.len() == DEFAULT_SAMPLES.len() => DEFAULT_SAMPLES.to_vec(),
        None => vec![200],
    };
    let samples = match samples.len() {
        1 => vec![samples[0]; exponents.len()],
        n if n == exponents.len() => samples,
        n => {
            return Err(format!(
                "--samples: {n} counts for {} record lengths (give one, or one per length)",
                exponents.len()
            ))
        }
    };
    let transient = match options.get("--transient") {
        Some(v) => match v.parse::<f64>() {
            Ok(t) if t.is_finite() && t >= 0.0 => t,
            _ => {
                return Err(format!(
                    "--transient {v}: must be a non-negative number of seconds"
                ))
            }
        },
        None => ten_cycles(base)?,
    };
    let cases: Vec<Case> = exponents
        .iter()
        .map(|&k| {
            let mut config = base.clone();
            config.run.duration = transient + 2f64.powi(k as i32);
            Case {
                name: format!("L2^{k}"),
                config,
                transient,
            }
        })
        .collect();
    let jobs: Vec<Job> = samples
        .iter()
        .enumerate()
        .flat_map(|(case, &n)| (1..=n as u64).map(move |seed| Job { case, seed }))
        .collect();
    let runs = run_campaign(
        &cases,
        &jobs,
        options.threads()?,
        &out.join("fig10.runs.csv"),
    )?;

    let mut csv = String::from("record_length_s,samples,mean_median_m,mean_iqr_m,mean_std_m,rms_median_m,rms_iqr_m,rms_std_m\n");
    let (mut mean_boxes, mut rms_boxes) = (Vec::new(), Vec::new());
    let (mut lengths, mut mean_std, mut rms_std) = (Vec::new(), Vec::new(), Vec::new());
    for ((case, &k), &n) in cases.iter().zip(&exponents).zip(&samples) {
        let (means, rmss) = surge_values(&runs, case, n);
        if means.len() < 2 {
            return Err(format!(
                "{}: fewer than 2 successful runs (see fig10.runs.csv)",
                case.name
            ));
        }
        let (bm, br) = (
            box_stats(&means).map_err(|e| e.to_string())?,
            box_stats(&rmss).map_err(|e| e.to_string())?,
        );
        let (sm, sr) = (
            sample_std(&means).map_err(|e| e.to_string())?,
            sample_std(&rmss).map_err(|e| e.to_string())?,
        );
        writeln!(
            csv,
            "{},{},{},{},{sm},{},{},{sr}",
            2u64.pow(k),
            means.len(),
            bm.median,
            bm.iqr(),
            br.median,
            br.iqr()
        )
        .ok();
        lengths.push(2f64.powi(k as i32));
        mean_std.push(sm);
        rms_std.push(sr);
        mean_boxes.push(BoxItem {
            x: k as f64,
            width: 0.5,
            stats: bm,
        });
        rms_boxes.push(BoxItem {
            x: k as f64,
            width: 0.5,
            stats: br,
        });
    }
    let slopes = [
        log_log_slope(&lengths, &mean_std).map_err(|e| e.to_string())?,
        log_log_slope(&lengths, &rms_std).map_err(|e| e.to_string())?,
    ];
    let (k0, k1) = (
        exponents[0] as f64 - 0.6,
        *exponents.last().unwrap_or(&17) as f64 + 0.6,
    );
    let box_panel = |title: &str, y_label: &str, boxes: Vec<BoxItem>| {
        let y_range = padded_range(
            boxes.iter().flat_map(|b| {
                [b.stats.lower_whisker, b.stats.upper_whisker]
                    .into_iter()
                    .chain(b.stats.outliers.iter().copied())
            }),
            0.05,
        );
        Panel {
            title: title.into(),
            x_label: "record length after the transient [s]".into(),
            y_label: y_label.into(),
            x_range: (k0, k1),
            y_range,
            x_ticks: Ticks::PowerOfTwo,
            series: Vec::new(),
            boxes,
            legend: LegendAt::UpperRight,
        }
    };
    let log_std = |std: &[f64]| -> Vec<(f64, f64)> {
        exponents
            .iter()
            .zip(std)
            .map(|(&k, s)| (k as f64, s.log2()))
            .collect()
    };
    let (mean_points, rms_points) = (log_std(&mean_std), log_std(&rms_std));
    let anchor = mean_points[0];
    let reference: Vec<(f64, f64)> = [k0, k1]
        .iter()
        .map(|&k| (k, anchor.1 - 0.5 * (k - anchor.0)))
        .collect();
    let scatter = Panel {
        title: "scatter over seeds (log₂ of the sample std)".into(),
        x_label: "record length after the transient [s]".into(),
        y_label: "log₂ std [log₂ m]".into(),
        x_range: (k0, k1),
        y_range: padded_range(
            mean_points
                .iter()
                .chain(&rms_points)
                .chain(&reference)
                .map(|p| p.1),
            0.08,
        ),
        x_ticks: Ticks::PowerOfTwo,
        series: vec![
            Series::new("∝ length^-1/2", reference, Style::Dashed, 0),
            Series::new(
                format!("surge mean (slope {:.2})", slopes[0]),
                mean_points,
                Style::Markers,
                1,
            ),
            Series::new(
                format!("surge rms (slope {:.2})", slopes[1]),
                rms_points,
                Style::Markers,
                2,
            ),
        ],
        boxes: Vec::new(),
        legend: LegendAt::UpperRight,
    };
    let counts: Vec<String> = samples.iter().map(usize::to_string).collect();
    let figure = Figure {
        title: format!("Surge mean and rms vs record length (E&S Fig. 10): {}; seeds per length {}, transient {transient:.0} s dropped", sea_text(base).split(", seed").next().unwrap_or_default(), counts.join("/")),
        panels: vec![box_panel("surge mean", "surge mean [m]", mean_boxes), box_panel("surge rms", "surge rms [m]", rms_boxes), scatter],
        columns: 3,
        size: (1700, 620),
    };
    let csv_path = out.join("fig10_scatter.csv");
    write_text(&csv_path, &csv)?;
    let mut written = vec![csv_path];
    written.extend(write_figure(&figure, &out.join("fig10_boxplots"))?);
    print!("{csv}");
    println!("log-log slope of the scatter against record length: surge mean {:.3}, surge rms {:.3} (1/sqrt(length): -0.5)", slopes[0], slopes[1]);
    report(&written);
    Ok(())
}

/// Fig. 11: surge mean and rms per block of `--block-cycles` (default ten) undamped surge
/// periods from the start, averaged over runs (seeds 1..=runs, the same seeds for every
/// initial condition), for initial surge offsets added to the configuration's initial
/// position (released at rest).
fn transient(base: &Config, options: &Options, out: &Path) -> Result<(), String> {
    let runs = options.whole("--runs", 200, 2)?;
    let blocks = options.whole("--blocks", 8, 2)?;
    let offsets = parse_numbers("--offsets", options.get("--offsets").unwrap_or("0,15"))?;
    let cycles = match options.get("--block-cycles") {
        Some(v) => parse_numbers("--block-cycles", v)?
            .first()
            .copied()
            .filter(|c| *c > 0.0)
            .ok_or_else(|| format!("--block-cycles {v}: must be a positive number"))?,
        None => TRANSIENT_CYCLES,
    };
    let block = ten_cycles(base)? / TRANSIENT_CYCLES * cycles;
    let dt = base.run.time_step;
    let jobs = offsets.len() * runs;
    println!(
        "{} initial offsets x {runs} runs of {blocks} blocks of {block:.0} s on {} thread(s)",
        offsets.len(),
        options.threads()?
    );
    let started = std::time::Instant::now();
    let results = parallel_map(jobs, options.threads()?, |i| {
        let mut config = base.clone();
        config.sea.seed = (i % runs) as u64 + 1;
        config.run.duration = blocks as f64 * block;
        config.initial.position[0] += offsets[i / runs];
        let [surge, _, _] = simulate_positions(config)?;
        block_summaries(&surge, dt, block)
    });
    println!("{jobs} runs in {:.1} s", started.elapsed().as_secs_f64());
    let mut csv =
        String::from("initial_offset_m,block,start_s,end_s,runs,mean_m,mean_se_m,rms_m,rms_se_m\n");
    let (mut mean_series, mut rms_series) = (Vec::new(), Vec::new());
    for (o, offset) in offsets.iter().enumerate() {
        let mine = results[o * runs..(o + 1) * runs]
            .iter()
            .map(|r| r.clone().map_err(|e| e.to_string()))
            .collect::<Result<Vec<_>, _>>()?;
        let (mut means, mut rmss) = (Vec::new(), Vec::new());
        for b in 0..blocks {
            let stat = |f: fn(&slowdrift::stats::Summary) -> f64| -> SeedStatistics {
                let values: Vec<f64> = mine.iter().map(|r| f(&r[b])).collect();
                seed_statistics(&values).expect("at least two runs")
            };
            let (m, r) = (stat(|s| s.mean), stat(|s| s.rms));
            let (mse, rse) = (
                m.standard_error.unwrap_or(0.0),
                r.standard_error.unwrap_or(0.0),
            );
            writeln!(
                csv,
                "{offset},{},{},{},{runs},{},{mse},{},{rse}",
                b + 1,
                b as f64 * block,
                (b + 1) as f64 * block,
                m.mean,
                r.mean
            )
            .ok();
            // Series side by side (dodged by 2 % of the axis) so that equal values stay visible.
            let dodge =
                (o as f64 - 0.5 * (offsets.len() - 1) as f64) * 0.02 * blocks as f64 * cycles;
            let x = (b as f64 + 0.5) * cycles + dodge;
            means.push((x, m.mean, mse));
            rmss.push((x, r.mean, rse));
        }
        let start = base.initial.position[0] + offset;
        let label = if start == 0.0 {
            "from rest at X = 0".to_string()
        } else {
            format!("released at rest from X = {start} m")
        };
        let series = |points: &[(f64, f64, f64)]| {
            Series::new(
                label.clone(),
                points.iter().map(|p| (p.0, p.1)).collect(),
                Style::Markers,
                o + 1,
            )
            .with_errors(points.iter().map(|p| p.2).collect())
        };
        mean_series.push(series(&means));
        rms_series.push(series(&rmss));
    }
    let x_range = (0.0, blocks as f64 * cycles);
    let panel = |title: &str, y_label: &str, series: Vec<Series>, legend: LegendAt| {
        let y_range = padded_range(
            series.iter().flat_map(|s| {
                s.points
                    .iter()
                    .zip(&s.errors)
                    .flat_map(|(p, e)| [p.1 - e, p.1 + e])
            }),
            0.25,
        );
        Panel {
            title: title.into(),
            x_label: "slow-drift cycles from the start (block centres) [-]".into(),
            y_label: y_label.into(),
            x_range,
            y_range,
            x_ticks: Ticks::Plain,
            series,
            boxes: Vec::new(),
            legend,
        }
    };
    let figure = Figure {
        title: format!("Start-up transient (E&S Fig. 11): surge per block of {cycles} cycles ({block:.0} s), mean of {runs} runs ± 1 standard error; {}", sea_text(base).split(", seed").next().unwrap_or_default()),
        panels: vec![
            panel("surge rms per block", "surge rms about the block mean [m]", rms_series, LegendAt::UpperRight),
            panel("surge mean per block", "surge mean [m]", mean_series, LegendAt::LowerRight),
        ],
        columns: 2,
        size: (1500, 600),
    };
    let csv_path = out.join(format!("fig11_blocks_{cycles}cycles.csv"));
    write_text(&csv_path, &csv)?;
    let mut written = vec![csv_path];
    written.extend(write_figure(
        &figure,
        &out.join(format!("fig11_transient_{cycles}cycles")),
    )?);
    print!("{csv}");
    report(&written);
    Ok(())
}

/// The axis description of a case-table column.
fn column_label(column: &str) -> String {
    match column {
        "cd" => "combined drag coefficient C_D [-]".into(),
        "cd_slow" => "slow-drift drag coefficient C_DS [-]".into(),
        "cd_fast" => "wave-frequency drag coefficient C_DL [-]".into(),
        "current_speed" => "current speed [m/s]".into(),
        "current_direction_deg" => "current direction [deg]".into(),
        "hs" => "Hs [m]".into(),
        "tp" => "Tp [s]".into(),
        "direction_deg" => "wave direction [deg]".into(),
        "duration" => "duration [s]".into(),
        other => other.into(),
    }
}

/// Figs 12-15: surge mean and rms (mean over seeds, +- 1 standard error) against one
/// column of a case table.
fn sensitivity(base: &Config, options: &Options, out: &Path) -> Result<(), String> {
    let table = PathBuf::from(options.required("--cases")?);
    let column = options.required("--x")?;
    let seeds = options.whole("--seeds", 100, 2)?;
    let rows = read_case_table(&table).map_err(|e| e.to_string())?;
    let source = table.display().to_string();
    let mut cases = Vec::new();
    let mut xs = Vec::new();
    for row in &rows {
        let x = row
            .values
            .iter()
            .find(|(c, _)| *c == column)
            .map(|(_, v)| *v)
            .ok_or_else(|| {
                format!(
                    "{source}: row {} ('{}') has no value in column '{column}'",
                    row.row, row.name
                )
            })?;
        xs.push(x);
        cases.push(row.case(base, None, &source).map_err(|e| e.to_string())?);
    }
    let stem = table
        .file_stem()
        .unwrap_or_default()
        .to_string_lossy()
        .to_string();
    let jobs: Vec<Job> = (0..cases.len())
        .flat_map(|case| (1..=seeds as u64).map(move |seed| Job { case, seed }))
        .collect();
    let runs = run_campaign(
        &cases,
        &jobs,
        options.threads()?,
        &out.join(format!("{stem}.runs.csv")),
    )?;
    let mut csv = format!(
        "case,{column},seeds_done,surge_mean_m,surge_mean_se_m,surge_rms_m,surge_rms_se_m\n"
    );
    let (mut mean_points, mut rms_points) = (Vec::new(), Vec::new());
    for (case, &x) in cases.iter().zip(&xs) {
        let (means, rmss) = surge_values(&runs, case, seeds);
        let (Some(m), Some(r)) = (seed_statistics(&means), seed_statistics(&rmss)) else {
            return Err(format!(
                "case '{}': no successful run (see {stem}.runs.csv)",
                case.name
            ));
        };
        let (mse, rse) = (
            m.standard_error.unwrap_or(0.0),
            r.standard_error.unwrap_or(0.0),
        );
        writeln!(
            csv,
            "{},{x},{},{},{mse},{},{rse}",
            case.name, m.n, m.mean, r.mean
        )
        .ok();
        mean_points.push((x, m.mean, mse));
        rms_points.push((x, r.mean, rse));
    }
    let x_range = padded_range(xs.iter().copied(), 0.08);
    let panel = |title: &str, y_label: &str, points: &[(f64, f64, f64)]| {
        let series = Series::new(
            "",
            points.iter().map(|p| (p.0, p.1)).collect(),
            Style::Markers,
            1,
        )
        .with_errors(points.iter().map(|p| p.2).collect());
        // From zero when every value is positive, so that the panel shows proportions.
        let (lo, hi) = padded_range(
            points
                .iter()
                .flat_map(|p| [p.1 - p.2, p.1 + p.2])
                .chain([0.0]),
            0.1,
        );
        let positive = points.iter().all(|p| p.1 - p.2 >= 0.0);
        let y_range = (if positive { 0.0 } else { lo }, hi);
        Panel {
            title: title.into(),
            x_label: column_label(column),
            y_label: y_label.into(),
            x_range,
            y_range,
            x_ticks: Ticks::Plain,
            series: vec![series],
            boxes: Vec::new(),
            legend: LegendAt::UpperRight,
        }
    };
    let figure = Figure {
        title: format!(
            "Surge vs {} ({stem}): mean of {seeds} seeds ± 1 standard error; {}",
            column_label(column).split(" [").next().unwrap_or(column),
            sea_text(base).split(", seed").next().unwrap_or_default()
        ),
        panels: vec![
            panel("surge mean", "surge mean [m]", &mean_points),
            panel("surge rms", "surge rms [m]", &rms_points),
        ],
        columns: 2,
        size: (1400, 560),
    };
    let csv_path = out.join(format!("{stem}.summary.csv"));
    write_text(&csv_path, &csv)?;
    let mut written = vec![csv_path];
    written.extend(write_figure(&figure, &out.join(&stem))?);
    print!("{csv}");
    report(&written);
    Ok(())
}
