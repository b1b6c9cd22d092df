//! The water and the waves: `[environment]`, `[sea]` and `[current]`.

use super::{chosen, refused, required};
use crate::model::{Environment, SpectrumKind, SpreadingKind};
use crate::scenario::{Current, DEFAULT_N_DIRECTIONS};
use crate::sea_state::{SeaState, Spectrum, Spreading};
use serde::Deserialize;

/// Number of directions of a long-crested sea (the only value accepted for it).
pub const LONG_CRESTED_DIRECTIONS: usize = 1;
/// Default seed of the random wave amplitudes.
pub const DEFAULT_SEED: u64 = 1;

/// `[environment]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields, default)]
pub(super) struct EnvironmentFile {
    /// m/s^2.
    gravity: f64,
    /// kg/m^3.
    water_density: f64,
}

impl Default for EnvironmentFile {
    fn default() -> Self {
        let core = Environment::default();
        EnvironmentFile {
            gravity: core.gravity,
            water_density: core.water_density,
        }
    }
}

impl EnvironmentFile {
    pub(super) fn into_core(self) -> Environment {
        Environment {
            gravity: self.gravity,
            water_density: self.water_density,
        }
    }
}

/// `[sea]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SeaFile {
    spectrum: SpectrumKind,
    /// Significant wave height, m.
    hs: Option<f64>,
    /// Peak period, s.
    tp: Option<f64>,
    /// JONSWAP peak enhancement factor.
    gamma: Option<f64>,
    /// Tabulated spectrum: frequencies, rad/s.
    omega: Option<Vec<f64>>,
    /// Tabulated spectrum: densities, m^2 s/rad.
    density: Option<Vec<f64>>,
    /// Long-crested when absent.
    spreading: Option<SpreadingKind>,
    /// N of cos^N or s of cos^2s.
    spreading_exponent: Option<f64>,
    /// Mean direction of propagation, deg.
    #[serde(default)]
    direction_deg: f64,
    n_directions: Option<usize>,
    #[serde(default = "default_seed")]
    seed: u64,
    /// [omega_min, omega_max], rad/s.
    band: Option<[f64; 2]>,
}

fn default_seed() -> u64 {
    DEFAULT_SEED
}

impl SeaFile {
    pub(super) fn into_core(self) -> Result<SeaState, String> {
        let spectrum = self.spectrum()?;
        let (spreading, n_directions) = self.spreading()?;
        Ok(SeaState {
            spectrum,
            spreading,
            mean_direction: self.direction_deg.to_radians(),
            n_directions,
            seed: self.seed,
            band: self.band.map(|[lo, hi]| (lo, hi)),
        })
    }

    fn spectrum(&self) -> Result<Spectrum, String> {
        let because = chosen("spectrum", self.spectrum);
        match self.spectrum {
            SpectrumKind::Jonswap => {
                refused(&self.omega, "omega", &because)?;
                refused(&self.density, "density", &because)?;
                Ok(Spectrum::Jonswap {
                    hs: required(self.hs, "hs", &because)?,
                    tp: required(self.tp, "tp", &because)?,
                    gamma: self.gamma,
                })
            }
            SpectrumKind::PiersonMoskowitz => {
                refused(&self.gamma, "gamma", &because)?;
                refused(&self.omega, "omega", &because)?;
                refused(&self.density, "density", &because)?;
                Ok(Spectrum::PiersonMoskowitz {
                    hs: required(self.hs, "hs", &because)?,
                    tp: required(self.tp, "tp", &because)?,
                })
            }
            SpectrumKind::Table => {
                refused(&self.hs, "hs", &because)?;
                refused(&self.tp, "tp", &because)?;
                refused(&self.gamma, "gamma", &because)?;
                Ok(Spectrum::Tabulated {
                    omega: required(self.omega.clone(), "omega", &because)?,
                    density: required(self.density.clone(), "density", &because)?,
                })
            }
        }
    }

    fn spreading(&self) -> Result<(Spreading, usize), String> {
        let kind = self.spreading.unwrap_or(SpreadingKind::LongCrested);
        let because = chosen("spreading", kind);
        let exponent = || required(self.spreading_exponent, "spreading_exponent", &because);
        let spread_directions = self.n_directions.unwrap_or(DEFAULT_N_DIRECTIONS);
        match kind {
            SpreadingKind::LongCrested => {
                refused(&self.spreading_exponent, "spreading_exponent", &because)?;
                match self.n_directions {
                    None | Some(LONG_CRESTED_DIRECTIONS) => {
                        Ok((Spreading::LongCrested, LONG_CRESTED_DIRECTIONS))
                    }
                    Some(n) => Err(format!(
                        "n_directions = {n} does not apply when {because} (one direction)"
                    )),
                }
            }
            SpreadingKind::CosN => Ok((Spreading::CosN { n: exponent()? }, spread_directions)),
            SpreadingKind::Cos2s => Ok((Spreading::Cos2s { s: exponent()? }, spread_directions)),
        }
    }
}

/// `[current]`.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub(super) struct CurrentFile {
    /// m/s.
    speed: f64,
    /// Direction the current flows towards, deg.
    direction_deg: f64,
}

impl CurrentFile {
    pub(super) fn into_core(self) -> Current {
        Current {
            speed: self.speed,
            direction: self.direction_deg.to_radians(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::{error_text, read, MINIMAL};
    use super::*;
    use crate::error::Error;

    #[test]
    fn short_crested_sea_defaults_to_fifteen_directions_and_jonswap_to_dnv_gamma() {
        let text = MINIMAL.replace(
            "spectrum = \"pierson-moskowitz\"",
            "spectrum = \"jonswap\"\nspreading = \"cos-2s\"\nspreading_exponent = 6",
        );
        let sea = read(&text).expect("valid file").sea;
        assert_eq!(
            sea.spectrum,
            Spectrum::Jonswap {
                hs: 2.0,
                tp: 8.0,
                gamma: None
            }
        );
        assert_eq!(sea.spreading, Spreading::Cos2s { s: 6.0 });
        assert_eq!(sea.n_directions, DEFAULT_N_DIRECTIONS);
    }

    #[test]
    fn tabulated_spectrum_is_read() {
        let text = MINIMAL.replace(
            "spectrum = \"pierson-moskowitz\"\nhs = 2.0\ntp = 8.0",
            "spectrum = \"table\"\nomega = [0.3, 1.0, 2.0]\ndensity = [0.0, 1.5, 0.1]",
        );
        let sea = read(&text).expect("valid file").sea;
        assert_eq!(
            sea.spectrum,
            Spectrum::Tabulated {
                omega: vec![0.3, 1.0, 2.0],
                density: vec![0.0, 1.5, 0.1]
            }
        );
    }

    #[test]
    fn key_that_does_not_apply_is_refused_with_the_section_line() {
        let text = MINIMAL.replace("tp = 8.0", "tp = 8.0\ngamma = 3.3");
        let err = read(&text).expect_err("gamma with pierson-moskowitz");
        assert!(
            matches!(&err, Error::Parse { line: Some(2), .. }),
            "{err:?}"
        );
        assert!(
            err.to_string()
                .contains("gamma does not apply when spectrum = \"pierson-moskowitz\""),
            "{err}"
        );
        let text = MINIMAL.replace("tp = 8.0", "tp = 8.0\nn_directions = 3");
        assert!(error_text(&text).contains(
            "n_directions = 3 does not apply when spreading = \"long-crested\" (one direction)"
        ));
    }

    #[test]
    fn missing_key_that_the_choice_requires_is_named() {
        let text = MINIMAL.replace("hs = 2.0\n", "");
        assert!(error_text(&text).contains("hs is required"));
        let text = MINIMAL.replace("tp = 8.0", "tp = 8.0\nspreading = \"cos-n\"");
        assert!(
            error_text(&text).contains("spreading_exponent is required when spreading = \"cos-n\"")
        );
    }

    /// A word that is no spectrum is refused listing the words (the mode's deserializer).
    #[test]
    fn an_unknown_spectrum_lists_the_words() {
        let text = MINIMAL.replace("\"pierson-moskowitz\"", "\"bretschneider\"");
        assert_eq!(
            error_text(&text),
            "test.toml:3: unknown variant `bretschneider`, expected one of `jonswap`, \
             `pierson-moskowitz`, `table`"
        );
    }
}
