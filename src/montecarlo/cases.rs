//! The case table: a CSV file whose header names the fields it overrides and whose every
//! row is one case on top of a base configuration.
//!
//! Columns (any subset, any order; an empty cell keeps the base value): `name`, `hs` (m),
//! `tp` (s), `gamma` (JONSWAP; 0 = the DNV default), `direction_deg`, `spreading_exponent`
//! (0 = long-crested, else the exponent of the base's spreading form: cos^N, or s of
//! cos-2s; a long-crested base becomes cos^N), `n_directions`, `current_speed` (m/s),
//! `current_direction_deg`, `cd` (combined drag model), `cd_slow` and `cd_fast` (separate
//! model; one of them alone keeps the other from a separate-model base), `duration` (s),
//! `yaw_stiffness` (N m/rad: the mooring's C_66), `yaw_headings` (0 = yaw following off,
//! n >= 2 = records at n body yaw angles around the full circle, `model.yaw_following`),
//! `interaction` (text: `auto`, `none`, `mean-direction` or `bidirectional`, as `[model]
//! interaction` of the configuration file).
//! Degrees are converted to radians here. Blank lines and lines starting with `#` are
//! skipped; fields are separated by commas and trimmed (no quoting).
//!
//! A malformed table is an [`Error::Parse`] naming the file, the line, the data row and the
//! column. Values are only checked for being numbers here: a value the model refuses (a
//! negative Hs, say) makes that case's runs fail, not the table.

use super::Case;
use crate::config::file::DEFAULT_N_DIRECTIONS;
use crate::error::{Error, Result};
use crate::model::{DragModel, Interaction, YawFollowing};
use crate::sea_state::{Spectrum, Spreading};
use crate::Config;
use std::path::Path;

/// The columns a case table may have.
pub const COLUMNS: [&str; 16] = [
    "name",
    "hs",
    "tp",
    "gamma",
    "direction_deg",
    "spreading_exponent",
    "n_directions",
    "current_speed",
    "current_direction_deg",
    "cd",
    "cd_slow",
    "cd_fast",
    "duration",
    "yaw_stiffness",
    "yaw_headings",
    "interaction",
];

/// One row of a case table: its name and the values it sets, by column name.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseRow {
    /// 1-based data row (the header is not counted).
    pub row: usize,
    /// 1-based line in the file.
    pub line: usize,
    pub name: String,
    /// (column, value) for every non-empty numeric cell, in header order.
    pub values: Vec<(&'static str, f64)>,
    /// The `interaction` cell, when given.
    pub interaction: Option<Interaction>,
}

/// Reads a case table file.
pub fn read_case_table(path: &Path) -> Result<Vec<CaseRow>> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    })?;
    parse_case_table(&text, &path.display().to_string())
}

/// Parses the text of a case table; `source` names it in errors.
pub fn parse_case_table(text: &str, source: &str) -> Result<Vec<CaseRow>> {
    let error = |line: usize, message: String| Error::Parse {
        path: source.to_string(),
        line: Some(line),
        message,
    };
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let (header_line, header) = lines
        .next()
        .ok_or_else(|| error(1, "the case table is empty (no header line)".into()))?;
    let mut columns: Vec<&'static str> = Vec::new();
    for field in header.split(',').map(str::trim) {
        let known = COLUMNS.iter().find(|c| **c == field).ok_or_else(|| {
            error(
                header_line,
                format!(
                    "unknown column '{field}'; the columns are {}",
                    COLUMNS.join(", ")
                ),
            )
        })?;
        if columns.contains(known) {
            return Err(error(
                header_line,
                format!("column '{field}' appears twice"),
            ));
        }
        columns.push(known);
    }
    if columns.contains(&"cd") && (columns.contains(&"cd_slow") || columns.contains(&"cd_fast")) {
        return Err(error(
            header_line,
            "columns 'cd' (combined drag) and 'cd_slow'/'cd_fast' (separate drag) exclude each \
             other"
                .into(),
        ));
    }
    let mut rows: Vec<CaseRow> = Vec::new();
    for (row, (line, text)) in lines.enumerate() {
        let row = row + 1;
        let fields: Vec<&str> = text.split(',').map(str::trim).collect();
        if fields.len() != columns.len() {
            return Err(error(
                line,
                format!(
                    "row {row} has {} fields, the header has {} ({})",
                    fields.len(),
                    columns.len(),
                    columns.join(", ")
                ),
            ));
        }
        let mut name = format!("case{row}");
        let mut values = Vec::new();
        let mut interaction = None;
        for (&column, &field) in columns.iter().zip(&fields) {
            if field.is_empty() {
                continue;
            }
            if column == "interaction" {
                interaction = Some(match field {
                    "auto" => Interaction::Auto,
                    "none" => Interaction::None,
                    "mean-direction" => Interaction::MeanDirection,
                    "bidirectional" => Interaction::Bidirectional,
                    _ => {
                        return Err(error(
                            line,
                            format!(
                                "row {row}, column 'interaction': '{field}' is not one of \
                                 auto, none, mean-direction, bidirectional"
                            ),
                        ))
                    }
                });
                continue;
            }
            if column == "name" {
                if field.contains('"') {
                    return Err(error(
                        line,
                        format!("row {row}, column 'name': '{field}' contains a quote"),
                    ));
                }
                name = field.to_string();
                continue;
            }
            let value = parse_value(column, field)
                .map_err(|why| error(line, format!("row {row}, column '{column}': {why}")))?;
            values.push((column, value));
        }
        if let Some(other) = rows.iter().find(|r| r.name == name) {
            return Err(error(
                line,
                format!(
                    "row {row}, column 'name': '{name}' is also the name of row {}",
                    other.row
                ),
            ));
        }
        rows.push(CaseRow {
            row,
            line,
            name,
            values,
            interaction,
        });
    }
    if rows.is_empty() {
        return Err(error(header_line, "the case table has no rows".into()));
    }
    Ok(rows)
}

fn parse_value(column: &str, field: &str) -> std::result::Result<f64, String> {
    if column == "yaw_headings" {
        return match field.parse::<usize>() {
            Ok(n) if n != 1 => Ok(n as f64),
            _ => Err(format!(
                "'{field}' is not 0 (off) or a whole number of at least 2"
            )),
        };
    }
    if column == "n_directions" {
        return match field.parse::<usize>() {
            Ok(n) if n >= 1 => Ok(n as f64),
            _ => Err(format!("'{field}' is not a whole number of at least 1")),
        };
    }
    match field.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(format!("'{field}' is not a finite number")),
    }
}

impl CaseRow {
    /// The case: `base` with this row's values, and its transient (`transient`, or the
    /// configuration's default when `None`). A value that does not fit the base (an `hs`
    /// for a tabulated spectrum, say) is an error naming the row and column.
    pub fn case(&self, base: &Config, transient: Option<f64>, source: &str) -> Result<Case> {
        let mut config = base.clone();
        if let Some(interaction) = self.interaction {
            config.model.interaction = interaction;
        }
        for &(column, value) in &self.values {
            self.set(&mut config, column, value)
                .map_err(|why| Error::Parse {
                    path: source.to_string(),
                    line: Some(self.line),
                    message: format!("row {}, column '{column}': {why}", self.row),
                })?;
        }
        let transient = transient.unwrap_or_else(|| config.default_transient());
        Ok(Case {
            name: self.name.clone(),
            config,
            transient,
        })
    }

    fn set(
        &self,
        config: &mut Config,
        column: &str,
        value: f64,
    ) -> std::result::Result<(), String> {
        let sea = &mut config.sea;
        match (column, &mut sea.spectrum) {
            ("hs", Spectrum::Jonswap { hs, .. } | Spectrum::PiersonMoskowitz { hs, .. }) => {
                *hs = value
            }
            ("tp", Spectrum::Jonswap { tp, .. } | Spectrum::PiersonMoskowitz { tp, .. }) => {
                *tp = value
            }
            ("gamma", Spectrum::Jonswap { gamma, .. }) => *gamma = (value != 0.0).then_some(value),
            ("hs" | "tp" | "gamma", spectrum) => {
                return Err(format!(
                    "the base configuration's spectrum ({}) has no {column}",
                    spectrum_name(spectrum)
                ))
            }
            ("direction_deg", _) => sea.mean_direction = value.to_radians(),
            ("spreading_exponent", _) => {
                sea.spreading = match sea.spreading {
                    _ if value == 0.0 => Spreading::LongCrested,
                    Spreading::Cos2s { .. } => Spreading::Cos2s { s: value },
                    Spreading::CosN { .. } => Spreading::CosN { n: value },
                    Spreading::LongCrested => {
                        if sea.n_directions <= 1 {
                            sea.n_directions = DEFAULT_N_DIRECTIONS;
                        }
                        Spreading::CosN { n: value }
                    }
                };
                if value == 0.0 {
                    sea.n_directions = 1;
                }
            }
            ("n_directions", _) => sea.n_directions = value as usize,
            ("current_speed", _) => config.current.speed = value,
            ("current_direction_deg", _) => config.current.direction = value.to_radians(),
            ("cd", _) => config.model.drag = DragModel::Combined { cd: value },
            ("cd_slow" | "cd_fast", _) => {
                let (mut slow, mut fast) = match config.model.drag {
                    DragModel::Separate { slow, fast } => (Some(slow), Some(fast)),
                    _ => (None, None),
                };
                let mut other = "cd_fast";
                if column == "cd_slow" {
                    slow = Some(value);
                } else {
                    fast = Some(value);
                    other = "cd_slow";
                }
                let given = |c: &str| self.values.iter().any(|(name, _)| *name == c);
                match (slow, fast) {
                    (Some(slow), Some(fast)) => {
                        config.model.drag = DragModel::Separate { slow, fast }
                    }
                    // The other coefficient comes later in this row.
                    _ if given(other) => {
                        config.model.drag = DragModel::Separate {
                            slow: slow.unwrap_or(0.0),
                            fast: fast.unwrap_or(0.0),
                        }
                    }
                    _ => {
                        return Err(format!(
                            "the base configuration's drag model is not 'separate': give \
                             {other} too"
                        ))
                    }
                }
            }
            ("duration", _) => config.run.duration = value,
            ("yaw_stiffness", _) => config.platform.stiffness[2][2] = value,
            ("yaw_headings", _) => {
                config.model.yaw_following = (value != 0.0).then_some(YawFollowing {
                    headings: value as usize,
                    range: None,
                })
            }
            (other, _) => return Err(format!("'{other}' is not an overridable field")),
        }
        Ok(())
    }
}

fn spectrum_name(spectrum: &Spectrum) -> &'static str {
    match spectrum {
        Spectrum::Jonswap { .. } => "jonswap",
        Spectrum::PiersonMoskowitz { .. } => "pierson-moskowitz",
        Spectrum::Tabulated { .. } => "table",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::file;

    fn base() -> Config {
        file::load(Path::new(concat!(
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
            parsed[0].config.model.interaction,
            Interaction::MeanDirection
        );
        assert_eq!(parsed[1].config.model.interaction, Interaction::None);
        assert_eq!(parsed[2].config.model.interaction, base().model.interaction);
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
        let a = &cases[0].config;
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
        assert_eq!(cases[1].config, expected);
    }

    #[test]
    fn drag_columns_choose_the_model() {
        let c = cases("cd_slow, cd_fast\n0.5, 0.9\n").unwrap();
        assert_eq!(
            c[0].config.model.drag,
            DragModel::Separate {
                slow: 0.5,
                fast: 0.9
            }
        );
        let c = cases("cd\n1.1\n").unwrap();
        assert_eq!(c[0].config.model.drag, DragModel::Combined { cd: 1.1 });
        // The example's drag is combined: one separate coefficient alone does not say the other.
        let e = cases("cd_slow\n0.5\n").unwrap_err().to_string();
        assert!(
            e.contains("row 1, column 'cd_slow'") && e.contains("cd_fast"),
            "{e}"
        );
        let e = cases("cd, cd_fast\n0.5, 0.9\n").unwrap_err().to_string();
        assert!(e.contains("exclude each other"), "{e}");
    }

    #[test]
    fn yaw_columns_set_the_spring_and_the_yaw_following() {
        let c = cases("yaw_stiffness, yaw_headings\n6.0e7, 36\n, 0\n").unwrap();
        assert_eq!(c[0].config.platform.stiffness[2][2], 6.0e7);
        assert_eq!(
            c[0].config.model.yaw_following,
            Some(YawFollowing {
                headings: 36,
                range: None
            })
        );
        assert_eq!(c[1].config, base());
        let e = cases("yaw_headings\n1\n").unwrap_err().to_string();
        assert!(e.contains("row 1, column 'yaw_headings'"), "{e}");
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
