//! The `Simulation` API: bit-for-bit reproducibility from the seed, snapshot / restore /
//! reset, and exact time keeping (time = start + n h from an integer count).

use crate::common::*;
use slowdrift::{Problem, Simulation};

fn seeded_problem(seed: u64) -> Problem {
    base_problem(600.0, 1.0, seed)
}

/// Positions after each of `steps` steps (with a small, time-varying external force so that
/// the external input path is exercised too).
fn trajectory(sim: &mut Simulation, steps: usize) -> Vec<[f64; 3]> {
    (0..steps)
        .map(|n| {
            let push = 1.0e4 * (n as f64 * 0.05).sin();
            sim.step([push, 0.5 * push, 0.0]).unwrap();
            sim.position()
        })
        .collect()
}

#[test]
fn the_same_seed_gives_identical_trajectories() {
    let mut a = Simulation::new(seeded_problem(42)).unwrap();
    let mut b = Simulation::new(seeded_problem(42)).unwrap();
    let ta = trajectory(&mut a, 500);
    let tb = trajectory(&mut b, 500);
    assert!(ta == tb, "same seed, different trajectories");
    assert_eq!(a.velocity(), b.velocity());
    // The run moved: the comparison is not between two zero vectors.
    assert!(ta.iter().any(|q| q[0].abs() > 1e-3));
}

#[test]
fn different_seeds_give_different_trajectories() {
    let mut a = Simulation::new(seeded_problem(42)).unwrap();
    let mut b = Simulation::new(seeded_problem(43)).unwrap();
    let ta = trajectory(&mut a, 500);
    let tb = trajectory(&mut b, 500);
    let differing = ta.iter().zip(&tb).filter(|(x, y)| x != y).count();
    assert!(differing > 490, "only {differing} of 500 positions differ");
}

#[test]
fn restore_replays_bit_for_bit() {
    let mut sim = Simulation::new(seeded_problem(7)).unwrap();
    trajectory(&mut sim, 200);
    let snap = sim.snapshot();
    assert_eq!(snap.time(), 200.0);
    let first: Vec<[f64; 3]> = (0..200)
        .map(|_| {
            sim.step([2.0e4, 0.0, 1.0e5]).unwrap();
            sim.position()
        })
        .collect();
    sim.restore(&snap).unwrap();
    assert_eq!(sim.time(), 200.0);
    let again: Vec<[f64; 3]> = (0..200)
        .map(|_| {
            sim.step([2.0e4, 0.0, 1.0e5]).unwrap();
            sim.position()
        })
        .collect();
    assert!(first == again, "the re-run after restore differs");
    assert_eq!(sim.time(), 400.0);

    // A fresh simulation of the same configuration continues identically from the snapshot.
    let mut other = Simulation::new(seeded_problem(7)).unwrap();
    other.restore(&snap).unwrap();
    let continued: Vec<[f64; 3]> = (0..200)
        .map(|_| {
            other.step([2.0e4, 0.0, 1.0e5]).unwrap();
            other.position()
        })
        .collect();
    assert!(first == continued, "the restored copy differs");
    assert_eq!(other.snapshot(), sim.snapshot());
    assert_eq!(other.outputs().unwrap(), sim.outputs().unwrap());
}

#[test]
fn reset_returns_to_the_initial_state_and_replays_the_run() {
    let mut c = seeded_problem(9);
    c.initial.position = [2.0, -1.0, 0.02];
    c.initial.velocity = [0.1, 0.0, -0.001];
    let mut sim = Simulation::new(c.clone()).unwrap();
    let initial = sim.snapshot();
    let first = trajectory(&mut sim, 300);
    sim.reset().unwrap();
    assert_eq!(sim.snapshot(), initial);
    assert_eq!(sim.time(), 0.0);
    assert_eq!(sim.position(), c.initial.position);
    assert_eq!(sim.velocity(), c.initial.velocity);
    let second = trajectory(&mut sim, 300);
    assert!(first == second, "the run after reset differs");
}

#[test]
fn time_is_start_plus_count_times_step_exactly() {
    for (start, h) in [(0.0, 0.5), (100.0, 0.5), (0.0, 0.1), (100.0, 0.1)] {
        let mut c = base_problem(2000.0 * h, h, 2);
        c.run.start_time = start;
        let mut sim = Simulation::new(c).unwrap();
        assert_eq!(sim.time(), start);
        let mut accumulated = start;
        let mut sum_drifted = false;
        for n in 1..=2000u32 {
            sim.step([0.0; 3]).unwrap();
            accumulated += h;
            assert_eq!(
                sim.time(),
                start + f64::from(n) * h,
                "start {start}, h {h}, n {n}"
            );
            sum_drifted |= accumulated != sim.time();
        }
        // With h = 0.1 (not a binary fraction) a running sum would have drifted.
        assert_eq!(sum_drifted, h == 0.1, "start {start}, h {h}");
    }
}

#[test]
fn advance_lands_exactly_on_the_requested_time() {
    let mut sim = Simulation::new(seeded_problem(5)).unwrap();
    for _ in 0..3 {
        sim.step([0.0; 3]).unwrap();
    }
    let t = sim.time();
    sim.advance(2.5, [0.0; 3]).unwrap();
    assert_eq!(sim.time(), t + 2.5);
    // Regular steps resume from there.
    sim.step([0.0; 3]).unwrap();
    assert_eq!(sim.time(), t + 3.5);
    // An interval that is not a binary fraction still lands on old time + interval.
    let t = sim.time();
    sim.advance(0.37, [0.0; 3]).unwrap();
    assert_eq!(sim.time(), t + 0.37);
    assert_eq!(sim.outputs().unwrap().time, sim.time());
}

/// A plan made once serves every seed of its configuration with the records, and so the
/// trajectories, of `Simulation::new`, bit for bit; in a spread sea with drag and Aranha
/// damping too (the plan then also holds the damping table and the cross-direction data).
#[test]
fn a_plan_gives_the_records_of_new_for_every_seed() {
    let mut spread = seeded_problem(1);
    spread.sea.spreading = slowdrift::sea_state::Spreading::CosN { n: 2.0 };
    spread.sea.n_directions = 5;
    spread.platform.columns = four_columns();
    spread.model.drag = slowdrift::model::DragModel::Combined { cd: 0.6 };
    spread.model.drift_damping = slowdrift::model::DriftDamping::Aranha;
    for base in [seeded_problem(1), spread] {
        let plan = std::sync::Arc::new(slowdrift::RecordPlan::new(&base).unwrap());
        for seed in [3, 11] {
            let mut c = base.clone();
            c.sea.seed = seed;
            let mut planned = Simulation::with_plan(c.clone(), &plan).unwrap();
            let mut fresh = Simulation::new(c).unwrap();
            assert!(planned.records() == fresh.records(), "seed {seed}");
            assert!(trajectory(&mut planned, 300) == trajectory(&mut fresh, 300));
        }
    }
}

/// A plan serves problems that differ only in what its records do not hold (the wave height,
/// the drag coefficient, the current, the mass): their records, bit for bit, and their
/// trajectories are those of a fresh simulation.
#[test]
fn a_plan_serves_problems_that_differ_outside_its_key() {
    let mut base = seeded_problem(1);
    base.model.drag = slowdrift::model::DragModel::Combined { cd: 0.6 };
    base.platform.columns = crate::common::four_columns();
    let plan = std::sync::Arc::new(slowdrift::RecordPlan::new(&base).unwrap());
    let mut other = base.clone();
    other.sea.seed = 7;
    if let slowdrift::sea_state::Spectrum::Jonswap { hs, .. } = &mut other.sea.spectrum {
        *hs *= 1.5;
    }
    other.model.drag = slowdrift::model::DragModel::Combined { cd: 1.2 };
    other.current.speed = 0.5;
    other.platform.mass = Some(1.1 * other.inertia().unwrap().mass);
    let mut planned = Simulation::with_plan(other.clone(), &plan).unwrap();
    let mut fresh = Simulation::new(other).unwrap();
    assert!(planned.records() == fresh.records());
    assert!(trajectory(&mut planned, 300) == trajectory(&mut fresh, 300));
}

/// A plan refuses a configuration that differs in more than the seed, naming itself.
#[test]
fn a_plan_refuses_another_configuration() {
    let plan = std::sync::Arc::new(slowdrift::RecordPlan::new(&seeded_problem(1)).unwrap());
    let mut other = seeded_problem(1);
    other.sea.mean_direction += 0.1;
    let err = Simulation::with_plan(other, &plan).unwrap_err().to_string();
    assert!(err.contains("plan"), "{err}");
}
