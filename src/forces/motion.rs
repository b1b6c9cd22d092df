//! Wave-frequency (first-order) motion records: the rigid body's linear response to the same
//! wave components as the force records (docs/theory.md#wave-frequency-motion).
//!
//! For DOF i (surge, sway, heave, roll, pitch, yaw) of the body reference point, in the
//! body-related frame that follows the slow drift (SIMO's convention: axes turned by the
//! slow yaw theta), with the RAOs xi_i(omega, beta) of `hydro::rao` (Re{xi e^{i omega t}},
//! phase relative to the elevation at the reference point):
//!
//! ```text
//! x_i(t)  = Re sum_j c_ij e^{i omega_j t},        c_ij = sum_k a_jk xi_i(omega_j, beta_k - theta)
//! x_i'(t) = Re sum_j i omega_j c_ij e^{i omega_j t}
//! ```
//!
//! a_jk the amplitudes of direction k (`sea_state::WaveComponents`, the elevation at the
//! origin is Re sum_jk a_jk e^{i omega_j t}), beta_k its heading (towards which it
//! propagates, from +X), theta the body yaw the records are made at: zero (the mean
//! position, as the force records), or every yaw of the yaw-following grid, between which
//! the records are interpolated linearly in the instantaneous slow yaw, as the force records
//! are (`forces::yaw_following`). The RAOs are interpolated linearly in frequency and in the
//! relative heading (real and imaginary parts apart), across the closing gap when their
//! headings cover the circle, and never beyond their grid: outside their frequencies the
//! motion is zero, which the problem allows for at most 1 % of the band's variance
//! (`Problem::check_rao_gap`), and a relative heading outside their headings is refused.
//!
//! Cost: the position and the velocity of two DOFs share one transform (two real series in
//! one, `Synthesizer::append_two_real_series`): six transforms per segment and body yaw,
//! one per DOF. The records are linear signals, so the stream joins them as it joins the
//! elevation (`forces::stream`).

use super::record::{Record, SamplePoint};
use super::synthesis::Synthesizer;
use super::yaw_following::YawPoint;
use crate::error::{Error, Result};
use crate::hydro::heading_grid::{heading_bracket, Bracket};
use crate::hydro::rao::Rao;
use crate::model::FREQUENCY_MATCH_TOLERANCE;
use crate::sea_state::{Direction, FrequencyGrid, WaveComponents};
use rustfft::num_complex::Complex64;

/// The RAOs of the six DOFs on a frequency grid, for one wave direction at one body yaw.
#[derive(Debug, Clone, PartialEq)]
pub struct MotionTransfer {
    /// `rao[j][i]`: xi_i(omega_j, beta - theta) at the grid's frequency j.
    rao: Vec<[Complex64; 6]>,
}

/// The RAOs of every direction of `directions` on `grid`'s frequencies, at the relative
/// headings beta_k - `yaw`; zero at a frequency outside the RAOs' (the problem bounds the
/// variance there: `Problem::check_rao_gap`). Refused: a relative heading outside their
/// headings (nothing is extrapolated); the error names the gap and the remedies.
pub fn motion_transfers(
    rao: &Rao,
    grid: &FrequencyGrid,
    directions: &[Direction],
    yaw: f64,
) -> Result<Vec<MotionTransfer>> {
    directions
        .iter()
        .map(|d| {
            let along = RaoAlong::new(rao, d.heading - yaw)?;
            Ok(MotionTransfer {
                rao: (0..grid.count).map(|j| along.at(grid.omega(j))).collect(),
            })
        })
        .collect()
}

/// The RAOs at one relative heading (interpolated linearly between the two headings that
/// bracket it), as a function of frequency: the interpolation of the records and of the
/// frequency-domain predictions (`studies::motion_spectra`).
#[derive(Debug, Clone, Copy)]
pub struct RaoAlong<'a> {
    rao: &'a Rao,
    bracket: Bracket,
}

impl<'a> RaoAlong<'a> {
    /// The RAOs at the relative heading `relative` (rad, any number of turns). Refused: a
    /// heading outside their headings (nothing is extrapolated); the error names the gap and
    /// the remedies.
    pub fn new(rao: &'a Rao, relative: f64) -> Result<Self> {
        let bracket = heading_bracket(&rao.headings, relative).ok_or_else(|| {
            Error::invalid(
                "first-order motions",
                format!("the relative heading {:.3} deg", relative.to_degrees()),
                format!(
                    "is outside the RAOs' headings [{:.3}, {:.3}] deg (nothing is \
                     extrapolated): give RAOs at those headings, turn the sea, or turn \
                     the wave-frequency motion off ([model] wave_frequency_motion = \
                     \"off\")",
                    rao.headings[0].to_degrees(),
                    rao.headings[rao.headings.len() - 1].to_degrees()
                ),
            )
        })?;
        Ok(RaoAlong { rao, bracket })
    }

    /// xi_i(omega) of the six DOFs, linear in frequency between the RAOs' frequencies (real
    /// and imaginary parts apart); zero outside them (within the frequency tolerance).
    pub fn at(&self, omega: f64) -> [Complex64; 6] {
        let omegas = &self.rao.omegas;
        let (lo, hi) = (omegas[0], omegas[omegas.len() - 1]);
        let covered = omega >= lo * (1.0 - FREQUENCY_MATCH_TOLERANCE)
            && omega <= hi * (1.0 + FREQUENCY_MATCH_TOLERANCE);
        if !covered {
            return [Complex64::default(); 6];
        }
        if omegas.len() == 1 {
            return self.along(0);
        }
        let w = omega.clamp(lo, hi);
        let upper = omegas
            .partition_point(|&v| v <= w)
            .clamp(1, omegas.len() - 1);
        let s = (w - omegas[upper - 1]) / (omegas[upper] - omegas[upper - 1]);
        let (a, b) = (self.along(upper - 1), self.along(upper));
        std::array::from_fn(|i| a[i] * (1.0 - s) + b[i] * s)
    }

    /// The RAOs at frequency index `n`, interpolated in heading.
    fn along(&self, n: usize) -> [Complex64; 6] {
        let h = &self.bracket;
        let (a, b) = (&self.rao.values[n][h.lo], &self.rao.values[n][h.hi]);
        std::array::from_fn(|i| a[i] * (1.0 - h.frac) + b[i] * h.frac)
    }
}

/// Which of the six DOFs move in the sea of `power` (expected power per component, summed
/// over the directions) through `transfers` (one yaw's, per direction): those whose
/// sum_j p_j sum_k |X_ki(omega_j)|^2 (a bound on the expected variance, p_j holding every
/// direction's power) exceeds [`STILL`]^2 times the largest DOF's. A DOF below it (sway, roll and yaw of a symmetric platform in head seas, whose
/// radiation-diffraction RAOs are 1e-15 of surge's) moves less than the rounding a transform
/// shared with a moving DOF already gives it, so its records are zero ([`Record::zero`]: no
/// memory) and its transforms are not made. The choice depends on the spectrum and the RAOs only, not on the seed: every
/// segment of a simulation asks the stream for the same series in the same order.
fn moving_dofs(transfers: &[MotionTransfer], power: &[f64]) -> [bool; 6] {
    let mut variance = [0.0f64; 6];
    for transfer in transfers {
        for (xi, p) in transfer.rao.iter().zip(power) {
            for (v, x) in variance.iter_mut().zip(xi) {
                *v += p * x.norm_sqr();
            }
        }
    }
    let largest = variance.iter().copied().fold(0.0, f64::max);
    variance.map(|v| v > STILL * STILL * largest)
}

/// The rms of a DOF's motion, relative to the largest DOF's (in their SI units, m and rad),
/// below which its records are zero ([`moving_dofs`]): far below a transform's rounding
/// (about 1e-16 of the series sharing it) times its size, and any motion of consequence.
const STILL: f64 = 1e-12;

/// The wave-frequency motion of one body yaw: position and velocity of the six DOFs, body
/// frame (m, rad; m/s, rad/s).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct MotionSet {
    pub position: [Record; 6],
    pub velocity: [Record; 6],
}

impl MotionSet {
    /// Record `i` of position (0 .. 6) then velocity (6 .. 12).
    fn record_mut(&mut self, i: usize) -> &mut Record {
        if i < 6 {
            &mut self.position[i]
        } else {
            &mut self.velocity[i - 6]
        }
    }
}

/// The buffer of `record`, emptied (its capacity kept), the record left zero.
fn emptied(record: &mut Record) -> Vec<f64> {
    let mut buffer = std::mem::take(record).into_samples();
    buffer.clear();
    buffer
}

/// A sink that writes each complex sample's real part into its first buffer and its
/// imaginary part into its second (two real series of one transform).
struct Split(Vec<f64>, Vec<f64>);

impl Extend<Complex64> for Split {
    fn extend<I: IntoIterator<Item = Complex64>>(&mut self, samples: I) {
        let samples = samples.into_iter();
        let (more, _) = samples.size_hint();
        self.0.reserve(more);
        self.1.reserve(more);
        for c in samples {
            self.0.push(c.re);
            self.1.push(c.im);
        }
    }
}

/// The wave-frequency motion records of a segment: one set at zero yaw, or one per yaw of
/// the yaw-following grid (the same grid as the force records').
#[derive(Debug, Clone, PartialEq, Default)]
pub struct MotionRecords {
    pub sets: Vec<MotionSet>,
}

/// The buffers of the motion records' synthesis.
#[derive(Debug, Clone, Default)]
pub struct MotionWork {
    /// c_ij per DOF, then i omega_j c_ij per DOF.
    coefficients: [Vec<Complex64>; 12],
}

impl MotionRecords {
    /// The records of `components` for `transfers[set][direction]` (one set per body yaw),
    /// written into these records' buffers.
    pub fn rebuild(
        &mut self,
        components: &WaveComponents,
        transfers: &[Vec<MotionTransfer>],
        synth: &mut Synthesizer,
        work: &mut MotionWork,
    ) {
        let grid = &components.grid;
        self.sets.resize_with(transfers.len(), MotionSet::default);
        for (set, directions) in self.sets.iter_mut().zip(transfers) {
            for c in work.coefficients.iter_mut() {
                c.clear();
                c.resize(grid.count, Complex64::default());
            }
            for (k, transfer) in directions.iter().enumerate() {
                let amplitudes = components.of_direction(k);
                for (j, (a, xi)) in amplitudes.iter().zip(&transfer.rao).enumerate() {
                    for (c, x) in work.coefficients.iter_mut().zip(xi) {
                        c[j] += a * x;
                    }
                }
            }
            let i_omega = |j: usize| Complex64::new(0.0, grid.omega(j));
            for i in 0..6 {
                let (position, velocity) = work.coefficients.split_at_mut(6);
                for (j, (v, c)) in velocity[i].iter_mut().zip(&position[i]).enumerate() {
                    *v = i_omega(j) * c;
                }
            }
            // The series of the DOFs that move, two to a transform (positions, then
            // velocities, in DOF order); the others' records are zero.
            let moving = moving_dofs(directions, components.expected_power());
            let (mut series, mut count) = ([0; 12], 0);
            for x in (0..12).filter(|&x| moving[x % 6]) {
                series[count] = x;
                count += 1;
            }
            // (An even count: a DOF's position and velocity move together.)
            for pair in series[..count].chunks_exact(2) {
                let (x, y) = (pair[0], pair[1]);
                // The pair's samples written straight into the two records' buffers.
                let mut split = Split(emptied(set.record_mut(x)), emptied(set.record_mut(y)));
                synth.append_two_real_series(
                    &work.coefficients[x],
                    &work.coefficients[y],
                    &mut split,
                );
                let Split(re, im) = split;
                (*set.record_mut(x), *set.record_mut(y)) = (Record::new(re), Record::new(im));
            }
            for x in (0..12).filter(|&x| !moving[x % 6]) {
                *set.record_mut(x) = Record::zero();
            }
        }
    }

    /// The position and velocity of the six DOFs at a located time and yaw, body frame:
    /// linear in the yaw between the grid's records (exactly a grid yaw's records there).
    pub fn at(&self, at: &SamplePoint, yaw: &YawPoint) -> ([f64; 6], [f64; 6]) {
        let (lo, hi, frac) = yaw.parts();
        let (lo, hi) = (&self.sets[lo], &self.sets[hi]);
        let blend = |a: &Record, b: &Record| {
            let x = a.at(at);
            if frac == 0.0 {
                x
            } else {
                x + frac * (b.at(at) - x)
            }
        };
        (
            std::array::from_fn(|i| blend(&lo.position[i], &hi.position[i])),
            std::array::from_fn(|i| blend(&lo.velocity[i], &hi.velocity[i])),
        )
    }
}

/// The slow drift plus the wave-frequency motion (docs/theory.md#wave-frequency-motion):
/// `wave_frequency` is the body-frame motion x_wf of [`MotionRecords::at`] turned into the
/// inertial axes, the totals the slow drift's (X, Y, 0, 0, 0, theta) plus it, and the rates
/// their exact time derivatives.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WholeMotion {
    /// (X_wf, Y_wf, Z_wf, roll_wf, pitch_wf, yaw_wf), inertial axes: m, rad.
    pub wave_frequency: [f64; 6],
    /// (X, Y, Z, roll, pitch, yaw) totals: m, rad.
    pub total: [f64; 6],
    /// Their time derivatives: m/s, rad/s.
    pub total_rate: [f64; 6],
}

impl WholeMotion {
    /// The whole motion of a slow drift (position q = (X, Y, theta), velocity qd) with the
    /// body-frame wave-frequency motion x_b and its rate v_b. With R(theta) the rotation by
    /// theta about Z, translations and the small rotation vector (roll, pitch) turn alike:
    ///
    /// ```text
    /// [X_wf, Y_wf]         = R(theta) [x_b0, x_b1],   [roll_wf, pitch_wf] = R(theta) [x_b3, x_b4]
    /// Z_wf = x_b2,  yaw_wf = x_b5
    /// X_total = X + X_wf, Y_total = Y + Y_wf, Z_total = Z_wf, roll_total = roll_wf,
    /// pitch_total = pitch_wf, yaw_total = theta + yaw_wf
    /// d/dt R(theta) u = R(theta) u' + theta' R(theta + pi/2) u
    /// ```
    ///
    /// (roll and pitch are small rotations about the inertial X and Y axes: the body's
    /// orientation is (I + [roll, pitch, 0]x) R(yaw_total) to first order in them).
    pub fn of(q: [f64; 3], qd: [f64; 3], x_b: [f64; 6], v_b: [f64; 6]) -> Self {
        let (s, c) = q[2].sin_cos();
        let turn = |u: f64, v: f64| [c * u - s * v, s * u + c * v];
        let rate = |u: f64, v: f64, du: f64, dv: f64| {
            let [a, b] = turn(du, dv);
            let [p, r] = turn(u, v);
            // d/dt R(theta) = theta' R(theta) J, J u = (-u_1, u_0): R(theta) J u = (-r, p)
            // with (p, r) = R(theta) u.
            [a - qd[2] * r, b + qd[2] * p]
        };
        let [x, y] = turn(x_b[0], x_b[1]);
        let [roll, pitch] = turn(x_b[3], x_b[4]);
        let wave_frequency = [x, y, x_b[2], roll, pitch, x_b[5]];
        let [xd, yd] = rate(x_b[0], x_b[1], v_b[0], v_b[1]);
        let [rolld, pitchd] = rate(x_b[3], x_b[4], v_b[3], v_b[4]);
        WholeMotion {
            wave_frequency,
            total: [q[0] + x, q[1] + y, x_b[2], roll, pitch, q[2] + x_b[5]],
            total_rate: [
                qd[0] + xd,
                qd[1] + yd,
                v_b[2],
                rolld,
                pitchd,
                qd[2] + v_b[5],
            ],
        }
    }

    /// The slow drift alone (no wave-frequency motion).
    pub fn slow_drift(q: [f64; 3], qd: [f64; 3]) -> Self {
        Self::of(q, qd, [0.0; 6], [0.0; 6])
    }
}

#[cfg(test)]
mod tests {
    use super::super::synthesis::SINGLE_PRECISION_ERROR;
    use super::*;

    /// RAOs interpolated linearly in frequency and heading, zero outside their frequencies,
    /// and a table of one frequency read at it without a bracket.
    #[test]
    fn transfers_interpolate_inside_and_are_zero_outside() {
        let grid = FrequencyGrid::new(0.0, 200.0, 0.5, (0.3, 1.2)).unwrap();
        let value = |w: f64, h: f64| Complex64::new(w, h);
        let omegas = vec![0.2, 0.6, 1.0];
        let headings = vec![0.0, 1.0];
        let rao = Rao {
            values: omegas
                .iter()
                .map(|&w| headings.iter().map(|&h| [value(w, h); 6]).collect())
                .collect(),
            omegas,
            headings,
        };
        let direction = [Direction {
            heading: 0.75,
            weight: 1.0,
        }];
        let t = motion_transfers(&rao, &grid, &direction, 0.5).unwrap();
        for (j, xi) in t[0].rao.iter().enumerate() {
            let w = grid.omega(j);
            // Bilinear in (w, relative heading 0.25): exact for a function linear in both.
            let expected = if w <= 1.0 {
                value(w, 0.25)
            } else {
                Complex64::default()
            };
            assert!(
                (xi[3] - expected).norm() < 1e-12,
                "omega {w}: {} vs {expected}",
                xi[3]
            );
        }
        let single = Rao {
            omegas: vec![0.6],
            headings: vec![0.0],
            values: vec![vec![[value(0.6, 0.0); 6]]],
        };
        let one = [Direction {
            heading: 0.0,
            weight: 1.0,
        }];
        let t = motion_transfers(&single, &grid, &one, 0.0).unwrap();
        assert!(t[0]
            .rao
            .iter()
            .all(|xi| xi[0] == Complex64::default() || xi[0] == value(0.6, 0.0)));
        // A relative heading outside the headings is refused.
        let outside = [Direction {
            heading: 2.0,
            weight: 1.0,
        }];
        assert!(motion_transfers(&rao, &grid, &outside, 0.0).is_err());
    }

    /// DOFs whose RAOs are below [`STILL`] of the largest have zero records (no samples)
    /// and no transform; the others (one just above it among them) are the direct sums
    /// Re sum_j c_j e^{i omega_j t} (positions) and Re sum_j i omega_j c_j e^{i omega_j t}
    /// (velocities), c_j = a_j X(omega_j), at every sample.
    #[test]
    fn still_dofs_have_zero_records_and_the_others_their_direct_sums() {
        use crate::sea_state::{SeaState, Spectrum, Spreading};
        let grid = FrequencyGrid::new(0.0, 300.0, 0.5, (0.3, 1.4)).unwrap();
        let sea = SeaState {
            spectrum: Spectrum::Jonswap {
                hs: 6.0,
                tp: 10.0,
                gamma: None,
            },
            spreading: Spreading::LongCrested,
            mean_direction: 0.0,
            n_directions: 1,
            seed: 11,
            band: None,
        };
        let components = WaveComponents::generate(&sea, grid);
        let grid = &components.grid;
        // Relative sizes: surge 1, sway 1e-15 (still), heave 0.7, roll 1e-11 (moves),
        // pitch 0.02, yaw 1e-14 (still).
        let sizes = [1.0, 1e-15, 0.7, 1e-11, 0.02, 1e-14];
        let omegas: Vec<f64> = (0..12).map(|n| 0.2 + 0.12 * n as f64).collect();
        let rao = Rao {
            values: omegas
                .iter()
                .map(|&w| {
                    vec![std::array::from_fn(|i| {
                        Complex64::from_polar(sizes[i] / (1.0 + w), w * (i + 1) as f64)
                    })]
                })
                .collect(),
            omegas,
            headings: vec![0.0],
        };
        let direction = [Direction {
            heading: 0.0,
            weight: 1.0,
        }];
        let transfers = vec![motion_transfers(&rao, grid, &direction, 0.0).unwrap()];
        assert_eq!(
            moving_dofs(&transfers[0], components.expected_power()),
            [true, false, true, true, true, false]
        );
        let mut records = MotionRecords::default();
        let mut synth = Synthesizer::new(grid);
        records.rebuild(
            &components,
            &transfers,
            &mut synth,
            &mut MotionWork::default(),
        );
        let set = &records.sets[0];
        let amplitudes = components.of_direction(0);
        // A transform in single precision shared by two DOFs rounds each by a fraction of
        // the pair's size (`synthesis::SINGLE_PRECISION_ERROR`): each DOF within that
        // fraction of the largest record.
        let largest_of_all = set.position[0]
            .samples()
            .iter()
            .chain(set.velocity[0].samples())
            .fold(0.0f64, |m, x| m.max(x.abs()));
        for i in 0..6 {
            let (position, velocity) = (set.position[i].samples(), set.velocity[i].samples());
            if sizes[i] < STILL {
                assert!(position.is_empty() && velocity.is_empty(), "dof {i}");
                continue;
            }
            let mut worst: f64 = 0.0;
            let mut largest: f64 = 0.0;
            for m in (0..position.len()).step_by(37) {
                let t = grid.start_time + m as f64 * grid.dt;
                let (mut x, mut v) = (0.0, 0.0);
                for (j, (a, xi)) in amplitudes.iter().zip(&transfers[0][0].rao).enumerate() {
                    let w = grid.omega(j);
                    let c = a * xi[i] * Complex64::from_polar(1.0, w * t);
                    x += c.re;
                    v += (Complex64::new(0.0, w) * c).re;
                }
                worst = worst
                    .max((position[m] - x).abs())
                    .max((velocity[m] - v).abs());
                largest = largest.max(x.abs()).max(v.abs());
            }
            assert!(
                largest > 0.0 && worst < SINGLE_PRECISION_ERROR * largest_of_all,
                "dof {i}: {worst:e} of {largest:e}"
            );
        }
    }

    /// The rates are the time derivatives of the totals: central differences of a motion
    /// whose yaw and body-frame motion vary together.
    #[test]
    fn the_rates_are_the_derivatives_of_the_totals() {
        let q = |t: f64| [3.0 * t, -t * t, 0.4 + 0.3 * t];
        let qd = |t: f64| [3.0, -2.0 * t, 0.3];
        let xb = |t: f64| -> [f64; 6] { std::array::from_fn(|i| (t * (i + 1) as f64).sin()) };
        let vb = |t: f64| -> [f64; 6] {
            std::array::from_fn(|i| (i + 1) as f64 * (t * (i + 1) as f64).cos())
        };
        let t = 0.7;
        let h = 1e-5;
        let at = |t: f64| WholeMotion::of(q(t), qd(t), xb(t), vb(t));
        let (now, plus, minus) = (at(t), at(t + h), at(t - h));
        for i in 0..6 {
            let numeric = (plus.total[i] - minus.total[i]) / (2.0 * h);
            assert!(
                (numeric - now.total_rate[i]).abs() < 1e-8,
                "DOF {i}: {numeric} vs {}",
                now.total_rate[i]
            );
        }
        // At zero yaw the body frame is the inertial one.
        let still = WholeMotion::of([1.0, 2.0, 0.0], [0.0; 3], xb(t), vb(t));
        assert_eq!(still.wave_frequency, xb(t));
        // A quarter turn: the body's surge is the inertial +Y, its roll a rotation about +Y.
        let turned = WholeMotion::of(
            [0.0, 0.0, std::f64::consts::FRAC_PI_2],
            [0.0; 3],
            [1.0, 0.0, 0.0, 1.0, 0.0, 0.0],
            [0.0; 6],
        );
        assert!(turned.wave_frequency[0].abs() < 1e-15 && turned.wave_frequency[1] == 1.0);
        assert!(turned.wave_frequency[3].abs() < 1e-15 && turned.wave_frequency[4] == 1.0);
    }
}
