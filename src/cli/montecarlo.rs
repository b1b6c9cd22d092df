//! `slowdrift montecarlo`: many seeds of one case or of a table of cases, on all cores,
//! resumable (see README "Monte Carlo").
//!
//! The per-run file `RESULTS.runs.csv` ([`runs_file`]) is appended and flushed as runs
//! finish; a restart with the same `--out` reads it back, refuses runs made with another
//! configuration, skips the (case, seed) pairs already done and runs the rest (failed runs
//! again). The summary `RESULTS.csv` is always recomputed from the per-run file, for the
//! requested seeds in seed order, so it does not depend on the threads, the finishing
//! order or the interruptions; it is written anew atomically.
//!
//! One process per runs file: a second one on the same `--out` is refused at once, naming
//! the first ([`RunsFile::open`] locks it). SIGINT and SIGTERM stop a campaign cleanly
//! ([`super::interrupt`]): the summary of the runs done is written and the command to
//! resume printed.

use super::args::{all_cores, gigabytes, load_problem, seconds, transient_leaves_samples, whole};
use super::interrupt::{this_command, Interrupts, Signal};
use super::out;
use super::Failure;
use clap::Args;
use slowdrift::error::numbers::{readable, written};
use slowdrift::fmi2::campaign;
use slowdrift::forces::{Isa, LANES};
use slowdrift::montecarlo::cases::{open_case_table, CaseRow};
use slowdrift::montecarlo::runs_file::{self, RunRow, RunsFile};
use slowdrift::montecarlo::{
    campaign_lane_widths, has_drag, lane_width, run_jobs, seed_statistics, Case, Job, DOFS,
    STATISTICS,
};
use slowdrift::Problem;
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// `slowdrift montecarlo`: run the seeds, or (`--print-cases`) print the cases.
#[derive(Args)]
#[command(
    args_override_self = true,
    override_usage = "slowdrift montecarlo [--config FILE.toml] [--cases CASES.csv] [--case NAME] --seeds N\n           \
                      [--first-seed 1] [--duration SECONDS] [--transient SECONDS] [--threads T]\n           \
                      --out RESULTS.csv\n       \
                      slowdrift montecarlo [--config FILE.toml] [--cases CASES.csv] [--duration SECONDS]\n           \
                      [--transient SECONDS] --print-cases"
)]
pub struct MontecarloArgs {
    /// Base configuration (TOML) [default: the embedded default platform]
    #[arg(long, value_name = "FILE.toml", allow_hyphen_values = true)]
    config: Option<PathBuf>,
    /// Case table (CSV), one case per row on top of the base; an empty cell keeps the base
    /// value [default: the base alone, case 'base']
    #[arg(long, value_name = "CASES.csv", allow_hyphen_values = true)]
    cases: Option<PathBuf>,
    /// Runs only the case of this name
    #[arg(long = "case", value_name = "NAME", allow_hyphen_values = true)]
    only: Option<String>,
    /// Seeds per case, at least 1: seeds S to S+N-1 (required unless --print-cases)
    #[arg(long, value_name = "N", allow_hyphen_values = true, value_parser = whole(1u64),
          required_unless_present = "print_cases")]
    seeds: Option<u64>,
    /// The first seed S, at least 0
    #[arg(long, value_name = "S", allow_hyphen_values = true, default_value_t = 1,
          value_parser = whole(0u64))]
    first_seed: u64,
    /// Replaces run.duration of the base, s [default: the configuration's]
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, value_parser = seconds(true))]
    duration: Option<f64>,
    /// Start-up transient dropped before the statistics, s, for every case [default: ten
    /// surge natural periods, at most half the run]
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, value_parser = seconds(false))]
    transient: Option<f64>,
    /// Threads, at least 1 (the results do not depend on it) [default: all cores]
    #[arg(long, value_name = "T", allow_hyphen_values = true, value_parser = whole(1usize))]
    threads: Option<usize>,
    /// Memory one run's records may take, GB (1e9 bytes): larger estimates are refused; a
    /// campaign's thread steps together (up to 4) only the runs whose records fit it
    /// together [default: the configuration's run.memory_limit_gb, 4]
    #[arg(long, value_name = "GB", allow_hyphen_values = true, value_parser = gigabytes())]
    memory_limit_gb: Option<f64>,
    /// The summary, one line per case and DOF; the runs go to RESULTS.runs.csv beside it,
    /// appended as they finish, and a restart with the same --out resumes (required unless
    /// --print-cases)
    #[arg(
        long,
        value_name = "RESULTS.csv",
        allow_hyphen_values = true,
        required_unless_present = "print_cases"
    )]
    out: Option<PathBuf>,
    /// Runs nothing: prints the cases as JSON on stdout (name, fingerprint, transient, steps
    /// and the FMU parameters that run each case)
    #[arg(long)]
    print_cases: bool,
}

struct Options {
    config: Option<PathBuf>,
    cases: Option<PathBuf>,
    /// Run only the case of this name.
    only: Option<String>,
    seeds: u64,
    first_seed: u64,
    duration: Option<f64>,
    transient: Option<f64>,
    threads: usize,
    memory_limit_gb: Option<f64>,
    out: PathBuf,
}

/// What the command does.
enum Command {
    Run(Options),
    /// `--print-cases`: the cases as JSON ([`plan`]) on stdout, nothing run.
    PrintCases(Options),
}

fn command(args: MontecarloArgs) -> Result<Command, String> {
    let MontecarloArgs {
        config,
        cases,
        only,
        seeds,
        first_seed,
        duration,
        transient,
        threads,
        memory_limit_gb,
        out,
        print_cases,
    } = args;
    if print_cases {
        return Ok(Command::PrintCases(Options {
            config,
            cases,
            only,
            seeds: 0,
            first_seed,
            duration,
            transient,
            threads: 1,
            memory_limit_gb,
            out: PathBuf::new(),
        }));
    }
    // clap requires both without --print-cases.
    let (Some(seeds), Some(out)) = (seeds, out) else {
        return Err("--seeds and --out are required without --print-cases".into());
    };
    first_seed
        .checked_add(seeds - 1)
        .ok_or_else(|| format!("--first-seed {first_seed} + --seeds {seeds} overflows"))?;
    // Before any work: the summary, and the runs file (and its lock) beside it.
    out::file(&out)?;
    out::file_beside(&out, &runs_path(&out))?;
    Ok(Command::Run(Options {
        config,
        cases,
        only,
        seeds,
        first_seed,
        duration,
        transient,
        threads: threads.unwrap_or_else(all_cores),
        memory_limit_gb,
        out,
    }))
}

/// The per-run file next to the summary: `RESULTS.csv` -> `RESULTS.runs.csv`.
pub fn runs_path(out: &Path) -> PathBuf {
    let stem = out.file_stem().unwrap_or_default().to_string_lossy();
    out.with_file_name(format!("{stem}.runs.csv"))
}

/// Runs `slowdrift montecarlo`.
pub fn run(args: MontecarloArgs) -> Result<(), Failure> {
    match command(args)? {
        Command::Run(options) => run_and_summarise(options),
        Command::PrintCases(options) => Ok(print_cases(&options)?),
    }
}

/// The base configuration as the file gives it (else the embedded default), and the one
/// the cases are made on (with `--duration` applied).
fn load_base(options: &Options, announce: bool) -> Result<(Problem, Problem), String> {
    let file_base = load_problem(options.config.as_deref(), options.memory_limit_gb)?;
    if announce {
        match &options.config {
            Some(path) => println!("base configuration: {}", path.display()),
            None => println!("base configuration: the embedded default platform"),
        }
        for line in file_base.summary().map_err(|e| e.to_string())? {
            println!("{line}");
        }
    }
    let mut base = file_base.clone();
    if let Some(duration) = options.duration {
        base.run.duration = duration;
    }
    Ok((file_base, base))
}

/// Case-table rows as they are read.
type Rows = Box<dyn Iterator<Item = slowdrift::Result<CaseRow>>>;

/// The rows the options select, read as a stream, and the name of their table: every row
/// of the table, or the one `--case` names (the table is read once before, to refuse an
/// unknown name by listing the names); without a table the base alone, case 'base'. The
/// table is read within `memory_limit` bytes (the base's).
fn case_rows(options: &Options, memory_limit: f64) -> Result<(Rows, String), String> {
    let no_such_case = |name: &str, names: &[&str]| {
        format!(
            "--case {name}: no such case; the cases are {}",
            names.join(", ")
        )
    };
    let Some(path) = &options.cases else {
        let base = CaseRow::base();
        if let Some(name) = options.only.as_ref().filter(|name| **name != base.name) {
            return Err(no_such_case(name, &[&base.name]));
        }
        return Ok((Box::new(std::iter::once(Ok(base))), String::new()));
    };
    let open = || open_case_table(path, memory_limit).map_err(|e| e.to_string());
    let rows: Rows = match &options.only {
        None => Box::new(open()?),
        Some(name) => {
            let mut table = open()?;
            let mut found = false;
            for row in &mut table {
                found |= row.map_err(|e| e.to_string())?.name == *name;
            }
            if !found {
                return Err(no_such_case(name, &table.names()));
            }
            let name = name.clone();
            Box::new(open()?.filter(move |row| row.as_ref().map_or(true, |r| r.name == name)))
        }
    };
    Ok((rows, path.display().to_string()))
}

/// `--print-cases`: the cases as JSON on stdout, each written as soon as it is made (the
/// table read as a stream: memory independent of its number of rows), with the FMU's
/// `hydroDatabase` = the absolute path of `--config` (empty: the FMU's packed default
/// platform). An error stops the document unfinished.
fn print_cases(options: &Options) -> Result<(), String> {
    let (file_base, base) = load_base(options, false)?;
    let hydro_database = match &options.config {
        Some(path) => std::fs::canonicalize(path)
            .map_err(|e| format!("{}: {e}", path.display()))?
            .to_str()
            .ok_or_else(|| format!("{}: the path is not UTF-8", path.display()))?
            .to_string(),
        None => String::new(),
    };
    let (rows, source) = case_rows(options, base.run.memory_limit)?;
    let cases = rows.map(|row| row.and_then(|row| row.case(&base, options.transient, &source)));
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    campaign::write_cases_json(
        &mut out,
        "standard output",
        cases,
        &file_base,
        &hydro_database,
    )
    .map_err(|e| e.to_string())
}

fn run_and_summarise(options: Options) -> Result<(), Failure> {
    let (_, base) = load_base(&options, true)?;
    let (rows, source) = case_rows(&options, base.run.memory_limit)?;
    let cases = rows
        .map(|row| row.and_then(|row| row.case(&base, options.transient, &source)))
        .collect::<Result<Vec<Case>, _>>()
        .map_err(|e| e.to_string())?;
    if let Some(transient) = options.transient {
        for case in &cases {
            let run = format!("the run of case '{}'", case.name);
            transient_leaves_samples(transient, case.problem.run.duration, &run)?;
        }
    }
    let runs_path = runs_path(&options.out);
    let seeds = options.first_seed..options.first_seed + options.seeds;
    let wanted: Vec<Job> = (0..cases.len())
        .flat_map(|case| seeds.clone().map(move |seed| Job { case, seed }))
        .collect();
    println!("seeds {} to {} of every case", seeds.start, seeds.end - 1);
    let Campaign { runs, interrupted } = run_campaign(
        &cases,
        &wanted,
        options.threads,
        &runs_path,
        base.run.memory_limit,
    )?;
    let total = wanted.len();
    let summaries: Vec<CaseSummary> = cases
        .iter()
        .map(|case| CaseSummary::new(case, &runs, &seeds))
        .collect();
    write_summary(&options.out, &summaries, options.seeds).map_err(|e| e.to_string())?;
    print_summary(&summaries, options.seeds);
    println!(
        "summary written to {}, runs to {}",
        options.out.display(),
        runs_path.display()
    );
    if let Some(interrupted) = interrupted {
        return Err(interrupted.failure(&runs_path, Some(&options.out)));
    }
    let failed: usize = summaries.iter().map(|s| s.failed).sum();
    if failed > 0 {
        return Err(format!(
            "{failed} of {total} runs failed (their errors are in {} and the summary)",
            runs_path.display()
        )
        .into());
    }
    Ok(())
}

/// What [`run_campaign`] leaves: every run the per-run file holds, and whether a signal
/// stopped the campaign before every run was done.
pub struct Campaign {
    pub runs: Vec<RunRow>,
    pub interrupted: Option<Interrupted>,
}

/// A campaign a signal stopped.
pub struct Interrupted {
    signal: Signal,
    /// Runs done (in the per-run file) and not done, of those this call had to run.
    done: usize,
    not_done: usize,
}

impl Interrupted {
    /// The failure the command ends with: what was kept, in which files, and how to resume.
    pub fn failure(&self, runs_path: &Path, summary: Option<&Path>) -> Failure {
        let summary = summary.map_or(String::new(), |path| {
            format!("; the summary of the runs done is in {}", path.display())
        });
        Failure {
            message: format!(
                "stopped by {}: {} run(s) done and written to {}, {} not done (the runs in \
                 flight abandoned){summary}. To resume, run the same command again:\n    {}",
                self.signal.name(),
                self.done,
                runs_path.display(),
                self.not_done,
                this_command()
            ),
            status: self.signal.exit_status(),
        }
    }
}

/// Runs the `wanted` jobs of `cases` that the per-run file `runs_path` does not already
/// hold as successful (resume; a case run before with another configuration is refused),
/// appending each result to the file as it finishes, with a progress line on stderr;
/// returns every run the file then holds. The file is locked meanwhile (another process
/// on it is refused), and SIGINT or SIGTERM stops the campaign ([`super::interrupt`]). The
/// file is read within `memory_limit` bytes.
pub fn run_campaign(
    cases: &[Case],
    wanted: &[Job],
    threads: usize,
    runs_path: &Path,
    memory_limit: f64,
) -> Result<Campaign, String> {
    let (done, mut file) = RunsFile::open(runs_path, memory_limit).map_err(|e| e.to_string())?;
    // Computed once per case: a fingerprint formats the whole configuration.
    let fingerprints: Vec<String> = cases.iter().map(Case::fingerprint).collect();
    check_fingerprints(cases, &fingerprints, &done, runs_path)?;
    let jobs: Vec<Job> = wanted
        .iter()
        .copied()
        .filter(|job| {
            !done
                .iter()
                .any(|r| r.case == cases[job.case].name && r.seed == job.seed && r.result.is_ok())
        })
        .collect();
    println!(
        "{} case(s) = {} runs; {} already in {}; {} to run on {threads} thread(s)",
        cases.len(),
        wanted.len(),
        wanted.len() - jobs.len(),
        runs_path.display(),
        jobs.len(),
    );
    println!(
        "statistics of the slow drift (X, Y, theta); the wave-frequency motion is not made \
         (the slow-drift equations do not use it)"
    );
    let widths = campaign_lane_widths(cases, jobs.len(), threads);
    for (case, &width) in cases.iter().zip(&widths) {
        let why = if width == LANES {
            "at most"
        } else if !has_drag(&case.problem) {
            "no drag for lanes to share"
        } else if width == lane_width(case) {
            "what the memory limit holds of its runs' records"
        } else {
            "the jobs per thread"
        };
        println!(
            "  {}: {} s at {} s, transient {} s; {width} seed(s) stepped together ({why}; \
             drag in {} lanes)",
            case.name,
            written(case.problem.run.duration),
            written(case.problem.run.time_step),
            readable(case.transient),
            Isa::detect().name()
        );
    }

    let interrupts = Interrupts::install()?;
    let mut progress = Progress::new(jobs.len());
    let mut write_error = None;
    run_jobs(cases, &jobs, threads, interrupts.stop(), |event| {
        if let Some(finished) = event {
            let job = jobs[finished.job];
            progress.failed += usize::from(finished.result.is_err());
            let row = runs_file::row(
                &cases[job.case],
                &fingerprints[job.case],
                job.seed,
                finished.result,
            );
            if let Err(e) = file.append(&row) {
                write_error.get_or_insert(e.to_string());
            }
            progress.done += 1;
        }
        progress.show(false);
    });
    progress.show(true);
    let interrupted = interrupts
        .received()
        .filter(|_| progress.done < jobs.len())
        .map(|signal| Interrupted {
            signal,
            done: progress.done,
            not_done: jobs.len() - progress.done,
        });
    drop(interrupts);
    if let Some(e) = write_error {
        return Err(e);
    }
    let runs = file.runs().map_err(|e| e.to_string())?;
    Ok(Campaign { runs, interrupted })
}

fn check_fingerprints(
    cases: &[Case],
    fingerprints: &[String],
    done: &[RunRow],
    path: &Path,
) -> Result<(), String> {
    for (case, fingerprint) in cases.iter().zip(fingerprints) {
        if let Some(other) = done
            .iter()
            .find(|r| r.case == case.name && r.result.is_ok() && r.fingerprint != *fingerprint)
        {
            return Err(format!(
                "{}: case '{}' was run with another configuration or transient (fingerprint \
                 {}, now {fingerprint}); give another --out or remove the file",
                path.display(),
                case.name,
                other.fingerprint
            ));
        }
    }
    Ok(())
}

/// What the summary says about one case.
struct CaseSummary {
    name: String,
    /// Per DOF and statistic, the values of the seeds done, in seed order.
    values: [[Vec<f64>; 4]; 3],
    failed: usize,
    first_error: Option<String>,
}

impl CaseSummary {
    fn new(case: &Case, runs: &[RunRow], seeds: &std::ops::Range<u64>) -> Self {
        let mut mine: Vec<&RunRow> = runs
            .iter()
            .filter(|r| r.case == case.name && seeds.contains(&r.seed))
            .collect();
        mine.sort_by_key(|r| r.seed);
        let mut values: [[Vec<f64>; 4]; 3] = Default::default();
        let (mut failed, mut first_error) = (0, None);
        for run in mine {
            match &run.result {
                Ok(stats) => {
                    for (dof, s) in values.iter_mut().zip(stats) {
                        for (list, v) in dof.iter_mut().zip(s.values()) {
                            list.push(v);
                        }
                    }
                }
                Err(message) => {
                    failed += 1;
                    first_error.get_or_insert_with(|| format!("seed {}: {message}", run.seed));
                }
            }
        }
        CaseSummary {
            name: case.name.clone(),
            values,
            failed,
            first_error,
        }
    }

    fn done(&self) -> usize {
        self.values[0][0].len()
    }

    /// `complete` (every seed requested done), `partial` (some), `failed` (none done, some
    /// failed) or `not started` (none run: a campaign stopped before it reached the case).
    fn status(&self, requested: u64) -> &'static str {
        match (self.done(), self.failed) {
            (0, 0) => "not started",
            (0, _) => "failed",
            (n, _) if n as u64 == requested => "complete",
            _ => "partial",
        }
    }
}

/// Writes the summary anew, atomically (a kill never leaves it cut: `files::replace`).
fn write_summary(path: &Path, summaries: &[CaseSummary], requested: u64) -> slowdrift::Result<()> {
    slowdrift::files::replace(path, |w| summary_text(w, summaries, requested))
}

fn summary_text(
    w: &mut impl Write,
    summaries: &[CaseSummary],
    requested: u64,
) -> std::io::Result<()> {
    let mut header = "case,dof,unit,seeds_requested,seeds_done,seeds_failed,status".to_string();
    for stat in STATISTICS {
        header += &format!(",{stat},{stat}_se");
    }
    writeln!(w, "{header},error")?;
    for s in summaries {
        for ((dof, unit), stats) in DOFS.iter().zip(&s.values) {
            write!(
                w,
                "{},{dof},{unit},{requested},{},{},{}",
                s.name,
                s.done(),
                s.failed,
                s.status(requested)
            )?;
            for list in stats {
                match seed_statistics(list) {
                    Some(m) => write!(
                        w,
                        ",{},{}",
                        m.mean,
                        m.standard_error.map_or(String::new(), |e| e.to_string())
                    )?,
                    None => write!(w, ",,")?,
                }
            }
            let error = s.first_error.as_deref().unwrap_or_default();
            if error.is_empty() {
                writeln!(w, ",")?;
            } else {
                writeln!(w, ",\"{}\"", error.replace('"', "\"\""))?;
            }
        }
    }
    Ok(())
}

fn print_summary(summaries: &[CaseSummary], requested: u64) {
    println!(
        "{:<16} {:<11} {:>9} {:>24} {:>24} {:>24}",
        "case", "dof", "seeds", "mean +- se", "rms +- se", "max +- se"
    );
    for s in summaries {
        for ((dof, unit), stats) in DOFS.iter().zip(&s.values) {
            let cells: Vec<String> = stats[..3]
                .iter()
                .map(|list| match seed_statistics(list) {
                    Some(m) => match m.standard_error {
                        Some(e) => format!("{:.4} +- {e:.4}", m.mean),
                        None => format!("{:.4}", m.mean),
                    },
                    None => "-".into(),
                })
                .collect();
            println!(
                "{:<16} {:<11} {:>9} {:>24} {:>24} {:>24}",
                s.name,
                format!("{dof} [{unit}]"),
                format!("{}/{requested}", s.done()),
                cells[0],
                cells[1],
                cells[2]
            );
        }
        if let Some(error) = &s.first_error {
            println!("{:<16} {} run(s) failed; first: {error}", s.name, s.failed);
        } else if s.status(requested) == "not started" {
            println!("{:<16} not started", s.name);
        }
    }
}

/// The progress line on stderr: on a terminal redrawn in place at most 4 times a second,
/// otherwise one line every 10 s; always a last line.
struct Progress {
    total: usize,
    done: usize,
    failed: usize,
    started: Instant,
    shown: Option<Instant>,
    terminal: bool,
}

impl Progress {
    fn new(total: usize) -> Self {
        Progress {
            total,
            done: 0,
            failed: 0,
            started: Instant::now(),
            shown: None,
            terminal: std::io::stderr().is_terminal(),
        }
    }

    fn show(&mut self, last: bool) {
        let interval = Duration::from_millis(if self.terminal { 250 } else { 10_000 });
        if !last && self.shown.is_some_and(|t| t.elapsed() < interval) {
            return;
        }
        self.shown = Some(Instant::now());
        let elapsed = self.started.elapsed().as_secs_f64();
        let rate = self.done as f64 / elapsed.max(1e-9);
        let left = if self.done == 0 {
            "time left unknown".to_string()
        } else {
            format!("{} left", clock((self.total - self.done) as f64 / rate))
        };
        let failed = if self.failed > 0 {
            format!(" ({} failed)", self.failed)
        } else {
            String::new()
        };
        let line = format!(
            "montecarlo: {}/{} runs{failed}, {rate:.2} runs/s, {} elapsed, {left}",
            self.done,
            self.total,
            clock(elapsed)
        );
        let mut err = std::io::stderr().lock();
        // Progress is best effort: a closed stderr must not stop the campaign.
        let _ = if self.terminal {
            write!(err, "\r{line:<100}{}", if last { "\n" } else { "" })
        } else {
            writeln!(err, "{line}")
        };
    }
}

/// `h:mm:ss` or `m:ss`.
fn clock(seconds: f64) -> String {
    let s = seconds.round() as u64;
    if s >= 3600 {
        format!("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60)
    } else {
        format!("{}:{:02}", s / 60, s % 60)
    }
}
