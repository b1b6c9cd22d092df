//! Gust records: the longitudinal wind speed's fluctuation about its mean at the height of
//! the wind force (docs/theory.md#wind), made as the waves' records are, in the block stream
//! at constant memory (`forces::stream`).
//!
//! Block k's gust is u_k(t) = Re sum_n b_n e^{i omega_n t} on the records' grid (N samples
//! at dt = h/2, omega_n = n d_omega), every component below the Nyquist frequency, n = 1 ..
//! (N - 1)/2, with b_n = sqrt(S_u(omega_n) d_omega) (xi + i xi') drawn from the wind's own
//! stream of (seed, k) (`sea_state::gust_amplitudes`), S_u the gust spectrum per rad/s. So
//! E u^2 = sum_n S_u(omega_n) d_omega, the spectrum's variance below the Nyquist frequency
//! pi / dt (1 Hz at the default 0.5 s; the variance above it is left out, and
//! [`GustStream::variance`] says how much is kept), and the record is Gaussian. Consecutive
//! blocks are joined by the stream's power-complementary cross-fade, so the variance holds
//! at every instant. Cost: one transform per segment.

use super::record::Record;
use super::stream::{Join, Segments};
use super::synthesis::{InverseFft, Synthesizer};
use crate::sea_state::{gust_amplitudes, FrequencyGrid};
use crate::wind::GustSpectrum;
use rustfft::num_complex::Complex64;
use std::sync::Arc;

/// The gusts of one wind on one stream: what a segment's gust record is made from, and its
/// buffers.
#[derive(Clone)]
pub struct GustStream {
    /// The components' grid: the records' grid from n = 1 to below the Nyquist index.
    grid: FrequencyGrid,
    /// sqrt(S_u(omega_n) d_omega), m/s, per component; shared by the plan's stream and each
    /// segment's clone.
    scale: Arc<[f64]>,
    synth: Synthesizer,
    amplitudes: Vec<Complex64>,
    series: Vec<Complex64>,
}

impl GustStream {
    /// The gusts of `spectrum` on the records' `grid` (its length, spacing and clock) and
    /// `segments`, transformed by `fft` (planned for the grid's length).
    pub fn new(
        spectrum: &GustSpectrum,
        grid: &FrequencyGrid,
        segments: Segments,
        fft: InverseFft,
    ) -> Self {
        let count = (grid.len - 1) / 2;
        let grid = FrequencyGrid {
            first: 1,
            count,
            ..grid.clone()
        };
        let scale = spectrum
            .densities_per_rad((0..count).map(|j| grid.omega(j)))
            .into_iter()
            .map(|s| (s * grid.d_omega).sqrt())
            .collect();
        let synth = Synthesizer::with_fft(&grid, fft).with_join(Join::new(segments));
        GustStream {
            grid,
            scale,
            synth,
            amplitudes: Vec::new(),
            series: Vec::new(),
        }
    }

    /// The variance of the records, sum_n S_u(omega_n) d_omega, m^2/s^2: the spectrum's below
    /// the Nyquist frequency, on the grid.
    pub fn variance(&self) -> f64 {
        self.scale.iter().map(|s| s * s).sum()
    }

    /// The highest frequency of the components, rad/s.
    pub fn top_frequency(&self) -> f64 {
        self.grid.omega(self.grid.count - 1)
    }

    /// Segment `k`'s gust record of the wind with seed `seed`, written into `record` (its
    /// buffer reused): joined to block k - 1's tail when `after_previous` (the previous call
    /// built segment k - 1), else without a predecessor (segment 0, or a segment built only
    /// for its tail), as `forces::stream` joins every linear record.
    pub fn build(&mut self, seed: u64, k: u64, after_previous: bool, record: &mut Record) {
        self.synth
            .join_mut()
            .expect("the gust synthesizer is joined")
            .begin(k, after_previous);
        gust_amplitudes(seed, k, &self.scale, &mut self.amplitudes);
        self.series
            .resize(self.synth.output_len(), Complex64::default());
        self.synth
            .complex_series(&self.amplitudes, &mut self.series);
        let mut samples = std::mem::take(record).into_samples();
        samples.clear();
        samples.extend(self.series.iter().map(|c| c.re));
        *record = Record::new(samples);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::forces::plan_inverse_fft;
    use crate::sea_state::WaveComponents;

    fn stream(spectrum: &GustSpectrum) -> (GustStream, Segments) {
        let segments = Segments {
            block: 2048,
            ramp: 256,
        };
        let grid = FrequencyGrid::new(0.0, segments.span() as f64 * 0.5, 0.5, (0.3, 1.0)).unwrap();
        let fft = plan_inverse_fft(&grid);
        (GustStream::new(spectrum, &grid, segments, fft), segments)
    }

    fn npd() -> GustSpectrum {
        GustSpectrum::Npd {
            speed: 20.0,
            height: 30.0,
        }
    }

    /// A stream of 64 segments: mean zero and variance equal to sum S d_omega within four
    /// standard errors (a block's variance is sum |b_n|^2 / 2 with |b_n|^2 / 2 exponential
    /// of mean S_n d_omega, so its standard deviation is sqrt(sum (S_n d_omega)^2), over
    /// independent blocks divided by sqrt(blocks)), and that variance the spectrum's integral
    /// over the components' band (Simpson by hand).
    #[test]
    fn gusts_have_the_spectrum_variance() {
        let spectrum = npd();
        let (mut gusts, segments) = stream(&spectrum);
        let mut record = Record::zero();
        let mut samples = Vec::new();
        let blocks = 64;
        for k in 0..blocks {
            gusts.build(5, k, k > 0, &mut record);
            // The segment's own samples (after the one-sample halo before it).
            samples.extend_from_slice(&record.samples()[1..1 + segments.block]);
        }
        let n = samples.len() as f64;
        let mean = samples.iter().sum::<f64>() / n;
        let variance = samples.iter().map(|u| (u - mean).powi(2)).sum::<f64>() / n;
        let expected = gusts.variance();
        // The integral of S(f) over the band the components stand for, (d_f / 2, f_top +
        // d_f / 2) with d_f = d_omega / 2 pi (midpoint rule), by Simpson in ln f.
        let d_f = gusts.grid.d_omega / (2.0 * std::f64::consts::PI);
        let top = gusts.top_frequency() / (2.0 * std::f64::consts::PI) + 0.5 * d_f;
        let (a, b, panels) = ((0.5 * d_f).ln(), top.ln(), 4000);
        let h = (b - a) / panels as f64;
        let f = |x: f64| spectrum.density(x.exp()) * x.exp();
        let inner: f64 = (1..panels)
            .map(|i| if i % 2 == 1 { 4.0 } else { 2.0 } * f(a + i as f64 * h))
            .sum();
        let integral = (f(a) + inner + f(b)) * h / 3.0;
        assert!(
            (expected / integral - 1.0).abs() < 0.01,
            "{expected} vs {integral}"
        );
        // The mean's standard deviation over T = n dt: sqrt(S(0) / (2 T)), S per Hz.
        let sd_of_mean = (spectrum.density(0.0) / (2.0 * n * 0.5)).sqrt();
        assert!(
            mean.abs() < 4.0 * sd_of_mean,
            "mean {mean} vs sd {sd_of_mean}"
        );
        let sd_of_variance =
            gusts.scale.iter().map(|s| s.powi(4)).sum::<f64>().sqrt() / (blocks as f64).sqrt();
        assert!(
            (variance - expected).abs() < 4.0 * sd_of_variance + mean * mean,
            "{variance} vs {expected} (sd {sd_of_variance})"
        );
    }

    /// The same segment made two ways is the same bit for bit: after its predecessor, or
    /// after making the predecessor only for its tail (a stop time or a restore anywhere);
    /// another seed gives other gusts.
    #[test]
    fn a_segment_depends_only_on_the_seed_and_its_index() {
        let spectrum = npd();
        let (mut gusts, _) = stream(&spectrum);
        let mut record = Record::zero();
        for k in 0..4 {
            gusts.build(9, k, k > 0, &mut record);
        }
        let in_order = record.samples().to_vec();
        let (mut fresh, _) = stream(&spectrum);
        fresh.build(9, 2, false, &mut record);
        fresh.build(9, 3, true, &mut record);
        assert_eq!(record.samples(), &in_order[..]);
        fresh.build(10, 2, false, &mut record);
        fresh.build(10, 3, true, &mut record);
        assert_ne!(record.samples(), &in_order[..]);
    }

    /// The wind's draws are not the waves' of the same seed and block: the normalised
    /// cross-correlation of the gust amplitudes with the wave amplitudes of block (seed, k)
    /// is within four standard errors of zero (1 / sqrt(n)), and drawing the gusts leaves
    /// the waves' amplitudes as they were.
    #[test]
    fn the_wind_is_independent_of_the_waves() {
        use crate::sea_state::{SeaState, Spectrum, Spreading};
        let sea = SeaState {
            spectrum: Spectrum::PiersonMoskowitz { hs: 4.0, tp: 10.0 },
            spreading: Spreading::LongCrested,
            mean_direction: 0.0,
            n_directions: 1,
            seed: 3,
            band: None,
        };
        let grid = FrequencyGrid::new(0.0, 4096.0, 0.5, sea.band()).unwrap();
        for k in [0, 1, 7] {
            let waves = WaveComponents::generate_block(&sea, grid.clone(), k);
            // Unit scale: the gust draws are the standard normals themselves.
            let mut gusts = Vec::new();
            gust_amplitudes(3, k, &vec![1.0; grid.count], &mut gusts);
            let again = WaveComponents::generate_block(&sea, grid.clone(), k);
            assert_eq!(waves, again);
            // The waves' standard normals: a_j / sqrt(S(omega_j) d_omega).
            let a: Vec<Complex64> = waves
                .of_direction(0)
                .iter()
                .enumerate()
                .map(|(j, a)| a / (sea.spectrum.density(grid.omega(j)) * grid.d_omega).sqrt())
                .collect();
            let norm = |v: &[Complex64]| v.iter().map(|c| c.norm_sqr()).sum::<f64>().sqrt();
            let dot: f64 = a
                .iter()
                .zip(&gusts)
                .map(|(x, y)| x.re * y.re + x.im * y.im)
                .sum();
            let correlation = dot / (norm(&a) * norm(&gusts));
            let bound = 4.0 / (2.0 * grid.count as f64).sqrt();
            assert!(correlation.abs() < bound, "block {k}: {correlation}");
        }
    }
}
