//! Monte Carlo campaigns: many seeds of one or many cases, on all cores.
//!
//! A [`Case`] is a complete [`Problem`] (its seed is replaced per run) with the start-up
//! transient to drop. [`run_seed`] simulates one (case, seed) and summarises surge, sway and
//! yaw after the transient ([`DofStats`]); [`run_jobs`] runs a list of (case, seed) jobs, seeds of
//! one case in lanes (`lanes`, docs/architecture.md#seeds-in-lanes), on
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
mod lanes;
pub mod runs_file;

use crate::error::{Error, Result};
use crate::fingerprint::fingerprint;
use crate::model::{DragModel, WaveFrequencyMotion};
use crate::record_plan::{MemoryEstimate, PlanKey};
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
    /// The problem a campaign simulates for this case: the case's, without the
    /// wave-frequency motion, which a campaign does not summarise (its statistics are of the
    /// slow drift X, Y, theta) and which the slow-drift equations do not use
    /// (docs/theory.md#wave-frequency-motion), so its records are not made. The sea, the
    /// slow drift and every statistic are those of the case as given.
    pub fn simulated(&self) -> Problem {
        let mut problem = self.problem.clone();
        problem.model.wave_frequency_motion = WaveFrequencyMotion::Off;
        problem
    }

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
    run_seed_with(case, &Arc::new(RecordPlan::new(&case.simulated())?), seed)
}

/// [`run_seed`] with the plan of the case's [`Case::simulated`] problem made beforehand.
fn run_seed_with(case: &Case, plan: &Arc<RecordPlan>, seed: u64) -> Result<[DofStats; 3]> {
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
    let Some(records) = positions(seed_simulation(case, plan, seed)?, stop)? else {
        return Ok(None);
    };
    summarize_positions(case, &records).map(Some)
}

/// The simulation of `case` ([`Case::simulated`]) with `seed`, its records from `plan`.
fn seed_simulation(case: &Case, plan: &Arc<RecordPlan>, seed: u64) -> Result<Simulation> {
    let mut problem = case.simulated();
    problem.sea.seed = seed;
    Simulation::with_plan(problem, plan)
}

/// Summarises a run's records of X, Y and theta after the case's transient (yaw in
/// degrees).
fn summarize_positions(case: &Case, records: &[Vec<f64>; 3]) -> Result<[DofStats; 3]> {
    let dt = case.problem.run.time_step;
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
    Ok(out)
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
    let (mut records, steps) = positions_reserved(&sim)?;
    for _ in 0..steps {
        if stop.load(Ordering::Relaxed) {
            return Ok(None);
        }
        sim.step([0.0; 3])?;
        records
            .iter_mut()
            .zip(sim.position())
            .for_each(|(r, v)| r.push(v));
    }
    Ok(Some(records))
}

/// The records of X, Y and theta of `sim`'s run, reserved for its steps
/// ([`crate::reserve_recorded`]) and holding its initial position, and the steps.
fn positions_reserved(sim: &Simulation) -> Result<([Vec<f64>; 3], usize)> {
    let mut records: [Vec<f64>; 3] = Default::default();
    let mut steps = 0;
    for record in &mut records {
        steps = crate::reserve_recorded(sim.problem(), record)?;
    }
    records
        .iter_mut()
        .zip(sim.position())
        .for_each(|(r, v)| r.push(v));
    Ok((records, steps))
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

/// Runs `jobs` on `threads` scoped threads (at least 1) sharing one counter of lane groups
/// ([`lane_groups`]: consecutive jobs of one case, run in lanes by `lanes::run_lanes`,
/// each result that of [`run_seed`] bit for bit). On the calling thread, `on_event`
/// receives `Some(finished)` as each run finishes (in finishing order; the runs of a group
/// finish together) and `None` every [`TICK`] while nothing finishes. Returns when every
/// job is done, or, once `stop` is set, as soon as the runs in flight have seen it: no job
/// starts after it, a run in flight is abandoned at its next time step (a plan being made
/// is finished first), and the jobs not run or abandoned are not reported. A group that
/// panics is run again seed by seed, so that the panic is the error of its own run only.
pub fn run_jobs(
    cases: &[Case],
    jobs: &[Job],
    threads: usize,
    stop: &AtomicBool,
    mut on_event: impl FnMut(Option<Finished>),
) {
    let plans = CasePlans::new(cases, jobs);
    let groups = lane_groups(jobs, &campaign_lane_widths(cases, jobs.len(), threads));
    let run_group = |g: usize| {
        let members = groups[g].clone();
        let case_index = jobs[members.start].case;
        let alone = |j: usize| {
            guarded(|| run_job(cases, &plans, jobs[j], stop)).unwrap_or_else(|e| Some(Err(e)))
        };
        let outcomes: Vec<Outcome> = match members.len() {
            1 => vec![alone(members.start)],
            _ => {
                match guarded(|| run_group_in_lanes(cases, &plans, &jobs[members.clone()], stop)) {
                    Ok(Some(results)) => results.into_iter().map(Some).collect(),
                    Ok(None) => Vec::new(),
                    // Which lane panicked is not known: each run again on its own.
                    Err(_) => members.clone().map(alone).collect(),
                }
            }
        };
        for _ in members.clone() {
            plans.done(case_index);
        }
        members.zip(outcomes).collect::<Vec<_>>()
    };
    crate::parallel::run_indexed(
        groups.len(),
        threads,
        run_group,
        TICK,
        |event| match event {
            Some((_, finished)) => {
                for (job, outcome) in finished {
                    // Abandoned (`None`): not reported.
                    if let Some(result) = outcome {
                        on_event(Some(Finished { job, result }));
                    }
                }
            }
            None => on_event(None),
        },
    );
}

/// A run's outcome as [`Finished`] holds it; `None` when abandoned.
type Outcome = Option<std::result::Result<[DofStats; 3], String>>;

/// `run` with a panic turned into the run's error.
fn guarded<T>(run: impl FnOnce() -> T) -> std::result::Result<T, String> {
    catch_unwind(AssertUnwindSafe(run))
        .map_err(|panic| Error::invalid("run", "panic", panic_text(&*panic)).to_string())
}

/// One job on its own (a group of one lane).
fn run_job(cases: &[Case], plans: &CasePlans, job: Job, stop: &AtomicBool) -> Outcome {
    if stop.load(Ordering::Relaxed) {
        return None;
    }
    let case = &cases[job.case];
    let plan = match plans.plan(job.case) {
        Ok(plan) => plan,
        Err(e) => return Some(Err(e)),
    };
    // A run's error names the settings it blames where the case wrote them.
    run_seed_unless(case, &plan, job.seed, stop)
        .map_err(|e| case.problem.explain(&e))
        .transpose()
}

/// The jobs of one group (one case) in lanes; `None` when abandoned.
fn run_group_in_lanes(
    cases: &[Case],
    plans: &CasePlans,
    group: &[Job],
    stop: &AtomicBool,
) -> Option<Vec<std::result::Result<[DofStats; 3], String>>> {
    if stop.load(Ordering::Relaxed) {
        return None;
    }
    let case = &cases[group[0].case];
    let plan = match plans.plan(group[0].case) {
        Ok(plan) => plan,
        Err(e) => return Some(vec![Err(e); group.len()]),
    };
    let seeds: Vec<u64> = group.iter().map(|job| job.seed).collect();
    let results = lanes::run_lanes(case, &plan, &seeds, stop)?;
    Some(
        results
            .into_iter()
            .map(|r| r.map_err(|e| case.problem.explain(&e)))
            .collect(),
    )
}

/// The seeds of `case` a lane group holds at most: 1 when the case has no drag (the lanes
/// share only the drag's strip sums: docs/benchmarks.md#how-cost-grows), else
/// [`crate::forces::LANES`], or fewer when the records of that many runs (and their plan,
/// once) would exceed the case's memory limit (`run.memory_limit_gb`, which bounds one
/// thread's records: [`MemoryEstimate`] of the case as given, which bounds the records of
/// its [`Case::simulated`] runs); 1 when the estimate cannot be made (the run then reports
/// why).
pub fn lane_width(case: &Case) -> usize {
    let problem = &case.problem;
    if !has_drag(problem) {
        return 1;
    }
    match MemoryEstimate::of(problem) {
        Ok(estimate) if estimate.per_run > 0.0 => {
            let fits = ((problem.run.memory_limit - estimate.plan) / estimate.per_run).floor();
            (fits.max(1.0) as usize).min(crate::forces::LANES)
        }
        _ => 1,
    }
}

/// Whether `problem` has a Morison drag on some column (what lanes share).
pub fn has_drag(problem: &Problem) -> bool {
    problem.model.drag != DragModel::Off && !problem.platform.columns.is_empty()
}

/// The seeds of each case stepped together in a campaign of `jobs` jobs on `threads`
/// threads: the case's [`lane_width`], and at most the jobs per thread (rounded up), so
/// that a short campaign still keeps every thread busy.
pub fn campaign_lane_widths(cases: &[Case], jobs: usize, threads: usize) -> Vec<usize> {
    let per_thread = jobs.div_ceil(threads.max(1)).max(1);
    cases
        .iter()
        .map(|case| lane_width(case).min(per_thread))
        .collect()
}

/// The jobs in groups to run in lanes: runs of consecutive jobs of one case, each of at
/// most the case's `widths` entry ([`campaign_lane_widths`]).
fn lane_groups(jobs: &[Job], widths: &[usize]) -> Vec<std::ops::Range<usize>> {
    let mut groups: Vec<std::ops::Range<usize>> = Vec::new();
    for (j, job) in jobs.iter().enumerate() {
        match groups.last_mut() {
            Some(g) if g.len() < widths[job.case] && jobs[g.start].case == job.case => {
                g.end = j + 1
            }
            _ => groups.push(j..j + 1),
        }
    }
    groups
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
        // Keyed by the cases as given: cases alike there are alike as simulated.
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
            let problem = self.cases[case].simulated();
            problem.check().map_err(|e| e.to_string())?;
            *slot = Some(RecordPlan::of_checked(&problem).map(Arc::new));
        }
        Ok(slot.as_ref().expect("made above").clone())
    }

    /// [`CasePlans::get`]'s plan, or its or the case's error as text.
    fn plan(&self, case: usize) -> std::result::Result<Arc<RecordPlan>, String> {
        self.get(case)?.map_err(|e| e.to_string())
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
