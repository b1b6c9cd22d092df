//! `slowdrift`: the command-line tool.
//!
//! `slowdrift simulate [--config FILE] [--out FILE.csv] [--transient SECONDS]` runs one
//! simulation (the embedded default platform without `--config`), prints the summary of
//! surge, sway and yaw, and writes the time series as CSV (17 significant digits, so every
//! value reads back bit for bit) ([`cli::simulate`]).
//!
//! `slowdrift hydro <wamit|nemoh|columns> ... --out FILE.json` imports WAMIT or NEMOH output,
//! or writes a configuration's drift table, as a native hydro database ([`cli::hydro`]).
//!
//! `slowdrift montecarlo ... --seeds N --out RESULTS.csv` runs many seeds of one case or a
//! table of cases on all cores, resumably ([`cli::montecarlo`]).
//!
//! `slowdrift study <waves|boxplots|transient|sensitivity> ... --out DIR` makes the paper's
//! studies as CSV and figures (PNG and SVG) ([`cli::study`], drawing in [`plot`]).

mod cli;
mod plot;

use clap::{Parser, Subcommand};
use cli::Failure;
use std::process::ExitCode;

/// Slow-drift motions of moored floating platforms in random waves (Emmerhoff & Sclavounos
/// 1996): one simulation, hydro databases, Monte Carlo campaigns and the paper's studies.
#[derive(Parser)]
#[command(
    name = "slowdrift",
    version,
    max_term_width = 100,
    subcommand_required = true,
    after_help = "Each command lists its options, units and defaults: slowdrift COMMAND --help."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// One simulation (the embedded default platform without --config): prints the summary
    /// of surge, sway and yaw, optionally writes the time series as CSV
    Simulate(cli::simulate::SimulateArgs),
    /// Hydro databases: imports WAMIT or NEMOH output, or writes a configuration's drift table
    Hydro(cli::hydro::HydroArgs),
    /// Many seeds of one case or of a table of cases on all cores, resumably
    Montecarlo(cli::montecarlo::MontecarloArgs),
    /// The paper's studies (E&S 1996 Figs 3-5 and 7-15) and the motion spectra against the
    /// frequency domain as CSV and figures (PNG and SVG) in a directory
    Study(cli::study::StudyArgs),
}

fn main() -> ExitCode {
    // Monte Carlo campaigns build and drop tens of MB of records per run.
    slowdrift::allocator::retain_freed_memory();
    // Usage errors (no command among them): clap's message on stderr, exit status 2; --help
    // and --version: exit 0.
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure { message, status }) => {
            eprintln!("slowdrift: {message}");
            ExitCode::from(status)
        }
    }
}

fn run(cli: Cli) -> Result<(), Failure> {
    match cli.command {
        Command::Simulate(args) => Ok(cli::simulate::run(args)?),
        Command::Hydro(args) => Ok(cli::hydro::run(args)?),
        Command::Montecarlo(args) => cli::montecarlo::run(args),
        Command::Study(args) => cli::study::run(args),
    }
}
