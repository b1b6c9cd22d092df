//! The sea state: spectrum, directional spreading, and the random wave components made
//! from them by filtering seeded white Gaussian noise (E&S 5, 6; docs/theory.md#sea-state,
//! docs/theory.md#random-waves).

mod components;
mod spectrum;
mod spreading;

pub use components::{gust_amplitudes, FrequencyGrid, WaveComponents};
pub use spectrum::{Spectrum, MAX_STEEPNESS};
pub use spreading::{Direction, Spreading};

use crate::error::numbers::{readable, written};
use crate::error::{require_finite, Error, Result};
use serde::Serialize;

/// Default lower edge of the simulated band, as a fraction of the peak frequency.
/// The PM and JONSWAP densities at 0.5 wp are about 2e-7 and 1e-7 of the peak, and the
/// variance below it is a fraction e^-20 (2e-9) of m0.
const DEFAULT_BAND_LOW_RATIO: f64 = 0.5;
/// Default upper edge of the simulated band, as a multiple of the peak frequency.
/// The PM tail above 4 wp holds 1.25 / 4^4 = 0.5 % of m0.
const DEFAULT_BAND_HIGH_RATIO: f64 = 4.0;

/// A short-term sea state.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SeaState {
    pub spectrum: Spectrum,
    pub spreading: Spreading,
    /// Mean direction of propagation beta_0, rad from +X, counter-clockwise.
    pub mean_direction: f64,
    /// Number of discrete directions N_beta over +-90 deg (ignored when long-crested).
    pub n_directions: usize,
    /// Seed of the xoshiro256++ stream that makes the wave amplitudes.
    pub seed: u64,
    /// Simulated frequency band (omega_min, omega_max), rad/s; `None` = the spectrum's default.
    pub band: Option<(f64, f64)>,
}

impl SeaState {
    /// Checks every field, and the steepness against [`MAX_STEEPNESS`] at gravity `gravity`
    /// (m/s^2); the error names the first offending field.
    pub fn validate(&self, gravity: f64) -> Result<()> {
        self.spectrum.validate()?;
        let steepness = self.spectrum.steepness(gravity);
        if steepness > MAX_STEEPNESS {
            let (field, value) = match &self.spectrum {
                Spectrum::Tabulated { .. } => ("sea.density", "the table".to_string()),
                spectrum => ("sea.hs", written(spectrum.significant_height())),
            };
            return Err(Error::invalid(
                field,
                value,
                format!(
                    "a sea steeper than waves can be: Hs / L_p = {} (L_p = 2 pi g / wp^2, the \
                     peak wave's length) exceeds the breaking limit 1/7",
                    readable(steepness)
                ),
            ));
        }
        self.spreading.validate()?;
        require_finite("sea.direction_deg", self.mean_direction.to_degrees())?;
        if self.n_directions == 0 && !matches!(self.spreading, Spreading::LongCrested) {
            return Err(Error::invalid("sea.n_directions", 0, "must be at least 1"));
        }
        if let Some((lo, hi)) = self.band {
            require_finite("sea.band[0]", lo)?;
            require_finite("sea.band[1]", hi)?;
            if !(lo > 0.0 && hi > lo) {
                return Err(Error::invalid(
                    "sea.band",
                    format!("[{}, {}]", written(lo), written(hi)),
                    "needs 0 < omega_min < omega_max",
                ));
            }
        }
        Ok(())
    }

    /// The simulated band (omega_min, omega_max) in rad/s.
    pub fn band(&self) -> (f64, f64) {
        match (self.band, &self.spectrum) {
            (Some(band), _) => band,
            (None, Spectrum::Tabulated { omega, .. }) => (omega[0], omega[omega.len() - 1]),
            (None, spectrum) => {
                let wp = spectrum.peak_frequency();
                (DEFAULT_BAND_LOW_RATIO * wp, DEFAULT_BAND_HIGH_RATIO * wp)
            }
        }
    }

    /// The discrete directions and their weights (weights sum to 1).
    pub fn directions(&self) -> Vec<Direction> {
        self.spreading
            .discretise(self.mean_direction, self.n_directions)
    }
}
