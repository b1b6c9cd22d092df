//! What the subcommands' options share: clap value parsers that check a value as the tool
//! always has and refuse it with the option and the value as the user wrote them
//! (`--ulen -1: must be a positive number`), followed by clap's usage line.

use clap::builder::TypedValueParser;
use clap::error::{Error, ErrorKind};
use clap::{Arg, Command};
use std::ffi::OsStr;

/// A value parser from a function of (`--flag`, value text) that returns the value or the
/// whole message.
#[derive(Clone)]
pub struct Checked<F>(pub F);

impl<T, F> TypedValueParser for Checked<F>
where
    F: Fn(&str, &str) -> Result<T, String> + Clone + Send + Sync + 'static,
    T: Clone + Send + Sync + 'static,
{
    type Value = T;

    fn parse_ref(&self, cmd: &Command, arg: Option<&Arg>, value: &OsStr) -> Result<T, Error> {
        let flag = arg
            .and_then(Arg::get_long)
            .map_or_else(|| "the value".to_string(), |long| format!("--{long}"));
        (self.0)(&flag, &value.to_string_lossy()).map_err(|message| {
            Error::raw(ErrorKind::ValueValidation, message).format(&mut cmd.clone())
        })
    }
}

/// `--flag N`, a whole number of at least `least`.
pub fn whole<T>(least: T) -> Checked<impl Fn(&str, &str) -> Result<T, String> + Clone>
where
    T: std::str::FromStr + PartialOrd + std::fmt::Display + Copy + Send + Sync + 'static,
{
    Checked(move |flag: &str, value: &str| parse_whole(flag, value, least))
}

pub fn parse_whole<T>(flag: &str, value: &str, least: T) -> Result<T, String>
where
    T: std::str::FromStr + PartialOrd + std::fmt::Display,
{
    match value.parse::<T>() {
        Ok(n) if n >= least => Ok(n),
        _ => Err(format!(
            "{flag} {value}: must be a whole number of at least {least}"
        )),
    }
}

/// `--flag SECONDS`, a finite number of seconds, positive or (`positive` false) also zero.
pub fn seconds(positive: bool) -> Checked<impl Fn(&str, &str) -> Result<f64, String> + Clone> {
    Checked(move |flag: &str, value: &str| match value.parse::<f64>() {
        Ok(v) if v.is_finite() && (v > 0.0 || (!positive && v == 0.0)) => Ok(v),
        _ => Err(format!(
            "{flag} {value}: must be a {} number of seconds",
            if positive { "positive" } else { "non-negative" }
        )),
    })
}

/// The number of threads when `--threads` is not given: all cores.
pub fn all_cores() -> usize {
    std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get)
}

/// `--memory-limit-gb GB`, a positive number of gigabytes, at most
/// [`MAX_MEMORY_LIMIT_GB`](slowdrift::scenario::limits::MAX_MEMORY_LIMIT_GB).
pub fn gigabytes() -> Checked<impl Fn(&str, &str) -> Result<f64, String> + Clone> {
    use slowdrift::scenario::limits::MAX_MEMORY_LIMIT_GB;
    Checked(|flag: &str, value: &str| match value.parse::<f64>() {
        Ok(v) if v > 0.0 && v <= MAX_MEMORY_LIMIT_GB => Ok(v),
        _ => Err(format!(
            "{flag} {value}: must be a positive number of GB, at most {}",
            slowdrift::error::numbers::written(MAX_MEMORY_LIMIT_GB)
        )),
    })
}

/// `--transient SECONDS` against a run of `duration` s (`run`: which one): the statistics
/// keep the samples at t >= transient, so it must not pass the run's end. Checked before
/// the run.
pub fn transient_leaves_samples(transient: f64, duration: f64, run: &str) -> Result<(), String> {
    if transient <= duration {
        return Ok(());
    }
    Err(format!(
        "--transient {}: longer than {run} ({} s): no sample would be left for the statistics",
        slowdrift::error::numbers::written(transient),
        slowdrift::error::numbers::written(duration)
    ))
}

/// The problem of `--config` (else the embedded default), `--memory-limit-gb` (when given)
/// written over its `run.memory_limit_gb` before it is resolved, so that a column solver's
/// table and the files the configuration names are budgeted against it too; the file itself
/// is read within it (else within the default limit).
pub fn load_problem(
    config: Option<&std::path::Path>,
    memory_limit_gb: Option<f64>,
) -> Result<slowdrift::Problem, String> {
    let memory_limit = memory_limit_gb.map(|gb| gb * slowdrift::error::BYTES_PER_GB);
    let mut scenario = match config {
        // Read within the limit given here (the file's own is not known before).
        Some(path) => slowdrift::scenario::file::load(
            path,
            memory_limit.unwrap_or(slowdrift::scenario::limits::DEFAULT_MEMORY_LIMIT),
        ),
        None => slowdrift::scenario::default::default_scenario(),
    }
    .map_err(|e| e.to_string())?;
    if let Some(limit) = memory_limit {
        scenario.run.memory_limit = limit;
    }
    slowdrift::problem::resolve(&scenario).map_err(|e| e.to_string())
}
