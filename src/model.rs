//! The shared vocabulary of SlowDrift: the degrees of freedom, the water, the platform's
//! cylinders, and the modelling choices. Every other module may import this one; it imports
//! nothing of the crate.
//!
//! Conventions (docs/theory.md#conventions): SI units and radians; the body frame follows the slow
//! yaw; DOF order surge, sway, yaw.
//!
//! The modes (the settings that take one of a few words: `NewmanForm`, `SecondOrder`,
//! `Interaction`, `DriftDamping`, `DragKind`, ...) are defined once, in `model/modes.rs`:
//! each is an enum that implements [`Mode`] (its words, their FMU codes and descriptions)
//! and serde's `Deserialize` from its words.

use serde::de::{self, Deserializer, Visitor};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;
use std::fmt;
use std::marker::PhantomData;

/// Defines the modes of `model/modes.rs`: for each, the enum, its [`Mode`] implementation and
/// its `Deserialize` from its words (paths from inside `modes`, where it expands). build.rs
/// reads the same file with a `modes!` of its own.
macro_rules! modes {
    ($(
        $(#[$meta:meta])*
        $name:ident
        $(in $parameter:literal $(, keeping $keep:literal: $keep_description:literal)?)? {
            $($(#[$variant_meta:meta])* $variant:ident = $word:literal: $description:literal,)+
        }
    )*) => {$(
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
        pub enum $name {
            $($(#[$variant_meta])* $variant,)+
        }

        impl super::Mode for $name {
            const VOCABULARY: super::Vocabulary = super::Vocabulary {
                words: &[$($word),+],
                descriptions: &[$($description),+],
                fmu: modes!(@fmu $($parameter $(, $keep, $keep_description)?)?),
            };
            const ALL: &'static [Self] = &[$(Self::$variant),+];

            fn word(self) -> &'static str {
                match self {
                    $(Self::$variant => $word,)+
                }
            }
        }

        impl<'de> serde::Deserialize<'de> for $name {
            fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
                super::deserialize_word(deserializer)
            }
        }
    )*};
    (@fmu) => { None };
    (@fmu $parameter:literal) => {
        Some(super::FmuCodes { parameter: $parameter, keep: None })
    };
    (@fmu $parameter:literal, $keep:literal, $keep_description:literal) => {
        Some(super::FmuCodes { parameter: $parameter, keep: Some(($keep, $keep_description)) })
    };
}

/// The modes, each defined once (its words, FMU codes and descriptions): `modes.rs`.
mod modes;

pub use modes::{
    BidirectionalDrift, DragKind, DriftDamping, Interaction, NewmanForm, SecondOrder, SpectrumKind,
    SpreadingKind, WaveFrequencyMotion, WindProfileKind, WindSource, WindSpectrumKind,
};

/// A setting that takes one of a few words: an enum defined in `model/modes.rs`.
pub trait Mode: Copy + Eq + fmt::Debug + 'static {
    /// Its words, FMU codes and descriptions.
    const VOCABULARY: Vocabulary;
    /// Every value, in the order of [`Vocabulary::words`].
    const ALL: &'static [Self];

    /// Its word, as the configuration file, the case table and messages write it
    /// (`mean-direction`), never its `Debug` form.
    fn word(self) -> &'static str;

    /// The value `word` names, if any.
    fn from_word(word: &str) -> Option<Self> {
        Self::ALL.iter().copied().find(|mode| mode.word() == word)
    }
}

/// The words of a mode and how the FMU codes them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Vocabulary {
    /// The words, one per value, in the enum's order.
    pub words: &'static [&'static str],
    /// One line per word: what it chooses.
    pub descriptions: &'static [&'static str],
    /// The FMU Integer parameter that writes the mode, if any.
    pub fmu: Option<FmuCodes>,
}

/// How an FMU Integer parameter codes a mode: code 0 the word that keeps the configuration's
/// choice where there is one (`interaction`'s `configuration`), then the mode's words in
/// their order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FmuCodes {
    /// The parameter's name in modelDescription.xml (`dragModel`).
    pub parameter: &'static str,
    /// The word (and its description) that keeps the configuration's choice: not a mode's
    /// value, a word of the FMU parameter and the case table only.
    pub keep: Option<(&'static str, &'static str)>,
}

impl Vocabulary {
    /// The FMU parameter that writes the mode, if any.
    pub const fn parameter(&self) -> Option<&'static str> {
        match self.fmu {
            Some(codes) => Some(codes.parameter),
            None => None,
        }
    }

    /// The word that keeps the configuration's choice, if the mode has one.
    pub fn keep(&self) -> Option<&'static str> {
        self.fmu.and_then(|codes| codes.keep).map(|(word, _)| word)
    }

    /// The words an override takes, in the order of their FMU codes (a word's code is its
    /// position): the keep word first, where there is one, then the mode's words.
    pub fn codes(&self) -> impl Iterator<Item = &'static str> + '_ {
        self.keep().into_iter().chain(self.words.iter().copied())
    }
}

/// Reads a mode from its word; any other word is refused listing the words (``unknown
/// variant `viscous`, expected one of `off`, `separate`, `combined` ``), as serde's derive
/// would.
fn deserialize_word<'de, M: Mode, D: Deserializer<'de>>(deserializer: D) -> Result<M, D::Error> {
    struct Word<M>(PhantomData<M>);

    impl<M: Mode> Visitor<'_> for Word<M> {
        type Value = M;

        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            let quoted: Vec<String> = M::VOCABULARY
                .words
                .iter()
                .map(|word| format!("`{word}`"))
                .collect();
            write!(f, "one of {}", quoted.join(", "))
        }

        fn visit_str<E: de::Error>(self, word: &str) -> Result<M, E> {
            M::from_word(word).ok_or_else(|| E::unknown_variant(word, M::VOCABULARY.words))
        }
    }

    deserializer.deserialize_str(Word(PhantomData))
}

/// A slow-drift degree of freedom, in the order of every force and state array of the crate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Dof {
    Surge,
    Sway,
    Yaw,
}

impl Dof {
    /// Surge, sway, yaw: the order of the crate's force arrays.
    pub const ALL: [Dof; 3] = [Dof::Surge, Dof::Sway, Dof::Yaw];

    /// Its name in messages: `surge`, `sway`, `yaw`.
    pub fn name(self) -> &'static str {
        match self {
            Dof::Surge => "surge",
            Dof::Sway => "sway",
            Dof::Yaw => "yaw",
        }
    }
}

/// Headings of hydrodynamic data closer than this are the same heading, rad (0.01 deg: files
/// print headings in degrees with five significant digits). A wave direction of the sea
/// matches a data heading within it (the full QTF is never interpolated in heading).
pub const HEADING_MATCH_TOLERANCE: f64 = 0.01 * PI / 180.0;

/// Frequencies closer than this relative distance are the same frequency, and a band limit
/// this close beyond a data grid's first or last frequency is covered by it (the data's end
/// value is used there; nothing further is extrapolated). Frequencies of hydrodynamic files
/// are computed from printed periods, omega = 2 pi / PER: a period printed with five
/// significant digits is off by up to 5e-5 of itself, so the IEA-15 MW file's 2.5 rad/s comes
/// out as 2.4999... and a band to 2.5 must still be covered. 1e-4 is below the relative
/// step of every real frequency grid (0.05 rad/s at 3 rad/s is 1.7e-2).
pub const FREQUENCY_MATCH_TOLERANCE: f64 = 1e-4;

/// Physical constants of the water (docs/theory.md#conventions).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Environment {
    /// Acceleration of gravity, m/s^2.
    pub gravity: f64,
    /// Water density, kg/m^3.
    pub water_density: f64,
}

impl Default for Environment {
    fn default() -> Self {
        Environment {
            gravity: 9.80665,
            water_density: 1025.0,
        }
    }
}

/// A vertical circular cylinder of the platform (a "column" in the paper and the
/// configuration file): Morison drag strips (E&S 8, 9) and the column solvers. Body frame, m.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Cylinder {
    /// Centre, body frame x (forward), m.
    pub x: f64,
    /// Centre, body frame y (port), m.
    pub y: f64,
    /// Diameter, m.
    pub diameter: f64,
    /// Draft: the keel is at z = -draft, m.
    pub draft: f64,
}

/// Morison drag models of the paper (E&S 8, 9).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum DragModel {
    /// No viscous drag.
    Off,
    /// Separate slow and fast parts: C_DS U|U| + C_DL u|u| (E&S 8).
    Separate { slow: f64, fast: f64 },
    /// One coefficient on the total relative velocity: C_D (U + u)|U + u| (E&S 9).
    Combined { cd: f64 },
}

impl DragModel {
    /// Which of the models it is.
    pub fn kind(&self) -> DragKind {
        match self {
            DragModel::Off => DragKind::Off,
            DragModel::Separate { .. } => DragKind::Separate,
            DragModel::Combined { .. } => DragKind::Combined,
        }
    }
}

/// Records of the wave force and damping that follow the body's yaw
/// (docs/theory.md#the-slowly-varying-force): built at `headings` body yaw angles theta_j and
/// interpolated linearly in the instantaneous yaw at every RK4 stage.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct YawFollowing {
    /// Number of body yaw angles theta_j (at least 2).
    pub headings: usize,
    /// The covered yaw range [min, max], rad, with theta_j evenly spaced from min to max
    /// (both included); a yaw outside it is an error. `None` = the full circle: theta_j
    /// evenly spaced over [-pi, pi), 360 deg / headings apart, periodic (any yaw is covered).
    pub range: Option<(f64, f64)>,
}

/// Default `qtf_tolerance` of the modelling options (`scenario::ModelOptions`).
pub const DEFAULT_QTF_TOLERANCE: f64 = 1e-6;

#[cfg(test)]
mod tests {
    use super::*;

    /// A mode read from a TOML value, as the configuration file reads it.
    fn read<M: Mode + de::DeserializeOwned>(value: &str) -> Result<M, String> {
        #[derive(Deserialize)]
        struct Key<M> {
            mode: M,
        }
        toml::from_str::<Key<M>>(&format!("mode = {value}"))
            .map(|key| key.mode)
            .map_err(|e| e.message().to_string())
    }

    /// Every word of a mode reads back as its value, its vocabulary lists them in the
    /// enum's order with one description each, and no word is there twice.
    fn words_read_back<M: Mode + de::DeserializeOwned>() {
        let vocabulary = M::VOCABULARY;
        assert_eq!(vocabulary.words.len(), M::ALL.len());
        assert_eq!(vocabulary.descriptions.len(), M::ALL.len());
        for (mode, word) in M::ALL.iter().zip(vocabulary.words) {
            assert_eq!(mode.word(), *word);
            assert_eq!(M::from_word(word), Some(*mode));
            assert_eq!(read::<M>(&format!("\"{word}\"")), Ok(*mode));
        }
        let codes: Vec<&str> = vocabulary.codes().collect();
        for (i, word) in codes.iter().enumerate() {
            assert!(!codes[i + 1..].contains(word), "{word} twice");
        }
    }

    #[test]
    fn every_mode_reads_its_words() {
        words_read_back::<SpectrumKind>();
        words_read_back::<SpreadingKind>();
        words_read_back::<SecondOrder>();
        words_read_back::<NewmanForm>();
        words_read_back::<Interaction>();
        words_read_back::<DriftDamping>();
        words_read_back::<DragKind>();
        words_read_back::<BidirectionalDrift>();
        words_read_back::<WaveFrequencyMotion>();
        words_read_back::<WindSpectrumKind>();
        words_read_back::<WindProfileKind>();
        words_read_back::<WindSource>();
    }

    /// Another word, or a value that is no word, is refused listing the words.
    #[test]
    fn other_values_are_refused_listing_the_words() {
        assert_eq!(
            read::<DragKind>("\"viscous\""),
            Err("unknown variant `viscous`, expected one of `off`, `separate`, `combined`".into())
        );
        assert_eq!(
            read::<DragKind>("2"),
            Err("invalid type: integer `2`, expected one of `off`, `separate`, `combined`".into())
        );
        assert_eq!(
            read::<BidirectionalDrift>("\"own\""),
            Err("unknown variant `own`, expected `column-array`".into())
        );
    }

    /// The FMU codes a word by its position, after the word that keeps the configuration's
    /// choice where the mode has one.
    #[test]
    fn fmu_codes_put_the_keep_word_first() {
        let interaction = Interaction::VOCABULARY;
        assert_eq!(interaction.parameter(), Some("interaction"));
        assert_eq!(interaction.keep(), Some("configuration"));
        assert_eq!(
            interaction.codes().collect::<Vec<_>>(),
            [
                "configuration",
                "auto",
                "bidirectional",
                "mean-direction",
                "none"
            ]
        );
        assert_eq!(
            DragKind::VOCABULARY.codes().collect::<Vec<_>>(),
            ["off", "separate", "combined"]
        );
        assert_eq!(NewmanForm::VOCABULARY.parameter(), None);
        // The wind's spectrum keeps the configuration's at 0 (kaimal is 5); its profile has no
        // FMU parameter.
        let spectrum = WindSpectrumKind::VOCABULARY;
        assert_eq!(spectrum.parameter(), Some("windSpectrum"));
        assert_eq!(spectrum.codes().position(|w| w == "kaimal"), Some(5));
        assert_eq!(spectrum.codes().next(), spectrum.keep());
        assert_eq!(WindProfileKind::VOCABULARY.parameter(), None);
    }

    #[test]
    fn a_drag_model_names_its_kind() {
        assert_eq!(DragModel::Off.kind(), DragKind::Off);
        assert_eq!(
            DragModel::Separate {
                slow: 0.5,
                fast: 0.9
            }
            .kind(),
            DragKind::Separate
        );
        assert_eq!(DragModel::Combined { cd: 0.7 }.kind().word(), "combined");
    }
}
