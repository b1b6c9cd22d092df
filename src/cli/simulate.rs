//! `slowdrift simulate`: one simulation, its summary of every DOF after the transient, and
//! optionally its time series as CSV. Nothing of the run is kept in memory: the summary is
//! taken sample by sample ([`RunningSummary`]) and each CSV row written as its step is made,
//! into a temporary file renamed over `--out` when the run ends (`files::replace`), so a run of
//! any length takes the memory of its records alone, and a failed run leaves no cut file.

use super::args::Checked;
use clap::Args;
use slowdrift::error::numbers::{readable, written};
use slowdrift::model::Mode;
use slowdrift::stats::{RunningSummary, Summary};
use slowdrift::{Outputs, Simulation};
use std::io::Write;
use std::path::PathBuf;

/// `slowdrift simulate`.
#[derive(Args)]
#[command(args_override_self = true)]
pub struct SimulateArgs {
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
    #[arg(long, value_name = "GB", allow_hyphen_values = true, value_parser = super::args::gigabytes())]
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

/// Runs `slowdrift simulate`.
pub fn run(args: SimulateArgs) -> Result<(), String> {
    if let Some(path) = &args.out {
        super::out::file(path)?;
    }
    match &args.config {
        Some(path) => println!("configuration: {}", path.display()),
        None => println!("configuration: the embedded default platform"),
    }
    let config = super::args::load_problem(args.config.as_deref(), args.memory_limit_gb)?;
    // Checked before the summary, so that an invalid configuration prints only its error.
    config.check().map_err(|e| e.to_string())?;
    for line in config.summary().map_err(|e| e.to_string())? {
        println!("{line}");
    }
    let transient = args.transient.unwrap_or_else(|| config.default_transient());
    super::args::transient_leaves_samples(transient, config.run.duration, "the run")?;
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
    let steps = slowdrift::run_steps(&config).map_err(|e| e.to_string())?;
    // The summary's rule on the run's samples (t = m dt, m = 0 ..= steps), before the run: a
    // transient past the last sample, within the duration's rounding to whole steps, leaves
    // no sample, refused now rather than after the run (and its CSV). The steps fit a usize:
    // the problem's check keeps the end within 4.5e9 steps.
    let summary =
        RunningSummary::new(config.run.time_step, transient).map_err(|e| e.to_string())?;
    summary
        .require_kept(steps as usize + 1)
        .map_err(|e| e.to_string())?;
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
    let mut rows = SummaryRows::of(&sim, summary, transient);
    let (summaries, what) = match &args.out {
        None => run_to_end(&mut sim, steps, &mut |o| {
            rows.take(o);
            Ok(())
        })
        .and_then(|()| rows.finish())
        .map(|summaries| (summaries, "records and stepping"))
        .map_err(|stop| stop.message(&sim))?,
        Some(path) => {
            // The summaries are finished before the file is renamed over `--out`: a run that
            // cannot be summarised leaves no CSV either.
            let (mut stopped, mut finished) = (None, None);
            let written = slowdrift::files::replace(path, |w| {
                writeln!(w, "{CSV_HEADER}")?;
                let run = run_to_end(&mut sim, steps, &mut |o| {
                    rows.take(o);
                    write_row(w, o)
                })
                .and_then(|()| rows.finish());
                match run {
                    Ok(summaries) => {
                        finished = Some(summaries);
                        Ok(())
                    }
                    Err(stop) => {
                        stopped = Some(stop);
                        Err(std::io::Error::other("the run stopped"))
                    }
                }
            });
            if let Some(stop) = stopped {
                return Err(stop.message(&sim));
            }
            written.map_err(|e| e.to_string())?;
            let summaries = finished.ok_or("the run wrote its CSV without its summary")?;
            (summaries, "records, stepping and the CSV")
        }
    };
    let elapsed = started.elapsed();
    rows.print(&summaries);
    println!("{steps} steps in {:.3} s ({what})", elapsed.as_secs_f64());
    if let Some(path) = &args.out {
        println!("time series written to {}", path.display());
    }
    Ok(())
}

/// Why a run stopped before its end.
enum Stop {
    /// The simulation's error.
    Run(slowdrift::error::Error),
    /// Writing a sample failed.
    Write(std::io::Error),
    /// The samples taken cannot be summarised.
    Summary(slowdrift::error::Error),
}

impl Stop {
    /// The message: a run's error names the settings it blames where the user wrote them
    /// ([`slowdrift::Problem::explain`]).
    fn message(&self, sim: &Simulation) -> String {
        match self {
            Stop::Run(e) => sim.problem().explain(e),
            Stop::Write(e) => e.to_string(),
            Stop::Summary(e) => e.to_string(),
        }
    }
}

/// Steps `sim` `steps` times, handing `take` the outputs of every sample: the initial state,
/// then each step's.
fn run_to_end(
    sim: &mut Simulation,
    steps: u64,
    take: &mut dyn FnMut(&Outputs) -> std::io::Result<()>,
) -> Result<(), Stop> {
    for k in 0..=steps {
        if k > 0 {
            sim.step([0.0; 3]).map_err(Stop::Run)?;
        }
        take(&sim.outputs().map_err(Stop::Run)?).map_err(Stop::Write)?;
    }
    Ok(())
}

/// Which output a summary row reads.
type Dofs = fn(&Outputs) -> &[f64];

/// The rows of the printed summary, each summarised as the samples come.
struct SummaryRows {
    /// (name, scale, unit, the output's DOFs, which DOF)
    rows: Vec<(String, f64, &'static str, Dofs, usize)>,
    summaries: Vec<RunningSummary>,
    transient: f64,
    dt: f64,
}

impl SummaryRows {
    /// Surge, sway and yaw; with wave-frequency motion its six DOFs (inertial axes) and the
    /// totals; with wind the wind speed at the force's height and the wind force in X; each
    /// summarised as `summary` (none taken yet) summarises, after `transient` s.
    fn of(sim: &Simulation, summary: RunningSummary, transient: f64) -> Self {
        let dt = sim.problem().run.time_step;
        let deg = 180.0 / std::f64::consts::PI;
        let mut rows: Vec<(String, f64, &str, Dofs, usize)> = ["surge", "sway", "yaw"]
            .iter()
            .enumerate()
            .map(|(i, name)| {
                let (scale, unit) = if i == 2 { (deg, "deg") } else { (1.0, "m") };
                (name.to_string(), scale, unit, (|o| &o.position) as Dofs, i)
            })
            .collect();
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
        let summaries = vec![summary; rows.len()];
        SummaryRows {
            rows,
            summaries,
            transient,
            dt,
        }
    }

    /// Takes one sample's outputs.
    fn take(&mut self, o: &Outputs) {
        for ((_, scale, _, dofs, i), summary) in self.rows.iter().zip(&mut self.summaries) {
            summary.push(dofs(o)[*i] * scale);
        }
    }

    /// The rows' summaries of the samples taken.
    fn finish(&self) -> Result<Vec<Summary>, Stop> {
        self.summaries
            .iter()
            .map(|s| s.finish().map_err(Stop::Summary))
            .collect()
    }

    /// Prints the table of the rows' `summaries`.
    fn print(&self, summaries: &[Summary]) {
        println!(
            "statistics after a transient of {} s ({} samples at {} s):",
            readable(self.transient),
            summaries[0].samples,
            written(self.dt)
        );
        println!(
            "{:<18} {:>14} {:>14} {:>14} {:>14}",
            "DOF", "mean", "rms", "max", "min"
        );
        for ((name, _, unit, _, _), s) in self.rows.iter().zip(summaries) {
            println!(
                "{:<18} {:>14.4} {:>14.4} {:>14.4} {:>14.4}",
                format!("{name} [{unit}]"),
                s.mean,
                s.rms,
                s.max,
                s.min
            );
        }
    }
}

/// The CSV's header: SI units in the names.
const CSV_HEADER: &str = "time_s,X_m,Y_m,theta_rad,Xdot_m_s,Ydot_m_s,thetadot_rad_s,eta_m,\
     Fx_wave_N,Fy_wave_N,Mz_wave_Nm,Fx_damping_N,Fy_damping_N,Mz_damping_Nm,\
     Fx_drag_N,Fy_drag_N,Mz_drag_Nm,\
     X_wf_m,Y_wf_m,Z_wf_m,roll_wf_rad,pitch_wf_rad,yaw_wf_rad,\
     X_total_m,Y_total_m,Z_total_m,roll_total_rad,pitch_total_rad,yaw_total_rad,\
     Xdot_total_m_s,Ydot_total_m_s,Zdot_total_m_s,rolldot_total_rad_s,\
     pitchdot_total_rad_s,yawdot_total_rad_s,\
     windVelocity_m_s,Fx_wind_N,Fy_wind_N,Mz_wind_Nm";

/// One sample's CSV row.
fn write_row(w: &mut impl Write, o: &Outputs) -> std::io::Result<()> {
    let f = &o.forces;
    let fields = std::iter::once(&o.time)
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
        .chain(&f.wind);
    // 17 significant digits: every f64 reads back bit for bit. Written as formatted, with no
    // string per field.
    for (i, v) in fields.enumerate() {
        let separator = if i == 0 { "" } else { "," };
        write!(w, "{separator}{v:.16e}")?;
    }
    writeln!(w)
}
