//! The TOML configuration file: reads it into a [`Scenario`]. The format (its sections,
//! keys, units and defaults) is described once, in docs/configuration.md.
//!
//! This module reads the text and names errors by file and line ([`load`], [`parse`]); each
//! section is read by the file of what it describes: `sea` (`[environment]`, `[sea]`,
//! `[current]`), `wind` (`[wind]`), `platform` (`[platform]`, `[[platform.columns]]`), `run`
//! (`[run]`, `[initial]`), `model` (`[model]`) and `drift` (`[drift]`). Degrees become radians there,
//! once; modes are read from their words (`model::Mode`). The reader refuses what does not
//! fit the format (unknown keys, wrong types, keys that the section's choice does not use);
//! values are checked when the problem is (`problem::Problem::check`).

mod drift;
mod model;
mod platform;
mod run;
mod sea;
mod wind;

pub use run::DEFAULT_TIME_STEP;
pub use sea::{DEFAULT_SEED, LONG_CRESTED_DIRECTIONS};

use super::lines::LineIndex;
use super::{ModelOptions, Origins, Scenario};
use crate::error::{Error, Location, Result};
use crate::files::Cost;
use crate::model::Mode;
use serde::Deserialize;
use std::ops::Range;
use std::path::Path;
use toml::Spanned;

/// Why a hydrodynamic database (JSON) is not a configuration, and what to do with it.
pub const DATABASE_NOT_CONFIGURATION: &str = "this is a hydrodynamic database (JSON, as \
    `slowdrift hydro wamit` or `hydro nemoh` writes it), not a configuration (TOML): it has no \
    sea, mooring or run; name it in a configuration's [drift] section (source = \"database\", \
    file = \"NAME.json\") beside the platform's stiffness and sea, and give that \
    configuration instead (docs/configuration.md)";

/// What reading a configuration costs: the TOML reader holds up to 590 bytes of memory per
/// byte of the file (measured on its costliest content, chains of dotted keys whose every
/// key makes a table: `{a.b.c.d=0}`; an inline drift table of numbers takes 100), with a
/// margin for the allocator's own overhead.
pub const READING: Cost = Cost {
    format: "TOML configuration",
    per_byte: 900.0,
};

/// Reads the configuration file at `path` within `memory_limit` bytes (the limit given
/// outside the file: the FMU's `memoryLimit`, the CLI's `--memory-limit-gb`, else
/// [`crate::scenario::limits::DEFAULT_MEMORY_LIMIT`]; the file's own `run.memory_limit_gb`
/// is not known before it is read). A CSV or database file it names is looked up relative
/// to the directory of `path` (and read when the scenario is resolved, within the
/// scenario's limit).
pub fn load(path: &Path, memory_limit: f64) -> Result<Scenario> {
    load_named(path, &path.display().to_string(), memory_limit)
}

/// [`load`], with errors in the file naming it `origin` (the FMU's embedded configuration,
/// not the temporary folder a master unpacked it to).
pub fn load_named(path: &Path, origin: &str, memory_limit: f64) -> Result<Scenario> {
    let text = crate::files::read_text(path, &READING, memory_limit).map_err(|e| match e {
        Error::Io { message, .. } => Error::Io {
            path: origin.to_string(),
            message,
        },
        Error::FileOverBudget(mut excess) => {
            excess.path = origin.to_string();
            Error::FileOverBudget(excess)
        }
        other => other,
    })?;
    let base_dir = path.parent().unwrap_or_else(|| Path::new(""));
    parse(&text, origin, base_dir)
}

/// Parses configuration text. `origin` names the text in error messages (normally the file
/// name); a CSV or database file is looked up relative to `base_dir`. Values are checked when
/// the problem is (`problem::Problem::check`); this reader refuses what does not fit
/// the format: unknown keys, wrong types, keys that the section's choice does not use.
pub fn parse(text: &str, origin: &str, base_dir: &Path) -> Result<Scenario> {
    // A TOML document cannot start with '{'; a JSON object does: most likely the database
    // that `slowdrift hydro` writes, given where a configuration belongs.
    if text.trim_start().starts_with('{') {
        return Err(Error::Parse {
            path: origin.to_string(),
            line: Some(1),
            message: DATABASE_NOT_CONFIGURATION.to_string(),
        });
    }
    let lines = LineIndex::new(text);
    let file: ConfigFile = toml::from_str(text).map_err(|e| Error::Parse {
        path: origin.to_string(),
        line: e.span().map(|span| lines.line(span.start)),
        message: in_the_users_words(e.message(), e.span().and_then(|span| text.get(span))),
    })?;
    let origins = Origins::of_file(origin, text, &lines);
    let source = Source { lines, origin };
    file.into_scenario(&source, base_dir, origins)
}

/// The reader's message in the user's words: a float shown as the file writes it
/// (`written`, the text of the value it is about; serde shows every digit, `seed = 1e308`
/// as "floating point `1000...0.0`" with 309 digits), and the type expected named as a
/// number, not as Rust's type (`expected u64`).
fn in_the_users_words(message: &str, written: Option<&str>) -> String {
    const FLOAT: &str = "invalid type: floating point `";
    let shown = message
        .strip_prefix(FLOAT)
        .and_then(|rest| Some((rest.split_once('`')?.1, written?.trim())));
    let message = match shown {
        Some((rest, value)) if !value.is_empty() => format!("{FLOAT}{value}`{rest}"),
        _ => message.to_string(),
    };
    [
        ("u64", "a whole number, 0 or more"),
        ("usize", "a whole number, 0 or more"),
        ("u32", "a whole number, 0 or more"),
        ("i64", "a whole number"),
        ("f64", "a number"),
    ]
    .iter()
    .fold(message, |m, (rust, words)| {
        m.replace(&format!("expected {rust}"), &format!("expected {words}"))
    })
}

/// The configuration's lines and its name, to turn spans into `file:line` errors.
struct Source<'a> {
    lines: LineIndex,
    origin: &'a str,
}

impl Source<'_> {
    /// The line where `span` starts.
    fn location(&self, span: Range<usize>) -> Location {
        Location {
            path: self.origin.to_string(),
            line: Some(self.lines.line(span.start)),
        }
    }

    /// A parse error at the line where `span` starts.
    fn error_at(&self, span: Range<usize>, message: String) -> Error {
        Error::Parse {
            path: self.origin.to_string(),
            line: Some(self.lines.line(span.start)),
            message,
        }
    }
}

/// The value of a key that the section's choice requires.
fn required<T>(value: Option<T>, key: &str, because: &str) -> std::result::Result<T, String> {
    value.ok_or_else(|| format!("{key} is required when {because}"))
}

/// Refuses a key that the section's choice ignores, so that it is not silently dropped.
fn refused<T>(value: &Option<T>, key: &str, because: &str) -> std::result::Result<(), String> {
    match value {
        Some(_) => Err(format!("{key} does not apply when {because}")),
        None => Ok(()),
    }
}

/// A choice as the file writes it, for the reason of [`required`] and [`refused`]:
/// `spectrum = "jonswap"`.
fn chosen(key: &str, mode: impl Mode) -> String {
    format!("{key} = \"{}\"", mode.word())
}

/// The whole file.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ConfigFile {
    #[serde(default)]
    environment: sea::EnvironmentFile,
    sea: Spanned<sea::SeaFile>,
    #[serde(default)]
    current: sea::CurrentFile,
    #[serde(default)]
    wind: wind::WindFile,
    run: run::RunFile,
    platform: platform::PlatformFile,
    #[serde(default)]
    model: Option<Spanned<model::ModelFile>>,
    #[serde(default)]
    initial: run::InitialFile,
    drift: Spanned<drift::DriftFile>,
}

impl ConfigFile {
    fn into_scenario(self, source: &Source, base_dir: &Path, origins: Origins) -> Result<Scenario> {
        let sea_span = self.sea.span();
        let sea = self
            .sea
            .into_inner()
            .into_core()
            .map_err(|m| source.error_at(sea_span, format!("[sea] {m}")))?;
        let model = match self.model {
            Some(model) => {
                let span = model.span();
                model
                    .into_inner()
                    .into_core()
                    .map_err(|m| source.error_at(span, format!("[model] {m}")))?
            }
            None => ModelOptions::default(),
        };
        let drift_span = self.drift.span();
        let hydro = self
            .drift
            .into_inner()
            .into_source(source, drift_span, base_dir)
            .map_err(|e| origins.locate(e))?;
        Ok(Scenario {
            environment: self.environment.into_core(),
            sea,
            current: self.current.into_core(),
            wind: self.wind.into_core(&origins)?,
            run: self.run.into_core().map_err(|e| origins.locate(e))?,
            platform: self.platform.into_core(&origins)?,
            hydro,
            model,
            initial: self.initial.into_core(),
            origins,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hydro::{DriftRow, DriftTable};
    use crate::model::{
        Cylinder, DragModel, DriftDamping, Environment, Interaction, NewmanForm, SecondOrder,
    };
    use crate::scenario::DEFAULT_BLOCK_DURATION;
    use crate::scenario::{
        limits, BodyInertia, Current, DriftSource, InitialCondition, Motions, Platform, Run,
    };
    use crate::sea_state::{SeaState, Spectrum, Spreading};

    /// A file with only the required keys (the file's lines are the tests' line numbers).
    pub(super) const MINIMAL: &str = include_str!("../../../tests/data/minimal.toml");

    /// A complete file: every key given, none at its default.
    const COMPLETE: &str = r#"
[environment]
gravity = 9.81
water_density = 1000.0

[sea]
spectrum = "jonswap"
hs = 4.0
tp = 10.0
gamma = 2.0
spreading = "cos-n"
spreading_exponent = 4
direction_deg = 30.0
n_directions = 9
seed = 42
band = [0.4, 1.8]

[current]
speed = 0.5
direction_deg = 45.0

[run]
duration = 3600.0
time_step = 0.5
start_time = 10.0

[platform]
mass = 1.0e7
yaw_inertia = 5.0e9
added_mass = [[1.0e6, 0, 0], [0, 2.0e6, 0], [0, 0, 3.0e9]]
stiffness = [[1.0e5, 0, 0], [0, 2.0e5, 0], [0, 0, 3.0e8]]
linear_damping = [[1.0e4, 0, 0], [0, 1.0e4, 0], [0, 0, 1.0e7]]
quadratic_damping = [[1.0e3, 0, 0], [0, 1.0e3, 0], [0, 0, 1.0e6]]

[[platform.columns]]
x = 20.0
y = -20.0
diameter = 8.0
draft = 15.0

[platform.motions]
centre_of_gravity = [0.5, -0.25, -10.0]
radii_of_gyration = [20.0, 21.0, 25.0]
external_stiffness = [[1.0e5, 0, 0, 0, 0, 0], [0, 1.0e5, 0, 0, 0, 0], [0, 0, 0, 0, 0, 0],
                      [0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 3.0e8]]
external_damping = [[0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 0], [0, 0, 2.0e5, 0, 0, 0],
                    [0, 0, 0, 1.0e8, 0, 0], [0, 0, 0, 0, 1.0e8, 0], [0, 0, 0, 0, 0, 0]]

[model]
newman = "arithmetic"
interaction = "mean-direction"
drift_damping = "table"
drag = "separate"
cd_slow = 0.6
cd_fast = 0.9
strips_per_column = 12

[initial]
position = [1.0, -2.0]
heading_deg = 5.0
velocity = [0.1, 0.2]
yaw_rate_deg = 0.5

[drift]
source = "table"
# the former name of `fields`, still read
columns = ["beta_deg", "omega", "yaw", "surge", "sway",
           "b11", "b12", "b13", "b21", "b22", "b23", "b31", "b32", "b33"]
rows = [
  [0.0, 0.3, 0.0, 100.0, 1.0, 11, 12, 13, 21, 22, 23, 31, 32, 33],
  [0.0, 2.0, 0.0, 900.0, 2.0, 11, 12, 13, 21, 22, 23, 31, 32, 33],
  [90.0, 0.3, 5.0, 3.0, 110.0, 11, 12, 13, 21, 22, 23, 31, 32, 33],
  [90.0, 2.0, 6.0, 4.0, 950.0, 11, 12, 13, 21, 22, 23, 31, 32, 33],
]
"#;

    /// The text read as `test.toml` in the current directory.
    pub(super) fn read(text: &str) -> Result<Scenario> {
        parse(text, "test.toml", Path::new("."))
    }

    /// The message of the error that reading `text` must give.
    pub(super) fn error_text(text: &str) -> String {
        read(text).expect_err("must be refused").to_string()
    }

    /// The 1-based line of the first line of `text` that starts with `key`.
    pub(super) fn key_line(text: &str, key: &str) -> usize {
        text.lines()
            .position(|l| l.starts_with(key))
            .expect("key present")
            + 1
    }

    /// MINIMAL with `section` (a header and its keys) before its drift section.
    pub(super) fn minimal_with(section: &str) -> String {
        MINIMAL.replace("[drift]", &format!("{section}\n\n[drift]"))
    }

    /// MINIMAL with `drift` (its keys) as its drift section.
    pub(super) fn minimal_with_drift(drift: &str) -> String {
        let head = MINIMAL.split("[drift]").next().expect("a drift section");
        format!("{head}[drift]\n{drift}\n")
    }

    /// The drift table of an inline source.
    pub(super) fn inline_table(scenario: &Scenario) -> &DriftTable {
        match &scenario.hydro {
            DriftSource::Table(table) => table,
            other => panic!("an inline drift table, not {other:?}"),
        }
    }

    fn diagonal(a: f64, b: f64, c: f64) -> [[f64; 3]; 3] {
        [[a, 0.0, 0.0], [0.0, b, 0.0], [0.0, 0.0, c]]
    }

    #[test]
    fn complete_file_gives_every_value_in_si_and_radians() {
        let scenario = read(COMPLETE).expect("valid file");
        assert_eq!(
            scenario.environment,
            Environment {
                gravity: 9.81,
                water_density: 1000.0
            }
        );
        assert_eq!(
            scenario.sea,
            SeaState {
                spectrum: Spectrum::Jonswap {
                    hs: 4.0,
                    tp: 10.0,
                    gamma: Some(2.0)
                },
                spreading: Spreading::CosN { n: 4.0 },
                mean_direction: 30f64.to_radians(),
                n_directions: 9,
                seed: 42,
                band: Some((0.4, 1.8)),
            }
        );
        assert_eq!(
            scenario.current,
            Current {
                speed: 0.5,
                direction: 45f64.to_radians()
            }
        );
        assert_eq!(
            scenario.run,
            Run {
                duration: 3600.0,
                time_step: 0.5,
                start_time: 10.0,
                block_duration: DEFAULT_BLOCK_DURATION,
                memory_limit: limits::DEFAULT_MEMORY_LIMIT,
            }
        );
        assert_eq!(
            scenario.platform,
            Platform {
                mass: Some(1.0e7),
                yaw_inertia: Some(5.0e9),
                added_mass: Some(diagonal(1.0e6, 2.0e6, 3.0e9)),
                stiffness: diagonal(1.0e5, 2.0e5, 3.0e8),
                linear_damping: diagonal(1.0e4, 1.0e4, 1.0e7),
                quadratic_damping: diagonal(1.0e3, 1.0e3, 1.0e6),
                columns: vec![Cylinder {
                    x: 20.0,
                    y: -20.0,
                    diameter: 8.0,
                    draft: 15.0
                }],
                motions: Some(Motions {
                    centre_of_gravity: [0.5, -0.25, -10.0],
                    inertia: BodyInertia::RadiiOfGyration([20.0, 21.0, 25.0]),
                    external_stiffness: std::array::from_fn(|i| {
                        std::array::from_fn(|j| match (i, j) {
                            (0, 0) | (1, 1) => 1.0e5,
                            (5, 5) => 3.0e8,
                            _ => 0.0,
                        })
                    }),
                    external_damping: std::array::from_fn(|i| {
                        std::array::from_fn(|j| match (i, j) {
                            (2, 2) => 2.0e5,
                            (3, 3) | (4, 4) => 1.0e8,
                            _ => 0.0,
                        })
                    }),
                }),
                wind: None,
            }
        );
        assert_eq!(
            scenario.model,
            ModelOptions {
                second_order: SecondOrder::Newman,
                qtf_tolerance: crate::model::DEFAULT_QTF_TOLERANCE,
                newman: NewmanForm::Arithmetic,
                interaction: Interaction::MeanDirection,
                drift_damping: DriftDamping::Table,
                drag: DragModel::Separate {
                    slow: 0.6,
                    fast: 0.9
                },
                strips_per_column: 12,
                yaw_following: None,
                wave_frequency_motion: crate::model::WaveFrequencyMotion::On,
            }
        );
        assert_eq!(
            scenario.initial,
            InitialCondition {
                position: [1.0, -2.0, 5f64.to_radians()],
                velocity: [0.1, 0.2, 0.5f64.to_radians()],
            }
        );
        let b = [[11.0, 12.0, 13.0], [21.0, 22.0, 23.0], [31.0, 32.0, 33.0]];
        let row = |omega: f64, beta_deg: f64, drift: [f64; 3]| DriftRow {
            omega,
            heading: beta_deg.to_radians(),
            drift,
            damping: Some(b),
        };
        let expected = DriftTable::from_rows(&[
            row(0.3, 0.0, [100.0, 1.0, 0.0]),
            row(2.0, 0.0, [900.0, 2.0, 0.0]),
            row(0.3, 90.0, [3.0, 110.0, 5.0]),
            row(2.0, 90.0, [4.0, 950.0, 6.0]),
        ])
        .expect("valid rows");
        assert_eq!(inline_table(&scenario), &expected);
        assert_eq!(
            inline_table(&scenario).headings(),
            &[0.0, 90f64.to_radians()]
        );
    }

    #[test]
    fn absent_keys_take_their_documented_defaults() {
        let scenario = read(MINIMAL).expect("valid file");
        assert_eq!(scenario.environment, Environment::default());
        assert_eq!(scenario.current, Current::default());
        assert_eq!(scenario.model, ModelOptions::default());
        assert_eq!(scenario.initial, InitialCondition::default());
        assert_eq!(scenario.sea.spreading, Spreading::LongCrested);
        assert_eq!(scenario.sea.n_directions, LONG_CRESTED_DIRECTIONS);
        assert_eq!(scenario.sea.mean_direction, 0.0);
        assert_eq!(scenario.sea.seed, DEFAULT_SEED);
        assert_eq!(scenario.sea.band, None);
        assert_eq!(scenario.run.time_step, DEFAULT_TIME_STEP);
        assert_eq!(scenario.run.start_time, 0.0);
        assert_eq!(scenario.run.block_duration, DEFAULT_BLOCK_DURATION);
        assert_eq!(scenario.run.memory_limit, limits::DEFAULT_MEMORY_LIMIT);
        assert_eq!(scenario.platform.added_mass, None);
        assert_eq!(scenario.platform.linear_damping, [[0.0; 3]; 3]);
        assert_eq!(scenario.platform.quadratic_damping, [[0.0; 3]; 3]);
        assert!(scenario.platform.columns.is_empty());
        assert_eq!(scenario.platform.motions, None);
        assert!(!inline_table(&scenario).has_damping());
    }

    /// A float where a whole number belongs is shown as written, not with its 309 digits.
    #[test]
    fn a_float_for_a_whole_number_is_shown_as_written() {
        let text = MINIMAL.replace("tp = 8.0", "tp = 8.0\nseed = 1e308");
        let line = key_line(&text, "seed");
        assert_eq!(
            error_text(&text),
            format!(
                "test.toml:{line}: invalid type: floating point `1e308`, expected a whole \
                 number, 0 or more"
            )
        );
    }

    #[test]
    fn unknown_key_is_refused_with_its_line() {
        let text = MINIMAL.replace("tp = 8.0", "tp = 8.0\nheight = 3.0");
        let line = key_line(&text, "height");
        let err = read(&text).expect_err("unknown key");
        match &err {
            Error::Parse {
                path,
                line: Some(at),
                message,
            } => {
                assert_eq!(path, "test.toml");
                assert_eq!(*at, line);
                assert!(message.contains("height"), "{message}");
            }
            other => panic!("expected a parse error, got {other:?}"),
        }
    }

    #[test]
    fn wrong_type_is_refused_with_its_line() {
        let text = MINIMAL.replace("duration = 600.0", "duration = \"long\"");
        let line = key_line(&text, "duration");
        let err = read(&text).expect_err("wrong type");
        assert!(
            matches!(&err, Error::Parse { line: Some(at), .. } if *at == line),
            "{err:?}"
        );
        assert!(
            err.to_string().starts_with(&format!("test.toml:{line}: ")),
            "{err}"
        );
    }

    /// A JSON database given as a configuration is named for what it is, with the remedy.
    #[test]
    fn a_database_is_not_a_configuration() {
        let err = parse(
            "\n  {\"format_version\": 1, \"drift\": []}",
            "iea.json",
            Path::new(""),
        )
        .expect_err("a JSON database");
        let text = err.to_string();
        assert!(
            text.starts_with("iea.json:1: this is a hydrodynamic database")
                && text.contains("source = \"database\""),
            "{text}"
        );
    }

    #[test]
    fn syntax_error_is_refused_with_its_line() {
        let text = MINIMAL.replace("hs = 2.0", "hs = = 2.0");
        let line = key_line(&text, "hs");
        let err = read(&text).expect_err("syntax error");
        assert!(
            matches!(&err, Error::Parse { line: Some(at), .. } if *at == line),
            "{err:?}"
        );
    }

    /// The commented example reads, its inline drift table covering its sea.
    #[test]
    fn example_file_loads() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/example.toml");
        let scenario = load(&path, limits::DEFAULT_MEMORY_LIMIT).expect("the example is valid");
        let drift = inline_table(&scenario);
        assert_eq!(drift.headings().len(), 2);
        assert_eq!(drift.omegas().len(), 6);
        drift
            .check_covers(scenario.sea.band(), &[scenario.sea.mean_direction])
            .expect("the example's drift table covers its sea state");
    }
}
