//! Where the mean drift comes from: `[drift]`, tagged by its `source`.

use super::Source;
use crate::error::numbers::written;
use crate::error::{Error, Result};
use crate::hydro::io::drift_csv::DriftFields;
use crate::hydro::DriftTable;
use crate::model::BidirectionalDrift;
use crate::scenario::{ColumnGrid, DriftSource};
use serde::Deserialize;
use std::ops::Range;
use std::path::{Path, PathBuf};

/// `[drift]`, tagged by `source`. A new source is a new variant and a new arm in
/// [`DriftFile::into_source`].
#[derive(Deserialize)]
#[serde(tag = "source", rename_all = "kebab-case", deny_unknown_fields)]
pub(super) enum DriftFile {
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
    pub(super) fn into_source(
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
    use super::super::parse;
    use super::super::tests::{error_text, minimal_with_drift, read, MINIMAL};
    use super::*;

    /// MINIMAL's drift rows, and how tests replace them.
    const ROWS: &str = "rows = [[0.3, 0, 100, 0, 0], [2.0, 0, 900, 0, 0]]";

    #[test]
    fn unknown_key_in_the_drift_section_is_refused() {
        let text = MINIMAL.replace("source = \"table\"", "source = \"table\"\nunits = \"si\"");
        assert!(error_text(&text).contains("units"));
    }

    #[test]
    fn hole_in_the_drift_table_is_refused() {
        let text = MINIMAL.replace(
            ROWS,
            "rows = [[0.3, 0, 100, 0, 0], [2.0, 0, 900, 0, 0], [0.3, 90, 0, 100, 0]]",
        );
        assert!(error_text(&text).contains("hole in the drift table"));
    }

    #[test]
    fn unsorted_drift_frequencies_are_refused() {
        let text = MINIMAL.replace(ROWS, "rows = [[2.0, 0, 900, 0, 0], [0.3, 0, 100, 0, 0]]");
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

    /// An inline drift table of 40 000 rows is read in well under a second, and a row's
    /// error names its line (each value's line was found by counting the newlines before
    /// it: 23 s for this table).
    #[test]
    fn a_long_inline_table_is_located_in_linear_time() {
        let rows: String = (1..=40_000)
            .map(|k| format!("[{}, 0, 100, 0, 0],\n", k as f64 * 1e-4))
            .collect();
        let text = MINIMAL.replace(ROWS, &format!("rows = [\n{rows}[-1, 0, 0, 0, 0]]"));
        let last = text.lines().position(|l| l.starts_with("[-1")).unwrap() + 1;
        let message = error_text(&text);
        assert!(
            message.starts_with(&format!("test.toml:{last}: invalid [drift] rows[40000]")),
            "{message}"
        );
    }

    /// A file the section names is relative to the configuration's directory, and read when
    /// the scenario is resolved (`problem::resolve`), not here.
    #[test]
    fn files_are_named_relative_to_the_base_directory() {
        let dir = Path::new("some/dir");
        let at = |drift: &str| {
            parse(&minimal_with_drift(drift), "test.toml", dir)
                .unwrap()
                .hydro
        };
        assert_eq!(
            at("source = \"csv\"\nfile = \"drift.csv\""),
            DriftSource::Csv(dir.join("drift.csv"))
        );
        assert_eq!(
            at("source = \"database\"\nfile = \"db.json\""),
            DriftSource::Database {
                path: dir.join("db.json"),
                bidirectional_from_columns: false,
            }
        );
        assert_eq!(
            at("source = \"database\"\nfile = \"db.json\"\nbidirectional = \"column-array\""),
            DriftSource::Database {
                path: dir.join("db.json"),
                bidirectional_from_columns: true,
            }
        );
        let text = minimal_with_drift(
            "source = \"database\"\nfile = \"db.json\"\nbidirectional = \"own\"",
        );
        assert!(error_text(&text).contains("expected `column-array`"));
    }

    #[test]
    fn column_solver_grids_are_read_and_checked() {
        let grid = |keys: &str| {
            read(&minimal_with_drift(&format!(
                "source = \"columns\"\n{keys}"
            )))
        };
        assert_eq!(
            grid("").unwrap().hydro,
            DriftSource::IsolatedColumns(ColumnGrid {
                omega_min: COLUMNS_OMEGA_MIN,
                omega_max: COLUMNS_OMEGA_MAX,
                n_omega: COLUMNS_N_OMEGA,
                heading_step: COLUMNS_HEADING_STEP_DEG.to_radians(),
            })
        );
        let message = grid("omega_min = 2.0\nomega_max = 1.0")
            .unwrap_err()
            .to_string();
        assert!(
            message.contains("need 0 < omega_min < omega_max"),
            "{message}"
        );
    }
}
