//! The wind a run applies (docs/theory.md#wind-force): the `[wind]` of the scenario on the
//! platform's wind coefficients (`[platform.wind]`), at the height of the wind force.

use super::Problem;
use crate::error::{Error, Result};
use crate::model::{Mode, WindSource};
use crate::wind::{GustSpectrum, WindForce};

/// The reference speed whose profile shapes the areas' speeds under an input wind, m/s.
pub const INPUT_PROFILE_SPEED: f64 = 1.0;

/// What a run needs of its wind: the force, its height, and where the speed there comes
/// from.
#[derive(Debug, Clone, PartialEq)]
pub struct RunWind {
    pub force: WindForce,
    /// The force's height, m.
    pub height: f64,
    /// The mean and its gusts; `None` when the speed is the FMU's input (`wind.source =
    /// "input"`).
    pub gusts: Option<Gusts>,
}

/// The speed at the force's height from the records: the mean and the gust spectrum there.
#[derive(Debug, Clone, PartialEq)]
pub struct Gusts {
    pub spectrum: GustSpectrum,
    /// The mean wind speed at the force's height, m/s, over the spectrum's averaging period.
    pub mean: f64,
}

impl Problem {
    /// The wind of a run: `None` when calm (`[wind] speed = 0` from the records). Refused: a
    /// wind on a platform without wind coefficients (its force would be silently zero), and
    /// what [`crate::wind::WindField`] refuses at the force's height.
    pub fn run_wind(&self) -> Result<Option<RunWind>> {
        let wind = &self.wind;
        wind.validate()?;
        if wind.is_calm() {
            return Ok(None);
        }
        let Some(load) = &self.platform.wind else {
            let (setting, value) = match wind.source {
                WindSource::Records => ("wind.speed", crate::error::numbers::written(wind.speed)),
                WindSource::Input => ("wind.source", format!("\"{}\"", wind.source.word())),
            };
            return Err(Error::invalid(
                setting,
                value,
                "needs the platform's wind coefficients ([platform.wind]: a table of C_x, C_y, \
                 C_mz against the relative angle, or projected areas) to load it; give them, \
                 or set the speed to 0 (and the source to \"records\")",
            ));
        };
        let height = load.height;
        let period = match wind.source {
            WindSource::Records => wind.spectrum_period(),
            WindSource::Input => wind.averaging_period,
        };
        // The areas' speeds relative to the force's height follow the profile; an input
        // speed has no mean to shape it, so the profile's shape at 1 m/s is taken (the power
        // law's and the logarithmic one are the same at every speed; the NPD profile's
        // C = 0.0573 sqrt(1 + 0.148 U0) varies with it).
        let shaped;
        let profile = match wind.source {
            WindSource::Records => wind,
            WindSource::Input => {
                shaped = crate::wind::WindField {
                    speed: INPUT_PROFILE_SPEED,
                    ..wind.clone()
                };
                &shaped
            }
        };
        let gusts = match wind.source {
            WindSource::Records => Some(Gusts {
                spectrum: wind.gust_spectrum(height)?,
                mean: wind.mean_at(height)?,
            }),
            WindSource::Input => None,
        };
        let force = WindForce::new(load, wind.direction, wind.air_density, |z| {
            profile.mean(period, z)
        })?;
        Ok(Some(RunWind {
            force,
            height,
            gusts,
        }))
    }
}
