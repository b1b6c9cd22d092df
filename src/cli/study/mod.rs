//! `slowdrift study <drift|waves|boxplots|transient|sensitivity|motion>`: the paper's studies
//! (E&S 1996 Figs 3-5 and 7-15) and the motion spectra against the frequency domain for a
//! platform, each written as data (CSV) and as a figure (PNG and SVG) in
//! `--out DIR`. The computations are [`slowdrift::studies`] and the Monte Carlo campaign
//! of `slowdrift montecarlo` (resumable: the per-run files in DIR are read back and only
//! missing runs are made); the drawing is [`crate::plot`].

mod boxplots;
mod drift;
mod motion;
mod sensitivity;
mod transient;
mod waves;

use super::args::{all_cores, parse_whole, seconds, whole, Checked};
use super::Failure;
use clap::{Args, Subcommand};
use slowdrift::montecarlo::runs_file::RunRow;
use slowdrift::montecarlo::Case;
use slowdrift::problem::{self, default_problem};
use slowdrift::scenario::default::DEFAULT_DRIFT_LABEL;
use slowdrift::scenario::TRANSIENT_CYCLES;
use slowdrift::Problem;
use std::path::{Path, PathBuf};

/// `slowdrift study`.
#[derive(Args)]
#[command(
    subcommand_required = true,
    subcommand_value_name = "drift|waves|boxplots|transient|sensitivity|motion"
)]
pub struct StudyArgs {
    #[command(subcommand)]
    study: Study,
}

#[derive(Subcommand)]
enum Study {
    /// The configuration's mean drift and wave-drift damping against frequency beside the
    /// column solver's on its columns (as E&S Figs 3-5)
    Drift(DriftArgs),
    /// The elevation's pdf against the Gaussian and its spectrum against the input for record
    /// lengths 2^A .. 2^B s (E&S Figs 7, 8)
    Waves(WavesArgs),
    /// Surge mean and rms over many seeds for record lengths 2^A .. 2^B s as box plots (E&S
    /// Fig. 10); resumable (DIR/fig10.runs.csv)
    Boxplots(BoxplotsArgs),
    /// Surge mean and rms per block of slow-drift cycles over many runs, for several initial
    /// offsets (E&S Fig. 11)
    Transient(TransientArgs),
    /// Surge mean and rms against a column of a case table (E&S Figs 12-15); resumable
    /// (DIR/CASES.runs.csv)
    Sensitivity(SensitivityArgs),
    /// The slow drift's and the wave-frequency motion's spectra of one long run against
    /// their frequency-domain predictions
    Motion(MotionArgs),
}

/// `study drift`.
#[derive(Args)]
struct DriftArgs {
    /// Platform (TOML) [default: the embedded default platform]
    #[arg(long, value_name = "FILE.toml", allow_hyphen_values = true)]
    config: Option<PathBuf>,
    /// Legend of the configuration's curves
    #[arg(
        long,
        value_name = "TEXT",
        default_value = "radiation-diffraction (default platform)"
    )]
    label: String,
    /// Directory of the CSV and the figures (PNG and SVG), created if missing
    #[arg(long, value_name = "DIR", allow_hyphen_values = true)]
    out: PathBuf,
}

/// `study waves`.
#[derive(Args)]
struct WavesArgs {
    /// Platform and sea (TOML) [default: the embedded default platform]
    #[arg(long, value_name = "FILE.toml", allow_hyphen_values = true)]
    config: Option<PathBuf>,
    /// Record lengths 2^A .. 2^B s, 4 <= A <= B <= 20
    #[arg(long, value_name = "A..B", allow_hyphen_values = true, default_value = "11..17",
          value_parser = Checked(exponents))]
    exponents: Exponents,
    /// Directory of the CSV and the figures (PNG and SVG), created if missing
    #[arg(long, value_name = "DIR", allow_hyphen_values = true)]
    out: PathBuf,
}

/// `study boxplots`.
#[derive(Args)]
struct BoxplotsArgs {
    /// Platform and sea (TOML) [default: the embedded default platform]
    #[arg(long, value_name = "FILE.toml", allow_hyphen_values = true)]
    config: Option<PathBuf>,
    /// Record lengths after the transient 2^A .. 2^B s, 4 <= A <= B <= 20
    #[arg(long, value_name = "A..B", allow_hyphen_values = true, default_value = "11..17",
          value_parser = Checked(exponents))]
    exponents: Exponents,
    /// Seeds (1 to N) per record length, each at least 2: one count for every length or one per
    /// length [default: 1000,1000,1000,400,200,200,200 for 11..17, else 200]
    #[arg(long, value_name = "N,N,...", allow_hyphen_values = true,
          value_parser = Checked(sample_counts))]
    samples: Option<Counts>,
    /// Start-up transient simulated before each record and dropped, s [default: ten
    /// undamped surge natural periods]
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, value_parser = seconds(false))]
    transient: Option<f64>,
    /// Threads, at least 1 (the results do not depend on it) [default: all cores]
    #[arg(long, value_name = "T", allow_hyphen_values = true, value_parser = whole(1usize))]
    threads: Option<usize>,
    /// Directory of the CSV, the figures (PNG and SVG) and the per-run file, created if missing
    #[arg(long, value_name = "DIR", allow_hyphen_values = true)]
    out: PathBuf,
}

/// `study transient`.
#[derive(Args)]
struct TransientArgs {
    /// Platform and sea (TOML); its [initial] position is the start [default: the embedded
    /// default platform]
    #[arg(long, value_name = "FILE.toml", allow_hyphen_values = true)]
    config: Option<PathBuf>,
    /// Runs (seeds 1 to N, the same for every offset) per initial offset, at least 2
    #[arg(long, value_name = "N", allow_hyphen_values = true, default_value_t = 200,
          value_parser = whole(2usize))]
    runs: usize,
    /// Blocks per run, at least 2
    #[arg(long, value_name = "N", allow_hyphen_values = true, default_value_t = 8,
          value_parser = whole(2usize))]
    blocks: usize,
    /// Length of a block in undamped surge natural periods (slow-drift cycles), positive
    #[arg(long, value_name = "CYCLES", allow_hyphen_values = true,
          default_value_t = TRANSIENT_CYCLES, value_parser = Checked(block_cycles))]
    block_cycles: f64,
    /// Initial surge offsets added to the configuration's initial position, m (released at
    /// rest)
    #[arg(long, value_name = "M,M,...", allow_hyphen_values = true, default_value = "0,15",
          value_parser = Checked(|flag: &str, text: &str| parse_numbers(flag, text).map(Numbers)))]
    offsets: Numbers,
    /// Threads, at least 1 (the results do not depend on it) [default: all cores]
    #[arg(long, value_name = "T", allow_hyphen_values = true, value_parser = whole(1usize))]
    threads: Option<usize>,
    /// Directory of the CSV and the figures (PNG and SVG), created if missing
    #[arg(long, value_name = "DIR", allow_hyphen_values = true)]
    out: PathBuf,
}

/// `study sensitivity`.
#[derive(Args)]
struct SensitivityArgs {
    /// Base platform and sea (TOML) [default: the embedded default platform]
    #[arg(long, value_name = "FILE.toml", allow_hyphen_values = true)]
    config: Option<PathBuf>,
    /// Case table (CSV, as for montecarlo), one point per row
    #[arg(long, value_name = "CASES.csv", allow_hyphen_values = true)]
    cases: PathBuf,
    /// The case-table column on the x axis (cd, cd_slow, current_speed, hs, ...)
    #[arg(long, value_name = "COLUMN", allow_hyphen_values = true)]
    x: String,
    /// Seeds 1 to N per case, at least 2
    #[arg(long, value_name = "N", allow_hyphen_values = true, default_value_t = 100,
          value_parser = whole(2usize))]
    seeds: usize,
    /// Threads, at least 1 (the results do not depend on it) [default: all cores]
    #[arg(long, value_name = "T", allow_hyphen_values = true, value_parser = whole(1usize))]
    threads: Option<usize>,
    /// Directory of the CSV (CASES.summary.csv), the figures (CASES.png, CASES.svg) and the
    /// per-run file (CASES.runs.csv), created if missing
    #[arg(long, value_name = "DIR", allow_hyphen_values = true)]
    out: PathBuf,
}

/// `study motion`.
#[derive(Args)]
struct MotionArgs {
    /// Platform and sea (TOML) [default: the embedded default platform]
    #[arg(long, value_name = "FILE.toml", allow_hyphen_values = true)]
    config: Option<PathBuf>,
    /// Length of the record analysed, after the transient, s
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, default_value = "65536",
          value_parser = seconds(true))]
    duration: f64,
    /// Start-up transient simulated before the record and dropped, s [default: ten
    /// undamped surge natural periods]
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, value_parser = seconds(false))]
    transient: Option<f64>,
    /// Directory of the CSV and the figures (PNG and SVG), created if missing
    #[arg(long, value_name = "DIR", allow_hyphen_values = true)]
    out: PathBuf,
}

/// `--exponents A..B`: record lengths 2^A .. 2^B s (inclusive).
#[derive(Clone)]
struct Exponents(Vec<u32>);

/// `--samples N,N,...`.
#[derive(Clone)]
struct Counts(Vec<usize>);

/// `--offsets X,X,...`.
#[derive(Clone)]
struct Numbers(Vec<f64>);

/// Runs `slowdrift study ...`.
pub fn run(args: StudyArgs) -> Result<(), Failure> {
    let (config, out) = match &args.study {
        Study::Drift(a) => (&a.config, &a.out),
        Study::Waves(a) => (&a.config, &a.out),
        Study::Boxplots(a) => (&a.config, &a.out),
        Study::Transient(a) => (&a.config, &a.out),
        Study::Sensitivity(a) => (&a.config, &a.out),
        Study::Motion(a) => (&a.config, &a.out),
    };
    super::out::directory(out)?;
    let base = match config {
        Some(path) => problem::load(path).map_err(|e| e.to_string())?,
        None => {
            println!("embedded default platform; drift: {DEFAULT_DRIFT_LABEL}");
            default_problem().map_err(|e| e.to_string())?
        }
    };
    // Checked before anything runs: the configuration a study simulates whole, the columns
    // (and environment) of the one whose drift it compares.
    match &args.study {
        Study::Drift(_) => base.check_columns(),
        _ => base.check(),
    }
    .map_err(|e| e.to_string())?;
    match &args.study {
        Study::Drift(a) => Ok(drift::drift(&base, a)?),
        Study::Waves(a) => Ok(waves::waves(&base, a)?),
        Study::Boxplots(a) => boxplots::boxplots(&base, a),
        Study::Transient(a) => Ok(transient::transient(&base, a)?),
        Study::Sensitivity(a) => sensitivity::sensitivity(&base, a),
        Study::Motion(a) => Ok(motion::motion(&base, a)?),
    }
}

/// `--exponents A..B` with 4 <= A <= B <= 20.
fn exponents(flag: &str, text: &str) -> Result<Exponents, String> {
    let parsed = text
        .split_once("..")
        .and_then(|(a, b)| Some((a.parse::<u32>().ok()?, b.parse::<u32>().ok()?)));
    match parsed {
        Some((a, b)) if (4..=b).contains(&a) && b <= 20 => Ok(Exponents((a..=b).collect())),
        _ => Err(format!(
            "{flag} {text}: must be A..B with 4 <= A <= B <= 20 (record lengths 2^A .. 2^B s)"
        )),
    }
}

/// `--samples N,N,...`, each at least 2 (how many against the record lengths is checked by
/// the study).
fn sample_counts(flag: &str, text: &str) -> Result<Counts, String> {
    text.split(',')
        .map(|v| parse_whole(flag, v.trim(), 2))
        .collect::<Result<_, _>>()
        .map(Counts)
}

/// `--block-cycles C`: the first of the numbers given, positive.
fn block_cycles(flag: &str, text: &str) -> Result<f64, String> {
    parse_numbers(flag, text)?
        .first()
        .copied()
        .filter(|c| *c > 0.0)
        .ok_or_else(|| format!("{flag} {text}: must be a positive number"))
}

/// `--threads T`, or all cores.
fn threads(given: Option<usize>) -> usize {
    given.unwrap_or_else(all_cores)
}

fn parse_numbers(flag: &str, text: &str) -> Result<Vec<f64>, String> {
    text.split(',')
        .map(|v| match v.trim().parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(format!("{flag} {text}: '{v}' is not a finite number")),
        })
        .collect()
}

/// Writes a study's data file anew, atomically (a kill never leaves it cut).
fn write_text(path: &Path, text: &str) -> Result<(), String> {
    slowdrift::files::replace(path, |w| std::io::Write::write_all(w, text.as_bytes()))
        .map_err(|e| e.to_string())
}

fn report(paths: &[PathBuf]) {
    for p in paths {
        println!("wrote {}", p.display());
    }
}

fn sea_text(problem: &Problem) -> String {
    use slowdrift::sea_state::Spectrum;
    let spectrum = match &problem.sea.spectrum {
        Spectrum::Jonswap { hs, tp, .. } => format!("JONSWAP Hs {hs} m, Tp {tp} s"),
        Spectrum::PiersonMoskowitz { hs, tp } => format!("PM Hs {hs} m, Tp {tp} s"),
        Spectrum::Tabulated { .. } => "tabulated spectrum".into(),
    };
    format!("{spectrum}, seed {}", problem.sea.seed)
}

/// The undamped surge natural period times [`TRANSIENT_CYCLES`] (ten slow-drift cycles), s.
fn ten_cycles(problem: &Problem) -> Result<f64, String> {
    problem
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
