//! Precomputed time records and their evaluation between samples.
//!
//! A record holds N samples at t_m = t0 + m dt. Values between samples come from 4-point
//! Lagrange (cubic) interpolation, exact at the samples and O(dt^4) accurate between them,
//! so RK4's fourth order survives any step (physics.md section 7). With the default
//! sampling dt = h/2 every RK4 stage lands on a sample and the records are used exactly.

use crate::error::{Error, Result};

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
        let mut index = position.floor() as usize;
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
#[derive(Debug, Clone, PartialEq)]
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

    /// Value at a located time.
    #[inline]
    pub fn at(&self, p: &SamplePoint) -> f64 {
        if self.samples.is_empty() {
            return 0.0;
        }
        if p.weights[1] == 1.0 {
            return self.samples[p.index];
        }
        let n = self.samples.len();
        let before = if p.index == 0 { n - 1 } else { p.index - 1 };
        p.weights[0] * self.samples[before]
            + p.weights[1] * self.samples[p.index]
            + p.weights[2] * self.samples[p.index + 1]
            + p.weights[3] * self.samples[(p.index + 2) % n]
    }
}

/// Several records on one [`RecordClock`], stored sample-major: row m holds sample m of
/// every record, so that reading all of them at one time reads one contiguous row (the
/// drag reads all of a column's strip records at every RK4 stage). Periodic like
/// [`Record`]; the same 4-point Lagrange interpolation between samples.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordBlock {
    width: usize,
    samples: Vec<f64>,
}

impl RecordBlock {
    /// The block whose row m is `samples[m * width .. (m + 1) * width]`.
    pub fn from_rows(width: usize, samples: Vec<f64>) -> Self {
        assert!(
            width > 0 && samples.len().is_multiple_of(width),
            "a block holds whole rows"
        );
        RecordBlock { width, samples }
    }

    /// Number of records.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Number of samples of each record.
    pub fn len(&self) -> usize {
        self.samples.len().checked_div(self.width).unwrap_or(0)
    }

    /// Whether the records have no samples.
    pub fn is_empty(&self) -> bool {
        self.samples.is_empty()
    }

    /// Every record at a located time.
    #[inline]
    pub fn row_at(&self, p: &SamplePoint) -> RowAt<'_> {
        let w = self.width;
        let row = |m: usize| &self.samples[m * w..(m + 1) * w];
        let n = self.len();
        let before = if p.index == 0 { n - 1 } else { p.index - 1 };
        RowAt {
            rows: [
                row(before),
                row(p.index),
                row(p.index + 1),
                row((p.index + 2) % n),
            ],
            weights: p.weights,
            on_sample: p.weights[1] == 1.0,
        }
    }
}

/// The values of a [`RecordBlock`]'s records at one located time.
#[derive(Debug, Clone, Copy)]
pub struct RowAt<'a> {
    rows: [&'a [f64]; 4],
    weights: [f64; 4],
    on_sample: bool,
}

impl<'a> RowAt<'a> {
    /// The row itself when the time falls on a sample (no interpolation needed).
    #[inline]
    pub fn on_sample(&self) -> Option<&'a [f64]> {
        self.on_sample.then_some(self.rows[1])
    }

    /// Record `j` at this time (exactly the sample on a sample time).
    #[inline]
    pub fn value(&self, j: usize) -> f64 {
        if self.on_sample {
            return self.rows[1][j];
        }
        self.weights[0] * self.rows[0][j]
            + self.weights[1] * self.rows[1][j]
            + self.weights[2] * self.rows[2][j]
            + self.weights[3] * self.rows[3][j]
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

    /// A block holds the same values as separate records, at samples and in between.
    #[test]
    fn a_block_equals_its_records() {
        let c = clock(16);
        let records: Vec<Vec<f64>> = (0..3)
            .map(|j| {
                (0..16)
                    .map(|m| ((m * 7 + j * 3) % 11) as f64 - 4.5)
                    .collect()
            })
            .collect();
        let rows = (0..16).flat_map(|m| records.iter().map(move |r| r[m]));
        let block = RecordBlock::from_rows(3, rows.collect());
        assert_eq!((block.width(), block.len()), (3, 16));
        for t in [10.0, 10.5, 10.2, 13.75, 16.9, 16.5] {
            let p = c.locate(t).unwrap();
            let row = block.row_at(&p);
            for (j, r) in records.iter().enumerate() {
                assert_eq!(row.value(j), Record::new(r.clone()).at(&p), "t {t} j {j}");
            }
        }
    }

    #[test]
    fn times_outside_the_record_are_refused() {
        let c = clock(8);
        assert!(matches!(c.locate(9.9), Err(Error::BeyondRecord { .. })));
        assert!(matches!(c.locate(13.1), Err(Error::BeyondRecord { .. })));
        assert!(c.locate(13.0).is_ok());
    }
}
