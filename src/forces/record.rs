//! Precomputed time records and their evaluation between samples.
//!
//! A record holds N samples at t_m = t0 + m dt. Values between samples come from 4-point
//! Lagrange (cubic) interpolation, exact at the samples and O(dt^4) accurate between them,
//! so RK4's fourth order survives any step (docs/theory.md#equations-of-motion). With the default
//! sampling dt = h/2 every RK4 stage lands on a sample and the records are used exactly.

use crate::error::{Error, Result};
use std::ops::{Add, Mul};

/// Where a time falls in the records: the sample index below it and the 4 stencil weights
/// for samples index-1 .. index+2. Computed once per RK4 stage, used by every record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SamplePoint {
    index: usize,
    weights: [f64; 4],
}

/// The shared time axis of all records.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RecordClock {
    pub start_time: f64,
    pub dt: f64,
    pub len: usize,
}

impl RecordClock {
    /// Locates time `t`; an error past the last sample that has a full stencil.
    pub fn locate(&self, t: f64) -> Result<SamplePoint> {
        let position = (t - self.start_time) / self.dt;
        let last = (self.len - 2) as f64;
        if !(position >= 0.0 && position <= last * (1.0 + 1e-12)) {
            return Err(Error::BeyondRecord {
                time: t,
                record_end: self.start_time + last * self.dt,
            });
        }
        // position >= 0 (above): the cast's truncation is the floor, without libm's call.
        let mut index = position as usize;
        let mut s = position - index as f64;
        // A stage time computed as t0 + n h may sit a rounding error away from its sample.
        if s > 1.0 - 1e-9 {
            index += 1;
            s = 0.0;
        } else if s < 1e-9 {
            s = 0.0;
        }
        let index = index.min(self.len - 2);
        Ok(SamplePoint {
            index,
            weights: lagrange_weights(s),
        })
    }
}

impl RecordClock {
    /// The sample at or below time `t`, without [`RecordClock::locate`]'s checks: 0 before
    /// the first sample, past the last when `t` is.
    pub fn sample_at_or_below(&self, t: f64) -> usize {
        // The cast truncates toward zero and saturates: the floor of a non-negative
        // position, 0 below the first sample (and for NaN), without libm's floor.
        ((t - self.start_time) / self.dt) as usize
    }
}

impl SamplePoint {
    /// Whether the time falls on a sample (the records are then read, not interpolated).
    #[inline]
    pub fn on_sample(&self) -> bool {
        self.weights[1] == 1.0
    }

    /// The sample at or below this time.
    #[inline]
    pub fn index(&self) -> usize {
        self.index
    }

    /// The value at this time of a periodic record of any real or complex samples on the
    /// clock: the sample itself, or the 4-point Lagrange interpolation, wrapping at sample 0.
    #[inline]
    pub fn interpolate<T>(&self, samples: &[T]) -> T
    where
        T: Copy + Mul<f64, Output = T> + Add<Output = T>,
    {
        self.interpolate_with(samples.len(), |m| samples[m])
    }

    /// [`SamplePoint::interpolate`] for a record of `len` samples read by `sample(m)`.
    #[inline(always)]
    pub fn interpolate_with<T>(&self, len: usize, sample: impl Fn(usize) -> T) -> T
    where
        T: Copy + Mul<f64, Output = T> + Add<Output = T>,
    {
        let m = self.index;
        if self.on_sample() {
            return sample(m);
        }
        let before = if m == 0 { len - 1 } else { m - 1 };
        let after = if m + 2 == len { 0 } else { m + 2 };
        let w = &self.weights;
        sample(before) * w[0] + sample(m) * w[1] + sample(m + 1) * w[2] + sample(after) * w[3]
    }
}

/// Cubic Lagrange weights for nodes -1, 0, 1, 2 at fraction s in [0, 1).
fn lagrange_weights(s: f64) -> [f64; 4] {
    if s == 0.0 {
        return [0.0, 1.0, 0.0, 0.0];
    }
    [
        -s * (s - 1.0) * (s - 2.0) / 6.0,
        (s + 1.0) * (s - 1.0) * (s - 2.0) / 2.0,
        -(s + 1.0) * s * (s - 2.0) / 2.0,
        (s + 1.0) * s * (s - 1.0) / 6.0,
    ]
}

/// A sampled real record on a [`RecordClock`]. The samples come from an FFT and are
/// periodic with period N dt, so the stencil wraps at sample 0.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Record {
    samples: Vec<f64>,
}

impl Record {
    /// Wraps samples at the clock's spacing.
    pub fn new(samples: Vec<f64>) -> Self {
        Record { samples }
    }

    /// A record that is zero everywhere (kept as an empty vector: no memory, no work).
    pub fn zero() -> Self {
        Record {
            samples: Vec::new(),
        }
    }

    /// The samples (empty for a zero record).
    pub fn samples(&self) -> &[f64] {
        &self.samples
    }

    /// The samples' buffer, to be written again (a stream's next segment).
    pub fn into_samples(self) -> Vec<f64> {
        self.samples
    }

    /// Asks the CPU to bring sample `m` into its caches (nothing past the end): a hint,
    /// which changes no result.
    #[inline]
    pub fn prefetch(&self, m: usize) {
        super::prefetch::prefetch(&self.samples, m);
    }

    /// Value at a located time.
    #[inline(always)]
    pub fn at(&self, p: &SamplePoint) -> f64 {
        if self.samples.is_empty() {
            return 0.0;
        }
        p.interpolate(&self.samples)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn clock(len: usize) -> RecordClock {
        RecordClock {
            start_time: 10.0,
            dt: 0.5,
            len,
        }
    }

    #[test]
    fn cubic_interpolation_is_exact_for_cubics() {
        let c = clock(40);
        let f = |t: f64| 0.3 * t.powi(3) - 2.0 * t * t + t - 5.0;
        let record = Record::new((0..40).map(|m| f(10.0 + 0.5 * m as f64)).collect());
        for t in [10.7, 13.01, 20.25, 28.9] {
            let got = record.at(&c.locate(t).unwrap());
            assert!((got - f(t)).abs() < 1e-9 * f(t).abs().max(1.0), "t = {t}");
        }
    }

    #[test]
    fn samples_are_returned_exactly() {
        let c = clock(8);
        let record = Record::new(vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
        assert_eq!(record.at(&c.locate(10.0 + 3.0 * 0.5).unwrap()), 4.0);
        assert_eq!(record.at(&c.locate(10.0).unwrap()), 1.0);
    }

    #[test]
    fn times_outside_the_record_are_refused() {
        let c = clock(8);
        assert!(matches!(c.locate(9.9), Err(Error::BeyondRecord { .. })));
        assert!(matches!(c.locate(13.1), Err(Error::BeyondRecord { .. })));
        assert!(c.locate(13.0).is_ok());
    }
}
