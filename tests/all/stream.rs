//! Records as a stream of blocks (`forces::stream`, docs/theory.md#open-ended-records): the sea
//! depends
//! on the seed alone, any segment is rebuilt bit for bit, memory does not grow with the run,
//! and the joins between blocks leave the statistics of the sea and of the slowly varying
//! force as the frequency domain gives them (docs/theory.md#checks-with-known-answers), with no
//! trace in the
//! increments.

use crate::common::*;
use crate::counting::{allocations, live_bytes};
use rustfft::num_complex::Complex64;
use slowdrift::forces::{ForceRecords, Record};
use slowdrift::hydro::qtf::{Qtf, QtfBlock};
use slowdrift::model::{
    Dof, DragModel, DriftDamping, Interaction, NewmanForm, SecondOrder, YawFollowing,
};
use slowdrift::sea_state::{Spectrum, Spreading};
use slowdrift::{Problem, Simulation};
use std::f64::consts::PI;

/// The oscillator platform of `base_problem` with blocks of `block` s.
fn with_blocks(duration: f64, block: f64, seed: u64) -> Problem {
    let mut c = base_problem(duration, 1.0, seed);
    c.run.block_duration = block;
    c
}

/// `pick` of the records over segments 0 .. count: each segment's own samples (global
/// kB .. (k+1)B), concatenated, sampled at the records' dt from the start.
fn stream_record(
    sim: &mut Simulation,
    count: u64,
    pick: impl Fn(&ForceRecords) -> &Record,
) -> Vec<f64> {
    let (block, dt) = (sim.segments().block, sim.grid().dt);
    let start = sim.problem().run.start_time;
    let mut out = Vec::with_capacity(count as usize * block);
    for k in 0..count {
        let t = start + (k as usize * block) as f64 * dt;
        let records = sim.records_at(t).unwrap();
        let first = ((t - records.clock.start_time) / dt).round() as usize;
        out.extend_from_slice(&pick(records).samples()[first..first + block]);
    }
    out
}

/// Every feature that goes through the stream, each on a problem with short blocks.
fn features() -> Vec<(&'static str, Problem)> {
    let mut drag = with_blocks(3000.0, 300.0, 21);
    drag.platform.columns = four_columns();
    drag.model.drag = DragModel::Combined { cd: 0.8 };
    drag.model.drift_damping = DriftDamping::Aranha;
    drag.current.speed = 0.4;
    drag.current.direction = 0.3;

    let mut spread = with_blocks(3000.0, 300.0, 22);
    spread.sea.spreading = Spreading::CosN { n: 2.0 };
    spread.sea.n_directions = 5;
    spread.sea.mean_direction = 0.4;
    spread.model.interaction = Interaction::MeanDirection;
    spread.model.newman = NewmanForm::Arithmetic;

    let mut qtf = with_blocks(3000.0, 300.0, 23);
    let omegas: Vec<f64> = (0..30).map(|i| 0.2 + 0.08 * i as f64).collect();
    let n = omegas.len();
    qtf.hydro.qtf = Some(Qtf {
        omegas: omegas.clone(),
        blocks: Dof::ALL
            .iter()
            .enumerate()
            .map(|(d, &dof)| QtfBlock {
                dof,
                heading: 0.0,
                second_heading: 0.0,
                values: (0..n * n)
                    .map(|ij| {
                        let (wi, wj) = (omegas[ij / n], omegas[ij % n]);
                        let s = (d + 1) as f64;
                        Complex64::new(1.0e4 * s * (1.0 + wi * wj), 2.0e3 * (wi - wj))
                    })
                    .collect(),
            })
            .collect(),
    });
    qtf.model.second_order = SecondOrder::FullQtf;

    let mut yaw = with_blocks(3000.0, 300.0, 24);
    yaw.sea.mean_direction = 0.2;
    yaw.model.yaw_following = Some(YawFollowing {
        headings: 12,
        range: None,
    });
    vec![
        ("drag, current and Aranha damping", drag),
        ("spread sea with cross terms", spread),
        ("full QTF", qtf),
        ("yaw following", yaw),
    ]
}

/// Positions after each of `steps` steps with a varying external force.
fn trajectory(sim: &mut Simulation, steps: usize) -> Vec<[u64; 6]> {
    (0..steps)
        .map(|n| {
            let push = 2.0e5 * (n as f64 * 0.013).sin();
            sim.step([push, -0.5 * push, 1.0e7 * (n as f64 * 0.007).cos()])
                .unwrap();
            let (q, v) = (sim.position(), sim.velocity());
            [q[0], q[1], q[2], v[0], v[1], v[2]].map(f64::to_bits)
        })
        .collect()
}

/// The same seed gives the same run, bit for bit, whatever the run's duration (a finite
/// one, a very long one, an open-ended one), through ten joins, for every feature.
#[test]
fn the_same_seed_gives_the_same_run_whatever_its_duration() {
    for (name, problem) in features() {
        let mut runs: Vec<Vec<[u64; 6]>> = Vec::new();
        for duration in [problem.run.duration, 1.0e7, f64::INFINITY] {
            let mut p = problem.clone();
            p.run.duration = duration;
            let mut sim = Simulation::new(p).unwrap();
            runs.push(trajectory(&mut sim, 3000));
            assert_eq!(sim.segment(), 9, "{name}: ten segments");
        }
        assert!(runs[0] == runs[1] && runs[1] == runs[2], "{name}");
    }
}

/// A plan serves every seed and every case of its key through the joins: a simulation of
/// another seed and wave height from the plan of the first is, through ten joins, the
/// simulation made alone, for every feature.
#[test]
fn a_shared_plan_makes_the_same_segments() {
    for (name, problem) in features() {
        let plan = std::sync::Arc::new(slowdrift::RecordPlan::new(&problem).unwrap());
        let mut other = problem.clone();
        other.sea.seed += 100;
        if let Spectrum::Jonswap { hs, .. } = &mut other.sea.spectrum {
            *hs *= 1.3;
        }
        let mut shared = Simulation::with_plan(other.clone(), &plan).unwrap();
        let mut alone = Simulation::new(other).unwrap();
        assert!(
            trajectory(&mut shared, 3000) == trajectory(&mut alone, 3000),
            "{name}"
        );
        assert_eq!(shared.segment(), 9, "{name}");
    }
}

/// A snapshot restored in a fresh simulation, in a segment it never made in sequence,
/// gives that segment's records and the continuation bit for bit; a reset after crossing
/// blocks replays the start.
#[test]
fn any_segment_is_rebuilt_bit_for_bit_for_every_feature() {
    for (name, problem) in features() {
        let mut a = Simulation::new(problem.clone()).unwrap();
        let first = trajectory(&mut a, 50);
        trajectory(&mut a, 1300);
        let snapshot = a.snapshot();
        let records = a.records().clone();
        let continued = trajectory(&mut a, 400);

        let mut b = Simulation::new(problem.clone()).unwrap();
        b.restore(&snapshot).unwrap();
        assert_eq!(b.segment(), 4, "{name}");
        assert!(b.records() == &records, "{name}: segment 4 rebuilt");
        assert_eq!(trajectory(&mut b, 400), continued, "{name}: continuation");

        a.reset().unwrap();
        assert_eq!(trajectory(&mut a, 50), first, "{name}: reset");
    }
}

/// A segment however far into the stream (30 years at 300-s blocks: segment 3.2 million) is
/// made directly from (seed, k): the restore there gives finite records and steps on.
#[test]
fn a_far_segment_is_made_directly() {
    let (_, problem) = features().remove(0);
    let mut sim = Simulation::new(problem).unwrap();
    let steps: u64 = 30 * 365 * 86_400;
    sim.restore(&snapshot_at_step(&sim.snapshot(), steps))
        .unwrap();
    assert_eq!(sim.segment(), steps / 300);
    trajectory(&mut sim, 400);
    assert!(sim
        .records()
        .elevation
        .samples()
        .iter()
        .all(|v| v.is_finite()));
    assert!(sim.position().iter().all(|v| v.is_finite()));
}

/// Crossing a join allocates nothing, for every feature: the next segment is written into
/// the buffers of the current one, and so is a segment made out of sequence on restore.
#[test]
fn segments_are_made_without_allocating() {
    for (name, problem) in features() {
        let mut sim = Simulation::new(problem).unwrap();
        let snapshot = sim.snapshot();
        let before = allocations();
        for _ in 0..3000 {
            sim.step([1.0e5, 0.0, 0.0]).unwrap();
        }
        sim.restore(&snapshot).unwrap();
        let during = allocations() - before;
        assert_eq!(sim.segment(), 0, "{name}");
        assert_eq!(
            during, 0,
            "{name}: allocations over nine joins and a restore"
        );
    }
}

/// Memory does not grow with the run: a simulation holds the same bytes at 3 h as at
/// 1000 h of simulated time (one segment, the tails of the cross-fade, the plan), and much
/// less with blocks half as long (not half: the plan and the tails do not depend on the
/// block).
#[test]
fn memory_is_bounded_by_a_block() {
    let held = |block: f64, at_hours: f64| {
        let mut p = with_blocks(f64::INFINITY, block, 5);
        p.platform.columns = four_columns();
        p.model.drag = DragModel::Combined { cd: 0.6 };
        let before = live_bytes();
        let mut sim = Simulation::new(p).unwrap();
        let late = snapshot_at_step(&sim.snapshot(), (at_hours * 3600.0) as u64);
        sim.restore(&late).unwrap();
        for _ in 0..200 {
            sim.step([0.0; 3]).unwrap();
        }
        let bytes = live_bytes() - before;
        drop(sim);
        bytes
    };
    let (early, late) = (held(4096.0, 3.0), held(4096.0, 1000.0));
    println!("bytes held: {early} at 3 h, {late} at 1000 h (blocks of 4096 s)");
    assert!(
        (late - early).abs() as f64 <= 0.01 * early as f64,
        "{early} at 3 h, {late} at 1000 h"
    );
    let half = held(2048.0, 1000.0);
    println!("bytes held with blocks of 2048 s: {half}");
    assert!(
        (half as f64) < 0.7 * late as f64,
        "blocks half as long: {half} vs {late}"
    );
}

/// Over 24 blocks of 1024 s (joins every 1024 s, ramps of 256 s: a quarter of the time), the
/// elevation's variance is the band integral of S, and its Welch spectrum is S, within the
/// sampling error of the record.
#[test]
fn the_joined_elevation_has_the_input_spectrum() {
    let spectrum = Spectrum::Jonswap {
        hs: 5.0,
        tp: 10.0,
        gamma: Some(2.0),
    };
    let mut problem = with_blocks(f64::INFINITY, 1024.0, 31);
    problem.sea.spectrum = spectrum.clone();
    let mut sim = Simulation::new(problem.clone()).unwrap();
    let eta = stream_record(&mut sim, 24, |r| &r.elevation);
    let dt = sim.grid().dt;
    let length = eta.len() as f64 * dt;
    let n = eta.len() as f64;
    let mean = eta.iter().sum::<f64>() / n;
    let variance = eta.iter().map(|e| (e - mean).powi(2)).sum::<f64>() / n;
    let (lo, hi) = problem.sea.band();
    let m0 = simpson(|w| spectrum.density(w), lo, hi, 20000);
    // Var of a Gaussian record's sample variance: 2 pi integral S^2 dw / T.
    let sigma =
        (2.0 * PI * simpson(|w| spectrum.density(w).powi(2), lo, hi, 20000) / length).sqrt();
    println!(
        "joined elevation: variance {variance:.5} m^2 vs {m0:.5}: {:+.2} sigma",
        (variance - m0) / sigma
    );
    assert!(
        (variance - m0).abs() < 5.0 * sigma,
        "variance {variance} vs {m0} (sigma {sigma})"
    );
    let wp = 2.0 * PI / 10.0;
    let (checked, worst) =
        welch_bands_match(&eta, dt, 1024, 4, (0.8 * wp, 2.0 * wp), 0.03, |a, b| {
            simpson(|w| spectrum.density(w), a, b, 200)
        });
    println!("joined elevation: Welch spectrum in {checked} bands, worst {worst:.2} sigma");
    assert!(checked >= 10, "checked {checked} bands");
}

/// Over 32 blocks of 1024 s the slowly varying Newman force has the frequency-domain mean
/// 2 integral S T dw and low-frequency spectrum S_F(mu) = 8 integral S(w) S(w + mu) T(w)
/// T(w + mu) dw (geometric form, positive T), within the record's sampling error.
#[test]
fn the_force_across_joins_has_the_frequency_domain_mean_and_spectrum() {
    let problem = with_blocks(f64::INFINITY, 1024.0, 41);
    let spectrum = problem.sea.spectrum.clone();
    let mut sim = Simulation::new(problem.clone()).unwrap();
    let force = stream_record(&mut sim, 32, |r| &r.wave_force[0]);
    let dt = sim.grid().dt;
    let length = force.len() as f64 * dt;
    let (lo, hi) = problem.sea.band();
    let drift = |w: f64| smooth_drift(w, 0.0)[0];
    let force_spectrum = surge_force_spectrum(&problem);
    let n = force.len() as f64;
    let mean = force.iter().sum::<f64>() / n;
    let expected_mean = 2.0 * simpson(|w| spectrum.density(w) * drift(w), lo, hi, 20000);
    // Var of the time average of a process with one-sided spectrum S_F: pi S_F(0) / T.
    let sigma = (PI * force_spectrum(0.0) / length).sqrt();
    println!(
        "Newman force across joins: mean {:+.2} % of 2 integral S T dw, {:+.2} sigma",
        100.0 * (mean / expected_mean - 1.0),
        (mean - expected_mean) / sigma
    );
    assert!(
        (mean - expected_mean).abs() < 5.0 * sigma,
        "mean {mean} vs {expected_mean} (sigma {sigma})"
    );
    let centred: Vec<f64> = force.iter().map(|f| f - mean).collect();
    let (checked, worst) = welch_bands_match(&centred, dt, 2048, 6, (0.0, 0.4), 0.05, |a, b| {
        simpson(&force_spectrum, a, b, 40)
    });
    println!("Newman force across joins: spectrum in {checked} bands below 0.4 rad/s, worst {worst:.2} sigma");
    assert!(checked >= 6, "checked {checked} bands");
}

/// The joins leave no trace: the sample-to-sample increments of the elevation in the
/// cross-fades have the variance and the tail fraction of the increments elsewhere, within
/// their sampling errors (24 blocks of 1024 s, ramps a quarter of each block).
#[test]
fn joins_leave_no_trace_in_the_increments() {
    let mut sim = Simulation::new(with_blocks(f64::INFINITY, 1024.0, 51)).unwrap();
    let eta = stream_record(&mut sim, 24, |r| &r.elevation);
    let segments = sim.segments();
    let (b, r) = (segments.block, segments.ramp);
    // The cross-fade of segment k >= 1 covers global samples kB + H .. kB + H + R.
    let halo = 4;
    let in_ramp = |m: usize| m >= b && (m % b) >= halo && (m % b) < halo + r;
    let (mut ramp, mut elsewhere) = (Vec::new(), Vec::new());
    for m in 0..eta.len() - 1 {
        let d = eta[m + 1] - eta[m];
        if in_ramp(m) && in_ramp(m + 1) {
            ramp.push(d);
        } else if !in_ramp(m) && !in_ramp(m + 1) {
            elsewhere.push(d);
        }
    }
    let variance = |v: &[f64]| v.iter().map(|d| d * d).sum::<f64>() / v.len() as f64;
    let (v_ramp, v_else) = (variance(&ramp), variance(&elsewhere));
    // Independent increments: about one per 4 s (the increments' correlation time at
    // Tp = 10 s), 8 samples at 0.5 s.
    let independent = |v: &[f64]| v.len() as f64 / 8.0;
    let sigma = (2.0 / independent(&ramp) + 2.0 / independent(&elsewhere)).sqrt();
    println!(
        "increments: variance in ramps / elsewhere {:.4} ({:+.2} sigma)",
        v_ramp / v_else,
        (v_ramp / v_else - 1.0) / sigma
    );
    assert!(
        (v_ramp / v_else - 1.0).abs() < 4.0 * sigma,
        "increment variance {v_ramp} in ramps vs {v_else} elsewhere (sigma {sigma})"
    );
    let tail =
        |v: &[f64], s: f64| v.iter().filter(|d| d.abs() > 1.5 * s).count() as f64 / v.len() as f64;
    let s = v_else.sqrt();
    let (p_ramp, p_else) = (tail(&ramp, s), tail(&elsewhere, s));
    let p_sigma =
        (p_else * (1.0 - p_else) * (1.0 / independent(&ramp) + 1.0 / independent(&elsewhere)))
            .sqrt();
    println!(
        "increments: P(|d| > 1.5 sd) {p_ramp:.4} in ramps, {p_else:.4} elsewhere ({:+.2} sigma)",
        (p_ramp - p_else) / p_sigma
    );
    assert!(
        (p_ramp - p_else).abs() < 4.0 * p_sigma,
        "P(|d| > 1.5 sd): {p_ramp} in ramps vs {p_else} elsewhere (sigma {p_sigma})"
    );
}
