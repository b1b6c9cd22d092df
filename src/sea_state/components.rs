//! Random wave components by filtering seeded white Gaussian noise (E&S 5, 6;
//! docs/theory.md#random-waves).
//!
//! Convention: the elevation at the body origin is eta(t) = Re sum_n a_n e^{i omega_n tau},
//! tau = t - t0, with omega_n = n d_omega and d_omega = 2 pi / (N dt). A component that
//! propagates in direction beta has the phase e^{-i k_n (x cos beta + y sin beta)} at (x, y).

use super::{Direction, SeaState};
use crate::error::numbers::{readable, typable_below, written};
use crate::error::{Error, Result};
use rand_xoshiro::rand_core::{Rng, SeedableRng};
use rand_xoshiro::{SplitMix64, Xoshiro256PlusPlus};
use rustfft::num_complex::Complex64;
use std::f64::consts::PI;

/// Extra samples past the run's end so that the last RK4 stage and the 4-point
/// interpolation stencil stay inside the record.
const RECORD_TAIL_SAMPLES: usize = 3;
/// Longest record accepted (2^24 samples: 97 days at 0.5 s), so that a huge duration is a
/// clear error instead of an allocation failure that would abort the process.
const MAX_RECORD_SAMPLES: usize = 1 << 24;

/// The common time and frequency grid of every record: N samples at spacing dt, and the
/// wave components n = first .. first + count - 1 at omega_n = n d_omega.
#[derive(Debug, Clone, PartialEq)]
pub struct FrequencyGrid {
    /// Time of sample 0, s.
    pub start_time: f64,
    /// Sample spacing of every record, s.
    pub dt: f64,
    /// Record length N (samples); the record repeats after N dt.
    pub len: usize,
    /// Frequency spacing 2 pi / (N dt), rad/s.
    pub d_omega: f64,
    /// Index n of the first wave component.
    pub first: usize,
    /// Number of wave components.
    pub count: usize,
}

impl FrequencyGrid {
    /// A grid whose records cover `duration` (plus a few samples) at spacing `dt`, and whose
    /// components cover the band [omega_min, omega_max]. The length is the smallest
    /// 2^a 3^b 5^c 7^d that is long enough, so the FFTs stay fast.
    pub fn new(start_time: f64, duration: f64, dt: f64, band: (f64, f64)) -> Result<Self> {
        let samples = (duration / dt).ceil();
        if !(samples.is_finite() && samples <= MAX_RECORD_SAMPLES as f64) {
            return Err(Error::invalid(
                "run.duration",
                duration,
                format!(
                    "needs {} record samples at {} s; at most {MAX_RECORD_SAMPLES} (about 128 \
                     MiB per record) are allowed: split the run or raise the time step",
                    readable(samples),
                    readable(dt)
                ),
            ));
        }
        let needed = samples as usize + RECORD_TAIL_SAMPLES;
        let len = smooth_length_at_least(needed);
        let d_omega = 2.0 * PI / (len as f64 * dt);
        let first = ((band.0 / d_omega).ceil() as usize).max(1);
        let last = (band.1 / d_omega).floor() as usize;
        let nyquist = PI / dt;
        if band.1 >= nyquist {
            return Err(Error::invalid(
                "run.time_step",
                2.0 * dt,
                format!(
                    "records are sampled at time_step/2 = {} s, whose Nyquist frequency {} \
                     rad/s is below the wave band's top {} rad/s: use time_step = {} s or \
                     less, or a [sea] band that ends below {} rad/s",
                    readable(dt),
                    readable(nyquist),
                    readable(band.1),
                    typable_below(2.0 * PI / band.1),
                    readable(nyquist)
                ),
            ));
        }
        if last < first {
            return Err(Error::invalid(
                "sea.band",
                format!("[{}, {}]", written(band.0), written(band.1)),
                format!(
                    "holds no frequency of the grid (d_omega = {} rad/s)",
                    readable(d_omega)
                ),
            ));
        }
        Ok(FrequencyGrid {
            start_time,
            dt,
            len,
            d_omega,
            first,
            count: last - first + 1,
        })
    }

    /// Frequency of the j-th component (j = 0 .. count), rad/s.
    pub fn omega(&self, j: usize) -> f64 {
        (self.first + j) as f64 * self.d_omega
    }

    /// Time of the m-th sample, s.
    pub fn time(&self, m: usize) -> f64 {
        self.start_time + m as f64 * self.dt
    }

    /// Last time a record can be evaluated at (the interpolation stencil included), s.
    pub fn end_time(&self) -> f64 {
        self.time(self.len - 2)
    }
}

/// The generator of block `k` of the sea with seed `seed`. Block 0: xoshiro256++ seeded
/// from `seed` (its four state words are SplitMix64's first four outputs from `seed`).
/// Block k >= 1: the state (first two SplitMix64 outputs from `seed`, first two from k),
/// one state per (seed, k) (SplitMix64's output is a bijection of its state), set in O(1)
/// for any k. Distinct states lie on xoshiro256++'s one cycle of 2^256 - 1, so the draws of
/// a block (a few 10^5) overlap another block's with probability of order 10^-60.
fn block_generator(seed: u64, k: u64) -> Xoshiro256PlusPlus {
    if k == 0 {
        return Xoshiro256PlusPlus::seed_from_u64(seed);
    }
    let mut of_seed = SplitMix64::seed_from_u64(seed);
    let mut of_block = SplitMix64::seed_from_u64(k);
    let words = [
        of_seed.next_u64(),
        of_seed.next_u64(),
        of_block.next_u64(),
        of_block.next_u64(),
    ];
    let mut state = [0u8; 32];
    for (chunk, word) in state.chunks_exact_mut(8).zip(words) {
        chunk.copy_from_slice(&word.to_le_bytes());
    }
    Xoshiro256PlusPlus::from_seed(state)
}

/// The gusts' complex amplitudes of block `k` of the wind with seed `seed`: b_n = scale_n
/// (xi + i xi'), xi, xi' independent standard normal, in increasing frequency, written into
/// `out` (its length that of `scale`). Their generator is the waves' of (seed, k)
/// (`block_generator`) after xoshiro256++'s long jump, 2^192 draws ahead: a stream of its
/// own that no block's wave draws (a few 10^5) reach, so the wind and the waves of one seed
/// are independent, a seed gives the same gusts whatever the waves, and adding wind leaves
/// the sea as it was (its draws are untouched).
pub fn gust_amplitudes(seed: u64, k: u64, scale: &[f64], out: &mut Vec<Complex64>) {
    let mut rng = block_generator(seed, k);
    rng.long_jump();
    out.clear();
    out.extend(scale.iter().map(|&s| {
        let (xi, xi_prime) = standard_normal_pair(&mut rng);
        Complex64::new(s * xi, s * xi_prime)
    }));
}

/// Smallest integer >= n whose only prime factors are 2, 3, 5 and 7.
fn smooth_length_at_least(n: usize) -> usize {
    (n.max(1)..)
        .find(|&m| {
            let mut r = m;
            for p in [2, 3, 5, 7] {
                while r % p == 0 {
                    r /= p;
                }
            }
            r == 1
        })
        .expect("smooth numbers are unbounded")
}

/// Complex amplitudes a_{n,k} of every component and direction.
#[derive(Debug, Clone, PartialEq)]
pub struct WaveComponents {
    pub grid: FrequencyGrid,
    pub directions: Vec<Direction>,
    /// Direction-major: `amplitudes[k * grid.count + j]` is a_{first + j, k}, m.
    amplitudes: Vec<Complex64>,
    /// E sum_k |a_{first + j, k}|^2 = 2 S(omega_j) d_omega sum_k w_k, m^2: the same for
    /// every block.
    power: Vec<f64>,
    /// Direction-major like `amplitudes`: sqrt(S(omega_j) w_k d_omega), m, the scale of
    /// every draw: the same for every block and seed, so computed once.
    scales: Vec<f64>,
}

impl WaveComponents {
    /// a_{n,k} = sqrt(S(omega_n) w_k d_omega) (xi + i xi'), with xi, xi' independent
    /// standard normal from one xoshiro256++ stream seeded by `sea.seed`, drawn direction by
    /// direction, in increasing frequency. So |a| is Rayleigh, its phase uniform and
    /// E|a|^2 = 2 S w_k d_omega (docs/theory.md#random-waves).
    pub fn generate(sea: &SeaState, grid: FrequencyGrid) -> Self {
        Self::generate_block(sea, grid, 0)
    }

    /// The amplitudes of block `k` of a stream of records (`forces::stream`): as
    /// [`WaveComponents::generate`], from the generator of (`sea.seed`, k)
    /// (`block_generator`), so that every block's draws depend only on (seed, k), cost
    /// the same for any k, and are independent of every other block's. Block 0 is
    /// [`WaveComponents::generate`].
    pub fn generate_block(sea: &SeaState, grid: FrequencyGrid, k: u64) -> Self {
        let mut components = Self::undrawn(sea, grid);
        components.regenerate(sea.seed, k);
        components
    }

    /// The components of `sea` on `grid` before any draw: their scales and expected power
    /// (every draw's variance S(omega_j) w_k d_omega, summed over the directions in order),
    /// no amplitudes yet ([`WaveComponents::regenerate`] draws them).
    pub fn undrawn(sea: &SeaState, grid: FrequencyGrid) -> Self {
        let directions = sea.directions();
        let mut power = vec![0.0; grid.count];
        let mut scales = Vec::with_capacity(directions.len() * grid.count);
        for dir in &directions {
            for (j, p) in power.iter_mut().enumerate() {
                let variance = sea.spectrum.density(grid.omega(j)) * dir.weight * grid.d_omega;
                scales.push(variance.sqrt());
                *p += 2.0 * variance;
            }
        }
        WaveComponents {
            directions,
            grid,
            amplitudes: Vec::new(),
            power,
            scales,
        }
    }

    /// These components redrawn as block `k`'s of the sea they were made for with seed
    /// `seed`, in place: [`WaveComponents::generate_block`] of that sea with that seed,
    /// without allocating or evaluating the spectrum.
    pub fn regenerate(&mut self, seed: u64, k: u64) {
        let mut rng = block_generator(seed, k);
        self.amplitudes.clear();
        self.amplitudes.extend(self.scales.iter().map(|&scale| {
            let (xi, xi_prime) = standard_normal_pair(&mut rng);
            Complex64::new(scale * xi, scale * xi_prime)
        }));
    }

    /// The expected power of component j summed over the directions, E sum_k |a_{j,k}|^2
    /// (m^2), indexed by component j: the same for every block and seed.
    pub fn expected_power(&self) -> &[f64] {
        &self.power
    }

    /// [`WaveComponents::expected_power`] of `sea` on `grid` without drawing the amplitudes
    /// (the same sums in the same order, so the same bits).
    pub fn expected_power_of(sea: &SeaState, grid: &FrequencyGrid) -> Vec<f64> {
        Self::undrawn(sea, grid.clone()).power
    }

    /// Amplitudes of direction k, indexed by component j.
    pub fn of_direction(&self, k: usize) -> &[Complex64] {
        &self.amplitudes[k * self.grid.count..(k + 1) * self.grid.count]
    }

    /// Amplitudes of the directions `range`, direction-major (`[(k - start) * count + j]`).
    pub fn of_directions(&self, range: std::ops::Range<usize>) -> &[Complex64] {
        &self.amplitudes[range.start * self.grid.count..range.end * self.grid.count]
    }
}

/// Two independent standard normal numbers by the Box-Muller transform (exact, no tables).
fn standard_normal_pair(rng: &mut Xoshiro256PlusPlus) -> (f64, f64) {
    const UNIT: f64 = 1.0 / (1u64 << 53) as f64;
    // u1 in (0, 1] so that ln(u1) is finite; u2 in [0, 1).
    let u1 = ((rng.next_u64() >> 11) + 1) as f64 * UNIT;
    let u2 = (rng.next_u64() >> 11) as f64 * UNIT;
    let radius = (-2.0 * u1.ln()).sqrt();
    let (sin, cos) = (2.0 * PI * u2).sin_cos();
    (radius * cos, radius * sin)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The power of a sea computed without drawing equals the drawn components' (bit for
    /// bit: a record plan's depth kernels are reused only on equal power), for a spread sea
    /// and another seed and block.
    #[test]
    fn expected_power_without_drawing() {
        use crate::sea_state::{Spectrum, Spreading};
        let sea = SeaState {
            spectrum: Spectrum::Jonswap {
                hs: 5.0,
                tp: 11.0,
                gamma: Some(2.0),
            },
            spreading: Spreading::CosN { n: 2.0 },
            mean_direction: 0.3,
            n_directions: 7,
            seed: 11,
            band: None,
        };
        let grid = FrequencyGrid::new(0.0, 900.0, 0.5, sea.band()).unwrap();
        let power = WaveComponents::expected_power_of(&sea, &grid);
        assert_eq!(power.len(), grid.count);
        assert!(power.iter().any(|&p| p > 0.0));
        assert_eq!(
            WaveComponents::generate(&sea, grid.clone()).expected_power(),
            power
        );
        let other = SeaState {
            seed: 12,
            ..sea.clone()
        };
        assert_eq!(
            WaveComponents::generate_block(&other, grid, 3).expected_power(),
            power
        );
    }

    #[test]
    fn smooth_lengths() {
        assert_eq!(smooth_length_at_least(1), 1);
        assert_eq!(smooth_length_at_least(11), 12);
        assert_eq!(smooth_length_at_least(43203), 43218);
        assert_eq!(smooth_length_at_least(1024), 1024);
    }

    /// Block 0's generator is the seed's (its state: SplitMix64's first four outputs, as
    /// block_generator's doc says); blocks differ from each other and from other seeds'
    /// blocks, and any block, however far, is made at once.
    #[test]
    fn block_generators() {
        let first = |mut g: Xoshiro256PlusPlus| [g.next_u64(), g.next_u64(), g.next_u64()];
        let mut sm = SplitMix64::seed_from_u64(7);
        let mut state = [0u8; 32];
        for chunk in state.chunks_exact_mut(8) {
            chunk.copy_from_slice(&sm.next_u64().to_le_bytes());
        }
        assert_eq!(
            first(Xoshiro256PlusPlus::from_seed(state)),
            first(Xoshiro256PlusPlus::seed_from_u64(7))
        );
        assert_eq!(
            first(block_generator(7, 0)),
            first(Xoshiro256PlusPlus::seed_from_u64(7))
        );
        let mut seen = Vec::new();
        for seed in 0..20 {
            for k in [0, 1, 2, 3, 1 << 40, u64::MAX] {
                seen.push(first(block_generator(seed, k)));
            }
        }
        let n = seen.len();
        seen.sort();
        seen.dedup();
        assert_eq!(seen.len(), n, "every (seed, block) has its own draws");
    }

    #[test]
    fn box_muller_moments() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(7);
        let n = 200_000;
        let (mut s1, mut s2, mut s4, mut cross) = (0.0, 0.0, 0.0, 0.0);
        for _ in 0..n {
            let (a, b) = standard_normal_pair(&mut rng);
            s1 += a + b;
            s2 += a * a + b * b;
            s4 += a.powi(4) + b.powi(4);
            cross += a * b;
        }
        let m = 2.0 * n as f64;
        // standard errors: mean 1/sqrt(m), variance sqrt(2/m), kurtosis sqrt(96/m)
        assert!((s1 / m).abs() < 5.0 / m.sqrt());
        assert!((s2 / m - 1.0).abs() < 5.0 * (2.0 / m).sqrt());
        assert!((s4 / m - 3.0).abs() < 5.0 * (96.0 / m).sqrt());
        assert!((cross / (m / 2.0)).abs() < 5.0 / (m / 2.0).sqrt());
    }
}
