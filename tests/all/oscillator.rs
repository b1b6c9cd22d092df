//! The central check that force, spectrum and solver agree
//! (docs/theory.md#checks-with-known-answers): a linear
//! oscillator M x'' + c x' + k x = F(t) driven by the slowly varying surge force.
//!
//! 1. Statistics: the time-domain variance of x over many seeds equals the frequency-domain
//!    integral of S_F |H|^2, with S_F(mu) = 8 integral S(w) S(w + mu) T(w, w + mu)^2 dw and
//!    Newman's geometric T(w, w + mu) = sqrt(T(w) T(w + mu)), within the sampling error.
//! 2. One realisation: after the start-up transient, the RK4 trajectory equals the exact
//!    periodic steady state of the same force record, computed by FFT as X = F H.

use crate::common::*;
use rustfft::num_complex::Complex64;
use rustfft::FftPlanner;
use slowdrift::forces::{transfers_on_grid, ForceRecords, RecordOptions};
use slowdrift::sea_state::WaveComponents;
use slowdrift::Simulation;
use std::f64::consts::PI;

const MASS: f64 = 1.0e7;
const PERIOD: f64 = 60.0;
const ZETA: f64 = 0.2;

fn stiffness() -> f64 {
    MASS * (2.0 * PI / PERIOD).powi(2)
}

fn damping() -> f64 {
    2.0 * ZETA * MASS * 2.0 * PI / PERIOD
}

/// Runs one seed with records in blocks of `block` s and returns the surge record at every
/// step after `transient`.
fn surge_record(duration: f64, h: f64, seed: u64, transient: f64, block: f64) -> Vec<f64> {
    let mut problem = base_problem(duration, h, seed);
    problem.run.block_duration = block;
    let mut sim = Simulation::new(problem).unwrap();
    let steps = (duration / h).round() as usize;
    let mut out = Vec::with_capacity(steps);
    for _ in 0..steps {
        sim.step([0.0; 3]).unwrap();
        if sim.time() >= transient {
            out.push(sim.position()[0]);
        }
    }
    out
}

#[test]
fn motion_variance_matches_the_frequency_domain_integral() {
    motion_variance_check(slowdrift::scenario::DEFAULT_BLOCK_DURATION);
}

/// The same check with the records in blocks of 2048 s: 16 joins per seed (the cross-fade
/// of the linear signals, `forces::stream`), so a join that changed the force's
/// statistics would show here.
#[test]
fn motion_variance_across_many_joins_matches_the_frequency_domain_integral() {
    motion_variance_check(2048.0);
}

fn motion_variance_check(block: f64) {
    let expected = oscillator_surge_variance(&base_problem(1.0, 1.0, 0));

    let (duration, transient, seeds) = (32_768.0, 1_000.0, 8);
    let mut mean_variance = 0.0;
    for seed in 0..seeds {
        let x = surge_record(duration, 1.0, 100 + seed, transient, block);
        let n = x.len() as f64;
        let mean = x.iter().sum::<f64>() / n;
        mean_variance += x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n / seeds as f64;
    }
    // Relative standard error of a variance estimate from a record of length T of a
    // Gaussian oscillator response: 1 / sqrt(T zeta w_n) (an upper bound here: the
    // quasi-static part of the response decorrelates faster than the resonant part).
    let wn = 2.0 * PI / PERIOD;
    let rel_sigma = 1.0 / ((duration - transient) * ZETA * wn * seeds as f64).sqrt();
    assert!(rel_sigma < 0.015, "the check must be tight: {rel_sigma}");
    let error = mean_variance / expected - 1.0;
    eprintln!(
        "oscillator: var x = {mean_variance:.6e} m^2 (time domain, {seeds} seeds) vs {expected:.6e} m^2 \
         (frequency domain): {:+.2} %, sigma {:.2} %",
        100.0 * error,
        100.0 * rel_sigma
    );
    assert!(
        error.abs() < 4.0 * rel_sigma,
        "time-domain var {mean_variance:.6e} vs frequency-domain {expected:.6e}: {:.2} % (4 sigma = {:.2} %)",
        100.0 * error,
        400.0 * rel_sigma
    );
}

/// The exact periodic response to the record's own force, sampled like the run.
fn periodic_steady_state(force: &[f64], dt: f64) -> Vec<f64> {
    let n = force.len();
    let mut spectrum: Vec<Complex64> = force.iter().map(|&f| Complex64::new(f, 0.0)).collect();
    let mut planner = FftPlanner::new();
    planner.plan_fft_forward(n).process(&mut spectrum);
    for (k, value) in spectrum.iter_mut().enumerate() {
        let index = if k <= n / 2 {
            k as f64
        } else {
            k as f64 - n as f64
        };
        let mu = 2.0 * PI * index / (n as f64 * dt);
        let h = 1.0 / Complex64::new(stiffness() - MASS * mu * mu, damping() * mu);
        *value *= h / n as f64;
    }
    planner.plan_fft_inverse(n).process(&mut spectrum);
    spectrum.iter().map(|c| c.re).collect()
}

/// RK4 error against the exact steady state for step h: relative rms difference.
fn steady_state_error(h: f64) -> f64 {
    let (duration, transient) = (4_000.0, 2_000.0);
    let problem = base_problem(duration, h, 7);
    let mut sim = Simulation::new(problem.clone()).unwrap();
    // The run stays in the first segment of the stream, whose force is block 0's periodic
    // record: built here whole (N samples, global sample m at time m dt).
    let components = WaveComponents::generate(&problem.sea, sim.grid().clone());
    let transfers = transfers_on_grid(
        &problem.hydro.drift,
        &components.grid,
        &components.directions,
        false,
    )
    .unwrap();
    let options = RecordOptions {
        newman: problem.model.newman,
        full_qtf: None,
        drag_columns: &[],
        strips_per_column: 20,
        gravity: problem.environment.gravity,
        fft: None,
    };
    let periodic = ForceRecords::build(&components, &transfers, &options);
    let exact = periodic_steady_state(periodic.wave_force[0].samples(), periodic.clock.dt);
    let steps = (duration / h).round() as usize;
    let (mut diff, mut norm) = (0.0, 0.0);
    for n in 1..=steps {
        sim.step([0.0; 3]).unwrap();
        if sim.time() >= transient {
            // the force records are sampled at h/2: step n is sample 2n
            let reference = exact[2 * n];
            diff += (sim.position()[0] - reference).powi(2);
            norm += reference * reference;
        }
    }
    (diff / norm).sqrt()
}

#[test]
fn trajectory_equals_the_exact_steady_state_of_its_own_force() {
    let coarse = steady_state_error(1.0);
    let fine = steady_state_error(0.5);
    eprintln!("steady state: relative rms error {coarse:.3e} at h = 1 s, {fine:.3e} at h = 0.5 s");
    assert!(coarse < 5e-5, "h = 1 s: relative rms error {coarse:e}");
    assert!(fine < 5e-6, "h = 0.5 s: relative rms error {fine:e}");
    // Fourth order: halving h divides the error by about 16 (the two runs are different
    // realisations, since the record grid follows h, hence the margin).
    assert!(
        coarse / fine > 8.0,
        "error ratio {} for h -> h/2",
        coarse / fine
    );
}
