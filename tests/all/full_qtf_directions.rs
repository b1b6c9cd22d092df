//! The full QTF in a spread sea: the cross terms between directions from
//! the bi-directional QTF T(w_i, w_j; b_k, b_l), factorised over (frequency, direction) at
//! FFT cost, the QTF interpolated bilinearly in the heading pair between data headings.
//! Against the O(N^2 N_beta^2) double sum on the QTF interpolated here by the test's own
//! code, and against the mean 2 sum_k w_k integral S T(w, w; b_k, b_k) dw.

use crate::common::*;
use crate::wamit_directions::closed_form_qtf;
use rustfft::num_complex::Complex64;
use slowdrift::forces::{
    DirectionTransfer, ForceRecords, QtfFactorisation, QtfGroup, RecordOptions,
};
use slowdrift::hydro::qtf::{Qtf, QtfBlock};
use slowdrift::model::NewmanForm;
use slowdrift::model::{Dof, Interaction, SecondOrder};
use slowdrift::sea_state::{FrequencyGrid, SeaState, Spreading, WaveComponents};
use slowdrift::stats::welch_spectrum;
use slowdrift::{Problem, Simulation};

const RHO_G: f64 = 1025.0 * 9.80665;

/// Data headings every 25 deg from -100 to 100: the sea's directions fall between them.
fn data_headings() -> Vec<f64> {
    (0..9)
        .map(|k| (-100.0 + 25.0 * k as f64).to_radians())
        .collect()
}

/// A QTF on `omegas` with every ordered pair of `headings` (the closed form of the WAMIT
/// tests, Hermitian in (w, beta)), or only the uni-directional blocks.
fn qtf(omegas: &[f64], headings: &[f64], pairs: bool) -> Qtf {
    let mut blocks = Vec::new();
    for &b1 in headings {
        for &b2 in headings {
            if !pairs && b1 != b2 {
                continue;
            }
            for (dof, wamit) in Dof::ALL.into_iter().zip([1, 2, 6]) {
                blocks.push(QtfBlock {
                    dof,
                    heading: b1,
                    second_heading: b2,
                    values: omegas
                        .iter()
                        .flat_map(|&w1| {
                            omegas
                                .iter()
                                .map(move |&w2| closed_form_qtf(wamit, w1, w2, b1, b2) * RHO_G)
                        })
                        .collect(),
                });
            }
        }
    }
    Qtf {
        omegas: omegas.to_vec(),
        blocks,
    }
}

/// The test's own interpolation: bilinear in the heading pair between the data headings,
/// then bilinear in frequency (the closed form sampled at the data nodes).
fn interpolated(dof: usize, omegas: &[f64], w1: f64, w2: f64, b1: f64, b2: f64) -> Complex64 {
    let headings = data_headings();
    let locate = |x: f64, grid: &[f64]| {
        let k = (0..grid.len() - 1)
            .find(|&k| grid[k] <= x + 1e-12 && x <= grid[k + 1] + 1e-12)
            .expect("inside the data");
        (k, ((x - grid[k]) / (grid[k + 1] - grid[k])).clamp(0.0, 1.0))
    };
    let ((p, f), (q, g)) = (locate(b1, &headings), locate(b2, &headings));
    let ((i, s), (j, t)) = (locate(w1, omegas), locate(w2, omegas));
    let mut total = Complex64::default();
    for (hp, wp) in [(headings[p], 1.0 - f), (headings[p + 1], f)] {
        for (hq, wq) in [(headings[q], 1.0 - g), (headings[q + 1], g)] {
            for (oi, wi) in [(omegas[i], 1.0 - s), (omegas[i + 1], s)] {
                for (oj, wj) in [(omegas[j], 1.0 - t), (omegas[j + 1], t)] {
                    let weight = wp * wq * wi * wj;
                    if weight != 0.0 {
                        total += weight * closed_form_qtf(dof, oi, oj, hp, hq) * RHO_G;
                    }
                }
            }
        }
    }
    total
}

fn sea(seed: u64, n_directions: usize) -> SeaState {
    SeaState {
        spectrum: jonswap(5.0, 9.0),
        spreading: Spreading::CosN { n: 2.0 },
        mean_direction: 0.1,
        n_directions,
        seed,
        band: Some((0.35, 1.6)),
    }
}

fn qtf_grid() -> Vec<f64> {
    (0..12).map(|k| 0.3 + 0.12 * k as f64).collect()
}

fn spread_problem(sea: SeaState, pairs: bool, duration: f64) -> Problem {
    let mut problem = base_problem(duration, 0.5, sea.seed);
    problem.run.start_time = 100.0;
    problem.run.block_duration = duration;
    problem.hydro.qtf = Some(qtf(&qtf_grid(), &data_headings(), pairs));
    problem.sea = sea;
    problem.model.second_order = SecondOrder::FullQtf;
    problem.model.qtf_tolerance = 1e-12;
    problem.model.interaction = Interaction::Bidirectional;
    problem
}

/// The records' force equals the double sum over every pair of (frequency, direction) of
/// the QTF interpolated bilinearly in heading pair and frequency, to round-off (full rank).
#[test]
fn joint_factorisation_equals_the_double_sum_over_directions() {
    let problem = spread_problem(sea(11, 3), true, 300.0);
    let sim = Simulation::new(problem.clone()).unwrap();
    let grid: FrequencyGrid = sim.grid().clone();
    let clock = sim.records().clock;
    let components = WaveComponents::generate(&problem.sea, grid.clone());
    let directions = problem.sea.directions();
    let nd = directions.len();
    let ranks = sim.qtf_ranks();
    assert_eq!(ranks.len(), 3, "one joint factorisation per DOF: {ranks:?}");
    assert!(ranks
        .iter()
        .all(|r| r.directions == nd && r.size == 12 * nd));
    let omegas = qtf_grid();
    let n = grid.count;
    for (d, wamit) in [1, 2, 6].into_iter().enumerate() {
        // T(w_i, w_j; b_k, b_l) on the simulation grid, by the test's own interpolation.
        let t: Vec<Complex64> = (0..nd * n)
            .flat_map(|a| (0..nd * n).map(move |b| (a, b)))
            .map(|(a, b)| {
                let (k, i, l, j) = (a / n, a % n, b / n, b % n);
                interpolated(
                    wamit,
                    &omegas,
                    grid.omega(i),
                    grid.omega(j),
                    directions[k].heading,
                    directions[l].heading,
                )
            })
            .collect();
        let samples = sim.records().wave_force[d].samples();
        let scale = samples.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let mut worst = 0.0f64;
        // Step ends (odd record samples: the records made there directly; between them they
        // are refined, `forces::refine`, checked against records made at every sample in
        // the library's tests).
        for m in [1usize, 3, 101, 333, clock.len - 2] {
            let time = clock.start_time + m as f64 * clock.dt;
            let rotated: Vec<Complex64> = (0..nd * n)
                .map(|a| {
                    let (k, i) = (a / n, a % n);
                    components.of_direction(k)[i]
                        * Complex64::from_polar(1.0, grid.omega(i) * (time - grid.start_time))
                })
                .collect();
            let mut direct = 0.0;
            for a in 0..nd * n {
                for b in 0..nd * n {
                    direct += (rotated[a] * rotated[b].conj() * t[a * nd * n + b]).re;
                }
            }
            worst = worst.max((samples[m] - direct).abs() / scale);
        }
        println!("DOF {wamit}: max |FFT - double sum| / max |F| = {worst:.2e}");
        assert!(worst < QUADRATIC_RECORD_TOLERANCE, "DOF {wamit}: {worst}");
    }
}

/// Without the bi-directional blocks the sea's directions take per-direction QTFs
/// interpolated linearly in heading (the data's diagonal), and no cross terms come from the
/// QTF: the force is the sum of the per-direction double sums.
#[test]
fn unidirectional_data_interpolated_in_heading_per_direction() {
    let mut problem = spread_problem(sea(12, 3), false, 300.0);
    problem.model.interaction = Interaction::None;
    let sim = Simulation::new(problem.clone()).unwrap();
    let grid = sim.grid().clone();
    let clock = sim.records().clock;
    let components = WaveComponents::generate(&problem.sea, grid.clone());
    let directions = problem.sea.directions();
    assert_eq!(sim.qtf_ranks().len(), 3 * directions.len());
    let omegas = qtf_grid();
    let headings = data_headings();
    let n = grid.count;
    for (d, wamit) in [1, 2, 6].into_iter().enumerate() {
        let samples = sim.records().wave_force[d].samples();
        let scale = samples.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        // Step ends (odd record samples, as above).
        for m in [1usize, 57, clock.len - 2] {
            let time = clock.start_time + m as f64 * clock.dt;
            let mut direct = 0.0;
            for (k, dir) in directions.iter().enumerate() {
                // Linear between the two data headings around the direction.
                let p = (0..headings.len() - 1)
                    .find(|&p| headings[p] <= dir.heading && dir.heading <= headings[p + 1])
                    .unwrap();
                let f = (dir.heading - headings[p]) / (headings[p + 1] - headings[p]);
                let rotated: Vec<Complex64> = (0..n)
                    .map(|i| {
                        components.of_direction(k)[i]
                            * Complex64::from_polar(1.0, grid.omega(i) * (time - grid.start_time))
                    })
                    .collect();
                for i in 0..n {
                    for j in 0..n {
                        let t = (1.0 - f)
                            * interpolated(
                                wamit,
                                &omegas,
                                grid.omega(i),
                                grid.omega(j),
                                headings[p],
                                headings[p],
                            )
                            + f * interpolated(
                                wamit,
                                &omegas,
                                grid.omega(i),
                                grid.omega(j),
                                headings[p + 1],
                                headings[p + 1],
                            );
                        direct += (rotated[i] * rotated[j].conj() * t).re;
                    }
                }
            }
            let error = (samples[m] - direct).abs() / scale;
            assert!(
                error < QUADRATIC_RECORD_TOLERANCE,
                "DOF {wamit}, sample {m}: {error}"
            );
        }
    }
}

/// The joint factorisation of the surge QTF of `sea`'s directions on `grid`, as the plan
/// makes it, on the QTF the library interpolates in heading (checked against the test's own
/// interpolation above), for all three DOFs.
fn joint_groups(grid: &FrequencyGrid, sea: &SeaState) -> [QtfGroup; 1] {
    let directions = sea.directions();
    let nd = directions.len();
    let omegas = qtf_grid();
    let data = qtf(&omegas, &data_headings(), true);
    let n = omegas.len();
    let m = n * nd;
    let mut matrix = vec![Complex64::default(); m * m];
    for (k, dk) in directions.iter().enumerate() {
        for (l, dl) in directions.iter().enumerate() {
            let block = data
                .interpolated(Dof::Surge, (dk.heading, dl.heading))
                .unwrap();
            for i in 0..n {
                for j in 0..n {
                    matrix[(k * n + i) * m + l * n + j] = block[i * n + j];
                }
            }
        }
    }
    let factors = QtfFactorisation::across_directions(&omegas, nd, &matrix, 1e-12).unwrap();
    let on_grid = factors.on_grid(grid).unwrap();
    [QtfGroup {
        first_direction: 0,
        dofs: [on_grid.clone(), on_grid.clone(), on_grid],
    }]
}

/// The records over the grid's whole period (no stream) with the full QTF of `groups`.
fn joint_records(grid: &FrequencyGrid, sea: &SeaState, groups: &[QtfGroup]) -> ForceRecords {
    let components = WaveComponents::generate(sea, grid.clone());
    let transfers = vec![DirectionTransfer::none(grid.count); components.directions.len()];
    ForceRecords::build(
        &components,
        &transfers,
        &RecordOptions {
            newman: NewmanForm::Geometric,
            full_qtf: Some(groups),
            drag_columns: &[],
            strips_per_column: 1,
            gravity: GRAVITY,
            fft: None,
        },
    )
}

/// The mean force of records over the grid's whole period: there every pair of different
/// frequencies completes whole cycles, so the mean is sum_i sum_{k,l} a_ik a_il*
/// T(w_i, w_i; b_k, b_l), whose expectation is 2 sum_k w_k integral S(w) T(w, w; b_k, b_k) dw
/// (the cross terms between directions have zero mean). Over several seeds within 4 sampling
/// sigma: |a_ik|^2 exponential with mean P_ik = 2 S w_k d_omega, and the cross products of
/// two directions add 2 P_ik P_il |T_kl|^2 per pair k < l. The factorisation is the one the
/// plan makes, on the QTF the library interpolates in heading (checked against the test's
/// own interpolation above).
#[test]
fn mean_force_over_directions_is_the_integral_of_the_diagonal() {
    let seeds = 8;
    let omegas = qtf_grid();
    let band = (0.35, 1.6);
    let grid = FrequencyGrid::new(0.0, 4096.0, 0.5, band).unwrap();
    let sea0 = sea(0, 3);
    let directions = sea0.directions();
    let groups = joint_groups(&grid, &sea0);
    let mut mean = 0.0;
    for seed in 0..seeds {
        let records = joint_records(&grid, &sea(200 + seed, 3), &groups);
        let f = records.wave_force[0].samples();
        mean += f.iter().sum::<f64>() / f.len() as f64 / seeds as f64;
    }
    let spectrum = &sea0.spectrum;
    let t = |w: f64, k: usize, l: usize| {
        interpolated(
            1,
            &omegas,
            w,
            w,
            directions[k].heading,
            directions[l].heading,
        )
    };
    let mut expected = 0.0;
    let mut variance = 0.0;
    for (k, dk) in directions.iter().enumerate() {
        expected += 2.0
            * dk.weight
            * simpson(
                |w| spectrum.density(w) * t(w, k, k).re,
                band.0,
                band.1,
                2000,
            );
        for i in 0..grid.count {
            let w = grid.omega(i);
            let p = |d: &slowdrift::sea_state::Direction| {
                2.0 * spectrum.density(w) * d.weight * grid.d_omega
            };
            variance += (p(dk) * t(w, k, k).re).powi(2);
            for (l, dl) in directions.iter().enumerate().skip(k + 1) {
                variance += 2.0 * p(dk) * p(dl) * t(w, k, l).norm_sqr();
            }
        }
    }
    let sigma = (variance / seeds as f64).sqrt();
    println!("mean surge force {mean:.5e} N vs {expected:.5e} N (sigma {sigma:.2e})");
    assert!(
        (mean - expected).abs() < 4.0 * sigma,
        "{mean} vs {expected}"
    );
}

/// The force spectrum with the cross terms: S_F(mu) = 8 sum_{k,l} w_k w_l integral
/// S(w + mu) S(w) |T(w + mu, w; b_k, b_l)|^2 dw (the two orders of a pair of (frequency,
/// direction) components give 2 Re[a_ik a_jl* T e^{i mu t}], of power 2 P_ik P_jl |T|^2 with
/// P = 2 S w d_omega), the QTF interpolated by the test's own code; against Welch estimates
/// over 6 seeds x 2^14 s, in bands of bins, within 5 sigma (sigma = sqrt(1.06 * 1.9 / (K B)),
/// as for one direction in tests/all/full_qtf.rs).
#[test]
fn force_spectrum_with_the_cross_terms_between_directions() {
    let dt = 0.5;
    let band = (0.35, 1.6);
    let grid = FrequencyGrid::new(0.0, 16384.0, dt, band).unwrap();
    let sea0 = sea(0, 3);
    let directions = sea0.directions();
    let groups = joint_groups(&grid, &sea0);
    let (segment, seeds) = (1024, 6);
    let mut estimate: Option<Vec<f64>> = None;
    let mut segments = 0;
    let mut bins = Vec::new();
    for seed in 0..seeds {
        let records = joint_records(&grid, &sea(300 + seed, 3), &groups);
        let welch = welch_spectrum(records.wave_force[0].samples(), dt, segment).unwrap();
        segments += 1 + (grid.len - segment) / (segment - segment / 2);
        let sum = estimate.get_or_insert_with(|| vec![0.0; welch.density.len()]);
        for (s, d) in sum.iter_mut().zip(&welch.density) {
            *s += d / seeds as f64;
        }
        bins = welch.omega;
    }
    let estimate = estimate.unwrap();
    let omegas = qtf_grid();
    let spectrum = &sea0.spectrum;
    let (w_low, w_high) = (grid.omega(0), grid.omega(grid.count - 1));
    let s_f = |mu: f64| {
        let mut total = 0.0;
        for dk in &directions {
            for dl in &directions {
                total += 8.0
                    * dk.weight
                    * dl.weight
                    * simpson(
                        |w| {
                            spectrum.density(w + mu)
                                * spectrum.density(w)
                                * interpolated(1, &omegas, w + mu, w, dk.heading, dl.heading)
                                    .norm_sqr()
                        },
                        w_low,
                        w_high - mu,
                        200,
                    );
            }
        }
        total
    };
    let d_mu = bins[1];
    for (low, high) in [(3usize, 10usize), (10, 20), (20, 40), (40, 80)] {
        let measured: f64 = estimate[low..high].iter().sum::<f64>() * d_mu;
        let expected: f64 = (low..high).map(|k| s_f(bins[k])).sum::<f64>() * d_mu;
        let sigma = (1.06 * 1.9 / (segments * (high - low)) as f64).sqrt();
        let ratio = measured / expected;
        println!(
            "mu {:.3}..{:.3} rad/s: Welch / integral = {ratio:.4} (sigma {sigma:.4})",
            bins[low], bins[high]
        );
        assert!(
            (ratio - 1.0).abs() < 5.0 * sigma + 0.01,
            "{ratio} (sigma {sigma})"
        );
    }
}

/// Heading interpolation never extrapolates and never invents a pair: a direction beyond the
/// data headings, and a pair of different headings with uni-directional data, are refused
/// naming them; a direction on a data heading takes that heading's block bit for bit.
#[test]
fn heading_interpolation_refuses_what_the_data_do_not_cover() {
    let omegas = qtf_grid();
    let uni = qtf(&omegas, &data_headings(), false);
    let message = uni
        .interpolated(Dof::Surge, (150f64.to_radians(), 150f64.to_radians()))
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("150.000 deg") && message.contains("-100.000"),
        "{message}"
    );
    let message = uni
        .interpolated(Dof::Yaw, (0.0, 30f64.to_radians()))
        .unwrap_err()
        .to_string();
    assert!(message.contains("bi-directional QTF"), "{message}");
    let node = 25f64.to_radians();
    assert_eq!(
        uni.interpolated(Dof::Sway, (node, node)).unwrap(),
        uni.block(Dof::Sway, node, 1e-12).unwrap().values
    );
    let pairs = qtf(&omegas, &data_headings(), true);
    assert_eq!(
        pairs.interpolated(Dof::Sway, (node, 0.0)).unwrap(),
        pairs
            .pair_block(Dof::Sway, (node, 0.0), 1e-12)
            .unwrap()
            .values
    );
    // Bilinear weights are symmetric: (b1, b2) and (b2, b1) of a Hermitian QTF are each
    // other's conjugate transpose.
    let (b1, b2) = (0.3, -0.7);
    let (a, b) = (
        pairs.interpolated(Dof::Yaw, (b1, b2)).unwrap(),
        pairs.interpolated(Dof::Yaw, (b2, b1)).unwrap(),
    );
    let n = omegas.len();
    for i in 0..n {
        for j in 0..n {
            assert!(
                (a[i * n + j] - b[j * n + i].conj()).norm() <= 1e-9 * a[i * n + j].norm().max(1.0)
            );
        }
    }
}

/// Yaw following with the full QTF: the records at body yaw theta_j are those of the sea
/// turned by -theta_j at the mean position (the same amplitudes, the QTF at the relative
/// headings beta_k - theta_j, cross terms included), for a spread sea on bi-directional data;
/// a yaw range whose relative headings leave the data is refused naming the yaw.
#[test]
fn yaw_following_records_are_the_full_qtf_at_the_relative_headings() {
    use slowdrift::model::YawFollowing;
    let mut problem = spread_problem(sea(21, 3), true, 300.0);
    problem.model.yaw_following = Some(YawFollowing {
        headings: 3,
        range: Some((-10f64.to_radians(), 10f64.to_radians())),
    });
    let sim = Simulation::new(problem.clone()).unwrap();
    let yaw = sim
        .records()
        .yaw_following
        .as_ref()
        .expect("yaw-following records");
    assert_eq!(yaw.sets.len(), 3);
    for (j, theta) in [-10.0f64, 0.0, 10.0].into_iter().enumerate() {
        let mut turned = problem.clone();
        turned.model.yaw_following = None;
        turned.sea.mean_direction -= theta.to_radians();
        let reference = Simulation::new(turned).unwrap();
        for d in 0..3 {
            let (a, b) = (
                yaw.sets[j].wave_force[d].samples(),
                reference.records().wave_force[d].samples(),
            );
            let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let worst = a
                .iter()
                .zip(b)
                .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
            assert!(
                worst <= 1e-9 * scale,
                "yaw {theta} deg, DOF {d}: {worst} of {scale}"
            );
        }
    }
    // Beyond the data: directions at about -54, 6 and 66 deg turned by up to 40 deg reach
    // -94 .. 106 deg, past the data's 100 deg.
    problem.model.yaw_following = Some(YawFollowing {
        headings: 3,
        range: Some((-40f64.to_radians(), 40f64.to_radians())),
    });
    let Err(error) = Simulation::new(problem) else {
        panic!("relative headings beyond the QTF must be refused")
    };
    let message = error.to_string();
    assert!(
        message.contains("model.yaw_following") && message.contains("-40.000 deg"),
        "{message}"
    );
}
