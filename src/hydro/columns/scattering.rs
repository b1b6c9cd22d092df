//! The first-order problem of one frequency: dispersion relation, the Linton & Evans (1990)
//! multiple-scattering system (docs/theory.md#columns-linton-and-evans), its solution for any
//! number of
//! incident waves, and the exciting force.
//!
//! Internally the time factor is Linton & Evans' e^{-i omega t}. With incident elevation
//! eta_I = A e^{i k (x cos b + y sin b)} (complex amplitude, e^{-i omega t}), the potential
//! is phi = -(i g A / omega) Z(z) psi(x, y), so that eta = A psi at z = 0, with the depth
//! function Z = cosh k(z + h)/cosh kh (bottom-mounted columns in depth h) or e^{kz}
//! (infinitely deep columns in deep water), and
//!   psi = psi_I + sum_j sum_n B_n^j H_n(k r_j) e^{i n t_j},
//! (r_j, t_j) polar coordinates about the centre of column j, H_n the Hankel function of the
//! first kind. In Linton & Evans' notation B_n^j = A_n^j Z_n^j.
//!
//! Near column k the regular part of psi is sum_m c_m^k J_m(k r_k) e^{i m t_k} with
//!   c_m^k = I_k e^{i m (pi/2 - b)} + sum_{j != k} sum_n B_n^j e^{i (n - m) alpha_jk} H_{n-m}(k R_jk)
//! (Graf's addition theorem; alpha_jk is the polar angle of the vector from centre j to
//! centre k, R_jk its length; I_k = e^{i k (x_k cos b + y_k sin b)}). The no-flux condition
//! on r_k = a_k gives B_m^k = -Z_m^k c_m^k, Z_m = J'_m(k a)/H'_m(k a). The unknowns solved
//! for are the scaled b_n^j = |H'_n(k a_j)| B_n^j, which balances the system: its
//! interaction entries are then bounded by about (2 a / R)^{|n| + |m|} even for k a -> 0,
//! where the raw B_n and H_{n-m}(k R) span hundreds of orders of magnitude.
//!
//! On the surface of column k, psi = sum_m u_m e^{i m t_k} with
//!   u_m = c_m (J_m H'_m - J'_m H_m)/H'_m = 2 i c_m / (pi k a H'_m(k a))
//! (Wronskian A&S 9.1.16), which never divides by a vanishing J'_m.

use crate::special::bessel::{bessel_j_y, hankel_derivatives};
use nalgebra::{DMatrix, Dyn, LU};
use rustfft::num_complex::Complex64;
use std::f64::consts::PI;

/// A column in plan view: the circle of its centre and radius, m.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub(super) struct Circle {
    pub x: f64,
    pub y: f64,
    pub radius: f64,
}

/// Newton iterations allowed for the finite-depth dispersion relation (it converges in < 8
/// from Eckart's guess; the bracket makes every step safe).
const DISPERSION_ITERATIONS: usize = 60;

/// Wavenumber k of frequency omega: k = omega^2/g in deep water (`depth` None), else the
/// root of omega^2 = g k tanh(k h). With x = k h and y = omega^2 h/g, x tanh x = y is solved
/// by Newton's method from Eckart's approximation x = y / sqrt(tanh y), safeguarded by the
/// bracket max(y, sqrt y) <= x <= y + sqrt y (tanh x < 1 and tanh x < x give the lower
/// bound; at the upper one x tanh x > y) with bisection when a step leaves it.
pub(super) fn wavenumber(omega: f64, gravity: f64, depth: Option<f64>) -> f64 {
    let deep = omega * omega / gravity;
    let Some(h) = depth else {
        return deep;
    };
    let y = deep * h;
    let (mut lo, mut hi) = (y.max(y.sqrt()), y + y.sqrt());
    let mut x = (y / y.tanh().sqrt()).clamp(lo, hi);
    for _ in 0..DISPERSION_ITERATIONS {
        let t = x.tanh();
        let f = x * t - y;
        if f == 0.0 {
            break;
        }
        if f > 0.0 {
            hi = x;
        } else {
            lo = x;
        }
        let mut next = x - f / (t + x * (1.0 - t * t));
        if !(next >= lo && next <= hi) {
            next = 0.5 * (lo + hi);
        }
        let done = (next - x).abs() <= 2.0 * f64::EPSILON * x;
        x = next;
        if done {
            break;
        }
    }
    x / h
}

/// Depth quantities of wavenumber k: s = 2kh/sinh 2kh (0 in deep water), so that
/// c_g/c = (1 + s)/2, and the vertical integral of the depth function,
/// int_{-h}^0 Z dz = tanh(kh)/k (1/k in deep water).
pub(super) fn depth_terms(k: f64, depth: Option<f64>) -> (f64, f64) {
    match depth {
        None => (0.0, 1.0 / k),
        Some(h) => {
            let kh2 = 2.0 * k * h;
            // sinh overflows to infinity for 2kh > 710, where s is 0 to double precision.
            (kh2 / kh2.sinh(), (k * h).tanh() / k)
        }
    }
}

/// H_n(x) = J_n + i Y_n for n = -n_max..=n_max at index n + n_max (H_{-n} = (-1)^n H_n).
fn hankel_values(n_max: usize, x: f64) -> Vec<Complex64> {
    let (j, y) = bessel_j_y(n_max, x);
    signed_orders(n_max, |n| Complex64::new(j[n], y[n]))
}

/// Values of orders -n_max..=n_max from a function of orders 0..=n_max, for functions with
/// C_{-n} = (-1)^n C_n (Bessel functions and their derivatives).
fn signed_orders(n_max: usize, of: impl Fn(usize) -> Complex64) -> Vec<Complex64> {
    (0..=2 * n_max)
        .map(|i| {
            let n = i.abs_diff(n_max);
            let v = of(n);
            if i < n_max && n % 2 == 1 {
                -v
            } else {
                v
            }
        })
        .collect()
}

/// Below this value of (pi k a / 2) |J'_m H'_m| the surface amplitude u_m of a row is
/// computed from the regular coefficients c = inc + P b instead of from b alone (see
/// [`FrequencySystem::solve`]): the shortcut divides by J'_m and would amplify the solver's
/// round-off by up to 1/0.1 here, more near the zeros of J'_m.
const SHORTCUT_LIMIT: f64 = 0.1;

/// How the surface amplitude of one row follows from the solution (see
/// [`FrequencySystem::solve`]).
#[derive(Debug, Clone, Copy)]
enum SurfaceRow {
    /// u_m = factor * b_m, factor = -2 i / (pi k a J'_m |H'_m|).
    FromScaled(Complex64),
    /// u_m = factor * (inc_m + (P b)_m), factor = 2 i / (pi k a H'_m).
    FromRegular(Complex64),
}

/// The factored scattering system of one wavenumber.
pub(super) struct FrequencySystem {
    /// Wavenumber, 1/m.
    pub k: f64,
    /// Modes -M..=M are kept on every column.
    pub modes: usize,
    /// 1 / |H'_m(k a_c)| at index c (2M+1) + m + M.
    inverse_norm: Vec<f64>,
    /// J'_m |H'_m| / H'_m (= |H'_m| Z_m), same index.
    row_scale: Vec<Complex64>,
    /// Surface amplitude of every row, same index.
    surface_rows: Vec<SurfaceRow>,
    /// P[(k, m), (j, n)] = e^{i (n-m) alpha_jk} H_{n-m}(k R_jk) / |H'_n(k a_j)|, j != k;
    /// zero diagonal blocks.
    interaction: DMatrix<Complex64>,
    /// LU factors of I + diag(row_scale) P.
    lu: LU<Complex64, Dyn, Dyn>,
}

/// Solutions for a set of incident waves (one per matrix column).
pub(super) struct Solution {
    /// Surface amplitudes u_m of every column (rows c (2M+1) + m + M).
    pub surface: DMatrix<Complex64>,
    /// Scattering coefficients B_n^j (same rows).
    pub scattered: DMatrix<Complex64>,
}

impl FrequencySystem {
    /// Builds and factors the system; `None` if an entry is not finite (Hankel functions out
    /// of range) or the matrix is singular.
    pub fn new(cylinders: &[Circle], k: f64, modes: usize) -> Option<Self> {
        let width = 2 * modes + 1;
        let n = cylinders.len() * width;
        let mut dh = Vec::with_capacity(n);
        let mut surface_rows = Vec::with_capacity(n);
        for c in cylinders {
            let ka = k * c.radius;
            let h = hankel_derivatives(modes, ka);
            for d in signed_orders(modes, |m| h[m]) {
                let jh = d.re * d.norm();
                surface_rows.push(if 0.5 * PI * ka * jh.abs() >= SHORTCUT_LIMIT {
                    SurfaceRow::FromScaled(Complex64::new(0.0, -2.0 / (PI * ka * jh)))
                } else {
                    SurfaceRow::FromRegular(Complex64::new(0.0, 2.0 / (PI * ka)) / d)
                });
                dh.push(d);
            }
        }
        let inverse_norm: Vec<f64> = dh.iter().map(|d| 1.0 / d.norm()).collect();
        let row_scale: Vec<Complex64> = dh.iter().map(|&d| d.re * d.norm() / d).collect();
        let mut interaction = DMatrix::zeros(n, n);
        for (kk, ck) in cylinders.iter().enumerate() {
            for (j, cj) in cylinders.iter().enumerate() {
                if j == kk {
                    continue;
                }
                let (dx, dy) = (ck.x - cj.x, ck.y - cj.y);
                let alpha = dy.atan2(dx);
                let h = hankel_values(2 * modes, k * dx.hypot(dy));
                // order d = n - m in -2M..=2M at index d + 2M
                let turned: Vec<Complex64> = h
                    .iter()
                    .enumerate()
                    .map(|(i, &v)| {
                        let d = i as f64 - 2.0 * modes as f64;
                        v * Complex64::from_polar(1.0, d * alpha)
                    })
                    .collect();
                for nn in 0..width {
                    let scale = inverse_norm[j * width + nn];
                    for m in 0..width {
                        interaction[(kk * width + m, j * width + nn)] =
                            turned[nn + 2 * modes - m] * scale;
                    }
                }
            }
        }
        let finite = |v: &Complex64| v.re.is_finite() && v.im.is_finite();
        if !interaction.iter().all(finite) || !dh.iter().all(finite) {
            return None;
        }
        let mut system = interaction.clone();
        for c in 0..n {
            for (r, s) in row_scale.iter().enumerate() {
                system[(r, c)] *= s;
            }
            system[(c, c)] += 1.0;
        }
        let lu = system.lu();
        if !lu.is_invertible() {
            return None;
        }
        Some(FrequencySystem {
            k,
            modes,
            inverse_norm,
            row_scale,
            surface_rows,
            interaction,
            lu,
        })
    }

    /// Regular-wave coefficients inc_(c, m) = I_c e^{i m (pi/2 - b)} of the incident wave of
    /// unit amplitude and heading `beta` at every column, written to `out`.
    pub fn incident(&self, cylinders: &[Circle], beta: f64, out: &mut [Complex64]) {
        let width = 2 * self.modes + 1;
        let (sin, cos) = beta.sin_cos();
        for (c, cyl) in cylinders.iter().enumerate() {
            let phase = Complex64::from_polar(1.0, self.k * (cyl.x * cos + cyl.y * sin));
            for (i, v) in out[c * width..(c + 1) * width].iter_mut().enumerate() {
                let m = i as f64 - self.modes as f64;
                *v = phase * Complex64::from_polar(1.0, m * (0.5 * PI - beta));
            }
        }
    }

    /// d/dbeta of [`Self::incident`]: inc_(c, m) (i k (-x_c sin b + y_c cos b) - i m).
    pub fn incident_derivative(&self, cylinders: &[Circle], beta: f64, out: &mut [Complex64]) {
        let width = 2 * self.modes + 1;
        self.incident(cylinders, beta, out);
        let (sin, cos) = beta.sin_cos();
        for (c, cyl) in cylinders.iter().enumerate() {
            let along = self.k * (-cyl.x * sin + cyl.y * cos);
            for (i, v) in out[c * width..(c + 1) * width].iter_mut().enumerate() {
                let m = i as f64 - self.modes as f64;
                *v *= Complex64::new(0.0, along - m);
            }
        }
    }

    /// Solves for the incident waves given by their regular-wave coefficients (one per
    /// column of `incident`; see [`Self::incident`]).
    ///
    /// The scaled system (I + diag(row_scale) P) b = -row_scale inc gives b = -row_scale c
    /// with c = inc + P b the regular coefficients, so u_m = 2 i c_m/(pi k a H'_m) =
    /// -2 i b_m/(pi k a J'_m |H'_m|) needs no product with P, except on the few rows where
    /// J'_m is nearly zero ([`SHORTCUT_LIMIT`]).
    pub fn solve(&self, incident: &DMatrix<Complex64>) -> Solution {
        let mut scaled = incident.clone();
        for c in 0..scaled.ncols() {
            for (r, s) in self.row_scale.iter().enumerate() {
                scaled[(r, c)] *= -s;
            }
        }
        let ok = self.lu.solve_mut(&mut scaled);
        debug_assert!(ok, "the factored matrix was checked to be invertible");
        let mut surface = DMatrix::zeros(scaled.nrows(), scaled.ncols());
        for (r, row) in self.surface_rows.iter().enumerate() {
            match *row {
                SurfaceRow::FromScaled(factor) => {
                    for c in 0..scaled.ncols() {
                        surface[(r, c)] = factor * scaled[(r, c)];
                    }
                }
                SurfaceRow::FromRegular(factor) => {
                    let regular = self.interaction.row(r) * &scaled + incident.row(r);
                    for c in 0..scaled.ncols() {
                        surface[(r, c)] = factor * regular[c];
                    }
                }
            }
        }
        let mut scattered = scaled;
        for c in 0..scattered.ncols() {
            for (r, inverse_norm) in self.inverse_norm.iter().enumerate() {
                scattered[(r, c)] *= inverse_norm;
            }
        }
        Solution { surface, scattered }
    }
}

/// First-order horizontal force on column `c` (surge, sway), per unit wave amplitude, in
/// Linton & Evans' e^{-i omega t} convention, from its surface amplitudes u:
///   F_x = -rho g a D pi (u_1 + u_{-1}),  F_y = -i pi rho g a D (u_1 - u_{-1}),
/// D = int Z dz (pressure p = rho g A Z psi, force -int p n dS with n = e_r, and
/// int_0^{2 pi} e^{i m t} (cos t, sin t) dt = pi (d_{m,1} + d_{m,-1}, i (d_{m,1} - d_{m,-1}))).
pub(super) fn column_force(
    u: &[Complex64],
    modes: usize,
    radius: f64,
    rho_g: f64,
    depth_integral: f64,
) -> [Complex64; 2] {
    let (up, um) = (u[modes + 1], u[modes - 1]);
    let scale = -rho_g * radius * depth_integral * PI;
    [scale * (up + um), scale * Complex64::i() * (up - um)]
}
