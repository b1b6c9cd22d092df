//! The memory budget: the estimate that a configuration is checked against
//! before anything is allocated bounds what making its simulation really takes (the peak
//! the test binary's counting allocator measures on this thread), and is not so loose that
//! it refuses what would fit; sizes beyond the bounds and the limit are refused with the
//! setting, its value, the estimate and the limit.

use crate::common::oc4_root_or_skip;
use crate::counting::{live_bytes, peak_bytes, reset_peak};
use slowdrift::hydro::io::wamit::{self, WamitOptions};
use slowdrift::model::{DragModel, Interaction, SecondOrder, YawFollowing};
use slowdrift::problem::default_problem;
use slowdrift::sea_state::Spreading;
use slowdrift::{Error, MemoryEstimate, Problem, Simulation};

/// The estimate's one-run total and the peak bytes held while the simulation is made
/// (above what was held before), with the simulation alive at the end.
fn estimated_and_measured(problem: Problem) -> (f64, f64) {
    let estimate = MemoryEstimate::of(&problem).unwrap().total();
    let before = live_bytes();
    reset_peak();
    let simulation = Simulation::new(problem).unwrap();
    let peak = peak_bytes() - before;
    drop(simulation);
    (estimate, peak as f64)
}

fn spread(problem: &mut Problem, directions: usize) {
    problem.sea.spreading = Spreading::CosN { n: 2.0 };
    problem.sea.n_directions = directions;
}

/// Every configuration stresses one term of the estimate; the estimate must be at least the
/// measured peak (it is the limit's guarantee) and at most 2.5 times it (else the budget
/// refuses what would fit).
#[test]
fn the_estimate_bounds_the_peak_of_making_a_simulation() {
    let base = default_problem().unwrap();
    let mut cases: Vec<(&str, Problem)> = vec![("default (drag on 4 x 20 strips)", base.clone())];
    let mut p = base.clone();
    p.model.drag = DragModel::Off;
    cases.push(("no drag", p));
    let mut p = base.clone();
    p.model.strips_per_column = 200;
    cases.push(("200 strips", p));
    let mut p = base.clone();
    p.run.block_duration = 65536.0;
    cases.push(("block of 65536 s", p));
    let mut p = base.clone();
    spread(&mut p, 60);
    cases.push(("60 directions, bi-directional", p));
    let mut p = base.clone();
    spread(&mut p, 60);
    p.model.drag = DragModel::Off;
    cases.push(("60 directions, bi-directional, no drag", p));
    let mut p = base.clone();
    spread(&mut p, 60);
    p.model.interaction = Interaction::None;
    cases.push(("60 directions, no interaction", p));
    let mut p = base.clone();
    spread(&mut p, 60);
    p.model.interaction = Interaction::None;
    p.model.drag = DragModel::Off;
    cases.push(("60 directions, no interaction, no drag", p));
    let mut p = base.clone();
    p.model.yaw_following = Some(YawFollowing {
        headings: 40,
        range: None,
    });
    cases.push(("40 yaw-following headings", p));
    if let Some(root) = oc4_root_or_skip() {
        let database = wamit::import(&root, &WamitOptions::default())
            .unwrap()
            .database;
        let mut p = crate::full_qtf::oc4_config(&database, SecondOrder::FullQtf, 1);
        p.run.duration = 3600.0;
        cases.push(("OC4 full QTF", p));
    }
    for (name, problem) in cases {
        let (estimate, measured) = estimated_and_measured(problem);
        let ratio = estimate / measured;
        println!(
            "{name}: estimate {:.1} MB, measured peak {:.1} MB, ratio {ratio:.2}",
            estimate / 1e6,
            measured / 1e6
        );
        assert!(
            (1.0..=2.5).contains(&ratio),
            "{name}: estimate {estimate} bytes against a measured peak of {measured}"
        );
    }
}

/// A configuration over the limit is refused before its records are made, naming the
/// setting that drives the estimate, the estimate and the limit.
#[test]
fn over_the_limit_is_refused_naming_the_setting_and_the_limit() {
    let mut p = default_problem().unwrap();
    spread(&mut p, 360);
    p.run.memory_limit = 3e8;
    let message = Simulation::new(p).unwrap_err().to_string();
    let sea_line = slowdrift::scenario::default::DEFAULT_CONFIG_TOML
        .lines()
        .position(|line| line == "[sea]")
        .unwrap()
        + 1;
    // The largest part: 360^2 pairs x 75 frequencies x 3 DOFs x 16 bytes = 467 MB.
    assert!(
        message.starts_with(&format!(
            "embedded default.toml:{sea_line}: invalid [sea] n_directions = 360: needs "
        )) && message.contains("of which 467 MB: the drift of 360 x 360 direction pairs")
            && message.contains("the limit is 300 MB (run.memory_limit_gb = 0.3)"),
        "{message}"
    );
    let mut p = default_problem().unwrap();
    p.run.memory_limit = 1e6;
    let message = Simulation::new(p).unwrap_err().to_string();
    assert!(
        message.contains("invalid [model] strips_per_column = 20: needs")
            && message.contains("the limit is 1.000 MB"),
        "{message}"
    );
}

/// Counts beyond their bounds are refused before they are used (no capacity overflow, no
/// allocation of terabytes).
#[test]
fn counts_beyond_their_bounds_are_refused() {
    let check = |edit: &dyn Fn(&mut Problem), key: &str| {
        let mut p = default_problem().unwrap();
        edit(&mut p);
        match p.validate() {
            Err(Error::InvalidValue { field, reason, .. }) => {
                assert_eq!(field, key);
                assert!(reason.starts_with("must be at most"), "{reason}");
            }
            other => panic!("{key}: {other:?}"),
        }
    };
    check(&|p| spread(p, usize::MAX), "sea.n_directions");
    check(
        &|p| p.model.strips_per_column = 9_223_372_036_854_775_807,
        "model.strips_per_column",
    );
    check(
        &|p| {
            p.model.yaw_following = Some(YawFollowing {
                headings: 2_147_483_647,
                range: None,
            })
        },
        "model.yaw_following.headings",
    );
}

/// The column-array solver's work is bounded before it runs: 10 000 frequencies x 720
/// headings x 4 columns (estimated at 18 minutes; 360 headings took 9 minutes here) is
/// refused at once, naming the setting.
#[test]
fn a_column_array_solve_of_hours_is_refused_before_it_runs() {
    let dir = std::env::temp_dir().join(format!("slowdrift-solver-work-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("long.toml");
    let text = slowdrift::scenario::default::DEFAULT_CONFIG_TOML.replace(
        "source = \"default-platform\"",
        "source = \"column-array\"\nn_omega = 10000\nheading_step_deg = 0.5",
    );
    std::fs::write(&path, text).unwrap();
    let start = std::time::Instant::now();
    let message = slowdrift::problem::load(&path).unwrap_err().to_string();
    assert!(start.elapsed().as_secs_f64() < 5.0);
    assert!(
        message.contains("invalid [drift] n_omega = 10000: the column-array solver on 10000 frequencies x 720 headings x 4 columns would take about")
            && message.contains("at most 10"),
        "{message}"
    );
    std::fs::remove_dir_all(dir).ok();
}
