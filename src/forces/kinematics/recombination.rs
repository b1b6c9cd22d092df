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
//!
//! The rows are summed on the widest instruction set the CPU runs ([`Isa`]: the baseline
//! or AVX2), the same operations in the same order on each, so the same bits.

// The one unsafe call: the AVX2 build of the rows, made only where the CPU has AVX2.
#![allow(unsafe_code)]

use crate::forces::isa::Isa;
use rustfft::num_complex::Complex32;
use std::ops::Range;

/// Floats of one block of a row's strip velocities (two SSE registers, one AVX2 register).
const LANES: usize = 8;
/// Blocks the recombination sums at a time (eight SSE registers or four AVX2 ones, which
/// the compiler keeps over the terms); 4 is the most that fits beside the operands in SSE.
const BLOCKS_AT_ONCE: usize = 4;

/// How a row holds its strips' velocities.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(super) enum RowLayout {
    /// (u_x, u_y) per strip: a term's sample g = g.re + i g.im spreads as (re, im, ...).
    #[default]
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

/// What a record's rows are recombined from: its strips and their layout, the weights laid
/// out by [`lay_out_weights`], the elevation of every row (`eta[m]`) and the depth terms'
/// series g_q(m), as many samples each as `eta` has: term q at `series[q * len + m]`, or,
/// when `paired` (waves along x, where each g_q is real), terms 2p and 2p + 1 as the real
/// and imaginary parts of `series[p * len + m]`.
#[derive(Debug, Clone, Default, PartialEq)]
pub(super) struct Rows {
    pub layout: RowLayout,
    pub strips: usize,
    pub weights: Vec<f32>,
    pub eta: Vec<f32>,
    pub series: Vec<Complex32>,
    pub rank: usize,
    pub paired: bool,
}

impl Rows {
    #[inline(always)]
    fn sample(&self, q: usize, m: usize) -> Complex32 {
        let len = self.eta.len();
        if self.paired {
            let pair = self.series[q / 2 * len + m];
            Complex32::new(
                if q.is_multiple_of(2) {
                    pair.re
                } else {
                    pair.im
                },
                0.0,
            )
        } else {
            self.series[q * len + m]
        }
    }

    /// Float `f` of row m's strip velocities (after the elevation) on its own: the sum over
    /// the terms, in order, of the term's sample as the row's pattern spreads it times its
    /// weight, the operations [`append_rows`] does for that float, so the same bits.
    pub(super) fn strip_float(&self, m: usize, f: usize) -> f32 {
        let width = self.layout.width(self.strips);
        let first = f - f % (BLOCKS_AT_ONCE * LANES);
        let floats = (width - first).min(BLOCKS_AT_ONCE * LANES);
        let weights = &self.weights[first * self.rank..];
        let mut sum = 0.0f32;
        for q in 0..self.rank {
            let g = self.sample(q, m);
            let p = match self.layout {
                RowLayout::Interleaved => interleaved(g)[f % LANES],
                RowLayout::AlongX => real_part(g)[f % LANES],
            };
            sum += p * weights[q * floats + f - first];
        }
        sum
    }
}

/// Appends rows `range` of `rows` to `out`: row m is the elevation then the strips'
/// velocities recombined from the terms, without the row's padding, on the instruction set
/// `isa`: the same operations in the same order on every one, so the same bits. `samples`
/// is scratch for one sample of every term (its capacity kept: no allocation once it has
/// held `rows.rank`).
pub(super) fn append_rows(
    isa: Isa,
    rows: &Rows,
    range: Range<usize>,
    samples: &mut Vec<Complex32>,
    out: &mut Vec<f32>,
) {
    samples.clear();
    samples.resize(rows.rank, Complex32::default());
    match isa {
        Isa::Baseline => append_rows_with(rows, range, samples, out),
        #[cfg(target_arch = "x86_64")]
        // SAFETY: `Isa::Avx2` is only made where the CPU reports AVX2 (`Isa::detect`,
        // `Isa::available`).
        Isa::Avx2 => unsafe { append_rows_avx2(rows, range, samples, out) },
    }
}

/// [`append_rows_with`] compiled for AVX2 (a block of [`LANES`] floats is one register).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn append_rows_avx2(
    rows: &Rows,
    range: Range<usize>,
    samples: &mut [Complex32],
    out: &mut Vec<f32>,
) {
    append_rows_with(rows, range, samples, out)
}

#[inline(always)]
fn append_rows_with(
    rows: &Rows,
    range: Range<usize>,
    samples: &mut [Complex32],
    out: &mut Vec<f32>,
) {
    let width = rows.layout.width(rows.strips);
    let padding = width - rows.layout.per_strip() * rows.strips;
    // The rows as stored, and one row's padding written past the last before it is dropped.
    out.reserve((1 + width - padding) * range.len() + padding);
    for m in range {
        out.push(rows.eta[m]);
        for (q, g) in samples.iter_mut().enumerate() {
            *g = rows.sample(q, m);
        }
        recombine_row(rows.layout, width, &rows.weights, samples, out);
        out.truncate(out.len() - padding);
    }
}

/// Appends one row (`width` floats: [`RowLayout::width`]) to `out` from the terms'
/// `samples` and the weights laid out by [`lay_out_weights`], summed over the terms in
/// order, [`BLOCKS_AT_ONCE`] blocks of the row at a time. A basis of rank 0 (a sea without
/// power) gives a zero row.
#[inline(always)]
fn recombine_row(
    layout: RowLayout,
    width: usize,
    weights: &[f32],
    samples: &[Complex32],
    out: &mut Vec<f32>,
) {
    // Each layout its own inlined loop (the spreading is a function item).
    match layout {
        RowLayout::Interleaved => blocks(width, weights, samples, interleaved, out),
        RowLayout::AlongX => blocks(width, weights, samples, real_part, out),
    }
}

#[inline(always)]
fn blocks(
    width: usize,
    mut weights: &[f32],
    samples: &[Complex32],
    pattern: impl Fn(Complex32) -> [f32; LANES] + Copy,
    out: &mut Vec<f32>,
) {
    for first in (0..width).step_by(BLOCKS_AT_ONCE * LANES) {
        let floats = (width - first).min(BLOCKS_AT_ONCE * LANES);
        let (this, rest) = weights.split_at(samples.len() * floats);
        weights = rest;
        match floats / LANES {
            BLOCKS_AT_ONCE => recombine::<BLOCKS_AT_ONCE>(this, samples, pattern, out),
            3 => recombine::<3>(this, samples, pattern, out),
            2 => recombine::<2>(this, samples, pattern, out),
            _ => recombine::<1>(this, samples, pattern, out),
        }
    }
}

/// Appends K blocks of [`LANES`] floats to `out`: the sum over the terms q, in order, of
/// the term's sample as `pattern` spreads it over a block, times its K blocks of `weights`
/// (term-major, then block).
#[inline(always)]
fn recombine<const K: usize>(
    weights: &[f32],
    samples: &[Complex32],
    pattern: impl Fn(Complex32) -> [f32; LANES],
    out: &mut Vec<f32>,
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
    for sum in &sum {
        out.extend_from_slice(sum);
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
    /// layouts, rank 0, paired and separate terms, and the same bits on every instruction
    /// set the CPU has; each row starts with its elevation and drops its padding, and each
    /// of its floats recombined alone ([`Rows::strip_float`]) is the same bits.
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
                // Two rows: each term's sample at row m.
                let sample = |q: usize, m: usize| {
                    Complex32::new(0.5 + q as f32 - m as f32, 1.5 - 0.25 * q as f32)
                };
                let separate: Vec<Complex32> = (0..rank)
                    .flat_map(|q| (0..2).map(move |m| sample(q, m)))
                    .collect();
                // Paired: terms 2p and 2p + 1 as one series' real and imaginary parts.
                let paired: Vec<Complex32> = (0..rank.div_ceil(2))
                    .flat_map(|p| {
                        (0..2).map(move |m| {
                            let second = if 2 * p + 1 < rank {
                                sample(2 * p + 1, m).re
                            } else {
                                0.0
                            };
                            Complex32::new(sample(2 * p, m).re, second)
                        })
                    })
                    .collect();
                let eta = [3.0, -6.0];
                for layout in [RowLayout::Interleaved, RowLayout::AlongX] {
                    let along_x = layout == RowLayout::AlongX;
                    let mut laid = Vec::new();
                    lay_out_weights(layout, strips, rank, |q| &weights[q], &mut laid);
                    let rows = Rows {
                        layout,
                        strips,
                        weights: laid,
                        eta: eta.to_vec(),
                        series: if along_x { &paired } else { &separate }.clone(),
                        rank,
                        paired: along_x,
                    };
                    let per_row = 1 + layout.per_strip() * strips;
                    let mut first: Option<Vec<f32>> = None;
                    for isa in Isa::available() {
                        let mut out = vec![f32::NAN];
                        append_rows(isa, &rows, 0..2, &mut Vec::new(), &mut out);
                        assert_eq!(out.len(), 1 + 2 * per_row, "{layout:?} {strips} {rank}");
                        for m in 0..2 {
                            let row = &out[1 + m * per_row..][..per_row];
                            assert_eq!(row[0], eta[m]);
                            // Each float alone, the same bits.
                            for f in 0..per_row - 1 {
                                assert_eq!(
                                    rows.strip_float(m, f).to_bits(),
                                    row[1 + f].to_bits(),
                                    "{layout:?} {strips} {rank} row {m} float {f} {isa:?}"
                                );
                            }
                            for j in 0..strips {
                                let sum = |part: fn(&Complex32) -> f32| -> f64 {
                                    (0..rank)
                                        .map(|q| weights[q][j] * part(&sample(q, m)) as f64)
                                        .sum()
                                };
                                let bound = 1e-5 * (1.0 + rank as f64);
                                let ux = row[1 + layout.per_strip() * j];
                                assert!(
                                    (ux as f64 - sum(|g| g.re)).abs() < bound,
                                    "{layout:?} {strips} {rank} {j} {isa:?}"
                                );
                                if !along_x {
                                    let uy = row[2 + 2 * j];
                                    assert!(
                                        (uy as f64 - sum(|g| g.im)).abs() < bound,
                                        "{layout:?} {strips} {rank} {j} {isa:?}"
                                    );
                                }
                            }
                        }
                        match &first {
                            None => first = Some(out),
                            Some(first) => assert!(
                                first
                                    .iter()
                                    .zip(&out)
                                    .skip(1)
                                    .all(|(a, b)| a.to_bits() == b.to_bits()),
                                "{layout:?} {strips} {rank}: {isa:?} differs from the baseline"
                            ),
                        }
                    }
                }
            }
        }
    }
}
