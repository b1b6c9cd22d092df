//! Statistics of sampled time records for slow-drift studies: a summary (mean, rms,
//! extremes) after a start-up transient, and Welch's estimate of the one-sided spectral
//! density per rad/s.
//!
//! Conventions: a record `x[m]` is sampled at the times `t_m = m * dt` (s), `m = 0, 1, ...`,
//! counted from the start of the run, its first sample the state at the start; a transient
//! of T s drops the samples at t < T and keeps those at t >= T, so a run of D s keeps
//! (D - T) / dt + 1 samples (the default's 3 hours at 1 s after 2000 s: t = 2000, 2001, ...,
//! 10800, 8801 samples: `slowdrift simulate`, a campaign's runs, fmu-pack's self-check and
//! slowdrift_dask all count so); angular frequencies are in rad/s; "rms" is the root mean
//! square *about the mean* (the standard deviation), as in the slow-drift literature (E&S
//! 1996 report the rms of the slow-drift motion's fluctuation).

use std::f64::consts::PI;

use rustfft::num_complex::Complex64;
use rustfft::FftPlanner;

use crate::error::numbers::readable;
use crate::error::{require_non_negative, require_positive, Error, Result};

/// Smallest accepted Welch segment length (a segment of one sample has no spectrum).
const MIN_SEGMENT_LEN: usize = 2;

/// Summary statistics of a record (after any transient has been dropped).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Summary {
    /// Arithmetic mean, in the units of the record.
    pub mean: f64,
    /// Root mean square about the mean, i.e. the population standard deviation
    /// `sqrt( (1/n) sum (x_m - mean)^2 )`, in the units of the record. This is the "rms"
    /// of the slow-drift literature (Emmerhoff & Sclavounos 1996): the rms of the
    /// fluctuation, not of the raw signal.
    pub rms: f64,
    /// Largest sample, in the units of the record.
    pub max: f64,
    /// Smallest sample, in the units of the record.
    pub min: f64,
    /// Number of samples summarised (those at times `t >= transient`).
    pub samples: usize,
}

/// Summarises `record` (sampled every `dt` seconds, sample `m` at `t = m * dt`) after
/// dropping the start-up transient: the samples with `t < transient` (s) are ignored.
///
/// Errors ([`Error::InvalidValue`]): `stats.dt` not finite or not positive;
/// `stats.transient` negative or not finite, or leaving no sample; `stats.record` empty;
/// `stats.record[m]` NaN or infinite (anywhere in the record, transient included, since a
/// non-finite sample means the record itself is broken).
pub fn summarize(record: &[f64], dt: f64, transient: f64) -> Result<Summary> {
    require_positive("stats.dt", dt)?;
    require_non_negative("stats.transient", transient)?;
    if record.is_empty() {
        return Err(empty_record());
    }
    require_finite_record(record)?;

    let first = record
        .iter()
        .enumerate()
        .position(|(m, _)| kept_at(m, dt, transient))
        .ok_or_else(|| no_sample_left(record.len(), dt, transient))?;
    let kept = &record[first..];

    let n = kept.len() as f64;
    let mean = kept.iter().sum::<f64>() / n;
    // Two passes: the deviations are summed about the computed mean, which avoids the
    // cancellation of the one-pass formula mean(x^2) - mean(x)^2.
    let variance = kept.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n;
    let max = kept.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let min = kept.iter().copied().fold(f64::INFINITY, f64::min);
    Ok(Summary {
        mean,
        rms: variance.sqrt(),
        max,
        min,
        samples: kept.len(),
    })
}

/// Whether sample m (at t = m dt) is past the transient: t >= transient.
fn kept_at(m: usize, dt: f64, transient: f64) -> bool {
    m as f64 * dt >= transient
}

/// The refusal of an empty record.
fn empty_record() -> Error {
    Error::invalid("stats.record", "[]", "is empty")
}

/// The refusal of a transient that leaves none of a record's `len` samples (len > 0).
fn no_sample_left(len: usize, dt: f64, transient: f64) -> Error {
    Error::invalid(
        "stats.transient",
        transient,
        format!(
            "leaves no sample: the record has {} samples at dt = {} s, the last at t = {} s",
            len,
            readable(dt),
            readable((len - 1) as f64 * dt)
        ),
    )
}

/// [`summarize`] of a record taken sample by sample, for a run whose samples are not kept
/// (`slowdrift simulate`): the same samples kept, the same extremes, count and errors (the
/// first sample that is not finite, wherever it is; a transient that leaves no sample).
/// The mean and the variance about it are Welford's updates (B. P. Welford, "Note on a
/// method for calculating corrected sums of squares and products", Technometrics 4(3),
/// 1962, 419-420) of the kept samples less the first kept one, K (a shift: T. F. Chan,
/// G. H. Golub and R. J. LeVeque, "Algorithms for computing the sample variance: analysis
/// and recommendations", The American Statistician 37(3), 1983, 242-247): for each kept x,
/// y = x - K, n += 1, d = y - mean_y, mean_y += d / n, M2 += d (y - mean_y); mean K +
/// mean_y, variance M2 / n. Every update is about the running mean (no cancellation of
/// sums of squares), and the shift keeps the deviations free of the offset's rounding: a
/// record far from zero with a small spread (1e6 + 0.5 sin) loses about 1e-11 of its rms
/// to Welford's updates of the raw samples, nothing beyond rounding with the shift. The
/// mean and rms differ from [`summarize`]'s two passes by rounding only (tested within
/// 1e-12, relative, of [`summarize`]'s); a constant record's rms is exactly 0.
#[derive(Debug, Clone, PartialEq)]
pub struct RunningSummary {
    dt: f64,
    transient: f64,
    /// Samples taken (the next one's index m).
    taken: usize,
    kept: usize,
    /// The first kept sample, K.
    shift: f64,
    /// The mean of the kept samples less K.
    mean: f64,
    /// The sum of their squared deviations from their mean.
    m2: f64,
    max: f64,
    min: f64,
    /// The first sample that is not finite: (m, x).
    not_finite: Option<(usize, f64)>,
}

impl RunningSummary {
    /// A summary of samples every `dt` s after `transient` s; errors as [`summarize`]'s.
    pub fn new(dt: f64, transient: f64) -> Result<Self> {
        require_positive("stats.dt", dt)?;
        require_non_negative("stats.transient", transient)?;
        Ok(RunningSummary {
            dt,
            transient,
            taken: 0,
            kept: 0,
            shift: 0.0,
            mean: 0.0,
            m2: 0.0,
            max: f64::NEG_INFINITY,
            min: f64::INFINITY,
            not_finite: None,
        })
    }

    /// Takes the next sample.
    pub fn push(&mut self, x: f64) {
        let m = self.taken;
        self.taken += 1;
        if !x.is_finite() {
            self.not_finite.get_or_insert((m, x));
            return;
        }
        if !kept_at(m, self.dt, self.transient) {
            return;
        }
        if self.kept == 0 {
            self.shift = x;
        }
        self.kept += 1;
        let y = x - self.shift;
        let d = y - self.mean;
        self.mean += d / self.kept as f64;
        self.m2 += d * (y - self.mean);
        self.max = self.max.max(x);
        self.min = self.min.min(x);
    }

    /// Refuses, before any sample is taken, a record of `samples` samples that
    /// [`RunningSummary::finish`] would refuse for its length: none (empty), or none kept by
    /// the transient (the last, at t = (samples - 1) dt, before it); in finish's words. A run
    /// of a known number of samples checks so before it is made.
    pub fn require_kept(&self, samples: usize) -> Result<()> {
        match samples.checked_sub(1) {
            None => Err(empty_record()),
            Some(last) if !kept_at(last, self.dt, self.transient) => {
                Err(no_sample_left(samples, self.dt, self.transient))
            }
            Some(_) => Ok(()),
        }
    }

    /// The summary of the samples taken.
    pub fn finish(&self) -> Result<Summary> {
        if self.taken == 0 {
            return Err(empty_record());
        }
        if let Some((m, x)) = self.not_finite {
            return Err(not_finite(m, x));
        }
        if self.kept == 0 {
            return Err(no_sample_left(self.taken, self.dt, self.transient));
        }
        Ok(Summary {
            mean: self.shift + self.mean,
            rms: (self.m2 / self.kept as f64).sqrt(),
            max: self.max,
            min: self.min,
            samples: self.kept,
        })
    }
}

/// One-sided spectral density estimate.
#[derive(Debug, Clone, PartialEq)]
pub struct Spectrum {
    /// Angular frequencies `omega_k = k * d_omega`, `k = 0 ..= L/2`, with
    /// `d_omega = 2 pi / (L dt)` (rad/s), L the segment length.
    pub omega: Vec<f64>,
    /// One-sided spectral density at `omega[k]`, in (record units)^2 s/rad, such that
    /// `sum_k density[k] * d_omega` is the variance (see [`welch_spectrum`]).
    pub density: Vec<f64>,
}

/// Welch's estimate of the one-sided spectral density of `record` (sampled every `dt`
/// seconds), per rad/s.
///
/// Method: the record is cut into K segments of `segment_len` = L samples, each starting
/// `L - floor(L/2)` samples after the previous one (50 % overlap; K = 1 + (N - L) /
/// (L - floor(L/2)), trailing samples that do not fill a segment are not used). From each
/// segment its own mean is removed, it is multiplied by the periodic Hann window
/// `w_n = (1 - cos(2 pi n / L)) / 2`, `n = 0 .. L-1`, and transformed,
/// `X_k = sum_n w_n x_n e^{-2 pi i k n / L}`. With `U = sum_n w_n^2`, the estimate is
///
/// `density[k] = c_k * dt * mean over segments of |X_k|^2 / (2 pi U)`,
///
/// with `c_k = 2` for `0 < k < L/2` (the negative frequencies folded in) and `c_k = 1` for
/// `k = 0` and, when L is even, `k = L/2` (those bins have no mirror image; for a flat
/// spectrum they read half the density of the others).
///
/// Normalisation (exact, by Parseval): with `d_omega = 2 pi / (L dt)`,
/// `sum_k density[k] * d_omega` equals the window-corrected mean square
/// `mean over segments of sum_n (w_n (x_n - segment mean))^2 / U`; for a stationary record
/// its expectation is the variance (less the little power below about two bins that the
/// mean removal takes away). White noise of variance s^2 thus reads `s^2 dt / pi` in the
/// interior bins. The bins 0 and 1 are biased low by the per-segment mean removal (the
/// Hann window's transform spans bins 0 and ±1).
///
/// Errors ([`Error::InvalidValue`]): `stats.dt` not finite or not positive;
/// `stats.segment_len` below 2 or longer than the record; `stats.record[m]` NaN or
/// infinite.
pub fn welch_spectrum(record: &[f64], dt: f64, segment_len: usize) -> Result<Spectrum> {
    require_positive("stats.dt", dt)?;
    if segment_len < MIN_SEGMENT_LEN {
        return Err(Error::invalid(
            "stats.segment_len",
            segment_len,
            format!("must be at least {MIN_SEGMENT_LEN}"),
        ));
    }
    if segment_len > record.len() {
        return Err(Error::invalid(
            "stats.segment_len",
            segment_len,
            format!("exceeds the record length of {} samples", record.len()),
        ));
    }
    require_finite_record(record)?;

    let len = segment_len;
    let step = len - len / 2;
    let segments = 1 + (record.len() - len) / step;
    let window: Vec<f64> = (0..len)
        .map(|n| 0.5 * (1.0 - (2.0 * PI * n as f64 / len as f64).cos()))
        .collect();
    let window_power: f64 = window.iter().map(|w| w * w).sum();

    let fft = FftPlanner::<f64>::new().plan_fft_forward(len);
    let mut buffer = vec![Complex64::new(0.0, 0.0); len];
    let mut scratch = vec![Complex64::new(0.0, 0.0); fft.get_inplace_scratch_len()];
    let bins = len / 2 + 1;
    let mut power = vec![0.0; bins];
    for s in 0..segments {
        let segment = &record[s * step..s * step + len];
        let mean = segment.iter().sum::<f64>() / len as f64;
        for ((b, x), w) in buffer.iter_mut().zip(segment).zip(&window) {
            *b = Complex64::new((x - mean) * w, 0.0);
        }
        fft.process_with_scratch(&mut buffer, &mut scratch);
        for (p, b) in power.iter_mut().zip(&buffer) {
            *p += b.norm_sqr();
        }
    }

    let d_omega = 2.0 * PI / (len as f64 * dt);
    let scale = dt / (2.0 * PI * window_power * segments as f64);
    let density = power
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let one_sided = if k == 0 || 2 * k == len { 1.0 } else { 2.0 };
            one_sided * scale * p
        })
        .collect();
    let omega = (0..bins).map(|k| k as f64 * d_omega).collect();
    Ok(Spectrum { omega, density })
}

/// Refuses a record with a NaN or infinite sample, naming its index.
fn require_finite_record(record: &[f64]) -> Result<()> {
    match record.iter().position(|x| !x.is_finite()) {
        Some(m) => Err(not_finite(m, record[m])),
        None => Ok(()),
    }
}

/// The refusal of sample m, `x`, not finite.
fn not_finite(m: usize, x: f64) -> Error {
    Error::invalid(format!("stats.record[{m}]"), x, "must be a finite number")
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand_xoshiro::rand_core::{Rng, SeedableRng};
    use rand_xoshiro::Xoshiro256PlusPlus;

    /// Rounding tolerance for results that are exact in closed form.
    const EXACT: f64 = 1e-12;
    /// Number of standard deviations allowed for statistical estimates.
    const SIGMAS: f64 = 5.0;
    /// Variance factor of a Hann-windowed Welch bin at 50 % overlap: var/S^2 = F/K with
    /// F = 1 + 2 c^2, c = 0.167 the correlation of overlapping Hann segments (Welch 1967;
    /// Harris 1978, table 1). So K/F is the effective number of segments.
    const OVERLAP_FACTOR: f64 = 1.056;
    /// Variance factor of an average of B adjacent Hann bins: var = G/B times that of one
    /// bin, with G = 1 + 2 (4/9) + 2 (1/36): the periodic Hann window makes the
    /// power of adjacent bins correlated by (2/3)^2 and of next-but-one by (1/6)^2.
    const ADJACENT_FACTOR: f64 = 1.0 + 8.0 / 9.0 + 1.0 / 18.0;

    /// Relative standard deviation of the average of `bins` adjacent Welch bins.
    fn band_relative_std(segments: usize, bins: usize) -> f64 {
        (OVERLAP_FACTOR * ADJACENT_FACTOR / (segments * bins) as f64).sqrt()
    }

    /// Two independent standard normal numbers by Box-Muller.
    fn standard_normal_pair(rng: &mut Xoshiro256PlusPlus) -> (f64, f64) {
        const UNIT: f64 = 1.0 / (1u64 << 53) as f64;
        // u1 in (0, 1] keeps ln(u1) finite; u2 in [0, 1).
        let u1 = ((rng.next_u64() >> 11) + 1) as f64 * UNIT;
        let u2 = (rng.next_u64() >> 11) as f64 * UNIT;
        let radius = (-2.0 * u1.ln()).sqrt();
        let (sin, cos) = (2.0 * PI * u2).sin_cos();
        (radius * cos, radius * sin)
    }

    fn gaussian_noise(seed: u64, count: usize, std: f64) -> Vec<f64> {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(seed);
        let mut out = Vec::with_capacity(count + 1);
        while out.len() < count {
            let (a, b) = standard_normal_pair(&mut rng);
            out.push(std * a);
            out.push(std * b);
        }
        out.truncate(count);
        out
    }

    fn field_of(error: Error) -> String {
        match error {
            Error::InvalidValue { field, .. } => field,
            other => panic!("expected InvalidValue, got {other:?}"),
        }
    }

    #[test]
    fn summary_of_offset_sine_over_whole_periods() {
        // x = c + A sin(2 pi m / P) over 25 whole periods of P = 40 samples: mean c exactly,
        // rms A / sqrt 2 (the discrete sum of sin^2 over whole periods is exactly n/2),
        // extremes c +- A reached at m = P/4 and 3P/4.
        let (amplitude, offset, period, periods) = (1.5, -0.25, 40, 25);
        let record: Vec<f64> = (0..period * periods)
            .map(|m| offset + amplitude * (2.0 * PI * m as f64 / period as f64).sin())
            .collect();
        let s = summarize(&record, 0.1, 0.0).unwrap();
        assert_eq!(s.samples, record.len());
        assert!((s.mean - offset).abs() < EXACT);
        assert!((s.rms - amplitude / 2f64.sqrt()).abs() < EXACT);
        assert!((s.max - (offset + amplitude)).abs() < EXACT);
        assert!((s.min - (offset - amplitude)).abs() < EXACT);
    }

    #[test]
    fn transient_drops_exactly_the_early_samples() {
        // x_m = m, dt = 0.5 s: t = 2.0 s is sample 4, kept (t >= transient); 2.1 s drops it.
        let record: Vec<f64> = (0..10).map(|m| m as f64).collect();
        let s = summarize(&record, 0.5, 2.0).unwrap();
        assert_eq!((s.samples, s.min, s.max), (6, 4.0, 9.0));
        // mean of 4..=9 is 6.5; population variance of 6 consecutive integers (36-1)/12.
        assert!((s.mean - 6.5).abs() < EXACT);
        assert!((s.rms - (35.0f64 / 12.0).sqrt()).abs() < EXACT);
        let s = summarize(&record, 0.5, 2.1).unwrap();
        assert_eq!((s.samples, s.min), (5, 5.0));
        // The last sample is at 4.5 s: a transient of 4.5 s keeps just it.
        let s = summarize(&record, 0.5, 4.5).unwrap();
        assert_eq!((s.samples, s.mean, s.rms), (1, 9.0, 0.0));
    }

    #[test]
    fn summary_errors_name_the_field() {
        let record = [1.0, 2.0, 3.0];
        for dt in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert_eq!(
                field_of(summarize(&record, dt, 0.0).unwrap_err()),
                "stats.dt"
            );
        }
        for transient in [-0.1, f64::NAN, f64::INFINITY] {
            let err = summarize(&record, 1.0, transient).unwrap_err();
            assert_eq!(field_of(err), "stats.transient");
        }
        // Last sample at t = 2 s; a transient just beyond leaves nothing.
        let err = summarize(&record, 1.0, 2.000_001).unwrap_err();
        assert_eq!(field_of(err), "stats.transient");
        assert_eq!(
            field_of(summarize(&[], 1.0, 0.0).unwrap_err()),
            "stats.record"
        );
        // A NaN is refused even inside the transient, with its index.
        let err = summarize(&[1.0, f64::NAN, 3.0], 1.0, 1.5).unwrap_err();
        assert_eq!(field_of(err), "stats.record[1]");
        let err = summarize(&[1.0, 2.0, f64::NEG_INFINITY], 1.0, 0.0).unwrap_err();
        assert_eq!(field_of(err), "stats.record[2]");
    }

    /// The summary taken sample by sample, as `summarize` of the record: of its samples.
    fn running(record: &[f64], dt: f64, transient: f64) -> Result<Summary> {
        let mut summary = RunningSummary::new(dt, transient)?;
        record.iter().for_each(|&x| summary.push(x));
        summary.finish()
    }

    /// The running summary against the two-pass `summarize`: means within 1e-12 of the
    /// mean, rms within 1e-12 of the rms (a constant's exactly 0, summarize's within 1e-12 of
    /// the mean), extremes and counts exact; on a sine on an offset of 1e6 (rms 0.35: the
    /// cancellation that Welford's updates of the raw samples suffer, 1.2e-11 of the rms
    /// measured without the shift), normal numbers, constants (one not a binary fraction),
    /// one kept sample, and transients that fall exactly on a sample (t = 500 s at 0.5 s,
    /// t = 100 s at 0.25 s, t = 2 s at 1 s).
    #[test]
    fn the_running_summary_is_the_two_pass_summary() {
        let normal: Vec<f64> = gaussian_noise(7, 50_000, 2.0)
            .iter()
            .map(|x| 3.0 + x)
            .collect();
        let sine: Vec<f64> = (0..20_000)
            .map(|m| 1e6 + 0.5 * (0.013 * m as f64).sin())
            .collect();
        let constant = [1e6 + 0.1; 300];
        // (record, dt, transient, kept samples: counted by hand)
        let cases: [(&[f64], f64, f64, usize); 7] = [
            (&sine, 0.5, 500.0, 19_000),
            (&sine, 0.5, 1000.2, 17_999),
            (&normal, 1.0, 0.0, 50_000),
            (&[4.25; 300], 1.0, 10.0, 290),
            (&constant, 0.1, 1.0, 290),
            (&[1.0, 2.0, 3.0], 1.0, 2.0, 1),
            (&normal[..1000], 0.25, 100.0, 600),
        ];
        for (record, dt, transient, kept) in cases {
            let (a, b) = (
                summarize(record, dt, transient).unwrap(),
                running(record, dt, transient).unwrap(),
            );
            assert_eq!((a.samples, a.max, a.min), (kept, b.max, b.min));
            assert_eq!(b.samples, kept);
            assert!(
                (a.mean - b.mean).abs() <= 1e-12 * a.mean.abs(),
                "{a:?} {b:?}"
            );
            if a.max == a.min {
                // A constant: no spread at all, summarize's within the rounding of its mean.
                assert_eq!((b.mean, b.rms), (a.max, 0.0), "{b:?}");
                assert!(a.rms <= 1e-12 * a.mean.abs(), "{a:?}");
            } else {
                assert!((a.rms - b.rms).abs() <= 1e-12 * a.rms, "{a:?} {b:?}");
            }
        }
        // The sine's rms against the offset removed exactly (x - 1e6 is exact for x in
        // [5e5, 2e6], Sterbenz): the deviations carry no rounding of the offset.
        let residual: Vec<f64> = sine.iter().map(|x| x - 1e6).collect();
        let reference = summarize(&residual, 0.5, 500.0).unwrap();
        let b = running(&sine, 0.5, 500.0).unwrap();
        assert!(
            (b.rms - reference.rms).abs() <= 1e-14 * reference.rms,
            "{b:?} {reference:?}"
        );
        assert!(
            (b.mean - 1e6 - reference.mean).abs() <= 1e-12 * 1e6,
            "{b:?} {reference:?}"
        );
    }

    /// The running summary refuses what `summarize` refuses, in the same words.
    #[test]
    fn the_running_summary_errors_are_the_two_pass_ones() {
        let record = [1.0, 2.0, 3.0];
        let cases: [(&[f64], f64, f64); 8] = [
            (&record, 0.0, 0.0),
            (&record, f64::NAN, 0.0),
            (&record, 1.0, -0.1),
            (&record, 1.0, f64::INFINITY),
            (&record, 1.0, 2.000_001),
            (&[], 1.0, 0.0),
            (&[1.0, f64::NAN, 3.0], 1.0, 1.5),
            (&[1.0, 2.0, f64::NEG_INFINITY, f64::NAN], 1.0, 5.0),
        ];
        for (record, dt, transient) in cases {
            let (a, b) = (
                summarize(record, dt, transient),
                running(record, dt, transient),
            );
            assert_eq!(
                a.unwrap_err().to_string(),
                b.unwrap_err().to_string(),
                "{record:?} {dt} {transient}"
            );
        }
    }

    /// `require_kept` of a length refuses exactly the records of that length that `finish`
    /// refuses for their length, in the same words: the transient on the last sample (t = 2 s
    /// of 3 at 1 s; 3 x 0.1 s rounds above 0.3 s), just past it, one sample, none.
    #[test]
    fn the_running_summary_refuses_a_length_as_finish_does() {
        let cases: [(usize, f64, f64, bool); 8] = [
            (3, 1.0, 2.0, true),
            (3, 1.0, 2.000_001, false),
            (4, 0.1, 0.3, true),
            (11, 0.1, 1.0, true),
            (1001, 1.0, 1000.3, false),
            (1, 1.0, 0.0, true),
            (1, 1.0, 1e-9, false),
            (0, 1.0, 0.0, false),
        ];
        for (len, dt, transient, kept) in cases {
            let summary = RunningSummary::new(dt, transient).unwrap();
            let checked = summary.require_kept(len);
            let finished = running(&vec![0.5; len], dt, transient);
            assert_eq!(checked.is_ok(), kept, "{len} {dt} {transient}");
            assert_eq!(
                checked.map_err(|e| e.to_string()),
                finished.map(|_| ()).map_err(|e| e.to_string()),
                "{len} {dt} {transient}"
            );
        }
    }

    #[test]
    fn welch_errors_name_the_field() {
        let record = [0.0; 8];
        for dt in [0.0, -0.5, f64::NAN] {
            assert_eq!(
                field_of(welch_spectrum(&record, dt, 4).unwrap_err()),
                "stats.dt"
            );
        }
        for len in [0, 1, 9] {
            let err = welch_spectrum(&record, 1.0, len).unwrap_err();
            assert_eq!(field_of(err), "stats.segment_len");
        }
        assert_eq!(
            field_of(welch_spectrum(&[], 1.0, 2).unwrap_err()),
            "stats.segment_len"
        );
        let mut bad = record;
        bad[5] = f64::NAN;
        assert_eq!(
            field_of(welch_spectrum(&bad, 1.0, 4).unwrap_err()),
            "stats.record[5]"
        );
    }

    #[test]
    fn welch_grid_and_odd_segment_parseval() {
        // Grid: omega_k = 2 pi k / (L dt), k = 0 ..= L/2. Parseval identity checked on an
        // odd segment length (no Nyquist bin) with a single segment: sum density d_omega
        // equals sum (w (x - mean))^2 / U exactly.
        let (len, dt) = (7, 0.3);
        let record = [0.3, -1.2, 2.5, 0.7, -0.4, 1.9, -2.2];
        let spectrum = welch_spectrum(&record, dt, len).unwrap();
        let d_omega = 2.0 * PI / (len as f64 * dt);
        assert_eq!(spectrum.omega.len(), len / 2 + 1);
        for (k, w) in spectrum.omega.iter().enumerate() {
            assert!((w - k as f64 * d_omega).abs() < EXACT);
        }
        let mean = record.iter().sum::<f64>() / len as f64;
        let window: Vec<f64> = (0..len)
            .map(|n| 0.5 * (1.0 - (2.0 * PI * n as f64 / len as f64).cos()))
            .collect();
        let u: f64 = window.iter().map(|w| w * w).sum();
        let mean_square: f64 = record
            .iter()
            .zip(&window)
            .map(|(x, w)| ((x - mean) * w).powi(2))
            .sum::<f64>()
            / u;
        let integral: f64 = spectrum.density.iter().sum::<f64>() * d_omega;
        assert!((integral - mean_square).abs() < EXACT * mean_square);
    }

    #[test]
    fn welch_two_sinusoids_variance_and_peaks() {
        // Two sinusoids centred on bins k1, k2 of a segment of L samples: every segment holds
        // whole periods, so the segment mean is 0 and the windowed mean square is exactly
        // A^2/2 each (w^2 has DFT support in bins 0, +-1, +-2 only, and 2 k1, k2 - k1,
        // k1 + k2 are all beyond 2). The periodic Hann window's transform is L/2 at bin 0
        // and -L/4 at bins +-1, so each sinusoid's power splits 1 : 1/4 : 1/4 over its bin
        // and the two neighbours: peak density (A^2/2) / (1.5 d_omega), neighbours a
        // quarter of that, and zero elsewhere.
        let (len, dt) = (256, 0.5);
        let (k1, a1, p1) = (20, 2.0, 0.3);
        let (k2, a2, p2) = (45, 0.7, -1.1);
        let d_omega = 2.0 * PI / (len as f64 * dt);
        let (w1, w2) = (k1 as f64 * d_omega, k2 as f64 * d_omega);
        let record: Vec<f64> = (0..len * 16)
            .map(|m| {
                let t = m as f64 * dt;
                a1 * (w1 * t + p1).sin() + a2 * (w2 * t + p2).cos()
            })
            .collect();
        let spectrum = welch_spectrum(&record, dt, len).unwrap();

        let variance = (a1 * a1 + a2 * a2) / 2.0;
        let integral: f64 = spectrum.density.iter().sum::<f64>() * d_omega;
        assert!((integral - variance).abs() < 1e-9 * variance);

        let peak1 = a1 * a1 / 2.0 / (1.5 * d_omega);
        let peak2 = a2 * a2 / 2.0 / (1.5 * d_omega);
        for (k, d) in spectrum.density.iter().enumerate() {
            let expected = match k {
                k if k == k1 => peak1,
                k if k + 1 == k1 || k == k1 + 1 => peak1 / 4.0,
                k if k == k2 => peak2,
                k if k + 1 == k2 || k == k2 + 1 => peak2 / 4.0,
                _ => 0.0,
            };
            assert!(
                (d - expected).abs() < 1e-9 * peak1,
                "bin {k}: {d} vs {expected}"
            );
        }
        assert!((spectrum.omega[k1] - w1).abs() < EXACT);
        assert!((spectrum.omega[k2] - w2).abs() < EXACT);
    }

    #[test]
    fn welch_white_noise_is_flat() {
        // White Gaussian noise of variance s^2: one-sided density s^2 dt / pi per rad/s.
        // Bins 0 and 1 (mean removal) and the Nyquist bin (not doubled) are left out.
        // Tolerances: 5 sigma, with the relative std of one bin sqrt(F/K) and of an average
        // of B bins sqrt(F G / (K B)) (see OVERLAP_FACTOR, ADJACENT_FACTOR).
        let (len, dt, std) = (256, 0.25, 2.0);
        let record = gaussian_noise(11, 1 << 16, std);
        let spectrum = welch_spectrum(&record, dt, len).unwrap();
        let segments = 1 + (record.len() - len) / (len / 2);
        let expected = std * std * dt / PI;

        let interior = &spectrum.density[2..len / 2];
        let bin_tolerance = SIGMAS * (OVERLAP_FACTOR / segments as f64).sqrt();
        for (k, d) in interior.iter().enumerate() {
            let relative = d / expected - 1.0;
            assert!(relative.abs() < bin_tolerance, "bin {}: {relative}", k + 2);
        }
        let average = interior.iter().sum::<f64>() / interior.len() as f64;
        let band_tolerance = SIGMAS * band_relative_std(segments, interior.len());
        assert!(
            (average / expected - 1.0).abs() < band_tolerance,
            "average {average} vs {expected} (tolerance {band_tolerance})"
        );
    }

    #[test]
    fn welch_ar1_matches_closed_form() {
        // x_{m+1} = phi x_m + e_m, e_m ~ N(0, s_e^2), started from the stationary law
        // N(0, s_e^2 / (1 - phi^2)): one-sided density s_e^2 dt / (pi |1 - phi e^{-i w dt}|^2).
        // Welch's estimate, averaged over bands of B bins (bins 2 .. L/2), is checked
        // against the band average of the closed form within 5 sigma of the band
        // (sqrt(F G / (K B)) relative). The Hann window's smoothing bias for phi = 0.7 and
        // L = 256 is below 0.15 % per bin (computed from the exact expectation of the
        // windowed periodogram), negligible beside the 5.9 % tolerance.
        let (len, dt, phi, std_e): (usize, f64, f64, f64) = (256, 0.5, 0.7, 1.0);
        let count = 1 << 17;
        let innovations = gaussian_noise(23, count, std_e);
        let mut record = Vec::with_capacity(count);
        let mut x = gaussian_noise(29, 1, std_e / (1.0 - phi * phi).sqrt())[0];
        for e in &innovations {
            record.push(x);
            x = phi * x + e;
        }
        let spectrum = welch_spectrum(&record, dt, len).unwrap();
        let segments = 1 + (record.len() - len) / (len / 2);
        let closed_form = |omega: f64| {
            let denominator = 1.0 - 2.0 * phi * (omega * dt).cos() + phi * phi;
            std_e * std_e * dt / (PI * denominator)
        };

        const BAND: usize = 14;
        let tolerance = SIGMAS * band_relative_std(segments, BAND);
        for start in (2..len / 2).step_by(BAND) {
            let bins = start..start + BAND;
            let estimate: f64 = spectrum.density[bins.clone()].iter().sum();
            let exact: f64 = spectrum.omega[bins].iter().map(|&w| closed_form(w)).sum();
            let relative = estimate / exact - 1.0;
            assert!(
                relative.abs() < tolerance,
                "band from bin {start}: {relative} (tolerance {tolerance})"
            );
        }
    }
}
