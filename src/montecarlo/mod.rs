//! Monte Carlo campaigns: many seeds of one or many cases, on all cores.
//!
//! A [`Case`] is a complete [`Problem`] (its seed is replaced per run) with the start-up
//! transient to drop. [`run_seed`] simulates one (case, seed) and summarises surge, sway and
//! yaw after the transient ([`DofStats`]); [`run_jobs`] runs a list of (case, seed) jobs on
//! scoped threads that take the next job from a shared counter and hand each result to the
//! calling thread as it finishes, and stops early, abandoning the runs in flight, when its
//! `stop` flag is set (the CLI sets it on SIGINT and SIGTERM; the library installs no signal
//! handler); [`seed_statistics`] is the mean over seeds and its
//! standard error. The results depend only on (case, seed): not on the thread count or the
//! order in which runs finish.
//!
//! [`cases`] reads the case table (CSV) and applies its overrides to a base configuration;
//! [`runs_file`] writes and reads the per-run CSV that makes a campaign resumable.

pub mod cases;
pub mod runs_file;

use crate::error::{Error, Result};
use crate::fingerprint::fingerprint;
use crate::record_plan::PlanKey;
use crate::stats::summarize;
use crate::{Problem, RecordPlan, Simulation};
use std::collections::HashMap;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// The degrees of freedom summarised, in order, with the unit of their statistics.
pub const DOFS: [(&str, &str); 3] = [("surge", "m"), ("sway", "m"), ("yaw", "deg")];

/// One case of a campaign.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    /// Unique name (the case table's `name`, or `case<row>`).
    pub name: String,
    /// The configuration; `sea.seed` is set per run.
    pub problem: Problem,
    /// Start-up transient dropped from the statistics, s from the start of the run.
    pub transient: f64,
}

impl Case {
    /// The fingerprint (`crate::fingerprint`) of everything that determines the results except the
    /// seed (the problem with seed 0, and the transient), as 16 hex digits: the per-run file
    /// stores it so that a resumed campaign refuses to mix configurations.
    pub fn fingerprint(&self) -> String {
        let mut problem = self.problem.clone();
        problem.sea.seed = 0;
        format!(
            "{:016x}",
            crate::fingerprint::fingerprint(&(&problem, self.transient))
        )
    }
}

/// Statistics of one DOF of one run after the transient: surge and sway in m, yaw in deg.
/// `rms` is about the mean (see [`crate::stats::Summary`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DofStats {
    pub mean: f64,
    pub rms: f64,
    pub max: f64,
    pub min: f64,
}

impl DofStats {
    /// The four statistics in the order mean, rms, max, min.
    pub fn values(&self) -> [f64; 4] {
        [self.mean, self.rms, self.max, self.min]
    }
}

/// The names of [`DofStats::values`].
pub const STATISTICS: [&str; 4] = ["mean", "rms", "max", "min"];

/// Simulates `case` with `seed` from its start for its duration (no external force) and
/// summarises (X, Y, theta) after the transient; yaw is reported in degrees.
pub fn run_seed(case: &Case, seed: u64) -> Result<[DofStats; 3]> {
    run_seed_with(case, &Arc::new(RecordPlan::new(&case.problem)?), seed)
}

/// [`run_seed`] with the case's [`RecordPlan`] made beforehand (once for all its seeds).
pub fn run_seed_with(case: &Case, plan: &Arc<RecordPlan>, seed: u64) -> Result<[DofStats; 3]> {
    let never = AtomicBool::new(false);
    let stats = run_seed_unless(case, plan, seed, &never)?;
    Ok(stats.expect("a run that is never stopped ends"))
}

/// [`run_seed_with`], abandoned (`Ok(None)`) at the first time step that finds `stop` set.
fn run_seed_unless(
    case: &Case,
    plan: &Arc<RecordPlan>,
    seed: u64,
    stop: &AtomicBool,
) -> Result<Option<[DofStats; 3]>> {
    let mut problem = case.problem.clone();
    problem.sea.seed = seed;
    let dt = problem.run.time_step;
    let Some(records) = positions(Simulation::with_plan(problem, plan)?, stop)? else {
        return Ok(None);
    };
    let mut out = [DofStats {
        mean: 0.0,
        rms: 0.0,
        max: 0.0,
        min: 0.0,
    }; 3];
    for (i, record) in records.iter().enumerate() {
        let s = summarize(record, dt, case.transient)?;
        let scale = if i == 2 {
            180.0 / std::f64::consts::PI
        } else {
            1.0
        };
        out[i] = DofStats {
            mean: s.mean * scale,
            rms: s.rms * scale,
            max: s.max * scale,
            min: s.min * scale,
        };
    }
    Ok(Some(out))
}

/// Simulates `problem` from its initial condition for its duration with no external force
/// and returns the records of X (m), Y (m) and theta (rad), sampled every time step from
/// t = start_time (the initial state) to the end.
pub fn simulate_positions(problem: Problem) -> Result<[Vec<f64>; 3]> {
    let never = AtomicBool::new(false);
    let records = positions(Simulation::new(problem)?, &never)?;
    Ok(records.expect("a run that is never stopped ends"))
}

/// The positions of [`simulate_positions`] for a simulation at its start; `None` when a
/// step finds `stop` set (checked before every step: one relaxed atomic load).
fn positions(mut sim: Simulation, stop: &AtomicBool) -> Result<Option<[Vec<f64>; 3]>> {
    let mut records: [Vec<f64>; 3] = Default::default();
    let mut steps = 0;
    for record in &mut records {
        steps = crate::reserve_recorded(sim.problem(), record)?;
    }
    let mut push = |q: [f64; 3]| records.iter_mut().zip(q).for_each(|(r, v)| r.push(v));
    push(sim.position());
    for _ in 0..steps {
        if stop.load(Ordering::Relaxed) {
            return Ok(None);
        }
        sim.step([0.0; 3])?;
        push(sim.position());
    }
    Ok(Some(records))
}

/// One run of a campaign: the index of its case and its seed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Job {
    pub case: usize,
    pub seed: u64,
}

/// A finished job: its index in the job list and the outcome (the error as text; a panic
/// in the core becomes an error too, so one bad run never takes the campaign down).
#[derive(Debug, Clone, PartialEq)]
pub struct Finished {
    pub job: usize,
    pub result: std::result::Result<[DofStats; 3], String>,
}

/// How often [`run_jobs`] calls back while no run finishes (for a progress display).
pub const TICK: Duration = Duration::from_millis(250);

/// Runs `jobs` on `threads` scoped threads (at least 1) sharing one job counter. On the
/// calling thread, `on_event` receives `Some(finished)` as each run finishes (in finishing
/// order) and `None` every [`TICK`] while nothing finishes. Returns when every job is done,
/// or, once `stop` is set, as soon as the runs in flight have seen it: no job starts after
/// it, a run in flight is abandoned at its next time step (a plan being made is finished
/// first), and the jobs not run or abandoned are not reported.
pub fn run_jobs(
    cases: &[Case],
    jobs: &[Job],
    threads: usize,
    stop: &AtomicBool,
    mut on_event: impl FnMut(Option<Finished>),
) {
    let plans = CasePlans::new(cases, jobs);
    let run_job = |index: usize| {
        let job = jobs[index];
        let run = || {
            if stop.load(Ordering::Relaxed) {
                return Ok(None);
            }
            let plan = plans.get(job.case)?.map_err(|e| e.to_string())?;
            let case = &cases[job.case];
            // A run's error names the settings it blames where the case wrote them.
            run_seed_unless(case, &plan, job.seed, stop).map_err(|e| case.problem.explain(&e))
        };
        let result = catch_unwind(AssertUnwindSafe(run)).unwrap_or_else(|panic| {
            Err(Error::invalid("run", "panic", panic_text(&*panic)).to_string())
        });
        plans.done(job.case);
        result.transpose()
    };
    crate::parallel::run_indexed(jobs.len(), threads, run_job, TICK, |event| match event {
        Some((job, Some(result))) => on_event(Some(Finished { job, result })),
        // Abandoned: not reported.
        Some((_, None)) => {}
        None => on_event(None),
    });
}

/// The [`RecordPlan`]s of a campaign, one per group of cases with the same
/// [`PlanKey`] (cases that differ only in the wave height, the drag coefficients, the current
/// or the mooring share one), made by the first of the group's jobs to start and dropped when
/// its last job is done, so that a campaign holds only the plans of the groups in progress.
struct CasePlans<'a> {
    cases: &'a [Case],
    /// The group of each case.
    group: Vec<usize>,
    /// Per group: its plan (or why it could not be made), once made.
    slots: Vec<Mutex<Option<SharedPlan>>>,
    /// Per group: jobs not yet done.
    remaining: Vec<AtomicUsize>,
}

type SharedPlan = Result<Arc<RecordPlan>>;

impl<'a> CasePlans<'a> {
    fn new(cases: &'a [Case], jobs: &[Job]) -> Self {
        let keys: Vec<PlanKey> = cases.iter().map(|c| PlanKey::of(&c.problem)).collect();
        let mut by_fingerprint: HashMap<u64, Vec<usize>> = HashMap::new();
        let mut first_of_group: Vec<usize> = Vec::new();
        let mut group = Vec::with_capacity(cases.len());
        for (case, key) in keys.iter().enumerate() {
            let candidates = by_fingerprint.entry(fingerprint(key)).or_default();
            let found = candidates
                .iter()
                .copied()
                .find(|&g| keys[first_of_group[g]] == *key);
            let g = found.unwrap_or_else(|| {
                first_of_group.push(case);
                candidates.push(first_of_group.len() - 1);
                first_of_group.len() - 1
            });
            group.push(g);
        }
        let remaining: Vec<AtomicUsize> = (0..first_of_group.len())
            .map(|_| AtomicUsize::new(0))
            .collect();
        for job in jobs {
            remaining[group[job.case]].fetch_add(1, Ordering::Relaxed);
        }
        CasePlans {
            cases,
            group,
            slots: (0..first_of_group.len())
                .map(|_| Mutex::new(None))
                .collect(),
            remaining,
        }
    }

    /// The plan of case `case`, made now from this case if no job of its group has made it
    /// yet. A case the model refuses makes no plan for its group: its error is its own.
    fn get(&self, case: usize) -> std::result::Result<SharedPlan, String> {
        let mut slot = self.slots[self.group[case]]
            .lock()
            .map_err(|_| "a run panicked while making this case's plan".to_string())?;
        if slot.is_none() {
            let problem = &self.cases[case].problem;
            problem.check().map_err(|e| e.to_string())?;
            *slot = Some(RecordPlan::of_checked(problem).map(Arc::new));
        }
        Ok(slot.as_ref().expect("made above").clone())
    }

    /// One job of case `case` is done; the last one of its group drops the plan.
    fn done(&self, case: usize) {
        let g = self.group[case];
        if self.remaining[g].fetch_sub(1, Ordering::AcqRel) == 1 {
            if let Ok(mut slot) = self.slots[g].lock() {
                slot.take();
            }
        }
    }
}

fn panic_text(panic: &(dyn std::any::Any + Send)) -> String {
    let message = crate::error::panic_message(panic).unwrap_or_default();
    format!("the run panicked: {message}")
}

/// Mean over seeds of one statistic and its sampling uncertainty.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeedStatistics {
    /// Number of seeds.
    pub n: usize,
    /// Arithmetic mean of the values, summed in the order given.
    pub mean: f64,
    /// Standard error of the mean, s / sqrt(n) with the sample standard deviation
    /// s = sqrt(sum (x - mean)^2 / (n - 1)); `None` for fewer than two seeds.
    pub standard_error: Option<f64>,
}

/// The mean of `values` (one per seed) and its standard error; `None` when empty.
pub fn seed_statistics(values: &[f64]) -> Option<SeedStatistics> {
    if values.is_empty() {
        return None;
    }
    let n = values.len();
    let mean = values.iter().sum::<f64>() / n as f64;
    let standard_error = (n >= 2).then(|| {
        let variance = values.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
        (variance / n as f64).sqrt()
    });
    Some(SeedStatistics {
        n,
        mean,
        standard_error,
    })
}
