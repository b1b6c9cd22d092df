//! Builders shared by the integration tests: a simple platform, sea and drift table whose
//! expected answers the tests derive independently.
#![allow(dead_code)] // each test binary uses a different subset

use slowdrift::hydro::{DriftRow, DriftTable};
use slowdrift::model::{
    Cylinder, DragModel, DriftDamping, Environment, Interaction, NewmanForm, SecondOrder,
    WaveFrequencyMotion, DEFAULT_QTF_TOLERANCE,
};
use slowdrift::problem::Hydro;
use slowdrift::scenario::{
    Current, InitialCondition, ModelOptions, Platform, Run, DEFAULT_BLOCK_DURATION,
};
use slowdrift::sea_state::{SeaState, Spectrum, Spreading};
use slowdrift::{Problem, Snapshot};
use std::f64::consts::PI;

pub const GRAVITY: f64 = 9.80665;

/// How far a record quadratic in the wave series (a squared modulus, a product of two
/// series) may be from its double sum, as a fraction of the record's largest value: the
/// series come from single-precision transforms, each sample within
/// `forces::SINGLE_PRECISION_ERROR` (e) of its series' rms, so a product of two errs by
/// about 2 e of the products' size, and twice that for a record made of several such
/// products.
pub const QUADRATIC_RECORD_TOLERANCE: f64 = 4.0 * slowdrift::forces::SINGLE_PRECISION_ERROR;

/// A drift table sampled from `drift(omega, beta)` on a regular grid of 0.02 .. 3 rad/s
/// and headings every 10 degrees around the circle.
pub fn drift_table(drift: impl Fn(f64, f64) -> [f64; 3]) -> DriftTable {
    let mut rows = Vec::new();
    for ih in 0..36 {
        let beta = (ih as f64 * 10.0).to_radians();
        for iw in 1..=150 {
            let omega = 0.02 * iw as f64;
            rows.push(DriftRow {
                omega,
                heading: beta,
                drift: drift(omega, beta),
                damping: None,
            });
        }
    }
    DriftTable::from_rows(&rows).unwrap()
}

/// The paper's four columns: radius 10 m at (+-35, +-35) m, draft 30 m.
pub fn four_columns() -> Vec<Cylinder> {
    [(35.0, 35.0), (-35.0, 35.0), (-35.0, -35.0), (35.0, -35.0)]
        .iter()
        .map(|&(x, y)| Cylinder {
            x,
            y,
            diameter: 20.0,
            draft: 30.0,
        })
        .collect()
}

/// A smooth positive surge drift of a plausible size (N/m^2), isotropic in heading.
pub fn smooth_drift(omega: f64, beta: f64) -> [f64; 3] {
    let f = 2.0e4 * (1.0 + omega * omega);
    [f * beta.cos(), f * beta.sin(), 0.0]
}

pub fn jonswap(hs: f64, tp: f64) -> Spectrum {
    Spectrum::Jonswap {
        hs,
        tp,
        gamma: Some(3.3),
    }
}

pub fn long_crested(spectrum: Spectrum, seed: u64) -> SeaState {
    SeaState {
        spectrum,
        spreading: Spreading::LongCrested,
        mean_direction: 0.0,
        n_directions: 1,
        seed,
        band: None,
    }
}

/// A platform with uncoupled surge, sway, yaw oscillators: natural periods `periods` (s)
/// and linear damping ratios `zeta`, no added mass.
pub fn oscillator_platform(mass: f64, yaw_inertia: f64, periods: [f64; 3], zeta: f64) -> Platform {
    let inertia = [mass, mass, yaw_inertia];
    let mut stiffness = [[0.0; 3]; 3];
    let mut damping = [[0.0; 3]; 3];
    for i in 0..3 {
        let wn = 2.0 * PI / periods[i];
        stiffness[i][i] = inertia[i] * wn * wn;
        damping[i][i] = 2.0 * zeta * inertia[i] * wn;
    }
    Platform {
        mass: Some(mass),
        yaw_inertia: Some(yaw_inertia),
        added_mass: Some([[0.0; 3]; 3]),
        stiffness,
        linear_damping: damping,
        quadratic_damping: [[0.0; 3]; 3],
        columns: Vec::new(),
        motions: None,
        wind: None,
    }
}

/// Head seas on an oscillator platform, Newman geometric, no drift damping, no drag.
pub fn base_problem(duration: f64, time_step: f64, seed: u64) -> Problem {
    Problem {
        environment: Environment::default(),
        sea: long_crested(jonswap(6.0, 10.0), seed),
        current: Current::default(),
        wind: slowdrift::wind::WindField::default(),
        run: Run {
            duration,
            time_step,
            start_time: 0.0,
            block_duration: DEFAULT_BLOCK_DURATION,
            memory_limit: slowdrift::scenario::limits::DEFAULT_MEMORY_LIMIT,
        },
        platform: oscillator_platform(1.0e7, 1.0e10, [60.0, 60.0, 40.0], 0.2),
        hydro: Hydro::from_drift(drift_table(smooth_drift)),
        model: ModelOptions {
            second_order: SecondOrder::Newman,
            qtf_tolerance: DEFAULT_QTF_TOLERANCE,
            newman: NewmanForm::Geometric,
            interaction: Interaction::None,
            drift_damping: DriftDamping::Off,
            drag: DragModel::Off,
            strips_per_column: 20,
            yaw_following: None,
            wave_frequency_motion: WaveFrequencyMotion::On,
        },
        initial: InitialCondition::default(),
        origins: Default::default(),
    }
}

/// Composite Simpson integral of f over [a, b] with `panels` (even) panels.
pub fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, panels: usize) -> f64 {
    let h = (b - a) / panels as f64;
    let inner: f64 = (1..panels)
        .map(|i| if i % 2 == 1 { 4.0 } else { 2.0 } * f(a + i as f64 * h))
        .sum();
    (f(a) + inner + f(b)) * h / 3.0
}

/// Frequency-domain variance of the surge of an oscillator platform (uncoupled surge:
/// mass + A11, stiffness C11, linear damping B11) in the long-crested head sea of `problem`
/// driven by Newman's geometric force of the [`smooth_drift`] surge drift:
/// var x = integral S_F(mu) |H(mu)|^2 dmu with S_F(mu) = 8 integral S(w) S(w + mu)
/// T(w) T(w + mu) dw over the simulated band (docs/theory.md#checks-with-known-answers).
pub fn oscillator_surge_variance(problem: &Problem) -> f64 {
    let (p, inertia) = (&problem.platform, problem.inertia().unwrap());
    let (mass, stiffness, damping) = (
        inertia.mass + inertia.added_mass[0][0],
        p.stiffness[0][0],
        p.linear_damping[0][0],
    );
    let transfer_squared =
        |mu: f64| 1.0 / ((stiffness - mass * mu * mu).powi(2) + (damping * mu).powi(2));
    let (lo, hi) = problem.sea.band();
    let force_spectrum = surge_force_spectrum(problem);
    simpson(
        |mu| force_spectrum(mu) * transfer_squared(mu),
        0.0,
        hi - lo,
        4000,
    )
}

/// The one-sided spectrum of the slowly varying surge force of `smooth_drift` (Newman,
/// geometric, positive T) in `problem`'s sea: S_F(mu) = 8 integral S(w) S(w + mu) T(w)
/// T(w + mu) dw over the simulated band (docs/theory.md#checks-with-known-answers).
pub fn surge_force_spectrum(problem: &Problem) -> impl Fn(f64) -> f64 + '_ {
    let drift = |w: f64| smooth_drift(w, 0.0)[0];
    let spectrum = &problem.sea.spectrum;
    let (lo, hi) = problem.sea.band();
    move |mu: f64| {
        8.0 * simpson(
            |w| spectrum.density(w) * spectrum.density(w + mu) * drift(w) * drift(w + mu),
            lo,
            hi - mu,
            2000,
        )
    }
}

/// Compares the Welch estimate of `record` (sampled at `dt`; Hann segments of `segment`
/// samples, 50 % overlap) with the true one-sided spectrum, in bands of `band_bins` bins
/// (from bin 1) whose centre lies in `centres`: each band's integral within 5 sigma +
/// `slack` of `expected(a, b)`, the true spectrum's integral over the band [a, b]
/// (sigma = sqrt(1.06 x 1.94 / (segments x bins)), Welch's variance for Hann with 50 %
/// overlap). Returns the bands checked and the worst error in sigma.
pub fn welch_bands_match(
    record: &[f64],
    dt: f64,
    segment: usize,
    band_bins: usize,
    centres: (f64, f64),
    slack: f64,
    expected: impl Fn(f64, f64) -> f64,
) -> (usize, f64) {
    let estimate = slowdrift::stats::welch_spectrum(record, dt, segment).unwrap();
    let segments = (2 * record.len() / segment - 1) as f64;
    let d_omega = estimate.omega[1];
    let rel_sigma = (1.06 * 1.94 / (segments * band_bins as f64)).sqrt();
    let (mut checked, mut worst) = (0, 0.0f64);
    for start in (1..estimate.omega.len() - band_bins).step_by(band_bins) {
        let centre = estimate.omega[start + band_bins / 2];
        if centre < centres.0 || centre > centres.1 {
            continue;
        }
        let measured: f64 = estimate.density[start..start + band_bins]
            .iter()
            .sum::<f64>()
            * d_omega;
        let true_integral = expected(
            estimate.omega[start] - 0.5 * d_omega,
            estimate.omega[start + band_bins - 1] + 0.5 * d_omega,
        );
        let error = measured / true_integral - 1.0;
        assert!(
            error.abs() < 5.0 * rel_sigma + slack,
            "omega {centre}: {measured} vs {true_integral}"
        );
        worst = worst.max(error.abs() / rel_sigma);
        checked += 1;
    }
    (checked, worst)
}

/// The shared data directory: `$SLOWDRIFT_DATA` if set, else `../shared/data` next to the
/// repository (where CI puts it).
pub fn shared_data_dir() -> std::path::PathBuf {
    std::env::var_os("SLOWDRIFT_DATA")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/data").into())
}

/// The OC4 semisubmersible's WAMIT files without extension (`.../marin_semi`), or `None`
/// after printing a "skipped" line when the data are absent. Under CI (env var `CI` set)
/// absent data is a failure.
pub fn oc4_root_or_skip() -> Option<std::path::PathBuf> {
    let dir = shared_data_dir().join("wamit/oc4-semi");
    if dir.join("marin_semi.12d").is_file() {
        return Some(dir.join("marin_semi"));
    }
    if std::env::var_os("CI").is_some() {
        panic!(
            "the OC4 WAMIT data are absent at {} (CI is set: they must be there; set \
             SLOWDRIFT_DATA to the shared data directory)",
            dir.display()
        );
    }
    println!("skipped: data absent at {}", dir.display());
    None
}

/// `snapshot` moved to `steps` steps after its origin, the rest of it unchanged: a state
/// however far into a run without stepping there (the step count is the second of
/// [`Snapshot::to_bytes`]' little-endian words).
pub fn snapshot_at_step(snapshot: &Snapshot, steps: u64) -> Snapshot {
    let mut bytes = snapshot.to_bytes();
    bytes[8..16].copy_from_slice(&steps.to_le_bytes());
    Snapshot::from_bytes(&bytes).expect("a snapshot's own bytes")
}
