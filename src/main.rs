//! `slowdrift`: the command-line tool.
//!
//! `slowdrift simulate [--config FILE] [--out FILE.csv] [--transient SECONDS]` runs one
//! simulation (the embedded default platform without `--config`), prints the summary of
//! surge, sway and yaw, and writes the time series as CSV (17 significant digits, so every
//! value reads back bit for bit).
//!
//! `slowdrift hydro wamit --root PATH/NAME --out FILE.json` imports WAMIT output into a
//! native hydro database ([`cli::hydro`]).
//!
//! `slowdrift montecarlo ... --seeds N --out RESULTS.csv` runs many seeds of one case or a
//! table of cases on all cores, resumably ([`cli::montecarlo`]).
//!
//! `slowdrift study <waves|boxplots|transient|sensitivity> ... --out DIR` makes the paper's
//! studies as CSV and figures (PNG and SVG) ([`cli::study`], drawing in [`plot`]).

mod cli;
mod plot;

use slowdrift::problem::{self, default_problem};
use slowdrift::scenario::default::DEFAULT_DRIFT_LABEL;
use slowdrift::stats::{summarize, Summary};
use slowdrift::{Outputs, Simulation};
use std::io::{BufWriter, Write};
use std::path::PathBuf;
use std::process::ExitCode;

const USAGE: &str =
    "usage: slowdrift simulate [--config FILE.toml] [--out FILE.csv] [--transient SECONDS]
       slowdrift hydro wamit --root PATH/NAME [--ulen 1] [--rho 1025] [--g 9.80665] --out FILE.json
       slowdrift hydro columns [--config FILE.toml] --out FILE.json
       slowdrift montecarlo [--config FILE.toml] [--cases CASES.csv] [--case NAME] --seeds N
                            [--first-seed 1] [--duration SECONDS] [--transient SECONDS] [--threads T]
                            --out RESULTS.csv
       slowdrift montecarlo [--config FILE.toml] [--cases CASES.csv] [--duration SECONDS]
                            [--transient SECONDS] --print-cases
       slowdrift study waves|boxplots|transient|sensitivity ... --out DIR (slowdrift study for the options)";

struct Arguments {
    config: Option<PathBuf>,
    out: Option<PathBuf>,
    transient: Option<f64>,
}

fn main() -> ExitCode {
    // Monte Carlo campaigns build and drop tens of MB of records per run.
    slowdrift::allocator::retain_freed_memory();
    match run(std::env::args().skip(1).collect()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("slowdrift: {message}");
            ExitCode::FAILURE
        }
    }
}

fn run(args: Vec<String>) -> Result<(), String> {
    match args.first().map(String::as_str) {
        Some("simulate") => simulate(parse_arguments(&args[1..])?),
        Some("hydro") => cli::hydro::run(&args[1..]),
        Some("montecarlo") => cli::montecarlo::run(&args[1..]),
        Some("study") => cli::study::run(&args[1..]),
        Some("--help") | Some("-h") | None => {
            println!("{USAGE}");
            Ok(())
        }
        Some(other) => Err(format!("unknown command '{other}'\n{USAGE}")),
    }
}

fn parse_arguments(args: &[String]) -> Result<Arguments, String> {
    let mut parsed = Arguments {
        config: None,
        out: None,
        transient: None,
    };
    let mut rest = args.iter();
    while let Some(flag) = rest.next() {
        let mut value = || {
            rest.next()
                .ok_or_else(|| format!("{flag} needs a value\n{USAGE}"))
        };
        match flag.as_str() {
            "--config" => parsed.config = Some(PathBuf::from(value()?)),
            "--out" => parsed.out = Some(PathBuf::from(value()?)),
            "--transient" => {
                let text = value()?;
                let seconds: f64 = text
                    .parse()
                    .map_err(|_| format!("--transient {text}: not a number"))?;
                if !(seconds.is_finite() && seconds >= 0.0) {
                    return Err(format!(
                        "--transient {text}: must be a non-negative number of seconds"
                    ));
                }
                parsed.transient = Some(seconds);
            }
            other => return Err(format!("unknown option '{other}'\n{USAGE}")),
        }
    }
    Ok(parsed)
}

fn simulate(args: Arguments) -> Result<(), String> {
    let config = match &args.config {
        Some(path) => problem::load(path).map_err(|e| e.to_string())?,
        None => {
            println!("embedded default platform; drift: {DEFAULT_DRIFT_LABEL}");
            default_problem().map_err(|e| e.to_string())?
        }
    };
    let transient = args.transient.unwrap_or_else(|| config.default_transient());
    let directions = config.sea.directions().len();
    if directions > 1 {
        println!(
            "short-crested: {directions} directions, interaction between them: {:?}",
            config.interaction()
        );
    }
    let started = std::time::Instant::now();
    let mut sim = Simulation::new(config).map_err(|e| e.to_string())?;
    for r in sim.qtf_ranks() {
        println!(
            "full QTF, {:?} at {:.1} deg: rank {} of {} (discarded {:.1e} of the eigenvalues' \
             absolute sum)",
            r.dof,
            r.heading.to_degrees(),
            r.rank,
            r.size,
            r.discarded
        );
    }
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

fn run_to_end(sim: &mut Simulation) -> Result<Vec<Outputs>, String> {
    let run = sim.config().run.clone();
    let steps = (run.duration / run.time_step).round() as usize;
    let mut outputs = Vec::with_capacity(steps + 1);
    outputs.push(sim.outputs().map_err(|e| e.to_string())?);
    for _ in 0..steps {
        sim.step([0.0; 3]).map_err(|e| e.to_string())?;
        outputs.push(sim.outputs().map_err(|e| e.to_string())?);
    }
    Ok(outputs)
}

fn print_summary(sim: &Simulation, outputs: &[Outputs], transient: f64) -> Result<(), String> {
    let dt = sim.config().run.time_step;
    let rows: [(&str, f64, &str); 3] = [
        ("surge", 1.0, "m"),
        ("sway", 1.0, "m"),
        ("yaw", 180.0 / std::f64::consts::PI, "deg"),
    ];
    let summaries = (0..3)
        .map(|i| {
            let record: Vec<f64> = outputs.iter().map(|o| o.position[i] * rows[i].1).collect();
            summarize(&record, dt, transient).map_err(|e| e.to_string())
        })
        .collect::<Result<Vec<Summary>, String>>()?;
    println!(
        "statistics after a transient of {transient:.0} s ({} samples at {dt} s):",
        summaries[0].samples
    );
    println!(
        "{:<10} {:>14} {:>14} {:>14} {:>14}",
        "DOF", "mean", "rms", "max", "min"
    );
    for ((name, _, unit), s) in rows.iter().zip(&summaries) {
        println!(
            "{:<10} {:>14.4} {:>14.4} {:>14.4} {:>14.4}",
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
         Fx_drag_N,Fy_drag_N,Mz_drag_Nm"
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
            // 17 significant digits: every f64 reads back bit for bit.
            .map(|v| format!("{v:.16e}"))
            .collect();
        writeln!(w, "{}", fields.join(","))?;
    }
    w.flush()
}
