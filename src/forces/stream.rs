//! Records as a stream of segments, for runs of any length at constant memory.
//!
//! The sea is synthesised block by block: block k has its own random amplitudes (from
//! `(seed, k)`, `WaveComponents::generate_block`) on the one frequency grid, and its linear
//! signals x_k(t) (the elevation, the factor series of Newman's approximation and of the full
//! QTF, the cross-direction series, the drag kinematics) come from one inverse FFT each of
//! the grid's length N >= B + H + R. Segment k holds the records of the global samples
//! m in [kB, (k+1)B) (B samples), with a halo of one sample before and H after, so that the
//! 4-point stencil of any time in [kB dt, (k+1)B dt] and an RK4 step that starts in the
//! segment stay inside it. Consecutive blocks are joined on the linear signals by a
//! power-complementary cross-fade, inside segment k:
//!
//! ```text
//! m in [kB - 1, kB + H)            x_{k-1}(m)
//! m in [kB + H, kB + H + R)        c_j x_{k-1}(m) + s_j x_k(m),  j = m - kB - H,
//!                                  c_j = cos(phi_j), s_j = sin(phi_j), phi_j = pi/2 (j + 1)/(R + 1)
//! m in [kB + H + R, (k+1)B + H)    x_k(m)
//! ```
//!
//! c_j^2 + s_j^2 = 1, and x_{k-1}, x_k are independent with the same statistics, so the
//! joined signal has the exact variance (and, Gaussian, the exact one-point distribution) at
//! every instant. Every quadratic record (Newman's |P|^2 and Re[Q eta*], the full QTF's
//! sum s_r |U_r|^2, the cross terms) is then formed from the joined linear signals, so it
//! keeps its product form; no quadratic record is cross-faded. Segment 0 has no
//! predecessor: x_0 throughout. The join reduces the correlation of the linear signals
//! across a ramp at lag tau by cos(pi/2 tau / (R dt)) at most, only within the ramp (R of
//! every B samples).
//!
//! A block's signal at global sample m is the FFT output at index m - kB (the block's time
//! origin is its segment's start). The samples x_k(m) for m in [(k+1)B - 1, (k+1)B + H + R)
//! are the *tail* that the next segment joins with; [`Join`] keeps them, one per linear
//! series, in the order the builders ask for the series (the same for every segment of a
//! simulation). Segment k thus depends on blocks k - 1 and k only: it can be rebuilt at
//! any time, bit for bit.

use super::record::RecordClock;
use crate::sea_state::FrequencyGrid;
use rustfft::num_complex::{Complex32, Complex64};
use std::f64::consts::FRAC_PI_2;

/// Samples of the halo after a segment: an RK4 step that starts on the segment's last
/// sample reaches two samples past it, and the stencil one more.
pub const HALO_AFTER: usize = 4;
/// Samples of the halo before a segment (the stencil's first node).
pub const HALO_BEFORE: usize = 1;

/// The lengths of a stream, in samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Segments {
    /// Samples per segment (and per block), B.
    pub block: usize,
    /// Samples of the cross-fade, R (< B).
    pub ramp: usize,
}

impl Segments {
    /// The FFT length a grid needs for these segments: B + H + R samples of one block.
    pub fn span(&self) -> usize {
        self.block + HALO_AFTER + self.ramp
    }

    /// Samples of a segment's records (halo included).
    pub fn record_len(&self) -> usize {
        HALO_BEFORE + self.block + HALO_AFTER
    }

    /// Samples of a tail: x_k for m in [(k+1)B - 1, (k+1)B + H + R).
    pub fn tail_len(&self) -> usize {
        HALO_BEFORE + HALO_AFTER + self.ramp
    }

    /// The segment of global sample m.
    pub fn of_sample(&self, m: u64) -> u64 {
        m / self.block as u64
    }

    /// The clock of segment k's records on `grid` (sample 0 is global sample kB - 1).
    pub fn clock(&self, grid: &FrequencyGrid, k: u64) -> RecordClock {
        let first = k as f64 * self.block as f64 - HALO_BEFORE as f64;
        RecordClock {
            start_time: grid.start_time + first * grid.dt,
            dt: grid.dt,
            len: self.record_len(),
        }
    }
}

/// Which global samples a joined series holds: every `step`-th (a multiple of the block
/// B), from `before` of its own samples before the segment's start to `after` past its end.
/// The records' own clock is [`Sampling::RECORDS`]; a quadratic record made at its
/// bandwidth uses a coarser one (`forces::refine`), whose transform of N / step points
/// gives block k's signal at global samples kB + step i (the same components, so the same
/// sea: e^{i omega_n t} at those times only sees n mod N / step).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Sampling {
    pub step: usize,
    pub before: usize,
    pub after: usize,
}

impl Sampling {
    /// The records' clock: every sample, with the stencil's halos.
    pub const RECORDS: Sampling = Sampling {
        step: 1,
        before: HALO_BEFORE,
        after: HALO_AFTER,
    };
}

/// The state that joins consecutive segments: which segment is being built, the tails of the
/// previous block's linear series (in the builders' order) and the cross-fade weights.
///
/// With a [`Sampling`] of step L, output sample l of segment k is global sample
/// kB + L (l - before), and the cross-fade above is the same function of the global sample
/// m (its weight c_j, s_j at j = m - kB - H): the joined series is the records' joined
/// series at every L-th sample.
#[derive(Debug, Clone, PartialEq)]
pub struct Join {
    segments: Segments,
    sampling: Sampling,
    /// The segment being built.
    segment: u64,
    /// Whether the tails hold block `segment - 1`'s (false for segment 0, and when a
    /// segment is built only for its tails).
    joined: bool,
    /// One tail per linear series, in call order.
    tails: Vec<Vec<Complex64>>,
    /// The series asked for so far in this segment.
    calls: usize,
    /// (c_j, s_j), j = 0 .. R.
    weights: Vec<(f64, f64)>,
}

impl Join {
    /// A join for `segments` on the records' clock, before any segment is built.
    pub fn new(segments: Segments) -> Self {
        Self::with_sampling(segments, Sampling::RECORDS)
    }

    /// A join for `segments` whose series hold the samples of `sampling` (its step divides
    /// the block).
    pub fn with_sampling(segments: Segments, sampling: Sampling) -> Self {
        debug_assert!(sampling.step > 0 && segments.block.is_multiple_of(sampling.step));
        let r = segments.ramp;
        let weights = (0..r)
            .map(|j| {
                let phi = FRAC_PI_2 * (j + 1) as f64 / (r + 1) as f64;
                (phi.cos(), phi.sin())
            })
            .collect();
        Join {
            segments,
            sampling,
            segment: 0,
            joined: false,
            tails: Vec::new(),
            calls: 0,
            weights,
        }
    }

    /// The segments joined.
    pub fn segments(&self) -> Segments {
        self.segments
    }

    /// Starts building segment `k`. `after_previous`: the tails hold block k - 1's (the
    /// previous segment was the last one built); otherwise segment k is built without a
    /// predecessor (right for k = 0; for k > 0 only to make its tails for segment k + 1).
    pub fn begin(&mut self, k: u64, after_previous: bool) {
        self.segment = k;
        self.joined = after_previous && k > 0;
        self.calls = 0;
    }

    /// The segment being built.
    pub fn segment(&self) -> u64 {
        self.segment
    }

    /// The samples the joined series hold.
    pub fn sampling(&self) -> Sampling {
        self.sampling
    }

    /// Samples of a joined series (on the records' clock, the segment's record length).
    pub fn len(&self) -> usize {
        let Sampling {
            step,
            before,
            after,
        } = self.sampling;
        before + self.segments.block / step + after
    }

    /// Output samples before the cross-fade (block k - 1 alone) and before the end of the
    /// cross-fade: l < before + ceil(H / L) and l < before + ceil((H + R) / L).
    fn regions(&self) -> (usize, usize) {
        let Sampling { step, before, .. } = self.sampling;
        let ramp_end = HALO_AFTER + self.segments.ramp;
        (
            before + HALO_AFTER.div_ceil(step),
            before + ramp_end.div_ceil(step),
        )
    }

    /// Never empty (a segment has at least one sample); for clippy's `len_without_is_empty`.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The next linear series of this segment, from block k's transform `block` (index i =
    /// global sample kB + L i, periodic; single-precision samples widened as they are
    /// read, exactly): appends the joined series ([`Join::len`] samples) to `out` and keeps
    /// block k's tail for segment k + 1.
    pub fn series<T: Widen>(&mut self, block: &[T], out: &mut impl Extend<Complex64>) {
        let Sampling { step, before, .. } = self.sampling;
        let n = block.len();
        let (alone, ramp_end) = self.regions();
        let len = self.len();
        debug_assert!(n >= len - before && n >= self.segments.block / step - before + ramp_end);
        let index = self.calls;
        self.calls += 1;
        if self.tails.len() <= index {
            // The tail of block k - 1: its samples at segment k's outputs l < ramp_end.
            self.tails.push(vec![Complex64::default(); ramp_end]);
        }
        let tail = &mut self.tails[index];
        // Output l is block k's index l - before (for l < before, the transform's periodic
        // samples n - before + l). No index arithmetic per sample: shifted slices.
        let h = before;
        if self.joined {
            // [kB - L before, kB + H): the previous block alone, from its tail.
            out.extend(tail[..alone].iter().copied());
            // The ramp's weights at the global samples of outputs alone .. ramp_end:
            // j = L (l - before) - H.
            let first = step * (alone - before) - HALO_AFTER;
            let weights = self.weights[first..].iter().step_by(step);
            let pairs = weights.zip(&tail[alone..]);
            let ramp = pairs.zip(&block[alone - h..]);
            out.extend(ramp.map(|((&(c, s), &previous), &next)| previous * c + next.widen() * s));
            out.extend(block[ramp_end - h..len - h].iter().map(|&b| b.widen()));
        } else {
            out.extend(block[n - h..].iter().map(|&b| b.widen()));
            out.extend(block[..len - h].iter().map(|&b| b.widen()));
        }
        // The tail of block k: segment k + 1's outputs l < ramp_end, global samples
        // (k+1)B + L (l - before): block index B / L - before + l.
        let start = self.segments.block / step - h;
        for (t, &b) in tail.iter_mut().zip(&block[start..start + ramp_end]) {
            *t = b.widen();
        }
    }
}

/// A transform's sample as the join takes it: in double precision (exactly).
pub trait Widen: Copy {
    fn widen(self) -> Complex64;
}

impl Widen for Complex64 {
    #[inline(always)]
    fn widen(self) -> Complex64 {
        self
    }
}

impl Widen for Complex32 {
    #[inline(always)]
    fn widen(self) -> Complex64 {
        Complex64::new(f64::from(self.re), f64::from(self.im))
    }
}

/// A real series' sample (`forces::synthesis::Halves`), as a complex one of zero imaginary part.
impl Widen for f32 {
    #[inline(always)]
    fn widen(self) -> Complex64 {
        Complex64::new(f64::from(self), 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two segments joined against the formula of the module doc, sample by sample, on the
    /// records' clock and at every second sample (the cross-fade the same function of the
    /// global sample), and the weights power-complementary.
    #[test]
    fn segments_follow_the_cross_fade_formula() {
        let segments = Segments { block: 40, ramp: 8 };
        let n = 72;
        assert!(n >= segments.span() + 12);
        // Block k's signal at its index i (global sample kB + i), written out by hand.
        let x = |k: usize, i: i64| -> Complex64 {
            (1..5)
                .map(|j| {
                    let w = 2.0 * std::f64::consts::PI * j as f64 / n as f64;
                    let a = Complex64::new((j + k) as f64, (j * k) as f64 - 1.5);
                    a * Complex64::from_polar(1.0, w * i.rem_euclid(n as i64) as f64)
                })
                .sum()
        };
        let coarse = Sampling {
            step: 2,
            before: 4,
            after: 6,
        };
        for sampling in [Sampling::RECORDS, coarse] {
            let step = sampling.step;
            let mut join = Join::with_sampling(segments, sampling);
            let mut out = Vec::new();
            let (b, h, r) = (40i64, HALO_AFTER as i64, 8i64);
            for k in 0..3usize {
                // The transform of n / L points: block k at global kB + L i.
                let block: Vec<Complex64> =
                    (0..n / step).map(|i| x(k, (step * i) as i64)).collect();
                join.begin(k as u64, true);
                out.clear();
                join.series(&block, &mut out);
                assert_eq!(out.len(), sampling.before + 40 / step + sampling.after);
                for (l, got) in out.iter().enumerate() {
                    let start = k as i64 * b;
                    let m = start + (step * l) as i64 - (step * sampling.before) as i64;
                    let own = |block: usize| x(block, m - block as i64 * b);
                    let expected = if k == 0 {
                        own(0)
                    } else if m < start + h {
                        own(k - 1)
                    } else if m < start + h + r {
                        let j = m - start - h;
                        let phi = FRAC_PI_2 * (j + 1) as f64 / (r + 1) as f64;
                        own(k - 1) * phi.cos() + own(k) * phi.sin()
                    } else {
                        own(k)
                    };
                    assert!(
                        (got - expected).norm() < 1e-12,
                        "step {step}, k {k}, m {m}: {got} vs {expected}"
                    );
                }
            }
            for (c, s) in &join.weights {
                assert!((c * c + s * s - 1.0).abs() < 1e-15);
            }
        }
    }

    /// A segment rebuilt after its predecessor was built only for its tails equals the
    /// segment built in sequence.
    #[test]
    fn a_segment_rebuilt_from_its_predecessor_alone_is_the_same() {
        let segments = Segments { block: 30, ramp: 5 };
        let n = 45;
        let blocks: Vec<Vec<Complex64>> = (0..4)
            .map(|k| {
                (0..n)
                    .map(|m| {
                        Complex64::new(((m * 7 + k * 13) % 11) as f64, (m % 5) as f64 - k as f64)
                    })
                    .collect()
            })
            .collect();
        let mut in_sequence = Join::new(segments);
        let mut out = Vec::new();
        let mut third = Vec::new();
        for k in 0..4u64 {
            in_sequence.begin(k, true);
            out.clear();
            in_sequence.series(&blocks[k as usize], &mut out);
            if k == 3 {
                third = out.clone();
            }
        }
        let mut jump = Join::new(segments);
        jump.begin(2, false);
        out.clear();
        jump.series(&blocks[2], &mut out);
        jump.begin(3, true);
        out.clear();
        jump.series(&blocks[3], &mut out);
        assert_eq!(out, third);
    }
}
