//! The wind: `[wind]` (docs/configuration.md#wind), read into a [`WindField`]. Degrees
//! become radians here; a key that the chosen profile or spectrum does not use is refused
//! naming it, its value and its line. The values themselves are checked with the problem
//! (`problem::Problem::check`, through [`WindField::validate`] and, when there is wind, the
//! gust spectrum at the reference height).

use crate::error::{Error, Result};
use crate::model::{Mode, WindProfileKind, WindSource, WindSpectrumKind};
use crate::scenario::Origins;
use crate::wind::{
    WindField, WindProfile, DEFAULT_AIR_DENSITY, DEFAULT_DRAG_COEFFICIENT,
    DEFAULT_POWER_LAW_EXPONENT, DEFAULT_ROUGHNESS_LENGTH,
};
use serde::Deserialize;

/// `[wind]`; absent keys take [`WindField::default`]'s values (no wind), a profile's
/// parameter its documented default.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct WindFile {
    /// Mean speed at `reference_height` over `averaging_period`, m/s; 0 = no wind.
    speed: Option<f64>,
    /// Direction the wind blows towards, deg from +X counter-clockwise.
    direction_deg: Option<f64>,
    /// m.
    reference_height: Option<f64>,
    /// s.
    averaging_period: Option<f64>,
    profile: Option<WindProfileKind>,
    /// alpha of the power law.
    profile_exponent: Option<f64>,
    /// z0 of the logarithmic profile, m.
    roughness_length: Option<f64>,
    spectrum: Option<WindSpectrumKind>,
    /// kappa of Harris, Davenport and Ochi-Shin.
    drag_coefficient: Option<f64>,
    /// API's and Kaimal's.
    turbulence_intensity: Option<f64>,
    /// Kaimal's, m.
    length_scale: Option<f64>,
    /// kg/m^3.
    air_density: Option<f64>,
    /// The gust records (the default) or the FMU's input.
    source: Option<WindSource>,
}

/// The spectra that use each of the spectrum's own keys.
const SPECTRUM_KEYS: [(&str, &[WindSpectrumKind]); 3] = [
    (
        "drag_coefficient",
        &[
            WindSpectrumKind::Harris,
            WindSpectrumKind::Davenport,
            WindSpectrumKind::OchiShin,
        ],
    ),
    (
        "turbulence_intensity",
        &[WindSpectrumKind::Api, WindSpectrumKind::Kaimal],
    ),
    ("length_scale", &[WindSpectrumKind::Kaimal]),
];

impl WindFile {
    /// The wind; a key the chosen profile or spectrum does not use is refused, located by
    /// `origins` (`test.toml:14: invalid [wind] length_scale = 300: ...`).
    pub(super) fn into_core(self, origins: &Origins) -> Result<WindField> {
        let calm = WindField::default();
        let spectrum = self.spectrum.unwrap_or(calm.spectrum);
        let spectrum_is = choice("spectrum", spectrum, self.spectrum.is_none());
        for (key, users) in SPECTRUM_KEYS {
            if let Some(value) = self.spectrum_key(key) {
                if !users.contains(&spectrum) {
                    let words: Vec<&str> = users.iter().map(|m| m.word()).collect();
                    return Err(origins.locate(Error::invalid(
                        format!("wind.{key}"),
                        value,
                        format!(
                            "does not apply when {spectrum_is}: only {} use{} it",
                            list(&words),
                            if words.len() == 1 { "s" } else { "" }
                        ),
                    )));
                }
            }
        }
        Ok(WindField {
            speed: self.speed.unwrap_or(calm.speed),
            direction: self.direction_deg.map_or(calm.direction, f64::to_radians),
            reference_height: self.reference_height.unwrap_or(calm.reference_height),
            averaging_period: self.averaging_period.unwrap_or(calm.averaging_period),
            profile: self.profile(origins)?,
            spectrum,
            drag_coefficient: self.drag_coefficient.unwrap_or(DEFAULT_DRAG_COEFFICIENT),
            turbulence_intensity: self.turbulence_intensity,
            length_scale: self.length_scale,
            air_density: self.air_density.unwrap_or(DEFAULT_AIR_DENSITY),
            source: self.source.unwrap_or(calm.source),
        })
    }

    fn spectrum_key(&self, key: &str) -> Option<f64> {
        match key {
            "drag_coefficient" => self.drag_coefficient,
            "turbulence_intensity" => self.turbulence_intensity,
            "length_scale" => self.length_scale,
            _ => None,
        }
    }

    /// The profile with its parameter (its default when not given); the other profile's
    /// parameter refused.
    fn profile(&self, origins: &Origins) -> Result<WindProfile> {
        let kind = self.profile.unwrap_or(WindProfileKind::Npd);
        let profile_is = choice("profile", kind, self.profile.is_none());
        let refuse = |key: &str, value: Option<f64>, users: &str| match value {
            Some(value) => Err(origins.locate(Error::invalid(
                format!("wind.{key}"),
                value,
                format!("does not apply when {profile_is}: only profile = \"{users}\" uses it"),
            ))),
            None => Ok(()),
        };
        let (exponent, roughness) = (self.profile_exponent, self.roughness_length);
        let (power_law, logarithmic) = (
            WindProfileKind::PowerLaw.word(),
            WindProfileKind::Logarithmic.word(),
        );
        Ok(match kind {
            WindProfileKind::PowerLaw => {
                refuse("roughness_length", roughness, logarithmic)?;
                WindProfile::PowerLaw {
                    exponent: exponent.unwrap_or(DEFAULT_POWER_LAW_EXPONENT),
                }
            }
            WindProfileKind::Logarithmic => {
                refuse("profile_exponent", exponent, power_law)?;
                WindProfile::Logarithmic {
                    roughness: roughness.unwrap_or(DEFAULT_ROUGHNESS_LENGTH),
                }
            }
            WindProfileKind::Npd => {
                refuse("profile_exponent", exponent, power_law)?;
                refuse("roughness_length", roughness, logarithmic)?;
                WindProfile::Npd
            }
        })
    }
}

/// A choice as the reason of a refusal names it: `spectrum = "kaimal"`, or `spectrum is
/// "npd" (the default)` when the file does not write it.
fn choice(key: &str, mode: impl Mode, by_default: bool) -> String {
    if by_default {
        format!("{key} is \"{}\" (the default)", mode.word())
    } else {
        super::chosen(key, mode)
    }
}

/// Words as a sentence lists them: `harris, davenport and ochi-shin`.
fn list(words: &[&str]) -> String {
    match words {
        [] => String::new(),
        [one] => one.to_string(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::{error_text, minimal_with, read, MINIMAL};
    use super::*;
    use crate::problem::resolve;

    /// MINIMAL with a `[wind]` section of `keys`.
    /// A minimal file with `[wind]` `keys` and, after them, one projected area at the
    /// reference height 10 m for the wind to load.
    fn with_wind(keys: &str) -> String {
        minimal_with(&format!(
            "[wind]\n{keys}\n\n[platform.wind]\nheight = 10.0\n[[platform.wind.areas]]\n\
             x = 0.0\ny = 0.0\nheight = 10.0\narea_x = 100.0\narea_y = 100.0\n\
             shape_coefficient = 1.0"
        ))
    }

    /// The 1-based line of `key` in the `[wind]` section of `text`.
    fn key_line(text: &str, key: &str) -> usize {
        let section = text.find("[wind]").expect("a wind section");
        let before = text[..section].lines().count();
        before
            + text[section..]
                .lines()
                .position(|l| l.starts_with(key))
                .expect("key present")
            + 1
    }

    /// The error of checking the problem of `text` (read, resolved, checked).
    fn check_error(text: &str) -> String {
        let scenario = read(text).expect("the file reads");
        let problem = resolve(&scenario).expect("resolves");
        problem.check().expect_err("must be refused").to_string()
    }

    #[test]
    fn a_wind_section_is_read_in_si_units_and_radians() {
        let text = with_wind(
            "speed = 25.0\ndirection_deg = 30.0\nreference_height = 20.0\n\
             averaging_period = 600.0\nprofile = \"power-law\"\nprofile_exponent = 0.11\n\
             spectrum = \"kaimal\"\nturbulence_intensity = 0.1\nlength_scale = 340.0\n\
             air_density = 1.2",
        );
        let wind = read(&text).expect("valid").wind;
        assert_eq!(
            wind,
            WindField {
                speed: 25.0,
                direction: 30f64.to_radians(),
                reference_height: 20.0,
                averaging_period: 600.0,
                profile: WindProfile::PowerLaw { exponent: 0.11 },
                spectrum: WindSpectrumKind::Kaimal,
                drag_coefficient: DEFAULT_DRAG_COEFFICIENT,
                turbulence_intensity: Some(0.1),
                length_scale: Some(340.0),
                air_density: 1.2,
                source: WindSource::Records,
            }
        );
        let text = with_wind("speed = 20\nspectrum = \"harris\"\ndrag_coefficient = 0.0025");
        let harris = read(&text).expect("valid").wind;
        assert_eq!(harris.drag_coefficient, 0.0025);
        assert_eq!(harris.spectrum, WindSpectrumKind::Harris);
    }

    /// No section, or an empty one, is no wind; a speed alone takes the NPD profile and
    /// spectrum, the 1-hour mean at 10 m; each profile's parameter its documented default.
    #[test]
    fn absent_keys_take_their_documented_defaults() {
        assert_eq!(read(MINIMAL).unwrap().wind, WindField::default());
        let empty = read(&with_wind("")).unwrap().wind;
        assert_eq!(empty, WindField::default());
        assert!(empty.is_calm());
        let speed = read(&with_wind("speed = 15.0")).unwrap().wind;
        assert_eq!(
            speed,
            WindField {
                speed: 15.0,
                ..WindField::default()
            }
        );
        assert_eq!(
            (speed.reference_height, speed.averaging_period),
            (10.0, 3600.0)
        );
        assert_eq!(
            (speed.profile, speed.spectrum),
            (WindProfile::Npd, WindSpectrumKind::Npd)
        );
        assert_eq!(speed.air_density, 1.225);
        assert_eq!(speed.drag_coefficient, 0.002);
        let law = read(&with_wind("speed = 15.0\nprofile = \"power-law\""))
            .unwrap()
            .wind;
        assert_eq!(law.profile, WindProfile::PowerLaw { exponent: 0.12 });
        let log = read(&with_wind("speed = 15.0\nprofile = \"logarithmic\""))
            .unwrap()
            .wind;
        assert_eq!(log.profile, WindProfile::Logarithmic { roughness: 0.001 });
    }

    /// `source = "input"` is read; a speed beside it (unused: the input is the speed) is
    /// refused on its line, and so is an input on a platform without wind coefficients.
    #[test]
    fn an_input_wind_takes_no_speed_and_needs_coefficients() {
        let text = with_wind("source = \"input\"\ndirection_deg = 90");
        let wind = read(&text).unwrap().wind;
        assert_eq!(wind.source, WindSource::Input);
        assert!(!wind.is_calm() && !wind.has_gusts());
        let problem = resolve(&read(&text).unwrap()).unwrap();
        problem
            .check()
            .expect("an input wind on the platform's coefficients");
        let text = with_wind("speed = 20\nsource = \"input\"");
        let line = key_line(&text, "speed");
        assert_eq!(
            check_error(&text),
            format!(
                "test.toml:{line}: invalid [wind] speed = 20: is not used when wind.source = \
                 \"input\" (the speed comes from the FMU's input windVelocity_ext): set it to \
                 0, or the source to \"records\""
            )
        );
        let text = minimal_with("[wind]\nsource = \"input\"");
        let message = check_error(&text);
        assert!(
            message.contains("[wind] source = \"input\": needs the platform's wind coefficients"),
            "{message}"
        );
    }

    /// A key that the chosen spectrum or profile does not use is refused with its value and
    /// line, naming the choice and the ones that use it.
    #[test]
    fn a_key_of_another_spectrum_or_profile_is_refused_on_its_line() {
        let text = with_wind("speed = 20.0\nspectrum = \"kaimal\"\ndrag_coefficient = 0.003");
        let line = key_line(&text, "drag_coefficient");
        assert_eq!(
            error_text(&text),
            format!(
                "test.toml:{line}: invalid [wind] drag_coefficient = 0.003: does not apply \
                 when spectrum = \"kaimal\": only harris, davenport and ochi-shin use it"
            )
        );
        let text = with_wind("speed = 20.0\nlength_scale = 300");
        let line = key_line(&text, "length_scale");
        assert_eq!(
            error_text(&text),
            format!(
                "test.toml:{line}: invalid [wind] length_scale = 300: does not apply when \
                 spectrum is \"npd\" (the default): only kaimal uses it"
            )
        );
        let text = with_wind("spectrum = \"harris\"\nturbulence_intensity = 0.1");
        assert!(error_text(&text)
            .contains("turbulence_intensity = 0.1: does not apply when spectrum = \"harris\": only api and kaimal use it"));
        let text = with_wind("profile = \"logarithmic\"\nprofile_exponent = 0.1");
        let line = key_line(&text, "profile_exponent");
        assert_eq!(
            error_text(&text),
            format!(
                "test.toml:{line}: invalid [wind] profile_exponent = 0.1: does not apply when \
                 profile = \"logarithmic\": only profile = \"power-law\" uses it"
            )
        );
        let text = with_wind("roughness_length = 0.002");
        assert!(error_text(&text).contains(
            "invalid [wind] roughness_length = 0.002: does not apply when profile is \"npd\" \
             (the default): only profile = \"logarithmic\" uses it"
        ));
    }

    /// An unknown key, a wrong type and an unknown word are refused on their line.
    #[test]
    fn unknown_keys_types_and_words_are_refused_on_their_line() {
        let text = with_wind("speed = 20.0\nheight = 50.0");
        let err = error_text(&text);
        let line = key_line(&text, "height");
        assert!(
            err.starts_with(&format!("test.toml:{line}: unknown field `height`")),
            "{err}"
        );
        let text = with_wind("speed = \"strong\"");
        let line = key_line(&text, "speed");
        assert_eq!(
            error_text(&text),
            format!("test.toml:{line}: invalid type: string \"strong\", expected a number")
        );
        let text = with_wind("spectrum = \"von-karman\"");
        let line = key_line(&text, "spectrum");
        let err = error_text(&text);
        assert!(
            err.starts_with(&format!("test.toml:{line}: unknown variant `von-karman`"))
                && err.contains("`ochi-shin`"),
            "{err}"
        );
    }

    /// A value the wind cannot have is refused when the problem is checked, naming the key
    /// as the file writes it, its value (in the file's units) and its line.
    #[test]
    fn a_bad_value_is_named_with_its_key_value_and_line() {
        for (keys, key, shown) in [
            ("speed = -5.0", "speed", "-5"),
            (
                "speed = 20.0\nreference_height = 0.0",
                "reference_height",
                "0",
            ),
            (
                "speed = 20.0\naveraging_period = -600",
                "averaging_period",
                "-600",
            ),
            ("speed = 20.0\ndirection_deg = 400", "direction_deg", "400"),
            ("air_density = 0", "air_density", "0"),
            (
                "speed = 20.0\nprofile = \"power-law\"\nprofile_exponent = 1.5",
                "profile_exponent",
                "1.5",
            ),
            (
                "speed = 20.0\nprofile = \"logarithmic\"\nroughness_length = -0.1",
                "roughness_length",
                "-0.1",
            ),
            (
                "speed = 20.0\nspectrum = \"davenport\"\ndrag_coefficient = 0.5",
                "drag_coefficient",
                "0.5",
            ),
            (
                "speed = 20.0\nspectrum = \"api\"\nturbulence_intensity = 2",
                "turbulence_intensity",
                "2",
            ),
            (
                "speed = 20.0\nspectrum = \"kaimal\"\naveraging_period = 600\n\
                 length_scale = 0",
                "length_scale",
                "0",
            ),
        ] {
            let text = with_wind(keys);
            let line = key_line(&text, key);
            let err = check_error(&text);
            assert!(
                err.starts_with(&format!(
                    "test.toml:{line}: invalid [wind] {key} = {shown}: "
                )),
                "{keys}: {err}"
            );
        }
    }

    /// A speed over another averaging period than the spectrum's is refused before a run
    /// when the profile cannot convert it, naming the setting written last: the period,
    /// or the spectrum when the period is left at its default.
    #[test]
    fn a_period_the_spectrum_does_not_take_is_refused_before_a_run() {
        let text = with_wind(
            "speed = 20.0\nprofile = \"power-law\"\naveraging_period = 3600\n\
             spectrum = \"harris\"",
        );
        let line = key_line(&text, "averaging_period");
        let err = check_error(&text);
        assert!(
            err.starts_with(&format!(
                "test.toml:{line}: invalid [wind] averaging_period = 3600: the harris \
                 spectrum is defined for the 600 s mean"
            )),
            "{err}"
        );
        let text = with_wind("speed = 20.0\nprofile = \"power-law\"\nspectrum = \"kaimal\"");
        let line = key_line(&text, "spectrum");
        let err = check_error(&text);
        assert!(
            err.starts_with(&format!(
                "test.toml:{line}: invalid [wind] spectrum = kaimal: the kaimal spectrum is \
                 defined for the 600 s mean"
            )),
            "{err}"
        );
        // The NPD profile converts: the same speed and spectrum are taken.
        let text = with_wind("speed = 20.0\nspectrum = \"kaimal\"");
        let problem = resolve(&read(&text).unwrap()).unwrap();
        problem
            .check()
            .expect("the NPD profile converts the 1-hour mean");
        // Calm: nothing of the spectrum is made.
        let text = with_wind("profile = \"power-law\"\nspectrum = \"harris\"");
        let problem = resolve(&read(&text).unwrap()).unwrap();
        problem.check().expect("no wind, no spectrum");
    }
}
