//! The motion spectra of a run against their frequency-domain predictions: the slow drift
//! (surge, sway, yaw) and the wave-frequency motion (six DOFs) of `slowdrift study motion`
//! (docs/theory.md#motion-spectra-in-the-frequency-domain).
//!
//! - Wave-frequency motion, DOF i: S_i(omega) = sum_k w_k |xi_i(omega, beta_k)|^2 S(omega),
//!   the RAOs at the relative headings of the mean position (yaw 0), w_k the directions'
//!   shares of the variance. Linear theory: exact for the records, up to their sampling.
//! - Slow drift, DOF i of (X, Y, theta), uncoupled: S_q(mu) = |H_i(mu)|^2 S_F,i(mu),
//!   H_i = 1 / (C_ii - (M + A)_ii mu^2 + i B_ii mu), with Newman's force spectrum from the
//!   drift table's diagonal, direction by direction (E&S 4; docs/theory.md#checks-with-known-answers):
//!   S_F,i(mu) = 8 sum_k w_k^2 integral S(omega) S(omega + mu) P(T_i(omega), T_i(omega + mu)) d omega,
//!   P = T T' where the signs agree and 0 otherwise (geometric), ((T + T')/2)^2
//!   (arithmetic). B_ii is the damping linearised about the mean position: the platform's
//!   linear damping, the mean wave-drift damping 2 sum_k w_k integral S b_ii d omega (E&S 7),
//!   the Morison drag's stochastic linearisation about the current (below) and the quadratic
//!   damping's sqrt(8/pi) Bq_ii sigma_v, sigma_v the predicted velocity's standard deviation
//!   (iterated to a fixed point).
//!
//! Drag, linearised: on a strip (E&S 8, 9), with w = u + U_c the wave particle velocity
//! plus the current (the relative velocity at rest), d(w|w|)/dw = |w| I + w w^T / |w|, so a
//! slow body velocity V adds -1/2 rho D dz C_D E[J(w)] V to the combined model's force
//! (E[J] over the Gaussian u at the strip's mean depth z, deep water: cov u = sum_k w_k
//! integral omega^2 e^{2 k z} S d omega (cos beta_k, sin beta_k)^2); the separate model's
//! slow term gives 1/2 rho D dz C_DS J(U_c). Strips at their midpoints from the keel to the
//! mean surface, the yaw rate through the strip's lever.
//!
//! Wind (docs/theory.md#wind-force), linearised about the mean wind on the body at rest at
//! the mean position: the gust force F_i ~ (dF_i/dU) u(t), so its spectrum (dF_i/dU)^2
//! S_u(mu), independent of the waves' and added to theirs, and the wind damping -dF_i/dv_i
//! added to B_ii (both by central differences of `wind::WindForce`).
//!
//! Left out, so what the comparison shows: the coupling between the DOFs, the cross terms
//! between directions of a spread sea, the full QTF's off-diagonal (Newman's rule stands
//! for it), the slowly varying parts of the damping and of the drag, the drag's own slowly
//! varying force and the wave-drift forces of the stretching, and the yaw following.

use crate::error::{Error, Result};
use crate::forces::RaoAlong;
use crate::hydro::rao::Rao;
use crate::model::{DragModel, NewmanForm};
use crate::problem::Problem;
use crate::Simulation;
use std::f64::consts::PI;

/// Frequencies of the slow-drift prediction's grid over the difference frequencies
/// [0, band width]: the force spectrum is a discrete correlation on it.
const SLOW_GRID: usize = 4001;

/// The quadrature of E[J(w)]: a midpoint rule over +-`NORMAL_SPAN` standard deviations with
/// `NORMAL_POINTS` nodes per axis (1e-4 of the folded normal's mean, `tests` below).
const NORMAL_POINTS: usize = 481;
const NORMAL_SPAN: f64 = 6.0;

/// Fixed-point iterations of the quadratic damping's linearisation (it converges in a few:
/// the velocity's deviation changes slowly with the damping).
const QUADRATIC_ITERATIONS: usize = 50;

/// The wave-frequency motion spectra of a problem.
pub struct WaveFrequencyPrediction<'a> {
    problem: &'a Problem,
    directions: Vec<(f64, RaoAlong<'a>)>,
}

impl<'a> WaveFrequencyPrediction<'a> {
    /// The prediction from `rao` (the problem's first-order motions) at the relative
    /// headings of the mean position. Refused: a direction outside the RAOs' headings.
    pub fn new(problem: &'a Problem, rao: &'a Rao) -> Result<Self> {
        let directions = problem
            .sea
            .directions()
            .iter()
            .map(|d| Ok((d.weight, RaoAlong::new(rao, d.heading)?)))
            .collect::<Result<_>>()?;
        Ok(WaveFrequencyPrediction {
            problem,
            directions,
        })
    }

    /// S_i(omega) of DOF `dof` (0..6: surge, sway, heave in m^2 s/rad; roll, pitch, yaw in
    /// rad^2 s/rad), zero outside the simulated band.
    pub fn density(&self, dof: usize, omega: f64) -> f64 {
        let (lo, hi) = self.problem.band();
        if omega < lo || omega > hi {
            return 0.0;
        }
        let s = self.problem.sea.spectrum.density(omega);
        self.directions
            .iter()
            .map(|(w, along)| w * along.at(omega)[dof].norm_sqr() * s)
            .sum()
    }
}

/// The linearised damping of one slow-drift DOF, by its source (N s/m or N m s/rad).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct DampingParts {
    /// `[platform] linear_damping`'s diagonal.
    pub linear: f64,
    /// The mean wave-drift damping.
    pub wave_drift: f64,
    /// The Morison drag's stochastic linearisation.
    pub drag: f64,
    /// The quadratic damping's equivalent linear damping.
    pub quadratic: f64,
    /// The wind's damping -dF_i/dv_i about the mean wind.
    pub wind: f64,
}

impl DampingParts {
    pub fn total(&self) -> f64 {
        self.linear + self.wave_drift + self.drag + self.quadratic + self.wind
    }
}

/// The slow drift's uncoupled linear frequency-domain model.
pub struct SlowDriftPrediction {
    /// (M + A)_ii, C_ii of (X, Y, theta).
    pub mass: [f64; 3],
    pub stiffness: [f64; 3],
    pub damping: [DampingParts; 3],
    /// Spacing of the difference-frequency grid, rad/s.
    pub d_mu: f64,
    /// S_F,i(m d_mu), m = 0 .. SLOW_GRID - 1 (N^2 s/rad, N^2 m^2 s/rad for yaw): the waves'.
    force: [Vec<f64>; 3],
    /// The gust force's spectrum on the same grid (zeros when calm).
    wind_force: [Vec<f64>; 3],
}

impl SlowDriftPrediction {
    /// The model of `problem` (its drift table, damping, drag and platform).
    pub fn new(problem: &Problem) -> Result<Self> {
        let inertia = problem.inertia()?;
        let mass = inertia.total_diagonal();
        let stiffness = std::array::from_fn(|i| problem.platform.stiffness[i][i]);
        let (lo, hi) = problem.band();
        let d_mu = (hi - lo) / (SLOW_GRID - 1) as f64;
        let omegas: Vec<f64> = (0..SLOW_GRID).map(|n| lo + n as f64 * d_mu).collect();
        let sea: Vec<f64> = omegas
            .iter()
            .map(|&w| problem.sea.spectrum.density(w))
            .collect();
        let directions = problem.sea.directions();
        let mut force: [Vec<f64>; 3] = std::array::from_fn(|_| vec![0.0; SLOW_GRID]);
        let mut wave_drift = [0.0; 3];
        let damping_table = problem.damping_table()?;
        for d in &directions {
            let drift: Vec<[f64; 3]> = omegas
                .iter()
                .map(|&w| problem.hydro.drift.drift(w, d.heading))
                .collect::<Result<_>>()?;
            for (i, spectrum) in force.iter_mut().enumerate() {
                let t: Vec<f64> = drift.iter().map(|v| v[i]).collect();
                add_force_spectrum(spectrum, &sea, &t, d.weight, d_mu, problem.model.newman);
            }
            if let Some(table) = &damping_table {
                let b: Vec<[[f64; 3]; 3]> = omegas
                    .iter()
                    .map(|&w| Ok(table.damping(w, d.heading)?.unwrap_or_default()))
                    .collect::<Result<_>>()?;
                for (i, mean) in wave_drift.iter_mut().enumerate() {
                    let f: Vec<f64> = (0..SLOW_GRID).map(|n| sea[n] * b[n][i][i]).collect();
                    *mean += 2.0 * d.weight * trapezoid(&f, d_mu);
                }
            }
        }
        let drag = drag_damping(problem);
        let (wind_damping, wind_force) = wind_linearised(problem, d_mu)?;
        let damping = std::array::from_fn(|i| DampingParts {
            linear: problem.platform.linear_damping[i][i],
            wave_drift: wave_drift[i],
            drag: drag[i][i],
            quadratic: 0.0,
            wind: wind_damping[i],
        });
        let mut prediction = SlowDriftPrediction {
            mass,
            stiffness,
            damping,
            d_mu,
            force,
            wind_force,
        };
        for i in 0..3 {
            let bq = problem.platform.quadratic_damping[i][i];
            if bq == 0.0 {
                continue;
            }
            for _ in 0..QUADRATIC_ITERATIONS {
                let sigma_v = prediction.velocity_variance(i).sqrt();
                prediction.damping[i].quadratic = (8.0 / PI).sqrt() * bq * sigma_v;
            }
        }
        Ok(prediction)
    }

    /// The difference frequencies of the grid, rad/s.
    pub fn mu(&self) -> impl Iterator<Item = f64> + '_ {
        (0..SLOW_GRID).map(|m| m as f64 * self.d_mu)
    }

    /// |H_i(mu)|^2 (m/N)^2 or (rad/(N m))^2.
    pub fn transfer_squared(&self, dof: usize, mu: f64) -> f64 {
        let real = self.stiffness[dof] - self.mass[dof] * mu * mu;
        let imag = self.damping[dof].total() * mu;
        1.0 / (real * real + imag * imag)
    }

    /// S_F,i at the grid's m-th difference frequency.
    pub fn force_density(&self, dof: usize, m: usize) -> f64 {
        self.force[dof][m]
    }

    /// S_q,i at the grid's m-th difference frequency (m^2 s/rad; rad^2 s/rad for yaw): the
    /// waves' part and the wind's.
    pub fn density(&self, dof: usize, m: usize) -> f64 {
        self.wave_density(dof, m) + self.wind_density(dof, m)
    }

    /// The waves' part of [`SlowDriftPrediction::density`].
    pub fn wave_density(&self, dof: usize, m: usize) -> f64 {
        self.force[dof][m] * self.transfer_squared(dof, m as f64 * self.d_mu)
    }

    /// The wind gusts' part of [`SlowDriftPrediction::density`] (zero when calm).
    pub fn wind_density(&self, dof: usize, m: usize) -> f64 {
        self.wind_force[dof][m] * self.transfer_squared(dof, m as f64 * self.d_mu)
    }

    /// Whether the prediction has a wind part.
    pub fn has_wind(&self) -> bool {
        self.wind_force[0].iter().any(|&s| s > 0.0)
            || self.wind_force[1].iter().any(|&s| s > 0.0)
            || self.wind_force[2].iter().any(|&s| s > 0.0)
    }

    /// The predicted variance of DOF `dof` (m^2, rad^2): the trapezoidal integral of the
    /// density over the grid (no stiffness: infinite).
    pub fn variance(&self, dof: usize) -> f64 {
        let s: Vec<f64> = (0..SLOW_GRID).map(|m| self.density(dof, m)).collect();
        trapezoid(&s, self.d_mu)
    }

    fn velocity_variance(&self, dof: usize) -> f64 {
        let s: Vec<f64> = (0..SLOW_GRID)
            .map(|m| (m as f64 * self.d_mu).powi(2) * self.density(dof, m))
            .collect();
        trapezoid(&s, self.d_mu)
    }
}

/// Adds direction weight `w`'s Newman force spectrum to `spectrum`: 8 w^2 sum_n S_n S_{n+m}
/// P(T_n, T_{n+m}) d_omega (trapezoidal in omega; the grid's spacing is d_mu).
fn add_force_spectrum(
    spectrum: &mut [f64],
    sea: &[f64],
    t: &[f64],
    w: f64,
    d_omega: f64,
    form: NewmanForm,
) {
    let n = sea.len();
    let pair = |a: f64, b: f64| match form {
        NewmanForm::Geometric if a * b > 0.0 => a * b,
        NewmanForm::Geometric => 0.0,
        NewmanForm::Arithmetic => (0.5 * (a + b)).powi(2),
    };
    for (m, out) in spectrum.iter_mut().enumerate() {
        let f: Vec<f64> = (0..n - m)
            .map(|k| sea[k] * sea[k + m] * pair(t[k], t[k + m]))
            .collect();
        *out += 8.0
            * w
            * w
            * if f.len() > 1 {
                trapezoid(&f, d_omega)
            } else {
                0.0
            };
    }
}

/// The wind linearised about its mean on the body at rest at the mean position: the
/// damping -dF_i/dv_i (N s/m, N m s/rad) and the gust force's spectrum (dF_i/dU)^2 S_u on the
/// grid m d_mu (central differences of the force, steps 1e-4 of the mean speed and 1e-4 m/s,
/// 1e-6 rad/s); zeros when calm, and when the speed is the FMU's input (0 m/s outside an
/// FMU: still air, whose quadratic force has no linear part).
fn wind_linearised(problem: &Problem, d_mu: f64) -> Result<([f64; 3], [Vec<f64>; 3])> {
    let zero = || std::array::from_fn(|_| vec![0.0; SLOW_GRID]);
    let Some((wind, gusts)) = problem
        .run_wind()?
        .and_then(|w| w.gusts.clone().map(|g| (w, g)))
    else {
        return Ok(([0.0; 3], zero()));
    };
    let force = |speed: f64, v: [f64; 3]| wind.force.force(speed, 0.0, v);
    let mean = gusts.mean;
    let du = 1e-4 * mean;
    let (up, down) = (force(mean + du, [0.0; 3]), force(mean - du, [0.0; 3]));
    let gain: [f64; 3] = std::array::from_fn(|i| (up[i] - down[i]) / (2.0 * du));
    let damping = std::array::from_fn(|i| {
        let step = if i == 2 { 1e-6 } else { 1e-4 };
        let mut v = [0.0; 3];
        v[i] = step;
        let plus = force(mean, v)[i];
        v[i] = -step;
        let minus = force(mean, v)[i];
        -(plus - minus) / (2.0 * step)
    });
    let mut spectra = zero();
    for (i, spectrum) in spectra.iter_mut().enumerate() {
        for (m, s) in spectrum.iter_mut().enumerate() {
            *s = gain[i] * gain[i] * gusts.spectrum.density_per_rad(m as f64 * d_mu);
        }
    }
    Ok((damping, spectra))
}

fn trapezoid(f: &[f64], h: f64) -> f64 {
    match f {
        [] | [_] => 0.0,
        [first, inner @ .., last] => h * (0.5 * (first + last) + inner.iter().sum::<f64>()),
    }
}

/// The drag's linearised damping matrix on (X', Y', theta') at the mean position, body
/// frame (N s/m, N s, N m s/rad): the sum over the columns' strips of G^T (1/2 rho D dz C
/// E[J]) G, G = [[1, 0, -y], [0, 1, x]] the strip's velocity per body velocity.
fn drag_damping(problem: &Problem) -> [[f64; 3]; 3] {
    let mut total = [[0.0; 3]; 3];
    let (cd, separate) = match problem.model.drag {
        DragModel::Off => return total,
        DragModel::Combined { cd } => (cd, false),
        DragModel::Separate { slow, .. } => (slow, true),
    };
    let c = &problem.current;
    let current = [c.speed * c.direction.cos(), c.speed * c.direction.sin()];
    let rho = problem.environment.water_density;
    let strips = problem.model.strips_per_column;
    for column in &problem.platform.columns {
        let dz = column.draft / strips as f64;
        for j in 0..strips {
            let z = -column.draft + (j as f64 + 0.5) * dz;
            let cov = if separate {
                [[0.0; 2]; 2]
            } else {
                velocity_covariance(problem, z)
            };
            let jacobian = expected_jacobian(current, cov);
            let g = [[1.0, 0.0, -column.y], [0.0, 1.0, column.x]];
            let scale = 0.5 * rho * column.diameter * dz * cd;
            for (a, row) in total.iter_mut().enumerate() {
                for (b, value) in row.iter_mut().enumerate() {
                    for p in 0..2 {
                        for q in 0..2 {
                            *value += scale * g[p][a] * jacobian[p][q] * g[q][b];
                        }
                    }
                }
            }
        }
    }
    total
}

/// The covariance of the horizontal wave particle velocity at depth `z` (m^2/s^2), deep
/// water, over the simulated band (Simpson, 400 panels).
fn velocity_covariance(problem: &Problem, z: f64) -> [[f64; 2]; 2] {
    let g = problem.environment.gravity;
    let (lo, hi) = problem.band();
    let panels = 400;
    let h = (hi - lo) / panels as f64;
    let f = |w: f64| w * w * (2.0 * w * w / g * z).exp() * problem.sea.spectrum.density(w);
    let inner: f64 = (1..panels)
        .map(|i| if i % 2 == 1 { 4.0 } else { 2.0 } * f(lo + i as f64 * h))
        .sum();
    let variance = (f(lo) + inner + f(hi)) * h / 3.0;
    let mut cov = [[0.0; 2]; 2];
    for d in problem.sea.directions() {
        let e = [d.heading.cos(), d.heading.sin()];
        for p in 0..2 {
            for q in 0..2 {
                cov[p][q] += d.weight * variance * e[p] * e[q];
            }
        }
    }
    cov
}

/// E[J(m + u)] for u ~ N(0, cov), J(w) = |w| I + w w^T / |w| (the Jacobian of w|w|, zero at
/// w = 0): a product midpoint rule over the covariance's principal axes.
pub fn expected_jacobian(mean: [f64; 2], cov: [[f64; 2]; 2]) -> [[f64; 2]; 2] {
    // Principal axes of the symmetric 2x2 covariance.
    let (a, b, c) = (cov[0][0], cov[0][1], cov[1][1]);
    let half_trace = 0.5 * (a + c);
    let root = (0.25 * (a - c).powi(2) + b * b).sqrt();
    let angle = 0.5 * (2.0 * b).atan2(a - c);
    let axes = [
        (
            (half_trace + root).max(0.0).sqrt(),
            [angle.cos(), angle.sin()],
        ),
        (
            (half_trace - root).max(0.0).sqrt(),
            [-angle.sin(), angle.cos()],
        ),
    ];
    let h = 2.0 * NORMAL_SPAN / NORMAL_POINTS as f64;
    let nodes: Vec<(f64, f64)> = (0..NORMAL_POINTS)
        .map(|n| {
            let x = -NORMAL_SPAN + (n as f64 + 0.5) * h;
            (x, (-0.5 * x * x).exp())
        })
        .collect();
    let norm: f64 = nodes.iter().map(|(_, p)| p).sum();
    let mut sum = [[0.0; 2]; 2];
    for &(x1, p1) in &nodes {
        for &(x2, p2) in &nodes {
            let w: [f64; 2] = std::array::from_fn(|k| {
                mean[k] + axes[0].0 * x1 * axes[0].1[k] + axes[1].0 * x2 * axes[1].1[k]
            });
            let speed = w[0].hypot(w[1]);
            if speed == 0.0 {
                continue;
            }
            let p = p1 * p2;
            for (i, row) in sum.iter_mut().enumerate() {
                for (j, value) in row.iter_mut().enumerate() {
                    let identity = if i == j { speed } else { 0.0 };
                    *value += p * (identity + w[i] * w[j] / speed);
                }
            }
        }
    }
    sum.map(|row| row.map(|v| v / (norm * norm)))
}

/// A run's motion sampled every time step after the transient.
#[derive(Debug, Clone, PartialEq)]
pub struct MotionRecord {
    /// Sample spacing, s (the time step).
    pub dt: f64,
    /// The slow drift (X, Y, theta), m, m, rad.
    pub slow: [Vec<f64>; 3],
    /// The wave-frequency motion of the six DOFs (inertial axes), m and rad; zeros where
    /// the run has none.
    pub wave_frequency: [Vec<f64>; 6],
    /// The wind speed at the force's height, m/s; zeros when calm.
    pub wind_speed: Vec<f64>,
}

/// Runs `problem` for `transient + length` seconds and keeps the motion of the last
/// `length` seconds, one sample per time step. Errors: `length` or `transient` out of range
/// (named `study.record_length`, `study.transient`), or what the simulation refuses.
pub fn motion_record(problem: &Problem, transient: f64, length: f64) -> Result<MotionRecord> {
    crate::error::require_positive("study.record_length", length)?;
    if !(transient >= 0.0 && transient.is_finite()) {
        return Err(Error::invalid(
            "study.transient",
            transient,
            "must be a finite number of seconds, at least 0",
        ));
    }
    let mut problem = problem.clone();
    problem.run.duration = transient + length;
    let dt = problem.run.time_step;
    let (skip, count) = (
        (transient / dt).round() as usize,
        (length / dt).round() as usize,
    );
    let mut sim = Simulation::new(problem)?;
    let mut record = MotionRecord {
        dt,
        slow: Default::default(),
        wave_frequency: Default::default(),
        wind_speed: Vec::new(),
    };
    for n in 0..skip + count {
        if n >= skip {
            let out = sim.outputs()?;
            for i in 0..3 {
                record.slow[i].push(out.position[i]);
            }
            for i in 0..6 {
                record.wave_frequency[i].push(out.motion.wave_frequency[i]);
            }
            record.wind_speed.push(out.wind_speed);
        }
        sim.step([0.0; 3])?;
    }
    Ok(record)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A one-dimensional Gaussian velocity along x with a current along x: E[J_xx] = 2
    /// E|w| and E[J_yy] = E|w| with E|c + u| = sigma sqrt(2/pi) e^{-c^2/(2 sigma^2)} + c
    /// erf(c / (sigma sqrt 2)) (the folded normal's mean); erf from its series.
    #[test]
    fn the_expected_jacobian_is_the_folded_normal_mean() {
        let erf = |x: f64| -> f64 {
            // Maclaurin series, enough terms for |x| < 3.
            let mut term = x;
            let mut sum = x;
            for n in 1..80 {
                term *= -x * x / n as f64;
                sum += term / (2 * n + 1) as f64;
            }
            2.0 / PI.sqrt() * sum
        };
        for (sigma, c) in [(1.0, 0.0), (0.5, 0.3), (0.4, 1.2)] {
            let folded = sigma * (2.0 / PI).sqrt() * (-c * c / (2.0 * sigma * sigma)).exp()
                + c * erf(c / (sigma * 2f64.sqrt()));
            let j = expected_jacobian([c, 0.0], [[sigma * sigma, 0.0], [0.0, 0.0]]);
            assert!(
                (j[0][0] / (2.0 * folded) - 1.0).abs() < 1e-4,
                "{j:?} {folded}"
            );
            assert!((j[1][1] / folded - 1.0).abs() < 1e-4, "{j:?} {folded}");
            assert!(j[0][1].abs() < 1e-12);
        }
        // The same sea turned by 90 degrees turns the matrix: J_yy = 2 E|w|.
        let turned = expected_jacobian([0.0, 0.0], [[0.0, 0.0], [0.0, 1.0]]);
        assert!((turned[1][1] / (2.0 * (2.0 / PI).sqrt()) - 1.0).abs() < 1e-4);
        // Without waves: J of the current itself, (|c| I + c c^T / |c|).
        let steady = expected_jacobian([0.6, 0.8], [[0.0; 2]; 2]);
        let expected = [[1.0 + 0.36, 0.48], [0.48, 1.0 + 0.64]];
        for i in 0..2 {
            for j in 0..2 {
                assert!((steady[i][j] - expected[i][j]).abs() < 1e-12);
            }
        }
    }

    /// The discrete correlation of a constant drift coefficient T over a flat spectrum S0
    /// on [lo, hi] is 8 S0^2 T^2 (hi - lo - mu), exact for the trapezoidal rule.
    #[test]
    fn the_force_spectrum_of_a_flat_sea_is_a_triangle() {
        let (n, d) = (101, 0.01);
        let sea = vec![2.0; n];
        let t = vec![-3.0; n];
        let mut spectrum = vec![0.0; n];
        add_force_spectrum(&mut spectrum, &sea, &t, 0.5, d, NewmanForm::Geometric);
        for (m, s) in spectrum.iter().enumerate().take(n - 1) {
            let expected = 8.0 * 0.25 * 4.0 * 9.0 * (n - 1 - m) as f64 * d;
            assert!(
                (s - expected).abs() < 1e-9 * expected,
                "{m}: {s} vs {expected}"
            );
        }
        // Signs that differ: a pair counts 0 in the geometric form and ((T + T')/2)^2 in
        // the arithmetic. T = 1 below k = 50, -4 from it: at m = 60 every pair differs,
        // 41 pairs of (-3/2)^2 (trapezoid over 40 intervals); at m = 10 the 40 pairs of
        // +1, the 41 of -4 and the 10 that differ.
        let mixed: Vec<f64> = (0..n).map(|k| if k < 50 { 1.0 } else { -4.0 }).collect();
        let mut geometric = vec![0.0; n];
        add_force_spectrum(&mut geometric, &sea, &mixed, 1.0, d, NewmanForm::Geometric);
        let mut arithmetic = vec![0.0; n];
        add_force_spectrum(
            &mut arithmetic,
            &sea,
            &mixed,
            1.0,
            d,
            NewmanForm::Arithmetic,
        );
        assert_eq!(geometric[60], 0.0);
        assert!((arithmetic[60] - 8.0 * 4.0 * 2.25 * 40.0 * d).abs() < 1e-12);
        // m = 10, trapezoid over k = 0..90 (ends at k = 0: +1 pair, k = 90: -4 pair, half
        // weight each): geometric 1 x 39.5 + 16 x 40.5, arithmetic adds 2.25 x 10.
        let g10 = 8.0 * 4.0 * (39.5 + 16.0 * 40.5) * d;
        assert!(
            (geometric[10] - g10).abs() < 1e-9 * g10,
            "{}",
            geometric[10]
        );
        let a10 = g10 + 8.0 * 4.0 * 2.25 * 10.0 * d;
        assert!(
            (arithmetic[10] - a10).abs() < 1e-9 * a10,
            "{}",
            arithmetic[10]
        );
    }
}
