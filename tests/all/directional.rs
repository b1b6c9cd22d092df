//! Interaction between directions of a short-crested sea (`forces::directional`): the FFT
//! form against the O(N^2 N_beta^2) double sum, the mean force, the mean-direction rule
//! against a long-crested sea of the summed amplitudes, and "none" = no change at all.

use crate::common::*;
use rustfft::num_complex::Complex64;
use slowdrift::forces::{
    cross_direction_force, direction_pairs, plan_inverse_fft, refine, transfers_on_grid,
    ForceRecords, RecordOptions,
};
use slowdrift::hydro::bidirectional::{BidirectionalSource, BidirectionalTable, DirectionPairs};
use slowdrift::hydro::columns::ColumnArray;
use slowdrift::model::{Interaction, NewmanForm};
use slowdrift::sea_state::{FrequencyGrid, SeaState, Spreading, WaveComponents};
use slowdrift::{Problem, Simulation};

fn spread_sea(seed: u64, n_directions: usize) -> SeaState {
    SeaState {
        spectrum: jonswap(5.0, 9.0),
        spreading: Spreading::CosN { n: 2.0 },
        mean_direction: 0.4,
        n_directions,
        seed,
        band: Some((0.3, 1.4)),
    }
}

fn components(seed: u64, n_directions: usize, duration: f64) -> WaveComponents {
    let sea = spread_sea(seed, n_directions);
    let grid = FrequencyGrid::new(0.0, duration, 0.5, sea.band()).unwrap();
    WaveComponents::generate(&sea, grid)
}

/// A Hermitian bi-directional drift, linear in omega (so that linear interpolation is
/// exact and the double sum can use the closed form): T_kl(w) = A_kl + B_kl w with complex
/// off-diagonal parts and a different pattern per DOF.
fn linear_t(dof: usize, k: usize, l: usize, omega: f64) -> Complex64 {
    let s = (dof + 1) as f64;
    let a = |k: usize, l: usize| {
        Complex64::new(
            1.0e4 * s * (1.0 + 0.3 * (k + l) as f64),
            2.0e3 * (k as f64 - l as f64) * s,
        )
    };
    let b =
        |k: usize, l: usize| Complex64::new(-4.0e3 * (k * l) as f64, 1.5e3 * (l as f64 - k as f64));
    a(k, l) + b(k, l) * omega
}

fn linear_pairs(n: usize) -> DirectionPairs {
    let omegas = vec![0.2, 0.9, 1.6];
    let mut values = Vec::new();
    for &w in &omegas {
        for k in 0..n {
            for l in 0..n {
                values.push(std::array::from_fn(|d| linear_t(d, k, l, w)));
            }
        }
    }
    DirectionPairs {
        omegas,
        directions: n,
        values,
    }
}

/// The FFT cross terms equal the direct double sum over (frequency, direction) pairs with
/// k != l and T = (T_kl(w_i) + T_kl(w_j))/2, for every DOF, to round-off.
#[test]
fn cross_terms_by_fft_equal_the_direct_double_sum() {
    let n = 3;
    let comps = components(5, n, 150.0);
    let grid = &comps.grid;
    let force = cross_direction_force(&comps, &linear_pairs(n), &plan_inverse_fft(&comps.grid));
    for (dof, record) in force.iter().enumerate() {
        assert_eq!(record.len(), grid.len);
        let scale = record.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(scale > 0.0);
        for m in (0..grid.len).step_by(37) {
            let t = grid.time(m);
            let mut direct = 0.0;
            for k in 0..n {
                for l in (0..n).filter(|&l| l != k) {
                    let (ak, al) = (comps.of_direction(k), comps.of_direction(l));
                    for (i, a_ik) in ak.iter().enumerate() {
                        for (j, a_jl) in al.iter().enumerate() {
                            let (wi, wj) = (grid.omega(i), grid.omega(j));
                            let qtf = 0.5 * (linear_t(dof, k, l, wi) + linear_t(dof, k, l, wj));
                            let phase = Complex64::from_polar(1.0, (wi - wj) * t);
                            direct += (a_ik * a_jl.conj() * qtf * phase).re;
                        }
                    }
                }
            }
            assert!(
                (record[m] - direct).abs() < QUADRATIC_RECORD_TOLERANCE * scale,
                "dof {dof} sample {m}: fft {} direct {direct}",
                record[m]
            );
        }
    }
}

/// Mean-direction rule with a heading-independent drift and the arithmetic form: the
/// whole force (each direction's terms + cross terms) equals the long-crested force of the
/// summed amplitudes A_i = sum_k a_ik (every pair has the same T).
#[test]
fn heading_independent_mean_direction_is_the_long_crested_force_of_summed_amplitudes() {
    let drift = |omega: f64, _beta: f64| [3.0e4 * (omega - 0.8), 1.0e4 * omega, -2.0e5];
    let mut problem = base_problem(400.0, 1.0, 11);
    problem.sea = spread_sea(11, 5);
    problem.hydro.drift = drift_table(drift);
    problem.model.newman = NewmanForm::Arithmetic;
    problem.model.interaction = Interaction::MeanDirection;
    problem.run.block_duration = 400.0;
    let sim = Simulation::new(problem.clone()).unwrap();
    let spread = &sim.records().wave_force;
    let clock = sim.records().clock;

    // The first segment's records: block 0 alone, sample l at clock.start_time + l dt.
    let comps = WaveComponents::generate(&problem.sea, sim.grid().clone());
    let summed: Vec<Complex64> = (0..comps.grid.count)
        .map(|i| (0..5).map(|k| comps.of_direction(k)[i]).sum())
        .collect();
    for (dof, record) in spread.iter().enumerate() {
        let scale = record.samples().iter().fold(0.0f64, |m, v| m.max(v.abs()));
        // Step ends (odd record samples: the records made there directly; between them they
        // are refined, `forces::refine`, checked in the library's tests).
        for m in (1..clock.len).step_by(54) {
            let t = clock.start_time + m as f64 * clock.dt;
            let (mut q_t, mut eta_t) = (Complex64::default(), Complex64::default());
            for (i, a) in summed.iter().enumerate() {
                let w = comps.grid.omega(i);
                let e = a * Complex64::from_polar(1.0, w * t);
                q_t += e * drift(w, 0.0)[dof];
                eta_t += e;
            }
            let expected = (q_t * eta_t.conj()).re;
            let got = record.samples()[m];
            assert!(
                (got - expected).abs() < QUADRATIC_RECORD_TOLERANCE * scale,
                "dof {dof} sample {m}: {got} vs {expected}"
            );
        }
    }
}

/// Cross terms have zero mean: over 24 seeds, the record mean of the full force (column
/// solver's bi-directional drift on a table) is 2 sum S D T(w; b, b) d_omega within 4
/// standard errors, and the cross part alone is within 4 standard errors of zero.
#[test]
fn mean_force_is_the_diagonal_integral() {
    let array = ColumnArray::new(four_columns(), None).unwrap();
    let env = slowdrift::model::Environment::default();
    let omegas: Vec<f64> = (0..13).map(|i| 0.25 + 0.1 * i as f64).collect();
    let headings: Vec<f64> = (0..72).map(|i| (i as f64 * 5.0).to_radians()).collect();
    let table = BidirectionalTable::from_column_array(&array, &env, &omegas, &headings).unwrap();
    let source = BidirectionalSource::Table(table.clone());
    let seeds = 24;
    let (mut total, mut cross, mut cross_std) = (Vec::new(), Vec::new(), 0.0f64);
    let mut expected = 0.0;
    for seed in 1..=seeds {
        let comps = components(seed, 5, 2000.0);
        let grid = &comps.grid;
        let band = (grid.omega(0), grid.omega(grid.count - 1));
        let heads: Vec<f64> = comps.directions.iter().map(|d| d.heading).collect();
        let pairs = source.pairs(&env, band, &heads).unwrap();
        let f = &cross_direction_force(&comps, &pairs, &plan_inverse_fft(&comps.grid))[0];
        let mean_cross = f.iter().sum::<f64>() / f.len() as f64;
        let var = f.iter().map(|v| (v - mean_cross).powi(2)).sum::<f64>() / f.len() as f64;
        cross_std = cross_std.max(var.sqrt());
        // Each direction's own (arithmetic Newman) mean: sum |a_ik|^2 T_kk(w_i).
        let mut own = 0.0;
        let spectrum = jonswap(5.0, 9.0);
        expected = 0.0;
        for (k, d) in comps.directions.iter().enumerate() {
            for i in 0..grid.count {
                let w = grid.omega(i);
                let t_kk = interpolate_diagonal(&pairs, k, w);
                own += comps.of_direction(k)[i].norm_sqr() * t_kk;
                expected += 2.0 * spectrum.density(w) * d.weight * grid.d_omega * t_kk;
            }
        }
        total.push(own + mean_cross);
        cross.push(mean_cross);
    }
    let stats = |v: &[f64]| {
        let n = v.len() as f64;
        let mean = v.iter().sum::<f64>() / n;
        let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
        (mean, (var / n).sqrt())
    };
    let (mean, se) = stats(&total);
    assert!(
        (mean - expected).abs() < 4.0 * se,
        "mean {mean} vs {expected} (se {se})"
    );
    let (mean_cross, se_cross) = stats(&cross);
    assert!(
        mean_cross.abs() < 4.0 * se_cross,
        "cross mean {mean_cross} (se {se_cross})"
    );
    // The cross terms are not small (the test would be empty otherwise): their standard
    // deviation in time is a sizeable fraction of the mean force.
    assert!(
        cross_std > 0.2 * expected.abs(),
        "{cross_std} vs {expected}"
    );
    println!("mean {mean:.4e} vs {expected:.4e} (se {se:.2e}); cross mean {mean_cross:.3e} (se {se_cross:.2e}), std {cross_std:.3e}");
}

/// T_kk(w), surge, linearly interpolated from the pairs' frequencies.
fn interpolate_diagonal(pairs: &DirectionPairs, k: usize, w: f64) -> f64 {
    let n = pairs
        .omegas
        .partition_point(|&v| v <= w)
        .clamp(1, pairs.omegas.len() - 1)
        - 1;
    let f = (w - pairs.omegas[n]) / (pairs.omegas[n + 1] - pairs.omegas[n]);
    let (lo, hi) = (pairs.get(n, k, k)[0], pairs.get(n + 1, k, k)[0]);
    (lo + (hi - lo) * f).re
}

fn spread_problem(interaction: Interaction) -> Problem {
    let mut problem = base_problem(600.0, 1.0, 3);
    problem.sea = spread_sea(3, 7);
    problem.hydro.drift = drift_table(smooth_drift);
    problem.model.interaction = interaction;
    problem
}

/// "none" builds exactly the records of the route without interaction (transfers on the
/// grid + ForceRecords::build), bit for bit; a long-crested sea gets no cross terms in any
/// mode; mean-direction on a spread sea changes the force.
#[test]
fn none_and_one_direction_leave_the_records_unchanged() {
    let problem = spread_problem(Interaction::None);
    let sim = Simulation::new(problem.clone()).unwrap();
    let comps = WaveComponents::generate(&problem.sea, sim.grid().clone());
    let transfers =
        transfers_on_grid(&problem.hydro.drift, &comps.grid, &comps.directions, false).unwrap();
    // The first segment of the stream, as the simulation makes it (the quadratic records
    // at every second sample and refined, where the band allows: `forces::refine`).
    let segments = sim.segments();
    let joined = |sampling| {
        let mut join = slowdrift::forces::Join::with_sampling(segments, sampling);
        join.begin(0, true);
        join
    };
    let synth = slowdrift::forces::Synthesizer::new(&comps.grid)
        .with_join(joined(slowdrift::forces::Sampling::RECORDS));
    let mut work = slowdrift::forces::RecordWork::new(synth, &comps.grid);
    assert!(refine::admits(&comps.grid, segments));
    let half = rustfft::FftPlanner::new().plan_fft_inverse(comps.grid.len / 2);
    let coarse = slowdrift::forces::Synthesizer::every_second_sample(&comps.grid, half)
        .with_join(joined(refine::SAMPLING));
    work = work.at_their_bandwidth(coarse);
    let mut plain = ForceRecords::empty();
    plain.rebuild(
        &comps,
        &slowdrift::forces::NewmanTransfer::all(NewmanForm::Geometric, &transfers),
        &RecordOptions {
            newman: NewmanForm::Geometric,
            full_qtf: None,
            drag_columns: &[],
            strips_per_column: 20,
            gravity: GRAVITY,
            fft: None,
        },
        &mut work,
    );
    assert_eq!(sim.records(), &plain);
    assert!(direction_pairs(&problem, &comps.grid, &comps.directions)
        .unwrap()
        .is_none());

    let with = Simulation::new(spread_problem(Interaction::MeanDirection)).unwrap();
    assert_ne!(with.records().wave_force, plain.wave_force);
    assert_eq!(with.records().elevation, plain.elevation);

    let mut long = base_problem(600.0, 1.0, 3);
    long.hydro.drift = drift_table(smooth_drift);
    let reference = Simulation::new(long.clone()).unwrap();
    long.model.interaction = Interaction::MeanDirection;
    assert_eq!(
        Simulation::new(long).unwrap().records(),
        reference.records()
    );
}

/// Bad input: bidirectional without data, a table that misses the band or a direction.
#[test]
fn missing_bidirectional_data_is_named() {
    let e = Simulation::new(spread_problem(Interaction::Bidirectional))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("model.interaction") && e.contains("no bi-directional drift"),
        "{e}"
    );
    let array = ColumnArray::new(four_columns(), None).unwrap();
    let env = slowdrift::model::Environment::default();
    let narrow: Vec<f64> = vec![0.0, 0.3, 0.6];
    let table =
        BidirectionalTable::from_column_array(&array, &env, &[0.3, 0.8, 1.5], &narrow).unwrap();
    let mut problem = spread_problem(Interaction::Bidirectional);
    problem.hydro.bidirectional = Some(BidirectionalSource::Table(table));
    let e = Simulation::new(problem.clone()).unwrap_err().to_string();
    assert!(
        e.contains("bidirectional_drift.headings") && e.contains("extrapolated"),
        "{e}"
    );
    let full: Vec<f64> = (0..36).map(|i| (i as f64 * 10.0).to_radians()).collect();
    let table =
        BidirectionalTable::from_column_array(&array, &env, &[0.5, 0.8, 1.5], &full).unwrap();
    problem.hydro.bidirectional = Some(BidirectionalSource::Table(table));
    let e = Simulation::new(problem).unwrap_err().to_string();
    assert!(e.contains("does not cover the wave band"), "{e}");
}
