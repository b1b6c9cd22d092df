//! Resolving a [`Scenario`]'s drift source into data, once: its CSV or database file read,
//! or its column solver run ([`resolve`]). Nothing here checks the values: that is
//! [`Problem::check`]'s (`problem/checks.rs`).

use super::{BodyData, Hydro, Problem};
use crate::error::numbers::written;
use crate::error::{Error, Result};
use crate::files::read_text;
use crate::hydro::bidirectional::BidirectionalSource;
use crate::hydro::column_drift::isolated_columns_table;
use crate::hydro::columns::ColumnArray;
use crate::hydro::default_platform;
use crate::hydro::io::database::{self, HydroDatabase};
use crate::hydro::io::drift_csv;
use crate::model::{BidirectionalDrift, Environment, Mode};
use crate::scenario::default::{default_scenario, DEFAULT_DRIFT_LABEL};
use crate::scenario::{file, limits, ColumnGrid, DriftSource, Platform, Scenario};
use std::path::Path;

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
                default_platform::without_bidirectional()?,
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
            first_order: database.first_order,
            rao: database.rao,
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
