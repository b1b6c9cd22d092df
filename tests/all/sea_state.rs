//! The synthesised elevation against the input sea state (docs/theory.md#sea-state,
//! docs/theory.md#random-waves, docs/theory.md#checks-with-known-answers):
//! variance vs Hs^2/16, Gaussian distribution, periodogram vs the spectrum.

use crate::common::*;
use slowdrift::forces::{ForceRecords, RecordOptions};
use slowdrift::model::NewmanForm;
use slowdrift::sea_state::{FrequencyGrid, SeaState, Spectrum, Spreading, WaveComponents};
use slowdrift::stats::summarize;
use std::f64::consts::PI;

fn elevation(sea: &SeaState, duration: f64, dt: f64) -> (Vec<f64>, FrequencyGrid) {
    let grid = FrequencyGrid::new(0.0, duration, dt, sea.band()).unwrap();
    let components = WaveComponents::generate(sea, grid.clone());
    let transfers: Vec<_> = components
        .directions
        .iter()
        .map(|_| slowdrift::forces::DirectionTransfer {
            drift: std::array::from_fn(|_| vec![0.0; grid.count]),
            damping: None,
        })
        .collect();
    let options = RecordOptions {
        newman: NewmanForm::Geometric,
        full_qtf: None,
        drag_columns: &[],
        strips_per_column: 1,
        gravity: GRAVITY,
        fft: None,
    };
    let records = ForceRecords::build(&components, &transfers, &options);
    (records.elevation.samples().to_vec(), grid)
}

/// The record's variance over its full period is (1/2) sum |a_n|^2 (Parseval), with mean
/// m0_band = sum S_n d omega and standard deviation sqrt(sum (S_n d omega)^2).
#[test]
fn variance_matches_hs_squared_over_16() {
    let hs = 4.0;
    for (spectrum, spreading) in [
        (
            Spectrum::PiersonMoskowitz { hs, tp: 9.0 },
            Spreading::LongCrested,
        ),
        (
            Spectrum::Jonswap {
                hs,
                tp: 12.0,
                gamma: None,
            },
            Spreading::CosN { n: 4.0 },
        ),
        (
            Spectrum::Jonswap {
                hs,
                tp: 8.0,
                gamma: Some(5.0),
            },
            Spreading::Cos2s { s: 6.0 },
        ),
    ] {
        let mut sea = long_crested(spectrum.clone(), 3);
        sea.spreading = spreading;
        sea.n_directions = 7;
        let (eta, grid) = elevation(&sea, 3.0 * 3600.0, 0.25);
        let n = grid.len as f64;
        let variance =
            eta.iter().map(|e| e * e).sum::<f64>() / n - (eta.iter().sum::<f64>() / n).powi(2);
        let (lo, hi) = sea.band();
        let m0_band = simpson(|w| spectrum.density(w), lo, hi, 20000);
        // the sampling spread of (1/2) sum |a_n|^2 over the directions
        let sigma = (0..grid.count)
            .map(|j| (spectrum.density(grid.omega(j)) * grid.d_omega).powi(2))
            .sum::<f64>()
            .sqrt()
            * sea
                .directions()
                .iter()
                .map(|d| d.weight * d.weight)
                .sum::<f64>()
                .sqrt();
        assert!(
            (variance - m0_band).abs() < 5.0 * sigma + 1e-3 * m0_band,
            "{spectrum:?}: {variance} vs {m0_band}"
        );
        // The band holds all but the tails of Hs^2/16; DNV's A_gamma is a fit
        // (docs/theory.md#sea-state).
        let m0 = hs * hs / 16.0;
        assert!(
            (m0_band / m0 - 1.0).abs() < 0.025,
            "{spectrum:?}: band m0 {m0_band} vs Hs^2/16 = {m0}"
        );
    }
}

/// Sample moments of a long record against the Gaussian: skewness 0 and kurtosis 3, with
/// tolerances from the number of independent samples (about one per zero-crossing period).
#[test]
fn elevation_is_gaussian() {
    let sea = long_crested(jonswap(3.0, 8.0), 5);
    let (eta, _) = elevation(&sea, 6.0 * 3600.0, 0.5);
    let n = eta.len() as f64;
    let mean = eta.iter().sum::<f64>() / n;
    let var = eta.iter().map(|e| (e - mean).powi(2)).sum::<f64>() / n;
    let skew = eta.iter().map(|e| (e - mean).powi(3)).sum::<f64>() / n / var.powf(1.5);
    let kurt = eta.iter().map(|e| (e - mean).powi(4)).sum::<f64>() / n / (var * var);
    let independent: f64 = 6.0 * 3600.0 / 6.0; // one per ~6 s
    assert!(
        skew.abs() < 5.0 * (6.0 / independent).sqrt(),
        "skewness {skew}"
    );
    assert!(
        (kurt - 3.0).abs() < 5.0 * (24.0 / independent).sqrt(),
        "kurtosis {kurt}"
    );
    // Fraction of samples within one standard deviation: 68.27 %.
    let inside = eta
        .iter()
        .filter(|e| (*e - mean).abs() < var.sqrt())
        .count() as f64
        / n;
    assert!(
        (inside - 0.6827).abs() < 0.02,
        "P(|eta| < sigma) = {inside}"
    );
}

/// The Welch estimate of the elevation spectrum against the input S(omega), averaged over
/// bands so that the estimate's relative error (about 1/sqrt(segments x bins)) is small.
#[test]
fn periodogram_matches_the_input_spectrum() {
    let spectrum = Spectrum::Jonswap {
        hs: 5.0,
        tp: 10.0,
        gamma: Some(2.0),
    };
    let sea = long_crested(spectrum.clone(), 9);
    let dt = 0.5;
    let (eta, _) = elevation(&sea, 24.0 * 3600.0, dt);
    let wp = 2.0 * PI / 10.0;
    let (checked, _) = welch_bands_match(&eta, dt, 1024, 4, (0.8 * wp, 2.0 * wp), 0.03, |a, b| {
        simpson(|w| spectrum.density(w), a, b, 200)
    });
    assert!(checked >= 10, "checked {checked} bands");
    let summary = summarize(&eta, dt, 0.0).unwrap();
    assert!(summary.mean.abs() < 0.05);
}

#[test]
fn same_seed_same_record_bit_for_bit() {
    let sea = long_crested(jonswap(3.0, 8.0), 42);
    let (a, _) = elevation(&sea, 1000.0, 0.5);
    let (b, _) = elevation(&sea, 1000.0, 0.5);
    assert_eq!(a, b);
    let other = long_crested(jonswap(3.0, 8.0), 43);
    let (c, _) = elevation(&other, 1000.0, 0.5);
    assert_ne!(a, c);
}

#[test]
fn record_covers_the_duration_without_repeating() {
    let grid = FrequencyGrid::new(0.0, 10_800.0, 0.5, (0.3, 3.0)).unwrap();
    assert!(grid.end_time() >= 10_800.0);
    assert!(grid.len as f64 * grid.dt >= 10_800.0);
}
