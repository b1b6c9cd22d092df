//! Yaw-following records on the default platform (column-solver drift,
//! Aranha damping), each against an independent route: the mean-position records of the
//! sea rotated by -theta (the existing path with the wave direction minus theta).

use slowdrift::forces::{ForceRecords, YawPoint};
use slowdrift::hydro::{DriftRow, DriftTable};
use slowdrift::model::{DragModel, Interaction, SecondOrder, YawFollowing};
use slowdrift::problem::default_problem;
use slowdrift::sea_state::Spreading;
use slowdrift::{Error, Problem, Simulation};
use std::sync::OnceLock;

/// The default configuration (its column solver runs once per test binary).
fn default() -> Problem {
    static DEFAULT: OnceLock<Problem> = OnceLock::new();
    DEFAULT.get_or_init(|| default_problem().unwrap()).clone()
}

/// The default platform for `duration` s in a sea towards `direction_deg`, optionally
/// spread cos^2 over 5 directions (each direction's own terms only: yaw following does not
/// carry the cross-direction terms), with the given yaw following.
fn yaw_problem(
    duration: f64,
    direction_deg: f64,
    spread: bool,
    yaw: Option<YawFollowing>,
) -> Problem {
    let mut c = default();
    c.run.duration = duration;
    c.sea.mean_direction = direction_deg.to_radians();
    if spread {
        c.sea.spreading = Spreading::CosN { n: 2.0 };
        c.sea.n_directions = 5;
        c.model.interaction = Interaction::None;
    }
    c.model.yaw_following = yaw;
    c
}

fn range(headings: usize, min_deg: f64, max_deg: f64) -> Option<YawFollowing> {
    Some(YawFollowing {
        headings,
        range: Some((min_deg.to_radians(), max_deg.to_radians())),
    })
}

/// The 12 slow records (3 forces, 9 damping) at every sample of the clock, at yaw `yaw`
/// (`None`: the mean-position records).
fn slow_series(records: &ForceRecords, yaw: Option<f64>) -> Vec<Vec<f64>> {
    let clock = records.clock;
    let mut out: Vec<Vec<f64>> = (0..12).map(|_| Vec::with_capacity(clock.len)).collect();
    for m in 0..clock.len - 1 {
        let t = clock.start_time + m as f64 * clock.dt;
        let at = clock.locate(t).unwrap();
        let point = match yaw {
            Some(theta) => records.locate_yaw(t, theta).unwrap(),
            None => YawPoint::MEAN_POSITION,
        };
        let f = records.wave_force_at(&at, &point);
        let b = records.damping_at(&at, &point).unwrap();
        for (i, v) in f.iter().chain(b.iter().flatten()).enumerate() {
            out[i].push(*v);
        }
    }
    out
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// The mean-position records of the sea rotated by -theta: the direct route at yaw theta.
fn direct(base: &Problem, theta_deg: f64) -> Vec<Vec<f64>> {
    let mut c = base.clone();
    c.model.yaw_following = None;
    c.sea.mean_direction -= theta_deg.to_radians();
    slow_series(Simulation::new(c).unwrap().records(), None)
}

#[test]
fn at_every_grid_yaw_the_records_are_those_of_the_rotated_sea() {
    // Oblique spread sea: every record non-zero, 5 directions x 5 yaws of relative headings.
    let on = yaw_problem(1200.0, 30.0, true, range(5, -10.0, 10.0));
    let sim = Simulation::new(on.clone()).unwrap();
    let mut spread_of_sway = (f64::INFINITY, 0.0f64);
    for theta_deg in [-10.0, -5.0, 0.0, 5.0, 10.0] {
        let got = slow_series(sim.records(), Some(f64::to_radians(theta_deg)));
        let want = direct(&on, theta_deg);
        for (r, (g, w)) in got.iter().zip(&want).enumerate() {
            let scale = max_abs(w);
            let error = g
                .iter()
                .zip(w)
                .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
            assert!(
                error <= 1e-10 * scale,
                "yaw {theta_deg} deg, record {r}: error {error:e} of max {scale:e}"
            );
        }
        let sway = max_abs(&want[1]);
        spread_of_sway = (spread_of_sway.0.min(sway), spread_of_sway.1.max(sway));
    }
    // The yaw matters: the sway force's size changes across the grid far beyond round-off.
    assert!(
        spread_of_sway.1 > 1.05 * spread_of_sway.0,
        "{spread_of_sway:?}"
    );
}

#[test]
fn between_grid_yaws_the_error_is_within_the_linear_interpolation_bound() {
    // Long-crested towards 25 deg, yaw grid 4 deg apart: on [0, 4] deg the relative headings
    // 21..25 deg stay inside one cell of the table (headings every 10 deg), where the
    // records are smooth in theta. Direct records every 0.5 deg give d^2 D / d theta^2 by
    // central differences; the linear remainder bounds the error at each sample:
    //   |D_lin - D| <= (theta - theta_j)(theta_j+1 - theta)/2 max |D''|.
    let on = yaw_problem(1200.0, 25.0, false, range(5, -8.0, 8.0));
    let sim = Simulation::new(on.clone()).unwrap();
    let step = 0.5f64;
    let direct_at: Vec<Vec<Vec<f64>>> = (0..=8).map(|q| direct(&on, q as f64 * step)).collect();
    let d2 = |r: usize, m: usize, q: usize| {
        (direct_at[q - 1][r][m] - 2.0 * direct_at[q][r][m] + direct_at[q + 1][r][m])
            / (step.to_radians() * step.to_radians())
    };
    let spacing = 4f64.to_radians();
    let mut worst_ratio = 0.0f64;
    let mut largest_error = 0.0f64;
    for (q, direct_q) in direct_at.iter().enumerate().take(8).skip(1) {
        let theta = (q as f64 * step).to_radians();
        let got = slow_series(sim.records(), Some(theta));
        for (r, g) in got.iter().enumerate() {
            let scale = max_abs(&direct_q[r]);
            if scale == 0.0 {
                continue;
            }
            for (m, value) in g.iter().enumerate() {
                let curvature = (1..8).map(|p| d2(r, m, p).abs()).fold(0.0, f64::max);
                let bound = 1.2 * theta * (spacing - theta) / 2.0 * curvature + 1e-12 * scale;
                let error = (value - direct_q[r][m]).abs();
                assert!(
                    error <= bound,
                    "theta {} deg, record {r}, sample {m}: error {error:e} > bound {bound:e}",
                    q as f64 * step
                );
                worst_ratio = worst_ratio.max(error / bound);
                largest_error = largest_error.max(error / scale);
            }
        }
    }
    // The interpolation is not exact here (so the bound is what is being tested).
    assert!(
        largest_error > 1e-6,
        "largest relative error {largest_error:e}"
    );
    println!("largest error {largest_error:.3e} of max; worst error/bound {worst_ratio:.3}");
}

#[test]
fn with_the_yaw_held_at_zero_yaw_following_changes_nothing() {
    // Head seas on the symmetric default platform (combined drag, Aranha damping): no yaw,
    // so the records at theta = 0 are read and the run equals the mean-position run.
    let off = yaw_problem(3600.0, 0.0, false, None);
    let on = yaw_problem(
        3600.0,
        0.0,
        false,
        Some(YawFollowing {
            headings: 36,
            range: None,
        }),
    );
    assert!(matches!(off.model.drag, DragModel::Combined { .. }));
    let (mut a, mut b) = (Simulation::new(off).unwrap(), Simulation::new(on).unwrap());
    let mut largest = [0.0f64; 6];
    let mut worst = [0.0f64; 6];
    while a.time() < 3590.0 {
        a.step([0.0; 3]).unwrap();
        b.step([0.0; 3]).unwrap();
        let (oa, ob) = (a.outputs().unwrap(), b.outputs().unwrap());
        assert!(oa.position[2].abs() < 1e-12, "yaw {}", oa.position[2]);
        for (i, (x, y)) in oa
            .position
            .iter()
            .chain(&oa.velocity)
            .zip(ob.position.iter().chain(&ob.velocity))
            .enumerate()
        {
            largest[i] = largest[i].max(x.abs());
            worst[i] = worst[i].max((x - y).abs());
        }
    }
    for i in [0, 3] {
        assert!(largest[i] > 1.0e-2, "surge moves: {largest:?}");
        assert!(
            worst[i] <= 1e-9 * largest[i],
            "dof {i}: {worst:?} of {largest:?}"
        );
    }
    for i in [1, 2, 4, 5] {
        assert!(worst[i] <= 1e-12, "dof {i}: {worst:?}");
    }
}

/// An oblique spread sea on the default platform with a yaw spring 20 times softer, from
/// an initial yaw of `initial_deg`.
fn yawing(duration: f64, initial_deg: f64, yaw: Option<YawFollowing>) -> Problem {
    let mut c = yaw_problem(duration, 30.0, true, yaw);
    c.platform.stiffness[2][2] /= 20.0;
    c.initial.position[2] = initial_deg.to_radians();
    c
}

#[test]
fn snapshot_restore_and_reset_continue_bit_for_bit_with_yaw_following() {
    let circle = Some(YawFollowing {
        headings: 36,
        range: None,
    });
    let mut sim = Simulation::new(yawing(1200.0, 3.0, circle)).unwrap();
    let mut smallest_yaw = f64::INFINITY;
    let mut run = |sim: &mut Simulation, steps: usize| -> Vec<u64> {
        let mut bits = Vec::new();
        for k in 0..steps {
            sim.step([1e5 * (k as f64).sin(), 0.0, 0.0]).unwrap();
            let o = sim.outputs().unwrap();
            smallest_yaw = smallest_yaw.min(o.position[2].to_degrees());
            bits.extend(o.position.iter().chain(&o.velocity).map(|v| v.to_bits()));
            bits.extend(
                o.forces
                    .wave
                    .iter()
                    .chain(&o.forces.damping)
                    .map(|v| v.to_bits()),
            );
        }
        bits
    };
    let first = run(&mut sim, 400);
    let snapshot = sim.snapshot();
    let second = run(&mut sim, 400);
    sim.restore(&snapshot).unwrap();
    assert_eq!(run(&mut sim, 400), second);
    sim.reset().unwrap();
    assert_eq!(run(&mut sim, 400), first);
    // The yaw swings from +3 deg across the grid yaw 0 to below -0.5 deg: the records are
    // read at and between grid yaws on both sides.
    assert!(smallest_yaw < -0.5, "smallest yaw {smallest_yaw} deg");
}

#[test]
fn a_yaw_outside_the_range_stops_the_step_naming_yaw_and_range() {
    let mut sim = Simulation::new(yawing(3000.0, 0.0, range(3, -0.2, 0.2))).unwrap();
    let error = loop {
        let before = sim.snapshot();
        match sim.step([0.0; 3]) {
            Ok(()) => assert!(sim.time() < 2900.0, "the yaw never left +-0.2 deg"),
            Err(e) => {
                assert_eq!(sim.snapshot(), before, "a failed step changes nothing");
                break e;
            }
        }
    };
    let Error::YawOutsideRecords { yaw, covered, .. } = &error else {
        panic!("{error}");
    };
    assert!(yaw.abs() > 0.2f64.to_radians(), "{error}");
    assert_eq!(covered.1, 0.2f64.to_radians());
    let text = error.to_string();
    assert!(text.contains("[-0.2000, 0.2000] deg"), "{text}");
    assert!(text.contains("model.yaw_following.range_deg"), "{text}");
}

#[test]
fn a_table_that_misses_relative_headings_is_refused_naming_the_gap() {
    // Headings 0..90 deg only, waves towards 0 deg, yaws -10..10 deg: the relative headings
    // -5 and -10 deg are missing.
    let rows: Vec<DriftRow> = (0..=9)
        .flat_map(|ih| {
            (1..=150).map(move |iw| DriftRow {
                omega: 0.02 * iw as f64,
                heading: (10.0 * ih as f64).to_radians(),
                drift: [1.0e4, 0.0, 0.0],
                damping: None,
            })
        })
        .collect();
    let mut c = crate::common::base_problem(600.0, 1.0, 1);
    c.hydro.drift = DriftTable::from_rows(&rows).unwrap();
    c.model.yaw_following = range(5, -10.0, 10.0);
    let text = Simulation::new(c.clone()).unwrap_err().to_string();
    assert!(text.contains("model.yaw_following"), "{text}");
    assert!(text.contains("[0.000, 90.000] deg only"), "{text}");
    assert!(
        text.contains("[-10.000, -5.000] deg are not covered"),
        "{text}"
    );
    // Yaws 0..10 deg need relative headings 0..-10 as well; -10..0 deg need 0..10: covered.
    c.model.yaw_following = range(3, -10.0, 0.0);
    assert!(Simulation::new(c).is_ok());
}

#[test]
fn invalid_yaw_following_options_are_refused_naming_the_field() {
    let mut c = crate::common::base_problem(600.0, 1.0, 1);
    c.model.yaw_following = Some(YawFollowing {
        headings: 1,
        range: None,
    });
    let text = Simulation::new(c.clone()).unwrap_err().to_string();
    assert!(text.contains("model.yaw_following.headings = 1"), "{text}");
    c.model.yaw_following = range(5, 3.0, -3.0);
    let text = Simulation::new(c.clone()).unwrap_err().to_string();
    assert!(text.contains("model.yaw_following.range"), "{text}");
    c.model.yaw_following = range(5, -3.0, 3.0);
    c.initial.position[2] = 4f64.to_radians();
    let text = Simulation::new(c.clone()).unwrap_err().to_string();
    assert!(text.contains("initial.heading_deg = 4.000 deg"), "{text}");
    c.initial.position[2] = 0.0;
    // Yaw following with the full QTF needs the QTF (tests/all/full_qtf_directions.rs runs it).
    c.model.second_order = SecondOrder::FullQtf;
    let text = Simulation::new(c.clone()).unwrap_err().to_string();
    assert!(
        text.contains("model.second_order") && text.contains("needs a QTF"),
        "{text}"
    );
    c.model.second_order = SecondOrder::Newman;
    c.model.yaw_following = range(5, f64::NAN, 3.0);
    assert!(Simulation::new(c).is_err());
}

#[test]
fn record_means_are_the_drift_at_the_relative_heading() {
    // Over the record's period the Newman record's mean is exactly sum |a_i|^2 T(w_i, beta - theta)
    // (Parseval: the cross terms average out), a sum without FFTs. Head seas; yaw -5, 0, 5 deg.
    use slowdrift::forces::{plan_inverse_fft, YawFollowingRecords, YawGrid};
    use slowdrift::sea_state::WaveComponents;
    let c = yaw_problem(10800.0, 0.0, false, range(3, -5.0, 5.0));
    let sim = Simulation::new(c.clone()).unwrap();
    // Block 0's records over their whole period N; the simulation's first segment holds
    // them from global sample -1 (forces::stream).
    let grid = sim.grid().clone();
    let components = WaveComponents::generate(&c.sea, grid.clone());
    let periodic = YawFollowingRecords::build(
        &components,
        YawGrid::new(c.model.yaw_following.as_ref().unwrap()),
        &c.hydro.drift,
        false,
        c.model.newman,
        &plan_inverse_fft(&grid),
    )
    .unwrap();
    let segment = &sim.records().yaw_following.as_ref().unwrap().sets;
    let n = grid.len;
    // At the step ends (odd samples l: the records made there directly, by a transform of
    // half the length, so to its rounding; between them refined, `forces::refine`).
    for (set, whole) in segment.iter().zip(&periodic.sets) {
        for (record, full) in set.wave_force.iter().zip(&whole.wave_force) {
            let scale = full.samples().iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for (l, v) in record.samples().iter().enumerate().skip(1).step_by(2) {
                let expected = full.samples()[(l + n - 1) % n];
                assert!(
                    (v - expected).abs() <= crate::common::QUADRATIC_RECORD_TOLERANCE * scale,
                    "sample {l}: {v} vs {expected}"
                );
            }
        }
    }
    let sets = &periodic.sets;
    let mut means = Vec::new();
    for (j, theta_deg) in [-5.0f64, 0.0, 5.0].into_iter().enumerate() {
        let mut expected = [0.0; 3];
        for (i, a) in components.of_direction(0).iter().enumerate() {
            let t = c
                .hydro
                .drift
                .drift(grid.omega(i), -theta_deg.to_radians())
                .unwrap();
            for dof in 0..3 {
                expected[dof] += a.norm_sqr() * t[dof];
            }
        }
        let got: Vec<f64> = sets[j]
            .wave_force
            .iter()
            .map(|r| r.samples().iter().sum::<f64>() / grid.len as f64)
            .collect();
        for dof in 0..3 {
            // The mean of a squared series z made in single precision, within delta of it,
            // errs by at most 2 rms(z) rms(delta) (Cauchy-Schwarz), and rms(delta) is below
            // 1e-6 of rms(z) (`forces::synthesis` tests): 2e-6 of the mean force's scale.
            let tolerance = 2e-6 * expected[0].abs();
            assert!(
                (got[dof] - expected[dof]).abs() <= tolerance,
                "yaw {theta_deg} deg, dof {dof}: {} vs {}",
                got[dof],
                expected[dof]
            );
        }
        means.push(expected);
    }
    // The paper's measure (E&S fig. 2): how much a 5 deg yaw changes the mean drift.
    println!(
        "head seas, yaw 5 deg: surge mean drift {:+.2} %, sway {:+.2} % and yaw moment \
         {:+.3e} N m vs the surge {:.4e} N at 0 deg",
        100.0 * (means[2][0] / means[1][0] - 1.0),
        100.0 * means[2][1] / means[1][0],
        means[2][2],
        means[1][0]
    );
    assert!(
        means[0][1] * means[2][1] < 0.0,
        "sway changes sign with the yaw"
    );
}

/// In a spread sea with cross-direction terms, yaw following is refused naming the option
/// (its records carry each direction's own terms only); with interaction "none" it runs.
#[test]
fn yaw_following_in_a_spread_sea_with_interaction_is_refused() {
    let circle = Some(YawFollowing {
        headings: 12,
        range: None,
    });
    let mut c = yaw_problem(600.0, 30.0, true, circle);
    assert!(Simulation::new(c.clone()).is_ok());
    c.model.interaction = Interaction::Auto;
    let e = Simulation::new(c).unwrap_err();
    assert!(
        matches!(&e, Error::InvalidValue { field, .. } if field == "[model] yaw_following"),
        "{e}"
    );
    assert!(e.to_string().contains("cross-direction terms"), "{e}");
}
