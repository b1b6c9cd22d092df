//! The TOML configuration file: reads it into a [`Scenario`].
//!
//! Units are SI everywhere except angles: every angle in the file is in degrees and its key
//! ends in `_deg` (rates in deg/s end in `_rate_deg`). This module converts them to radians,
//! once; the core never sees a degree. Unknown keys are errors, so a typo never silently
//! falls back to a default.
//!
//! # Format
//!
//! ```toml
//! [environment]              # optional section
//! gravity = 9.80665          # m/s^2
//! water_density = 1025.0     # kg/m^3
//!
//! [sea]
//! spectrum = "jonswap"       # "jonswap" | "pierson-moskowitz" | "table"
//! hs = 4.0                   # m, jonswap and pierson-moskowitz only
//! tp = 10.0                  # s, jonswap and pierson-moskowitz only
//! gamma = 3.3                # jonswap only, optional: DNV-RP-C205 default from hs, tp
//! # omega = [...]            # rad/s, strictly increasing, "table" only
//! # density = [...]          # m^2 s/rad, same length, "table" only
//! spreading = "long-crested" # default | "cos-n" | "cos-2s"
//! # spreading_exponent = 2.0 # N of cos^N, or s of cos^2s; required for those, else refused
//! direction_deg = 0.0        # mean direction of propagation, deg from +X, counter-clockwise
//! # n_directions = 15        # short-crested only (default 15); long-crested: 1 or absent
//! seed = 1                   # seed of the random amplitudes, 0 ..= 2^63 - 1
//! # band = [0.3, 2.0]        # simulated band [omega_min, omega_max], rad/s; default from
//!                            # the spectrum (0.5 .. 4 wp, or the table's range)
//!
//! [current]                  # optional section
//! speed = 0.0                # m/s
//! direction_deg = 0.0        # direction the current flows towards, deg from +X
//!
//! [run]
//! duration = 10800.0         # s, required
//! time_step = 1.0            # s (RK4 step)
//! start_time = 0.0           # s
//! block_duration = 16384.0   # s: records are made one block at a time (memory per block)
//! memory_limit_gb = 4.0      # GB (1e9 bytes) the records may take; larger estimates refused
//!
//! [platform]                 # matrices are 3x3, rows and columns (surge, sway, yaw)
//! mass = 1.2e7               # kg; default: the drift database's mass_properties
//! yaw_inertia = 7.5e9        # kg m^2; default: the drift database's mass_properties
//! stiffness = [[...], [...], [...]]  # N/m, N, N m/rad on (X, Y, theta), required
//! added_mass = [[...], ...]          # kg, kg m, kg m^2; default: the drift database's
//!                                    # low_frequency_added_mass, else zeros
//! linear_damping = [[...], ...]      # N s/m, ...; default zeros
//! quadratic_damping = [[...], ...]   # force_i = sum_j Bq_ij v_j |v_j|; default zeros
//! [[platform.columns]]       # zero or more, body frame, m
//! x = 25.0
//! y = 25.0
//! diameter = 10.0
//! draft = 20.0
//!
//! [model]                    # optional section
//! second_order = "newman"    # default | "full-qtf" (the database's QTF, factorised)
//! qtf_tolerance = 1e-6       # full-qtf only: discarded share of the QTF's eigenvalues
//! newman = "geometric"       # default | "arithmetic" (force under newman; damping always)
//! interaction = "auto"       # default | "bidirectional" | "mean-direction" | "none":
//!                            # cross-direction terms of a short-crested sea
//! drift_damping = "aranha"   # default | "table" (needs the b_ij columns) | "off"
//! drag = "off"               # default | "separate" (cd_slow, cd_fast) | "combined" (cd)
//! strips_per_column = 20
//! yaw_following = { headings = 36 }  # off by default; records at 36 yaws over the circle,
//!                            # or { headings = 13, range_deg = [-15.0, 15.0] }: an interval
//!
//! [initial]                  # optional section, inertial frame, all zero by default
//! position = [0.0, 0.0]      # X, Y in m
//! heading_deg = 0.0          # yaw angle theta, deg
//! velocity = [0.0, 0.0]      # dX/dt, dY/dt in m/s
//! yaw_rate_deg = 0.0         # d theta/dt, deg/s
//!
//! [drift]                    # mean drift table, per unit wave amplitude squared
//! source = "table"           # "table" (inline) | "csv" | "database" | "columns"
//! fields = ["omega", "beta_deg", "surge", "sway", "yaw"]
//! rows = [[0.3, 0.0, 2.0e3, 0.0, 0.0], ...]
//! # source = "csv"
//! # file = "drift.csv"       # relative to the configuration file's directory
//! # source = "database"
//! # file = "platform.json"   # native hydro database (`slowdrift hydro wamit`), relative
//!                            # to the configuration file; its rho and g must equal
//!                            # [environment]'s; its QTF (if any) serves full-qtf
//! ```
//!
//! The fields of a drift table (inline or CSV) are those of `hydro::io::drift_csv`: `omega`
//! (rad/s), `beta_deg`, `surge`, `sway`, `yaw`, optionally all nine `b11` .. `b33`.

use super::lines::LineIndex;
use super::{
    limits, ColumnGrid, Current, DriftSource, InitialCondition, ModelOptions, Origins, Platform,
    Run, Scenario, DEFAULT_BLOCK_DURATION, DEFAULT_N_DIRECTIONS,
};
use crate::error::numbers::written;
use crate::error::{Error, Location, Result};
use crate::files::Cost;
use crate::hydro::io::drift_csv::DriftFields;
use crate::hydro::DriftTable;
use crate::model::{
    BidirectionalDrift, Cylinder, DragKind, DragModel, DriftDamping, Environment, Interaction,
    Mode, NewmanForm, SecondOrder, SpectrumKind, SpreadingKind, YawFollowing,
};
use crate::sea_state::{SeaState, Spectrum, Spreading};
use serde::Deserialize;
use std::ops::Range;
use std::path::{Path, PathBuf};
use toml::Spanned;

/// Default RK4 time step, s.
pub const DEFAULT_TIME_STEP: f64 = 1.0;
/// Number of directions of a long-crested sea (the only value accepted for it).
pub const LONG_CRESTED_DIRECTIONS: usize = 1;
/// Default seed of the random wave amplitudes.
pub const DEFAULT_SEED: u64 = 1;

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
    environment: EnvironmentFile,
    sea: Spanned<SeaFile>,
    #[serde(default)]
    current: CurrentFile,
    run: RunFile,
    platform: PlatformFile,
    #[serde(default)]
    model: Option<Spanned<ModelFile>>,
    #[serde(default)]
    initial: InitialFile,
    drift: Spanned<DriftFile>,
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
            run: self.run.into_core().map_err(|e| origins.locate(e))?,
            platform: self.platform.into_core(),
            hydro,
            model,
            initial: self.initial.into_core(),
            origins,
        })
    }
}

/// `[environment]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields, default)]
struct EnvironmentFile {
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
    fn into_core(self) -> Environment {
        Environment {
            gravity: self.gravity,
            water_density: self.water_density,
        }
    }
}

/// `[sea]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SeaFile {
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
    fn into_core(self) -> std::result::Result<SeaState, String> {
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

    fn spectrum(&self) -> std::result::Result<Spectrum, String> {
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

    fn spreading(&self) -> std::result::Result<(Spreading, usize), String> {
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
struct CurrentFile {
    /// m/s.
    speed: f64,
    /// Direction the current flows towards, deg.
    direction_deg: f64,
}

impl CurrentFile {
    fn into_core(self) -> Current {
        Current {
            speed: self.speed,
            direction: self.direction_deg.to_radians(),
        }
    }
}

/// `[run]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RunFile {
    /// s.
    duration: f64,
    /// s.
    #[serde(default = "default_time_step")]
    time_step: f64,
    /// s.
    #[serde(default)]
    start_time: f64,
    /// s.
    #[serde(default = "default_block_duration")]
    block_duration: f64,
    /// GB (1e9 bytes).
    #[serde(default = "default_memory_limit_gb")]
    memory_limit_gb: f64,
}

fn default_time_step() -> f64 {
    DEFAULT_TIME_STEP
}

fn default_block_duration() -> f64 {
    DEFAULT_BLOCK_DURATION
}

fn default_memory_limit_gb() -> f64 {
    limits::DEFAULT_MEMORY_LIMIT / crate::error::BYTES_PER_GB
}

impl RunFile {
    fn into_core(self) -> Result<Run> {
        Ok(Run {
            duration: self.duration,
            time_step: self.time_step,
            start_time: self.start_time,
            block_duration: self.block_duration,
            memory_limit: limits::memory_limit_of_gb(self.memory_limit_gb)?,
        })
    }
}

/// `[platform]`; every matrix is indexed (surge, sway, yaw) like [`Platform`].
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PlatformFile {
    mass: Option<f64>,
    yaw_inertia: Option<f64>,
    added_mass: Option<[[f64; 3]; 3]>,
    stiffness: [[f64; 3]; 3],
    #[serde(default)]
    linear_damping: [[f64; 3]; 3],
    #[serde(default)]
    quadratic_damping: [[f64; 3]; 3],
    #[serde(default)]
    columns: Vec<ColumnFile>,
}

/// `[[platform.columns]]`, body frame, m.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ColumnFile {
    x: f64,
    y: f64,
    diameter: f64,
    draft: f64,
}

impl PlatformFile {
    fn into_core(self) -> Platform {
        Platform {
            mass: self.mass,
            yaw_inertia: self.yaw_inertia,
            added_mass: self.added_mass,
            stiffness: self.stiffness,
            linear_damping: self.linear_damping,
            quadratic_damping: self.quadratic_damping,
            columns: self
                .columns
                .into_iter()
                .map(|c| Cylinder {
                    x: c.x,
                    y: c.y,
                    diameter: c.diameter,
                    draft: c.draft,
                })
                .collect(),
        }
    }
}

/// `[model]`; absent keys take [`ModelOptions::default`].
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ModelFile {
    second_order: Option<SecondOrder>,
    qtf_tolerance: Option<f64>,
    newman: Option<NewmanForm>,
    interaction: Option<Interaction>,
    drift_damping: Option<DriftDamping>,
    drag: Option<DragKind>,
    /// Drag coefficient of the combined model.
    cd: Option<f64>,
    /// Slow drag coefficient of the separate model.
    cd_slow: Option<f64>,
    /// Fast drag coefficient of the separate model.
    cd_fast: Option<f64>,
    strips_per_column: Option<usize>,
    yaw_following: Option<YawFollowingFile>,
}

/// `model.yaw_following`: `{ headings = n }` (the full circle) or
/// `{ headings = n, range_deg = [min, max] }`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct YawFollowingFile {
    headings: usize,
    range_deg: Option<[f64; 2]>,
}

impl ModelFile {
    fn into_core(self) -> std::result::Result<ModelOptions, String> {
        let default = ModelOptions::default();
        let (second_order, qtf_tolerance) = match self.second_order {
            None | Some(SecondOrder::Newman) => {
                refused(
                    &self.qtf_tolerance,
                    "qtf_tolerance",
                    &format!(
                        "second_order is \"{}\" (the default)",
                        SecondOrder::Newman.word()
                    ),
                )?;
                (SecondOrder::Newman, default.qtf_tolerance)
            }
            Some(SecondOrder::FullQtf) => (
                SecondOrder::FullQtf,
                self.qtf_tolerance.unwrap_or(default.qtf_tolerance),
            ),
        };
        let drag = match self.drag {
            None => {
                let because = format!("drag is {} (the default)", DragKind::Off.word());
                self.refuse_coefficients(&[], &because)?;
                default.drag
            }
            Some(kind) => self.drag(kind)?,
        };
        Ok(ModelOptions {
            second_order,
            qtf_tolerance,
            newman: self.newman.unwrap_or(default.newman),
            interaction: self.interaction.unwrap_or(default.interaction),
            drift_damping: self.drift_damping.unwrap_or(default.drift_damping),
            drag,
            strips_per_column: self.strips_per_column.unwrap_or(default.strips_per_column),
            yaw_following: self.yaw_following.map(|y| YawFollowing {
                headings: y.headings,
                range: y
                    .range_deg
                    .map(|[min, max]| (min.to_radians(), max.to_radians())),
            }),
        })
    }

    /// The drag model `kind` with its coefficients, the others refused.
    fn drag(&self, kind: DragKind) -> std::result::Result<DragModel, String> {
        let because = chosen("drag", kind);
        Ok(match kind {
            DragKind::Off => {
                self.refuse_coefficients(&[], &because)?;
                DragModel::Off
            }
            DragKind::Separate => {
                self.refuse_coefficients(&["cd_slow", "cd_fast"], &because)?;
                DragModel::Separate {
                    slow: required(self.cd_slow, "cd_slow", &because)?,
                    fast: required(self.cd_fast, "cd_fast", &because)?,
                }
            }
            DragKind::Combined => {
                self.refuse_coefficients(&["cd"], &because)?;
                DragModel::Combined {
                    cd: required(self.cd, "cd", &because)?,
                }
            }
        })
    }

    /// Refuses every drag coefficient that is given but not in `used`.
    fn refuse_coefficients(&self, used: &[&str], because: &str) -> std::result::Result<(), String> {
        for (key, value) in [
            ("cd", self.cd),
            ("cd_slow", self.cd_slow),
            ("cd_fast", self.cd_fast),
        ] {
            if !used.contains(&key) {
                refused(&value, key, because)?;
            }
        }
        Ok(())
    }
}

/// `[initial]`, inertial frame.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
struct InitialFile {
    /// X, Y in m.
    position: [f64; 2],
    /// Yaw angle theta, deg.
    heading_deg: f64,
    /// dX/dt, dY/dt in m/s.
    velocity: [f64; 2],
    /// d theta/dt, deg/s.
    yaw_rate_deg: f64,
}

impl InitialFile {
    fn into_core(self) -> InitialCondition {
        let [x, y] = self.position;
        let [vx, vy] = self.velocity;
        InitialCondition {
            position: [x, y, self.heading_deg.to_radians()],
            velocity: [vx, vy, self.yaw_rate_deg.to_radians()],
        }
    }
}

/// `[drift]`, tagged by `source`. A new source is a new variant and a new arm in
/// [`DriftFile::into_table`].
#[derive(Deserialize)]
#[serde(tag = "source", rename_all = "kebab-case", deny_unknown_fields)]
enum DriftFile {
    /// The table inline: column names and rows of numbers.
    Table {
        /// The name of each field of a row (`hydro::io::drift_csv`); `columns` is its
        /// former name, still read.
        #[serde(alias = "columns")]
        fields: Vec<String>,
        rows: Vec<Vec<f64>>,
    },
    /// A CSV file, relative to the configuration file's directory.
    Csv { file: PathBuf },
    /// The drift table of a native hydro database (JSON, `hydro::io::database`), relative to
    /// the configuration file's directory. `bidirectional = "column-array"` takes the
    /// bi-directional drift from the deep-water column solver on `[[platform.columns]]` at
    /// the database's drift frequencies (what the FMU's packed default platform uses, since
    /// a bi-directional table would be large); otherwise the database's own table, if any.
    Database {
        file: PathBuf,
        bidirectional: Option<BidirectionalDrift>,
    },
    /// The default platform's radiation-diffraction database compiled into the library
    /// (`tests/bem`: the paper's columns on pontoons, freely floating): its mean and
    /// bi-directional drift on its own grid.
    DefaultPlatform {},
    /// The closed-form drift of the platform's columns, each treated as an isolated,
    /// infinitely deep column (no interaction; see `hydro::column_drift`), on `n_omega`
    /// frequencies from `omega_min` to `omega_max` (rad/s) and headings every
    /// `heading_step_deg` around the circle.
    Columns {
        #[serde(default = "default_columns_omega_min")]
        omega_min: f64,
        #[serde(default = "default_columns_omega_max")]
        omega_max: f64,
        #[serde(default = "default_columns_n_omega")]
        n_omega: usize,
        #[serde(default = "default_columns_heading_step")]
        heading_step_deg: f64,
    },
    /// The platform's columns as an interacting array (Linton & Evans 1990;
    /// `hydro::columns`): near-field drift with Aranha's wave-drift damping from the solver's
    /// own derivatives, on the same grid keys as `columns`; `depth` in m for bottom-mounted
    /// columns, absent for deep water and infinitely deep columns.
    ColumnArray {
        #[serde(default = "default_columns_omega_min")]
        omega_min: f64,
        #[serde(default = "default_columns_omega_max")]
        omega_max: f64,
        #[serde(default = "default_columns_n_omega")]
        n_omega: usize,
        #[serde(default = "default_columns_heading_step")]
        heading_step_deg: f64,
        depth: Option<f64>,
    },
}

/// Default frequency range and resolution of `source = "columns"`.
const COLUMNS_OMEGA_MIN: f64 = 0.05;
const COLUMNS_OMEGA_MAX: f64 = 3.0;
const COLUMNS_N_OMEGA: usize = 100;
const COLUMNS_HEADING_STEP_DEG: f64 = 10.0;

fn default_columns_omega_min() -> f64 {
    COLUMNS_OMEGA_MIN
}
fn default_columns_omega_max() -> f64 {
    COLUMNS_OMEGA_MAX
}
fn default_columns_n_omega() -> usize {
    COLUMNS_N_OMEGA
}
fn default_columns_heading_step() -> f64 {
    COLUMNS_HEADING_STEP_DEG
}

/// A column-solver grid: `count` frequencies from `min` to `max` (rad/s), headings every
/// `step_deg` around the circle.
fn columns_grid(
    min: f64,
    max: f64,
    count: usize,
    step_deg: f64,
) -> std::result::Result<ColumnGrid, String> {
    if !(min > 0.0 && max > min && min.is_finite() && max.is_finite()) {
        return Err(format!(
            "omega_min = {}, omega_max = {}: need 0 < omega_min < omega_max",
            written(min),
            written(max)
        ));
    }
    if count < 2 {
        return Err(format!("n_omega = {count}: need at least 2"));
    }
    if !(step_deg > 0.0 && step_deg <= 180.0) {
        return Err(format!(
            "heading_step_deg = {}: need 0 < step <= 180",
            written(step_deg)
        ));
    }
    Ok(ColumnGrid {
        omega_min: min,
        omega_max: max,
        n_omega: count,
        heading_step: step_deg.to_radians(),
    })
}

impl DriftFile {
    /// The drift source this section names; `span` locates the `[drift]` section for error
    /// messages. An inline table is checked and sorted here; files are read, and solvers
    /// run, when the scenario is resolved.
    fn into_source(
        self,
        source: &Source,
        span: Range<usize>,
        base_dir: &Path,
    ) -> Result<DriftSource> {
        let grid = |omega_min, omega_max, n_omega, heading_step_deg| {
            columns_grid(omega_min, omega_max, n_omega, heading_step_deg)
                .map_err(|m| source.error_at(span.clone(), format!("[drift] {m}")))
        };
        Ok(match self {
            DriftFile::Database {
                file,
                bidirectional,
            } => DriftSource::Database {
                path: base_dir.join(file),
                bidirectional_from_columns: matches!(
                    bidirectional,
                    Some(BidirectionalDrift::ColumnArray)
                ),
            },
            DriftFile::DefaultPlatform {} => DriftSource::DefaultPlatform,
            DriftFile::Columns {
                omega_min,
                omega_max,
                n_omega,
                heading_step_deg,
            } => {
                DriftSource::IsolatedColumns(grid(omega_min, omega_max, n_omega, heading_step_deg)?)
            }
            DriftFile::ColumnArray {
                omega_min,
                omega_max,
                n_omega,
                heading_step_deg,
                depth,
            } => DriftSource::ColumnArray {
                grid: grid(omega_min, omega_max, n_omega, heading_step_deg)?,
                depth,
            },
            DriftFile::Table { fields, rows } => {
                let at = source.location(span.clone());
                let names: Vec<&str> = fields.iter().map(String::as_str).collect();
                let fields = DriftFields::new(&names, &at)?;
                let rows = rows
                    .iter()
                    .enumerate()
                    .map(|(r, values)| {
                        fields.row(values, &at).map_err(|e| match e {
                            Error::Parse {
                                path,
                                line,
                                message,
                            } => Error::Parse {
                                path,
                                line,
                                message: format!("[drift] rows[{r}]: {message}"),
                            },
                            other => other,
                        })
                    })
                    .collect::<Result<Vec<_>>>()?;
                DriftSource::Table(DriftTable::from_rows(&rows)?)
            }
            DriftFile::Csv { file } => DriftSource::Csv(base_dir.join(file)),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hydro::bidirectional::BidirectionalSource;
    use crate::hydro::io::database::HydroDatabase;
    use crate::hydro::DriftRow;
    use crate::problem::{resolve, Problem};
    use std::sync::atomic::{AtomicUsize, Ordering};

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

    /// A file with only the required keys.
    const MINIMAL: &str = r#"
[sea]
spectrum = "pierson-moskowitz"
hs = 2.0
tp = 8.0

[run]
duration = 600.0

[platform]
mass = 1.0e7
yaw_inertia = 5.0e9
stiffness = [[1.0e5, 0, 0], [0, 1.0e5, 0], [0, 0, 1.0e8]]

[drift]
source = "table"
fields = ["omega", "beta_deg", "surge", "sway", "yaw"]
rows = [[0.3, 0, 100, 0, 0], [2.0, 0, 900, 0, 0]]
"#;

    /// The text parsed, resolved and checked, as a simulation would take it.
    fn problem(text: &str, base_dir: &Path) -> Result<Problem> {
        let problem = resolve(&parse(text, "test.toml", base_dir)?)?;
        problem.check()?;
        Ok(problem)
    }

    fn parse_text(text: &str) -> Result<Problem> {
        problem(text, Path::new("."))
    }

    /// The 1-based line of the first line of `text` that starts with `key`.
    fn key_line(text: &str, key: &str) -> usize {
        text.lines()
            .position(|l| l.starts_with(key))
            .expect("key present")
            + 1
    }

    fn error_text(text: &str) -> String {
        parse_text(text).expect_err("must be refused").to_string()
    }

    /// A file under the temporary directory whose name no other test uses.
    fn temp_file(stem: &str, contents: &str) -> PathBuf {
        static COUNTER: AtomicUsize = AtomicUsize::new(0);
        let unique = COUNTER.fetch_add(1, Ordering::Relaxed);
        let path = std::env::temp_dir().join(format!(
            "slowdrift-config-{}-{unique}-{stem}",
            std::process::id()
        ));
        std::fs::write(&path, contents).expect("temporary file is writable");
        path
    }

    /// MINIMAL with its drift section replaced by a CSV source.
    fn minimal_with_csv(csv: &Path) -> String {
        let head = MINIMAL
            .split("[drift]")
            .next()
            .expect("MINIMAL has a drift section");
        format!(
            "{head}[drift]\nsource = \"csv\"\nfile = {:?}\n",
            csv.display().to_string()
        )
    }

    fn diagonal(a: f64, b: f64, c: f64) -> [[f64; 3]; 3] {
        [[a, 0.0, 0.0], [0.0, b, 0.0], [0.0, 0.0, c]]
    }

    #[test]
    fn complete_file_gives_every_value_in_si_and_radians() {
        let config = parse_text(COMPLETE).expect("valid file");
        assert_eq!(
            config.environment,
            Environment {
                gravity: 9.81,
                water_density: 1000.0
            }
        );
        assert_eq!(
            config.sea,
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
            config.current,
            Current {
                speed: 0.5,
                direction: 45f64.to_radians()
            }
        );
        assert_eq!(
            config.run,
            Run {
                duration: 3600.0,
                time_step: 0.5,
                start_time: 10.0,
                block_duration: DEFAULT_BLOCK_DURATION,
                memory_limit: limits::DEFAULT_MEMORY_LIMIT,
            }
        );
        assert_eq!(
            config.platform,
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
            }
        );
        assert_eq!(
            config.model,
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
            }
        );
        assert_eq!(
            config.initial,
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
        assert_eq!(config.hydro.drift, expected);
        assert_eq!(config.hydro.drift.headings(), &[0.0, 90f64.to_radians()]);
    }

    #[test]
    fn absent_keys_take_their_documented_defaults() {
        let config = parse_text(MINIMAL).expect("valid file");
        assert_eq!(config.environment, Environment::default());
        assert_eq!(config.current, Current::default());
        assert_eq!(config.model, ModelOptions::default());
        assert_eq!(config.initial, InitialCondition::default());
        assert_eq!(config.sea.spreading, Spreading::LongCrested);
        assert_eq!(config.sea.n_directions, LONG_CRESTED_DIRECTIONS);
        assert_eq!(config.sea.mean_direction, 0.0);
        assert_eq!(config.sea.seed, DEFAULT_SEED);
        assert_eq!(config.sea.band, None);
        assert_eq!(config.run.time_step, DEFAULT_TIME_STEP);
        assert_eq!(config.run.start_time, 0.0);
        assert_eq!(config.platform.added_mass, None);
        let inertia = config.inertia().unwrap();
        assert_eq!(inertia.added_mass, [[0.0; 3]; 3]);
        assert_eq!(inertia.added_mass_origin, crate::problem::Origin::Zero);
        assert_eq!(config.platform.linear_damping, [[0.0; 3]; 3]);
        assert_eq!(config.platform.quadratic_damping, [[0.0; 3]; 3]);
        assert!(config.platform.columns.is_empty());
        assert!(!config.hydro.drift.has_damping());
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

    /// The word messages use for an interaction mode is the one the file takes for it.
    #[test]
    fn interaction_words_read_back_as_their_mode() {
        for mode in [
            Interaction::Auto,
            Interaction::None,
            Interaction::MeanDirection,
            Interaction::Bidirectional,
        ] {
            let text = format!("{MINIMAL}\n[model]\ninteraction = \"{}\"\n", mode.word());
            let scenario = parse(&text, "test.toml", Path::new(".")).expect("a known word");
            assert_eq!(scenario.model.interaction, mode);
        }
    }

    #[test]
    fn yaw_following_reads_headings_and_a_range_in_degrees() {
        let with =
            |model: &str| MINIMAL.replace("[drift]", &format!("[model]\n{model}\n\n[drift]"));
        let circle = parse_text(&with("yaw_following = { headings = 36 }")).expect("valid");
        assert_eq!(
            circle.model.yaw_following,
            Some(YawFollowing {
                headings: 36,
                range: None
            })
        );
        let text = with("yaw_following = { headings = 13, range_deg = [-15.0, 15.0] }");
        let range = parse_text(&text)
            .expect("valid")
            .model
            .yaw_following
            .unwrap();
        assert_eq!(range.range, Some((-15f64.to_radians(), 15f64.to_radians())));
        assert_eq!(parse_text(MINIMAL).unwrap().model.yaw_following, None);
        let e = parse_text(&with("yaw_following = { headings = 36, range = [1, 2] }"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("range"), "{e}");
    }

    #[test]
    fn short_crested_sea_defaults_to_fifteen_directions_and_jonswap_to_dnv_gamma() {
        let text = MINIMAL.replace(
            "spectrum = \"pierson-moskowitz\"",
            "spectrum = \"jonswap\"\nspreading = \"cos-2s\"\nspreading_exponent = 6",
        );
        let sea = parse_text(&text).expect("valid file").sea;
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
        let sea = parse_text(&text).expect("valid file").sea;
        assert_eq!(
            sea.spectrum,
            Spectrum::Tabulated {
                omega: vec![0.3, 1.0, 2.0],
                density: vec![0.0, 1.5, 0.1]
            }
        );
    }

    #[test]
    fn unknown_key_is_refused_with_its_line() {
        let text = MINIMAL.replace("tp = 8.0", "tp = 8.0\nheight = 3.0");
        let line = text
            .lines()
            .position(|l| l.starts_with("height"))
            .expect("inserted")
            + 1;
        let err = parse_text(&text).expect_err("unknown key");
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
    fn unknown_key_in_the_drift_section_is_refused() {
        let text = MINIMAL.replace("source = \"table\"", "source = \"table\"\nunits = \"si\"");
        assert!(error_text(&text).contains("units"));
    }

    #[test]
    fn wrong_type_is_refused_with_its_line() {
        let text = MINIMAL.replace("duration = 600.0", "duration = \"long\"");
        let line = text
            .lines()
            .position(|l| l.starts_with("duration"))
            .expect("present")
            + 1;
        let err = parse_text(&text).expect_err("wrong type");
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

    /// An inline drift table of 40 000 rows is read in well under a second, and a row's
    /// error names its line (each value's line was found by counting the newlines before
    /// it: 23 s for this table).
    #[test]
    fn a_long_inline_table_is_located_in_linear_time() {
        let rows: String = (1..=40_000)
            .map(|k| format!("[{}, 0, 100, 0, 0],\n", k as f64 * 1e-4))
            .collect();
        let text = MINIMAL.replace(
            "rows = [[0.3, 0, 100, 0, 0], [2.0, 0, 900, 0, 0]]",
            &format!("rows = [\n{rows}[-1, 0, 0, 0, 0]]"),
        );
        let last = text.lines().position(|l| l.starts_with("[-1")).unwrap() + 1;
        let message = error_text(&text);
        assert!(
            message.starts_with(&format!("test.toml:{last}: invalid [drift] rows[40000]")),
            "{message}"
        );
    }

    #[test]
    fn syntax_error_is_refused_with_its_line() {
        let text = MINIMAL.replace("hs = 2.0", "hs = = 2.0");
        let line = text
            .lines()
            .position(|l| l.starts_with("hs"))
            .expect("present")
            + 1;
        let err = parse_text(&text).expect_err("syntax error");
        assert!(
            matches!(&err, Error::Parse { line: Some(at), .. } if *at == line),
            "{err:?}"
        );
    }

    #[test]
    fn negative_hs_is_refused_by_validation() {
        let text = MINIMAL.replace("hs = 2.0", "hs = -1");
        assert!(
            error_text(&text).starts_with("test.toml:4: invalid [sea] hs = -1: "),
            "{}",
            error_text(&text)
        );
    }

    #[test]
    fn gamma_below_one_is_refused() {
        let text = MINIMAL.replace(
            "spectrum = \"pierson-moskowitz\"",
            "spectrum = \"jonswap\"\ngamma = 0.5",
        );
        let expected = format!(
            "test.toml:{}: invalid [sea] gamma = 0.5: ",
            key_line(&text, "gamma")
        );
        assert!(
            error_text(&text).starts_with(&expected),
            "{}",
            error_text(&text)
        );
    }

    #[test]
    fn nan_is_refused() {
        let text = MINIMAL.replace("tp = 8.0", "tp = nan");
        let expected = format!(
            "test.toml:{}: invalid [sea] tp = NaN: ",
            key_line(&text, "tp")
        );
        assert!(
            error_text(&text).starts_with(&expected),
            "{}",
            error_text(&text)
        );
        let text = MINIMAL.replace("mass = 1.0e7", "mass = nan");
        let expected = format!(
            "test.toml:{}: invalid [platform] mass = NaN: ",
            key_line(&text, "mass")
        );
        assert!(
            error_text(&text).starts_with(&expected),
            "{}",
            error_text(&text)
        );
    }

    #[test]
    fn key_that_does_not_apply_is_refused_with_the_section_line() {
        let text = MINIMAL.replace("tp = 8.0", "tp = 8.0\ngamma = 3.3");
        let err = parse_text(&text).expect_err("gamma with pierson-moskowitz");
        assert!(
            matches!(&err, Error::Parse { line: Some(_), .. }),
            "{err:?}"
        );
        assert!(err.to_string().contains("gamma does not apply"), "{err}");
    }

    #[test]
    fn missing_key_that_the_choice_requires_is_named() {
        let text = MINIMAL.replace("hs = 2.0\n", "");
        assert!(error_text(&text).contains("hs is required"));
        let text = format!("{MINIMAL}\n[model]\ndrag = \"combined\"\n");
        assert!(error_text(&text).contains("cd is required"));
        let text = MINIMAL.replace("tp = 8.0", "tp = 8.0\nspreading = \"cos-n\"");
        assert!(error_text(&text).contains("spreading_exponent is required"));
    }

    #[test]
    fn hole_in_the_drift_table_is_refused() {
        let text = MINIMAL.replace(
            "rows = [[0.3, 0, 100, 0, 0], [2.0, 0, 900, 0, 0]]",
            "rows = [[0.3, 0, 100, 0, 0], [2.0, 0, 900, 0, 0], [0.3, 90, 0, 100, 0]]",
        );
        assert!(error_text(&text).contains("hole in the drift table"));
    }

    #[test]
    fn unsorted_drift_frequencies_are_refused() {
        let text = MINIMAL.replace(
            "rows = [[0.3, 0, 100, 0, 0], [2.0, 0, 900, 0, 0]]",
            "rows = [[2.0, 0, 900, 0, 0], [0.3, 0, 100, 0, 0]]",
        );
        assert!(error_text(&text).contains("not increasing"));
    }

    #[test]
    fn partial_damping_columns_and_short_rows_are_refused() {
        let text = MINIMAL.replace("\"yaw\"]", "\"yaw\", \"b11\"]");
        assert!(error_text(&text).contains("no \"b12\""));
        let text = MINIMAL.replace("[2.0, 0, 900, 0, 0]", "[2.0, 0, 900, 0]");
        let message = error_text(&text);
        assert!(
            message.contains("rows[1]") && message.contains("4 values"),
            "{message}"
        );
    }

    #[test]
    fn csv_drift_table_is_read_relative_to_the_base_directory() {
        let csv = temp_file(
            "good.csv",
            "# invented numbers\nomega, beta_deg, surge, sway, yaw\n\n0.3, 0, 100, 0, 0\n2.0, 0, 900, 0, 0\n",
        );
        let dir = csv.parent().expect("temp dir");
        let name = csv
            .file_name()
            .expect("file name")
            .to_string_lossy()
            .to_string();
        let head = MINIMAL.split("[drift]").next().expect("drift section");
        let text = format!("{head}[drift]\nsource = \"csv\"\nfile = \"{name}\"\n");
        let mut from_csv = problem(&text, dir).expect("valid file");
        std::fs::remove_file(&csv).expect("remove temporary file");
        let inline = parse_text(MINIMAL).expect("valid file");
        // The same table; only the summary's description of where it came from differs.
        assert_eq!(
            from_csv.hydro.source,
            format!("the CSV drift table {}", csv.display())
        );
        from_csv.hydro.source = inline.hydro.source.clone();
        assert_eq!(from_csv, inline);
    }

    #[test]
    fn malformed_csv_line_names_file_and_line() {
        let csv = temp_file(
            "bad.csv",
            "omega,beta_deg,surge,sway,yaw\n# comment\n0.3,0,100,0,0\n2.0,0,9oo,0,0\n",
        );
        let err = parse_text(&minimal_with_csv(&csv)).expect_err("malformed line");
        std::fs::remove_file(&csv).expect("remove temporary file");
        match &err {
            Error::Parse {
                path,
                line,
                message,
            } => {
                assert_eq!(path, &csv.display().to_string());
                assert_eq!(*line, Some(4));
                assert!(
                    message.contains("surge") && message.contains("9oo"),
                    "{message}"
                );
            }
            other => panic!("expected a parse error, got {other:?}"),
        }
    }

    /// A CSV table cut inside its last number (no newline after it, fewer digits than the
    /// line above: "9.0e2" cut to "9.0") is refused at that line; the same line ended by
    /// a newline, or with as many digits, is whole.
    #[test]
    fn a_csv_cut_inside_its_last_number_is_refused() {
        let head = "omega,beta_deg,sway,yaw,surge\n0.3,0,0,0,1.0e2\n";
        for (tail, cut) in [
            ("2.0,0,0,0,9.0", true),
            ("2.0,0,0,0,9.0\n", false),
            ("2.0,0,0,0,9.0e2", false),
        ] {
            let csv = temp_file("cut.csv", &format!("{head}{tail}"));
            let result = parse_text(&minimal_with_csv(&csv));
            std::fs::remove_file(&csv).expect("remove temporary file");
            match (result, cut) {
                (Err(Error::Parse { line, message, .. }), true) => {
                    assert_eq!(line, Some(3));
                    assert!(message.contains("\"9.0\" has fewer digits"), "{message}");
                }
                (Ok(_), false) => {}
                (other, _) => panic!("{tail:?}: {other:?}"),
            }
        }
    }

    #[test]
    fn csv_missing_a_column_names_it() {
        let csv = temp_file(
            "nosway.csv",
            "omega,beta_deg,surge,yaw\n0.3,0,100,0\n2.0,0,900,0\n",
        );
        let err = parse_text(&minimal_with_csv(&csv)).expect_err("missing column");
        std::fs::remove_file(&csv).expect("remove temporary file");
        assert!(
            matches!(&err, Error::Parse { line: Some(1), message, .. } if message.contains("\"sway\"")),
            "{err:?}"
        );
    }

    /// A database holding MINIMAL's drift table, made with `rho` and g = 9.80665.
    fn database_with_minimal_drift(rho: f64) -> HydroDatabase {
        use crate::hydro::io::database::{DriftPoint, FORMAT_VERSION};
        let point = |omega: f64, surge: f64| DriftPoint {
            omega,
            heading: 0.0,
            surge,
            sway: 0.0,
            yaw: 0.0,
            damping: None,
        };
        HydroDatabase {
            format_version: FORMAT_VERSION,
            name: "minimal".into(),
            source: "test".into(),
            water_density: rho,
            gravity: 9.80665,
            mass_properties: None,
            low_frequency_added_mass: None,
            stiffness: None,
            drift: vec![point(0.3, 100.0), point(2.0, 900.0)],
            qtf: None,
            bidirectional_drift: None,
            provenance: Default::default(),
        }
    }

    /// A database's bi-directional table reaches the configuration; `bidirectional =
    /// "column-array"` takes the solver instead, and refuses to shadow a table.
    #[test]
    fn database_bidirectional_drift_sources() {
        use crate::hydro::bidirectional::BidirectionalTable;
        let json = temp_file("db-bidirectional.json", "");
        let dir = json.parent().expect("temp dir");
        let name = json.file_name().expect("file name").to_string_lossy();
        let head = MINIMAL.split("[drift]").next().expect("drift section");
        let text = format!("{head}[drift]\nsource = \"database\"\nfile = \"{name}\"\n");
        let with_columns = format!(
            "{head}[[platform.columns]]\nx = 20.0\ny = 0.0\ndiameter = 8.0\ndraft = 10.0\n\
             [drift]\nsource = \"database\"\nfile = \"{name}\"\nbidirectional = \"column-array\"\n"
        );
        let mut database = database_with_minimal_drift(1025.0);
        database.save(&json).expect("writable");
        let solver = problem(&with_columns, dir).expect("valid");
        let table = BidirectionalTable {
            omegas: vec![0.3, 2.0],
            headings: vec![0.0],
            re: vec![vec![vec![[1.0, 0.0, 0.0]]]; 2],
            im: vec![vec![vec![[0.0; 3]]]; 2],
        };
        database.bidirectional_drift = Some(table.clone());
        database.save(&json).expect("writable");
        let own = problem(&text, dir).expect("valid");
        let clash = problem(&with_columns, dir).expect_err("two sources");
        std::fs::remove_file(&json).expect("remove temporary file");
        assert!(matches!(
            solver.hydro.bidirectional,
            Some(BidirectionalSource::ColumnArray { ref omegas, .. }) if omegas == &[0.3, 2.0]
        ));
        assert_eq!(
            own.hydro.bidirectional,
            Some(BidirectionalSource::Table(table))
        );
        let message = clash.to_string();
        assert!(
            message.contains("bidirectional = \"column-array\"")
                && message.contains("own bidirectional_drift"),
            "{message}"
        );
    }

    #[test]
    fn database_drift_is_read_relative_to_the_base_directory() {
        let json = temp_file("db.json", "");
        database_with_minimal_drift(1025.0)
            .save(&json)
            .expect("writable");
        let dir = json.parent().expect("temp dir");
        let name = json.file_name().expect("file name").to_string_lossy();
        let head = MINIMAL.split("[drift]").next().expect("drift section");
        let text = format!("{head}[drift]\nsource = \"database\"\nfile = \"{name}\"\n");
        let from_database = problem(&text, dir);

        database_with_minimal_drift(1000.0)
            .save(&json)
            .expect("writable");
        let mismatch = problem(&text, dir).expect_err("rho differs");
        std::fs::remove_file(&json).expect("remove temporary file");
        let mut from_database = from_database.expect("valid file");
        // The database has no body data, but it is named as their source.
        assert_eq!(from_database.hydro.body.name, json.display().to_string());
        from_database.hydro.body = Default::default();
        let inline = parse_text(MINIMAL).expect("valid file");
        assert!(from_database.hydro.source.starts_with("the database "));
        from_database.hydro.source = inline.hydro.source.clone();
        assert_eq!(from_database, inline);
        let message = mismatch.to_string();
        assert!(
            message.starts_with("test.toml:") && message.contains("water_density = 1000"),
            "{message}"
        );
    }

    /// MINIMAL with its drift from a database whose QTF spans `omegas` at `heading_deg`,
    /// and `model` as the [model] section.
    fn with_qtf_database(
        stem: &str,
        omegas: &[f64],
        heading_deg: f64,
        model: &str,
    ) -> Result<Problem> {
        use crate::hydro::io::database::{QtfData, QtfMatrix};
        use crate::model::Dof;
        let n = omegas.len();
        let mut database = database_with_minimal_drift(1025.0);
        database.qtf = Some(QtfData {
            omegas: omegas.to_vec(),
            blocks: Dof::ALL
                .into_iter()
                .map(|dof| QtfMatrix {
                    dof,
                    heading: heading_deg.to_radians(),
                    second_heading: None,
                    re: (0..n)
                        .map(|i| (0..n).map(|j| 1.0e3 * (1 + i + j) as f64).collect())
                        .collect(),
                    im: (0..n)
                        .map(|i| (0..n).map(|j| 10.0 * (i as f64 - j as f64)).collect())
                        .collect(),
                })
                .collect(),
        });
        let json = temp_file(stem, "");
        database.save(&json).expect("writable");
        let dir = json.parent().expect("temp dir");
        let name = json.file_name().expect("file name").to_string_lossy();
        let head = MINIMAL.split("[drift]").next().expect("drift section");
        let text = format!("{head}{model}\n[drift]\nsource = \"database\"\nfile = \"{name}\"\n");
        let config = problem(&text, dir);
        std::fs::remove_file(&json).expect("remove temporary file");
        config
    }

    #[test]
    fn full_qtf_mode_takes_the_database_qtf_and_names_what_is_missing() {
        // PM, Tp = 8 s: the default band is 0.39 .. 3.14 rad/s.
        let covering = [0.3, 1.0, 2.0, 3.5];
        let full = "[model]\nsecond_order = \"full-qtf\"\nqtf_tolerance = 1e-4";
        let config = with_qtf_database("qtf-ok.json", &covering, 0.0, full).expect("valid");
        assert_eq!(config.model.second_order, SecondOrder::FullQtf);
        assert_eq!(config.model.qtf_tolerance, 1e-4);
        assert_eq!(config.hydro.qtf.as_ref().map(|q| q.omegas.len()), Some(4));
        let defaults = with_qtf_database("qtf-default.json", &covering, 0.0, "").expect("valid");
        assert_eq!(defaults.model.second_order, SecondOrder::Newman);
        assert!(
            defaults.hydro.qtf.is_some(),
            "the QTF is carried even when unused"
        );

        let short = with_qtf_database("qtf-short.json", &[0.3, 1.0, 2.0], 0.0, full)
            .expect_err("band not covered")
            .to_string();
        assert!(short.contains("2.0000 .. 3.1416 rad/s"), "{short}");
        let heading = with_qtf_database("qtf-heading.json", &covering, 30.0, full)
            .expect_err("no QTF at 0 deg")
            .to_string();
        assert!(
            heading.contains("0.000 deg") && heading.contains("30.000 deg"),
            "{heading}"
        );
        let tolerance = "[model]\nsecond_order = \"full-qtf\"\nqtf_tolerance = 0.0";
        assert!(with_qtf_database("qtf-tol.json", &covering, 0.0, tolerance)
            .expect_err("zero tolerance")
            .to_string()
            .contains("[model] qtf_tolerance"));
        let newman = "[model]\nqtf_tolerance = 1e-4";
        assert!(with_qtf_database("qtf-newman.json", &covering, 0.0, newman)
            .expect_err("tolerance without full-qtf")
            .to_string()
            .contains("qtf_tolerance"));
        let no_qtf = MINIMAL.replace("[drift]", "[model]\nsecond_order = \"full-qtf\"\n\n[drift]");
        assert!(error_text(&no_qtf).contains("needs a QTF"));
    }

    #[test]
    fn unreadable_csv_is_an_io_error() {
        let missing = std::env::temp_dir().join("slowdrift-config-no-such-file.csv");
        let err = parse_text(&minimal_with_csv(&missing)).expect_err("no file");
        assert!(matches!(err, Error::Io { .. }), "{err:?}");
    }

    #[test]
    fn example_file_loads() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/example.toml");
        let config =
            resolve(&load(&path, limits::DEFAULT_MEMORY_LIMIT).expect("the example is valid"))
                .expect("resolves");
        assert_eq!(config.hydro.drift.headings().len(), 2);
        assert_eq!(config.hydro.drift.omegas().len(), 6);
        let band = config.sea.band();
        config
            .hydro
            .drift
            .check_covers(band, &[config.sea.mean_direction])
            .expect("the example's drift table covers its sea state");
    }
}
