//! `slowdrift`: the command-line tool.
//!
//! `slowdrift simulate [--config FILE] [--out FILE.csv] [--transient SECONDS]` runs one
//! simulation (the embedded default platform without `--config`), prints the summary of
//! surge, sway and yaw, and writes the time series as CSV (17 significant digits, so every
//! value reads back bit for bit).
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

use clap::{Args, Parser, Subcommand};
use cli::args::Checked;
use cli::Failure;
use slowdrift::error::numbers::{readable, written};
use slowdrift::model::Mode;
use slowdrift::stats::{summarize, Summary};
use slowdrift::{Outputs, Simulation};
use std::io::{BufWriter, Write};
use std::path::PathBuf;
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
    Simulate(SimulateArgs),
    /// Hydro databases: imports WAMIT or NEMOH output, or writes a configuration's drift table
    Hydro(cli::hydro::HydroArgs),
    /// Many seeds of one case or of a table of cases on all cores, resumably
    Montecarlo(cli::montecarlo::MontecarloArgs),
    /// The paper's studies (E&S 1996 Figs 3-5 and 7-15) and the motion spectra against the
    /// frequency domain as CSV and figures (PNG and SVG) in a directory
    Study(cli::study::StudyArgs),
}

/// `slowdrift simulate`.
#[derive(Args)]
#[command(args_override_self = true)]
struct SimulateArgs {
    /// Platform, sea and run configuration (TOML) [default: the embedded default platform]
    #[arg(long, value_name = "FILE.toml", allow_hyphen_values = true)]
    config: Option<PathBuf>,
    /// Writes the time series as CSV, 17 significant digits (every value reads back bit for
    /// bit) [default: not written]
    #[arg(long, value_name = "FILE.csv", allow_hyphen_values = true)]
    out: Option<PathBuf>,
    /// Start-up transient dropped before the statistics, s [default: ten surge natural
    /// periods, at most half the run]
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, value_parser = Checked(transient))]
    transient: Option<f64>,
    /// Memory the records may take, GB (1e9 bytes): larger estimates are refused [default:
    /// the configuration's run.memory_limit_gb, 4]
    #[arg(long, value_name = "GB", allow_hyphen_values = true, value_parser = cli::args::gigabytes())]
    memory_limit_gb: Option<f64>,
}

/// `--transient SECONDS` of `simulate`.
fn transient(flag: &str, text: &str) -> Result<f64, String> {
    let seconds: f64 = text
        .parse()
        .map_err(|_| format!("{flag} {text}: not a number"))?;
    if !(seconds.is_finite() && seconds >= 0.0) {
        return Err(format!(
            "{flag} {text}: must be a non-negative number of seconds"
        ));
    }
    Ok(seconds)
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
        Command::Simulate(args) => Ok(simulate(args)?),
        Command::Hydro(args) => Ok(cli::hydro::run(args)?),
        Command::Montecarlo(args) => cli::montecarlo::run(args),
        Command::Study(args) => cli::study::run(args),
    }
}

fn simulate(args: SimulateArgs) -> Result<(), String> {
    if let Some(path) = &args.out {
        cli::out::file(path)?;
    }
    match &args.config {
        Some(path) => println!("configuration: {}", path.display()),
        None => println!("configuration: the embedded default platform"),
    }
    let config = cli::args::load_problem(args.config.as_deref(), args.memory_limit_gb)?;
    // Checked before the summary, so that an invalid configuration prints only its error.
    config.check().map_err(|e| e.to_string())?;
    for line in config.summary().map_err(|e| e.to_string())? {
        println!("{line}");
    }
    let transient = args.transient.unwrap_or_else(|| config.default_transient());
    cli::args::transient_leaves_samples(transient, config.run.duration, "the run")?;
    if let Some(trim) = config.band_trim() {
        println!(
            "wave band: the default {:.4} .. {:.4} rad/s limited to the hydrodynamic data's \
             {:.4} .. {:.4} rad/s ({:.2e} of its variance left out; [sea] band sets it)",
            trim.default.0, trim.default.1, trim.band.0, trim.band.1, trim.variance_left_out
        );
    }
    let directions = config.sea.directions().len();
    if directions > 1 {
        println!(
            "short-crested: {directions} directions, interaction between them: {}",
            config.interaction().word()
        );
    }
    let started = std::time::Instant::now();
    let mut sim = Simulation::new(config).map_err(|e| e.to_string())?;
    for r in sim.qtf_ranks() {
        println!(
            "full QTF, {} {}: rank {} of {} (discarded {:.1e} of the eigenvalues' absolute \
             sum)",
            r.dof.name(),
            if r.directions > 1 {
                format!("across {} directions with their cross terms", r.directions)
            } else {
                format!("at {:.1} deg", r.heading.to_degrees())
            },
            r.rank,
            r.size,
            r.discarded
        );
    }
    println!("{}", sim.records_line());
    let outputs = run_to_end(&mut sim)?;
    let elapsed = started.elapsed();
    print_summary(&sim, &outputs, transient)?;
    println!(
        "{} steps in {:.3} s (records and stepping)",
        outputs.len() - 1,
        elapsed.as_secs_f64()
    );
    if let Some(path) = &args.out {
        write_csv(path, &outputs).map_err(|e| format!("{}: {e}", path.display()))?;
        println!("time series written to {}", path.display());
    }
    Ok(())
}

/// The outputs at every step of the run; an error of the run names the settings it blames
/// where the user wrote them ([`slowdrift::Problem::explain`]).
fn run_to_end(sim: &mut Simulation) -> Result<Vec<Outputs>, String> {
    let mut outputs = Vec::new();
    let steps =
        slowdrift::reserve_recorded(sim.problem(), &mut outputs).map_err(|e| e.to_string())?;
    let mut record = |sim: &mut Simulation, step: bool| {
        if step {
            sim.step([0.0; 3])?;
        }
        outputs.push(sim.outputs()?);
        Ok(())
    };
    for k in 0..=steps {
        record(sim, k > 0).map_err(|e| sim.problem().explain(&e))?;
    }
    Ok(outputs)
}

fn print_summary(sim: &Simulation, outputs: &[Outputs], transient: f64) -> Result<(), String> {
    let dt = sim.problem().run.time_step;
    let deg = 180.0 / std::f64::consts::PI;
    // (name, scale, unit, the output's DOFs, which DOF)
    type Dofs = fn(&Outputs) -> &[f64];
    let mut rows: Vec<(String, f64, &str, Dofs, usize)> = ["surge", "sway", "yaw"]
        .iter()
        .enumerate()
        .map(|(i, name)| {
            let (scale, unit) = if i == 2 { (deg, "deg") } else { (1.0, "m") };
            (name.to_string(), scale, unit, (|o| &o.position) as Dofs, i)
        })
        .collect();
    // With wave-frequency motion: its six DOFs (inertial axes) and the totals.
    if sim.records().motion.is_some() {
        let parts: [(&str, Dofs); 2] = [
            ("wf", |o| &o.motion.wave_frequency),
            ("total", |o| &o.motion.total),
        ];
        for (suffix, dofs) in parts {
            for (i, dof) in ["X", "Y", "Z", "roll", "pitch", "yaw"].iter().enumerate() {
                let (scale, unit) = if i < 3 { (1.0, "m") } else { (deg, "deg") };
                rows.push((format!("{dof}_{suffix}"), scale, unit, dofs, i));
            }
        }
    }
    // With wind: the instantaneous wind speed at the force's height and the wind force in X.
    if !sim.problem().wind.is_calm() {
        rows.push((
            "wind speed".into(),
            1.0,
            "m/s",
            |o| std::slice::from_ref(&o.wind_speed),
            0,
        ));
        rows.push(("Fx_wind".into(), 1.0, "N", |o| &o.forces.wind, 0));
    }
    let summaries = rows
        .iter()
        .map(|(_, scale, _, dofs, i)| {
            let record: Vec<f64> = outputs.iter().map(|o| dofs(o)[*i] * scale).collect();
            summarize(&record, dt, transient).map_err(|e| e.to_string())
        })
        .collect::<Result<Vec<Summary>, String>>()?;
    println!(
        "statistics after a transient of {} s ({} samples at {} s):",
        readable(transient),
        summaries[0].samples,
        written(dt)
    );
    println!(
        "{:<18} {:>14} {:>14} {:>14} {:>14}",
        "DOF", "mean", "rms", "max", "min"
    );
    for ((name, _, unit, _, _), s) in rows.iter().zip(&summaries) {
        println!(
            "{:<18} {:>14.4} {:>14.4} {:>14.4} {:>14.4}",
            format!("{name} [{unit}]"),
            s.mean,
            s.rms,
            s.max,
            s.min
        );
    }
    Ok(())
}

fn write_csv(path: &std::path::Path, outputs: &[Outputs]) -> std::io::Result<()> {
    let mut w = BufWriter::new(std::fs::File::create(path)?);
    writeln!(
        w,
        "time_s,X_m,Y_m,theta_rad,Xdot_m_s,Ydot_m_s,thetadot_rad_s,eta_m,\
         Fx_wave_N,Fy_wave_N,Mz_wave_Nm,Fx_damping_N,Fy_damping_N,Mz_damping_Nm,\
         Fx_drag_N,Fy_drag_N,Mz_drag_Nm,\
         X_wf_m,Y_wf_m,Z_wf_m,roll_wf_rad,pitch_wf_rad,yaw_wf_rad,\
         X_total_m,Y_total_m,Z_total_m,roll_total_rad,pitch_total_rad,yaw_total_rad,\
         Xdot_total_m_s,Ydot_total_m_s,Zdot_total_m_s,rolldot_total_rad_s,\
         pitchdot_total_rad_s,yawdot_total_rad_s,\
         windVelocity_m_s,Fx_wind_N,Fy_wind_N,Mz_wind_Nm"
    )?;
    for o in outputs {
        let f = &o.forces;
        let fields: Vec<String> = [o.time]
            .iter()
            .chain(&o.position)
            .chain(&o.velocity)
            .chain(std::iter::once(&o.wave_elevation))
            .chain(&f.wave)
            .chain(&f.damping)
            .chain(&f.drag)
            .chain(&o.motion.wave_frequency)
            .chain(&o.motion.total)
            .chain(&o.motion.total_rate)
            .chain(std::iter::once(&o.wind_speed))
            .chain(&f.wind)
            // 17 significant digits: every f64 reads back bit for bit.
            .map(|v| format!("{v:.16e}"))
            .collect();
        writeln!(w, "{}", fields.join(","))?;
    }
    w.flush()
}
