//! The paper's Fig. 10 workload: `cargo bench --bench montecarlo`.
//!
//! Default platform (its radiation-diffraction drift, read once), long-crested head seas,
//! Newman geometric, Aranha drift damping, combined drag on 4 columns x 20 strips,
//! 2^14 s at h = 1 s, transient 10 surge periods; one run = `Simulation::new` + 16384 RK4
//! steps + the statistics ([`run_seed`]; a campaign's run makes no wave-frequency motion,
//! `Case::simulated`). A run of 2^14 s is one block of the record stream
//! (`run.block_duration` = 2^14 s): its records are one segment, made once, whose transforms
//! span the block plus the halo and the join's ramp (printed as N); no join is crossed.
//!
//! 1. `montecarlo/fig10_one_run` (criterion): one run on one thread.
//! 2. The workload itself, 1000 runs through [`run_jobs`] on all cores, is too long for
//!    criterion's repetitions: it is timed once with `Instant` and printed with runs per
//!    second per core (`SLOWDRIFT_BENCH_RUNS` overrides the count for a quick look).
//! 3. Seeds in lanes: 16384 steps of a seed alone (`Simulation::step`) against the same
//!    steps in lanes of 4 (`Lockstep`), once per instruction set the CPU runs, in turns in
//!    one run (records made beforehand, not timed); medians per seed.
//! 4. The NumPy reference `tests/clients/bench_numpy.py` (same case, records vectorised,
//!    RK4 loop in Python) is run in the same process when `target/client-venv` exists
//!    (created by `tests/clients/run_clients.sh`), and the ratio of the single-core times
//!    per run is printed; otherwise the summary says it is absent.
//!
//! Like the CLI, the benchmark first keeps freed memory in the process
//! ([`slowdrift::allocator::retain_freed_memory`]).

use criterion::Criterion;
use slowdrift::forces::{Isa, LANES};
use slowdrift::hydro::io::database::HydroDatabase;
use slowdrift::montecarlo::{run_jobs, run_seed, Case, Job};
use slowdrift::problem::default_problem;
use slowdrift::scenario::default::DEFAULT_DRIFT_LABEL;
use slowdrift::{Lockstep, RecordPlan, Simulation};
use std::hint::black_box;
use std::path::Path;
use std::process::Command;
use std::sync::Arc;
use std::time::{Duration, Instant};

const DURATION: f64 = 16_384.0;
const WORKLOAD_RUNS: u64 = 1000;
/// Seeds of the NumPy reference (each takes seconds).
const NUMPY_RUNS: usize = 2;

fn fig10_case() -> Case {
    let mut config = default_problem().expect("the default platform");
    config.run.duration = DURATION;
    let transient = config.default_transient();
    Case {
        name: "fig10".into(),
        problem: config,
        transient,
    }
}

/// Seconds per run of `runs` single-thread runs.
fn single_core_seconds(case: &Case, runs: u64) -> f64 {
    let start = Instant::now();
    for seed in 0..runs {
        black_box(run_seed(case, 10_000 + seed).expect("a Fig. 10 run"));
    }
    start.elapsed().as_secs_f64() / runs as f64
}

/// The NumPy reference's seconds per run, or why there is none.
fn numpy_seconds(case: &Case) -> Result<(f64, String), String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let python = root.join("target/client-venv/bin/python");
    if !python.exists() {
        return Err(format!(
            "absent: {} does not exist (tests/clients/run_clients.sh creates it)",
            python.display()
        ));
    }
    let dir = std::env::temp_dir().join(format!("slowdrift-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
    let database = dir.join("platform.json");
    // The damping the Rust run uses, tabulated for NumPy (Aranha's, from the drift table).
    let problem = &case.problem;
    let table = problem
        .damping_table()
        .map_err(|e| e.to_string())?
        .ok_or("the Fig. 10 case has drift damping")?;
    HydroDatabase::from_drift_table(
        "platform",
        DEFAULT_DRIFT_LABEL,
        &problem.environment,
        &table,
    )
    .save(&database)
    .map_err(|e| e.to_string())?;
    let output = Command::new(&python)
        .arg(root.join("tests/clients/bench_numpy.py"))
        .arg(&database)
        .args(["--runs", &NUMPY_RUNS.to_string()])
        .args(["--duration", &DURATION.to_string()])
        .output()
        .map_err(|e| e.to_string())?;
    std::fs::remove_dir_all(&dir).ok();
    let stdout = String::from_utf8_lossy(&output.stdout).trim().to_string();
    if !output.status.success() {
        return Err(format!(
            "failed: {}",
            String::from_utf8_lossy(&output.stderr)
        ));
    }
    let json: serde_json::Value = serde_json::from_str(&stdout).map_err(|e| e.to_string())?;
    let seconds = json["seconds_per_run"]
        .as_f64()
        .ok_or("no seconds_per_run in the output")?;
    Ok((seconds, stdout))
}

/// Rounds of [`lanes_summary`], each of [`LANES`] seeds per side.
const LANE_ROUNDS: u64 = 6;

/// The steps alone against the steps in lanes, per instruction set, in one run: each round
/// makes the records of [`LANES`] seeds (not timed), then steps copies of them 16 384 times
/// seed by seed (`Simulation::step`) and in lanes (`Lockstep`, once per instruction set
/// the CPU runs), in turn; prints the medians per seed.
fn lanes_summary(case: &Case) {
    let problem = case.simulated();
    let plan = Arc::new(RecordPlan::new(&problem).expect("the plan"));
    let steps = (problem.run.duration / problem.run.time_step).round() as usize;
    let isas = Isa::available();
    let mut alone = Vec::new();
    let mut lanes: Vec<Vec<f64>> = vec![Vec::new(); isas.len()];
    for round in 0..LANE_ROUNDS {
        let sims: Vec<Simulation> = (0..LANES as u64)
            .map(|l| {
                let mut p = problem.clone();
                p.sea.seed = 20_000 + LANES as u64 * round + l;
                Simulation::with_plan(p, &plan).expect("a Fig. 10 simulation")
            })
            .collect();
        let start = Instant::now();
        for mut sim in sims.clone() {
            for _ in 0..steps {
                sim.step([0.0; 3]).expect("a step");
            }
            black_box(sim.position());
        }
        alone.push(start.elapsed().as_secs_f64() / LANES as f64);
        for (i, &isa) in isas.iter().enumerate() {
            let mut lockstep = Lockstep::with_isa(sims.clone(), isa).expect("lanes");
            let start = Instant::now();
            for _ in 0..steps {
                black_box(lockstep.step());
            }
            lanes[i].push(start.elapsed().as_secs_f64() / LANES as f64);
        }
    }
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let alone = median(&mut alone);
    println!(
        "seeds in lanes ({LANE_ROUNDS} rounds of {LANES} seeds, medians per seed of {steps} steps, \
         records not timed): alone {:.1} ms",
        1e3 * alone
    );
    for (isa, times) in isas.iter().zip(&mut lanes) {
        let t = median(times);
        println!(
            "  in lanes of {LANES}, {} drag sums: {:.1} ms = {:.2} x alone",
            isa.name(),
            1e3 * t,
            t / alone
        );
    }
}

fn main() {
    // As the CLI does: keep freed record memory for the next run (src/allocator.rs).
    let retained = slowdrift::allocator::retain_freed_memory();
    println!("allocator keeps freed memory: {retained}");
    let case = fig10_case();
    let mut criterion = Criterion::default()
        .sample_size(10)
        .measurement_time(Duration::from_secs(5))
        .configure_from_args();
    let mut seed = 0;
    criterion.bench_function("montecarlo/fig10_one_run", |b| {
        b.iter(|| {
            seed += 1;
            run_seed(black_box(&case), seed).expect("a Fig. 10 run")
        })
    });
    criterion.final_summary();

    let runs: u64 = std::env::var("SLOWDRIFT_BENCH_RUNS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(WORKLOAD_RUNS);
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let jobs: Vec<Job> = (1..=runs).map(|seed| Job { case: 0, seed }).collect();
    let start = Instant::now();
    let mut failed = 0;
    let never = std::sync::atomic::AtomicBool::new(false);
    run_jobs(std::slice::from_ref(&case), &jobs, cores, &never, |event| {
        failed += usize::from(matches!(event, Some(f) if f.result.is_err()));
    });
    let wall = start.elapsed().as_secs_f64();
    let single = single_core_seconds(&case, 5);

    println!("\n=== Monte Carlo summary (Fig. 10 workload: default platform, 2^14 s at 1 s, drag on) ===");
    println!(
        "{runs} runs on {cores} threads: {wall:.1} s wall (timed once with Instant, not criterion; \
         target of issue #32: 1000 runs < 8 s), {:.2} runs/s, {:.2} runs/s per core; {failed} failed",
        runs as f64 / wall,
        runs as f64 / wall / cores as f64
    );
    println!(
        "one run on one thread: {:.1} ms ({:.2} runs/s)",
        1e3 * single,
        1.0 / single
    );
    let plan = RecordPlan::new(&case.simulated()).expect("the plan");
    println!(
        "records per run: one segment of {} samples, transforms of N = {} (block {} s at {} s)",
        plan.segments().record_len(),
        plan.grid().len,
        case.problem.run.block_duration,
        plan.grid().dt
    );
    lanes_summary(&case);
    match numpy_seconds(&case) {
        Ok((numpy, line)) => println!(
            "NumPy reference ({NUMPY_RUNS} runs, one core): {numpy:.2} s per run = {:.1} x the Rust \
             run on one core, same process\n  {line}",
            numpy / single
        ),
        Err(why) => println!("NumPy reference: {why}"),
    }
}
