//! Newman's approximation by FFT against the O(N^2) double sum
//! (docs/theory.md#the-slowly-varying-force), and
//! the mean force against 2 * integral S T d omega.

use crate::common::*;
use rustfft::num_complex::Complex64;
use slowdrift::forces::{transfers_on_grid, ForceRecords, RecordOptions};
use slowdrift::hydro::{DriftRow, DriftTable};
use slowdrift::model::NewmanForm;
use slowdrift::sea_state::{FrequencyGrid, SeaState, Spreading, WaveComponents};

/// Drift that changes sign with frequency and heading, and a yaw moment.
fn mixed_sign_drift(omega: f64, beta: f64) -> [f64; 3] {
    let f = 3.0e4 * (omega - 0.9);
    [
        f * beta.cos(),
        1.0e4 * (1.2 - omega) * beta.sin(),
        5.0e5 * (omega - 0.6) * (2.0 * beta).sin(),
    ]
}

fn spread_sea(seed: u64) -> SeaState {
    SeaState {
        spectrum: jonswap(5.0, 9.0),
        spreading: Spreading::CosN { n: 2.0 },
        mean_direction: 0.4,
        n_directions: 3,
        seed,
        band: Some((0.3, 2.0)),
    }
}

/// The direct double sum Re sum_k sum_i sum_j a_ik a_jk* T_ij e^{i (w_i - w_j) t}.
fn double_sum(
    components: &WaveComponents,
    diagonal: &[Vec<f64>],
    qtf: impl Fn(f64, f64) -> f64,
    t: f64,
) -> f64 {
    let grid = &components.grid;
    let mut total = 0.0;
    for (k, t_k) in diagonal.iter().enumerate() {
        let a = components.of_direction(k);
        for i in 0..grid.count {
            for j in 0..grid.count {
                let phase = (grid.omega(i) - grid.omega(j)) * (t - grid.start_time);
                let term = a[i] * a[j].conj() * Complex64::from_polar(1.0, phase);
                total += term.re * qtf(t_k[i], t_k[j]);
            }
        }
    }
    total
}

fn geometric(ti: f64, tj: f64) -> f64 {
    if ti * tj > 0.0 {
        ti.signum() * (ti * tj).sqrt()
    } else {
        0.0
    }
}

fn arithmetic(ti: f64, tj: f64) -> f64 {
    0.5 * (ti + tj)
}

fn damping_table() -> DriftTable {
    let mut rows = Vec::new();
    for ih in 0..36 {
        let beta = (ih as f64 * 10.0).to_radians();
        for iw in 1..=150 {
            let omega = 0.02 * iw as f64;
            let b = [
                [1.0e3 * (omega - 1.0), 2.0e2 * beta.sin(), -50.0 * omega],
                [3.0e2 * omega, 8.0e2 * (0.7 - omega), 10.0],
                [4.0e3, -2.0e3 * omega * omega, 7.0e4 * (omega - 0.8)],
            ];
            rows.push(DriftRow {
                omega,
                heading: beta,
                drift: mixed_sign_drift(omega, beta),
                damping: Some(b),
            });
        }
    }
    DriftTable::from_rows(&rows).unwrap()
}

fn build(
    form: NewmanForm,
) -> (
    WaveComponents,
    Vec<slowdrift::forces::DirectionTransfer>,
    ForceRecords,
) {
    let grid = FrequencyGrid::new(100.0, 300.0, 0.25, (0.3, 2.0)).unwrap();
    let components = WaveComponents::generate(&spread_sea(11), grid);
    let transfers = transfers_on_grid(
        &damping_table(),
        &components.grid,
        &components.directions,
        true,
    )
    .unwrap();
    let records = ForceRecords::build(
        &components,
        &transfers,
        &RecordOptions {
            newman: form,
            full_qtf: None,
            drag_columns: &[],
            strips_per_column: 1,
            gravity: GRAVITY,
            fft: None,
        },
    );
    (components, transfers, records)
}

fn assert_matches_double_sum(form: NewmanForm, qtf: fn(f64, f64) -> f64) {
    let (components, transfers, records) = build(form);
    let samples = [0usize, 1, 17, 250, 611, records.clock.len - 2];
    let mut checked = 0;
    let mut records_to_check: Vec<(Vec<Vec<f64>>, &[f64])> = Vec::new();
    for dof in 0..3 {
        let diag: Vec<Vec<f64>> = transfers.iter().map(|t| t.drift[dof].clone()).collect();
        records_to_check.push((diag, records.wave_force[dof].samples()));
    }
    let damping = records.damping.as_ref().unwrap();
    for (r, c) in [(0, 0), (1, 2), (2, 1), (2, 2)] {
        let diag: Vec<Vec<f64>> = transfers
            .iter()
            .map(|t| t.damping.as_ref().unwrap()[r][c].clone())
            .collect();
        records_to_check.push((diag, damping[r][c].samples()));
    }
    for (diag, fft) in &records_to_check {
        let scale = fft.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(scale > 0.0);
        for &m in &samples {
            let t = components.grid.time(m);
            let direct = double_sum(&components, diag, qtf, t);
            assert!(
                (fft[m] - direct).abs() <= QUADRATIC_RECORD_TOLERANCE * scale,
                "{form:?} sample {m}: fft {} vs double sum {direct}",
                fft[m]
            );
            checked += 1;
        }
    }
    assert_eq!(checked, 7 * samples.len());
}

#[test]
fn geometric_newman_equals_the_double_sum() {
    assert_matches_double_sum(NewmanForm::Geometric, geometric);
}

#[test]
fn arithmetic_newman_equals_the_double_sum() {
    assert_matches_double_sum(NewmanForm::Arithmetic, arithmetic);
}

#[test]
fn elevation_equals_the_direct_sum() {
    let (components, _, records) = build(NewmanForm::Geometric);
    let grid = &components.grid;
    let eta = records.elevation.samples();
    let scale = eta.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for m in [0usize, 5, 333, grid.len - 2] {
        let t = grid.time(m) - grid.start_time;
        let direct: f64 = (0..components.directions.len())
            .map(|k| {
                let a = components.of_direction(k);
                (0..grid.count)
                    .map(|j| (a[j] * Complex64::from_polar(1.0, grid.omega(j) * t)).re)
                    .sum::<f64>()
            })
            .sum();
        // A series, linear in the components: within the transform's bound of its largest.
        let bound = slowdrift::forces::SINGLE_PRECISION_ERROR * scale;
        assert!((eta[m] - direct).abs() < bound, "sample {m}");
    }
}

/// Over one period of the record every difference frequency completes whole cycles, so the
/// record's average is exactly sum |a_i|^2 T_i, whose expectation is 2 sum S_i T_i d omega
/// -> 2 integral S T d omega. Averaged over seeds, the standard error is known from the
/// exponential distribution of |a_i|^2 (variance (2 S_i d omega T_i)^2 per component).
#[test]
fn mean_force_is_twice_the_integral_of_spectrum_times_drift() {
    let spectrum = jonswap(6.0, 10.0);
    let band = (0.35, 2.4);
    let drift = |w: f64| 2.0e4 * (1.0 + w * w);
    let expected = 2.0 * simpson(|w| spectrum.density(w) * drift(w), band.0, band.1, 4000);
    let seeds = 20;
    let mut mean_of_means = 0.0;
    let mut variance_of_mean = 0.0;
    for seed in 0..seeds {
        let mut sea = long_crested(spectrum.clone(), seed);
        sea.band = Some(band);
        let grid = FrequencyGrid::new(0.0, 4000.0, 0.5, band).unwrap();
        let components = WaveComponents::generate(&sea, grid);
        let table = drift_table(smooth_drift);
        let transfers =
            transfers_on_grid(&table, &components.grid, &components.directions, false).unwrap();
        let records = ForceRecords::build(
            &components,
            &transfers,
            &RecordOptions {
                newman: NewmanForm::Geometric,
                full_qtf: None,
                drag_columns: &[],
                strips_per_column: 1,
                gravity: GRAVITY,
                fft: None,
            },
        );
        let f = records.wave_force[0].samples();
        mean_of_means += f.iter().sum::<f64>() / f.len() as f64 / seeds as f64;
        let g = &components.grid;
        variance_of_mean += (0..g.count)
            .map(|j| {
                (2.0 * spectrum.density(g.omega(j)) * g.d_omega * transfers[0].drift[0][j]).powi(2)
            })
            .sum::<f64>()
            / (seeds * seeds) as f64;
    }
    let sigma = variance_of_mean.sqrt();
    assert!(
        sigma < 0.02 * expected,
        "the check is tight: sigma/mean = {}",
        sigma / expected
    );
    assert!(
        (mean_of_means - expected).abs() < 4.0 * sigma + 1e-3 * expected,
        "mean {mean_of_means} vs 2 int S T = {expected} (sigma {sigma})"
    );
}
