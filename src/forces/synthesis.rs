//! Sums of wave components at every sample by one inverse FFT (E&S 6; docs/theory.md#random-waves).
//!
//! Convention: `series(first, c)[m] = sum_j c_j e^{i omega_{first+j} m dt}`
//! = sum_j c_j e^{2 pi i (first + j) m / N}: RustFFT's inverse transform, unnormalised.
//!
//! Precision: the transform runs in single precision (its input narrowed from the f64
//! coefficients, its output widened back), twice as fast as in double with AVX; its error,
//! 1.3e-7 of the series' rms over the samples (below the depth kernel's 1e-6) and at most
//! [`SINGLE_PRECISION_ERROR`] of it at any sample (docs/theory.md#random-waves).
//!
//! A synthesizer with a [`Join`] writes the series of one segment of a stream instead of the
//! N samples of one record (`forces::stream`): its output is the joined series of the
//! segment's record length ([`Synthesizer::output_len`]).

use super::super::sea_state::FrequencyGrid;
use super::stream::{Join, Widen};
use rustfft::num_complex::{Complex32, Complex64};
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// The transforms' error in single precision: every sample of a series is within this
/// fraction of the series' rms, sqrt(sum_j |c_j|^2), of the exact sum (the coefficients
/// narrowed to 6e-8 and the transform's rounding over its log2 N levels; at the default's
/// N = 34 020 the error's rms is 1.3e-7 of the series' and its worst sample 2.1e-6:
/// `tests::the_single_precision_transform_is_within_its_bound`). Two real series made in
/// one transform share the bound of their pair's rms.
pub const SINGLE_PRECISION_ERROR: f64 = 5e-6;

/// A planned inverse FFT in single precision (its twiddle factors cost about three
/// transforms to compute), shareable between threads and reusable by every build on the
/// same grid.
pub type InverseFft = Arc<dyn Fft<f32>>;

/// Plans the inverse FFT of the grid's record length.
pub fn plan_inverse_fft(grid: &FrequencyGrid) -> InverseFft {
    FftPlanner::new().plan_fft_inverse(grid.len)
}

/// An inverse FFT for the record length, with its scratch space, and optionally the join
/// of a stream's segments.
#[derive(Clone)]
pub struct Synthesizer {
    fft: InverseFft,
    scratch: Vec<Complex32>,
    /// The transform's input and output, in place.
    buffer: Vec<Complex32>,
    first: usize,
    count: usize,
    /// The stream's join.
    join: Option<Join>,
    /// The real series by a transform of N/2 points, when the band allows ([`Halves`]).
    halves: Option<Halves>,
}

/// A real series' N samples by one complex transform of N/2 points: its even samples
/// x_{2m} = Re sum_j c_j e^{2 pi i k_j m / (N/2)} and its odd ones x_{2m+1}, the same sum of
/// the coefficients rotated by e^{i omega_j dt} (k_j = first + j), are two real series of
/// N/2 samples, made in one transform as x_{2m} + i x_{2m+1}
/// ([`Synthesizer::append_two_real_series`]'s pairs), whose floats are then the series in
/// order. Needs N even and the band below a quarter of the samples, first + count <= N/4,
/// so that the pairs lie below the half transform's Nyquist index.
#[derive(Clone)]
pub struct Halves {
    /// The transform of N/2 points.
    fft: InverseFft,
    /// e^{i omega_j dt} = e^{2 pi i (first + j) / N} for the band's components j.
    rotation: Arc<[Complex64]>,
    /// The rotated coefficients, and the series' N samples.
    rotated: Vec<Complex64>,
    samples: Vec<f32>,
}

impl Halves {
    /// Whether `grid`'s band allows its real series by halves: N even and
    /// first + count <= N/4.
    pub fn allows(grid: &FrequencyGrid) -> bool {
        grid.len.is_multiple_of(2) && 4 * (grid.first + grid.count) <= grid.len
    }

    /// For `grid`, whose band allows them ([`Halves::allows`]), with `fft` its transform of
    /// N/2 points.
    pub fn new(grid: &FrequencyGrid, fft: InverseFft) -> Self {
        let n = grid.len;
        debug_assert!(Self::allows(grid));
        debug_assert_eq!(fft.len() * 2, n);
        Halves {
            fft,
            rotation: (grid.first..grid.first + grid.count)
                .map(|k| Complex64::from_polar(1.0, std::f64::consts::TAU * k as f64 / n as f64))
                .collect(),
            rotated: Vec::new(),
            samples: Vec::new(),
        }
    }
}

impl Synthesizer {
    /// Plans the transform for the grid's record length, and the real series' [`Halves`]
    /// where the band allows.
    pub fn new(grid: &FrequencyGrid) -> Self {
        let mut planner = FftPlanner::new();
        let synth = Self::with_fft(grid, planner.plan_fft_inverse(grid.len));
        if Halves::allows(grid) {
            synth.with_halves(Halves::new(grid, planner.plan_fft_inverse(grid.len / 2)))
        } else {
            synth
        }
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
            buffer: Vec::new(),
            count: grid.count,
            join: None,
            halves: None,
        }
    }

    /// The same transform making real series by [`Halves`] (its transform of N/2 points).
    pub fn with_halves(mut self, halves: Halves) -> Self {
        self.halves = Some(halves);
        self
    }

    /// The same transform writing the joined series of a stream's segments (`join`
    /// chooses the segment: [`Synthesizer::join_mut`]).
    pub fn with_join(mut self, join: Join) -> Self {
        self.join = Some(join);
        self
    }

    /// Sizes the transform's scratch on first use, so that a plan's synthesizer (cloned
    /// into each simulation) carries no buffers. (A stream's join reads the transform's
    /// output where it lies: no widened copy of the block.)
    fn size_scratch(&mut self) {
        let scratch = self.fft.get_inplace_scratch_len();
        if self.scratch.len() < scratch {
            self.scratch.resize(scratch, Complex32::default());
        }
    }

    /// The join of the segments, when this synthesizer writes a stream.
    pub fn join_mut(&mut self) -> Option<&mut Join> {
        self.join.as_mut()
    }

    /// The join of the segments, when this synthesizer writes a stream.
    pub fn join(&self) -> Option<&Join> {
        self.join.as_ref()
    }

    /// Samples of every series written: N, or a segment's record length when joined.
    pub fn output_len(&self) -> usize {
        match &self.join {
            Some(join) => join.len(),
            None => self.fft.len(),
        }
    }

    /// Complex series of the band's components: writes sum_j c_j e^{i omega_j t_m} into
    /// `out` ([`Synthesizer::output_len`] samples) for every sample m.
    pub fn complex_series(&mut self, coefficients: &[Complex64], out: &mut [Complex64]) {
        self.complex_series_into(coefficients, &mut Fill(out));
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
        let buffer = &mut self.buffer;
        transform(
            &self.fft,
            &mut self.scratch,
            self.first,
            coefficients,
            buffer,
        );
        self.give(sink);
    }

    /// The real series Re sum_j c_j e^{i omega_j t_m}, given to `sink` sample by sample, in
    /// order ([`Synthesizer::output_len`] samples): by [`Halves`] when the synthesizer has
    /// them, else by the complex transform of N points.
    pub fn real_series_into(&mut self, coefficients: &[Complex64], sink: &mut impl Extend<f64>) {
        debug_assert_eq!(coefficients.len(), self.count);
        let Some(halves) = &mut self.halves else {
            self.complex_series_into(coefficients, &mut RealParts(sink));
            return;
        };
        halves.rotated.clear();
        let rotated = coefficients.iter().zip(halves.rotation.iter());
        halves.rotated.extend(rotated.map(|(c, r)| c * r));
        let scratch = halves.fft.get_inplace_scratch_len();
        if self.scratch.len() < scratch {
            self.scratch.resize(scratch, Complex32::default());
        }
        pair_transform(
            &halves.fft,
            &mut self.scratch,
            self.first,
            coefficients,
            &halves.rotated,
            &mut self.buffer,
        );
        // x_{2m} + i x_{2m+1}: the floats in order are the series.
        halves.samples.clear();
        let floats = self.buffer.iter().flat_map(|z| [z.re, z.im]);
        halves.samples.extend(floats);
        let mut parts = RealParts(sink);
        match &mut self.join {
            Some(join) => join.series(&halves.samples, &mut parts),
            None => parts.extend(halves.samples.iter().map(|&x| x.widen())),
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
        pair_transform(
            &self.fft,
            &mut self.scratch,
            self.first,
            cx,
            cy,
            &mut self.buffer,
        );
        self.give(out);
    }

    /// The transform's output, widened, given to `sink`: joined when the synthesizer
    /// writes a stream, as it is otherwise.
    fn give(&mut self, sink: &mut impl Extend<Complex64>) {
        match &mut self.join {
            Some(join) => join.series(&self.buffer, sink),
            None => sink.extend(self.buffer.iter().map(|&c| c.widen())),
        }
    }
}

/// A coefficient narrowed to the transform's single precision.
#[inline]
fn narrow(c: Complex64) -> Complex32 {
    Complex32::new(c.re as f32, c.im as f32)
}

/// A sink of complex samples that gives their real parts to a sink of reals.
struct RealParts<'a, S>(&'a mut S);

impl<S: Extend<f64>> Extend<Complex64> for RealParts<'_, S> {
    fn extend<I: IntoIterator<Item = Complex64>>(&mut self, values: I) {
        self.0.extend(values.into_iter().map(|c| c.re));
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
/// elsewhere), in `buffer` (sized to the transform's length).
fn transform(
    fft: &InverseFft,
    scratch: &mut [Complex32],
    first: usize,
    coefficients: &[Complex64],
    buffer: &mut Vec<Complex32>,
) {
    let (n, count) = (fft.len(), coefficients.len());
    buffer.clear();
    buffer.resize(first, Complex32::default());
    buffer.extend(coefficients.iter().map(|&c| narrow(c)));
    buffer.resize(n, Complex32::default());
    debug_assert!(first + count <= n);
    fft.process_with_scratch(buffer, scratch);
}

/// The two-real-series transform of [`Synthesizer::append_two_real_series`], in `buffer`.
fn pair_transform(
    fft: &InverseFft,
    scratch: &mut [Complex32],
    first: usize,
    cx: &[Complex64],
    cy: &[Complex64],
    buffer: &mut Vec<Complex32>,
) {
    let count = cx.len();
    debug_assert_eq!(cy.len(), count);
    let n = fft.len();
    let zeros = |count: usize| std::iter::repeat_n(Complex32::default(), count);
    let i = Complex64::new(0.0, 1.0);
    let pairs = cx.iter().zip(cy);
    // Index k = first + j holds (cx_j + i cy_j) / 2, index N - k the conjugates' pair;
    // the second run goes up in index, so down in j.
    buffer.clear();
    buffer.extend(zeros(first));
    buffer.extend(pairs.clone().map(|(x, y)| narrow(0.5 * (x + i * y))));
    buffer.extend(zeros(n + 1 - 2 * (first + count)));
    buffer.extend(
        pairs
            .rev()
            .map(|(x, y)| narrow(0.5 * (x.conj() + i * y.conj()))),
    );
    buffer.extend(zeros(first - 1));
    debug_assert_eq!(buffer.len(), n);
    fft.process_with_scratch(buffer, scratch);
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
            let half = FftPlanner::<f32>::new().plan_fft_inverse(n / 2);
            let rms = c.iter().map(|c| c.norm_sqr()).sum::<f64>().sqrt();
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
                assert!((got - direct).norm() < SINGLE_PRECISION_ERROR * rms, "{i}");
                assert!(
                    (got - fine[2 * i]).norm() < 2.0 * SINGLE_PRECISION_ERROR * rms,
                    "{i}"
                );
            }
        }
    }

    /// The real series by halves (a band below a quarter of the samples: records at
    /// 0.5 s) against the same sum in double precision: within [`SINGLE_PRECISION_ERROR`]
    /// of the series' rms at every sample; and not made so where the band
    /// reaches past a quarter (records at 1 s), where the complex transform makes it.
    #[test]
    fn the_real_series_by_halves_is_within_the_bound() {
        for (dt, by_halves) in [(0.5, true), (1.0, false)] {
            let grid = FrequencyGrid::new(0.0, 4000.0, dt, (0.2, 2.4)).unwrap();
            let (n, first) = (grid.len, grid.first);
            let c: Vec<Complex64> = (0..grid.count)
                .map(|j| {
                    let phase = (j as f64 * 2.399_963_229_728_653) % std::f64::consts::TAU;
                    Complex64::from_polar(1.0 + (j as f64 * 0.01).sin(), phase)
                })
                .collect();
            let mut exact = vec![Complex64::default(); n];
            exact[first..first + c.len()].copy_from_slice(&c);
            FftPlanner::<f64>::new()
                .plan_fft_inverse(n)
                .process(&mut exact);
            let rms = c.iter().map(|c| c.norm_sqr()).sum::<f64>().sqrt();
            let mut synth = Synthesizer::new(&grid);
            assert_eq!(synth.halves.is_some(), by_halves, "dt {dt}");
            let mut got = Vec::new();
            synth.real_series_into(&c, &mut got);
            assert_eq!(got.len(), n);
            let worst = got
                .iter()
                .zip(&exact)
                .fold(0.0f64, |m, (a, b)| m.max((a - b.re).abs()));
            assert!(
                worst > 0.0 && worst < SINGLE_PRECISION_ERROR * rms,
                "dt {dt}: {worst:e} of {rms:e}"
            );
        }
    }

    /// Every sample of a transform of the default's length (N = 34 020, its band of 5 955
    /// components with random phases and a spectrum's shape) against the same sum in
    /// double precision (rustfft's f64 transform, itself within 1e-12 of the direct sum
    /// here): within [`SINGLE_PRECISION_ERROR`] of the series' rms, and not exact (the
    /// transform does run in single precision); the same for two real series in one
    /// transform, against the pair's rms.
    #[test]
    fn the_single_precision_transform_is_within_its_bound() {
        let grid = FrequencyGrid::new(0.0, 8505.0, 0.5, (0.2, 2.4)).unwrap();
        let (n, first) = (grid.len, grid.first);
        // Phases spread as a random draw's would be: j times the golden angle.
        let coefficients = |scale: f64, shift: f64| -> Vec<Complex64> {
            (0..grid.count)
                .map(|j| {
                    let w = grid.omega(j);
                    let a = scale * (-(w - 0.6).powi(2) / 0.05).exp() / w;
                    let phase = (j as f64 * 2.399_963_229_728_653 + shift) % std::f64::consts::TAU;
                    Complex64::from_polar(a, phase)
                })
                .collect()
        };
        let exact = |c: &[Complex64]| {
            let mut x = vec![Complex64::default(); n];
            x[first..first + c.len()].copy_from_slice(c);
            FftPlanner::<f64>::new().plan_fft_inverse(n).process(&mut x);
            x
        };
        let energy = |c: &[Complex64]| c.iter().map(|c| c.norm_sqr()).sum::<f64>();
        let (cx, cy) = (coefficients(3.0e6, 0.0), coefficients(2.0, 1.0));
        let mut got = vec![Complex64::default(); n];
        let mut synth = Synthesizer::new(&grid);
        synth.complex_series(&cx, &mut got);
        let rms = energy(&cx).sqrt();
        let worst = got
            .iter()
            .zip(exact(&cx))
            .fold(0.0f64, |m, (a, b)| m.max((a - b).norm()));
        // The error's rms over the samples: below the depth kernel's 1e-6.
        let squares: f64 = got
            .iter()
            .zip(exact(&cx))
            .map(|(a, b)| (a - b).norm_sqr())
            .sum();
        assert!((squares / n as f64).sqrt() < 1e-6 * rms);
        assert!(
            worst > 0.0 && worst < SINGLE_PRECISION_ERROR * rms,
            "{worst:e} of {rms:e}"
        );
        // x + i y of two real series: y a million times smaller than x.
        let mut pair = Vec::new();
        synth.append_two_real_series(&cx, &cy, &mut pair);
        let (ex, ey) = (exact(&cx), exact(&cy));
        let rms = (0.5 * (energy(&cx) + energy(&cy))).sqrt();
        let worst = pair
            .iter()
            .zip(ex.iter().zip(&ey))
            .fold(0.0f64, |m, (p, (x, y))| {
                m.max((p.re - x.re).abs()).max((p.im - y.re).abs())
            });
        assert!(
            worst > 0.0 && worst < SINGLE_PRECISION_ERROR * rms,
            "{worst:e} of {rms:e}"
        );
    }
}
