//! The one table of settings that can be written over a configuration: by the FMU's
//! parameters, and by the columns of a Monte Carlo case table. Each [`Setting`] has one
//! name (its configuration-file key path, `sea.hs`), the FMU variable and the case-table
//! column that write it, and one rule, the same wherever it is written.
//!
//! Rules, for every setting:
//! - **An override changes only what it names.** `hs` changes the significant wave height of
//!   the spectrum the configuration has (JONSWAP or Pierson-Moskowitz), and nothing else;
//!   `spreading_exponent` changes the exponent of the spreading form it has (cos^N or cos-2s).
//! - **A setting that applies only under a choice** (`gamma` under JONSWAP, `cd` under drag =
//!   combined, `cd_slow` and `cd_fast` under drag = separate, `hs` and `tp` under a parametric
//!   spectrum) is refused when the scenario makes another choice: [`Refusal::NotInForce`].
//!   A case table reports it; the FMU, whose parameters always have a value, leaves such a
//!   parameter unapplied.
//! - **Units**: SI and radians. A key whose name ends in `_deg` is in degrees in the
//!   configuration file and the case table, and its FMU variable in radians (its declared
//!   unit); the table's values ([`Value::Number`]) are SI and radians.
//! - **Order**: the table is applied in its order, modes before what depends on them
//!   (`drag` before `cd`, `spreading_exponent` before `n_directions`).
//! - **Modes in the FMU**: a setting of words (a mode: `model.drag`) is an FMU Integer whose
//!   value is the word's code, its position in [`Setting::words`] (`dragModel` 0 off,
//!   1 separate, 2 combined): every master can set an Integer, where libcosim and ecos skip
//!   Enumerations. The words and codes are the mode's one definition (`model/modes.rs`,
//!   [`Mode`]); build.rs checks that the XML's min, max and description list exactly them.
//!
//! Adding a setting is one entry here (and its FMU variable in modelDescription.xml).

use super::{Current, ModelOptions, Platform, Run, Scenario, Written, DEFAULT_N_DIRECTIONS};
use crate::error::numbers::written;
use crate::model::{
    DragKind, DragModel, DriftDamping, Interaction, Mode, SpectrumKind, Vocabulary,
    WaveFrequencyMotion, WindSource, WindSpectrumKind, YawFollowing,
};
use crate::sea_state::SeaState;
use crate::sea_state::{Spectrum, Spreading};
use crate::wind::WindField;

/// A value written for a setting.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value<'a> {
    /// A number, SI units and radians.
    Number(f64),
    /// A word of the setting's mode ([`Setting::words`]).
    Word(&'a str),
}

/// Why a value was not applied.
#[derive(Debug, Clone, PartialEq)]
pub enum Refusal {
    /// The setting applies only under a choice the scenario does not make; the reason says
    /// which.
    NotInForce(String),
    /// The setting does not take this value; the reason says why.
    Invalid(String),
}

impl Refusal {
    /// The reason, for a message.
    pub fn reason(&self) -> &str {
        match self {
            Refusal::NotInForce(why) | Refusal::Invalid(why) => why,
        }
    }
}

type Applied = Result<(), Refusal>;

/// 2^53: every whole number up to it is exact in an f64 (the value type of the table).
const LARGEST_EXACT_WHOLE: f64 = 9_007_199_254_740_992.0;

/// The parts of a scenario that settings write (never its hydrodynamics).
pub struct Parts<'a> {
    pub sea: &'a mut SeaState,
    pub current: &'a mut Current,
    pub wind: &'a mut WindField,
    pub run: &'a mut Run,
    pub platform: &'a mut Platform,
    pub model: &'a mut ModelOptions,
}

/// The same parts, to read.
pub struct View<'a> {
    pub sea: &'a SeaState,
    pub current: &'a Current,
    pub wind: &'a WindField,
    pub run: &'a Run,
    pub platform: &'a Platform,
    pub model: &'a ModelOptions,
}

/// One setting of the table.
pub struct Setting {
    /// The configuration-file key path, the setting's name (`sea.hs`).
    pub key: &'static str,
    /// The FMU parameter that writes it, if any (a mode's is its definition's).
    pub fmu: Option<&'static str>,
    /// The case-table column that writes it, if any.
    pub column: Option<&'static str>,
    /// The mode it sets, for a setting of words (`None` for a number).
    pub mode: Option<&'static Vocabulary>,
    /// What it means, with its unit (for documentation and help).
    pub meaning: &'static str,
    apply: fn(Parts, Value) -> Applied,
    get: fn(View) -> Value<'static>,
}

impl std::fmt::Debug for Setting {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Setting({})", self.key)
    }
}

impl Setting {
    /// Writes `value` into `scenario` and records where it was written.
    pub fn apply<H>(&self, scenario: &mut Scenario<H>, value: Value, written: Written) -> Applied {
        if let Value::Word(word) = value {
            if !self.words().any(|w| w == word) {
                return Err(Refusal::Invalid(format!(
                    "'{word}' is not one of {}",
                    self.words().collect::<Vec<_>>().join(", ")
                )));
            }
        }
        let parts = Parts {
            sea: &mut scenario.sea,
            current: &mut scenario.current,
            wind: &mut scenario.wind,
            run: &mut scenario.run,
            platform: &mut scenario.platform,
            model: &mut scenario.model,
        };
        (self.apply)(parts, value)?;
        scenario.origins.record(self.key, written);
        Ok(())
    }

    /// The value the scenario has (what writing it would keep).
    pub fn get<H>(&self, scenario: &Scenario<H>) -> Value<'static> {
        (self.get)(View {
            sea: &scenario.sea,
            current: &scenario.current,
            wind: &scenario.wind,
            run: &scenario.run,
            platform: &scenario.platform,
            model: &scenario.model,
        })
    }

    /// Whether the setting takes words rather than numbers.
    pub fn takes_words(&self) -> bool {
        self.mode.is_some()
    }

    /// The words it takes, in the order of their FMU codes (none for a number): its mode's,
    /// after the word that keeps the configuration's choice where there is one
    /// ([`Vocabulary::codes`]).
    pub fn words(&self) -> impl Iterator<Item = &'static str> {
        self.mode.into_iter().flat_map(Vocabulary::codes)
    }

    /// The FMU code of `word`: its position in [`Setting::words`].
    pub fn code_of(&self, word: &str) -> Option<i32> {
        let position = self.words().position(|w| w == word)?;
        i32::try_from(position).ok()
    }

    /// The word of FMU code `code`, or why there is none (the codes it takes, listed).
    pub fn word_of(&self, code: i32) -> Result<&'static str, Refusal> {
        usize::try_from(code)
            .ok()
            .and_then(|i| self.words().nth(i))
            .ok_or_else(|| {
                let codes: Vec<String> = self
                    .words()
                    .enumerate()
                    .map(|(i, w)| format!("{i} ({w})"))
                    .collect();
                Refusal::Invalid(format!("must be one of {}", codes.join(", ")))
            })
    }

    /// Whether its key is in degrees in the file and the case table (the FMU's is radians).
    pub fn in_degrees(&self) -> bool {
        self.key.contains("_deg")
    }
}

/// The setting with FMU parameter `name`.
pub fn by_fmu(name: &str) -> Option<&'static Setting> {
    SETTINGS.iter().find(|s| s.fmu == Some(name))
}

/// The setting with configuration-file key `key`.
pub fn by_key(key: &str) -> Option<&'static Setting> {
    SETTINGS.iter().find(|s| s.key == key)
}

/// The setting of case-table column `name`.
pub fn by_column(name: &str) -> Option<&'static Setting> {
    SETTINGS.iter().find(|s| s.column == Some(name))
}

fn number(value: Value) -> Result<f64, Refusal> {
    match value {
        Value::Number(x) => Ok(x),
        Value::Word(w) => Err(Refusal::Invalid(format!("'{w}' is not a number"))),
    }
}

/// The mode a word chooses; `None` for the word that keeps the configuration's choice.
fn chosen<M: Mode>(value: Value) -> Result<Option<M>, Refusal> {
    let word = match value {
        Value::Word(w) => w,
        Value::Number(x) => return Err(Refusal::Invalid(format!("{} is not a word", written(x)))),
    };
    if M::VOCABULARY.keep() == Some(word) {
        return Ok(None);
    }
    M::from_word(word).map(Some).ok_or_else(|| {
        Refusal::Invalid(format!(
            "'{word}' is not one of {}",
            M::VOCABULARY.words.join(", ")
        ))
    })
}

/// A whole number of at least `min`.
fn whole(value: Value, min: i64) -> Result<i64, Refusal> {
    let x = number(value)?;
    if x.fract() == 0.0 && x >= min as f64 && x <= i32::MAX as f64 {
        Ok(x as i64)
    } else {
        Err(Refusal::Invalid(format!(
            "{} is not a whole number of at least {min}",
            written(x)
        )))
    }
}

fn not_in_force(what: &str, needs: &str, has: &str) -> Refusal {
    Refusal::NotInForce(format!(
        "{what} applies when {needs}; this scenario has {has}"
    ))
}

/// A spectrum, as the file writes it: `spectrum = "jonswap"`.
fn spectrum_is(kind: SpectrumKind) -> String {
    format!("spectrum = \"{}\"", kind.word())
}

/// A drag model, as messages name it: `drag = combined`.
fn drag_is(kind: DragKind) -> String {
    format!("drag = {}", kind.word())
}

/// The table, in the order it is applied.
pub static SETTINGS: [Setting; 29] = [
    Setting {
        key: "sea.spreading_exponent",
        fmu: Some("spreadingExponent"),
        column: Some("spreading_exponent"),
        mode: None,
        meaning: "0 = long-crested; else the exponent of the configuration's spreading form \
                  (N of cos^N, s of cos-2s; a long-crested sea becomes cos^N with 15 directions)",
        apply: |mut s, v| {
            let x = number(v)?;
            if x < 0.0 || !x.is_finite() {
                return Err(Refusal::Invalid(format!(
                    "{} is not 0 or a positive exponent",
                    written(x)
                )));
            }
            let sea = &mut s.sea;
            sea.spreading = match sea.spreading {
                _ if x == 0.0 => {
                    sea.n_directions = 1;
                    Spreading::LongCrested
                }
                Spreading::Cos2s { .. } => Spreading::Cos2s { s: x },
                Spreading::CosN { .. } => Spreading::CosN { n: x },
                Spreading::LongCrested => {
                    if sea.n_directions <= 1 {
                        sea.n_directions = DEFAULT_N_DIRECTIONS;
                    }
                    Spreading::CosN { n: x }
                }
            };
            Ok(())
        },
        get: |s| {
            Value::Number(match s.sea.spreading {
                Spreading::LongCrested => 0.0,
                Spreading::CosN { n } => n,
                Spreading::Cos2s { s } => s,
            })
        },
    },
    Setting {
        key: "sea.n_directions",
        fmu: Some("nDirections"),
        column: Some("n_directions"),
        mode: None,
        meaning: "number of discrete directions of a spread sea (1 for a long-crested sea)",
        apply: |s, v| {
            let n = whole(v, 1)? as usize;
            if s.sea.spreading == Spreading::LongCrested && n != 1 {
                return Err(not_in_force(
                    "n_directions > 1",
                    "the sea is spread (spreading_exponent > 0)",
                    "a long-crested sea",
                ));
            }
            s.sea.n_directions = n;
            Ok(())
        },
        get: |s| Value::Number(s.sea.n_directions as f64),
    },
    Setting {
        key: "sea.hs",
        fmu: Some("Hs"),
        column: Some("hs"),
        mode: None,
        meaning: "significant wave height of the JONSWAP or Pierson-Moskowitz spectrum, m",
        apply: |s, v| {
            let x = number(v)?;
            match &mut s.sea.spectrum {
                Spectrum::Jonswap { hs, .. } | Spectrum::PiersonMoskowitz { hs, .. } => *hs = x,
                other => {
                    return Err(not_in_force(
                        "hs",
                        "the spectrum is parametric",
                        &spectrum_is(other.kind()),
                    ))
                }
            }
            Ok(())
        },
        get: |s| match s.sea.spectrum {
            Spectrum::Jonswap { hs, .. } | Spectrum::PiersonMoskowitz { hs, .. } => {
                Value::Number(hs)
            }
            Spectrum::Tabulated { .. } => Value::Number(f64::NAN),
        },
    },
    Setting {
        key: "sea.tp",
        fmu: Some("Tp"),
        column: Some("tp"),
        mode: None,
        meaning: "peak period of the JONSWAP or Pierson-Moskowitz spectrum, s",
        apply: |s, v| {
            let x = number(v)?;
            match &mut s.sea.spectrum {
                Spectrum::Jonswap { tp, .. } | Spectrum::PiersonMoskowitz { tp, .. } => *tp = x,
                other => {
                    return Err(not_in_force(
                        "tp",
                        "the spectrum is parametric",
                        &spectrum_is(other.kind()),
                    ))
                }
            }
            Ok(())
        },
        get: |s| match s.sea.spectrum {
            Spectrum::Jonswap { tp, .. } | Spectrum::PiersonMoskowitz { tp, .. } => {
                Value::Number(tp)
            }
            Spectrum::Tabulated { .. } => Value::Number(f64::NAN),
        },
    },
    Setting {
        key: "sea.gamma",
        fmu: Some("gamma"),
        column: Some("gamma"),
        mode: None,
        meaning: "JONSWAP peak enhancement factor; 0 = the DNV-RP-C205 default from Hs and Tp \
                  (the only value for a Pierson-Moskowitz spectrum)",
        apply: |s, v| {
            let x = number(v)?;
            match &mut s.sea.spectrum {
                Spectrum::Jonswap { gamma, .. } => *gamma = (x != 0.0).then_some(x),
                Spectrum::PiersonMoskowitz { .. } if x == 0.0 => {}
                other => {
                    return Err(not_in_force(
                        "gamma",
                        &spectrum_is(SpectrumKind::Jonswap),
                        &spectrum_is(other.kind()),
                    ))
                }
            }
            Ok(())
        },
        get: |s| match s.sea.spectrum {
            Spectrum::Jonswap { gamma, .. } => Value::Number(gamma.unwrap_or(0.0)),
            _ => Value::Number(0.0),
        },
    },
    Setting {
        key: "sea.direction_deg",
        fmu: Some("waveDirection"),
        column: Some("direction_deg"),
        mode: None,
        meaning: "mean direction of propagation, from +X counter-clockwise (deg in the file \
                  and case table, rad in the FMU)",
        apply: |s, v| {
            s.sea.mean_direction = number(v)?;
            Ok(())
        },
        get: |s| Value::Number(s.sea.mean_direction),
    },
    Setting {
        key: "sea.seed",
        fmu: Some("seed"),
        column: None,
        mode: None,
        meaning: "seed of the random wave amplitudes (Monte Carlo campaigns set it per run)",
        apply: |s, v| {
            let x = number(v)?;
            if x.fract() != 0.0 || !(0.0..=LARGEST_EXACT_WHOLE).contains(&x) {
                return Err(Refusal::Invalid(format!(
                    "{} is not a whole number of at least 0 (must not be negative)",
                    written(x)
                )));
            }
            s.sea.seed = x as u64;
            Ok(())
        },
        get: |s| Value::Number(s.sea.seed as f64),
    },
    Setting {
        key: "current.speed",
        fmu: Some("currentSpeed"),
        column: Some("current_speed"),
        mode: None,
        meaning: "speed of the steady, depth-uniform current, m/s",
        apply: |s, v| {
            s.current.speed = number(v)?;
            Ok(())
        },
        get: |s| Value::Number(s.current.speed),
    },
    Setting {
        key: "current.direction_deg",
        fmu: Some("currentDirection"),
        column: Some("current_direction_deg"),
        mode: None,
        meaning: "direction the current flows towards, from +X counter-clockwise (deg in the \
                  file and case table, rad in the FMU)",
        apply: |s, v| {
            s.current.direction = number(v)?;
            Ok(())
        },
        get: |s| Value::Number(s.current.direction),
    },
    Setting {
        key: "wind.speed",
        fmu: Some("windSpeed"),
        column: Some("wind_speed"),
        mode: None,
        meaning: "mean wind speed at the reference height over the averaging period, m/s \
                  (0 = no wind)",
        apply: |s, v| {
            s.wind.speed = number(v)?;
            Ok(())
        },
        get: |s| Value::Number(s.wind.speed),
    },
    Setting {
        key: "wind.direction_deg",
        fmu: Some("windDirection"),
        column: Some("wind_direction_deg"),
        mode: None,
        meaning: "direction the wind blows towards, from +X counter-clockwise (deg in the file \
                  and case table, rad in the FMU)",
        apply: |s, v| {
            s.wind.direction = number(v)?;
            Ok(())
        },
        get: |s| Value::Number(s.wind.direction),
    },
    Setting {
        key: "wind.spectrum",
        fmu: WindSpectrumKind::VOCABULARY.parameter(),
        column: Some("wind_spectrum"),
        mode: Some(&WindSpectrumKind::VOCABULARY),
        meaning: "gust spectrum: configuration (keep), npd, api, harris, davenport, kaimal, \
                  ochi-shin or constant; \
                  the configuration's drag_coefficient, turbulence_intensity and length_scale \
                  stay, used where the spectrum uses them",
        apply: |s, v| {
            if let Some(spectrum) = chosen(v)? {
                s.wind.spectrum = spectrum;
            }
            Ok(())
        },
        get: |s| Value::Word(s.wind.spectrum.word()),
    },
    Setting {
        key: "wind.reference_height",
        fmu: Some("windReferenceHeight"),
        column: Some("wind_reference_height"),
        mode: None,
        meaning: "height of the wind speed above the still water level, m",
        apply: |s, v| {
            s.wind.reference_height = number(v)?;
            Ok(())
        },
        get: |s| Value::Number(s.wind.reference_height),
    },
    Setting {
        key: "wind.source",
        fmu: WindSource::VOCABULARY.parameter(),
        column: None,
        mode: Some(&WindSource::VOCABULARY),
        meaning: "where the wind speed at the force's height comes from: records (the mean \
                  speed with its gusts) or input (the FMU's input windVelocity_ext; the speed \
                  then 0)",
        apply: |s, v| {
            if let Some(source) = chosen(v)? {
                s.wind.source = source;
            }
            Ok(())
        },
        get: |s| Value::Word(s.wind.source.word()),
    },
    Setting {
        key: "model.drag",
        fmu: DragKind::VOCABULARY.parameter(),
        column: Some("drag"),
        mode: Some(&DragKind::VOCABULARY),
        meaning: "Morison drag model: off, separate (cd_slow, cd_fast; E&S 8) or combined (cd; \
                  E&S 9); a model chosen here needs its coefficients written too",
        apply: |s, v| {
            let drag = &mut s.model.drag;
            match chosen::<DragKind>(v)? {
                Some(kind) if kind != drag.kind() => {
                    // A model chosen here has no coefficients yet (NaN: not written).
                    *drag = match kind {
                        DragKind::Off => DragModel::Off,
                        DragKind::Separate => DragModel::Separate {
                            slow: f64::NAN,
                            fast: f64::NAN,
                        },
                        DragKind::Combined => DragModel::Combined { cd: f64::NAN },
                    }
                }
                _ => {}
            }
            Ok(())
        },
        get: |s| Value::Word(s.model.drag.kind().word()),
    },
    Setting {
        key: "model.cd",
        fmu: Some("cd"),
        column: Some("cd"),
        mode: None,
        meaning: "drag coefficient of the combined model (drag = combined)",
        apply: |s, v| {
            let x = number(v)?;
            match &mut s.model.drag {
                DragModel::Combined { cd } => *cd = x,
                other => {
                    return Err(not_in_force(
                        "cd",
                        &drag_is(DragKind::Combined),
                        &drag_is(other.kind()),
                    ))
                }
            }
            Ok(())
        },
        get: |s| match s.model.drag {
            DragModel::Combined { cd } => Value::Number(cd),
            _ => Value::Number(f64::NAN),
        },
    },
    Setting {
        key: "model.cd_slow",
        fmu: Some("cdSlow"),
        column: Some("cd_slow"),
        mode: None,
        meaning: "slow-drift drag coefficient of the separate model (drag = separate)",
        apply: |s, v| {
            let x = number(v)?;
            match &mut s.model.drag {
                DragModel::Separate { slow, .. } => *slow = x,
                other => {
                    return Err(not_in_force(
                        "cd_slow",
                        &drag_is(DragKind::Separate),
                        &drag_is(other.kind()),
                    ))
                }
            }
            Ok(())
        },
        get: |s| match s.model.drag {
            DragModel::Separate { slow, .. } => Value::Number(slow),
            _ => Value::Number(f64::NAN),
        },
    },
    Setting {
        key: "model.cd_fast",
        fmu: Some("cdFast"),
        column: Some("cd_fast"),
        mode: None,
        meaning: "wave-frequency drag coefficient of the separate model (drag = separate)",
        apply: |s, v| {
            let x = number(v)?;
            match &mut s.model.drag {
                DragModel::Separate { fast, .. } => *fast = x,
                other => {
                    return Err(not_in_force(
                        "cd_fast",
                        &drag_is(DragKind::Separate),
                        &drag_is(other.kind()),
                    ))
                }
            }
            Ok(())
        },
        get: |s| match s.model.drag {
            DragModel::Separate { fast, .. } => Value::Number(fast),
            _ => Value::Number(f64::NAN),
        },
    },
    Setting {
        key: "model.drift_damping",
        fmu: DriftDamping::VOCABULARY.parameter(),
        column: Some("drift_damping"),
        mode: Some(&DriftDamping::VOCABULARY),
        meaning: "wave-drift damping: off, table (the drift table's b_ij) or aranha (Aranha's \
                  formula)",
        apply: |s, v| {
            if let Some(damping) = chosen(v)? {
                s.model.drift_damping = damping;
            }
            Ok(())
        },
        get: |s| Value::Word(s.model.drift_damping.word()),
    },
    Setting {
        key: "model.wave_frequency_motion",
        fmu: WaveFrequencyMotion::VOCABULARY.parameter(),
        column: Some("wave_frequency_motion"),
        mode: Some(&WaveFrequencyMotion::VOCABULARY),
        meaning: "the RAOs' wave-frequency motion on the slow drift (outputs only): on (where \
                  the platform has RAOs) or off",
        apply: |s, v| {
            if let Some(motion) = chosen(v)? {
                s.model.wave_frequency_motion = motion;
            }
            Ok(())
        },
        get: |s| Value::Word(s.model.wave_frequency_motion.word()),
    },
    Setting {
        key: "model.interaction",
        fmu: Interaction::VOCABULARY.parameter(),
        column: Some("interaction"),
        mode: Some(&Interaction::VOCABULARY),
        meaning: "cross-direction terms of a spread sea: configuration (keep), auto, \
                  bidirectional, mean-direction or none",
        apply: |s, v| {
            if let Some(interaction) = chosen(v)? {
                s.model.interaction = interaction;
            }
            Ok(())
        },
        get: |s| Value::Word(s.model.interaction.word()),
    },
    Setting {
        key: "model.yaw_following.headings",
        fmu: Some("yawFollowingHeadings"),
        column: Some("yaw_headings"),
        mode: None,
        meaning: "records that follow the yaw: -1 = off, 0 = keep the configuration's, n >= 2 = \
                  records at n body yaw angles (the configuration's range, else the full circle)",
        apply: |s, v| {
            let n = whole(v, -1)?;
            let yaw = &mut s.model.yaw_following;
            match n {
                -1 => *yaw = None,
                0 => {}
                1 => {
                    return Err(Refusal::Invalid(
                        "1 is not -1 (off), 0 (keep) or at least 2".into(),
                    ))
                }
                n => {
                    let range = yaw.as_ref().and_then(|y| y.range);
                    *yaw = Some(YawFollowing {
                        headings: n as usize,
                        range,
                    });
                }
            }
            Ok(())
        },
        get: |s| {
            Value::Number(
                s.model
                    .yaw_following
                    .as_ref()
                    .map_or(-1.0, |y| y.headings as f64),
            )
        },
    },
    Setting {
        key: "model.yaw_following.range_deg",
        fmu: Some("yawFollowingRange"),
        column: None,
        mode: None,
        meaning: "half-width of the covered yaw range about zero, rad (FMU); 0 = keep the \
                  configuration's range (the full circle for records turned on by headings)",
        apply: |s, v| {
            let half = number(v)?;
            if half == 0.0 {
                return Ok(());
            }
            if !(half.is_finite() && half > 0.0) {
                return Err(Refusal::Invalid(format!(
                    "{} is not 0 (keep) or a positive half-width",
                    written(half)
                )));
            }
            match &mut s.model.yaw_following {
                Some(y) => y.range = Some((-half, half)),
                None => {
                    return Err(not_in_force(
                        "a yaw-following range",
                        "yaw following is on",
                        "no yaw following",
                    ))
                }
            }
            Ok(())
        },
        get: |s| {
            Value::Number(match s.model.yaw_following.as_ref().and_then(|y| y.range) {
                Some((lo, hi)) if lo == -hi => hi,
                Some(_) => f64::NAN,
                None => 0.0,
            })
        },
    },
    Setting {
        key: "platform.stiffness[0][0]",
        fmu: Some("stiffnessSurge"),
        column: Some("surge_stiffness"),
        mode: None,
        meaning: "mooring stiffness C_11 in surge, N/m",
        apply: |s, v| {
            s.platform.stiffness[0][0] = number(v)?;
            Ok(())
        },
        get: |s| Value::Number(s.platform.stiffness[0][0]),
    },
    Setting {
        key: "platform.stiffness[1][1]",
        fmu: Some("stiffnessSway"),
        column: Some("sway_stiffness"),
        mode: None,
        meaning: "mooring stiffness C_22 in sway, N/m",
        apply: |s, v| {
            s.platform.stiffness[1][1] = number(v)?;
            Ok(())
        },
        get: |s| Value::Number(s.platform.stiffness[1][1]),
    },
    Setting {
        key: "platform.stiffness[2][2]",
        fmu: Some("stiffnessYaw"),
        column: Some("yaw_stiffness"),
        mode: None,
        meaning: "mooring stiffness C_66 in yaw, N m/rad",
        apply: |s, v| {
            s.platform.stiffness[2][2] = number(v)?;
            Ok(())
        },
        get: |s| Value::Number(s.platform.stiffness[2][2]),
    },
    Setting {
        key: "run.time_step",
        fmu: Some("stepSize"),
        column: Some("time_step"),
        mode: None,
        meaning: "RK4 step h, s (records are sampled at h/2)",
        apply: |s, v| {
            s.run.time_step = number(v)?;
            Ok(())
        },
        get: |s| Value::Number(s.run.time_step),
    },
    Setting {
        key: "run.duration",
        fmu: None,
        column: Some("duration"),
        mode: None,
        meaning: "simulated duration, s (the FMU's is stopTime - startTime)",
        apply: |s, v| {
            s.run.duration = number(v)?;
            Ok(())
        },
        get: |s| Value::Number(s.run.duration),
    },
    Setting {
        key: "run.memory_limit_gb",
        fmu: Some("memoryLimit"),
        column: None,
        mode: None,
        meaning: "memory the records may take, GB (1e9 bytes); larger estimates are refused",
        apply: |s, v| {
            let gb = number(v)?;
            if !(gb > 0.0 && gb <= super::limits::MAX_MEMORY_LIMIT_GB) {
                return Err(Refusal::Invalid(format!(
                    "must be a number of GB greater than zero and at most {} (a petabyte)",
                    crate::error::numbers::readable(super::limits::MAX_MEMORY_LIMIT_GB)
                )));
            }
            s.run.memory_limit = gb * crate::error::BYTES_PER_GB;
            Ok(())
        },
        get: |s| Value::Number(s.run.memory_limit / crate::error::BYTES_PER_GB),
    },
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::default::default_scenario;
    use crate::scenario::file::parse;
    use std::path::Path;

    /// Names are unique in each vocabulary, a key is a key path, and a mode's FMU parameter
    /// is the one its definition names.
    #[test]
    fn names_are_unique() {
        for (i, a) in SETTINGS.iter().enumerate() {
            for b in &SETTINGS[i + 1..] {
                assert_ne!(a.key, b.key);
                assert!(a.fmu.is_none() || a.fmu != b.fmu, "{}", a.key);
                assert!(a.column.is_none() || a.column != b.column, "{}", a.key);
            }
            assert!(a.key.contains('.'), "{}", a.key);
            if let Some(mode) = a.mode {
                assert_eq!(a.fmu, mode.parameter(), "{}: its mode's parameter", a.key);
            }
        }
    }

    /// A mode's FMU code is its word's position among [`Setting::words`] (`interaction`'s
    /// keep word first), both ways; a code beyond them has no word.
    #[test]
    fn codes_and_words_name_each_other() {
        for s in SETTINGS.iter().filter(|s| s.takes_words()) {
            let words: Vec<&str> = s.words().collect();
            for (code, word) in words.iter().enumerate() {
                assert_eq!(s.code_of(word), Some(code as i32), "{}", s.key);
                assert_eq!(s.word_of(code as i32), Ok(*word), "{}", s.key);
            }
            assert!(s.word_of(-1).is_err() && s.word_of(words.len() as i32).is_err());
        }
        let interaction = by_key("model.interaction").unwrap();
        assert_eq!(interaction.word_of(0), Ok("configuration"));
        assert_eq!(interaction.word_of(4), Ok("none"));
    }

    /// Writing a setting's value back keeps the scenario (get and apply agree), for every
    /// setting on the embedded default.
    #[test]
    fn writing_the_current_value_changes_nothing() {
        let base = default_scenario().unwrap();
        for setting in &SETTINGS {
            let mut s = base.clone();
            let v = setting.get(&s);
            let written = Written::Fmu {
                variable: "x",
                code: None,
            };
            match setting.apply(&mut s, v, written) {
                Ok(()) => assert_eq!(s, base, "{}", setting.key),
                Err(Refusal::NotInForce(_)) => {}
                Err(e) => panic!("{}: {e:?}", setting.key),
            }
        }
    }

    /// An override of a key gives the scenario that writing the key in the file gives: one
    /// name and one unit convention for the file and the table (degrees for `_deg` keys).
    #[test]
    fn an_override_equals_the_same_key_in_the_file() {
        let text = crate::scenario::default::DEFAULT_CONFIG_TOML;
        let base = default_scenario().unwrap();
        let edits: [(&str, &str, &str, Value); 4] = [
            ("sea", "hs = 7.0", "hs = 5.5", Value::Number(5.5)),
            (
                "sea",
                "direction_deg = 0.0",
                "direction_deg = 30.0",
                Value::Number(30f64.to_radians()),
            ),
            (
                "current",
                "direction_deg = 0.0",
                "direction_deg = 45.0",
                Value::Number(45f64.to_radians()),
            ),
            ("model", "cd = 0.6", "cd = 1.1", Value::Number(1.1)),
        ];
        for (section, old, new, value) in edits {
            let key = format!("{section}.{}", new.split(' ').next().unwrap());
            let setting = SETTINGS.iter().find(|s| s.key == key).unwrap();
            let header = format!("[{section}]");
            let at = text.find(&header).unwrap();
            let edited = format!("{}{}", &text[..at], text[at..].replacen(old, new, 1));
            assert_ne!(edited, text, "{key}");
            let from_file = parse(&edited, "edited.toml", Path::new(".")).unwrap();
            let mut from_override = base.clone();
            setting
                .apply(
                    &mut from_override,
                    value,
                    Written::Fmu {
                        variable: "x",
                        code: None,
                    },
                )
                .unwrap();
            assert_eq!(from_override, from_file, "{key}");
        }
    }

    /// The wind's settings give the scenario that the same keys of `[wind]` give: the
    /// direction in degrees in the file, radians in the table's values; the spectrum by its
    /// word, a word of another mode refused listing the spectra.
    #[test]
    fn wind_overrides_equal_the_wind_section() {
        let minimal = include_str!("../../tests/data/minimal.toml");
        let wind = "[wind]\nspeed = 12.0\ndirection_deg = 45.0\nspectrum = \"api\"\n\
                    reference_height = 20.0\n\n[drift]";
        let from_file = parse(&minimal.replace("[drift]", wind), "w.toml", Path::new(".")).unwrap();
        let mut from_override = parse(minimal, "m.toml", Path::new(".")).unwrap();
        assert_ne!(from_override, from_file);
        let at = || Written::Fmu {
            variable: "x",
            code: None,
        };
        for (key, value) in [
            ("wind.speed", Value::Number(12.0)),
            ("wind.direction_deg", Value::Number(45f64.to_radians())),
            ("wind.spectrum", Value::Word("api")),
            ("wind.reference_height", Value::Number(20.0)),
        ] {
            let setting = by_key(key).unwrap_or_else(|| panic!("{key}"));
            setting.apply(&mut from_override, value, at()).unwrap();
            assert_eq!(setting.get(&from_override), value, "{key}");
        }
        assert_eq!(from_override, from_file);
        assert_eq!(
            by_column("wind_direction_deg").unwrap().key,
            "wind.direction_deg"
        );
        assert!(by_key("wind.direction_deg").unwrap().in_degrees());
        assert!(matches!(
            by_key("wind.spectrum").unwrap().apply(&mut from_override, Value::Word("jonswap"), at()),
            Err(Refusal::Invalid(why)) if why.contains("npd, api, harris, davenport, kaimal, ochi-shin, constant")
        ));
    }

    #[test]
    fn a_setting_out_of_its_choice_is_not_in_force() {
        let mut s = default_scenario().unwrap();
        let at = || Written::Fmu {
            variable: "x",
            code: None,
        };
        let cd_slow = SETTINGS.iter().find(|s| s.key == "model.cd_slow").unwrap();
        assert!(matches!(
            cd_slow.apply(&mut s, Value::Number(0.5), at()),
            Err(Refusal::NotInForce(why)) if why.contains("drag = separate")
        ));
        let drag = SETTINGS.iter().find(|s| s.key == "model.drag").unwrap();
        drag.apply(&mut s, Value::Word("separate"), at()).unwrap();
        cd_slow.apply(&mut s, Value::Number(0.5), at()).unwrap();
        assert!(matches!(s.model.drag, DragModel::Separate { slow, .. } if slow == 0.5));
        assert!(matches!(
            drag.apply(&mut s, Value::Word("viscous"), at()),
            Err(Refusal::Invalid(why)) if why.contains("off, separate, combined")
        ));
        s.sea.spectrum = Spectrum::PiersonMoskowitz { hs: 2.0, tp: 8.0 };
        let hs = SETTINGS.iter().find(|s| s.key == "sea.hs").unwrap();
        hs.apply(&mut s, Value::Number(3.0), at()).unwrap();
        assert_eq!(
            s.sea.spectrum,
            Spectrum::PiersonMoskowitz { hs: 3.0, tp: 8.0 }
        );
    }
}
