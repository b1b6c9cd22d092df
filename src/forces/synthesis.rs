//! Sums of wave components at every sample by one inverse FFT (E&S 6; docs/theory.md#random-waves).
//!
//! Convention: `series(first, c)[m] = sum_j c_j e^{i omega_{first+j} m dt}`
//! = sum_j c_j e^{2 pi i (first + j) m / N}: RustFFT's inverse transform, unnormalised.
//!
//! A synthesizer with a [`Join`] writes the series of one segment of a stream instead of the
//! N samples of one record (`forces::stream`): its output is the joined series of the
//! segment's record length ([`Synthesizer::output_len`]).

use super::super::sea_state::FrequencyGrid;
use super::stream::Join;
use rustfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// A planned inverse FFT (its twiddle factors cost about three transforms to compute),
/// shareable between threads and reusable by every build on the same grid.
pub type InverseFft = Arc<dyn Fft<f64>>;

/// Plans the inverse FFT of the grid's record length.
pub fn plan_inverse_fft(grid: &FrequencyGrid) -> InverseFft {
    FftPlanner::new().plan_fft_inverse(grid.len)
}

/// An inverse FFT for the record length, with its scratch space, and optionally the join
/// of a stream's segments.
#[derive(Clone)]
pub struct Synthesizer {
    fft: InverseFft,
    scratch: Vec<Complex64>,
    first: usize,
    count: usize,
    /// The stream's join, and the block's full transform before it is joined.
    join: Option<(Join, Vec<Complex64>)>,
    /// The transform of [`Synthesizer::append_two_real_series`] and
    /// [`Synthesizer::complex_series_into`] without a join.
    pair_block: Vec<Complex64>,
}

impl Synthesizer {
    /// Plans the transform for the grid's record length.
    pub fn new(grid: &FrequencyGrid) -> Self {
        Self::with_fft(grid, plan_inverse_fft(grid))
    }

    /// Uses a transform already planned for the grid's record length.
    pub fn with_fft(grid: &FrequencyGrid, fft: InverseFft) -> Self {
        debug_assert_eq!(fft.len(), grid.len);
        Self::subsampled(grid, fft)
    }

    /// The series at every second sample by a transform of M = N/2 points: sum_j c_j
    /// e^{i omega_j t} at t = 2 m dt is sum_j c_j e^{2 pi i (first + j) m / M}, and the band
    /// lies below the grid's Nyquist index N/2 = M ([`FrequencyGrid::new`]), so the
    /// coefficients keep their indices (`forces::refine`). Complex series only.
    pub fn every_second_sample(grid: &FrequencyGrid, fft: InverseFft) -> Self {
        debug_assert!(fft.len() * 2 == grid.len && grid.first + grid.count <= fft.len());
        Self::subsampled(grid, fft)
    }

    fn subsampled(grid: &FrequencyGrid, fft: InverseFft) -> Self {
        Synthesizer {
            first: grid.first,
            fft,
            scratch: Vec::new(),
            count: grid.count,
            join: None,
            pair_block: Vec::new(),
        }
    }

    /// The same transform writing the joined series of a stream's segments (`join`
    /// chooses the segment: [`Synthesizer::join_mut`]).
    pub fn with_join(mut self, join: Join) -> Self {
        self.join = Some((join, Vec::new()));
        self
    }

    /// Sizes the transform's scratch on first use, so that a plan's synthesizer (cloned
    /// into each simulation) carries no buffers (nor does its joined block, sized by its
    /// first transform).
    fn size_scratch(&mut self) {
        let scratch = self.fft.get_inplace_scratch_len();
        if self.scratch.len() < scratch {
            self.scratch.resize(scratch, Complex64::default());
        }
    }

    /// The join of the segments, when this synthesizer writes a stream.
    pub fn join_mut(&mut self) -> Option<&mut Join> {
        self.join.as_mut().map(|(join, _)| join)
    }

    /// The join of the segments, when this synthesizer writes a stream.
    pub fn join(&self) -> Option<&Join> {
        self.join.as_ref().map(|(join, _)| join)
    }

    /// Samples of every series written: N, or a segment's record length when joined.
    pub fn output_len(&self) -> usize {
        match &self.join {
            Some((join, _)) => join.len(),
            None => self.fft.len(),
        }
    }

    /// Complex series of the band's components: writes sum_j c_j e^{i omega_j t_m} into
    /// `out` ([`Synthesizer::output_len`] samples) for every sample m.
    pub fn complex_series(&mut self, coefficients: &[Complex64], out: &mut [Complex64]) {
        debug_assert_eq!(coefficients.len(), self.count);
        match &mut self.join {
            None => {
                self.size_scratch();
                transform(&self.fft, &mut self.scratch, self.first, coefficients, out);
            }
            Some(_) => self.complex_series_into(coefficients, &mut Fill(out)),
        }
    }

    /// [`Synthesizer::complex_series`] given to `sink` sample by sample, in order
    /// ([`Synthesizer::output_len`] samples), instead of written into a series: a record
    /// made from the series (a squared modulus) takes the joined samples as they are made.
    pub fn complex_series_into(
        &mut self,
        coefficients: &[Complex64],
        sink: &mut impl Extend<Complex64>,
    ) {
        debug_assert_eq!(coefficients.len(), self.count);
        self.size_scratch();
        let (join, block) = match &mut self.join {
            Some((join, block)) => (Some(join), block),
            None => (None, &mut self.pair_block),
        };
        // Every sample is written by the transform: the zeros are only its size.
        block.resize(self.fft.len(), Complex64::default());
        transform(
            &self.fft,
            &mut self.scratch,
            self.first,
            coefficients,
            block,
        );
        match join {
            Some(join) => join.series(block, sink),
            None => sink.extend(block.iter().copied()),
        }
    }

    /// Two real series in one transform, appended to `out` as [`Synthesizer::output_len`]
    /// more samples:
    /// x_m + i y_m with x_m = Re sum_j cx_j e^{i omega_j t_m} and
    /// y_m = Re sum_j cy_j e^{i omega_j t_m}. Uses the Hermitian pairs n and N - n, so the
    /// band must lie below the Nyquist index (guaranteed by [`FrequencyGrid::new`]). Every
    /// input sample is written once: the band's pairs and the zeros around them. `out` is
    /// any sink (the drag kinematics narrow the samples as they take them); the transform
    /// runs in the synthesizer's own buffer, whose capacity later calls reuse.
    pub fn append_two_real_series(
        &mut self,
        cx: &[Complex64],
        cy: &[Complex64],
        out: &mut impl Extend<Complex64>,
    ) {
        debug_assert!(
            self.first + self.count <= self.fft.len() / 2,
            "below the Nyquist index"
        );
        self.size_scratch();
        let (join, block) = match &mut self.join {
            Some((join, block)) => (Some(join), block),
            None => (None, &mut self.pair_block),
        };
        block.clear();
        pair_transform(&self.fft, &mut self.scratch, self.first, cx, cy, block);
        match join {
            Some(join) => join.series(block, out),
            None => out.extend(block.iter().copied()),
        }
    }
}

/// A sink that writes into a slice from its start, in order.
struct Fill<'a>(&'a mut [Complex64]);

impl Extend<Complex64> for Fill<'_> {
    fn extend<I: IntoIterator<Item = Complex64>>(&mut self, values: I) {
        let rest = std::mem::take(&mut self.0);
        let mut written = 0;
        for (slot, value) in rest.iter_mut().zip(values) {
            *slot = value;
            written += 1;
        }
        self.0 = &mut rest[written..];
    }
}

/// The inverse transform of the band's coefficients placed from index `first` (zeros
/// elsewhere), into `out` (the transform's length).
fn transform(
    fft: &InverseFft,
    scratch: &mut [Complex64],
    first: usize,
    coefficients: &[Complex64],
    out: &mut [Complex64],
) {
    let count = coefficients.len();
    let (below, rest) = out.split_at_mut(first);
    let (band, above) = rest.split_at_mut(count);
    below.fill(Complex64::default());
    band.copy_from_slice(coefficients);
    above.fill(Complex64::default());
    fft.process_with_scratch(out, scratch);
}

/// The two-real-series transform of [`Synthesizer::append_two_real_series`], appended to
/// `out`.
fn pair_transform(
    fft: &InverseFft,
    scratch: &mut [Complex64],
    first: usize,
    cx: &[Complex64],
    cy: &[Complex64],
    out: &mut Vec<Complex64>,
) {
    let count = cx.len();
    debug_assert_eq!(cy.len(), count);
    let (n, start) = (fft.len(), out.len());
    let zeros = |count: usize| std::iter::repeat_n(Complex64::default(), count);
    let i = Complex64::new(0.0, 1.0);
    let pairs = cx.iter().zip(cy);
    // Index k = first + j holds (cx_j + i cy_j) / 2, index N - k the conjugates' pair;
    // the second run goes up in index, so down in j.
    out.extend(zeros(first));
    out.extend(pairs.clone().map(|(x, y)| 0.5 * (x + i * y)));
    out.extend(zeros(n + 1 - 2 * (first + count)));
    out.extend(pairs.rev().map(|(x, y)| 0.5 * (x.conj() + i * y.conj())));
    out.extend(zeros(first - 1));
    debug_assert_eq!(out.len(), start + n);
    fft.process_with_scratch(&mut out[start..], scratch);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The series at every second sample equals the direct sum over the components there,
    /// and the full transform's samples, up to a band that reaches the Nyquist index.
    #[test]
    fn every_second_sample_is_the_direct_sum() {
        let dt = 0.5;
        for band in [(0.4, 1.9), (0.0, 6.0)] {
            let grid = FrequencyGrid::new(0.0, 40.0, dt, band).unwrap();
            let n = grid.len;
            assert!(n.is_multiple_of(2), "{n}");
            let c: Vec<Complex64> = (0..grid.count)
                .map(|j| Complex64::new((j as f64 * 0.7).sin(), 1.0 / (1.0 + j as f64)))
                .collect();
            let half = FftPlanner::new().plan_fft_inverse(n / 2);
            let mut coarse = vec![Complex64::default(); n / 2];
            Synthesizer::every_second_sample(&grid, half).complex_series(&c, &mut coarse);
            let mut fine = vec![Complex64::default(); n];
            Synthesizer::new(&grid).complex_series(&c, &mut fine);
            for (i, got) in coarse.iter().enumerate() {
                let t = (2 * i) as f64 * dt;
                let direct: Complex64 = c
                    .iter()
                    .enumerate()
                    .map(|(j, c)| c * Complex64::from_polar(1.0, grid.omega(j) * t))
                    .sum();
                assert!((got - direct).norm() < 1e-12 * c.len() as f64, "{i}");
                assert!((got - fine[2 * i]).norm() < 1e-12 * c.len() as f64, "{i}");
            }
        }
    }
}
