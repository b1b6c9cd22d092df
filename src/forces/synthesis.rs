//! Sums of wave components at every sample by one inverse FFT (E&S 6; physics.md 3).
//!
//! Convention: `series(first, c)[m] = sum_j c_j e^{i omega_{first+j} m dt}`
//! = sum_j c_j e^{2 pi i (first + j) m / N}: RustFFT's inverse transform, unnormalised.

use super::super::sea_state::FrequencyGrid;
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

/// An inverse FFT for the record length, with its scratch space.
pub struct Synthesizer {
    fft: InverseFft,
    scratch: Vec<Complex64>,
    first: usize,
    count: usize,
}

impl Synthesizer {
    /// Plans the transform for the grid's record length.
    pub fn new(grid: &FrequencyGrid) -> Self {
        Self::with_fft(grid, plan_inverse_fft(grid))
    }

    /// Uses a transform already planned for the grid's record length.
    pub fn with_fft(grid: &FrequencyGrid, fft: InverseFft) -> Self {
        debug_assert_eq!(fft.len(), grid.len);
        let scratch = vec![Complex64::default(); fft.get_inplace_scratch_len()];
        Synthesizer {
            fft,
            scratch,
            first: grid.first,
            count: grid.count,
        }
    }

    /// Complex series of the band's components: writes sum_j c_j e^{i omega_j t_m} into
    /// `out` (length N) for every sample m.
    pub fn complex_series(&mut self, coefficients: &[Complex64], out: &mut [Complex64]) {
        debug_assert_eq!(coefficients.len(), self.count);
        let (below, rest) = out.split_at_mut(self.first);
        let (band, above) = rest.split_at_mut(self.count);
        below.fill(Complex64::default());
        band.copy_from_slice(coefficients);
        above.fill(Complex64::default());
        self.fft.process_with_scratch(out, &mut self.scratch);
    }

    /// Two real series in one transform, appended to `out` as N more samples:
    /// x_m + i y_m with x_m = Re sum_j cx_j e^{i omega_j t_m} and
    /// y_m = Re sum_j cy_j e^{i omega_j t_m}. Uses the Hermitian pairs n and N - n, so the
    /// band must lie below the Nyquist index (guaranteed by [`FrequencyGrid::new`]). Every
    /// input sample is written once: the band's pairs and the zeros around them.
    pub fn append_two_real_series(
        &mut self,
        cx: &[Complex64],
        cy: &[Complex64],
        out: &mut Vec<Complex64>,
    ) {
        debug_assert_eq!((cx.len(), cy.len()), (self.count, self.count));
        let (n, start) = (self.fft.len(), out.len());
        let zeros = |count: usize| std::iter::repeat_n(Complex64::default(), count);
        let i = Complex64::new(0.0, 1.0);
        let pairs = cx.iter().zip(cy);
        // Index k = first + j holds (cx_j + i cy_j) / 2, index N - k the conjugates' pair;
        // the second run goes up in index, so down in j.
        out.extend(zeros(self.first));
        out.extend(pairs.clone().map(|(x, y)| 0.5 * (x + i * y)));
        out.extend(zeros(n + 1 - 2 * (self.first + self.count)));
        out.extend(pairs.rev().map(|(x, y)| 0.5 * (x.conj() + i * y.conj())));
        out.extend(zeros(self.first - 1));
        debug_assert_eq!(out.len(), start + n);
        self.fft
            .process_with_scratch(&mut out[start..], &mut self.scratch);
    }
}
