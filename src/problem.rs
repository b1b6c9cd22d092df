//! A [`Problem`]: a scenario with its hydrodynamics resolved, checked once, ready for a
//! [`crate::Simulation`].
//!
//! [`resolve`] turns a [`Scenario`]'s [`DriftSource`] into data ([`Hydro`]): it reads the CSV
//! or database file, or runs the column solver, once. [`Problem::validate`] is the one check
//! of every field; [`crate::RecordPlan::new`] calls it ([`Problem::check`]) before any record
//! is made. Errors name
//! fields by their configuration-file keys (`sea.hs`, `current.direction_deg`), in the file's
//! units; the scenario's [`crate::scenario::Origins`] then say where the value was written.

use crate::error::numbers::{readable, typable_below, written, written_matrix};
use crate::error::{
    require_finite, require_finite_matrix, require_non_negative, require_positive, Error, Result,
};
use crate::files::read_text;
use crate::hydro::aranha::aranha_damping;
use crate::hydro::bidirectional::BidirectionalSource;
use crate::hydro::column_drift::isolated_columns_table;
use crate::hydro::columns::ColumnArray;
use crate::hydro::default_platform;
use crate::hydro::io::database::{self, HydroDatabase};
use crate::hydro::io::drift_csv;
use crate::hydro::qtf::{check_tolerance, Qtf};
use crate::hydro::DriftTable;
use crate::model::{
    BidirectionalDrift, Dof, DragModel, DriftDamping, Environment, Interaction, Mode, SecondOrder,
};
use crate::scenario::default::{default_scenario, DEFAULT_DRIFT_LABEL};
use crate::scenario::{file, limits, ColumnGrid, DriftSource, Platform, Scenario};
use serde::Serialize;
use std::path::Path;

pub mod inertia;
pub mod ranges;
mod steps;
mod summary;
pub use inertia::{BodyData, Inertia, Origin};

/// The hydrodynamic data of a problem.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Hydro {
    /// What the data are and where they come from, one phrase for the run's summary
    /// ([`Problem::summary`]).
    pub source: String,
    /// The body data the drift source's data hold (a database's mass properties and
    /// low-frequency added mass), for [`Problem::inertia`].
    pub body: BodyData,
    /// Mean drift (and, when given, the wave-drift damping b_ij) per unit amplitude squared.
    pub drift: DriftTable,
    /// The full difference-frequency QTF (uni-directional headings), when the drift source
    /// has one; used by [`SecondOrder::FullQtf`].
    pub qtf: Option<Qtf>,
    /// The bi-directional drift, when the drift source has it (the column-array solver, a
    /// database with a `bidirectional_drift` table); used by [`Interaction::Bidirectional`].
    pub bidirectional: Option<BidirectionalSource>,
}

impl Hydro {
    /// A drift table alone.
    pub fn from_drift(drift: DriftTable) -> Hydro {
        Hydro {
            source: "a drift table".to_string(),
            body: BodyData::default(),
            drift,
            qtf: None,
            bidirectional: None,
        }
    }
}

/// Everything one simulation needs: the scenario with its hydrodynamics resolved.
pub type Problem = Scenario<Hydro>;

/// The finest fraction of a step a time must resolve: times t with |t| eps <=
/// TIME_RESOLUTION h (eps the double's relative spacing, 2.2e-16), so that the step count,
/// the communication points and the records' sample index stay exact.
pub const TIME_RESOLUTION: f64 = 1e-6;

/// The spacing of doubles near `t`, s (an upper bound: |t| eps).
pub fn time_spacing(t: f64) -> f64 {
    t.abs() * f64::EPSILON
}

/// Whether a double resolves times near `t` to [`TIME_RESOLUTION`] of a step `h`.
pub fn time_resolved(t: f64, h: f64) -> bool {
    time_spacing(t) <= TIME_RESOLUTION * h
}

/// The largest |t| that [`time_resolved`] accepts for a step `h`, s (4.5e9 h).
pub fn largest_resolved_time(h: f64) -> f64 {
    TIME_RESOLUTION * h / f64::EPSILON
}

/// Resolves the scenario's drift source into data: reads its file or runs its solver, once.
/// (The problem is checked where the records are planned, [`Problem::check`].)
pub fn resolve(scenario: &Scenario) -> Result<Problem> {
    limits::check_sizes(scenario, Some(&scenario.hydro)).map_err(|e| scenario.origins.locate(e))?;
    let hydro = resolve_hydro(
        &scenario.hydro,
        &scenario.platform,
        &scenario.environment,
        scenario.run.memory_limit,
    )
    .map_err(|e| scenario.origins.locate(e))?;
    Ok(scenario.clone().with_hydro(hydro))
}

/// The problem of the configuration file at `path`: read (within the default memory limit,
/// none being given outside the file) and resolved (within its own).
pub fn load(path: &Path) -> Result<Problem> {
    resolve(&file::load(path, limits::DEFAULT_MEMORY_LIMIT)?)
}

/// The embedded default platform and sea, resolved (its column solver runs: about a second).
pub fn default_problem() -> Result<Problem> {
    resolve(&default_scenario()?)
}

/// The data of a drift source for a platform in an environment, its files read within
/// `memory_limit` bytes.
pub fn resolve_hydro(
    source: &DriftSource,
    platform: &Platform,
    environment: &Environment,
    memory_limit: f64,
) -> Result<Hydro> {
    let described = |hydro: Hydro, source: String| Hydro { source, ..hydro };
    match source {
        DriftSource::Table(table) => Ok(described(
            Hydro::from_drift(table.clone()),
            "the configuration's [drift] table".to_string(),
        )),
        DriftSource::Csv(path) => Ok(described(
            Hydro::from_drift(drift_csv::read(path, memory_limit)?),
            format!("the CSV drift table {}", path.display()),
        )),
        DriftSource::Database {
            path,
            bidirectional_from_columns,
        } => {
            let text = read_text(path, &database::READING, memory_limit)?;
            let name = path.display().to_string();
            from_database(
                HydroDatabase::parse(&text, &name)?,
                (&text, &name),
                *bidirectional_from_columns,
                platform,
                environment,
            )
        }
        DriftSource::DefaultPlatform => {
            let (text, name) = (default_platform::DATABASE, default_platform::DATABASE_NAME);
            let hydro = from_database(
                HydroDatabase::parse(text, name)?,
                (text, name),
                false,
                platform,
                environment,
            )?;
            Ok(Hydro {
                source: format!("the embedded default platform's {DEFAULT_DRIFT_LABEL}"),
                bidirectional: Some(BidirectionalSource::Embedded {
                    name: default_platform::BIDIRECTIONAL_NAME,
                    json: default_platform::BIDIRECTIONAL,
                }),
                ..hydro
            })
        }
        DriftSource::IsolatedColumns(grid) => {
            if platform.columns.is_empty() {
                return Err(Error::invalid(
                    "drift.source",
                    "columns",
                    "needs [[platform.columns]]",
                ));
            }
            let (omegas, headings) = grid_nodes(grid);
            Ok(described(
                Hydro::from_drift(isolated_columns_table(
                    &platform.columns,
                    environment,
                    &omegas,
                    &headings,
                )?),
                format!(
                    "the closed-form drift of the {} columns, each alone in deep water (no \
                     interaction)",
                    platform.columns.len()
                ),
            ))
        }
        DriftSource::ColumnArray { grid, depth } => {
            let (omegas, headings) = grid_nodes(grid);
            let array = ColumnArray::new(platform.columns.clone(), *depth)?;
            let drift = array.drift_table(environment, &omegas, &headings)?;
            Ok(Hydro {
                source: format!(
                    "the column-array solver (Linton & Evans 1990) on the {} columns, {}",
                    platform.columns.len(),
                    depth.map_or("deep water".to_string(), |h| format!(
                        "bottom-mounted in {h} m of water"
                    ))
                ),
                body: BodyData::default(),
                drift,
                qtf: None,
                bidirectional: Some(BidirectionalSource::ColumnArray { array, omegas }),
            })
        }
    }
}

/// The data of a database read from `(text, name)` (the name says where it came from in
/// errors, which are located in the text): its drift table, QTF and bi-directional drift,
/// or the column solver's bi-directional drift on the platform's columns at the database's
/// frequencies when `bidirectional_from_columns`.
fn from_database(
    database: HydroDatabase,
    (text, name): (&str, &str),
    bidirectional_from_columns: bool,
    platform: &Platform,
    environment: &Environment,
) -> Result<Hydro> {
    let made_with = (database.water_density, database.gravity);
    if made_with != (environment.water_density, environment.gravity) {
        return Err(Error::invalid(
            "drift.file",
            name,
            format!(
                "the database was made with water_density = {}, gravity = {}, but \
                 [environment] has {}, {}: set [environment] to the database's values \
                 or re-import with them",
                written(made_with.0),
                written(made_with.1),
                written(environment.water_density),
                written(environment.gravity)
            ),
        ));
    }
    let drift = database
        .to_drift_table()
        .map_err(|e| database::locate(e, text, name))?;
    let qtf = database.qtf.as_ref().map(|q| q.to_qtf());
    let bidirectional = match (database.bidirectional_drift, bidirectional_from_columns) {
        (own, false) => own.map(BidirectionalSource::Table),
        (None, true) => Some(BidirectionalSource::ColumnArray {
            array: ColumnArray::new(platform.columns.clone(), None)?,
            omegas: drift.omegas().to_vec(),
        }),
        (Some(_), true) => {
            return Err(Error::invalid(
                "drift.bidirectional",
                format!("\"{}\"", BidirectionalDrift::ColumnArray.word()),
                format!(
                    "the database {name} has its own bidirectional_drift table: use one of them"
                ),
            ))
        }
    };
    let source = format!(
        "the database {name} (\"{}\"{}{})",
        database.name,
        if qtf.is_some() { "; with a QTF" } else { "" },
        if bidirectional.is_some() {
            "; with bi-directional drift"
        } else {
            ""
        }
    );
    Ok(Hydro {
        source,
        body: BodyData {
            name: name.to_string(),
            mass_properties: database.mass_properties,
            added_mass: database.low_frequency_added_mass,
            provenance: database.provenance,
        },
        drift,
        qtf,
        bidirectional,
    })
}

/// The frequencies (evenly spaced from min to max) and headings (every step from 0 up to,
/// not including, a full turn; computed in degrees, as the file gives the step) of a
/// column-solver grid, rad/s and rad. The grid was checked when it was read.
fn grid_nodes(grid: &ColumnGrid) -> (Vec<f64>, Vec<f64>) {
    let n = grid.n_omega;
    let omegas = (0..n)
        .map(|i| grid.omega_min + (grid.omega_max - grid.omega_min) * i as f64 / (n - 1) as f64)
        .collect();
    let n_headings = (360.0 / grid.heading_step.to_degrees()).round() as usize;
    let headings = (0..n_headings)
        .map(|i| (i as f64 * 360.0 / n_headings as f64).to_radians())
        .collect();
    (omegas, headings)
}

/// The largest share of the spectrum's variance that limiting the default band to the
/// hydrodynamic data may leave out ([`Problem::band`]).
pub const DEFAULT_BAND_TRIM_LIMIT: f64 = 0.01;

/// The default band limited to the hydrodynamic data ([`Problem::band_trim`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BandTrim {
    /// The spectrum's default band, rad/s.
    pub default: (f64, f64),
    /// The band simulated: the default band within the data's frequencies, rad/s.
    pub band: (f64, f64),
    /// The share of the default band's variance left out.
    pub variance_left_out: f64,
}

impl Problem {
    /// The rigid-body mass, yaw inertia and low-frequency added mass the equations of motion
    /// use, each from the configuration or the hydrodynamic data ([`inertia`]'s rule), or
    /// the error that names what is missing.
    pub fn inertia(&self) -> Result<Inertia> {
        Inertia::resolve(&self.platform, &self.hydro.body).map_err(|missing| {
            let data = if missing.data.is_empty() {
                format!("{} holds no mass properties", self.hydro.source)
            } else {
                format!("{} has no mass_properties", missing.data)
            };
            Error::invalid(
                missing.key,
                "(not given)",
                format!("is required: {data}; give it in [platform]"),
            )
        })
    }

    /// The undamped surge natural period 2 pi sqrt((M + A11) / C11), s; `None` without
    /// surge stiffness (or without a mass).
    pub fn surge_natural_period(&self) -> Option<f64> {
        self.inertia()
            .ok()?
            .uncoupled_periods(&self.platform.stiffness)[0]
    }

    /// The default start-up transient, s: [`crate::scenario::TRANSIENT_CYCLES`] surge
    /// natural periods, at most half the run (0 without surge stiffness).
    pub fn default_transient(&self) -> f64 {
        self.surge_natural_period().map_or(0.0, |period| {
            (crate::scenario::TRANSIENT_CYCLES * period).min(0.5 * self.run.duration)
        })
    }

    /// The simulated band (omega_min, omega_max), rad/s: `sea.band` when the user set it;
    /// otherwise the spectrum's default band ([`crate::sea_state::SeaState::band`]), limited
    /// to the frequencies the hydrodynamic data cover (the drift table, and the QTF under
    /// `second_order = "full-qtf"`) when they stop inside it and what is left out holds at
    /// most [`DEFAULT_BAND_TRIM_LIMIT`] of the default band's variance ([`Problem::band_trim`]).
    /// A data file whose last frequency, computed from a printed period, is 2.4999 rad/s
    /// thus serves the default band to 2.5133 rad/s of Tp = 10 s. Beyond the limit the
    /// default band is kept and the coverage checks name the gap.
    pub fn band(&self) -> (f64, f64) {
        self.band_trim()
            .map_or_else(|| self.sea.band(), |trim| trim.band)
    }

    /// How the default band was limited to the data ([`Problem::band`]), or `None` when it
    /// was not (the user set `sea.band`, the data cover the default band, or limiting it
    /// would leave out more than [`DEFAULT_BAND_TRIM_LIMIT`] of the variance).
    pub fn band_trim(&self) -> Option<BandTrim> {
        if self.sea.band.is_some() {
            return None;
        }
        let default = self.sea.band();
        let mut cover = {
            let w = self.hydro.drift.omegas();
            (w[0], w[w.len() - 1])
        };
        if let (SecondOrder::FullQtf, Some(q)) = (self.model.second_order, &self.hydro.qtf) {
            if let (Some(&lo), Some(&hi)) = (q.omegas.first(), q.omegas.last()) {
                cover = (cover.0.max(lo), cover.1.min(hi));
            }
        }
        let tolerance = crate::model::FREQUENCY_MATCH_TOLERANCE;
        let band = (
            if default.0 < cover.0 * (1.0 - tolerance) {
                cover.0
            } else {
                default.0
            },
            if default.1 > cover.1 * (1.0 + tolerance) {
                cover.1
            } else {
                default.1
            },
        );
        if band == default || band.0 >= band.1 {
            return None;
        }
        let variance = |a: f64, b: f64| {
            if b <= a {
                return 0.0;
            }
            let panels = 400;
            let h = (b - a) / panels as f64;
            let density = |w: f64| self.sea.spectrum.density(w);
            let inner: f64 = (1..panels)
                .map(|i| if i % 2 == 1 { 4.0 } else { 2.0 } * density(a + i as f64 * h))
                .sum();
            (density(a) + inner + density(b)) * h / 3.0
        };
        let total = variance(default.0, default.1);
        let left_out = (variance(default.0, band.0) + variance(band.1, default.1)) / total;
        (left_out <= DEFAULT_BAND_TRIM_LIMIT).then_some(BandTrim {
            default,
            band,
            variance_left_out: left_out,
        })
    }

    /// The drift table with the wave-drift damping a run of this problem uses: the table's
    /// own b_ij (`drift_damping = "table"`), Aranha's on its nodes (`"aranha"`, whatever
    /// b_ij the table holds), or `None` (`"off"`).
    pub fn damping_table(&self) -> Result<Option<DriftTable>> {
        Ok(match self.model.drift_damping {
            DriftDamping::Off => None,
            DriftDamping::Table => Some(self.hydro.drift.clone()),
            DriftDamping::Aranha => Some(aranha_damping(
                &self.hydro.drift,
                self.environment.gravity,
                &self.platform.columns,
            )?),
        })
    }

    /// The steps of a run that keeps every step's output (the CLI's time series, a Monte
    /// Carlo run's statistics), round(duration / time_step), with a buffer for them
    /// reserved in `buffer` (one entry per sample: the steps and the initial state).
    /// Refused, located where the user wrote the duration, for an open-ended run (that is
    /// the FMU's) and for one whose samples cannot be allocated.
    pub fn reserve_recorded<T>(&self, buffer: &mut Vec<T>) -> Result<usize> {
        let run = &self.run;
        let refuse = |reason: String| {
            self.origins
                .locate(Error::invalid("run.duration", run.duration, reason))
        };
        if !run.duration.is_finite() {
            return Err(refuse(
                "is not finite: a run that records every step has an end (the FMU runs \
                 without one)"
                    .into(),
            ));
        }
        let steps = (run.duration / run.time_step).round();
        let bytes = (steps + 1.0) * std::mem::size_of::<T>() as f64;
        if bytes > run.memory_limit {
            return Err(self.origins.locate(limits::over_budget(
                "run.duration",
                run.duration,
                &format!(
                    "the output of {} steps of {} s",
                    readable(steps),
                    written(run.time_step)
                ),
                bytes,
                run,
            )));
        }
        let samples = steps as usize + 1;
        if steps >= usize::MAX as f64 || buffer.try_reserve_exact(samples).is_err() {
            return Err(refuse(format!(
                "needs {} steps of {} s whose {} of output cannot be allocated",
                readable(steps),
                written(run.time_step),
                crate::error::bytes_text(steps * std::mem::size_of::<T>() as f64)
            )));
        }
        Ok(steps as usize)
    }

    /// Times a double resolves to [`TIME_RESOLUTION`] of a step: the start time and, for a
    /// run with an end, the end (`start_time + duration`); an open-ended run is checked as
    /// it goes (`Simulation`). Refused naming the setting that moves the time out of reach.
    fn check_time_resolution(&self) -> Result<()> {
        let run = &self.run;
        let end = run.start_time + run.duration;
        for (key, value, time) in [
            ("run.start_time", run.start_time, run.start_time),
            ("run.duration", run.duration, end),
        ] {
            if time.is_finite() && !time_resolved(time, run.time_step) {
                return Err(Error::invalid(
                    key,
                    value,
                    format!(
                        "reaches t = {} s, where a double resolves time only to {} s: too \
                         coarse for steps of {} s (times within +-{} s keep a millionth of a \
                         step)",
                        readable(time),
                        readable(time_spacing(time)),
                        written(run.time_step),
                        readable(largest_resolved_time(run.time_step))
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The message of `error` with the settings it names as causes or remedies (those of a
    /// running simulation: [`Error::describe`]) as the user wrote them and where:
    /// `[sea] hs (platform.toml:14)`, `row 3, column 'cd' (cases.csv:4)`, and the drift data
    /// with their source and the `[drift]` that names them. `Display` names the key paths.
    pub fn explain(&self, error: &Error) -> String {
        struct Explained<'a>(&'a Problem, &'a Error);
        impl std::fmt::Display for Explained<'_> {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                let Explained(problem, error) = self;
                error.describe(f, &|key| match key {
                    "drift" => {
                        let source = &problem.hydro.source;
                        match problem.origins.name_and_place(key) {
                            (name, Some(at)) => {
                                format!("the drift data of {name} ({at}; {source})")
                            }
                            (name, None) => format!("the drift data of {name} ({source})"),
                        }
                    }
                    _ => problem.origins.name(key),
                })
            }
        }
        Explained(self, error).to_string()
    }

    /// [`Problem::validate`], the error located where the user wrote the value.
    pub fn check(&self) -> Result<()> {
        self.validate().map_err(|e| self.origins.locate(e))
    }

    /// Checks every field; the error names the first offending field (by its key path) and
    /// value.
    pub fn validate(&self) -> Result<()> {
        limits::check_sizes(self, None)?;
        ranges::GRAVITY.check("environment.gravity", self.environment.gravity)?;
        ranges::WATER_DENSITY.check("environment.water_density", self.environment.water_density)?;
        // The ranges first: a Tp of 1e-6 s is named as such, not as the steep sea it makes.
        self.check_sea_ranges()?;
        self.sea.validate(self.environment.gravity)?;
        ranges::CURRENT_SPEED.check("current.speed", self.current.speed)?;
        ranges::DIRECTION.check_degrees("current.direction_deg", self.current.direction)?;
        if self.run.duration.is_nan() || self.run.duration <= 0.0 {
            return Err(Error::invalid(
                "run.duration",
                self.run.duration,
                "must be greater than zero (infinite: an open-ended run)",
            ));
        }
        require_positive("run.time_step", self.run.time_step)?;
        require_positive("run.block_duration", self.run.block_duration)?;
        steps::check_steps(self)?;
        require_finite("run.start_time", self.run.start_time)?;
        self.check_time_resolution()?;
        steps::check_duration(self)?;
        self.validate_platform()?;
        if self.model.strips_per_column == 0 {
            return Err(Error::invalid(
                "model.strips_per_column",
                0,
                "must be at least 1",
            ));
        }
        match self.model.drag {
            DragModel::Off => {}
            DragModel::Separate { slow, fast } => {
                require_non_negative("model.cd_slow", slow)?;
                require_non_negative("model.cd_fast", fast)?;
            }
            DragModel::Combined { cd } => require_non_negative("model.cd", cd)?,
        }
        if self.model.drag != DragModel::Off && self.platform.columns.is_empty() {
            return Err(Error::invalid(
                "platform.columns",
                "[]",
                "viscous drag is on but the platform has no columns",
            ));
        }
        if self.model.drift_damping == DriftDamping::Table && !self.hydro.drift.has_damping() {
            return Err(Error::invalid(
                "model.drift_damping",
                DriftDamping::Table.word(),
                "this drift data has no wave-drift damping table (b11 .. b33; the embedded \
                 default has none): the damping choices that work with it are aranha and off",
            ));
        }
        self.validate_yaw_following()?;
        self.validate_qtf()?;
        self.validate_interaction()?;
        ranges::check_initial_state(&self.initial.position, &self.initial.velocity)
    }

    /// The sea's peak period and band within their physical ranges
    /// ([`ranges`]; `SeaState::validate` has checked their signs and the steepness).
    fn check_sea_ranges(&self) -> Result<()> {
        use crate::sea_state::Spectrum;
        // Hs is bounded by the breaking limit at this Tp (`SeaState::validate`).
        match &self.sea.spectrum {
            Spectrum::Jonswap { tp, .. } | Spectrum::PiersonMoskowitz { tp, .. } => {
                ranges::PEAK_PERIOD.check("sea.tp", *tp)?;
            }
            Spectrum::Tabulated { omega, .. } => {
                if let (Some(first), Some(last)) = (omega.first(), omega.last()) {
                    ranges::BAND.check("sea.omega", *first)?;
                    ranges::BAND.check("sea.omega", *last)?;
                }
            }
        }
        if let Some((lo, hi)) = self.sea.band {
            ranges::BAND.check("sea.band[0]", lo)?;
            ranges::BAND.check("sea.band[1]", hi)?;
        }
        ranges::DIRECTION.check_degrees("sea.direction_deg", self.sea.mean_direction)
    }

    /// The full QTF, when selected: present, covering the band, and its headings covering
    /// every wave direction (bilinear interpolation in the heading pair between data
    /// headings, never extrapolated; with the cross terms from the QTF, every pair of
    /// directions).
    fn validate_qtf(&self) -> Result<()> {
        if let Some(q) = &self.hydro.qtf {
            q.validate()?;
        }
        if self.model.second_order != SecondOrder::FullQtf {
            return Ok(());
        }
        check_tolerance(self.model.qtf_tolerance)?;
        let Some(q) = &self.hydro.qtf else {
            return Err(Error::invalid(
                "model.second_order",
                SecondOrder::FullQtf.word(),
                "needs a QTF: use [drift] source = \"database\" with a database that holds one \
                 (`slowdrift hydro wamit` with a .12d, .11d or .10d file, `slowdrift hydro \
                 nemoh`)",
            ));
        };
        let headings: Vec<f64> = self.sea.directions().iter().map(|d| d.heading).collect();
        let pairs: Vec<(f64, f64)> = if self.cross_terms_from_qtf() {
            headings
                .iter()
                .flat_map(|&a| headings.iter().map(move |&b| (a, b)))
                .collect()
        } else {
            headings.iter().map(|&a| (a, a)).collect()
        };
        for pair in pairs {
            for dof in Dof::ALL {
                q.interpolated(dof, pair).map_err(|e| {
                    Error::invalid(
                        "model.second_order",
                        SecondOrder::FullQtf.word(),
                        format!(
                            "the QTF does not serve the wave direction(s) ({:.3}, {:.3}) deg: {e}",
                            pair.0.to_degrees(),
                            pair.1.to_degrees()
                        ),
                    )
                })?;
            }
        }
        crate::hydro::qtf::check_covers(&q.omegas, self.band())
    }

    /// Whether the cross terms between the directions of a spread sea come from the
    /// bi-directional QTF: the full QTF is selected, the QTF has bi-directional blocks, the
    /// sea has several directions and the interaction is bi-directional (`auto` resolves to
    /// it with such a QTF).
    pub fn cross_terms_from_qtf(&self) -> bool {
        self.model.second_order == SecondOrder::FullQtf
            && self.sea.directions().len() > 1
            && self
                .hydro
                .qtf
                .as_ref()
                .is_some_and(|q| q.is_bidirectional())
            && self.interaction() == Interaction::Bidirectional
    }

    /// Yaw following: at least two headings, a finite increasing range that holds the
    /// initial yaw.
    fn validate_yaw_following(&self) -> Result<()> {
        let Some(yaw) = &self.model.yaw_following else {
            return Ok(());
        };
        if yaw.headings < 2 {
            return Err(Error::invalid(
                "model.yaw_following.headings",
                yaw.headings,
                "must be at least 2",
            ));
        }
        if let Some((min, max)) = yaw.range {
            require_finite("model.yaw_following.range_deg[0]", min)?;
            require_finite("model.yaw_following.range_deg[1]", max)?;
            if min >= max {
                return Err(Error::invalid(
                    "model.yaw_following.range_deg",
                    format!("[{:.3}, {:.3}] deg", min.to_degrees(), max.to_degrees()),
                    "needs min < max",
                ));
            }
            let theta = self.initial.position[2];
            if !(min..=max).contains(&theta) {
                return Err(Error::invalid(
                    "initial.heading_deg",
                    format!("{:.3} deg", theta.to_degrees()),
                    format!(
                        "the initial yaw is outside model.yaw_following.range_deg [{:.3}, {:.3}] deg",
                        min.to_degrees(),
                        max.to_degrees()
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Bi-directional interaction needs bi-directional data; a table must be sound.
    fn validate_interaction(&self) -> Result<()> {
        if let Some(BidirectionalSource::Table(table)) = &self.hydro.bidirectional {
            table.validate()?;
        }
        let qtf_has_it = self.model.second_order == SecondOrder::FullQtf
            && self
                .hydro
                .qtf
                .as_ref()
                .is_some_and(|q| q.is_bidirectional());
        if self.model.interaction == Interaction::Bidirectional
            && self.hydro.bidirectional.is_none()
            && !qtf_has_it
        {
            return Err(Error::invalid(
                "model.interaction",
                Interaction::Bidirectional.word(),
                "the drift source has no bi-directional drift (it comes from [drift] source = \
                 \"column-array\" or a database with a bidirectional_drift table); use \
                 interaction = \"mean-direction\" to approximate it from the drift table, or \
                 \"none\"",
            ));
        }
        Ok(())
    }

    /// The interaction actually used ([`Interaction::Auto`] resolved against the data:
    /// bi-directional when the drift source has the bi-directional drift, or under the full
    /// QTF a bi-directional QTF).
    pub fn interaction(&self) -> Interaction {
        let qtf_has_it = self.model.second_order == SecondOrder::FullQtf
            && self
                .hydro
                .qtf
                .as_ref()
                .is_some_and(|q| q.is_bidirectional());
        match (self.model.interaction, &self.hydro.bidirectional) {
            (Interaction::Auto, Some(_)) => Interaction::Bidirectional,
            (Interaction::Auto, None) if qtf_has_it => Interaction::Bidirectional,
            (Interaction::Auto, None) => Interaction::MeanDirection,
            (chosen, _) => chosen,
        }
    }

    /// The platform's values: the mass and inertia within their physical ranges (named where
    /// they came from: `platform.mass`, or the database's `mass_properties.mass`), M + A
    /// positive definite, the stiffness storing no negative energy and resolved by the RK4
    /// step, finite damping matrices, the columns within their ranges.
    fn validate_platform(&self) -> Result<()> {
        let p = &self.platform;
        if let Some(added) = &p.added_mass {
            require_finite_matrix("platform.added_mass", added)?;
        }
        let inertia = self.inertia()?;
        let named = |key: &str, origin: &Origin, data_field: &str| match origin {
            Origin::Data { name, .. } => format!("{data_field} of {name}"),
            _ => key.to_string(),
        };
        ranges::MASS.check(
            named(
                "platform.mass",
                &inertia.mass_origin,
                "mass_properties.mass",
            ),
            inertia.mass,
        )?;
        ranges::YAW_INERTIA.check(
            named(
                "platform.yaw_inertia",
                &inertia.yaw_inertia_origin,
                "mass_properties.yaw_inertia",
            ),
            inertia.yaw_inertia,
        )?;
        let rigid = [inertia.mass, inertia.mass, inertia.yaw_inertia];
        let total: [[f64; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|j| inertia.added_mass[i][j] + if i == j { rigid[i] } else { 0.0 })
        });
        if !ranges::mass_matrix_is_positive(&total) {
            return Err(Error::invalid(
                named(
                    "platform.added_mass",
                    &inertia.added_mass_origin,
                    "low_frequency_added_mass",
                ),
                written_matrix(&inertia.added_mass),
                format!(
                    "makes the mass matrix M + A (mass {} kg, yaw inertia {} kg m^2) not \
                     positive definite: no body has such a kinetic energy",
                    written(inertia.mass),
                    written(inertia.yaw_inertia)
                ),
            ));
        }
        require_finite_matrix("platform.stiffness", &p.stiffness)?;
        ranges::check_stiffness(&p.stiffness)?;
        self.check_stiffness_against_the_step(&inertia)?;
        require_finite_matrix("platform.linear_damping", &p.linear_damping)?;
        require_finite_matrix("platform.quadratic_damping", &p.quadratic_damping)?;
        self.validate_columns()
    }

    /// The columns within their ranges.
    fn validate_columns(&self) -> Result<()> {
        for (k, c) in self.platform.columns.iter().enumerate() {
            ranges::COLUMN_OFFSET.check(format!("platform.columns[{k}].x"), c.x)?;
            ranges::COLUMN_OFFSET.check(format!("platform.columns[{k}].y"), c.y)?;
            ranges::COLUMN_DIAMETER.check(format!("platform.columns[{k}].diameter"), c.diameter)?;
            ranges::COLUMN_DRAFT.check(format!("platform.columns[{k}].draft"), c.draft)?;
        }
        Ok(())
    }

    /// What the drift of the columns needs and nothing a run needs besides (`slowdrift
    /// hydro columns`, `study drift`): the environment and the columns within their ranges,
    /// the error located where the user wrote the value.
    pub fn check_columns(&self) -> Result<()> {
        let checked = ranges::GRAVITY
            .check("environment.gravity", self.environment.gravity)
            .and_then(|()| {
                ranges::WATER_DENSITY
                    .check("environment.water_density", self.environment.water_density)
            })
            .and_then(|()| self.validate_columns());
        checked.map_err(|e| self.origins.locate(e))
    }

    /// Each DOF's undamped natural period must be long enough for the RK4 step to follow:
    /// RK4 is unstable for an oscillator with omega h > 2 sqrt(2) (its stability region on
    /// the imaginary axis), so the period must exceed 2 pi h / (2 sqrt(2)) = 2.22 h. A
    /// stiffness that breaks it is refused naming the stiffness and the step.
    fn check_stiffness_against_the_step(&self, inertia: &Inertia) -> Result<()> {
        const KEYS: [&str; 3] = [
            "platform.stiffness[0][0]",
            "platform.stiffness[1][1]",
            "platform.stiffness[2][2]",
        ];
        let h = self.run.time_step;
        let shortest = 2.0 * std::f64::consts::PI * h / (2.0 * std::f64::consts::SQRT_2);
        for (i, period) in inertia
            .uncoupled_periods(&self.platform.stiffness)
            .into_iter()
            .enumerate()
        {
            if let Some(period) = period.filter(|t| *t <= shortest) {
                return Err(Error::invalid(
                    KEYS[i],
                    self.platform.stiffness[i][i],
                    format!(
                        "gives a natural period of {} s, too short for RK4 steps of {} s \
                         (unstable below 2.22 steps a period): lower the stiffness, or \
                         time_step to {} s or less",
                        readable(period),
                        written(h),
                        typable_below(period * h / shortest)
                    ),
                ));
            }
        }
        Ok(())
    }
}
