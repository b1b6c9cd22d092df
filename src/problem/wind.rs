//! The wind a run applies (docs/theory.md#wind-force): the `[wind]` of the scenario on the
//! platform's wind coefficients (`[platform.wind]`), at the height of the wind force.

use super::Problem;
use crate::error::{Error, Result};
use crate::wind::{GustSpectrum, WindForce};

/// What a run needs of its wind: the force, the gust spectrum at the force's height and the
/// mean speed there.
#[derive(Debug, Clone, PartialEq)]
pub struct RunWind {
    pub force: WindForce,
    pub gust: GustSpectrum,
    /// The mean wind speed at the force's height, m/s, over the spectrum's averaging period.
    pub mean: f64,
    /// The force's height, m.
    pub height: f64,
}

impl Problem {
    /// The wind of a run: `None` when calm (`[wind] speed = 0`). Refused: a wind on a
    /// platform without wind coefficients (its force would be silently zero), and what
    /// [`crate::wind::WindField`] refuses at the force's height.
    pub fn run_wind(&self) -> Result<Option<RunWind>> {
        let wind = &self.wind;
        wind.validate()?;
        if wind.is_calm() {
            return Ok(None);
        }
        let Some(load) = &self.platform.wind else {
            return Err(Error::invalid(
                "wind.speed",
                wind.speed,
                "needs the platform's wind coefficients ([platform.wind]: a table of C_x, C_y, \
                 C_mz against the relative angle, or projected areas) to load it; give them, \
                 or set the speed to 0",
            ));
        };
        let height = load.height;
        let period = wind.spectrum_period();
        let force = WindForce::new(load, wind.direction, wind.air_density, |z| {
            wind.mean(period, z)
        })?;
        Ok(Some(RunWind {
            force,
            gust: wind.gust_spectrum(height)?,
            mean: wind.mean_at(height)?,
            height,
        }))
    }
}
