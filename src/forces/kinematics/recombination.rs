//! The recombination kernel of the kinematics records: one row's strip velocities
//! u_j(m) = sum_q V_jq g_q(m) from the depth terms' samples g_q(m) and the depth kernel's
//! weights V_jq ([`DepthBasis`](crate::forces::depth_basis::DepthBasis)), in single
//! precision, register-blocked. No physics here: the weights and the samples come from
//! the kinematics module, which says what they are.
//!
//! Layout. A row is a run of floats, interleaved (u_x, u_y) per strip (or u_x alone in
//! waves along x, where u_y = 0), padded with zeros to whole blocks of [`LANES`] floats
//! (the records store it after the elevation, without the padding).
//! The weights ([`lay_out_weights`]) are stored in chunks of [`BLOCKS_AT_ONCE`] blocks,
//! each chunk term-major, then block, as [`recombine_row`] reads them; each weight twice in
//! an interleaved row (for u_x and u_y), once along x.

use rustfft::num_complex::Complex32;

/// Floats of one block of a row's strip velocities (two SSE registers).
const LANES: usize = 8;
/// Blocks the recombination sums at a time (eight SSE registers, which the compiler keeps
/// over the terms); 4 is the most that fits beside the operands.
const BLOCKS_AT_ONCE: usize = 4;

/// How a row holds its strips' velocities.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum RowLayout {
    /// (u_x, u_y) per strip: a term's sample g = g.re + i g.im spreads as (re, im, ...).
    Interleaved,
    /// u_x alone per strip (waves along x): a term's sample spreads as (re, re, ...).
    AlongX,
}

impl RowLayout {
    /// Floats per strip.
    pub(super) fn per_strip(self) -> usize {
        match self {
            RowLayout::Interleaved => 2,
            RowLayout::AlongX => 1,
        }
    }

    /// Floats of a row of `strips` strips, padded to whole blocks.
    pub(super) fn width(self, strips: usize) -> usize {
        LANES * (self.per_strip() * strips).div_ceil(LANES)
    }
}

/// Lays out the weights V_jq (`weights(q)[j]`, terms q < `rank`) of `strips` strips for
/// [`recombine_row`] into `out` (cleared first), in single precision.
pub(super) fn lay_out_weights<'a>(
    layout: RowLayout,
    strips: usize,
    rank: usize,
    weights: impl Fn(usize) -> &'a [f64],
    out: &mut Vec<f32>,
) {
    let per_strip = layout.per_strip();
    let width = layout.width(strips);
    out.clear();
    for first in (0..width).step_by(BLOCKS_AT_ONCE * LANES) {
        let floats = first..(first + BLOCKS_AT_ONCE * LANES).min(width);
        for q in 0..rank {
            let v = weights(q);
            let repeated = floats
                .clone()
                .map(|i| v.get(i / per_strip).map_or(0.0, |&v| v as f32));
            out.extend(repeated);
        }
    }
}

/// One row (`row`: [`RowLayout::width`] floats) from the terms' `samples` and the weights
/// laid out by [`lay_out_weights`], summed over the terms in order, [`BLOCKS_AT_ONCE`]
/// blocks of the row at a time. A basis of rank 0 (a sea without power) leaves the row
/// zero.
#[inline(always)]
pub(super) fn recombine_row(
    layout: RowLayout,
    weights: &[f32],
    samples: &[Complex32],
    row: &mut [f32],
) {
    // Each layout its own inlined loop (the spreading is a function item).
    match layout {
        RowLayout::Interleaved => blocks(weights, samples, interleaved, row),
        RowLayout::AlongX => blocks(weights, samples, real_part, row),
    }
}

#[inline(always)]
fn blocks(
    mut weights: &[f32],
    samples: &[Complex32],
    pattern: impl Fn(Complex32) -> [f32; LANES] + Copy,
    row: &mut [f32],
) {
    for out in row.chunks_mut(BLOCKS_AT_ONCE * LANES) {
        let (this, rest) = weights.split_at(samples.len() * out.len());
        weights = rest;
        match out.len() / LANES {
            BLOCKS_AT_ONCE => recombine::<BLOCKS_AT_ONCE>(this, samples, pattern, out),
            3 => recombine::<3>(this, samples, pattern, out),
            2 => recombine::<2>(this, samples, pattern, out),
            _ => recombine::<1>(this, samples, pattern, out),
        }
    }
}

/// `out` (K blocks of [`LANES`] floats) = sum over the terms q, in order, of the term's
/// sample as `pattern` spreads it over a block, times its K blocks of `weights`
/// (term-major, then block).
#[inline(always)]
fn recombine<const K: usize>(
    weights: &[f32],
    samples: &[Complex32],
    pattern: impl Fn(Complex32) -> [f32; LANES],
    out: &mut [f32],
) {
    let mut sum = [[0.0f32; LANES]; K];
    for (weights, &g) in weights.chunks_exact(K * LANES).zip(samples) {
        let pattern = pattern(g);
        for (sum, weights) in sum.iter_mut().zip(weights.chunks_exact(LANES)) {
            for ((s, &v), &p) in sum.iter_mut().zip(weights).zip(&pattern) {
                *s += p * v;
            }
        }
    }
    // Block by block: a copy of a known length, kept inline.
    for (out, sum) in out.chunks_exact_mut(LANES).zip(&sum) {
        out.copy_from_slice(sum);
    }
}

/// A sample over a block of interleaved (u_x, u_y) floats: (re, im, re, im, ...).
#[inline(always)]
fn interleaved(g: Complex32) -> [f32; LANES] {
    std::array::from_fn(|i| if i % 2 == 0 { g.re } else { g.im })
}

/// A sample over a block of u_x floats (waves along x): (re, re, ...).
#[inline(always)]
fn real_part(g: Complex32) -> [f32; LANES] {
    [g.re; LANES]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The blocked kernel against the plain double sum u_j = sum_q V_jq g_q, strip by
    /// strip, for every number of blocks (1 to 4 per chunk and more than one chunk), both
    /// layouts and rank 0.
    #[test]
    fn the_blocked_sum_is_the_plain_sum() {
        for strips in [1, 3, 4, 5, 8, 12, 16, 17, 20, 33] {
            for rank in [0, 1, 4, 7] {
                let weights: Vec<Vec<f64>> = (0..rank)
                    .map(|q| {
                        (0..strips)
                            .map(|j| ((q * 7 + j * 3) % 11) as f64 / 4.0 - 1.0)
                            .collect()
                    })
                    .collect();
                let samples: Vec<Complex32> = (0..rank)
                    .map(|q| Complex32::new(0.5 + q as f32, 1.5 - 0.25 * q as f32))
                    .collect();
                for layout in [RowLayout::Interleaved, RowLayout::AlongX] {
                    let mut laid = Vec::new();
                    lay_out_weights(layout, strips, rank, |q| &weights[q], &mut laid);
                    let mut row = vec![f32::NAN; layout.width(strips)];
                    recombine_row(layout, &laid, &samples, &mut row);
                    for j in 0..strips {
                        let sum = |part: fn(&Complex32) -> f32| -> f64 {
                            (0..rank)
                                .map(|q| weights[q][j] * part(&samples[q]) as f64)
                                .sum()
                        };
                        let (ux, uy) = match layout {
                            RowLayout::Interleaved => (row[2 * j], Some(row[2 * j + 1])),
                            RowLayout::AlongX => (row[j], None),
                        };
                        let bound = 1e-5 * (1.0 + rank as f64);
                        assert!(
                            (ux as f64 - sum(|g| g.re)).abs() < bound,
                            "{layout:?} {strips} {rank} {j}"
                        );
                        if let Some(uy) = uy {
                            assert!(
                                (uy as f64 - sum(|g| g.im)).abs() < bound,
                                "{layout:?} {strips} {rank} {j}"
                            );
                        }
                    }
                    // The padding is zero.
                    let used = strips * if layout == RowLayout::AlongX { 1 } else { 2 };
                    assert!(
                        row[used..].iter().all(|&u| u == 0.0),
                        "{layout:?} {strips} {rank}"
                    );
                }
            }
        }
    }
}
