//! Closed-form mean wave-drift force on fixed vertical circular columns in regular waves
//! (docs/theory.md#checks-with-known-answers), and a drift table for an array of such columns.
//!
//! Single column of radius a in waves of amplitude A and wavenumber k: the mean horizontal
//! force along the wave direction is F = rho g A^2 a C(ka), with C from Havelock (1940) in
//! deep water, or with the MacCamy & Fuchs (1954) kinematics in water of depth h, where the
//! finite-depth factor 1 + 2kh/sinh(2kh) = 2 c_g/c multiplies the deep-water series. Two
//! independent routes are given: the near-field pressure-integration series
//! ([`havelock_drift_coefficient`]) and the far-field momentum flux
//! ([`far_field_drift_coefficient`]). Limits: C -> 2/3 as ka -> infinity (the reflection
//! from the lit half of the waterline, (1/2) rho g A^2 integrated with cos^3), and
//! C ~ (5 pi^2/16) (ka)^3 as ka -> 0.
//!
//! [`isolated_columns_table`] is a closed-form APPROXIMATION used for the interim default
//! platform: every column is treated as an isolated, fixed, infinitely deep cylinder in deep
//! water. It ignores the hydrodynamic interaction between columns
//! (docs/theory.md#columns-linton-and-evans),
//! the finite draft and any pontoons, and the body motions. Because the real column is
//! truncated, it over-predicts the drift at low k*draft (docs/theory.md#columns-linton-and-evans:
//! the
//! truncated column carries roughly a fraction 1 - e^{-k draft} of it); the column drafts
//! are not used.

use crate::error::numbers::{readable, written};
use crate::error::{require_finite, require_positive, Error, Result};
use crate::hydro::{DriftRow, DriftTable};
use crate::model::{Cylinder, Environment};
use crate::special::bessel::hankel_derivatives;
use rustfft::num_complex::Complex64;
use std::f64::consts::PI;

/// Orders summed beyond ka before the series may be truncated.
const MIN_EXTRA_ORDERS: usize = 10;

/// The series stops at the first term (n >= ka + [`MIN_EXTRA_ORDERS`]) below this fraction
/// of the partial sum.
const SERIES_TOLERANCE: f64 = 1e-16;

/// C ~ LONG_WAVE_SLOPE (ka)^3 as ka -> 0 (deep water): with x = ka, |H'_0|^2 ~ 4/(pi x)^2,
/// |H'_1|^2 ~ 4/(pi^2 x^4), |H'_2|^2 ~ 64/(pi^2 x^6) (A&S 9.1.9), the n = 0 and n = 1
/// terms of the series are pi^4 x^6/16 and pi^4 x^6/64 (the others are O(x^10)); times
/// 4/(pi^2 x^3) this is (5 pi^2/16) x^3.
pub const LONG_WAVE_SLOPE: f64 = 5.0 * PI * PI / 16.0;

/// Below this ka [`havelock_drift_coefficient`] returns LONG_WAVE_SLOPE (ka)^3 times the
/// depth factor: the relative error of that limit is ~2e-12 here (an O((ka)^2) correction),
/// while the series' high-order Hankel derivatives approach overflow as ka -> 0.
const LONG_WAVE_KA: f64 = 1e-6;

/// Largest ka accepted by the table: the range where the Bessel functions are verified.
pub const MAX_KA: f64 = 200.0;

/// F_mean / (rho g A^2 a) on a fixed vertical circular column by the near-field series
/// (docs/theory.md#checks-with-known-answers; Havelock 1940, MacCamy & Fuchs 1954 in finite depth):
///
/// C = 4/(pi^2 (ka)^3) * depth_factor
///     * sum_{n>=0} (1 - n(n+1)/(ka)^2)^2 / (|H'_n(ka)|^2 |H'_{n+1}(ka)|^2),
///
/// H_n the Hankel function of the first kind, depth_factor = 1 + 2kh/sinh(2kh) (1 in deep
/// water). The series is truncated adaptively: at least to n = ka + 10, then until a term
/// is below 1e-16 of the partial sum. A term whose Hankel derivatives overflow (high order
/// at small ka) is negligible and counted as zero. Below ka = 1e-6 the long-wave limit
/// [`LONG_WAVE_SLOPE`] (ka)^3 * depth_factor is returned instead (C < 4e-18 there).
///
/// # Panics
/// If `ka` is not finite and positive (see `special::bessel::bessel_j_y`).
pub fn havelock_drift_coefficient(ka: f64, depth_factor: f64) -> f64 {
    if ka < LONG_WAVE_KA && ka > 0.0 {
        return LONG_WAVE_SLOPE * ka.powi(3) * depth_factor;
    }
    let ka2 = ka * ka;
    let sum = adaptive_series(ka, |h, n| {
        let nf = n as f64;
        let angular = 1.0 - nf * (nf + 1.0) / ka2;
        angular * angular / (h[n].norm_sqr() * h[n + 1].norm_sqr())
    });
    4.0 / (PI * PI * ka2 * ka) * depth_factor * sum
}

/// F_mean / (rho g A^2 a) by the far-field momentum flux
/// (docs/theory.md#checks-with-known-answers):
/// F_mean = (2 rho g A^2 / k) (c_g/c) sum_{n>=0} |B_n - B_{n+1}|^2, B_n = J'_n(ka)/H'_n(ka),
/// so C = (2/(ka)) (c_g/c) sum_{n>=0} |B_n - B_{n+1}|^2 (deep water: c_g/c = 1/2).
///
/// Normalisation: the formula of docs/theory.md#checks-with-known-answers holds, with the sum over
/// n >= 0 only. By A&S 9.1.27 and the Wronskian A&S 9.1.15,
/// J'_n Y'_{n+1} - J'_{n+1} Y'_n = -(2/(pi ka)) (1 - n(n+1)/(ka)^2), hence
/// |B_n - B_{n+1}|^2 = 4/(pi^2 (ka)^2) (1 - n(n+1)/(ka)^2)^2 / (|H'_n|^2 |H'_{n+1}|^2):
/// the two routes agree term by term when depth_factor = 2 c_g/c, i.e.
/// c_g/c = (1/2)(1 + 2kh/sinh 2kh).
///
/// # Panics
/// If `ka` is not finite and positive.
pub fn far_field_drift_coefficient(ka: f64, cg_over_c: f64) -> f64 {
    let sum = adaptive_series(ka, |h, n| {
        let b = |m: usize| h[m].re / h[m];
        (b(n) - b(n + 1)).norm_sqr()
    });
    2.0 / ka * cg_over_c * sum
}

/// Sums term(H', n) for n = 0, 1, ... with H' = H'_0..=H'_{n_max+1}(ka), stopping at the
/// first n >= ka + [`MIN_EXTRA_ORDERS`] whose term is below [`SERIES_TOLERANCE`] of the
/// partial sum; n_max is doubled until that happens.
fn adaptive_series(ka: f64, term: impl Fn(&[Complex64], usize) -> f64) -> f64 {
    let min_order = ka.ceil() as usize + MIN_EXTRA_ORDERS;
    let mut n_max = min_order;
    loop {
        let h = hankel_derivatives(n_max + 1, ka);
        let mut sum = 0.0;
        for n in 0..=n_max {
            let t = term(&h, n);
            let t = if t.is_finite() { t } else { 0.0 };
            sum += t;
            if n >= min_order && t <= SERIES_TOLERANCE * sum {
                return sum;
            }
        }
        n_max *= 2;
    }
}

/// Deep-water drift table of an array of columns treated as isolated (module doc: no
/// interaction, infinitely deep columns, draft ignored). For wave frequency omega
/// (k = omega^2/g) and heading beta, column c of radius a_c at (x_c, y_c) carries
/// F_c = rho g a_c C(k a_c) along the wave direction (C = [`havelock_drift_coefficient`]
/// with depth factor 1), so per unit amplitude squared
/// T_surge = sum F_c cos beta, T_sway = sum F_c sin beta,
/// T_yaw = sum (x_c F_c sin beta - y_c F_c cos beta).
///
/// Rows carry no damping. Frequencies must be positive and strictly increasing, headings
/// finite and distinct, and k a_c must not exceed [`MAX_KA`].
pub fn isolated_columns_table(
    columns: &[Cylinder],
    environment: &Environment,
    omegas: &[f64],
    headings: &[f64],
) -> Result<DriftTable> {
    validate_inputs(columns, environment, omegas, headings)?;
    let g = environment.gravity;
    let rho = environment.water_density;
    let mut rows = Vec::with_capacity(omegas.len() * headings.len());
    for &omega in omegas {
        let k = omega * omega / g;
        let forces = columns
            .iter()
            .map(|c| column_force(c, k, rho, g))
            .collect::<Result<Vec<f64>>>()?;
        for &heading in headings {
            rows.push(DriftRow {
                omega,
                heading,
                drift: array_drift(columns, &forces, heading),
                damping: None,
            });
        }
    }
    DriftTable::from_rows(&rows)
}

/// Drift force per unit amplitude squared on one isolated column, N/m^2.
fn column_force(column: &Cylinder, k: f64, rho: f64, g: f64) -> Result<f64> {
    let radius = 0.5 * column.diameter;
    let ka = k * radius;
    if ka > MAX_KA {
        return Err(Error::invalid(
            "drift.omega",
            format!("{} rad/s", readable((k * g).sqrt())),
            format!(
                "k a = {} exceeds {MAX_KA} for a column of diameter {} m",
                readable(ka),
                written(column.diameter)
            ),
        ));
    }
    Ok(rho * g * radius * havelock_drift_coefficient(ka, 1.0))
}

/// (surge, sway, yaw) of forces `forces[c]` along heading beta applied at the column centres.
fn array_drift(columns: &[Cylinder], forces: &[f64], heading: f64) -> [f64; 3] {
    let (sin, cos) = heading.sin_cos();
    columns.iter().zip(forces).fold([0.0; 3], |acc, (c, &f)| {
        [
            acc[0] + f * cos,
            acc[1] + f * sin,
            acc[2] + f * (c.x * sin - c.y * cos),
        ]
    })
}

fn validate_inputs(
    columns: &[Cylinder],
    environment: &Environment,
    omegas: &[f64],
    headings: &[f64],
) -> Result<()> {
    if columns.is_empty() {
        return Err(Error::invalid(
            "platform.columns",
            "[]",
            "no columns to compute the drift of",
        ));
    }
    for (i, c) in columns.iter().enumerate() {
        require_finite(format_args!("platform.columns[{i}].x"), c.x)?;
        require_finite(format_args!("platform.columns[{i}].y"), c.y)?;
        require_positive(&format!("platform.columns[{i}].diameter"), c.diameter)?;
    }
    validate_grid(environment, omegas, headings)
}

/// Environment, frequencies and headings of a drift request (shared with
/// `hydro/columns/`).
pub(crate) fn validate_grid(
    environment: &Environment,
    omegas: &[f64],
    headings: &[f64],
) -> Result<()> {
    require_positive("environment.gravity", environment.gravity)?;
    require_positive("environment.water_density", environment.water_density)?;
    if omegas.is_empty() {
        return Err(Error::invalid("drift.omegas", "[]", "no frequencies"));
    }
    for (i, &w) in omegas.iter().enumerate() {
        require_positive(&format!("drift.omegas[{i}]"), w)?;
    }
    if headings.is_empty() {
        return Err(Error::invalid("drift.headings", "[]", "no headings"));
    }
    for (i, &h) in headings.iter().enumerate() {
        require_finite(format_args!("drift.headings[{i}]"), h)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Limit of C as ka -> infinity: a wall reflects totally, with mean pressure force
    /// (1/2) rho g A^2 per unit length normal to it; on the lit half of the cylinder the
    /// normal component along the waves is (1/2) rho g A^2 cos^2(t) cos(t) a dt, integrated
    /// over t in (-pi/2, pi/2): (1/2)(4/3) = 2/3.
    const SHORT_WAVE_LIMIT: f64 = 2.0 / 3.0;

    fn square_array(half_side: f64, diameter: f64) -> Vec<Cylinder> {
        [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)]
            .iter()
            .map(|&(sx, sy)| Cylinder {
                x: sx * half_side,
                y: sy * half_side,
                diameter,
                draft: 20.0,
            })
            .collect()
    }

    fn degrees(values: &[f64]) -> Vec<f64> {
        values.iter().map(|d| d.to_radians()).collect()
    }

    /// The Havelock series evaluated independently with mpmath (40 digits, its own Bessel
    /// functions, derivatives by A&S 9.1.27).
    #[test]
    fn series_matches_arbitrary_precision_values() {
        let table = [
            (0.1, 0.003_065_583_712_732_55),
            (0.5, 0.285_985_628_729_025),
            (1.0, 0.664_925_637_776_087),
            (2.0, 0.627_174_665_368_125_4),
            (5.0, 0.643_759_948_356_199_2),
            (10.0, 0.655_083_530_358_728),
            (50.0, 0.664_860_869_522_420_8),
        ];
        for (ka, reference) in table {
            let c = havelock_drift_coefficient(ka, 1.0);
            assert!(
                (c - reference).abs() < 1e-13 * reference,
                "ka = {ka}: {c} vs {reference}"
            );
        }
    }

    /// Approach to 2/3 from below. The remainder decays only like ~(ka)^-1.3 (it is
    /// 1.8e-3 at ka = 50, 3.2e-4 at ka = 200, confirmed with mpmath), so the bounds are
    /// looser than a 1e-3 at ka = 50.
    #[test]
    fn short_wave_limit_is_two_thirds() {
        let mut previous = f64::INFINITY;
        for (ka, bound) in [(20.0, 6e-3), (50.0, 2e-3), (100.0, 1e-3), (200.0, 4e-4)] {
            let gap = SHORT_WAVE_LIMIT - havelock_drift_coefficient(ka, 1.0);
            assert!(gap > 0.0 && gap < bound, "ka = {ka}: 2/3 - C = {gap}");
            assert!(gap < previous, "the gap must shrink with ka");
            previous = gap;
        }
    }

    /// C / ((5 pi^2/16) (ka)^3) -> 1 with an O((ka)^2) correction.
    #[test]
    fn long_wave_limit_is_cubic() {
        for (ka, tolerance) in [(1e-4, 1e-7), (1e-3, 1e-5), (1e-2, 1e-3)] {
            let ratio = havelock_drift_coefficient(ka, 1.0) / (LONG_WAVE_SLOPE * ka.powi(3));
            assert!((ratio - 1.0).abs() < tolerance, "ka = {ka}: ratio {ratio}");
        }
        // The series and the limit used below LONG_WAVE_KA join continuously.
        let below = havelock_drift_coefficient(LONG_WAVE_KA * (1.0 - 1e-12), 1.0);
        let above = havelock_drift_coefficient(LONG_WAVE_KA, 1.0);
        assert!((above - below).abs() < 1e-11 * above, "{below} vs {above}");
        let tiny = havelock_drift_coefficient(1e-200, 1.0);
        assert!(tiny.is_finite() && tiny >= 0.0);
    }

    /// Near-field series and far-field momentum flux agree in deep water (c_g/c = 1/2).
    #[test]
    fn near_and_far_field_agree() {
        for i in 0..=40 {
            let ka = 0.05 * 400.0_f64.powf(i as f64 / 40.0);
            let near = havelock_drift_coefficient(ka, 1.0);
            let far = far_field_drift_coefficient(ka, 0.5);
            assert!(
                (near - far).abs() < 1e-10 * near,
                "ka = {ka}: {near} vs {far}"
            );
        }
    }

    /// Finite depth: c_g/c taken from a numerical derivative of the dispersion relation
    /// omega^2 = g k tanh(kh) equals (1 + 2kh/sinh 2kh)/2, and the near-field series with
    /// that depth factor agrees with the far-field flux; deep water is the kh -> inf limit.
    #[test]
    fn finite_depth_consistency() {
        let depth = 1.0;
        let omega = |k: f64| (k * (k * depth).tanh()).sqrt();
        for kh in [0.3, 1.0, 3.0, 30.0] {
            let k = kh / depth;
            let step = 1e-5 * k;
            let group = (omega(k + step) - omega(k - step)) / (2.0 * step);
            let cg_over_c = group / (omega(k) / k);
            let depth_factor = 1.0 + 2.0 * kh / (2.0 * kh).sinh();
            assert!((cg_over_c - 0.5 * depth_factor).abs() < 1e-8, "kh = {kh}");
            for ka in [0.2, 1.0, 4.0] {
                let near = havelock_drift_coefficient(ka, depth_factor);
                let far = far_field_drift_coefficient(ka, 0.5 * depth_factor);
                assert!((near - far).abs() < 1e-10 * near);
                let deep = havelock_drift_coefficient(ka, 1.0);
                assert!((near - depth_factor * deep).abs() < 1e-14 * near);
            }
        }
        let deep_factor = 1.0 + 60.0 / 60.0_f64.sinh();
        assert_eq!(deep_factor, 1.0);
    }

    /// Square array centred at the origin: no sway and no yaw at beta = 0, yaw zero at every
    /// heading, T_surge(beta) = T_sway(beta + 90 deg), and |T| = 4 F at every heading.
    #[test]
    fn square_array_symmetry() {
        let env = Environment::default();
        let columns = square_array(30.0, 12.0);
        let omegas = [0.3, 0.5, 0.8, 1.2];
        let headings = degrees(&(0..24).map(|i| 15.0 * i as f64).collect::<Vec<f64>>());
        let table = isolated_columns_table(&columns, &env, &omegas, &headings).expect("valid");
        for (iw, &omega) in omegas.iter().enumerate() {
            let ka = omega * omega / env.gravity * 6.0;
            let single =
                env.water_density * env.gravity * 6.0 * havelock_drift_coefficient(ka, 1.0);
            let at_zero = table.drift_at_node(0, iw);
            assert!(at_zero[1].abs() < 1e-12 * single && at_zero[2].abs() < 1e-9 * single);
            for ih in 0..24 {
                let t = table.drift_at_node(ih, iw);
                let turned = table.drift_at_node((ih + 6) % 24, iw);
                assert!((t[0] - turned[1]).abs() < 1e-12 * single, "ih = {ih}");
                assert!(t[2].abs() < 1e-9 * single, "yaw at ih = {ih}: {}", t[2]);
                assert!((t[0].hypot(t[1]) - 4.0 * single).abs() < 1e-12 * single);
            }
        }
    }

    /// One off-centre column: the yaw moment vanishes when the waves travel along the line
    /// through the origin and the column centre, and equals F |r| across it.
    #[test]
    fn off_centre_column_moment() {
        let env = Environment::default();
        let column = Cylinder {
            x: 30.0,
            y: -40.0,
            diameter: 10.0,
            draft: 25.0,
        };
        let along = column.y.atan2(column.x);
        let across = along + 0.5 * PI;
        let table =
            isolated_columns_table(&[column], &env, &[0.6], &[along, across]).expect("valid");
        let ka = 0.36 / env.gravity * 5.0;
        let force = env.water_density * env.gravity * 5.0 * havelock_drift_coefficient(ka, 1.0);
        let (ih_along, ih_across) = if along < across { (0, 1) } else { (1, 0) };
        assert!(table.drift_at_node(ih_along, 0)[2].abs() < 1e-12 * force * 50.0);
        let moment = table.drift_at_node(ih_across, 0)[2];
        assert!(
            (moment - force * 50.0).abs() < 1e-12 * force * 50.0,
            "{moment}"
        );
    }

    /// A single column at ka = 1 reproduces rho g a C(1) with C from mpmath.
    #[test]
    fn single_column_value() {
        let env = Environment::default();
        let radius = 5.0;
        let omega = (env.gravity / radius).sqrt();
        let column = Cylinder {
            x: 0.0,
            y: 0.0,
            diameter: 2.0 * radius,
            draft: 30.0,
        };
        let table = isolated_columns_table(&[column], &env, &[omega], &[0.0]).expect("valid");
        let expected = env.water_density * env.gravity * radius * 0.664_925_637_776_087;
        let surge = table.drift_at_node(0, 0)[0];
        assert!(
            (surge - expected).abs() < 1e-12 * expected,
            "{surge} vs {expected}"
        );
        assert!(!table.has_damping());
    }

    fn field_of(err: Error) -> String {
        match err {
            Error::InvalidValue { field, .. } => field,
            other => panic!("unexpected error {other:?}"),
        }
    }

    #[test]
    fn input_errors_name_the_field() {
        let env = Environment::default();
        let good = square_array(20.0, 8.0);
        let w = [0.4, 0.6];
        let b = [0.0];
        let call = |c: &[Cylinder], e: &Environment, w: &[f64], b: &[f64]| {
            field_of(isolated_columns_table(c, e, w, b).expect_err("must be refused"))
        };
        assert_eq!(call(&[], &env, &w, &b), "platform.columns");
        let mut bad = good.clone();
        bad[2].diameter = -1.0;
        assert_eq!(call(&bad, &env, &w, &b), "platform.columns[2].diameter");
        let mut bad = good.clone();
        bad[1].x = f64::NAN;
        assert_eq!(call(&bad, &env, &w, &b), "platform.columns[1].x");
        let no_gravity = Environment {
            gravity: 0.0,
            ..env.clone()
        };
        assert_eq!(call(&good, &no_gravity, &w, &b), "environment.gravity");
        assert_eq!(call(&good, &env, &[], &b), "drift.omegas");
        assert_eq!(call(&good, &env, &[0.4, -0.6], &b), "drift.omegas[1]");
        assert_eq!(call(&good, &env, &w, &[]), "drift.headings");
        assert_eq!(call(&good, &env, &w, &[f64::INFINITY]), "drift.headings[0]");
        assert_eq!(call(&good, &env, &[0.6, 0.4], &b), "drift.rows[1].omega");
        assert_eq!(call(&good, &env, &[0.4, 30.0], &b), "drift.omega");
    }
}
