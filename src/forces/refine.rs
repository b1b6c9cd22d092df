//! Quadratic records at their bandwidth: made at every second record sample (the RK4 step h)
//! and refined to the records' samples (docs/theory.md#records-at-their-bandwidth).
//!
//! A quadratic record (Newman's |P+|^2 - |P-|^2 or Re[Q eta*], the damping's, the full QTF's
//! sum s_r |U_r|^2) holds only difference frequencies mu = omega_i - omega_j in [0, W],
//! W = omega_max - omega_min the band's width, whatever the band's top frequency. Its
//! factor series are sums over the grid's components; at the times t_m = m 2 dt their
//! e^{i omega_n t_m} only sees n mod N/2, so a transform of N/2 points gives them exactly
//! at every second sample when the band has at most N/2 components (`forces::synthesis`),
//! joined as the records' are (`forces::stream::Sampling`). The record is then exact at
//! every second sample, the step's ends, and in between (the RK4 midpoint t + h/2) the
//! symmetric 8-point Lagrange interpolation of the coarse samples:
//!   F(t + h/2) = sum_{k=1..4} w_k [F(t - (k - 1) h) + F(t + k h)],
//!   w = (1225, -245, 49, -5) / 2048,
//! exact for polynomials of degree 7. For a tone e^{i mu t} its relative error is
//!   e(theta) = |1 - 2 sum_k w_k cos((k - 1/2) theta)|,  theta = mu h,
//! 3.9e-6 at theta = 0.5, 8.5e-4 at 1, 6.1e-2 at 1.83 (the default band's top) and 0.37 at
//! 2.5, the widest band admitted ([`MAX_BAND_PHASE`]); a record's error is this weighted by
//! its spectrum, which is small where e is not ([`midpoint_error`] estimates it for a sea).

// The two unsafe operations: the AVX2 build of the refinement, made only where the CPU has
// AVX2, and the refined record's length set once every sample is written.
#![allow(unsafe_code)]

use super::isa::Isa;
use super::stream::{Sampling, Segments, HALO_AFTER, HALO_BEFORE};
use crate::sea_state::FrequencyGrid;
use std::mem::MaybeUninit;

/// Record samples per coarse sample: the coarse interval is the step h = 2 dt.
pub const STEP: usize = 2;

/// The widest band made at the coarse interval: W h <= 2.5 rad, 0.8 of the coarse
/// interval's Nyquist phase pi (so no difference frequency aliases), where the midpoint
/// error of a tone at the band's top is 0.37 and the error weighted by a sea's difference-
/// frequency spectrum is of order 1e-3 ([`midpoint_error`]).
pub const MAX_BAND_PHASE: f64 = 2.5;

/// The stencil's nodes.
const TAPS: usize = 2 * WEIGHTS.len();

/// The interpolation weights w_1 .. w_4 of the nodes at -(k - 1) and +k coarse samples.
const WEIGHTS: [f64; 4] = [
    1225.0 / 2048.0,
    -245.0 / 2048.0,
    49.0 / 2048.0,
    -5.0 / 2048.0,
];

/// The coarse series' halos: the record's first sample (global kB - 1, odd) needs coarse
/// nodes from kB - 8, its last (global (k+1)B + H - 1, odd) up to (k+1)B + H + 6.
const BEFORE: usize = 4;
const AFTER: usize = (HALO_AFTER + 6) / STEP + 1;

// The refinement below pairs record samples (odd global, then even global) from the
// record's first sample: it needs an odd halo before and an even block.
const _: () = assert!(HALO_BEFORE == 1 && HALO_AFTER.is_multiple_of(2));

/// The coarse clock of a quadratic record: every [`STEP`]-th sample with the halos the
/// refinement's stencil needs.
pub const SAMPLING: Sampling = Sampling {
    step: STEP,
    before: BEFORE,
    after: AFTER,
};

/// Whether the quadratic records of `grid` (record interval dt, components first..first +
/// count) in segments `segments` can be made at the coarse interval 2 dt: N and B even (the
/// coarse samples are the records' even ones and keep the period N dt), the band's
/// components distinct modulo N/2, its width W with W 2 dt <= [`MAX_BAND_PHASE`], and the
/// block's transform long enough for the coarse halos.
pub fn admits(grid: &FrequencyGrid, segments: Segments) -> bool {
    let (n, b) = (grid.len, segments.block);
    let width = (grid.count.max(1) - 1) as f64 * grid.d_omega;
    n.is_multiple_of(STEP)
        && b.is_multiple_of(STEP)
        && grid.count <= n / STEP
        && width * STEP as f64 * grid.dt <= MAX_BAND_PHASE
        && n / STEP >= b / STEP + AFTER
        && n / STEP >= b / STEP + (HALO_AFTER + segments.ramp).div_ceil(STEP)
}

/// Refines a segment's coarse samples (on [`SAMPLING`]) in `samples` to the record's
/// `record_len` = B + H + 1 samples from global sample kB - 1: the even global samples
/// copied, the odd ones interpolated (module doc), by the widest instruction set the CPU
/// runs (the same bits on every one: [`Isa`]). An empty record (zero) stays empty.
/// The refined samples are written once into `spare` (no zero fill, no growth of the
/// coarse buffer), which then swaps with `samples`: `spare` is left with the coarse
/// buffer, or a new one of the refined length if that was shorter, so the buffers a
/// stream's segments pass round allocate nothing after the first segment.
pub fn refine(samples: &mut Vec<f64>, record_len: usize, spare: &mut Vec<f64>) {
    refine_on(Isa::detect(), samples, record_len, spare);
}

/// [`refine`] on the instruction set `isa` (one the CPU runs).
fn refine_on(isa: Isa, samples: &mut Vec<f64>, record_len: usize, spare: &mut Vec<f64>) {
    if samples.is_empty() {
        return;
    }
    let coarse_len = samples.len();
    debug_assert_eq!(
        coarse_len,
        (record_len - HALO_BEFORE - HALO_AFTER) / STEP + BEFORE + AFTER
    );
    // Record sample 2i is global kB + 2i - 1, between coarse i + 3 and i + 4; record sample
    // 2i + 1 is global kB + 2i, coarse i + 4: pair i is the window of coarse i .. i + 8.
    let pairs = record_len.div_ceil(2);
    // A spare shorter than the refined record is replaced, not grown (growing copies it):
    // before the samples are written (the first call) and after the swap (a coarse buffer
    // new in this segment), so that the segments after the first find one long enough.
    let hold_refined = |spare: &mut Vec<f64>| {
        if spare.capacity() < 2 * pairs {
            *spare = Vec::with_capacity(2 * pairs);
        }
    };
    spare.clear();
    hold_refined(spare);
    // Every pair's window is coarse (the slice checks it).
    let nodes = &samples[..pairs + TAPS - 1];
    let out = &mut spare.spare_capacity_mut()[..2 * pairs];
    match isa {
        Isa::Baseline => write_pairs(nodes, out),
        #[cfg(target_arch = "x86_64")]
        // SAFETY: `Isa::Avx2` is only made where the CPU reports AVX2 (`Isa::detect`,
        // `Isa::available`).
        Isa::Avx2 => unsafe { write_pairs_avx2(nodes, out) },
    }
    // SAFETY: `write_pairs` wrote every one of the 2 * pairs elements, the length set here.
    unsafe { spare.set_len(2 * pairs) };
    spare.truncate(record_len);
    std::mem::swap(samples, spare);
    hold_refined(spare);
}

/// Writes pair i of the refined record, the midpoint of window i of `nodes` and node
/// i + 4, into elements 2i and 2i + 1 of `out` (every element: `out` holds as many pairs
/// as `nodes` has windows of [`TAPS`]).
#[inline(always)]
fn write_pairs(nodes: &[f64], out: &mut [MaybeUninit<f64>]) {
    debug_assert_eq!(out.len(), 2 * (nodes.len() + 1 - TAPS));
    for (i, pair) in out.chunks_exact_mut(2).enumerate() {
        pair[0] = MaybeUninit::new(midpoint(nodes, i));
        pair[1] = MaybeUninit::new(nodes[i + 4]);
    }
}

/// [`write_pairs`] compiled for AVX2 (four midpoints a register; the additions and
/// products of [`midpoint`] in its order, never contracted: the same bits).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn write_pairs_avx2(nodes: &[f64], out: &mut [MaybeUninit<f64>]) {
    write_pairs(nodes, out);
}

/// The interpolated midpoint between nodes i + 3 and i + 4 of `x` (the stencil on nodes
/// i .. i + 7, its symmetric pairs first).
#[inline(always)]
fn midpoint(x: &[f64], i: usize) -> f64 {
    let [a, b, c, d, e, f, g, h]: [f64; TAPS] = x[i..i + TAPS].try_into().expect("8 taps");
    let [w1, w2, w3, w4] = WEIGHTS;
    w1 * (d + e) + w2 * (c + f) + w3 * (b + g) + w4 * (a + h)
}

/// The relative error of the midpoint interpolation for a tone of phase theta = mu h per
/// coarse interval (module doc).
pub fn tone_error(theta: f64) -> f64 {
    let sum: f64 = WEIGHTS
        .iter()
        .enumerate()
        .map(|(k, w)| w * ((k as f64 + 0.5) * theta).cos())
        .sum();
    (1.0 - 2.0 * sum).abs()
}

/// The rms error of the midpoint interpolation relative to the rms of the record's
/// fluctuation, for a record of difference-frequency spectrum S_F(mu) = sum_n P_n P_{n+k}
/// (the products of the components' expected powers `power` at distance k on a grid of
/// spacing `d_omega`: Newman's force for a drift coefficient flat across the band), at the
/// coarse interval `h`. The powers are binned into 256 bands of the grid first (the
/// estimate's resolution).
pub fn midpoint_error(power: &[f64], d_omega: f64, h: f64) -> f64 {
    const BINS: usize = 256;
    let per_bin = power.len().div_ceil(BINS).max(1);
    let binned: Vec<f64> = power.chunks(per_bin).map(|c| c.iter().sum()).collect();
    let bin_width = per_bin as f64 * d_omega;
    let (mut total, mut error) = (0.0, 0.0);
    for k in 1..binned.len() {
        let s: f64 = binned.iter().zip(&binned[k..]).map(|(a, b)| a * b).sum();
        total += s;
        error += s * tone_error(k as f64 * bin_width * h).powi(2);
    }
    if total > 0.0 {
        (error / total).sqrt()
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The stencil reproduces polynomials of degree 7 at the midpoints, and the even
    /// samples exactly.
    #[test]
    fn refinement_is_exact_for_degree_seven() {
        let f = |g: f64| 1e-9 * g.powi(7) - 3e-6 * g.powi(5) + 0.01 * g.powi(3) - g + 2.0;
        let block = 40;
        let record_len = HALO_BEFORE + block + HALO_AFTER;
        // Coarse l is global 2 (l - BEFORE).
        let mut out: Vec<f64> = (0..block / STEP + BEFORE + AFTER)
            .map(|l| f(STEP as f64 * (l as f64 - BEFORE as f64)))
            .collect();
        refine(&mut out, record_len, &mut Vec::new());
        assert_eq!(out.len(), record_len);
        for (r, got) in out.iter().enumerate() {
            let g = r as f64 - HALO_BEFORE as f64;
            let expected = f(g);
            assert!(
                (got - expected).abs() <= 1e-9 * expected.abs().max(1.0),
                "sample {r}: {got} vs {expected}"
            );
            if r % 2 == 1 {
                assert_eq!(*got, expected, "even global samples are copied");
            }
        }
    }

    /// Every instruction set the CPU runs refines to the baseline's bits (a record of
    /// irregular samples, over a thousand pairs), and into a spare that held another
    /// record.
    #[test]
    fn every_instruction_set_refines_to_the_same_bits() {
        let block = 2000;
        let record_len = HALO_BEFORE + block + HALO_AFTER;
        let coarse: Vec<f64> = (0..block / STEP + BEFORE + AFTER)
            .map(|l| 1e5 * (0.37 * l as f64).sin() + (1.3 * l as f64).cos() / 3.0)
            .collect();
        let refined = |isa: Isa| {
            let mut samples = coarse.clone();
            let mut spare = vec![7.0; 3 * record_len];
            refine_on(isa, &mut samples, record_len, &mut spare);
            samples.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
        };
        let baseline = refined(Isa::Baseline);
        assert_eq!(baseline.len(), record_len);
        for isa in Isa::available() {
            assert_eq!(refined(isa), baseline, "{}", isa.name());
        }
    }

    /// A tone's midpoint error, by the refinement itself, against the closed form; and the
    /// closed form's leading term theta^8 (7!!)^2 / (2^8 8!) at small theta.
    #[test]
    fn a_tones_error_is_the_closed_form() {
        let block = 64;
        let record_len = HALO_BEFORE + block + HALO_AFTER;
        for theta in [0.1, 0.5, 1.0, 1.83, 2.5] {
            // The tone e^{i theta t} (t in coarse intervals, coarse l at t = l - BEFORE) as
            // its real and imaginary records.
            let refined = |part: fn(f64) -> f64| {
                let mut out: Vec<f64> = (0..block / STEP + BEFORE + AFTER)
                    .map(|l| part(theta * (l as f64 - BEFORE as f64)))
                    .collect();
                refine(&mut out, record_len, &mut Vec::new());
                out
            };
            let (re, im) = (refined(f64::cos), refined(f64::sin));
            // At every midpoint (record sample 2i, global 2i - 1) the complex error's modulus
            // is the closed form.
            for r in (0..record_len).step_by(2) {
                let t = (r as f64 - 1.0) / 2.0;
                let error = (re[r] - (theta * t).cos()).hypot(im[r] - (theta * t).sin());
                let expected = tone_error(theta);
                assert!(
                    (error - expected).abs() <= 1e-9 * expected + 1e-14,
                    "theta {theta}, sample {r}: {error} vs {expected}"
                );
            }
        }
        let leading = 0.1f64.powi(8) * (105.0f64 * 105.0) / (256.0 * 40320.0);
        assert!((tone_error(0.1) / leading - 1.0).abs() < 1e-2);
    }

    /// A band-limited record's estimated error grows with the interval, and a flat band of
    /// width W at W h = 1 lies between the tone errors of its mid and top frequencies.
    #[test]
    fn the_estimate_is_bounded_by_its_tones() {
        let power = vec![1.0; 1000];
        let d_omega = 1e-3;
        let width = 999.0 * d_omega;
        let at = |h: f64| midpoint_error(&power, d_omega, h);
        assert!(at(0.5) < at(1.0) && at(1.0) < at(2.0));
        let e = at(1.0 / width);
        assert!(e > tone_error(0.5) && e < tone_error(1.0), "{e}");
    }
}
