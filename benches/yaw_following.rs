//! Yaw-following records: `cargo bench --bench yaw_following`.
//!
//! The default platform (column-solver drift, Aranha damping: 3 force + 7 non-zero damping
//! records per yaw) in long-crested waves towards 30 deg, a 3-hour run at h = 1 s (records
//! at 0.5 s; since the records stream in segments, one segment of a 16384-s block, 32 773
//! samples, transforms of N = 34 020, whatever the run's duration):
//! 1. `yaw/new_36_headings`: `Simulation::new` with `yaw_following = { headings = 36 }`,
//!    next to `yaw/new_off` (the mean-position records). Target: initialisation < 1 s.
//! 2. `yaw/step_{off,on}_{no_drag,drag_4x20}`: one `Simulation::step`, yaw following off
//!    and on (36 headings), without drag and with combined drag on 4 columns x 20 strips.
//!    Target: no cost per step beyond the interpolation (two records read instead of one).
//!
//! A summary with `Instant` medians, the ratios and the records' memory is printed at the end.

mod timing;

use criterion::Criterion;
use slowdrift::model::{DragModel, YawFollowing};
use slowdrift::problem::default_problem;
use slowdrift::{Problem, Simulation};
use std::hint::black_box;
use std::time::Duration;
use timing::median_time;

const THREE_HOURS: f64 = 3.0 * 3600.0;

fn config(base: &Problem, yaw: bool, drag: bool) -> Problem {
    let mut c = base.clone();
    c.run.duration = THREE_HOURS;
    c.run.time_step = 1.0;
    c.sea.mean_direction = 30f64.to_radians();
    if !drag {
        c.model.drag = DragModel::Off;
    }
    c.model.yaw_following = yaw.then_some(YawFollowing {
        headings: 36,
        range: None,
    });
    c
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    let base = default_problem().unwrap();
    let mut report = Vec::new();

    let mut group = c.benchmark_group("yaw");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(5));
    for (name, yaw) in [("new_off", false), ("new_36_headings", true)] {
        let cfg = config(&base, yaw, false);
        group.bench_function(name, |b| {
            b.iter(|| Simulation::new(black_box(cfg.clone())).unwrap())
        });
    }
    let mut sims = Vec::new();
    for (drag, drag_name) in [(false, "no_drag"), (true, "drag_4x20")] {
        for (yaw, yaw_name) in [(false, "off"), (true, "on")] {
            let mut sim = Simulation::new(config(&base, yaw, drag)).unwrap();
            group.bench_function(format!("step_{yaw_name}_{drag_name}"), |b| {
                b.iter(|| {
                    if sim.time() >= THREE_HOURS - 1.0 {
                        sim.reset().unwrap();
                    }
                    sim.step(black_box([0.0; 3])).unwrap();
                })
            });
            sims.push((format!("{yaw_name}_{drag_name}"), sim));
        }
    }
    group.finish();
    c.final_summary();

    let new_off = median_time(7, || {
        black_box(Simulation::new(config(&base, false, false)).unwrap());
    });
    let new_on = median_time(7, || {
        black_box(Simulation::new(config(&base, true, false)).unwrap());
    });
    report.push(format!(
        "Simulation::new, 3-hour run at h = 1 s (records: one block of 16384 s): off {:.1} ms, \
         36 headings {:.1} ms ({:.1} x); target < 1 s: {}",
        new_off.as_secs_f64() * 1e3,
        new_on.as_secs_f64() * 1e3,
        new_on.as_secs_f64() / new_off.as_secs_f64(),
        if new_on.as_secs_f64() < 1.0 {
            "met"
        } else {
            "NOT met"
        }
    ));
    let with = Simulation::new(config(&base, true, false)).unwrap();
    let yaw_records = with.records().yaw_following.as_ref().unwrap();
    report.push(format!(
        "records: a segment of {} samples (transforms of N = {}), 36 headings hold {:.1} MB \
         ({:.2} MB per heading)",
        with.records().clock.len,
        with.grid().len,
        yaw_records.bytes() as f64 / 1e6,
        yaw_records.bytes() as f64 / 1e6 / 36.0
    ));
    let mut per_step = Vec::new();
    for (name, sim) in &mut sims {
        // 1000 steps per repetition, reset outside the timing.
        let t = median_time(31, || {
            sim.reset().unwrap();
            for _ in 0..1000 {
                sim.step(black_box([0.0; 3])).unwrap();
            }
        }) / 1000;
        per_step.push(t.as_secs_f64() * 1e6);
        report.push(format!("step {name}: {:.3} us", t.as_secs_f64() * 1e6));
    }
    report.push(format!(
        "yaw following adds {:+.3} us per step without drag, {:+.3} us with drag",
        per_step[1] - per_step[0],
        per_step[3] - per_step[2]
    ));
    println!("\n==== yaw-following summary (std::time::Instant medians) ====");
    for line in report {
        println!("{line}");
    }
}
