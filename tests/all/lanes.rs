//! Seeds in lanes (`Lockstep`, docs/architecture.md#seeds-in-lanes): each lane's run is the
//! one-seed `Simulation::step` run bit for bit, for every instruction set this CPU runs; a
//! lane that fails gets the error it gets alone and the others go on; and a campaign's
//! results (`run_jobs`, which runs seeds in lanes) are `run_seed`'s.

use crate::common::*;
use slowdrift::forces::Isa;
use slowdrift::forces::LANES;
use slowdrift::model::DragModel;
use slowdrift::montecarlo::{lane_width, run_jobs, run_seed, Case, Job};
use slowdrift::sea_state::Spreading;
use slowdrift::{Lockstep, MemoryEstimate, Problem, Simulation};
use std::sync::atomic::AtomicBool;

/// Four columns with drag (E&S 8) and the wave drift, in a sea spread (`spread`) or along
/// x, for 300 s at 0.5 s in blocks of 128 s (so that the runs cross segment boundaries).
fn drag_problem(seed: u64, spread: bool) -> Problem {
    let mut problem = base_problem(300.0, 0.5, seed);
    problem.run.block_duration = 128.0;
    problem.platform.columns = four_columns();
    problem.model.drag = DragModel::Combined { cd: 0.7 };
    if spread {
        problem.sea.spreading = Spreading::CosN { n: 4.0 };
        problem.sea.mean_direction = 0.4;
        problem.sea.n_directions = 5;
    }
    problem
}

/// [`drag_problem`]'s spread sea with every other term of E&S 1 that the lanes take side
/// by side: Aranha's wave-drift damping, yaw following (the records at 12 headings), a
/// current of 0.6 m/s across the sea, quadratic extra damping, and a gusty wind (Kaimal,
/// 15 m/s, a coefficient table).
fn every_term_problem(seed: u64) -> Problem {
    use slowdrift::model::{DriftDamping, WindSpectrumKind, YawFollowing};
    use slowdrift::wind::{CoefficientTable, WindCoefficients, WindField, WindLoad};
    let mut problem = drag_problem(seed, true);
    problem.model.drift_damping = DriftDamping::Aranha;
    problem.model.yaw_following = Some(YawFollowing {
        headings: 12,
        range: None,
    });
    problem.current.speed = 0.6;
    problem.current.direction = 1.2;
    problem.platform.quadratic_damping = [[2.0e5, 0.0, 0.0], [0.0, 2.0e5, 0.0], [0.0, 0.0, 1.0e9]];
    let angles = [-180.0f64, -90.0, 0.0, 90.0].map(f64::to_radians).to_vec();
    problem.platform.wind = Some(WindLoad {
        height: 10.0,
        coefficients: WindCoefficients::Table(CoefficientTable {
            cx: vec![-0.8, 0.1, 1.0, 0.1],
            cy: vec![0.0, 0.9, 0.0, -0.9],
            cmz: vec![0.0, 0.05, 0.0, -0.05],
            angles,
            area_x: 3000.0,
            area_y: 4000.0,
            length: 50.0,
            centre: [2.0, -1.0],
        }),
    });
    problem.wind = WindField {
        speed: 15.0,
        spectrum: WindSpectrumKind::Kaimal,
        ..WindField::default()
    };
    problem
}

/// [`every_term_problem`] without yaw following: the reads the lanes keep from one RK4
/// stage to the next at the same time (the wave force, the damping, the gust), across the
/// segments' boundaries.
fn every_term_but_yaw_following(seed: u64) -> Problem {
    let mut problem = every_term_problem(seed);
    problem.model.yaw_following = None;
    problem
}

/// The cases the lanes are checked on: drag along x, drag in a spread sea, every term, and
/// every term but yaw following.
fn problems(seed: u64) -> [(&'static str, Problem); 4] {
    [
        ("drag along x", drag_problem(seed, false)),
        ("drag in a spread sea", drag_problem(seed, true)),
        ("every term", every_term_problem(seed)),
        (
            "every term but yaw following",
            every_term_but_yaw_following(seed),
        ),
    ]
}

fn state(sim: &Simulation) -> [u64; 6] {
    let (q, v) = (sim.position(), sim.velocity());
    [q[0], q[1], q[2], v[0], v[1], v[2]].map(f64::to_bits)
}

#[test]
fn each_lane_steps_as_its_seed_alone_bit_for_bit() {
    for case in 0..problems(1).len() {
        let problem = |seed: u64| problems(seed)[case].1.clone();
        let name = problems(1)[case].0;
        let alone: Vec<Vec<[u64; 6]>> = (1..=4)
            .map(|seed| {
                let mut sim = Simulation::new(problem(seed)).unwrap();
                (0..600)
                    .map(|_| {
                        sim.step([0.0; 3]).unwrap();
                        state(&sim)
                    })
                    .collect()
            })
            .collect();
        // The runs move: the comparison is not between states at rest.
        assert!(alone[0].iter().any(|s| f64::from_bits(s[0]).abs() > 1e-3));
        for isa in Isa::available() {
            for lanes in [1, 3, 4] {
                let sims = (1..=lanes as u64)
                    .map(|seed| Simulation::new(problem(seed)).unwrap())
                    .collect();
                let mut lockstep = Lockstep::with_isa(sims, isa).unwrap();
                // Step n of every lane, read across the lanes.
                #[allow(clippy::needless_range_loop)]
                for n in 0..alone[0].len() {
                    for outcome in lockstep.step() {
                        outcome.unwrap();
                    }
                    for (l, sim) in lockstep.lanes().iter().enumerate() {
                        assert_eq!(
                            state(sim),
                            alone[l][n],
                            "{name}, {isa:?}, {lanes} lanes: lane {l} at step {}",
                            n + 1
                        );
                        assert_eq!(sim.time(), (n + 1) as f64 * 0.5);
                    }
                }
            }
        }
    }
}

/// Lane 1 starts 1 m inside the bound on the offset, moving out at 100 m/s: its first step
/// is refused with the error its run gets alone, its state is the one before the step, and
/// the other lanes go on as their seeds alone.
#[test]
fn a_failing_lane_gets_its_own_error_and_the_others_go_on() {
    let start = |seed: u64| {
        let mut problem = drag_problem(seed, true);
        if seed == 2 {
            problem.initial.position[0] = slowdrift::problem::ranges::MAX_OFFSET - 1.0;
            problem.initial.velocity[0] = 100.0;
        }
        Simulation::new(problem).unwrap()
    };
    let mut alone = start(2);
    let want = alone.step([0.0; 3]).unwrap_err().to_string();
    assert!(want.contains("X = "), "{want}");
    for isa in Isa::available() {
        let mut lockstep = Lockstep::with_isa((1..=4).map(start).collect(), isa).unwrap();
        let outcome = lockstep.step();
        assert_eq!(
            outcome[1].as_ref().unwrap_err().to_string(),
            want,
            "{isa:?}"
        );
        assert!(outcome.iter().enumerate().all(|(l, o)| l == 1 || o.is_ok()));
        let failed = lockstep.remove(1);
        assert_eq!(failed.time(), 0.0);
        assert_eq!(
            failed.position()[0],
            slowdrift::problem::ranges::MAX_OFFSET - 1.0
        );
        for _ in 0..99 {
            assert!(lockstep.step().iter().all(Result::is_ok));
        }
        for (sim, seed) in lockstep.lanes().iter().zip([1, 3, 4]) {
            let mut one = start(seed);
            for _ in 0..100 {
                one.step([0.0; 3]).unwrap();
            }
            assert_eq!(state(sim), state(&one), "{isa:?}, seed {seed}");
        }
    }
}

#[test]
fn lanes_of_other_cases_times_or_counts_are_refused() {
    let sim = |seed: u64| Simulation::new(drag_problem(seed, false)).unwrap();
    let refused = |sims: Vec<Simulation>| Lockstep::new(sims).unwrap_err().to_string();
    assert!(refused(Vec::new()).contains("at least one"));
    assert!(refused((1..=5).map(sim).collect()).contains("at most 4"));
    let mut other = drag_problem(2, false);
    other.run.time_step = 0.25;
    let e = refused(vec![sim(1), Simulation::new(other).unwrap()]);
    assert!(e.contains("one model and time step at one time"), "{e}");
    let mut later = sim(2);
    later.step([0.0; 3]).unwrap();
    assert!(refused(vec![sim(1), later]).contains("at one time"));
    let mut stiffer = drag_problem(2, false);
    stiffer.model.drag = DragModel::Combined { cd: 1.2 };
    assert!(refused(vec![sim(1), Simulation::new(stiffer).unwrap()]).contains("one model"));
}

/// A campaign of 7 seeds of one case on 1 and 2 threads (groups of 4 + 3, and of 4 + 3
/// lanes again as 7 jobs over 2 threads round up to 4) gives `run_seed`'s statistics for
/// every seed, bit for bit.
#[test]
fn a_campaign_in_lanes_gives_each_seeds_own_run() {
    let case = Case {
        name: "drag".into(),
        problem: drag_problem(0, true),
        transient: 50.0,
    };
    let jobs: Vec<Job> = (11..18).map(|seed| Job { case: 0, seed }).collect();
    let want: Vec<_> = jobs
        .iter()
        .map(|j| run_seed(&case, j.seed).unwrap())
        .collect();
    for threads in [1, 2, 3] {
        let mut got = vec![None; jobs.len()];
        run_jobs(
            std::slice::from_ref(&case),
            &jobs,
            threads,
            &AtomicBool::new(false),
            |event| {
                if let Some(finished) = event {
                    got[finished.job] = Some(finished.result.unwrap());
                }
            },
        );
        for (j, (got, want)) in got.iter().zip(&want).enumerate() {
            let got = got.expect("every job reported");
            for dof in 0..3 {
                assert_eq!(
                    got[dof].values().map(f64::to_bits),
                    want[dof].values().map(f64::to_bits),
                    "{threads} threads, seed {}, dof {dof}",
                    jobs[j].seed
                );
            }
        }
    }
}

/// A lane group holds at most the runs whose records fit the case's memory limit together
/// (the plan once, each run's records): 4 under the default limit, 2 when the limit leaves
/// room for 2.5 runs, 1 when it leaves room for less than 2, from the estimate the limit is
/// checked against; a case without drag runs alone (the lanes share only the drag).
#[test]
fn lanes_hold_no_more_runs_than_the_memory_limit_allows() {
    let mut case = Case {
        name: "drag".into(),
        problem: drag_problem(0, true),
        transient: 50.0,
    };
    assert_eq!(lane_width(&case), LANES);
    let mut no_drag = case.clone();
    no_drag.problem.model.drag = DragModel::Off;
    assert_eq!(lane_width(&no_drag), 1, "no drag to share");
    let estimate = MemoryEstimate::of(&case.problem).unwrap();
    for (runs, width) in [(2.5, 2), (3.0, 3), (1.9, 1), (0.5, 1), (40.0, LANES)] {
        case.problem.run.memory_limit = estimate.plan + runs * estimate.per_run;
        assert_eq!(lane_width(&case), width, "room for {runs} runs");
    }
}
