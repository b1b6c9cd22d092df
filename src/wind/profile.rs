//! The mean wind profile: the mean speed from the height where it is given (the reference
//! height z_r) to the height of the wind force z (docs/theory.md#wind). Speeds in m/s,
//! heights in m above the still water level, averaging periods in s.

use crate::error::{require_finite, require_positive, Error, Result};
use crate::model::WindProfileKind;
use serde::Serialize;

/// The reference height of the NPD profile and spectrum: U0 is the mean at 10 m.
pub const NPD_REFERENCE_HEIGHT: f64 = 10.0;

/// The averaging period of the NPD profile's U0, T0 = 1 hour, s.
pub const NPD_REFERENCE_PERIOD: f64 = 3600.0;

/// The power-law exponent alpha when none is given (`[wind] profile_exponent`): DNV-RP-C205
/// sec. 2.3.2's open sea.
pub const DEFAULT_POWER_LAW_EXPONENT: f64 = 0.12;

/// The logarithmic profile's roughness length z0 when none is given (`[wind]
/// roughness_length`), m: within DNV-RP-C205 table 2-1's 1e-4 to 3e-3 m for the open sea
/// with waves.
pub const DEFAULT_ROUGHNESS_LENGTH: f64 = 0.001;

/// The largest power-law exponent accepted: offshore profiles have alpha of about 0.1-0.14
/// (DNV-RP-C205 table 2-1 lists up to 0.4 for cities); 1 would make the speed grow as the
/// height itself.
const MAX_EXPONENT: f64 = 1.0;

/// A mean wind profile U(z).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum WindProfile {
    /// Power law, U(z) = U_r (z / z_r)^alpha (DNV-RP-C205 sec. 2.3.2): the speed is taken
    /// as given, for the averaging period it was given for.
    PowerLaw {
        /// alpha, dimensionless (`wind.profile_exponent`); 0.12 is DNV-RP-C205's open sea.
        exponent: f64,
    },
    /// Logarithmic, U(z) = U_r ln(z / z0) / ln(z_r / z0) (the neutral surface layer,
    /// DNV-RP-C205 sec. 2.3.2): the speed is taken as given, for the averaging period it was
    /// given for.
    Logarithmic {
        /// The terrain roughness z0, m (`wind.roughness_length`): 1e-4 to 3e-3 m over the
        /// open sea with waves (DNV-RP-C205 table 2-1).
        roughness: f64,
    },
    /// ISO 19901-1 / NPD (DNV-RP-C205 sec. 2.3.2, the Frøya model): the 1-hour mean at z from
    /// U0, the 1-hour mean at 10 m, U(z) = U0 [1 + C ln(z / 10)], C = 5.73e-2 sqrt(1 + 0.148
    /// U0); and the mean over T <= T0 = 3600 s, U(T, z) = U(z) [1 - 0.41 I_u(z) ln(T /
    /// T0)], I_u(z) = 0.06 (1 + 0.043 U0) (z / 10)^-0.22 ([`npd_mean`]).
    Npd,
}

/// The NPD (ISO 19901-1, DNV-RP-C205 sec. 2.3.2) mean speed over `period` s at height `z`
/// m, from `u0`, the 1-hour mean at 10 m (m/s):
///
/// U(T, z) = U0 [1 + C ln(z / 10)] [1 - 0.41 I_u(z) ln(T / T0)],
/// C = 5.73e-2 sqrt(1 + 0.148 U0), I_u(z) = 0.06 (1 + 0.043 U0) (z / 10)^-0.22, T0 = 3600 s.
///
/// No check of its arguments: [`WindProfile::speed_at`] and [`WindProfile::convert_period`]
/// check them.
pub fn npd_mean(u0: f64, z: f64, period: f64) -> f64 {
    let c = 5.73e-2 * (1.0 + 0.148 * u0).sqrt();
    let one_hour = u0 * (1.0 + c * (z / NPD_REFERENCE_HEIGHT).ln());
    one_hour * (1.0 - 0.41 * npd_turbulence_intensity(u0, z) * (period / NPD_REFERENCE_PERIOD).ln())
}

/// The NPD turbulence intensity I_u(z) = 0.06 (1 + 0.043 U0) (z / 10)^-0.22 (ISO 19901-1,
/// DNV-RP-C205 sec. 2.3.2), from U0 the 1-hour mean at 10 m (m/s) and the height z (m).
pub fn npd_turbulence_intensity(u0: f64, z: f64) -> f64 {
    0.06 * (1.0 + 0.043 * u0) * (z / NPD_REFERENCE_HEIGHT).powf(-0.22)
}

impl WindProfile {
    /// Which of the profiles it is (`[wind] profile`).
    pub fn kind(&self) -> WindProfileKind {
        match self {
            WindProfile::PowerLaw { .. } => WindProfileKind::PowerLaw,
            WindProfile::Logarithmic { .. } => WindProfileKind::Logarithmic,
            WindProfile::Npd => WindProfileKind::Npd,
        }
    }

    /// Checks the profile's own parameters; the error names the setting.
    pub fn validate(&self) -> Result<()> {
        match *self {
            WindProfile::PowerLaw { exponent } => {
                require_finite("wind.profile_exponent", exponent)?;
                if !(0.0..=MAX_EXPONENT).contains(&exponent) {
                    return Err(Error::invalid(
                        "wind.profile_exponent",
                        exponent,
                        format!(
                            "must be from 0 to {MAX_EXPONENT}: the mean wind does not fall with \
                             height, and offshore alpha is about 0.1-0.14"
                        ),
                    ));
                }
                Ok(())
            }
            WindProfile::Logarithmic { roughness } => {
                require_positive("wind.roughness_length", roughness)
            }
            WindProfile::Npd => Ok(()),
        }
    }

    /// The mean speed at height `z` (m, `wind.height`), from `speed` (m/s, `wind.speed`)
    /// the mean at `reference_height` (m, `wind.reference_height`), over the same averaging
    /// period. The NPD profile's speed is a 1-hour mean: at another reference height than
    /// 10 m, U0 is found by bisection from U(z_r) (U(z) increases with U0 from 10 m up).
    pub fn speed_at(&self, speed: f64, reference_height: f64, z: f64) -> Result<f64> {
        self.validate()?;
        require_positive("wind.speed", speed)?;
        require_positive("wind.reference_height", reference_height)?;
        require_positive("wind.height", z)?;
        let at_z = match *self {
            WindProfile::PowerLaw { exponent } => speed * (z / reference_height).powf(exponent),
            WindProfile::Logarithmic { roughness } => {
                for (name, height) in [
                    ("wind.reference_height", reference_height),
                    ("wind.height", z),
                ] {
                    if height <= roughness {
                        return Err(Error::invalid(
                            name,
                            height,
                            format!(
                                "must be above the roughness length wind.roughness_length = \
                                 {roughness} m, where the logarithmic profile is zero"
                            ),
                        ));
                    }
                }
                speed * (z / roughness).ln() / (reference_height / roughness).ln()
            }
            WindProfile::Npd => {
                let u0 = npd_reference_speed(speed, reference_height, NPD_REFERENCE_PERIOD)?;
                npd_mean(u0, z, NPD_REFERENCE_PERIOD)
            }
        };
        if at_z.is_finite() && at_z > 0.0 {
            Ok(at_z)
        } else {
            Err(Error::invalid(
                "wind.height",
                z,
                format!(
                    "the {} profile gives no positive mean speed there ({at_z} m/s)",
                    self.kind_word()
                ),
            ))
        }
    }

    /// The mean speed at height `z` (m) over the averaging period `to` (s), from `speed`
    /// (m/s), its mean over the period `from` (s) at the same height. Only the NPD profile
    /// defines one (ISO 19901-1, DNV-RP-C205 sec. 2.3.2; periods up to T0 = 3600 s); the
    /// power-law and logarithmic profiles take the speed as given, and are refused naming
    /// `wind.profile`.
    pub fn convert_period(&self, speed: f64, z: f64, from: f64, to: f64) -> Result<f64> {
        if *self != WindProfile::Npd {
            return Err(Error::invalid(
                "wind.profile",
                self.kind_word(),
                "defines no conversion between averaging periods: it takes wind.speed as given, \
                 for the averaging period it was given for (the npd profile converts)",
            ));
        }
        require_positive("wind.speed", speed)?;
        require_positive("wind.height", z)?;
        for period in [from, to] {
            require_positive("wind.averaging_period", period)?;
            if period > NPD_REFERENCE_PERIOD {
                return Err(Error::invalid(
                    "wind.averaging_period",
                    period,
                    "must be at most 3600 s: the NPD gust factor holds for averaging periods up \
                     to its 1-hour mean",
                ));
            }
        }
        let u0 = npd_reference_speed(speed, z, from)?;
        Ok(npd_mean(u0, z, to))
    }

    fn kind_word(&self) -> &'static str {
        use crate::model::Mode;
        self.kind().word()
    }
}

/// U0 (the 1-hour mean at 10 m) whose NPD mean over `period` at height `z` is `speed`:
/// bisection on [0, hi], hi doubled until it brackets `speed` (U(T, z) increases with U0
/// wherever the profile is positive at 10 m and above).
fn npd_reference_speed(speed: f64, z: f64, period: f64) -> Result<f64> {
    let mean = |u0: f64| npd_mean(u0, z, period);
    let mut hi = speed.max(1.0);
    let mut doublings = 0;
    while mean(hi) < speed {
        hi *= 2.0;
        doublings += 1;
        if doublings > 60 || !mean(hi).is_finite() {
            return Err(Error::invalid(
                "wind.height",
                z,
                format!("the NPD profile reaches no mean speed of {speed} m/s there"),
            ));
        }
    }
    let mut lo = 0.0;
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mean(mid) < speed {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo <= 1e-15 * hi {
            break;
        }
    }
    Ok(0.5 * (lo + hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, rel: f64) -> bool {
        (a - b).abs() <= rel * b.abs()
    }

    /// Power law, alpha = 0.12: at twice the height the speed is 2^0.12 = 1.086735 times.
    #[test]
    fn power_law_at_twice_the_height() {
        let profile = WindProfile::PowerLaw { exponent: 0.12 };
        let u = profile.speed_at(20.0, 10.0, 20.0).unwrap();
        // 2^0.12 = exp(0.12 ln 2) = exp(0.0831777) = 1.0867349
        assert!(close(u, 20.0 * 1.0867349, 1e-7), "{u}");
        assert_eq!(profile.speed_at(20.0, 10.0, 10.0).unwrap(), 20.0);
    }

    /// The log profile gives U_r at z_r, and ln(z/z0)/ln(z_r/z0) elsewhere.
    #[test]
    fn logarithmic_profile_at_and_above_the_reference() {
        let profile = WindProfile::Logarithmic { roughness: 1e-3 };
        assert!(close(
            profile.speed_at(15.0, 10.0, 10.0).unwrap(),
            15.0,
            1e-14
        ));
        // ln(100 / 1e-3) / ln(10 / 1e-3) = ln(1e5) / ln(1e4) = 5 / 4
        let u = profile.speed_at(15.0, 10.0, 100.0).unwrap();
        assert!(close(u, 15.0 * 1.25, 1e-12), "{u}");
    }

    /// The NPD profile at 10 m is U0; at 50 m with U0 = 40 m/s, C = 0.0573 sqrt(1 + 5.92) =
    /// 0.150733 and U = 40 (1 + 0.150733 ln 5) = 49.7039 m/s.
    #[test]
    fn npd_profile_by_hand() {
        let profile = WindProfile::Npd;
        assert!(close(
            profile.speed_at(40.0, 10.0, 10.0).unwrap(),
            40.0,
            1e-12
        ));
        let u = profile.speed_at(40.0, 10.0, 50.0).unwrap();
        assert!(close(u, 49.7039, 1e-5), "{u}");
        // Given at 50 m, the same profile returns U0 = 40 m/s at 10 m.
        let back = profile.speed_at(49.7039, 50.0, 10.0).unwrap();
        assert!(close(back, 40.0, 1e-5), "{back}");
    }

    /// The NPD 10-min mean at 10 m from U0 = 40 m/s: I_u = 0.06 (1 + 1.72) = 0.1632, and
    /// U = 40 (1 - 0.41 0.1632 ln(600/3600)) = 40 (1 + 0.066912 1.791759) = 44.79561 m/s;
    /// back to the hour gives U0 again.
    #[test]
    fn npd_averaging_periods_by_hand() {
        let profile = WindProfile::Npd;
        let ten_min = profile.convert_period(40.0, 10.0, 3600.0, 600.0).unwrap();
        assert!(close(ten_min, 44.79561, 1e-6), "{ten_min}");
        let hour = profile
            .convert_period(ten_min, 10.0, 600.0, 3600.0)
            .unwrap();
        assert!(close(hour, 40.0, 1e-10), "{hour}");
        // At 50 m, a 3-s gust and back.
        let gust = profile.convert_period(30.0, 50.0, 600.0, 3.0).unwrap();
        assert!(gust > 30.0);
        let back = profile.convert_period(gust, 50.0, 3.0, 600.0).unwrap();
        assert!(close(back, 30.0, 1e-10), "{back}");
    }

    /// The power-law and logarithmic profiles take the speed as given: a conversion between
    /// averaging periods is refused naming the profile.
    #[test]
    fn only_npd_converts_averaging_periods() {
        let err = WindProfile::PowerLaw { exponent: 0.12 }
            .convert_period(20.0, 10.0, 600.0, 3600.0)
            .unwrap_err();
        assert!(
            err.to_string()
                .starts_with("invalid wind.profile = power-law"),
            "{err}"
        );
        let err = WindProfile::Npd
            .convert_period(20.0, 10.0, 600.0, 7200.0)
            .unwrap_err();
        assert!(
            err.to_string()
                .starts_with("invalid wind.averaging_period = 7200"),
            "{err}"
        );
    }

    /// Negative or zero heights, speeds and parameters are refused naming the setting.
    #[test]
    fn errors_name_the_setting() {
        let power = WindProfile::PowerLaw { exponent: 0.12 };
        let message = |r: Result<f64>| r.unwrap_err().to_string();
        assert!(message(power.speed_at(-5.0, 10.0, 20.0)).starts_with("invalid wind.speed = -5"));
        assert!(message(power.speed_at(5.0, 0.0, 20.0))
            .starts_with("invalid wind.reference_height = 0"));
        assert!(message(power.speed_at(5.0, 10.0, -1.0)).starts_with("invalid wind.height = -1"));
        assert!(
            message(WindProfile::PowerLaw { exponent: -0.1 }.speed_at(5.0, 10.0, 20.0))
                .starts_with("invalid wind.profile_exponent = -0.1")
        );
        let log = WindProfile::Logarithmic { roughness: 0.01 };
        assert!(message(log.speed_at(5.0, 10.0, 0.005)).starts_with("invalid wind.height = 0.005"));
        assert!(message(
            WindProfile::Logarithmic {
                roughness: f64::NAN
            }
            .speed_at(5.0, 10.0, 20.0)
        )
        .starts_with("invalid wind.roughness_length = NaN"));
    }

    #[test]
    fn a_profile_names_its_kind() {
        use crate::model::Mode;
        assert_eq!(WindProfile::Npd.kind().word(), "npd");
        assert_eq!(
            WindProfile::PowerLaw { exponent: 0.1 }.kind(),
            WindProfileKind::PowerLaw
        );
        assert_eq!(
            WindProfile::Logarithmic { roughness: 1e-3 }.kind().word(),
            "logarithmic"
        );
    }
}
