//! One-sided gust spectra of the wind speed: the density of the longitudinal turbulence u(t)
//! about the mean speed (docs/theory.md#wind).
//!
//! Units: S(f) in m^2/s^2 per Hz, f in Hz, one-sided (the variance sigma^2 = integral of S
//! from 0 to infinity); [`GustSpectrum::density_per_rad`] gives S(omega) = S(f) / (2 pi) in
//! m^2/s^2 per rad/s at omega = 2 pi f, the unit of the wave spectra of this code, with the
//! same integral over omega.

use super::profile::{npd_mean, NPD_REFERENCE_HEIGHT, NPD_REFERENCE_PERIOD};
use crate::error::{require_finite, require_non_negative, require_positive, Error, Result};
use crate::model::WindSpectrumKind;
use serde::Serialize;
use std::f64::consts::PI;

/// Harris's length scale, m (Harris 1971).
pub const HARRIS_LENGTH: f64 = 1800.0;

/// Davenport's length scale, m (Davenport 1961).
pub const DAVENPORT_LENGTH: f64 = 1200.0;

/// The API spectrum's peak constant a in f_p = a u(z) / z (API RP 2A-WSD sec. 2.3.2: 0.025,
/// within 0.01 to 0.1).
pub const API_PEAK_CONSTANT: f64 = 0.025;

/// The exponent n of the NPD spectrum (ISO 19901-1, DNV-RP-C205 sec. 2.3.4).
pub const NPD_EXPONENT: f64 = 0.468;

/// The largest surface drag coefficient accepted: Davenport's heavily built-up city centre,
/// 0.05; over the sea it is 0.001 to 0.003.
const MAX_DRAG_COEFFICIENT: f64 = 0.05;

/// Steps of the band integral per unit of ln f (0.2 % of f per step).
const STEPS_PER_LN_F: f64 = 500.0;

/// The lowest frequency of the band integral's logarithmic grid, Hz. Below it the
/// trapezoidal rule takes over: every form is finite at f = 0 and holds less than 1e-9 Hz
/// times S(0) there (S(0) = 1280 m^2/s^2 per Hz for NPD at 20 m/s: 1.3e-6 m^2/s^2), within
/// 0.2 % of flat.
const LOG_FLOOR: f64 = 1e-9;

/// A one-sided gust spectrum of the longitudinal wind speed. Each variant holds the mean
/// speed it is defined for (`wind.speed`, m/s: which mean, over which period and at which
/// height, is said per variant) and the height z of the wind force where the spectrum is
/// taken (`wind.height`, m) where the form depends on it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum GustSpectrum {
    /// NPD / Frøya (ISO 19901-1; DNV-RP-C205 sec. 2.3.4), from U0 the 1-hour mean at 10 m:
    ///
    /// S(f) = 320 (U0/10)^2 (z/10)^0.45 / (1 + f~^n)^(5/(3n)),
    /// f~ = 172 f (z/10)^(2/3) (U0/10)^-0.75, n = 0.468.
    ///
    /// Its mean at z is the NPD profile's 1-hour mean U(z) = U0 [1 + C ln(z/10)].
    Npd { speed: f64, height: f64 },
    /// API RP 2A-WSD sec. 2.3.2, from u(z) the 1-hour mean at the height z:
    ///
    /// S(f) = sigma^2 / f_p / (1 + 1.5 f / f_p)^(5/3), f_p = 0.025 u(z) / z,
    /// sigma = I u(z), I the turbulence intensity (`wind.turbulence_intensity`; API's
    /// default in [`api_turbulence_intensity`]).
    ///
    /// Its integral is sigma^2 and f S(f) peaks at f_p.
    Api {
        speed: f64,
        height: f64,
        turbulence_intensity: f64,
    },
    /// Harris (1971; DNV-RP-C205 sec. 2.3.4), from U10 the 10-min mean at 10 m (DNV's U10;
    /// the height z does not enter):
    ///
    /// S(f) = 4 kappa U10 L / (2 + x^2)^(5/6), x = f L / U10, L = 1800 m,
    /// kappa the surface drag coefficient (`wind.drag_coefficient`).
    ///
    /// Its integral is 4 kappa U10^2 2^(-4/3) B(1/2, 1/3) = 6.6776 kappa U10^2.
    Harris { speed: f64, drag_coefficient: f64 },
    /// Davenport (1961), from U10 the mean at 10 m (DNV's U10, the 10-min mean; the height z
    /// does not enter):
    ///
    /// S(f) = 4 kappa U10^2 x^2 / (f (1 + x^2)^(4/3)), x = f L / U10, L = 1200 m,
    /// kappa the surface drag coefficient (`wind.drag_coefficient`).
    ///
    /// Its integral is 6 kappa U10^2.
    Davenport { speed: f64, drag_coefficient: f64 },
    /// Kaimal (Kaimal et al. 1972) in the form of IEC 61400-1 (ed. 3 annex B), from U the
    /// 10-min mean at the height z:
    ///
    /// S(f) = sigma^2 (4 L / U) / (1 + 6 f L / U)^(5/3), sigma = I U,
    /// I the turbulence intensity (`wind.turbulence_intensity`), L the integral length scale
    /// (`wind.length_scale`; IEC's L = 8.1 Lambda, [`iec_length_scale`]).
    ///
    /// Its integral is sigma^2. DNV-RP-C205 sec. 2.3.4 writes the same shape as
    /// 6.868 L_u / U / (1 + 10.32 f L_u / U)^(5/3) with its own L_u (L = 1.717 L_u).
    Kaimal {
        speed: f64,
        turbulence_intensity: f64,
        length_scale: f64,
    },
    /// Ochi and Shin (1988, "Wind turbulent spectra for design consideration of offshore
    /// structures", OTC 5736), from U10 the mean at 10 m, taken as the 1-hour mean:
    ///
    /// S(f) = u*^2 / f S*(f*), f* = f z / U(z), u*^2 = kappa U10^2,
    /// S* = 583 f* for f* <= 0.003, 420 f*^0.70 / (1 + f*^0.35)^11.5 up to f* = 0.1,
    /// 838 f* / (1 + f*^0.35)^11.5 above; U(z) = U10 + 2.5 u* ln(z/10), the log law of the
    /// same u* (von Kármán's 0.4).
    OchiShin {
        speed: f64,
        height: f64,
        drag_coefficient: f64,
    },
    /// No gust: the mean speed alone, S = 0.
    Constant { speed: f64 },
}

/// API RP 2A-WSD sec. 2.3.2's turbulence intensity at the height z (m): I(z) = 0.15
/// (z/z_s)^-0.125 for z <= z_s, 0.15 (z/z_s)^-0.275 above, z_s = 20 m (the thickness of the
/// surface layer).
pub fn api_turbulence_intensity(z: f64) -> f64 {
    const SURFACE_LAYER: f64 = 20.0;
    let exponent = if z <= SURFACE_LAYER { -0.125 } else { -0.275 };
    0.15 * (z / SURFACE_LAYER).powf(exponent)
}

/// IEC 61400-1 (ed. 3 sec. 6.3.1 and annex B)'s longitudinal integral length scale at the
/// height z (m): L = 8.1 Lambda, Lambda = 0.7 z up to 60 m and 42 m above, m.
pub fn iec_length_scale(z: f64) -> f64 {
    8.1 * 0.7 * z.min(60.0)
}

impl GustSpectrum {
    /// Which of the spectra it is (`[wind] spectrum`).
    pub fn kind(&self) -> WindSpectrumKind {
        match self {
            GustSpectrum::Npd { .. } => WindSpectrumKind::Npd,
            GustSpectrum::Api { .. } => WindSpectrumKind::Api,
            GustSpectrum::Harris { .. } => WindSpectrumKind::Harris,
            GustSpectrum::Davenport { .. } => WindSpectrumKind::Davenport,
            GustSpectrum::Kaimal { .. } => WindSpectrumKind::Kaimal,
            GustSpectrum::OchiShin { .. } => WindSpectrumKind::OchiShin,
            GustSpectrum::Constant { .. } => WindSpectrumKind::Constant,
        }
    }

    /// Checks ranges and finiteness; the error names the setting of the `[wind]` section.
    pub fn validate(&self) -> Result<()> {
        match *self {
            GustSpectrum::Npd { speed, height } => {
                require_positive("wind.speed", speed)?;
                require_positive("wind.height", height)?;
                self.require_positive_mean()
            }
            GustSpectrum::Api {
                speed,
                height,
                turbulence_intensity,
            } => {
                require_positive("wind.speed", speed)?;
                require_positive("wind.height", height)?;
                require_intensity(turbulence_intensity)
            }
            GustSpectrum::Harris {
                speed,
                drag_coefficient,
            }
            | GustSpectrum::Davenport {
                speed,
                drag_coefficient,
            } => {
                require_positive("wind.speed", speed)?;
                require_drag_coefficient(drag_coefficient)
            }
            GustSpectrum::Kaimal {
                speed,
                turbulence_intensity,
                length_scale,
            } => {
                require_positive("wind.speed", speed)?;
                require_intensity(turbulence_intensity)?;
                require_positive("wind.length_scale", length_scale)
            }
            GustSpectrum::OchiShin {
                speed,
                height,
                drag_coefficient,
            } => {
                require_positive("wind.speed", speed)?;
                require_positive("wind.height", height)?;
                require_drag_coefficient(drag_coefficient)?;
                self.require_positive_mean()
            }
            GustSpectrum::Constant { speed } => require_non_negative("wind.speed", speed),
        }
    }

    /// The NPD and Ochi-Shin means at z come from a profile that falls to zero near the
    /// surface: a height below that is refused.
    fn require_positive_mean(&self) -> Result<()> {
        let mean = self.mean_speed();
        if mean.is_finite() && mean > 0.0 {
            Ok(())
        } else {
            let height = match *self {
                GustSpectrum::Npd { height, .. } | GustSpectrum::OchiShin { height, .. } => height,
                _ => f64::NAN,
            };
            Err(Error::invalid(
                "wind.height",
                height,
                format!(
                    "is too close to the surface: the mean speed of the spectrum's profile \
                     there is {mean} m/s"
                ),
            ))
        }
    }

    /// The mean speed at the spectrum's height, m/s, the mean of its turbulence intensity:
    /// NPD the NPD profile's 1-hour mean U(z); API u(z); Harris and Davenport U10; Kaimal U;
    /// Ochi-Shin U(z) of its log law; constant its speed.
    pub fn mean_speed(&self) -> f64 {
        match *self {
            GustSpectrum::Npd { speed, height } => npd_mean(speed, height, NPD_REFERENCE_PERIOD),
            GustSpectrum::OchiShin {
                speed,
                height,
                drag_coefficient,
            } => ochi_shin_mean(speed, height, drag_coefficient),
            GustSpectrum::Api { speed, .. }
            | GustSpectrum::Harris { speed, .. }
            | GustSpectrum::Davenport { speed, .. }
            | GustSpectrum::Kaimal { speed, .. }
            | GustSpectrum::Constant { speed } => speed,
        }
    }

    /// The one-sided density S(f) at the frequency `f` (Hz), m^2/s^2 per Hz; 0 for f < 0.
    /// Each form is finite at f = 0 and is written without dividing by f.
    pub fn density(&self, f: f64) -> f64 {
        if f < 0.0 {
            return 0.0;
        }
        match *self {
            GustSpectrum::Npd { speed, height } => {
                let (u, z) = (speed / NPD_REFERENCE_HEIGHT, height / NPD_REFERENCE_HEIGHT);
                let f_tilde = 172.0 * f * z.powf(2.0 / 3.0) * u.powf(-0.75);
                let n = NPD_EXPONENT;
                320.0 * u * u * z.powf(0.45) / (1.0 + f_tilde.powf(n)).powf(5.0 / (3.0 * n))
            }
            GustSpectrum::Api {
                speed,
                height,
                turbulence_intensity,
            } => {
                let f_p = API_PEAK_CONSTANT * speed / height;
                let sigma = turbulence_intensity * speed;
                sigma * sigma / f_p / (1.0 + 1.5 * f / f_p).powf(5.0 / 3.0)
            }
            GustSpectrum::Harris {
                speed,
                drag_coefficient,
            } => {
                let x = f * HARRIS_LENGTH / speed;
                4.0 * drag_coefficient * speed * HARRIS_LENGTH / (2.0 + x * x).powf(5.0 / 6.0)
            }
            GustSpectrum::Davenport {
                speed,
                drag_coefficient,
            } => {
                // 4 kappa U^2 x^2 / (f (1 + x^2)^(4/3)) with x^2 / f = x L / U.
                let x = f * DAVENPORT_LENGTH / speed;
                4.0 * drag_coefficient * speed * DAVENPORT_LENGTH * x
                    / (1.0 + x * x).powf(4.0 / 3.0)
            }
            GustSpectrum::Kaimal {
                speed,
                turbulence_intensity,
                length_scale,
            } => {
                let sigma = turbulence_intensity * speed;
                let y = f * length_scale / speed;
                sigma * sigma * 4.0 * length_scale / speed / (1.0 + 6.0 * y).powf(5.0 / 3.0)
            }
            GustSpectrum::OchiShin {
                speed,
                height,
                drag_coefficient,
            } => {
                // u*^2 / f S*(f*) = u*^2 (z / U(z)) S*(f*) / f*.
                let mean = ochi_shin_mean(speed, height, drag_coefficient);
                let f_star = f * height / mean;
                let friction_squared = drag_coefficient * speed * speed;
                friction_squared * height / mean * ochi_shin_shape_over_f_star(f_star)
            }
            GustSpectrum::Constant { .. } => 0.0,
        }
    }

    /// The one-sided density per rad/s at `omega` (rad/s), m^2/s^2 per rad/s: S(omega) =
    /// S(f = omega / (2 pi)) / (2 pi), the same variance over the same band.
    pub fn density_per_rad(&self, omega: f64) -> f64 {
        self.density(omega / (2.0 * PI)) / (2.0 * PI)
    }

    /// [`GustSpectrum::density_per_rad`] at every frequency of `omegas`, the constants of
    /// the spectrum taken once (NPD's four powers of the speed and the height; the others
    /// have none worth hoisting): the same values within rounding.
    pub fn densities_per_rad(&self, omegas: impl Iterator<Item = f64>) -> Vec<f64> {
        match *self {
            GustSpectrum::Npd { speed, height } => {
                let (u, z) = (speed / NPD_REFERENCE_HEIGHT, height / NPD_REFERENCE_HEIGHT);
                let per_omega = 172.0 * z.powf(2.0 / 3.0) * u.powf(-0.75) / (2.0 * PI);
                let level = 320.0 * u * u * z.powf(0.45) / (2.0 * PI);
                let n = NPD_EXPONENT;
                omegas
                    .map(|omega| {
                        if omega < 0.0 {
                            return 0.0;
                        }
                        level / (1.0 + (per_omega * omega).powf(n)).powf(5.0 / (3.0 * n))
                    })
                    .collect()
            }
            _ => omegas.map(|omega| self.density_per_rad(omega)).collect(),
        }
    }

    /// The variance of the gust within the band [f_low, f_high] (Hz), m^2/s^2: the integral
    /// of S(f) by Simpson's rule in ln f (500 steps per unit of ln f, from 1e-9 Hz up) and
    /// the trapezoidal rule below, where every form is flat.
    pub fn variance(&self, f_low: f64, f_high: f64) -> Result<f64> {
        require_non_negative("wind band's lower frequency", f_low)?;
        require_finite("wind band's upper frequency", f_high)?;
        if f_high <= f_low {
            return Err(Error::invalid(
                "wind band's upper frequency",
                f_high,
                format!("must be above the lower frequency, {f_low} Hz"),
            ));
        }
        let floor = LOG_FLOOR.clamp(f_low, f_high);
        let below = 0.5 * (self.density(f_low) + self.density(floor)) * (floor - f_low);
        if floor == f_high {
            return Ok(below);
        }
        let (a, b) = (floor.ln(), f_high.ln());
        let steps = (((b - a) * STEPS_PER_LN_F).ceil() as usize).max(2);
        let steps = steps + steps % 2;
        let h = (b - a) / steps as f64;
        let g = |i: usize| {
            let f = (a + i as f64 * h).exp();
            f * self.density(f)
        };
        let inner: f64 = (1..steps)
            .map(|i| if i % 2 == 1 { 4.0 * g(i) } else { 2.0 * g(i) })
            .sum();
        Ok(below + h / 3.0 * (g(0) + inner + g(steps)))
    }

    /// The turbulence intensity the band implies, sigma / mean: sigma the square root of
    /// [`GustSpectrum::variance`] over the band, the mean [`GustSpectrum::mean_speed`]
    /// (0 for the constant wind).
    pub fn turbulence_intensity(&self, f_low: f64, f_high: f64) -> Result<f64> {
        let variance = self.variance(f_low, f_high)?;
        let mean = self.mean_speed();
        Ok(if mean > 0.0 {
            variance.sqrt() / mean
        } else {
            0.0
        })
    }
}

/// Ochi and Shin's mean at z: U(z) = U10 + 2.5 u* ln(z/10), u* = sqrt(kappa) U10.
fn ochi_shin_mean(speed: f64, height: f64, drag_coefficient: f64) -> f64 {
    speed * (1.0 + 2.5 * drag_coefficient.sqrt() * (height / NPD_REFERENCE_HEIGHT).ln())
}

/// Ochi and Shin's S*(f*) / f*, the three pieces of their spectrum (continuous at f* =
/// 0.003 and 0.1).
fn ochi_shin_shape_over_f_star(f_star: f64) -> f64 {
    if f_star <= 0.003 {
        583.0
    } else if f_star <= 0.1 {
        420.0 * f_star.powf(-0.3) / (1.0 + f_star.powf(0.35)).powf(11.5)
    } else {
        838.0 / (1.0 + f_star.powf(0.35)).powf(11.5)
    }
}

pub(super) fn require_drag_coefficient(kappa: f64) -> Result<()> {
    require_positive("wind.drag_coefficient", kappa)?;
    if kappa > MAX_DRAG_COEFFICIENT {
        return Err(Error::invalid(
            "wind.drag_coefficient",
            kappa,
            format!(
                "must be at most {MAX_DRAG_COEFFICIENT} (a city centre's; over the sea it is \
                 0.001 to 0.003)"
            ),
        ));
    }
    Ok(())
}

pub(super) fn require_intensity(intensity: f64) -> Result<()> {
    require_positive("wind.turbulence_intensity", intensity)?;
    if intensity > 1.0 {
        return Err(Error::invalid(
            "wind.turbulence_intensity",
            intensity,
            "must be at most 1 (sigma / mean; offshore it is about 0.05 to 0.2)",
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Mode;

    fn close(a: f64, b: f64, rel: f64) -> bool {
        (a - b).abs() <= rel * b.abs()
    }

    /// Gamma(x) for x >= 1/2 by Lanczos's approximation (g = 7, nine coefficients; relative
    /// error about 1e-15), for the closed-form integrals below.
    fn gamma(x: f64) -> f64 {
        const G: f64 = 7.0;
        const C: [f64; 9] = [
            0.999_999_999_999_809_9,
            676.520_368_121_885_1,
            -1_259.139_216_722_402_8,
            771.323_428_777_653_1,
            -176.615_029_162_140_6,
            12.507_343_278_686_905,
            -0.138_571_095_265_720_12,
            9.984_369_578_019_572e-6,
            1.505_632_735_149_311_6e-7,
        ];
        assert!(x >= 0.5);
        let x = x - 1.0;
        let t = x + G + 0.5;
        let sum: f64 = C[0]
            + C[1..]
                .iter()
                .enumerate()
                .map(|(i, c)| c / (x + i as f64 + 1.0))
                .sum::<f64>();
        (2.0 * PI).sqrt() * t.powf(x + 0.5) * (-t).exp() * sum
    }

    #[test]
    fn the_test_gamma_is_gamma() {
        assert!(close(gamma(0.5), PI.sqrt(), 1e-13));
        assert!(close(gamma(5.0), 24.0, 1e-13));
        // Published values: Gamma(1/3) = 2.678938534707747, Gamma(5/6) = 1.128787029908126.
        assert!(close(gamma(4.0 / 3.0) * 3.0, 2.678_938_534_707_747, 1e-13));
        assert!(close(gamma(5.0 / 6.0), 1.128_787_029_908_126, 1e-13));
    }

    /// The frequency (Hz) where f S(f) is largest, by golden-section search in ln f.
    fn peak_of_f_s(spectrum: &GustSpectrum, lo: f64, hi: f64) -> f64 {
        let g = |u: f64| u.exp() * spectrum.density(u.exp());
        let (mut a, mut b) = (lo.ln(), hi.ln());
        let r = (5f64.sqrt() - 1.0) / 2.0;
        for _ in 0..200 {
            let (c, d) = (b - r * (b - a), a + r * (b - a));
            if g(c) > g(d) {
                b = d;
            } else {
                a = c;
            }
        }
        (0.5 * (a + b)).exp()
    }

    const NPD: GustSpectrum = GustSpectrum::Npd {
        speed: 20.0,
        height: 10.0,
    };

    /// NPD at U0 = 20 m/s: z = 10 m, f = 0.01 Hz: f~ = 172 0.01 2^-0.75 = 1.022718, S =
    /// 320 2^2 / (1 + 1.022718^0.468)^(5/1.404) = 1280 / 12.02814 = 106.4179; z = 50 m,
    /// f = 0.05 Hz: f~ = 172 0.05 5^(2/3) 2^-0.75 = 14.95223, S = 1280 5^0.45 / (1 +
    /// 14.95223^0.468)^3.561254 = 12.01422; at f = 0 the numerator, 1280 at 10 m.
    #[test]
    fn npd_by_hand() {
        assert!(
            close(NPD.density(0.01), 106.4179, 1e-6),
            "{}",
            NPD.density(0.01)
        );
        let high = GustSpectrum::Npd {
            speed: 20.0,
            height: 50.0,
        };
        assert!(
            close(high.density(0.05), 12.01422, 1e-6),
            "{}",
            high.density(0.05)
        );
        assert_eq!(NPD.density(0.0), 1280.0);
        assert_eq!(NPD.density(-1.0), 0.0);
    }

    /// f S(f) of the NPD form peaks where d/df [f / (1 + f~^n)^(5/(3n))] = 0, f~^n = 3/2:
    /// f~ = 1.5^(1/0.468) = 2.378282, f = 2.378282 / (172 2^-0.75) = 0.0232545 Hz at U0 =
    /// 20 m/s and z = 10 m.
    #[test]
    fn npd_peak_of_f_s() {
        let peak = peak_of_f_s(&NPD, 1e-4, 1.0);
        assert!(close(peak, 0.023_254_5, 1e-5), "{peak}");
    }

    /// The NPD integral: with t = f~^n, integral of (1 + f~^n)^(-5/(3n)) df~ = B(1/n,
    /// 2/(3n)) / n, so sigma^2 = 320 u^2 z^0.45 / (172 z^(2/3) u^-0.75) B(1/n, 2/(3n)) / n
    /// (u = U0/10, z in tens of m); at U0 = 20 m/s, z = 10 m: 1280 / 102.27 0.567222 =
    /// 7.09916 m^2/s^2. The band stops at 1e6 Hz: its tail, 1.5 A c^(-5/3) F^(-2/3), is
    /// subtracted.
    #[test]
    fn npd_integral_is_its_beta_function() {
        for (speed, height) in [(20.0, 10.0), (35.0, 60.0)] {
            let spectrum = GustSpectrum::Npd { speed, height };
            let (u, z, n) = (speed / 10.0, height / 10.0, 0.468);
            let a = 320.0 * u * u * z.powf(0.45);
            let c = 172.0 * z.powf(2.0 / 3.0) * u.powf(-0.75);
            let beta = gamma(1.0 / n) * gamma(2.0 / (3.0 * n)) / gamma(5.0 / (3.0 * n));
            let total = a / c * beta / n;
            let top: f64 = 1e6;
            let tail = 1.5 * a * c.powf(-5.0 / 3.0) * top.powf(-2.0 / 3.0);
            let variance = spectrum.variance(0.0, top).unwrap();
            assert!(
                close(variance, total - tail, 1e-7),
                "{variance} {total} {tail}"
            );
            if height == 10.0 {
                assert!(close(total, 7.09916, 1e-5), "{total}");
                // The intensity it implies, on the 1-hour mean at 10 m (U0 itself).
                let intensity = spectrum.turbulence_intensity(0.0, top).unwrap();
                assert!(close(intensity, (total - tail).sqrt() / 20.0, 1e-7));
            }
        }
    }

    const API: GustSpectrum = GustSpectrum::Api {
        speed: 30.0,
        height: 20.0,
        turbulence_intensity: 0.15,
    };

    /// API at u(z) = 30 m/s, z = 20 m, I = 0.15: f_p = 0.025 30 / 20 = 0.0375 Hz, sigma^2 =
    /// 4.5^2 = 20.25; at 0.02 Hz S = 20.25 / 0.0375 / (1 + 0.8)^(5/3) = 540 / 2.663493 =
    /// 202.7401. f S(f) peaks at f_p; a band's variance is sigma^2 [(1 + 1.5 a/f_p)^(-2/3) -
    /// (1 + 1.5 b/f_p)^(-2/3)], the whole sigma^2.
    #[test]
    fn api_by_hand_its_peak_and_integral() {
        assert!(
            close(API.density(0.02), 202.7401, 1e-6),
            "{}",
            API.density(0.02)
        );
        assert!(close(peak_of_f_s(&API, 1e-4, 1.0), 0.0375, 1e-6));
        let band = |a: f64, b: f64| {
            20.25
                * ((1.0 + 1.5 * a / 0.0375).powf(-2.0 / 3.0)
                    - (1.0 + 1.5 * b / 0.0375).powf(-2.0 / 3.0))
        };
        for (a, b) in [(0.0, 1e6), (0.01, 0.1), (0.0, 0.005)] {
            let variance = API.variance(a, b).unwrap();
            assert!(close(variance, band(a, b), 1e-8), "{a} {b}: {variance}");
        }
        let intensity = API.turbulence_intensity(0.0, 1e9).unwrap();
        assert!(close(intensity, 0.15, 1e-5), "{intensity}");
    }

    /// API's intensity: 0.15 at z_s = 20 m, 0.15 0.5^-0.125 = 0.163576 at 10 m, 0.15
    /// 2^-0.275 = 0.123968 at 40 m.
    #[test]
    fn api_intensity_by_height() {
        assert_eq!(api_turbulence_intensity(20.0), 0.15);
        assert!(close(api_turbulence_intensity(10.0), 0.163_576, 1e-5));
        assert!(close(api_turbulence_intensity(40.0), 0.123_968, 1e-5));
    }

    /// Harris at U10 = 20 m/s, kappa = 0.002, f = 0.01 Hz: x = 0.01 1800 / 20 = 0.9, S =
    /// 4 0.002 20 1800 / 2.81^(5/6) = 288 / 2.365495 = 121.7504. f S peaks at x = sqrt(3)
    /// (d/dx [x / (2 + x^2)^(5/6)] = 0). The integral, with x = sqrt(2) t: 4 kappa U10^2
    /// 2^(-1/3) (1/2) B(1/2, 1/3) = 6.677476 kappa U10^2; the band's tail above F, 6 kappa
    /// U10 L (L/U10)^(-5/3) F^(-2/3), is subtracted.
    #[test]
    fn harris_by_hand_its_peak_and_integral() {
        let (speed, kappa) = (20.0, 0.002);
        let spectrum = GustSpectrum::Harris {
            speed,
            drag_coefficient: kappa,
        };
        assert!(close(spectrum.density(0.01), 121.7504, 1e-6));
        let peak = peak_of_f_s(&spectrum, 1e-5, 1.0);
        assert!(close(peak, 3f64.sqrt() * speed / 1800.0, 1e-6), "{peak}");
        let beta = PI.sqrt() * 2.678_938_534_707_747 / 1.128_787_029_908_126; // B(1/2, 1/3)
        let total = 4.0 * kappa * speed * speed * 2f64.powf(-1.0 / 3.0) * 0.5 * beta;
        assert!(close(total, 6.677476 * kappa * speed * speed, 1e-6));
        let top: f64 = 1e6;
        let tail =
            6.0 * kappa * speed * 1800.0 * (1800.0 / speed).powf(-5.0 / 3.0) * top.powf(-2.0 / 3.0);
        let variance = spectrum.variance(0.0, top).unwrap();
        assert!(close(variance, total - tail, 1e-7), "{variance} {total}");
    }

    /// Davenport at U10 = 20 m/s, kappa = 0.002, f = 0.01 Hz: x = 0.6, S = 4 0.002 400
    /// 0.36 / (0.01 1.36^(4/3)) = 1.152 / 0.0150679 = 76.45407. f S peaks at x = sqrt(3);
    /// a band's variance is 6 kappa U10^2 [(1 + x_a^2)^(-1/3) - (1 + x_b^2)^(-1/3)], the
    /// whole 6 kappa U10^2.
    #[test]
    fn davenport_by_hand_its_peak_and_integral() {
        let (speed, kappa) = (20.0, 0.002);
        let spectrum = GustSpectrum::Davenport {
            speed,
            drag_coefficient: kappa,
        };
        assert!(close(spectrum.density(0.01), 76.45407, 1e-6));
        let peak = peak_of_f_s(&spectrum, 1e-5, 1.0);
        assert!(close(peak, 3f64.sqrt() * speed / 1200.0, 1e-6), "{peak}");
        let band = |a: f64, b: f64| {
            let x = |f: f64| f * 1200.0 / speed;
            6.0 * kappa
                * speed
                * speed
                * ((1.0 + x(a).powi(2)).powf(-1.0 / 3.0) - (1.0 + x(b).powi(2)).powf(-1.0 / 3.0))
        };
        for (a, b) in [(0.0, 1e6), (0.005, 0.2)] {
            let variance = spectrum.variance(a, b).unwrap();
            assert!(close(variance, band(a, b), 1e-8), "{variance}");
        }
        let intensity = spectrum.turbulence_intensity(0.0, 1e12).unwrap();
        assert!(close(intensity, (6.0 * kappa).sqrt(), 1e-6), "{intensity}");
    }

    /// Kaimal at U = 12 m/s, I = 0.12, L = 340.2 m (IEC's 8.1 42 m above 60 m): sigma^2 =
    /// 1.44^2 = 2.0736; at 0.05 Hz, y = 0.05 340.2 / 12 = 1.4175, S = 2.0736 4 28.35 /
    /// 9.505^(5/3) = 235.1462 / 42.6503 = 5.513379. f S peaks at y = 1/4; a band's variance
    /// is sigma^2 [(1 + 6 y_a)^(-2/3) - (1 + 6 y_b)^(-2/3)], the whole sigma^2 (I again).
    #[test]
    fn kaimal_by_hand_its_peak_and_integral() {
        let length_scale = iec_length_scale(100.0);
        assert!(close(length_scale, 340.2, 1e-12));
        assert!(close(iec_length_scale(30.0), 8.1 * 21.0, 1e-12));
        let spectrum = GustSpectrum::Kaimal {
            speed: 12.0,
            turbulence_intensity: 0.12,
            length_scale,
        };
        assert!(close(spectrum.density(0.05), 5.513379, 1e-6));
        let peak = peak_of_f_s(&spectrum, 1e-5, 1.0);
        assert!(close(peak, 0.25 * 12.0 / 340.2, 1e-6), "{peak}");
        let band = |a: f64, b: f64| {
            let y = |f: f64| 6.0 * f * 340.2 / 12.0;
            2.0736 * ((1.0 + y(a)).powf(-2.0 / 3.0) - (1.0 + y(b)).powf(-2.0 / 3.0))
        };
        for (a, b) in [(0.0, 1e6), (0.002, 0.3)] {
            let variance = spectrum.variance(a, b).unwrap();
            assert!(close(variance, band(a, b), 1e-8), "{variance}");
        }
        let intensity = spectrum.turbulence_intensity(0.0, 1e9).unwrap();
        assert!(close(intensity, 0.12, 1e-5), "{intensity}");
    }

    const OCHI_SHIN: GustSpectrum = GustSpectrum::OchiShin {
        speed: 20.0,
        height: 30.0,
        drag_coefficient: 0.002,
    };

    /// Ochi-Shin at U10 = 20 m/s, z = 30 m, kappa = 0.002: u* = 0.894427 m/s, U(z) = 20 +
    /// 2.5 0.894427 ln 3 = 22.45657 m/s. f = 0.001 Hz: f* = 0.00133591 (first piece), S =
    /// u*^2 583 z / U(z) = 0.8 583 1.335912 = 623.0693; f = 0.01 Hz: f* = 0.0133591,
    /// S = 0.8 / 0.01 420 f*^0.7 / (1 + f*^0.35)^11.5 = 165.1671; f = 0.3 Hz: f* = 0.400774,
    /// S = 0.8 / 0.3 838 f* / (1 + f*^0.35)^11.5 = 1.681764.
    #[test]
    fn ochi_shin_by_hand() {
        assert!(close(OCHI_SHIN.mean_speed(), 22.45657, 1e-6));
        for (f, expected) in [(0.001, 623.0693), (0.01, 165.1671), (0.3, 1.681764)] {
            let s = OCHI_SHIN.density(f);
            assert!(close(s, expected, 1e-6), "{f}: {s}");
        }
    }

    /// The three pieces meet at f* = 0.003 and 0.1 (to the published constants' digits), and
    /// the first two integrate in closed form: 583 0.003 = 1.749 for the first, and with w =
    /// f*^0.35 the second is 1200 integral of w (1 + w)^-11.5 dw = 1200 [-(1 + w)^-9.5 / 9.5
    /// + (1 + w)^-10.5 / 10.5] from 0.003^0.35 to 0.1^0.35; times u*^2.
    #[test]
    fn densities_on_a_grid_are_the_density_of_each_frequency() {
        let spectra = [
            GustSpectrum::Npd {
                speed: 23.0,
                height: 37.0,
            },
            GustSpectrum::Harris {
                speed: 20.0,
                drag_coefficient: 0.002,
            },
        ];
        for spectrum in spectra {
            let omegas = (0..2000).map(|j| j as f64 * 3e-3);
            let grid = spectrum.densities_per_rad(omegas.clone());
            for (omega, s) in omegas.zip(grid) {
                let one = spectrum.density_per_rad(omega);
                assert!(
                    (s - one).abs() <= 1e-13 * one,
                    "{spectrum:?} at {omega}: {s} vs {one}"
                );
            }
        }
    }

    #[test]
    fn ochi_shin_pieces_meet_and_integrate() {
        let per_f_star = 30.0 / OCHI_SHIN.mean_speed(); // Hz per unit of f*
        let f_at = |f_star: f64| f_star / per_f_star;
        for f_star in [0.003, 0.1] {
            let (below, above) = (
                OCHI_SHIN.density(f_at(f_star) * (1.0 - 1e-12)),
                OCHI_SHIN.density(f_at(f_star) * (1.0 + 1e-12)),
            );
            assert!(close(below, above, 1e-3), "{f_star}: {below} {above}");
        }
        let antiderivative = |w: f64| -(1.0 + w).powf(-9.5) / 9.5 + (1.0 + w).powf(-10.5) / 10.5;
        let friction_squared = 0.002 * 400.0;
        let first = friction_squared * 583.0 * 0.003;
        let second = friction_squared
            * 1200.0
            * (antiderivative(0.1f64.powf(0.35)) - antiderivative(0.003f64.powf(0.35)));
        let variance = OCHI_SHIN.variance(0.0, f_at(0.003)).unwrap();
        assert!(close(variance, first, 1e-7), "{variance} {first}");
        let variance = OCHI_SHIN.variance(f_at(0.003), f_at(0.1)).unwrap();
        assert!(close(variance, second, 1e-7), "{variance} {second}");
    }

    /// Per rad/s: S(omega) = S(f) / (2 pi) at omega = 2 pi f, and the integral over the same
    /// band in omega (trapezoidal rule on a fine linear grid here) is the variance in Hz.
    #[test]
    fn per_rad_has_the_same_integral() {
        for spectrum in [NPD, API, OCHI_SHIN] {
            let f = 0.02;
            assert!(close(
                spectrum.density_per_rad(2.0 * PI * f),
                spectrum.density(f) / (2.0 * PI),
                1e-15
            ));
            let (a, b) = (0.005, 0.5);
            let n = 200_000;
            let h = 2.0 * PI * (b - a) / n as f64;
            let in_omega: f64 = (0..=n)
                .map(|i| {
                    let weight = if i == 0 || i == n { 0.5 } else { 1.0 };
                    weight * spectrum.density_per_rad(2.0 * PI * a + i as f64 * h)
                })
                .sum::<f64>()
                * h;
            let in_hz = spectrum.variance(a, b).unwrap();
            assert!(close(in_omega, in_hz, 1e-6), "{in_omega} {in_hz}");
        }
    }

    /// No gust: density, variance and intensity zero; the mean is the speed.
    #[test]
    fn constant_wind_has_no_gust() {
        let spectrum = GustSpectrum::Constant { speed: 15.0 };
        assert_eq!(spectrum.density(0.01), 0.0);
        assert_eq!(spectrum.variance(0.0, 10.0).unwrap(), 0.0);
        assert_eq!(spectrum.turbulence_intensity(0.0, 10.0).unwrap(), 0.0);
        assert_eq!(spectrum.mean_speed(), 15.0);
        assert!(spectrum.validate().is_ok());
    }

    /// Each refusal names the `[wind]` setting and its value.
    #[test]
    fn errors_name_the_setting() {
        let message = |spectrum: GustSpectrum| spectrum.validate().unwrap_err().to_string();
        assert!(message(GustSpectrum::Npd {
            speed: -20.0,
            height: 10.0
        })
        .starts_with("invalid wind.speed = -20: must be greater than zero"));
        assert!(message(GustSpectrum::Npd {
            speed: 20.0,
            height: 0.0
        })
        .starts_with("invalid wind.height = 0"));
        // U(z) = 40 (1 + 0.1507 ln(z/10)) is negative at 1 mm.
        assert!(message(GustSpectrum::Npd {
            speed: 40.0,
            height: 1e-3
        })
        .starts_with("invalid wind.height = 0.001: is too close to the surface"));
        assert!(message(GustSpectrum::Api {
            speed: 30.0,
            height: 20.0,
            turbulence_intensity: 1.5
        })
        .starts_with("invalid wind.turbulence_intensity = 1.5"));
        assert!(message(GustSpectrum::Harris {
            speed: 30.0,
            drag_coefficient: f64::NAN
        })
        .starts_with("invalid wind.drag_coefficient = NaN"));
        assert!(message(GustSpectrum::Davenport {
            speed: 30.0,
            drag_coefficient: 0.2
        })
        .starts_with("invalid wind.drag_coefficient = 0.2: must be at most 0.05"));
        assert!(message(GustSpectrum::Kaimal {
            speed: 12.0,
            turbulence_intensity: 0.1,
            length_scale: -3.0
        })
        .starts_with("invalid wind.length_scale = -3"));
        assert!(message(GustSpectrum::OchiShin {
            speed: 12.0,
            height: -1.0,
            drag_coefficient: 0.002
        })
        .starts_with("invalid wind.height = -1"));
        assert!(message(GustSpectrum::Constant { speed: -1.0 })
            .starts_with("invalid wind.speed = -1: must not be negative"));
        assert!(NPD.validate().is_ok() && API.validate().is_ok() && OCHI_SHIN.validate().is_ok());
        let band = NPD.variance(0.5, 0.1).unwrap_err().to_string();
        assert!(band.contains("upper frequency"), "{band}");
    }

    #[test]
    fn a_spectrum_names_its_kind() {
        assert_eq!(NPD.kind(), WindSpectrumKind::Npd);
        assert_eq!(OCHI_SHIN.kind().word(), "ochi-shin");
        assert_eq!(
            GustSpectrum::Constant { speed: 1.0 }.kind().word(),
            "constant"
        );
        assert_eq!(API.kind().word(), "api");
    }
}
