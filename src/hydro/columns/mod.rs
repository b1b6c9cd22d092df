//! Built-in hydrodynamics of an array of vertical circular columns: the interaction theory
//! of Linton & Evans (1990) (docs/theory.md#columns-linton-and-evans), first-order exciting forces,
//! the mean
//! drift force and yaw moment by near-field pressure integration and, independently, by the
//! far-field momentum flux of the array's Kochin function, the bi-directional mean drift,
//! and Aranha's wave-drift damping with derivatives taken from the solver itself.
//!
//! # Model
//!
//! Fixed vertical circular columns (centre (x_c, y_c), radius a_c = diameter/2), either
//! - in deep water, infinitely deep (depth function e^{kz}, k = omega^2/g), or
//! - bottom-mounted in water of depth h (cosh k(z+h)/cosh kh, omega^2 = g k tanh kh);
//!
//! the column drafts are not used. The linear diffraction problem is solved exactly up to
//! the truncation of the Fourier modes at |m| <= M on every column, with
//!   M = ceil(k a_max) + max([`EXTRA_MODES`], ceil(ln(1e-13) / (2 ln q))),
//! q = max over pairs (a_i + a_j)/R_ij < 1. Beyond k a the coupling of mode m of one
//! column to mode n of another decays like q^{|m| + |n|} (the Graf series of
//! H_{n-m}(k R) J_m(k a_i) with Z_n(k a_j)), so close columns need more modes than k a + 10
//! when k a is small: four columns of radius 10 m on a 70 m square have q = 0.29 and 12
//! geometric modes, a tighter irregular array (q = 0.4) 17. The geometric term is capped at
//! [`MAX_GEOMETRIC_MODES`] (nearly touching columns). The tests show that two more modes
//! change the drift by less than 1e-8 relative.
//!
//! # Conventions
//!
//! SI units; headings beta are the direction of propagation from +x, counter-clockwise, in
//! the array's (body) frame; every quantity is per unit incident amplitude (force per m of
//! amplitude, drift per m^2). The solver works in Linton & Evans' e^{-i omega t}; results
//! with a phase ([`ArrayHydro::excitation`], [`BidirectionalDrift::get`]) are converted to
//! the project's convention Re[a e^{i omega t}] (docs/theory.md#conventions) by complex
//! conjugation, with the incident wave eta = Re[a e^{i (omega t - k (x cos beta + y sin beta))}]
//! (phase reference at the origin). The drift is real and convention-free.
//!
//! # What the model leaves out for a real floater
//!
//! - Finite draft d. The infinitely deep column scatters with its whole depth; a truncated
//!   one only down to z = -d (plus the flow under the keel). A strip estimate (each slice
//!   scattering like the infinite column, far field = projection of the slice sources onto
//!   the propagating mode e^{kz}) scales the Kochin function by 1 - e^{-2kd} and the drift
//!   (quadratic in it) by (1 - e^{-2kd})^2; docs/theory.md#columns-linton-and-evans quotes the
//!   milder
//!   1 - e^{-kd}. For the paper's columns (d = 30 m) the strip factor is 0.18 at
//!   omega = 0.3 rad/s (kd = 0.28), 0.61 at 0.5 rad/s, 0.90 at 0.7 rad/s and > 0.99 above
//!   1 rad/s: the infinitely deep column over-predicts the drift by factors of about 5, 1.6,
//!   1.1 there. Where it matters most the drift is small anyway (it starts as (ka)^3), but
//!   the relative error at the low-frequency end of a storm spectrum is large.
//! - Pontoons and bracing: not modelled. They scatter mainly in long waves (their depth
//!   factor e^{-2k d_p} is small in short waves) and change the interaction between columns.
//! - Body motions: the platform is fixed (diffraction only, no radiation). Near heave, roll
//!   or pitch resonance, and in long waves where a moored floater follows the waves, the
//!   first-order motions change the drift substantially.
//! - Aranha's formula is a deep-water result; in finite depth it is applied unchanged.
//!
//! # Sources
//!
//! Linton & Evans, J. Fluid Mech. 215 (1990) 549-569 (interaction theory, exciting force);
//! MacCamy & Fuchs (1954) and Havelock, Proc. R. Soc. A 175 (1940) (single column);
//! Maruo (1960), Newman, J. Ship Res. 11 (1967) (far-field drift force and yaw moment);
//! Aranha, J. Fluid Mech. 275 (1994) (damping). The derivations are in the docs of the
//! private modules `scattering` (system, exciting force) and `drift` (both drift routes).

mod drift;
mod scattering;

use crate::error::numbers::{readable, written};
use crate::error::{require_finite, require_positive, Error, Result};
use crate::hydro::aranha::{aranha_coefficients, ColumnMoments};
use crate::hydro::column_drift::{validate_grid, MAX_KA};
use crate::hydro::{DriftRow, DriftTable};
use crate::model::{Cylinder, Environment};
use drift::{near_field_form, real_parts, FarField};
use nalgebra::DMatrix;
use rustfft::num_complex::Complex64;
use rustfft::FftPlanner;
use scattering::{column_force, depth_terms, wavenumber, Circle, FrequencySystem};
use serde::Serialize;

/// Least number of modes kept beyond k a_max on every column (module doc).
pub const EXTRA_MODES: usize = 10;

/// Target truncation error of the geometric decay q^{2 (M - k a)} (module doc).
const MODE_TOLERANCE: f64 = 1e-13;

/// Cap on the geometric number of modes (q -> 1 for nearly touching columns).
pub const MAX_GEOMETRIC_MODES: usize = 120;

/// Relative frequency step of the central difference dF/domega, divided by
/// max(1, k L) with L the size of the array (largest centre distance, or diameter). The
/// drift varies with omega on the scale omega / (2 k L) (phases k L between columns), so the
/// truncation error is about (1e-4)^2 relative; the round-off, ~1e-16 relative in the drift
/// times the solver's condition, divided by the step, stays near 1e-11.
const FREQUENCY_STEP: f64 = 1e-4;

/// An array of fixed vertical circular columns (module doc).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ColumnArray {
    columns: Vec<Cylinder>,
    cylinders: Vec<Circle>,
    depth: Option<f64>,
    /// max(EXTRA_MODES, geometric modes) (module doc).
    extra_modes: usize,
    /// Modes added on top of the rule (convergence studies).
    added_modes: usize,
}

/// Results of [`ColumnArray::solve`] on a heading x frequency grid, per unit amplitude.
#[derive(Debug, Clone, PartialEq)]
pub struct ArrayHydro {
    omegas: Vec<f64>,
    headings: Vec<f64>,
    wavenumbers: Vec<f64>,
    columns: usize,
    /// Heading-major: index ih * omegas.len() + iw.
    excitation: Vec<[Complex64; 3]>,
    /// Index (ih * omegas.len() + iw) * columns + c.
    column_excitation: Vec<[Complex64; 2]>,
    drift_near: Vec<[f64; 3]>,
    drift_far: Vec<[f64; 3]>,
    drift_domega: Vec<[f64; 3]>,
    drift_dbeta: Vec<[f64; 3]>,
}

/// Bi-directional mean drift T(omega; beta_p, beta_q) of one frequency (project convention):
/// two (or more) waves of complex amplitudes a_p at headings beta_p give the mean force
/// F = sum_{p,q} a_p conj(a_q) T(beta_p, beta_q); T is Hermitian, T(beta_q, beta_p) =
/// conj T(beta_p, beta_q), and T(beta, beta) is the uni-directional drift.
#[derive(Debug, Clone, PartialEq)]
pub struct BidirectionalDrift {
    omega: f64,
    headings: Vec<f64>,
    /// Index p * headings.len() + q.
    values: Vec<[Complex64; 3]>,
}

/// What one frequency produces, per heading.
struct FrequencyResults {
    excitation: Vec<[Complex64; 3]>,
    column_excitation: Vec<[Complex64; 2]>,
    drift_near: Vec<[f64; 3]>,
    drift_far: Vec<[f64; 3]>,
    drift_domega: Vec<[f64; 3]>,
    drift_dbeta: Vec<[f64; 3]>,
}

impl ColumnArray {
    /// An array of `columns` (the drafts are not used) in deep water (`depth` None) or
    /// bottom-mounted in water of depth `depth`. Refuses an empty list, non-finite centres,
    /// non-positive diameters, overlapping or touching columns, and a non-positive depth.
    pub fn new(columns: Vec<Cylinder>, depth: Option<f64>) -> Result<Self> {
        if columns.is_empty() {
            return Err(Error::invalid(
                "platform.columns",
                "[]",
                "no columns to compute the hydrodynamics of",
            ));
        }
        for (i, c) in columns.iter().enumerate() {
            require_finite(format_args!("platform.columns[{i}].x"), c.x)?;
            require_finite(format_args!("platform.columns[{i}].y"), c.y)?;
            require_positive(&format!("platform.columns[{i}].diameter"), c.diameter)?;
        }
        for (j, cj) in columns.iter().enumerate() {
            for (i, ci) in columns[..j].iter().enumerate() {
                let distance = (cj.x - ci.x).hypot(cj.y - ci.y);
                if distance <= 0.5 * (ci.diameter + cj.diameter) {
                    return Err(Error::invalid(
                        format!("platform.columns[{j}]"),
                        format!(
                            "({}, {}) m, diameter {} m",
                            written(cj.x),
                            written(cj.y),
                            written(cj.diameter)
                        ),
                        format!(
                            "overlaps or touches platform.columns[{i}]: centres {} m apart, \
                             radii sum {} m",
                            readable(distance),
                            readable(0.5 * (ci.diameter + cj.diameter))
                        ),
                    ));
                }
            }
        }
        if let Some(h) = depth {
            require_positive("environment.depth", h)?;
        }
        let cylinders: Vec<Circle> = columns
            .iter()
            .map(|c| Circle {
                x: c.x,
                y: c.y,
                radius: 0.5 * c.diameter,
            })
            .collect();
        let extra_modes = geometric_modes(&cylinders).max(EXTRA_MODES);
        Ok(ColumnArray {
            columns,
            cylinders,
            depth,
            extra_modes,
            added_modes: 0,
        })
    }

    /// The same array with `added` modes more than the rule of the module doc on every
    /// column (convergence studies).
    pub fn with_added_modes(mut self, added: usize) -> Self {
        self.added_modes = added;
        self
    }

    /// M at wavenumber k (module doc).
    pub fn modes(&self, k: f64) -> usize {
        let a_max = self.cylinders.iter().map(|c| c.radius).fold(0.0, f64::max);
        (k * a_max).ceil() as usize + self.extra_modes + self.added_modes
    }

    /// The columns as given.
    pub fn columns(&self) -> &[Cylinder] {
        &self.columns
    }

    /// Water depth, m (None: deep water, infinitely deep columns).
    pub fn depth(&self) -> Option<f64> {
        self.depth
    }

    /// Wavenumber of frequency `omega` (deep water or finite-depth dispersion relation).
    pub fn wavenumber(&self, omega: f64, gravity: f64) -> f64 {
        wavenumber(omega, gravity, self.depth)
    }

    /// Exciting forces, near- and far-field drift and the drift's derivatives for every
    /// frequency and heading. One factorisation per frequency serves all headings; the
    /// frequency derivative needs two more (central difference with step 1e-4 omega / max(1, k L)), the
    /// heading derivative is exact (one more right-hand side).
    pub fn solve(
        &self,
        environment: &Environment,
        omegas: &[f64],
        headings: &[f64],
    ) -> Result<ArrayHydro> {
        validate_grid(environment, omegas, headings)?;
        let (nw, nh, nc) = (omegas.len(), headings.len(), self.cylinders.len());
        let mut out = ArrayHydro {
            omegas: omegas.to_vec(),
            headings: headings.to_vec(),
            wavenumbers: Vec::with_capacity(nw),
            columns: nc,
            excitation: vec![[Complex64::new(0.0, 0.0); 3]; nw * nh],
            column_excitation: vec![[Complex64::new(0.0, 0.0); 2]; nw * nh * nc],
            drift_near: vec![[0.0; 3]; nw * nh],
            drift_far: vec![[0.0; 3]; nw * nh],
            drift_domega: vec![[0.0; 3]; nw * nh],
            drift_dbeta: vec![[0.0; 3]; nw * nh],
        };
        let mut planner = FftPlanner::new();
        for (iw, &omega) in omegas.iter().enumerate() {
            let k = self.checked_wavenumber(environment, iw, omega)?;
            out.wavenumbers.push(k);
            let r = self.frequency(environment, iw, omega, k, headings, &mut planner)?;
            for ih in 0..nh {
                let node = ih * nw + iw;
                out.excitation[node] = r.excitation[ih];
                out.drift_near[node] = r.drift_near[ih];
                out.drift_far[node] = r.drift_far[ih];
                out.drift_domega[node] = r.drift_domega[ih];
                out.drift_dbeta[node] = r.drift_dbeta[ih];
                out.column_excitation[node * nc..(node + 1) * nc]
                    .copy_from_slice(&r.column_excitation[ih * nc..(ih + 1) * nc]);
            }
        }
        Ok(out)
    }

    /// Drift table (near-field drift) with Aranha's wave-drift damping from the solver's own
    /// derivatives, and the yaw-rate column by the per-column approximation of
    /// [`crate::hydro::aranha`]. Frequencies must be increasing (as for every drift table).
    pub fn drift_table(
        &self,
        environment: &Environment,
        omegas: &[f64],
        headings: &[f64],
    ) -> Result<DriftTable> {
        let hydro = self.solve(environment, omegas, headings)?;
        let moments = ColumnMoments::of(&self.columns);
        let mut rows = Vec::with_capacity(omegas.len() * headings.len());
        for (ih, &heading) in headings.iter().enumerate() {
            for (iw, &omega) in omegas.iter().enumerate() {
                let drift = hydro.drift_near(ih, iw);
                let (df_domega, df_dbeta) = hydro.drift_derivatives(ih, iw);
                let mut b = aranha_coefficients(
                    omega,
                    heading,
                    drift,
                    df_domega,
                    df_dbeta,
                    environment.gravity,
                );
                moments.fill_yaw_rate_column(&mut b);
                rows.push(DriftRow {
                    omega,
                    heading,
                    drift,
                    damping: Some(b),
                });
            }
        }
        DriftTable::from_rows(&rows)
    }

    /// Bi-directional mean drift at one frequency for every pair of `headings` (near field).
    pub fn bidirectional_drift(
        &self,
        environment: &Environment,
        omega: f64,
        headings: &[f64],
    ) -> Result<BidirectionalDrift> {
        validate_grid(environment, &[omega], headings)?;
        let k = self.checked_wavenumber(environment, 0, omega)?;
        let modes = self.modes(k);
        let system = self.system(k, modes, 0, omega)?;
        let solution = system.solve(&self.incident_matrix(&system, headings, false));
        let n = solution.surface.nrows();
        let u = solution.surface.as_slice();
        let (s, _) = depth_terms(k, self.depth);
        let rho_g = environment.water_density * environment.gravity;
        let nh = headings.len();
        let mut values = Vec::with_capacity(nh * nh);
        for p in 0..nh {
            for q in 0..nh {
                let t = near_field_form(
                    &self.cylinders,
                    modes,
                    k,
                    rho_g,
                    s,
                    &u[p * n..(p + 1) * n],
                    &u[q * n..(q + 1) * n],
                );
                // e^{-i omega t} amplitudes A = conj(a): T_project = conj(T_LE).
                values.push(t.map(|v| v.conj()));
            }
        }
        Ok(BidirectionalDrift {
            omega,
            headings: headings.to_vec(),
            values,
        })
    }

    /// Wavenumber of omegas[iw], refused where k a exceeds the verified Bessel range.
    fn checked_wavenumber(&self, environment: &Environment, iw: usize, omega: f64) -> Result<f64> {
        let k = wavenumber(omega, environment.gravity, self.depth);
        for c in &self.columns {
            let ka = 0.5 * k * c.diameter;
            if ka > MAX_KA {
                return Err(Error::invalid(
                    format!("drift.omegas[{iw}]"),
                    format!("{} rad/s", written(omega)),
                    format!(
                        "k a = {} exceeds {MAX_KA} (the verified Bessel range) for a column of \
                         diameter {} m",
                        readable(ka),
                        written(c.diameter)
                    ),
                ));
            }
        }
        Ok(k)
    }

    fn system(&self, k: f64, modes: usize, iw: usize, omega: f64) -> Result<FrequencySystem> {
        FrequencySystem::new(&self.cylinders, k, modes).ok_or_else(|| {
            Error::invalid(
                format!("drift.omegas[{iw}]"),
                format!("{} rad/s", written(omega)),
                "the scattering system is singular or out of the Hankel functions' range \
                 at this frequency",
            )
        })
    }

    /// Incident coefficients of every heading, one matrix column each; with `derivatives`,
    /// columns 2 ih and 2 ih + 1 hold heading ih's values and d/dbeta.
    fn incident_matrix(
        &self,
        system: &FrequencySystem,
        headings: &[f64],
        derivatives: bool,
    ) -> DMatrix<Complex64> {
        let n = self.cylinders.len() * (2 * system.modes + 1);
        let per = if derivatives { 2 } else { 1 };
        let mut incident = DMatrix::zeros(n, per * headings.len());
        let data = incident.as_mut_slice();
        for (ih, &beta) in headings.iter().enumerate() {
            let at = per * ih * n;
            system.incident(&self.cylinders, beta, &mut data[at..at + n]);
            if derivatives {
                system.incident_derivative(&self.cylinders, beta, &mut data[at + n..at + 2 * n]);
            }
        }
        incident
    }

    /// Near-field drift of every heading at wavenumber k with `modes` modes.
    fn near_drift(
        &self,
        environment: &Environment,
        k: f64,
        modes: usize,
        (iw, omega): (usize, f64),
        headings: &[f64],
    ) -> Result<Vec<[f64; 3]>> {
        let system = self.system(k, modes, iw, omega)?;
        let solution = system.solve(&self.incident_matrix(&system, headings, false));
        let n = solution.surface.nrows();
        let u = solution.surface.as_slice();
        let (s, _) = depth_terms(k, self.depth);
        let rho_g = environment.water_density * environment.gravity;
        Ok((0..headings.len())
            .map(|ih| {
                let v = &u[ih * n..(ih + 1) * n];
                real_parts(
                    near_field_form(&self.cylinders, modes, k, rho_g, s, v, v),
                    1.0,
                )
            })
            .collect())
    }

    /// Everything of one frequency.
    fn frequency(
        &self,
        environment: &Environment,
        iw: usize,
        omega: f64,
        k: f64,
        headings: &[f64],
        planner: &mut FftPlanner<f64>,
    ) -> Result<FrequencyResults> {
        let modes = self.modes(k);
        let width = 2 * modes + 1;
        let nc = self.cylinders.len();
        let system = self.system(k, modes, iw, omega)?;
        let solution = system.solve(&self.incident_matrix(&system, headings, true));
        let n = solution.surface.nrows();
        let u = solution.surface.as_slice();
        let scattered = solution.scattered.as_slice();
        let (s, depth_integral) = depth_terms(k, self.depth);
        let rho_g = environment.water_density * environment.gravity;
        let far = FarField::new(&self.cylinders, k, modes, planner);
        let nh = headings.len();
        let mut r = FrequencyResults {
            excitation: Vec::with_capacity(nh),
            column_excitation: Vec::with_capacity(nh * nc),
            drift_near: Vec::with_capacity(nh),
            drift_far: Vec::with_capacity(nh),
            drift_domega: Vec::with_capacity(nh),
            drift_dbeta: Vec::with_capacity(nh),
        };
        for (ih, &beta) in headings.iter().enumerate() {
            let value = &u[2 * ih * n..(2 * ih + 1) * n];
            let slope = &u[(2 * ih + 1) * n..(2 * ih + 2) * n];
            let form = |p: &[Complex64], q: &[Complex64]| {
                near_field_form(&self.cylinders, modes, k, rho_g, s, p, q)
            };
            r.drift_near.push(real_parts(form(value, value), 1.0));
            // d/dbeta T(u, u) = T(u', u) + T(u, u') = 2 Re T(u', u).
            r.drift_dbeta.push(real_parts(form(slope, value), 2.0));
            r.drift_far
                .push(far.drift(&scattered[2 * ih * n..(2 * ih + 1) * n], beta, rho_g, s));
            let mut total = [Complex64::new(0.0, 0.0); 3];
            for (c, cyl) in self.cylinders.iter().enumerate() {
                let [fx, fy] = column_force(
                    &value[c * width..(c + 1) * width],
                    modes,
                    cyl.radius,
                    rho_g,
                    depth_integral,
                )
                .map(|v| v.conj());
                r.column_excitation.push([fx, fy]);
                total[0] += fx;
                total[1] += fy;
                total[2] += cyl.x * fy - cyl.y * fx;
            }
            r.excitation.push(total);
        }
        let step = FREQUENCY_STEP * omega / (k * self.extent()).max(1.0);
        let g = environment.gravity;
        let above = omega + step;
        let below = omega - step;
        let plus = self.near_drift(
            environment,
            wavenumber(above, g, self.depth),
            modes,
            (iw, above),
            headings,
        )?;
        let minus = self.near_drift(
            environment,
            wavenumber(below, g, self.depth),
            modes,
            (iw, below),
            headings,
        )?;
        for (p, m) in plus.iter().zip(&minus) {
            r.drift_domega
                .push(std::array::from_fn(|i| (p[i] - m[i]) / (2.0 * step)));
        }
        Ok(r)
    }

    /// Size L of the array: the largest distance between centres, or the largest diameter.
    fn extent(&self) -> f64 {
        let mut extent = self.columns.iter().map(|c| c.diameter).fold(0.0, f64::max);
        for (j, cj) in self.cylinders.iter().enumerate() {
            for ci in &self.cylinders[..j] {
                extent = extent.max((cj.x - ci.x).hypot(cj.y - ci.y));
            }
        }
        extent
    }
}

impl ArrayHydro {
    /// Frequencies, rad/s, as given.
    pub fn omegas(&self) -> &[f64] {
        &self.omegas
    }

    /// Headings, rad, as given.
    pub fn headings(&self) -> &[f64] {
        &self.headings
    }

    /// Wavenumbers of the frequencies, 1/m.
    pub fn wavenumbers(&self) -> &[f64] {
        &self.wavenumbers
    }

    /// First-order exciting force on the array (surge, sway: N/m; yaw: N m/m), complex
    /// amplitude in the project's e^{i omega t} convention, phase relative to the incident
    /// elevation at the origin.
    pub fn excitation(&self, ih: usize, iw: usize) -> [Complex64; 3] {
        self.excitation[ih * self.omegas.len() + iw]
    }

    /// First-order exciting force on column `c` (surge, sway), as [`Self::excitation`].
    pub fn column_excitation(&self, ih: usize, iw: usize, c: usize) -> [Complex64; 2] {
        self.column_excitation[(ih * self.omegas.len() + iw) * self.columns + c]
    }

    /// Mean drift (surge, sway: N/m^2; yaw: N m/m^2) by near-field pressure integration.
    pub fn drift_near(&self, ih: usize, iw: usize) -> [f64; 3] {
        self.drift_near[ih * self.omegas.len() + iw]
    }

    /// Mean drift by the far-field momentum and angular-momentum flux (Kochin function).
    pub fn drift_far(&self, ih: usize, iw: usize) -> [f64; 3] {
        self.drift_far[ih * self.omegas.len() + iw]
    }

    /// (dF/domega, dF/dbeta) of the near-field drift: central difference in omega, exact in
    /// beta.
    pub fn drift_derivatives(&self, ih: usize, iw: usize) -> ([f64; 3], [f64; 3]) {
        let node = ih * self.omegas.len() + iw;
        (self.drift_domega[node], self.drift_dbeta[node])
    }
}

impl BidirectionalDrift {
    /// Frequency, rad/s.
    pub fn omega(&self) -> f64 {
        self.omega
    }

    /// Headings, rad, as given.
    pub fn headings(&self) -> &[f64] {
        &self.headings
    }

    /// T(omega; beta_p, beta_q) for (surge, sway, yaw), N/m^2 and N m/m^2.
    pub fn get(&self, p: usize, q: usize) -> [Complex64; 3] {
        self.values[p * self.headings.len() + q]
    }
}

/// ceil(ln(MODE_TOLERANCE) / (2 ln q)), q = max (a_i + a_j)/R_ij, at most
/// MAX_GEOMETRIC_MODES; 0 for a single column.
fn geometric_modes(cylinders: &[Circle]) -> usize {
    let mut q: f64 = 0.0;
    for (j, cj) in cylinders.iter().enumerate() {
        for ci in &cylinders[..j] {
            q = q.max((ci.radius + cj.radius) / (cj.x - ci.x).hypot(cj.y - ci.y));
        }
    }
    if q == 0.0 {
        return 0;
    }
    let modes = MODE_TOLERANCE.ln() / (2.0 * q.ln());
    (modes.ceil() as usize).min(MAX_GEOMETRIC_MODES)
}

#[cfg(test)]
mod tests;
