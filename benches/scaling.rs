//! How cost grows: `cargo bench --bench scaling`.
//!
//! The default problem (combined drag, Aranha damping, h = 1 s, open-ended) with one
//! parameter varied at a time: the block length (the records' FFT length), the number of
//! directions of a cos^2 sea (with the bi-directional cross terms), the strips per column,
//! and the number of columns (on a ring of the default's radius, each with its drag strips);
//! and, on the OC4 semisubmersible's full QTF (`../shared/data`, or `$SLOWDRIFT_DATA`; the
//! sweep says so and is left out when the data are absent), the QTF's retained rank through
//! its truncation tolerance (drag off, Hs 6 m, Tp 10 s, head seas).
//! For each: `Simulation::new` (plan and first segment, median of 5), one RK4 step
//! (median over 2000 steps, 5 rounds), the step per seed of 4 seeds in lanes (`Lockstep`,
//! once per instruction set the CPU runs, same rounds; its ratio to the step alone), and the
//! exponent p of cost ~ x^p fitted by least squares on the logarithms. Printed; no criterion run (each point builds a new plan).

#[path = "../tests/all/common.rs"]
mod common;
mod timing;

use slowdrift::forces::{Isa, LANES};
use slowdrift::hydro::io::wamit::{self, WamitOptions};
use slowdrift::model::{Cylinder, DragModel, DriftDamping, Interaction, SecondOrder};
use slowdrift::problem::default_problem;
use slowdrift::sea_state::Spectrum;
use slowdrift::sea_state::Spreading;
use slowdrift::{Lockstep, Problem, Simulation};
use std::hint::black_box;
use timing::median_time;

/// Steps per timed round of stepping.
const STEPS: usize = 2000;

/// (seconds of `Simulation::new`, seconds per step) of `problem`.
fn cost(problem: &Problem) -> (f64, f64) {
    let init = median_time(5, || {
        black_box(Simulation::new(black_box(problem.clone())).unwrap());
    });
    let mut sim = Simulation::new(problem.clone()).unwrap();
    let step = median_time(5, || {
        for _ in 0..STEPS {
            sim.step(black_box([0.0; 3])).unwrap();
        }
    });
    (init.as_secs_f64(), step.as_secs_f64() / STEPS as f64)
}

/// Seconds per step per seed of [`LANES`] seeds of `problem` stepped in lanes
/// (`Lockstep`), once per instruction set the CPU runs (median over 5 rounds of
/// [`STEPS`] steps), with the set's name.
fn lanes_cost(problem: &Problem) -> Vec<(&'static str, f64)> {
    let sims: Vec<Simulation> = (0..LANES as u64)
        .map(|l| {
            let mut p = problem.clone();
            p.sea.seed = p.sea.seed.wrapping_add(1 + l);
            Simulation::new(p).unwrap()
        })
        .collect();
    Isa::available()
        .into_iter()
        .map(|isa| {
            let mut lockstep = Lockstep::with_isa(sims.clone(), isa).unwrap();
            let step = median_time(5, || {
                for _ in 0..STEPS {
                    black_box(lockstep.step());
                }
            });
            (isa.name(), step.as_secs_f64() / (STEPS * LANES) as f64)
        })
        .collect()
}

/// The exponent p of y ~ x^p, least squares on (ln x, ln y).
fn exponent(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let (lx, ly): (Vec<f64>, Vec<f64>) = points.iter().map(|&(x, y)| (x.ln(), y.ln())).unzip();
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let sxy: f64 = lx.iter().zip(&ly).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = lx.iter().map(|x| (x - mx).powi(2)).sum();
    sxy / sxx
}

/// (a, b) of y ~ a + b x, least squares.
fn line(points: &[(f64, f64)]) -> (f64, f64) {
    let n = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x / n, b + y / n));
    let sxy: f64 = points.iter().map(|&(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = points.iter().map(|&(x, _)| (x - mx).powi(2)).sum();
    let b = sxy / sxx;
    (my - b * mx, b)
}

/// One row of the table per value of `values`, then the fitted exponents and lines; `x` of
/// a row is `measure` of its problem (the value itself, or what it leads to).
fn sweep(name: &str, values: &[f64], make: impl Fn(f64) -> Problem) {
    sweep_measured(name, values, make, |x, _| x)
}

fn sweep_measured(
    name: &str,
    values: &[f64],
    make: impl Fn(f64) -> Problem,
    measure: impl Fn(f64, &Problem) -> f64,
) {
    println!("{name}:");
    let (mut init, mut step) = (Vec::new(), Vec::new());
    for &value in values {
        let problem = make(value);
        let x = measure(value, &problem);
        let (i, s) = cost(&problem);
        let lanes: Vec<String> = lanes_cost(&problem)
            .into_iter()
            .map(|(isa, t)| format!("{isa} {:.3} us ({:.2} x)", t * 1e6, t / s))
            .collect();
        println!(
            "  {x:>8}  Simulation::new {:>9.2} ms   step {:>7.3} us   per seed in lanes of \
             {LANES}: {}",
            i * 1e3,
            s * 1e6,
            lanes.join(", ")
        );
        init.push((x, i));
        step.push((x, s));
    }
    let (ia, ib) = line(&init);
    let (sa, sb) = line(&step);
    println!(
        "  fitted exponent: Simulation::new {:.2}, step {:.2}; lines: Simulation::new {:.2} + \
         {:.4} x ms, step {:.3} + {:.4} x us",
        exponent(&init),
        exponent(&step),
        ia * 1e3,
        ib * 1e3,
        sa * 1e6,
        sb * 1e6
    );
}

fn base() -> Problem {
    let mut problem = default_problem().expect("the default problem");
    problem.run.duration = f64::INFINITY;
    problem
}

/// `count` columns of the default's diameter and draft on the default's ring (radius
/// 35 sqrt 2 m), evenly spaced from 45 degrees (4: the default's columns).
fn ring(count: usize) -> Vec<Cylinder> {
    let radius = 35.0 * 2f64.sqrt();
    (0..count)
        .map(|k| {
            let angle =
                std::f64::consts::FRAC_PI_4 + 2.0 * std::f64::consts::PI * k as f64 / count as f64;
            // Rounded to a nanometre, so that columns the ring puts at one x share it exactly
            // (the kinematics groups columns that see the same wave phase in head seas).
            let round = |v: f64| (v * 1e9).round() / 1e9;
            Cylinder {
                x: round(radius * angle.cos()),
                y: round(radius * angle.sin()),
                diameter: 20.0,
                draft: 30.0,
            }
        })
        .collect()
}

fn main() {
    slowdrift::allocator::retain_freed_memory();
    println!("cost against size, default problem (combined drag, Aranha, h = 1 s), this machine:");
    sweep(
        "block length [s] (records: FFT of 2 x block / h points)",
        &[4096.0, 8192.0, 16384.0, 32768.0, 65536.0],
        |x| {
            let mut p = base();
            p.run.block_duration = x;
            p
        },
    );
    sweep(
        "directions of a cos^2 sea (bi-directional cross terms)",
        &[3.0, 7.0, 15.0, 31.0],
        |x| {
            let mut p = base();
            p.sea.spreading = Spreading::CosN { n: 2.0 };
            p.sea.n_directions = x as usize;
            p.model.interaction = Interaction::Bidirectional;
            p
        },
    );
    sweep(
        "strips per column (4 columns)",
        &[5.0, 10.0, 20.0, 40.0, 80.0],
        |x| {
            let mut p = base();
            p.model.strips_per_column = x as usize;
            p
        },
    );
    sweep(
        "columns (20 strips each)",
        &[1.0, 2.0, 4.0, 8.0, 16.0],
        |x| {
            let mut p = base();
            p.platform.columns = ring(x as usize);
            p
        },
    );
    let data = common::shared_data_dir().join("wamit/oc4-semi/marin_semi");
    if !data.with_extension("12d").is_file() {
        println!(
            "full QTF rank: left out, the OC4 data are absent at {}",
            data.display()
        );
        return;
    }
    let database = wamit::import(&data, &WamitOptions::default())
        .expect("the OC4 files")
        .database;
    let oc4 = |tolerance: f64| {
        let mut p = base();
        p.sea.spectrum = Spectrum::Jonswap {
            hs: 6.0,
            tp: 10.0,
            gamma: None,
        };
        p.hydro.drift = database.to_drift_table().unwrap();
        p.hydro.qtf = database.qtf.as_ref().map(|q| q.to_qtf());
        p.hydro.bidirectional = None;
        p.model.second_order = SecondOrder::FullQtf;
        p.model.qtf_tolerance = tolerance;
        p.model.drift_damping = DriftDamping::Off;
        p.model.drag = DragModel::Off;
        p
    };
    sweep_measured(
        "full QTF rank (OC4, head seas; x = the ranks retained over its surge, sway and yaw \
         QTFs, at tolerances 0.3 .. 1e-6)",
        &[0.3, 0.1, 0.03, 0.01, 1e-3, 1e-6],
        oc4,
        |_, p| {
            let sim = Simulation::new(p.clone()).unwrap();
            sim.qtf_ranks().iter().map(|r| r.rank).sum::<usize>() as f64
        },
    );
}
