//! Mean drift force and yaw moment of the column array, by two independent routes.
//!
//! Both work with the surface amplitudes u_m and scattering coefficients B_n^j of
//! [`super::scattering`] (e^{-i omega t}, unit incident amplitude). The mean drift is a real
//! quadratic quantity and has no time convention; the bi-directional form is converted by
//! the caller.
//!
//! # (a) Near field: pressure integration on each column
//!
//! For a fixed body, with n = e_r pointing out of the column into the fluid, the mean
//! force to second order is (Pinkster's pressure integration; Faltinsen 1990 ch. 5)
//!   F = -(rho g / 4) oint_WL |eta|^2 n dl + (rho / 4) int int_S |grad phi|^2 n dS,
//! where |eta|^2/2 and |grad phi|^2/2 are the time averages of zeta^2 and |grad Phi|^2 for
//! complex amplitudes eta, phi: the first term is the waterline integral of
//! int_0^zeta rho g (zeta - z) dz = rho g zeta^2/2, the second the mean of the Bernoulli term
//! -rho |grad Phi|^2/2 in -int p n dS. On the column d phi/dr = 0, so
//! |grad phi|^2 = (g/omega)^2 (Z^2 |psi_t|^2 / a^2 + Z'^2 |psi|^2), and the depth integrals in
//! closed form, with s = 2kh/sinh 2kh and omega^2 = g k tanh kh,
//!   (g/omega)^2 int_{-h}^0 Z^2 dz = g (1 + s)/(2 k^2),  (g/omega)^2 int Z'^2 dz = g (1 - s)/2
//! (deep water: int e^{2kz} dz = 1/(2k), s = 0), give per unit waterline length
//!   (rho g/8) [(1 + s) |psi_t|^2/(k a)^2 + (1 - s) |psi|^2] - (rho g/4) |psi|^2
//!   = (rho g (1 + s)/8) (|psi_t|^2/(k a)^2 - |psi|^2).
//! With psi = sum u_m e^{i m t} on r = a the angular integrals are finite sums:
//!   F_x - i F_y = (pi/4) rho g a (1 + s) Q,   Q = sum_m (m (m + 1)/(k a)^2 - 1) u_{m+1} conj(u_m).
//! For one column this is, term by term, Havelock's series times 1 + 2kh/sinh 2kh
//! (docs/theory.md#checks-with-known-answers). Pressure acts normal to the circular column, through
//! its axis, so
//! the yaw moment about the origin is sum_c (x_c F_y,c - y_c F_x,c), exactly.
//!
//! Two incident waves of amplitudes A_p, A_q (headings b_p, b_q, same frequency) give
//! u = A_p u_p + A_q u_q, and the force is the Hermitian form
//!   F = sum_{p,q} A_p conj(A_q) T_pq,
//!   T^x_pq = (c/2) [Q(u_p, u_q) + conj Q(u_q, u_p)],  T^y_pq = (i c/2) [Q(u_p, u_q) - conj Q(u_q, u_p)],
//! c = (pi/4) rho g a (1 + s), Q(v, w) = sum_m (m(m+1)/(ka)^2 - 1) v_{m+1} conj(w_m). T_pp is
//! the uni-directional drift and T_qp = conj(T_pq).
//!
//! # (b) Far field: momentum and angular-momentum flux (Maruo 1960; Newman 1967)
//!
//! With the Kochin function H(t) = sum_j e^{-i k (x_j cos t + y_j sin t)} sum_n B_n^j (-i)^n e^{i n t},
//! the scattered wave far away is psi_S ~ H(t) sqrt(2/(pi k r)) e^{i (k r - pi/4)}. The mean
//! momentum flux through a large circle, per unit length, for fields eta with the same depth
//! profile is (rho g c_g / (4 c)) [(|eta|^2 - |grad eta|^2/k^2) n + (2/k^2) Re(grad eta conj(d eta/dn))];
//! evaluating the scattered-scattered part and the incident-scattered part (stationary phase
//! at t = b) gives, per unit amplitude squared,
//!   F = -(rho g/k)(c_g/c) [(1/pi) int |H|^2 e_r dt + 2 Re H(b) e_b]
//!     = (rho g/(pi k))(c_g/c) int_0^{2 pi} |H(t)|^2 (e_b - e_r(t)) dt,
//! by the optical theorem int |H|^2 dt = -2 pi Re H(b) (zero mean energy flux). For one
//! column this is (2 rho g / k)(c_g/c) sum_{n>=0} |Z_n - Z_{n+1}|^2
//! (docs/theory.md#checks-with-known-answers).
//! The moment about the origin follows from the angular-momentum flux r M_t, where the
//! scattered wave's angular gradient (1/r) dH/dt enters at O(1/r) and the incident-
//! scattered term, after an integration by parts in t, at the stationary point t = b:
//!   N_z = -(rho g/(pi k^2))(c_g/c) [int_0^{2 pi} Im(H'(t) conj H(t)) dt + 2 pi Im H'(b)],
//! H' = dH/dt (this is Newman's (1967) formula in the present normalisation; it agrees with
//! the near-field moment in the tests).
//!
//! The integrands are trigonometric polynomials: H has bandwidth M + P, where
//! P = k rho_max + 12 (k rho_max)^{1/3} + 12 bounds the orders p of the Jacobi-Anger expansion
//! of e^{-i k rho cos(t - t_j)} with |J_p(k rho)| above ~1e-17 (Debye: J_p decays like
//! Ai(2^{1/3} (p - x)/x^{1/3})). The trapezoidal rule with N > 2 (M + P) + 1 nodes
//! integrates them exactly; H and H' on the nodes come from one inverse FFT per column and
//! quantity.

use super::scattering::Circle;
use rustfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};
use std::f64::consts::PI;
use std::sync::Arc;

/// Near-field Hermitian form T_pq (surge, sway, yaw) for surface amplitudes `u_p`, `u_q` of
/// all columns (module doc), Linton & Evans convention (F = sum A_p conj(A_q) T_pq).
/// `rho_g` = rho g, `s` = 2kh/sinh 2kh.
pub(super) fn near_field_form(
    cylinders: &[Circle],
    modes: usize,
    k: f64,
    rho_g: f64,
    s: f64,
    u_p: &[Complex64],
    u_q: &[Complex64],
) -> [Complex64; 3] {
    let width = 2 * modes + 1;
    let mut t = [Complex64::new(0.0, 0.0); 3];
    for (col, cyl) in cylinders.iter().enumerate() {
        let range = col * width..(col + 1) * width;
        let (p, q) = (&u_p[range.clone()], &u_q[range]);
        let ka2 = (k * cyl.radius).powi(2);
        let mut q_pq = Complex64::new(0.0, 0.0);
        let mut q_qp = Complex64::new(0.0, 0.0);
        for i in 0..width - 1 {
            let m = i as f64 - modes as f64;
            let weight = m * (m + 1.0) / ka2 - 1.0;
            q_pq += weight * p[i + 1] * q[i].conj();
            q_qp += weight * q[i + 1] * p[i].conj();
        }
        let c = 0.25 * PI * rho_g * cyl.radius * (1.0 + s);
        let tx = 0.5 * c * (q_pq + q_qp.conj());
        let ty = Complex64::new(0.0, 0.5 * c) * (q_pq - q_qp.conj());
        t[0] += tx;
        t[1] += ty;
        t[2] += cyl.x * ty - cyl.y * tx;
    }
    t
}

/// Real part of a form evaluated on the diagonal (the uni-directional drift) or twice the
/// real part (the derivative of the diagonal along a direction in amplitude space).
pub(super) fn real_parts(t: [Complex64; 3], factor: f64) -> [f64; 3] {
    t.map(|v| factor * v.re)
}

/// Far-field evaluation of one frequency (module doc, route (b)).
pub(super) struct FarField {
    k: f64,
    modes: usize,
    nodes: usize,
    fft: Arc<dyn Fft<f64>>,
    cylinders: Vec<Circle>,
    /// e^{-i k (x_j cos t_l + y_j sin t_l)} at index j * nodes + l.
    phase: Vec<Complex64>,
    /// d/dt of the phase's exponent: -i k (-x_j sin t_l + y_j cos t_l).
    slope: Vec<Complex64>,
    /// (cos t_l, sin t_l).
    direction: Vec<(f64, f64)>,
}

impl FarField {
    pub fn new(cylinders: &[Circle], k: f64, modes: usize, planner: &mut FftPlanner<f64>) -> Self {
        let reach = cylinders
            .iter()
            .map(|c| k * c.x.hypot(c.y))
            .fold(0.0, f64::max);
        let band = modes + (reach + 12.0 * reach.cbrt() + 12.0).ceil() as usize;
        let nodes = (2 * band + 2).next_power_of_two();
        let direction: Vec<(f64, f64)> = (0..nodes)
            .map(|l| {
                let (s, c) = (2.0 * PI * l as f64 / nodes as f64).sin_cos();
                (c, s)
            })
            .collect();
        let mut phase = Vec::with_capacity(cylinders.len() * nodes);
        let mut slope = Vec::with_capacity(cylinders.len() * nodes);
        for c in cylinders {
            for &(cos, sin) in &direction {
                phase.push(Complex64::from_polar(1.0, -k * (c.x * cos + c.y * sin)));
                slope.push(Complex64::new(0.0, -k * (-c.x * sin + c.y * cos)));
            }
        }
        FarField {
            k,
            modes,
            nodes,
            fft: planner.plan_fft_inverse(nodes),
            cylinders: cylinders.to_vec(),
            phase,
            slope,
            direction,
        }
    }

    /// Mean drift (surge, sway, yaw) per unit amplitude squared for scattering coefficients
    /// `b` (all columns) of the wave of heading `beta`.
    pub fn drift(&self, b: &[Complex64], beta: f64, rho_g: f64, s: f64) -> [f64; 3] {
        let width = 2 * self.modes + 1;
        let n = self.nodes;
        let mut kochin = vec![Complex64::new(0.0, 0.0); n];
        let mut slope_kochin = vec![Complex64::new(0.0, 0.0); n];
        let mut g = vec![Complex64::new(0.0, 0.0); n];
        let mut dg = vec![Complex64::new(0.0, 0.0); n];
        let mut at_beta = Complex64::new(0.0, 0.0);
        let (sin_b, cos_b) = beta.sin_cos();
        for (j, cyl) in self.cylinders.iter().enumerate() {
            g.iter_mut().for_each(|v| *v = Complex64::new(0.0, 0.0));
            dg.iter_mut().for_each(|v| *v = Complex64::new(0.0, 0.0));
            let mut g_beta = Complex64::new(0.0, 0.0);
            let mut dg_beta = Complex64::new(0.0, 0.0);
            for (i, &coefficient) in b[j * width..(j + 1) * width].iter().enumerate() {
                let order = i as isize - self.modes as isize;
                // (-i)^n
                let turn = match order.rem_euclid(4) {
                    0 => Complex64::new(1.0, 0.0),
                    1 => Complex64::new(0.0, -1.0),
                    2 => Complex64::new(-1.0, 0.0),
                    _ => Complex64::new(0.0, 1.0),
                };
                let gn = coefficient * turn;
                let dgn = gn * Complex64::new(0.0, order as f64);
                let slot = order.rem_euclid(n as isize) as usize;
                g[slot] = gn;
                dg[slot] = dgn;
                let e = Complex64::from_polar(1.0, order as f64 * beta);
                g_beta += gn * e;
                dg_beta += dgn * e;
            }
            self.fft.process(&mut g);
            self.fft.process(&mut dg);
            let phase = &self.phase[j * n..(j + 1) * n];
            let slope = &self.slope[j * n..(j + 1) * n];
            for l in 0..n {
                kochin[l] += phase[l] * g[l];
                slope_kochin[l] += phase[l] * (slope[l] * g[l] + dg[l]);
            }
            let phase_b = Complex64::from_polar(1.0, -self.k * (cyl.x * cos_b + cyl.y * sin_b));
            let slope_b = Complex64::new(0.0, -self.k * (-cyl.x * sin_b + cyl.y * cos_b));
            at_beta += phase_b * (slope_b * g_beta + dg_beta);
        }
        let (mut fx, mut fy, mut moment) = (0.0, 0.0, 0.0);
        for l in 0..n {
            let power = kochin[l].norm_sqr();
            let (cos, sin) = self.direction[l];
            fx += power * (cos_b - cos);
            fy += power * (sin_b - sin);
            moment += (slope_kochin[l] * kochin[l].conj()).im;
        }
        let dt = 2.0 * PI / n as f64;
        let cg_over_c = 0.5 * (1.0 + s);
        let force_scale = rho_g / (PI * self.k) * cg_over_c * dt;
        let moment_scale = -rho_g / (PI * self.k * self.k) * cg_over_c;
        [
            force_scale * fx,
            force_scale * fy,
            moment_scale * (moment * dt + 2.0 * PI * at_beta.im),
        ]
    }
}
