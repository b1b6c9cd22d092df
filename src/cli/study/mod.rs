//! `slowdrift study <waves|boxplots|transient|sensitivity>`: the paper's studies (E&S 1996
//! Figs 7-15) for a platform, each written as data (CSV) and as a figure (PNG and SVG) in
//! `--out DIR`. The computations are [`slowdrift::studies`] and the Monte Carlo campaign
//! of `slowdrift montecarlo` (resumable: the per-run files in DIR are read back and only
//! missing runs are made); the drawing is [`crate::plot`].

mod boxplots;
mod sensitivity;
mod transient;
mod waves;

use slowdrift::montecarlo::runs_file::RunRow;
use slowdrift::montecarlo::Case;
use slowdrift::problem::default_problem;
use slowdrift::scenario::default::DEFAULT_DRIFT_LABEL;
use slowdrift::scenario::TRANSIENT_CYCLES;
use slowdrift::{problem, Problem};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

pub const USAGE: &str = "slowdrift study waves [--config FILE.toml] [--exponents 11..17] --out DIR
       slowdrift study boxplots [--config FILE.toml] [--exponents 11..17] [--samples N,N,...]
                                [--transient SECONDS] [--threads T] --out DIR
       slowdrift study transient [--config FILE.toml] [--runs 200] [--blocks 8] [--block-cycles 10]
                                 [--offsets 0,15]
                                 [--threads T] --out DIR
       slowdrift study sensitivity [--config FILE.toml] --cases CASES.csv --x COLUMN [--seeds 100]
                                   [--threads T] --out DIR";

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
        Some(path) => problem::load(Path::new(path)).map_err(|e| e.to_string())?,
        None => {
            println!("embedded default platform; drift: {DEFAULT_DRIFT_LABEL}");
            default_problem().map_err(|e| e.to_string())?
        }
    };
    match kind {
        Some("waves") => waves::waves(&base, &options, &out),
        Some("boxplots") => boxplots::boxplots(&base, &options, &out),
        Some("transient") => transient::transient(&base, &options, &out),
        _ => sensitivity::sensitivity(&base, &options, &out),
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

fn sea_text(config: &Problem) -> String {
    use slowdrift::sea_state::Spectrum;
    let spectrum = match &config.sea.spectrum {
        Spectrum::Jonswap { hs, tp, .. } => format!("JONSWAP Hs {hs} m, Tp {tp} s"),
        Spectrum::PiersonMoskowitz { hs, tp } => format!("PM Hs {hs} m, Tp {tp} s"),
        Spectrum::Tabulated { .. } => "tabulated spectrum".into(),
    };
    format!("{spectrum}, seed {}", config.sea.seed)
}

/// The undamped surge natural period times [`TRANSIENT_CYCLES`] (ten slow-drift cycles), s.
fn ten_cycles(config: &Problem) -> Result<f64, String> {
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
