//! Sums of wave components at every sample by one inverse FFT (E&S 6; physics.md 3).
//!
//! Convention: `series(first, c)[m] = sum_j c_j e^{i omega_{first+j} m dt}`
//! = sum_j c_j e^{2 pi i (first + j) m / N}: RustFFT's inverse transform, unnormalised.

use super::super::sea_state::FrequencyGrid;
use rustfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// An inverse FFT planned once for the record length, with its scratch space.
pub struct Synthesizer {
    fft: Arc<dyn Fft<f64>>,
    scratch: Vec<Complex64>,
    first: usize,
    count: usize,
}

impl Synthesizer {
    /// Plans the transform for the grid's record length.
    pub fn new(grid: &FrequencyGrid) -> Self {
        let fft = FftPlanner::new().plan_fft_inverse(grid.len);
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
        out.fill(Complex64::default());
        out[self.first..self.first + self.count].copy_from_slice(coefficients);
        self.fft.process_with_scratch(out, &mut self.scratch);
    }

    /// Two real series in one transform: out[m] = x_m + i y_m with
    /// x_m = Re sum_j cx_j e^{i omega_j t_m} and y_m = Re sum_j cy_j e^{i omega_j t_m}.
    /// Uses the Hermitian pairs n and N - n, so the band must lie below the Nyquist index
    /// (guaranteed by [`FrequencyGrid::new`]).
    pub fn two_real_series(&mut self, cx: &[Complex64], cy: &[Complex64], out: &mut [Complex64]) {
        out.fill(Complex64::default());
        self.place_and_transform(cx, cy, out);
    }

    /// [`Synthesizer::two_real_series`] appended to `out` as N more samples (the zeros
    /// outside the band are written once, by the append).
    pub fn append_two_real_series(
        &mut self,
        cx: &[Complex64],
        cy: &[Complex64],
        out: &mut Vec<Complex64>,
    ) {
        let start = out.len();
        out.resize(start + self.fft.len(), Complex64::default());
        self.place_and_transform(cx, cy, &mut out[start..]);
    }

    /// The transform of a zeroed `out` with the band's Hermitian pairs placed in it.
    fn place_and_transform(&mut self, cx: &[Complex64], cy: &[Complex64], out: &mut [Complex64]) {
        let n = out.len();
        let i = Complex64::new(0.0, 1.0);
        for j in 0..self.count {
            let k = self.first + j;
            out[k] += 0.5 * (cx[j] + i * cy[j]);
            out[n - k] += 0.5 * (cx[j].conj() + i * cy[j].conj());
        }
        self.fft.process_with_scratch(out, &mut self.scratch);
    }
}
