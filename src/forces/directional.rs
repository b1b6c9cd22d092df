//! Interaction between the directions of a short-crested sea: the cross-direction terms of
//! the slowly varying force, by a Newman-type approximation at FFT cost (E&S 3, 4;
//! docs/theory.md#the-slowly-varying-force).
//!
//! # The double sum
//!
//! With components a_{ik} (frequency omega_i, direction beta_k; `sea_state::WaveComponents`)
//! the low-frequency force runs over pairs of (frequency, direction):
//!   F(t) = Re sum_{i,k} sum_{j,l} a_{ik} a_{jl}* T(omega_i, omega_j; beta_k, beta_l) e^{i (omega_i - omega_j) t}.
//! The terms k = l are each direction's own double sum (`forces::newman`, or the full QTF);
//! this module adds the terms k != l, which [`Interaction::None`] drops.
//!
//! # Newman-type form for k != l (arithmetic mean)
//!
//! Only the bi-directional *mean* drift T_kl(omega) = T(omega; beta_k, beta_l) is known
//! (Hermitian: T_lk = conj T_kl). Off the frequency diagonal take the arithmetic mean
//!   T(omega_i, omega_j; beta_k, beta_l) ~ (T_kl(omega_i) + T_kl(omega_j)) / 2,
//! which keeps the Hermitian symmetry of the full QTF. Then, with
//!   Q_kl(t) = sum_i a_{ik} T_kl(omega_i) e^{i omega_i t},  eta_l(t) = sum_j a_{jl} e^{i omega_j t},
//! the first half of the sum is sum_{kl} Q_kl eta_l*, and the second,
//! sum_{kl} eta_k conj(sum_j a_{jl} conj T_kl(omega_j) e^{i omega_j t}) = sum_{kl} eta_k Q_lk*
//! (by T_kl* = T_lk) = conj(sum_{kl} Q_kl eta_l*) after swapping k and l. So
//!   F_cross(t) = Re sum_l P_l(t) eta_l(t)*,  P_l(t) = sum_{k != l} Q_kl(t)
//!             = sum_i (sum_{k != l} a_{ik} T_kl(omega_i)) e^{i omega_i t}:
//! the coefficients of P_l are formed directly (O(N_omega N_beta) per l), so the cost is
//! **one FFT per direction and DOF for P_l plus one per direction for eta_l**: linear in
//! N_beta, not the N_beta^2 single-sum products of the paper's E&S 4 route. The pairing with
//! the within-direction terms:
//! - `newman = "arithmetic"`: F = Re sum_{k,l} Q_kl eta_l* in full, the same rule for every
//!   pair;
//! - `newman = "geometric"` (default): E&S 4's sign-split geometric mean within each
//!   direction, the arithmetic mean across directions. A geometric mean needs a sign and
//!   T_kl (k != l) is complex; the matrix analogue (principal square roots of the positive
//!   and negative parts of the N_beta x N_beta matrix T(omega)) would cost an eigen-
//!   decomposition per grid frequency, O(N_omega N_beta^3), and is not built.
//!
//! T_kl(omega) is interpolated linearly in omega from the data frequencies
//! ([`DirectionPairs`]) onto the grid. The mean of F_cross is zero (independent amplitudes),
//! so the mean force stays 2 double-integral S D T(omega; beta, beta).
//!
//! # Data ([`Interaction`])
//!
//! `Auto` (default): `Bidirectional` when the configuration has the data, else
//! `MeanDirection`. `Bidirectional`: the configuration's [`BidirectionalSource`] (column solver at the exact
//! directions, or a database table); `MeanDirection`: T(omega; (beta_k + beta_l)/2) from the
//! uni-directional drift table (`hydro::bidirectional::mean_direction_pairs`). The
//! wave-drift damping records keep no cross terms (no bi-directional damping data exists).

use super::refine;
use super::synthesis::{InverseFft, Synthesizer};
use super::{ForceRecords, Record};
use crate::error::{Error, Result};
use crate::hydro::bidirectional::{mean_direction_pairs, DirectionPairs};
use crate::model::{Interaction, Mode};
use crate::problem::Problem;
use crate::sea_state::{Direction, FrequencyGrid, WaveComponents};
use rustfft::num_complex::Complex64;

/// The bi-directional drift at the sea's directions that `problem` asks for, or `None`
/// when there is nothing to add (interaction off, or one direction).
pub fn direction_pairs(
    problem: &Problem,
    grid: &FrequencyGrid,
    directions: &[Direction],
) -> Result<Option<DirectionPairs>> {
    let headings: Vec<f64> = directions.iter().map(|d| d.heading).collect();
    if headings.len() < 2 {
        return Ok(None);
    }
    let band = (grid.omega(0), grid.omega(grid.count - 1));
    match problem.interaction() {
        Interaction::None => Ok(None),
        Interaction::MeanDirection => {
            mean_direction_pairs(&problem.hydro.drift, band, &headings).map(Some)
        }
        Interaction::Bidirectional | Interaction::Auto => {
            let source = problem.hydro.bidirectional.as_ref().ok_or_else(|| {
                Error::invalid(
                    "model.interaction",
                    Interaction::Bidirectional.word(),
                    "the drift source has no bi-directional drift",
                )
            })?;
            source
                .pairs(&problem.environment, band, &headings)
                .map(Some)
        }
    }
}

/// The cross-direction force F_cross (surge, sway, yaw; module doc), one vector of record
/// samples per DOF (empty where every T_kl, k != l, of that DOF is zero), over the grid's
/// period. `fft` is the grid's planned inverse transform.
pub fn cross_direction_force(
    components: &WaveComponents,
    pairs: &DirectionPairs,
    fft: &InverseFft,
) -> [Vec<f64>; 3] {
    let mut synth = Synthesizer::with_fft(&components.grid, fft.clone());
    let mut work = CrossWork::default();
    work.force(components, pairs, &mut synth);
    work.cross
}

/// Adds the cross-direction force to the records' wave force (`synth` writes the records'
/// series: a grid's period or a stream's segment; with `refined` = Some((len, spare)), at
/// every second sample, refined to the records' len samples through `spare`:
/// `forces::refine`).
pub fn add_cross_terms(
    records: &mut ForceRecords,
    components: &WaveComponents,
    pairs: &DirectionPairs,
    synth: &mut Synthesizer,
    refined: Option<(usize, &mut Vec<f64>)>,
    work: &mut CrossWork,
) {
    work.force(components, pairs, synth);
    if let Some((len, spare)) = refined {
        work.cross
            .iter_mut()
            .for_each(|v| refine::refine(v, len, spare));
    }
    for (record, extra) in records.wave_force.iter_mut().zip(&mut work.cross) {
        if extra.is_empty() {
            continue;
        }
        let mut samples = std::mem::take(record).into_samples();
        if samples.is_empty() {
            samples.extend_from_slice(extra);
        } else {
            for (s, v) in samples.iter_mut().zip(extra.iter()) {
                *s += v;
            }
        }
        *record = Record::new(samples);
    }
}

/// The buffers of the cross-direction force, kept from one build to the next (a stream's
/// segments): a build of the same shape allocates nothing.
#[derive(Default, Clone)]
pub struct CrossWork {
    brackets: Vec<(usize, usize, f64)>,
    eta: Vec<Complex64>,
    series: Vec<Complex64>,
    coefficients: Vec<Complex64>,
    /// The cross-direction force of the last build, per DOF (empty: zero).
    cross: [Vec<f64>; 3],
}

impl CrossWork {
    /// The cross-direction force into `self.cross`: per direction l, the transform of
    /// eta_l and of P_l = sum_{k != l} a_k T_kl, and Re P_l eta_l* summed (module doc).
    fn force(
        &mut self,
        components: &WaveComponents,
        pairs: &DirectionPairs,
        synth: &mut Synthesizer,
    ) {
        let grid = &components.grid;
        let nd = components.directions.len();
        debug_assert_eq!(pairs.directions, nd);
        let len = synth.output_len();
        frequency_brackets(pairs, components, &mut self.brackets);
        let active: [bool; 3] = std::array::from_fn(|dof| {
            pairs.values.chunks(nd * nd).any(|block| {
                (0..nd).any(|k| {
                    (0..nd).any(|l| k != l && block[k * nd + l][dof] != Complex64::default())
                })
            })
        });
        for v in &mut self.cross {
            v.clear();
        }
        self.eta.resize(len, Complex64::default());
        self.series.resize(len, Complex64::default());
        self.coefficients.resize(grid.count, Complex64::default());
        for l in 0..nd {
            synth.complex_series(components.of_direction(l), &mut self.eta);
            for (dof, out) in self.cross.iter_mut().enumerate() {
                if !active[dof] {
                    continue;
                }
                for (i, (c, &(n, n_hi, f))) in
                    self.coefficients.iter_mut().zip(&self.brackets).enumerate()
                {
                    let mut sum = Complex64::default();
                    for k in (0..nd).filter(|&k| k != l) {
                        let lo = pairs.get(n, k, l)[dof];
                        let hi = pairs.get(n_hi, k, l)[dof];
                        sum += components.of_direction(k)[i] * (lo + (hi - lo) * f);
                    }
                    *c = sum;
                }
                synth.complex_series(&self.coefficients, &mut self.series);
                out.resize(len, 0.0);
                for ((o, p), e) in out.iter_mut().zip(&self.series).zip(&self.eta) {
                    *o += (p * e.conj()).re;
                }
            }
        }
    }
}

/// For every grid component, the data nodes (lo, hi) around it and the weight of hi
/// (linear interpolation; the data cover the band, see `DirectionPairs`).
fn frequency_brackets(
    pairs: &DirectionPairs,
    components: &WaveComponents,
    out: &mut Vec<(usize, usize, f64)>,
) {
    let w = &pairs.omegas;
    let last = w.len() - 1;
    let grid = &components.grid;
    out.clear();
    out.extend((0..grid.count).map(|i| {
        let omega = grid.omega(i).clamp(w[0], w[last]);
        if last == 0 {
            return (0, 0, 0.0);
        }
        let n = w.partition_point(|&v| v <= omega).clamp(1, last) - 1;
        (n, n + 1, (omega - w[n]) / (w[n + 1] - w[n]))
    }));
}
