//! Bessel functions of the first and second kind, J_n(x) and Y_n(x), of integer order
//! n = 0..=n_max and real argument x > 0, with their derivatives and the derivative of the
//! Hankel function of the first kind H_n = J_n + i Y_n.
//!
//! Method (Abramowitz & Stegun 1964, chapter 9, "A&S 9.x.y" below):
//! - J_n by Miller's backward recurrence J_{n-1} = (2n/x) J_n - J_{n+1} (A&S 9.1.27),
//!   started well above max(n_max, x) and normalised by J_0 + 2 sum_k J_2k = 1 (A&S 9.1.46),
//!   or, for x >= [`HANKEL_SWITCH`], by the asymptotic J_0 or J_1 (whichever is larger);
//! - Y_0 and Y_1 by the Neumann series in the J's (A&S 9.1.88, 9.1.89) for
//!   x < [`HANKEL_SWITCH`], by Hankel's asymptotic expansion (A&S 9.2.5-9.2.10) above;
//! - Y_n, n >= 2, by forward recurrence, which is stable for the second kind.
//!
//! Accuracy: relative ~1e-14 or better for x in (0, 200] away from zeros (absolute
//! ~1e-16 times the local amplitude sqrt(2/(pi x)) near zeros), checked against
//! arbitrary-precision values in the tests. Larger x works but is slower and untested.

use rustfft::num_complex::Complex64;
use std::f64::consts::{FRAC_1_SQRT_2, PI};

/// Euler-Mascheroni constant gamma_E (A&S 6.1.3).
const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// Above this argument Y_0 and Y_1 come from Hankel's asymptotic expansion: its smallest
/// term is ~exp(-2x), below 1e-17 here, while the Neumann series slowly loses digits to
/// the growing logarithm and the number of terms.
const HANKEL_SWITCH: f64 = 25.0;

/// Extra orders above max(n_max, x) where Miller's recurrence starts, as in Numerical
/// Recipes' `bessj`: start = m + sqrt(MILLER_HEADROOM * m) + MILLER_MARGIN.
const MILLER_HEADROOM: f64 = 160.0;

/// Fixed safety margin of orders for the start of Miller's recurrence.
const MILLER_MARGIN: usize = 20;

/// Rescaling threshold during the backward recurrence (avoids overflow).
const RESCALE_ABOVE: f64 = 1e250;

/// Relative size of the last retained term of Hankel's asymptotic series.
const SERIES_TOLERANCE: f64 = 1e-17;

/// J_0..=J_{n_max} and Y_0..=Y_{n_max} at x.
///
/// # Panics
/// If `x` is not finite and strictly positive (the functions are defined here for x > 0).
pub fn bessel_j_y(n_max: usize, x: f64) -> (Vec<f64>, Vec<f64>) {
    assert!(
        x.is_finite() && x > 0.0,
        "Bessel functions need a finite x > 0, got {x}"
    );
    let mut j = bessel_j_all(n_max, x);
    let (y0, y1) = if x < HANKEL_SWITCH {
        neumann_y0_y1(&j, x)
    } else {
        let (j0, y0) = hankel_asymptotic(0, x);
        let (j1, y1) = hankel_asymptotic(1, x);
        renormalise(&mut j, j0, j1);
        (y0, y1)
    };
    let y = forward_recurrence_y(n_max, x, y0, y1);
    (j[..=n_max].to_vec(), y)
}

/// H'_n(x) = J'_n(x) + i Y'_n(x) for n = 0..=n_max, H_n the Hankel function of the first
/// kind (A&S 9.1.3), with J'_0 = -J_1, J'_n = (J_{n-1} - J_{n+1}) / 2 (A&S 9.1.27) and the
/// same for Y.
///
/// # Panics
/// As [`bessel_j_y`].
pub fn hankel_derivatives(n_max: usize, x: f64) -> Vec<Complex64> {
    let (j, y) = bessel_j_y(n_max + 1, x);
    derivatives(&j)
        .into_iter()
        .zip(derivatives(&y))
        .map(|(dj, dy)| Complex64::new(dj, dy))
        .collect()
}

/// Derivatives of orders 0..len-1 from values of orders 0..len (A&S 9.1.27, C_n = J or Y).
fn derivatives(c: &[f64]) -> Vec<f64> {
    (0..c.len() - 1)
        .map(|n| {
            if n == 0 {
                -c[1]
            } else {
                0.5 * (c[n - 1] - c[n + 1])
            }
        })
        .collect()
}

/// J_0..=J_start by Miller's backward recurrence, normalised by A&S 9.1.46, where the
/// starting order lies well above max(n_max, x): the orders above n_max are kept for the
/// Neumann series (they are negligible, not accurate, near the start).
fn bessel_j_all(n_max: usize, x: f64) -> Vec<f64> {
    let start = miller_start(n_max, x);
    let mut j = vec![0.0; start + 1];
    j[start] = 0.0;
    j[start - 1] = 1.0;
    for n in (1..start).rev() {
        j[n - 1] = 2.0 * n as f64 / x * j[n] - j[n + 1];
        if j[n - 1].abs() > RESCALE_ABOVE {
            j[n - 1..].iter_mut().for_each(|v| *v /= RESCALE_ABOVE);
        }
    }
    let even_sum: f64 = j.iter().step_by(2).skip(1).sum();
    let norm = j[0] + 2.0 * even_sum;
    j.iter_mut().for_each(|v| *v /= norm);
    j
}

/// Rescales Miller's J's to match the asymptotic J_0 or J_1, whichever is larger in
/// magnitude (so never near a zero): at large x the sum rule of A&S 9.1.46 adds up
/// hundreds of terms of size sqrt(2/(pi x)) and its round-off, ~1e-14 relative at x = 200,
/// exceeds that of the asymptotic expansion.
fn renormalise(j: &mut [f64], j0: f64, j1: f64) {
    let scale = if j0.abs() >= j1.abs() {
        j0 / j[0]
    } else {
        j1 / j[1]
    };
    j.iter_mut().for_each(|v| *v *= scale);
}

/// Even starting order of Miller's recurrence, well above max(n_max, x).
fn miller_start(n_max: usize, x: f64) -> usize {
    let m = (n_max as f64).max(x.ceil());
    let start = (m + (MILLER_HEADROOM * m).sqrt()).ceil() as usize + MILLER_MARGIN;
    start + start % 2
}

/// Y_0 and Y_1 from the Neumann series (A&S 9.1.88, 9.1.89):
/// Y_0 = (2/pi)(ln(x/2) + gamma) J_0 - (4/pi) sum_{k>=1} (-1)^k J_2k / k,
/// Y_1 = (2/pi)(ln(x/2) + gamma - 1) J_1 - 2 J_0/(pi x)
///       - (2/pi) sum_{k>=1} (-1)^k (2k+1)/(k(k+1)) J_{2k+1}.
/// `j` must hold enough orders for the neglected J's to be below round-off.
fn neumann_y0_y1(j: &[f64], x: f64) -> (f64, f64) {
    let log_term = (0.5 * x).ln() + EULER_GAMMA;
    let mut sum0 = 0.0;
    let mut sum1 = 0.0;
    let mut sign = -1.0;
    for k in 1.. {
        if 2 * k + 1 >= j.len() {
            break;
        }
        let kf = k as f64;
        sum0 += sign * j[2 * k] / kf;
        sum1 += sign * (2.0 * kf + 1.0) / (kf * (kf + 1.0)) * j[2 * k + 1];
        sign = -sign;
    }
    let y0 = 2.0 / PI * log_term * j[0] - 4.0 / PI * sum0;
    let y1 = 2.0 / PI * (log_term - 1.0) * j[1] - 2.0 / (PI * x) * j[0] - 2.0 / PI * sum1;
    (y0, y1)
}

/// Hankel's asymptotic expansion (A&S 9.2.5-9.2.10) of (J_nu, Y_nu) for nu = 0 or 1:
/// J = sqrt(2/(pi x)) (P cos chi - Q sin chi), Y = sqrt(2/(pi x)) (P sin chi + Q cos chi),
/// chi = x - (nu/2 + 1/4) pi, summed until the terms are negligible or start to grow.
fn hankel_asymptotic(nu: u32, x: f64) -> (f64, f64) {
    let (p, q) = hankel_p_q(nu, x);
    let (s, c) = x.sin_cos();
    // cos and sin of chi = x - pi/4 (nu = 0) or x - 3 pi/4 (nu = 1), without reducing chi.
    let (cos_chi, sin_chi) = if nu == 0 {
        ((c + s) * FRAC_1_SQRT_2, (s - c) * FRAC_1_SQRT_2)
    } else {
        ((s - c) * FRAC_1_SQRT_2, -(s + c) * FRAC_1_SQRT_2)
    };
    let amplitude = (2.0 / (PI * x)).sqrt();
    (
        amplitude * (p * cos_chi - q * sin_chi),
        amplitude * (p * sin_chi + q * cos_chi),
    )
}

/// P(nu, x) and Q(nu, x) of A&S 9.2.9-9.2.10 with mu = 4 nu^2:
/// term_k = term_{k-1} * (mu - (2k-1)^2) / (k 8x), alternately feeding Q and P with the
/// signs (-1)^{floor(k/2)}.
fn hankel_p_q(nu: u32, x: f64) -> (f64, f64) {
    let mu = 4.0 * f64::from(nu * nu);
    let mut p = 1.0;
    let mut q = 0.0;
    let mut term: f64 = 1.0;
    for k in 1.. {
        let odd = (2 * k - 1) as f64;
        let next = term * (mu - odd * odd) / (k as f64 * 8.0 * x);
        if next.abs() >= term.abs() {
            break;
        }
        term = next;
        let signed = if (k / 2) % 2 == 0 { term } else { -term };
        if k % 2 == 1 {
            q += signed;
        } else {
            p += signed;
        }
        if term.abs() < SERIES_TOLERANCE * p.abs().max(q.abs()) {
            break;
        }
    }
    (p, q)
}

/// Y_0..=Y_{n_max} from Y_0, Y_1 by Y_{n+1} = (2n/x) Y_n - Y_{n-1} (A&S 9.1.27).
fn forward_recurrence_y(n_max: usize, x: f64, y0: f64, y1: f64) -> Vec<f64> {
    let mut y = Vec::with_capacity(n_max + 1);
    y.push(y0);
    if n_max >= 1 {
        y.push(y1);
    }
    for n in 1..n_max {
        y.push(2.0 * n as f64 / x * y[n] - y[n - 1]);
    }
    y
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Relative error, or absolute error below a unit-sized reference.
    fn rel_err(value: f64, reference: f64) -> f64 {
        (value - reference).abs() / reference.abs().max(f64::MIN_POSITIVE)
    }

    /// Abramowitz & Stegun, tables 9.1 and 9.2 (the values given there to 15 digits were
    /// cross-checked with mpmath at 30 digits, which supplied the last digits).
    #[test]
    fn published_values_abramowitz_stegun() {
        // (n, x, J_n(x), Y_n(x))
        let table = [
            (0, 1.0, 0.765_197_686_557_966_6, 0.088_256_964_215_676_96),
            (1, 1.0, 0.440_050_585_744_933_5, -0.781_212_821_300_288_7),
            (0, 10.0, -0.245_935_764_451_348_3, 0.055_671_167_283_599_39),
            (1, 10.0, 0.043_472_746_168_861_44, 0.249_015_424_206_953_9),
            (5, 10.0, -0.234_061_528_186_793_6, 0.135_403_047_689_362_3),
        ];
        for (n, x, j_ref, y_ref) in table {
            let (j, y) = bessel_j_y(n, x);
            assert!(
                rel_err(j[n], j_ref) < 1e-14,
                "J_{n}({x}) = {} vs {j_ref}",
                j[n]
            );
            assert!(
                rel_err(y[n], y_ref) < 1e-14,
                "Y_{n}({x}) = {} vs {y_ref}",
                y[n]
            );
        }
    }

    /// Values from an independent arbitrary-precision evaluation (mpmath 1.4, 30 digits,
    /// `besselj`, `bessely`), covering both Y_0/Y_1 routes and the recurrences.
    #[test]
    fn arbitrary_precision_values() {
        let table = [
            (0, 0.1, 0.997_501_562_066_04, -1.534_238_651_350_366_8),
            (
                4,
                1e-3,
                2.604_166_536_458_336_3e-15,
                -30_557_751_620_123.151,
            ),
            (3, 2.5, 0.216_600_391_039_113_52, -0.756_055_496_753_671),
            (10, 5.0, 0.001_467_802_647_310_474_1, -25.129_110_095_610_1),
            (2, 25.0, -0.106_294_803_242_381_31, 0.119_343_035_085_347_15),
            (
                30,
                50.0,
                0.048_434_257_245_509_42,
                -0.116_457_234_935_441_45,
            ),
            (7, 100.0, 0.070_172_690_987_212_72, 0.038_178_048_317_133_43),
            (
                1,
                200.0,
                -0.054_304_538_182_378_22,
                0.015_301_824_580_389_989,
            ),
        ];
        for (n, x, j_ref, y_ref) in table {
            let (j, y) = bessel_j_y(n, x);
            assert!(
                rel_err(j[n], j_ref) < 1e-13,
                "J_{n}({x}) = {} vs {j_ref}",
                j[n]
            );
            assert!(
                rel_err(y[n], y_ref) < 1e-13,
                "Y_{n}({x}) = {} vs {y_ref}",
                y[n]
            );
        }
    }

    /// Sample arguments spanning (0.1, 100] across the Neumann/Hankel switch.
    fn arguments() -> Vec<f64> {
        (0..=60)
            .map(|i| 0.1 * 1000.0_f64.powf(i as f64 / 60.0))
            .collect()
    }

    /// A&S 9.1.15: J_{n+1} Y_n - J_n Y_{n+1} = 2/(pi x).
    #[test]
    fn wronskian_holds_for_many_orders_and_arguments() {
        for x in arguments() {
            let (j, y) = bessel_j_y(40, x);
            let expected = 2.0 / (PI * x);
            for n in 0..40 {
                let w = j[n + 1] * y[n] - j[n] * y[n + 1];
                assert!(
                    rel_err(w, expected) < 1e-13,
                    "n = {n}, x = {x}: {w} vs {expected}"
                );
            }
        }
    }

    /// A&S 9.1.16 with the derivatives: J_n Y'_n - J'_n Y_n = 2/(pi x), and the
    /// derivative cross product J'_n Y'_{n+1} - J'_{n+1} Y'_n = -(2/(pi x))(1 - n(n+1)/x^2)
    /// (from A&S 9.1.27 and 9.1.15), which links the near- and far-field drift formulas.
    #[test]
    fn derivative_wronskians() {
        for x in arguments() {
            let (j, y) = bessel_j_y(30, x);
            let dh = hankel_derivatives(30, x);
            let scale = 2.0 / (PI * x);
            for n in 0..30 {
                let w = j[n] * dh[n].im - dh[n].re * y[n];
                assert!(rel_err(w, scale) < 1e-13, "n = {n}, x = {x}: {w}");
                let nf = n as f64;
                let cross = dh[n].re * dh[n + 1].im - dh[n + 1].re * dh[n].im;
                let expected = -scale * (1.0 - nf * (nf + 1.0) / (x * x));
                let tolerance = 1e-12 * scale * (1.0 + nf * (nf + 1.0) / (x * x));
                assert!(
                    (cross - expected).abs() < tolerance,
                    "n = {n}, x = {x}: {cross} vs {expected}"
                );
            }
        }
    }

    /// Sum rules independent of Miller's normalisation: sum_{n in Z} J_n^2 = 1 (A&S 9.1.76)
    /// and the Jacobi-Anger series cos x = J_0 + 2 sum (-1)^k J_2k,
    /// sin x = 2 sum (-1)^k J_{2k+1} (A&S 9.1.44, 9.1.45).
    #[test]
    fn sum_rules_and_jacobi_anger() {
        for x in arguments() {
            let n_max = (x as usize) + 60;
            let (j, _) = bessel_j_y(n_max, x);
            let squares: f64 = j[0] * j[0] + 2.0 * j[1..].iter().map(|v| v * v).sum::<f64>();
            assert!(
                (squares - 1.0).abs() < 1e-14,
                "x = {x}: sum J^2 = {squares}"
            );
            let alternating = |start: usize| -> f64 {
                j.iter()
                    .skip(start)
                    .step_by(2)
                    .enumerate()
                    .map(|(k, v)| if k % 2 == 0 { *v } else { -*v })
                    .sum()
            };
            let cos = 2.0 * alternating(0) - j[0];
            let sin = 2.0 * alternating(1);
            assert!(
                (cos - x.cos()).abs() < 1e-14,
                "x = {x}: {cos} vs {}",
                x.cos()
            );
            assert!(
                (sin - x.sin()).abs() < 1e-14,
                "x = {x}: {sin} vs {}",
                x.sin()
            );
        }
    }

    /// The three-term recurrence C_{n-1} + C_{n+1} = (2n/x) C_n (A&S 9.1.27) for J and Y,
    /// and the derivative form C'_n = C_{n-1} - (n/x) C_n.
    #[test]
    fn recurrence_relations() {
        for x in arguments() {
            let (j, y) = bessel_j_y(20, x);
            let dh = hankel_derivatives(19, x);
            for n in 1..20 {
                let nf = n as f64;
                for (c, dc) in [(&j, dh[n].re), (&y, dh[n].im)] {
                    let lhs = c[n - 1] + c[n + 1];
                    let rhs = 2.0 * nf / x * c[n];
                    let scale = c[n - 1].abs() + c[n + 1].abs();
                    assert!((lhs - rhs).abs() <= 1e-14 * scale, "n = {n}, x = {x}");
                    let other = c[n - 1] - nf / x * c[n];
                    assert!((dc - other).abs() <= 1e-14 * (c[n - 1].abs() + nf / x * c[n].abs()));
                }
            }
        }
    }

    /// The Neumann series and Hankel's expansion are independent routes to Y_0, Y_1 (and J_0,
    /// J_1 against Miller's J's); they must agree where both are accurate.
    #[test]
    fn neumann_and_hankel_routes_agree() {
        for x in [18.0, 20.0, 22.5, 25.0, 27.5, 30.0] {
            let miller = bessel_j_all(1, x);
            let (y0, y1) = neumann_y0_y1(&miller, x);
            let (j0, h0) = hankel_asymptotic(0, x);
            let (j1, h1) = hankel_asymptotic(1, x);
            let amplitude = (2.0 / (PI * x)).sqrt();
            for (a, b) in [(y0, h0), (y1, h1), (miller[0], j0), (miller[1], j1)] {
                assert!((a - b).abs() < 1e-14 * amplitude, "x = {x}: {a} vs {b}");
            }
        }
    }

    /// Leading large-x behaviour (A&S 9.2.1, 9.2.2): C_n ~ sqrt(2/(pi x)) trig(x - n pi/2 -
    /// pi/4) with a first correction (4n^2 - 1)/(8x) in quadrature, so the remainder is
    /// O(x^-2) relative to the amplitude.
    #[test]
    fn large_argument_asymptotics() {
        for x in [120.0, 150.0, 175.5, 200.0] {
            let (j, y) = bessel_j_y(4, x);
            let amplitude = (2.0 / (PI * x)).sqrt();
            for n in 0..=4 {
                let mu = 4.0 * (n * n) as f64;
                let chi = x - (0.5 * n as f64 + 0.25) * PI;
                let q = (mu - 1.0) / (8.0 * x);
                let j_asym = amplitude * (chi.cos() - q * chi.sin());
                let y_asym = amplitude * (chi.sin() + q * chi.cos());
                let bound = amplitude * (mu + 1.0) * (mu + 9.0) / (128.0 * x * x);
                assert!((j[n] - j_asym).abs() < bound, "J_{n}({x})");
                assert!((y[n] - y_asym).abs() < bound, "Y_{n}({x})");
            }
        }
    }

    /// Small-x limits (A&S 9.1.7, 9.1.8, 9.1.9): J_n ~ (x/2)^n / n!,
    /// Y_0 ~ (2/pi)(ln(x/2) + gamma), Y_n ~ -(n-1)!/pi (2/x)^n.
    #[test]
    fn small_argument_limits() {
        let x = 1e-6;
        let (j, y) = bessel_j_y(3, x);
        let factorial = [1.0, 1.0, 2.0, 6.0];
        for n in 0..=3 {
            let j_lim = (0.5 * x).powi(n as i32) / factorial[n];
            assert!(rel_err(j[n], j_lim) < 1e-12, "J_{n}");
        }
        let y0_lim = 2.0 / PI * ((0.5 * x).ln() + EULER_GAMMA);
        assert!(rel_err(y[0], y0_lim) < 1e-12);
        for n in 1..=3 {
            let y_lim = -factorial[n - 1] / PI * (2.0 / x).powi(n as i32);
            assert!(rel_err(y[n], y_lim) < 1e-10, "Y_{n}");
        }
    }

    #[test]
    fn lengths_follow_n_max() {
        let (j, y) = bessel_j_y(0, 3.0);
        assert_eq!((j.len(), y.len()), (1, 1));
        assert_eq!(hankel_derivatives(5, 3.0).len(), 6);
    }

    #[test]
    #[should_panic(expected = "finite x > 0")]
    fn non_positive_argument_panics() {
        bessel_j_y(2, 0.0);
    }
}
