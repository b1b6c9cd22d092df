//! The wind as a user describes it (`[wind]`, docs/theory.md#wind): a mean speed with its
//! averaging period and reference height, a direction, a profile and a gust spectrum's kind
//! and parameters; and what a run makes of it at the height of the wind force: the mean
//! there and the [`GustSpectrum`] of the gusts about it.
//!
//! Which mean a spectrum is defined for (its averaging period and height) is the spectrum's
//! (docs/theory.md#wind): NPD and Ochi-Shin the 1-hour mean at 10 m, API the 1-hour mean at
//! the force's height, Harris and Davenport the 10-min mean at 10 m, Kaimal the 10-min mean at
//! the force's height. The speed given is brought there by the profile; between averaging
//! periods only the NPD profile converts (ISO 19901-1), so with another profile the speed must
//! be given over the spectrum's period, else the run is refused naming
//! `wind.averaging_period`. The mean at the force's height is the profile's over the
//! spectrum's period (the constant wind's: over the period given).

use super::profile::{WindProfile, NPD_REFERENCE_HEIGHT, NPD_REFERENCE_PERIOD};
use super::spectrum::{
    api_turbulence_intensity, iec_length_scale, require_drag_coefficient, require_intensity,
    GustSpectrum,
};
use crate::error::{require_finite, require_positive, Error, Result};
use crate::model::{Mode, WindSource, WindSpectrumKind};
use serde::Serialize;

/// Averaging period of the 10-min means (Harris, Davenport, Kaimal), s.
const TEN_MINUTES: f64 = 600.0;

/// Air density at sea level in the ISO 2533 standard atmosphere (15 deg C, 101 325 Pa),
/// kg/m^3.
pub const DEFAULT_AIR_DENSITY: f64 = 1.225;

/// The surface drag coefficient kappa of Harris, Davenport and Ochi-Shin over the open sea
/// when none is given (DNV-RP-C205 sec. 2.3.2 gives 0.001-0.003 for open sea with waves).
pub const DEFAULT_DRAG_COEFFICIENT: f64 = 0.002;

/// The wind of a scenario.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WindField {
    /// Mean speed at `reference_height` over `averaging_period`, m/s; 0 = no wind.
    pub speed: f64,
    /// The direction the wind blows towards, rad from +X, counter-clockwise (as the waves'
    /// and the current's).
    pub direction: f64,
    /// Height of `speed` above the still water level, m.
    pub reference_height: f64,
    /// Averaging period of `speed`, s.
    pub averaging_period: f64,
    pub profile: WindProfile,
    pub spectrum: WindSpectrumKind,
    /// kappa of Harris, Davenport and Ochi-Shin, dimensionless.
    pub drag_coefficient: f64,
    /// API's and Kaimal's turbulence intensity; `None`: API's own I(z), and for Kaimal the
    /// NPD profile's I_u(z) (ISO 19901-1).
    pub turbulence_intensity: Option<f64>,
    /// Kaimal's integral length scale, m; `None`: IEC 61400-1's 8.1 x 0.7 min(z, 60 m).
    pub length_scale: Option<f64>,
    /// kg/m^3.
    pub air_density: f64,
    /// Where the speed at the force's height comes from: the mean and its gust records, or
    /// the FMU's input `windVelocity_ext` (the speed, the spectrum and the profile then
    /// unused: `speed` must be 0).
    pub source: WindSource,
}

impl Default for WindField {
    /// No wind: speed 0 (the NPD profile and spectrum, the 1-hour mean at 10 m, when a speed
    /// is given).
    fn default() -> Self {
        WindField {
            speed: 0.0,
            direction: 0.0,
            reference_height: NPD_REFERENCE_HEIGHT,
            averaging_period: NPD_REFERENCE_PERIOD,
            profile: WindProfile::Npd,
            spectrum: WindSpectrumKind::Npd,
            drag_coefficient: DEFAULT_DRAG_COEFFICIENT,
            turbulence_intensity: None,
            length_scale: None,
            air_density: DEFAULT_AIR_DENSITY,
            source: WindSource::Records,
        }
    }
}

impl WindField {
    /// No wind (speed 0 and no input): nothing of the wind is made or serialised.
    pub fn is_calm(&self) -> bool {
        self.speed == 0.0 && self.source == WindSource::Records
    }

    /// Whether the run makes gust records: a wind of the records' source.
    pub fn has_gusts(&self) -> bool {
        !self.is_calm() && self.source == WindSource::Records
    }

    /// Checks what does not depend on the force's height (the spectrum's parameters too,
    /// whether or not there is wind); the error names the setting.
    pub fn validate(&self) -> Result<()> {
        require_finite("wind.speed", self.speed)?;
        if self.speed < 0.0 {
            return Err(Error::invalid(
                "wind.speed",
                self.speed,
                "must be at least 0 m/s (0: no wind)",
            ));
        }
        if self.source == WindSource::Input && self.speed != 0.0 {
            return Err(Error::invalid(
                "wind.speed",
                self.speed,
                "is not used when wind.source = \"input\" (the speed comes from the FMU's \
                 input windVelocity_ext): set it to 0, or the source to \"records\"",
            ));
        }
        require_finite("wind.direction", self.direction)?;
        require_positive("wind.reference_height", self.reference_height)?;
        require_positive("wind.averaging_period", self.averaging_period)?;
        require_positive("wind.air_density", self.air_density)?;
        require_drag_coefficient(self.drag_coefficient)?;
        if let Some(intensity) = self.turbulence_intensity {
            require_intensity(intensity)?;
        }
        if let Some(length) = self.length_scale {
            require_positive("wind.length_scale", length)?;
        }
        self.profile.validate()
    }

    /// The averaging period the spectrum's mean is defined for, s (the constant wind's: the
    /// period given).
    pub fn spectrum_period(&self) -> f64 {
        match self.spectrum {
            WindSpectrumKind::Npd | WindSpectrumKind::Api | WindSpectrumKind::OchiShin => {
                NPD_REFERENCE_PERIOD
            }
            WindSpectrumKind::Harris | WindSpectrumKind::Davenport | WindSpectrumKind::Kaimal => {
                TEN_MINUTES
            }
            WindSpectrumKind::Constant => self.averaging_period,
        }
    }

    /// The mean speed at height `z` (m) over `period` (s), m/s: the profile from the speed
    /// given; between periods only through the NPD profile (else refused naming
    /// `wind.averaging_period`).
    pub fn mean(&self, period: f64, z: f64) -> Result<f64> {
        let (given, at) = (self.averaging_period, self.reference_height);
        if (period - given).abs() <= 1e-9 * given {
            return self.profile.speed_at(self.speed, at, z);
        }
        if self.profile != WindProfile::Npd {
            return Err(Error::invalid(
                "wind.averaging_period",
                given,
                format!(
                    "the {} spectrum is defined for the {period} s mean, and the {} profile \
                     takes wind.speed as given: give the {period} s mean, or use profile = \
                     \"npd\", which converts between averaging periods (ISO 19901-1)",
                    self.spectrum.word(),
                    self.profile.kind().word()
                ),
            ));
        }
        let hour = self
            .profile
            .convert_period(self.speed, at, given, NPD_REFERENCE_PERIOD)?;
        let hour_at_z = self.profile.speed_at(hour, at, z)?;
        self.profile
            .convert_period(hour_at_z, z, NPD_REFERENCE_PERIOD, period)
    }

    /// The mean speed at the force's height `z` (m) that the gusts fluctuate about, m/s: over
    /// the spectrum's averaging period ([`WindField::spectrum_period`]).
    pub fn mean_at(&self, z: f64) -> Result<f64> {
        self.mean(self.spectrum_period(), z)
    }

    /// The gust spectrum at the force's height `z` (m), from the mean it is defined for.
    pub fn gust_spectrum(&self, z: f64) -> Result<GustSpectrum> {
        self.validate()?;
        let period = self.spectrum_period();
        let kappa = self.drag_coefficient;
        let spectrum = match self.spectrum {
            WindSpectrumKind::Npd => GustSpectrum::Npd {
                speed: self.mean(period, NPD_REFERENCE_HEIGHT)?,
                height: z,
            },
            WindSpectrumKind::Api => GustSpectrum::Api {
                speed: self.mean(period, z)?,
                height: z,
                turbulence_intensity: self
                    .turbulence_intensity
                    .unwrap_or_else(|| api_turbulence_intensity(z)),
            },
            WindSpectrumKind::Harris => GustSpectrum::Harris {
                speed: self.mean(period, NPD_REFERENCE_HEIGHT)?,
                drag_coefficient: kappa,
            },
            WindSpectrumKind::Davenport => GustSpectrum::Davenport {
                speed: self.mean(period, NPD_REFERENCE_HEIGHT)?,
                drag_coefficient: kappa,
            },
            WindSpectrumKind::Kaimal => {
                let speed = self.mean(period, z)?;
                let intensity = match self.turbulence_intensity {
                    Some(i) => i,
                    None => super::profile::npd_turbulence_intensity(
                        self.mean(NPD_REFERENCE_PERIOD, NPD_REFERENCE_HEIGHT)?,
                        z,
                    ),
                };
                GustSpectrum::Kaimal {
                    speed,
                    turbulence_intensity: intensity,
                    length_scale: self.length_scale.unwrap_or_else(|| iec_length_scale(z)),
                }
            }
            WindSpectrumKind::OchiShin => GustSpectrum::OchiShin {
                speed: self.mean(period, NPD_REFERENCE_HEIGHT)?,
                height: z,
                drag_coefficient: kappa,
            },
            WindSpectrumKind::Constant => GustSpectrum::Constant {
                speed: self.mean(period, z)?,
            },
        };
        spectrum.validate()?;
        Ok(spectrum)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wind(spectrum: WindSpectrumKind, profile: WindProfile, period: f64) -> WindField {
        WindField {
            speed: 20.0,
            averaging_period: period,
            profile,
            spectrum,
            ..WindField::default()
        }
    }

    /// The NPD spectrum from a 1-hour mean at 10 m takes that speed as its U0; from a 10-min
    /// mean, U0 is the speed whose NPD 10-min mean is the one given (ISO 19901-1:
    /// U(600 s, 10 m) = U0 (1 - 0.41 x 0.06 (1 + 0.043 U0) ln(1/6)), solved here by hand
    /// as a quadratic in U0).
    #[test]
    fn npd_takes_the_one_hour_mean_at_ten_metres() {
        let hour = wind(WindSpectrumKind::Npd, WindProfile::Npd, 3600.0);
        let spectrum = hour.gust_spectrum(30.0).unwrap();
        assert!(
            matches!(spectrum, GustSpectrum::Npd { speed, height } if (speed - 20.0).abs() < 1e-9 && height == 30.0)
        );
        let ten = wind(WindSpectrumKind::Npd, WindProfile::Npd, 600.0);
        // 20 = U0 (1 + b) + U0^2 b 0.043 with b = -0.41 x 0.06 ln(1/6) = 0.0440769...
        let b = -0.41 * 0.06 * (1.0f64 / 6.0).ln();
        let (qa, qb, qc) = (0.043 * b, 1.0 + b, -20.0);
        let u0 = (-qb + (qb * qb - 4.0 * qa * qc).sqrt()) / (2.0 * qa);
        match ten.gust_spectrum(10.0).unwrap() {
            GustSpectrum::Npd { speed, .. } => {
                assert!((speed - u0).abs() < 1e-6, "{speed} vs {u0}")
            }
            other => panic!("{other:?}"),
        }
    }

    /// With the power law, the spectrum's own period must be the one given: a 1-hour mean is
    /// refused for Harris (a 10-min spectrum) naming the period; the 10-min mean at 10 m is
    /// taken as U10 whatever the force's height, and the mean at the force's height is the
    /// power law's, 20 (50/10)^0.12.
    #[test]
    fn another_profile_takes_the_speed_over_the_spectrum_period() {
        let law = WindProfile::PowerLaw { exponent: 0.12 };
        let err = wind(WindSpectrumKind::Harris, law, 3600.0)
            .gust_spectrum(50.0)
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("wind.averaging_period") && err.contains("600 s mean"),
            "{err}"
        );
        let ten = wind(WindSpectrumKind::Harris, law, 600.0);
        assert!(matches!(
            ten.gust_spectrum(50.0).unwrap(),
            GustSpectrum::Harris { speed, .. } if speed == 20.0
        ));
        let mean = ten.mean_at(50.0).unwrap();
        assert!((mean - 20.0 * 5f64.powf(0.12)).abs() < 1e-12, "{mean}");
    }

    /// Defaults: API's intensity at the force's height, Kaimal's IEC length scale, calm at
    /// speed 0, and bad settings named.
    #[test]
    fn defaults_and_errors() {
        let api = wind(WindSpectrumKind::Api, WindProfile::Npd, 3600.0);
        match api.gust_spectrum(20.0).unwrap() {
            GustSpectrum::Api {
                turbulence_intensity,
                ..
            } => assert!((turbulence_intensity - 0.15).abs() < 1e-12),
            other => panic!("{other:?}"),
        }
        let kaimal = wind(WindSpectrumKind::Kaimal, WindProfile::Npd, 600.0);
        match kaimal.gust_spectrum(30.0).unwrap() {
            GustSpectrum::Kaimal { length_scale, .. } => {
                assert!((length_scale - 8.1 * 0.7 * 30.0).abs() < 1e-12)
            }
            other => panic!("{other:?}"),
        }
        assert!(WindField::default().is_calm());
        let negative = WindField {
            speed: -1.0,
            ..WindField::default()
        };
        let err = negative.validate().unwrap_err().to_string();
        assert!(err.contains("wind.speed") && err.contains("-1"), "{err}");
        let thin = WindField {
            speed: 10.0,
            air_density: 0.0,
            ..WindField::default()
        };
        assert!(thin
            .validate()
            .unwrap_err()
            .to_string()
            .contains("wind.air_density"));
    }
}
