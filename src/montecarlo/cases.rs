//! The case table: a CSV file whose header names the settings it writes and whose every row
//! is one case on top of a base configuration.
//!
//! Columns (any subset, any order): `name`, and the case-table columns of the override
//! table ([`crate::scenario::overrides::SETTINGS`]: `hs`, `tp`, `gamma`, `direction_deg`,
//! `spreading_exponent`, `n_directions`, `current_speed`, `current_direction_deg`,
//! `wind_speed`, `wind_direction_deg`, `wind_spectrum`, `wind_reference_height`, `drag`,
//! `cd`, `cd_slow`, `cd_fast`, `drift_damping`, `interaction`, `yaw_headings`,
//! `surge_stiffness`, `sway_stiffness`, `yaw_stiffness`, `time_step`, `duration`), each with
//! the rule, unit and vocabulary of its setting: an override changes only what it names; a
//! value the base's choice does not use (`cd_slow` under combined drag) is refused; columns
//! ending in `_deg` are in degrees. An empty cell keeps the base value. Blank lines and lines
//! starting with `#` are skipped; fields are trimmed; quoting follows RFC 4180.
//!
//! A malformed table is an [`Error::Parse`] naming the file, the line, the data row and the
//! column. The table is read as a stream ([`CaseRows`], row by row), so that a table of any
//! length is read in the same memory (but for its names). A value the model refuses (a negative Hs, say) makes that case's runs fail, not
//! the table; its error names the row and column.

use super::Case;
use crate::error::{Error, Location, Result};
use crate::files::Cost;
use crate::model::DragModel;
use crate::scenario::overrides::{by_column, Refusal, Setting, Value, SETTINGS};
use crate::scenario::Written;
use crate::Problem;
use std::collections::HashMap;
use std::io::Read;
use std::path::Path;

/// One cell of a case table.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// A number, in the column's unit (degrees for a column ending in `_deg`).
    Number(f64),
    /// A word of the setting's vocabulary.
    Word(String),
}

/// One row of a case table: its name and the values it writes, by setting.
#[derive(Debug, Clone)]
pub struct CaseRow {
    /// 1-based data row (the header is not counted).
    pub row: usize,
    /// 1-based line in the file.
    pub line: usize,
    pub name: String,
    /// (setting, value) for every non-empty cell, in header order.
    pub cells: Vec<(&'static Setting, Cell)>,
}

/// The known column names, for messages.
fn columns() -> String {
    let names: Vec<&str> = std::iter::once("name")
        .chain(SETTINGS.iter().filter_map(|s| s.column))
        .collect();
    names.join(", ")
}

/// What reading a case table costs, every row kept ([`read_case_table`]): up to 160 bytes of
/// memory per byte of the file (measured on its costliest content: a column of one-digit
/// numbers, each a row with its generated name), with a margin for the allocator's own
/// overhead. Read as a stream, it keeps less: the names.
pub const READING: Cost = Cost {
    format: "case table",
    per_byte: 240.0,
};

/// Reads a case table file within `memory_limit` bytes (every row; [`open_case_table`]
/// reads them one at a time).
pub fn read_case_table(path: &Path, memory_limit: f64) -> Result<Vec<CaseRow>> {
    open_case_table(path, memory_limit)?.collect()
}

/// The rows of the case table file at `path`, read as they are asked for ([`CaseRows`]),
/// within `memory_limit` bytes (every row kept: [`READING`]).
pub fn open_case_table(path: &Path, memory_limit: f64) -> Result<CaseRows<crate::files::Input>> {
    let input = crate::files::open(path, &READING, memory_limit)?;
    CaseRows::new(input, &path.display().to_string())
}

/// Parses the text of a case table; `source` names it in errors.
pub fn parse_case_table(text: &str, source: &str) -> Result<Vec<CaseRow>> {
    CaseRows::new(text.as_bytes(), source)?.collect()
}

/// The header's columns: `None` for `name`, else the setting.
type Header = Vec<Option<&'static Setting>>;

/// The rows of a case table read from `R` one at a time: an iterator of [`CaseRow`]s that
/// ends after the first error. What it holds does not grow with the rows read but for the
/// names seen (a map from name to row, to refuse a name used twice).
pub struct CaseRows<R> {
    reader: csv::Reader<R>,
    /// The record read last (one buffer for every row).
    record: csv::StringRecord,
    source: String,
    header: Header,
    /// The header's fields as written.
    columns: Vec<String>,
    header_line: u64,
    /// Data rows read so far.
    rows: usize,
    /// The row of every name seen.
    names: HashMap<String, usize>,
    finished: bool,
}

impl<R: Read> CaseRows<R> {
    /// Reads the header of the table `input`; `source` names it in errors.
    pub fn new(input: R, source: &str) -> Result<Self> {
        let reader = csv::ReaderBuilder::new()
            .has_headers(false)
            .comment(Some(b'#'))
            .trim(csv::Trim::All)
            .flexible(true)
            .from_reader(input);
        let mut table = CaseRows {
            reader,
            record: csv::StringRecord::new(),
            source: source.to_string(),
            header: Vec::new(),
            columns: Vec::new(),
            header_line: 1,
            rows: 0,
            names: HashMap::new(),
            finished: false,
        };
        if !table.read_record()? {
            return Err(table.error(1, "the case table is empty (no header line)".into()));
        }
        table.header_line = table.line();
        for field in table.record.iter() {
            let setting = match field {
                "name" => None,
                _ => Some(by_column(field).ok_or_else(|| {
                    table.error(
                        table.header_line,
                        format!("unknown column '{field}'; the columns are {}", columns()),
                    )
                })?),
            };
            if table.columns.iter().any(|c| c == field) {
                return Err(
                    table.error(table.header_line, format!("column '{field}' appears twice"))
                );
            }
            table.columns.push(field.to_string());
            table.header.push(setting);
        }
        Ok(table)
    }

    /// The names of the rows read so far, in row order.
    pub fn names(&self) -> Vec<&str> {
        let mut names: Vec<(&str, usize)> = self
            .names
            .iter()
            .map(|(n, &row)| (n.as_str(), row))
            .collect();
        names.sort_by_key(|&(_, row)| row);
        names.into_iter().map(|(name, _)| name).collect()
    }

    fn error(&self, line: u64, message: String) -> Error {
        Location {
            path: self.source.clone(),
            line: usize::try_from(line).ok(),
        }
        .error(message)
    }

    /// The line of the record read last.
    fn line(&self) -> u64 {
        self.record
            .position()
            .map_or(self.header_line, csv::Position::line)
    }

    /// Reads the next record into `self.record`; `false` at the end of the table.
    fn read_record(&mut self) -> Result<bool> {
        self.reader.read_record(&mut self.record).map_err(|e| {
            let line = e.position().map(csv::Position::line);
            match e.kind() {
                csv::ErrorKind::Io(io) => Error::Io {
                    path: self.source.clone(),
                    message: io.to_string(),
                },
                _ => self.error(line.unwrap_or(self.header_line), e.to_string()),
            }
        })
    }

    /// The next row, `None` at the end of the table.
    fn next_row(&mut self) -> Result<Option<CaseRow>> {
        if !self.read_record()? {
            if self.rows == 0 {
                return Err(self.error(self.header_line, "the case table has no rows".into()));
            }
            return Ok(None);
        }
        self.rows += 1;
        let (row, line) = (self.rows, self.line());
        if self.record.len() != self.header.len() {
            return Err(self.error(
                line,
                format!(
                    "row {row} has {} fields, the header has {} ({})",
                    self.record.len(),
                    self.header.len(),
                    self.columns.join(", ")
                ),
            ));
        }
        let mut name = format!("case{row}");
        let mut cells = Vec::new();
        for ((setting, column), field) in self.header.iter().zip(&self.columns).zip(&self.record) {
            if field.is_empty() {
                continue;
            }
            let Some(setting) = setting else {
                if field.contains('"') {
                    return Err(self.error(
                        line,
                        format!("row {row}, column 'name': '{field}' contains a quote"),
                    ));
                }
                name = field.to_string();
                continue;
            };
            let cell = if setting.takes_words() {
                if !setting.words().any(|word| word == field) {
                    return Err(self.error(
                        line,
                        format!(
                            "row {row}, column '{column}': '{field}' is not one of {}",
                            setting.words().collect::<Vec<_>>().join(", ")
                        ),
                    ));
                }
                Cell::Word(field.to_string())
            } else {
                match field.parse::<f64>() {
                    Ok(v) if v.is_finite() => Cell::Number(v),
                    _ => {
                        return Err(self.error(
                            line,
                            format!(
                                "row {row}, column '{column}': '{field}' is not a finite number"
                            ),
                        ))
                    }
                }
            };
            cells.push((*setting, cell));
        }
        if let Some(&other) = self.names.get(&name) {
            return Err(self.error(
                line,
                format!("row {row}, column 'name': '{name}' is also the name of row {other}"),
            ));
        }
        self.names.insert(name.clone(), row);
        Ok(Some(CaseRow {
            row,
            line: line as usize,
            name,
            cells,
        }))
    }
}

impl<R: Read> Iterator for CaseRows<R> {
    type Item = Result<CaseRow>;

    fn next(&mut self) -> Option<Result<CaseRow>> {
        if self.finished {
            return None;
        }
        let next = self.next_row();
        self.finished = !matches!(next, Ok(Some(_)));
        next.transpose()
    }
}

impl CaseRow {
    /// The single case of a campaign without a case table.
    pub fn base() -> CaseRow {
        CaseRow {
            row: 1,
            line: 1,
            name: "base".into(),
            cells: Vec::new(),
        }
    }

    /// The number this row writes in `column`, in the column's unit, if any.
    pub fn number(&self, column: &str) -> Option<f64> {
        self.cells.iter().find_map(|(s, cell)| match cell {
            Cell::Number(x) if s.column == Some(column) => Some(*x),
            _ => None,
        })
    }

    /// The case: `base` with this row's values written in the override table's order, and
    /// its transient (`transient`, or the case's default when `None`). A value the base's
    /// choices do not use, or a drag model chosen without its coefficients, is an error
    /// naming the row and column.
    pub fn case(&self, base: &Problem, transient: Option<f64>, source: &str) -> Result<Case> {
        let at = Location {
            path: source.to_string(),
            line: Some(self.line),
        };
        let mut config = base.clone();
        for setting in &SETTINGS {
            let Some((_, cell)) = self.cells.iter().find(|(s, _)| std::ptr::eq(*s, setting)) else {
                continue;
            };
            let column = setting.column.expect("a case-table cell has a column");
            let value = match cell {
                Cell::Number(x) if setting.in_degrees() => Value::Number(x.to_radians()),
                Cell::Number(x) => Value::Number(*x),
                Cell::Word(w) => Value::Word(w),
            };
            let written = Written::CaseTable {
                at: at.clone(),
                row: self.row,
                column,
            };
            setting
                .apply(&mut config, value, written)
                .map_err(|refusal| {
                    let hint = match refusal {
                        Refusal::NotInForce(_) if setting.key.starts_with("model.cd") => {
                            " (add a 'drag' column)"
                        }
                        _ => "",
                    };
                    at.error(format!(
                        "row {}, column '{column}': {}{hint}",
                        self.row,
                        refusal.reason()
                    ))
                })?;
        }
        self.check_drag(&config.model.drag, &at)?;
        let transient = transient.unwrap_or_else(|| config.default_transient());
        Ok(Case {
            name: self.name.clone(),
            problem: config,
            transient,
        })
    }

    /// A drag model this row chose needs its coefficients in the row.
    fn check_drag(&self, drag: &DragModel, at: &Location) -> Result<()> {
        let missing = match *drag {
            DragModel::Combined { cd } if cd.is_nan() => "cd",
            DragModel::Separate { slow, .. } if slow.is_nan() => "cd_slow",
            DragModel::Separate { fast, .. } if fast.is_nan() => "cd_fast",
            _ => return Ok(()),
        };
        Err(at.error(format!(
            "row {}, column 'drag': the model chosen needs a '{missing}' column too",
            self.row
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Interaction, YawFollowing};
    use crate::scenario::DEFAULT_N_DIRECTIONS;
    use crate::sea_state::{Spectrum, Spreading};

    fn base() -> Problem {
        crate::problem::load(Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/data/example.toml"
        )))
        .unwrap()
    }

    fn cases(text: &str) -> Result<Vec<Case>> {
        parse_case_table(text, "cases.csv")?
            .iter()
            .map(|row| row.case(&base(), None, "cases.csv"))
            .collect()
    }

    #[test]
    fn interaction_column_sets_the_model_and_names_bad_values() {
        let parsed = cases("name, interaction\na, mean-direction\nb, none\nc,\n").unwrap();
        assert_eq!(
            parsed[0].problem.model.interaction,
            Interaction::MeanDirection
        );
        assert_eq!(parsed[1].problem.model.interaction, Interaction::None);
        assert_eq!(
            parsed[2].problem.model.interaction,
            base().model.interaction
        );
        let e = cases("interaction\nboth\n").unwrap_err().to_string();
        assert!(
            e.contains("row 1, column 'interaction': 'both' is not one of"),
            "{e}"
        );
    }

    #[test]
    fn overrides_reach_the_configuration_in_si_units() {
        let text = "name, hs, tp, gamma, direction_deg, spreading_exponent, current_speed, \
                    current_direction_deg, duration\n\
                    # a comment\n\
                    a, 4, 11, 0, 90, 2, 1.5, 45, 3600\n\
                    ,,,,,0,,,\n";
        let cases = cases(text).unwrap();
        let a = &cases[0].problem;
        assert_eq!(cases[0].name, "a");
        assert_eq!(
            a.sea.spectrum,
            Spectrum::Jonswap {
                hs: 4.0,
                tp: 11.0,
                gamma: None
            }
        );
        assert_eq!(a.sea.mean_direction, 90f64.to_radians());
        assert_eq!(a.sea.spreading, Spreading::CosN { n: 2.0 });
        assert_eq!(a.sea.n_directions, DEFAULT_N_DIRECTIONS);
        assert_eq!(a.current.speed, 1.5);
        assert_eq!(a.current.direction, 45f64.to_radians());
        assert_eq!(a.run.duration, 3600.0);
        assert_eq!(cases[0].transient, a.default_transient());
        // Row 2: only the spreading is set; everything else is the base.
        assert_eq!(cases[1].name, "case2");
        let mut expected = base();
        expected.sea.n_directions = 1;
        assert_eq!(cases[1].problem, expected);
    }

    /// A coefficient changes only its own model's; a model is chosen by the `drag` column,
    /// with its coefficients.
    #[test]
    fn drag_columns_choose_the_model() {
        let c = cases("drag, cd_slow, cd_fast\nseparate, 0.5, 0.9\n").unwrap();
        assert_eq!(
            c[0].problem.model.drag,
            DragModel::Separate {
                slow: 0.5,
                fast: 0.9
            }
        );
        let c = cases("cd\n1.1\n").unwrap();
        assert_eq!(c[0].problem.model.drag, DragModel::Combined { cd: 1.1 });
        // The example's drag is combined: a separate coefficient does not apply to it.
        let e = cases("cd_slow, cd_fast\n0.5, 0.9\n")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("row 1, column 'cd_slow': cd_slow applies when drag = separate")
                && e.contains("add a 'drag' column"),
            "{e}"
        );
        let e = cases("drag, cd_slow\nseparate, 0.5\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("needs a 'cd_fast' column"), "{e}");
        let e = cases("drag\noff\n").unwrap();
        assert_eq!(e[0].problem.model.drag, DragModel::Off);
        let e = cases("drag\nviscous\n").unwrap_err().to_string();
        assert!(
            e.contains("'viscous' is not one of off, separate, combined"),
            "{e}"
        );
    }

    #[test]
    fn yaw_columns_set_the_spring_and_the_yaw_following() {
        let c = cases("yaw_stiffness, yaw_headings\n6.0e7, 36\n, 0\n").unwrap();
        assert_eq!(c[0].problem.platform.stiffness[2][2], 6.0e7);
        assert_eq!(
            c[0].problem.model.yaw_following,
            Some(YawFollowing {
                headings: 36,
                range: None
            })
        );
        assert_eq!(c[1].problem, base());
        let e = cases("yaw_headings\n1\n").unwrap_err().to_string();
        assert!(e.contains("row 1, column 'yaw_headings'"), "{e}");
        let c = cases("yaw_headings\n-1\n").unwrap();
        assert_eq!(c[0].problem.model.yaw_following, None);
    }

    #[test]
    fn malformed_tables_name_the_row_and_column() {
        let cases_err = |t: &str| cases(t).unwrap_err().to_string();
        let e = cases_err("hs, tp\n3, 9\n4, x9\n");
        assert_eq!(
            e,
            "cases.csv:3: row 2, column 'tp': 'x9' is not a finite number"
        );
        let e = cases_err("hs, wind\n3, 9\n");
        assert!(e.starts_with("cases.csv:1: unknown column 'wind'"), "{e}");
        let e = cases_err("hs, tp\n3\n");
        assert!(
            e.starts_with("cases.csv:2: row 1 has 1 fields, the header has 2"),
            "{e}"
        );
        let e = cases_err("name, hs\na, 3\na, 4\n");
        assert!(
            e.contains("row 2, column 'name': 'a' is also the name of row 1"),
            "{e}"
        );
        let e = cases_err("n_directions\n2.5\n");
        assert!(e.contains("row 1, column 'n_directions'"), "{e}");
        let e = cases_err("hs\nnan\n");
        assert!(
            e.contains("row 1, column 'hs': 'nan' is not a finite number"),
            "{e}"
        );
        assert!(cases_err("hs\n").contains("no rows"));
    }
}
