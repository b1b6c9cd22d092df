//! Where the settings of a scenario were written, so that an error names a setting as the
//! user wrote it: `platform.toml:12: invalid [sea] hs = -1: ...` for a configuration file,
//! `invalid FMU parameter Hs = -1: ...` for the FMU, `cases.csv:4: invalid row 3, column
//! 'hs' = -1: ...` for a case table.
//!
//! Errors of `problem::Problem::validate` name fields by their configuration-file
//! key path (`sea.hs`, `platform.columns[2].draft`, `current.direction_deg`, in the file's
//! units); [`Origins::locate`] rewrites such an error for the place the value came from.

use super::lines::LineIndex;
use crate::error::numbers::readable;
use crate::error::{Error, Location, OverBudget};
use std::collections::BTreeMap;
use std::ops::Range;

/// One setting written over the configuration: by an FMU parameter or a case-table cell.
#[derive(Debug, Clone)]
pub enum Written {
    /// An FMU parameter: its variable name and, for a mode (an Integer of the override
    /// table's words), the code the master wrote, which messages show beside the word
    /// (`driftDamping = 1 (table)`). FMU angles are in radians.
    Fmu {
        variable: &'static str,
        code: Option<i32>,
    },
    /// A cell of a case table.
    CaseTable {
        at: Location,
        row: usize,
        column: &'static str,
    },
}

/// Where each setting of a scenario came from. Two scenarios that describe the same
/// simulation are equal wherever they were written: `Origins` always compare equal.
#[derive(Debug, Clone, Default)]
pub struct Origins {
    /// The configuration file: its name and the line of every key path in it.
    file: Option<(String, BTreeMap<String, usize>)>,
    /// Settings written over the file, by key path; the last one written wins.
    overrides: Vec<(String, Written)>,
}

impl PartialEq for Origins {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl Origins {
    /// The keys of configuration text `text` (already known to parse) read from `path`: the
    /// line of every table, key and array element, by key path (`sea`, `sea.hs`,
    /// `platform.columns[1]`, `platform.columns[1].draft`); `index` is the text's lines.
    pub fn of_file(path: &str, text: &str, index: &LineIndex) -> Origins {
        let mut lines = BTreeMap::new();
        if let Ok(table) = toml::de::DeTable::parse(text) {
            index_table(index, "", table.get_ref(), &mut lines);
        }
        Origins {
            file: Some((path.to_string(), lines)),
            overrides: Vec::new(),
        }
    }

    /// Records that `key` (a key path) was written by `written`.
    pub fn record(&mut self, key: &str, written: Written) {
        self.overrides.push((key.to_string(), written));
    }

    /// A setting (key path) as the user wrote it and where, for a message that names it as
    /// a cause or a remedy rather than refusing its value: `[sea] hs (platform.toml:14)`
    /// (a key the file leaves out at its section's line, if it has one), `[drift]
    /// (platform.toml:110)` for a whole section, `row 3, column 'hs' (cases.csv:4)`, `FMU
    /// parameter Hs`; the key path itself when nothing says where.
    pub fn name(&self, key: &str) -> String {
        match self.name_and_place(key) {
            (name, Some(at)) => format!("{name} ({at})"),
            (name, None) => name,
        }
    }

    /// [`Origins::name`]'s name and place (`platform.toml:14`) apart.
    pub fn name_and_place(&self, key: &str) -> (String, Option<String>) {
        let (name, _, at) = self.place(key.to_string(), String::new());
        let name = if key.contains('.') || self.file.is_none() {
            name
        } else {
            format!("[{key}]")
        };
        let at = at.map(|Location { path, line }| match line {
            Some(line) => format!("{path}:{line}"),
            None => path,
        });
        (name, at)
    }

    /// Of the settings `keys` (key paths), the one the user wrote last: one written over the
    /// file (an FMU parameter, a case-table cell; the later, the more recent) before one
    /// the file writes, before one left at its default; the first of `keys` among equals.
    /// For a refusal of two settings that do not fit together, the one to name.
    pub fn latest<'k>(&self, keys: &[&'k str]) -> &'k str {
        let rank = |key: &str| {
            let overridden = self.overrides.iter().rposition(|(k, _)| covers(k, key));
            match overridden {
                Some(i) => i + 2,
                None => usize::from(
                    self.file
                        .as_ref()
                        .is_some_and(|(_, lines)| lines.contains_key(key)),
                ),
            }
        };
        let mut best = keys[0];
        for &key in &keys[1..] {
            if rank(key) > rank(best) {
                best = key;
            }
        }
        best
    }

    /// `error` (from validation, naming a key path) as the user wrote the setting: where
    /// it was written and under which name. Other errors, and errors located already (a
    /// key path has no space, a located name has: `[sea] hs`, `FMU parameter Hs`), are
    /// returned unchanged.
    pub fn locate(&self, error: Error) -> Error {
        match error {
            Error::InvalidValue { ref field, .. } if field.contains(' ') => error,
            Error::OverBudget(ref excess) if excess.field.contains(' ') => error,
            Error::InvalidValue {
                field,
                value,
                reason,
                at: None,
            } => {
                let (field, value, at) = self.place(field, value);
                Error::InvalidValue {
                    field,
                    value,
                    reason,
                    at,
                }
            }
            Error::OverBudget(mut excess) if excess.at.is_none() => {
                let (field, value, at) = self.place(
                    std::mem::take(&mut excess.field),
                    std::mem::take(&mut excess.value),
                );
                *excess = OverBudget {
                    field,
                    value,
                    at,
                    ..*excess
                };
                Error::OverBudget(excess)
            }
            other => other,
        }
    }

    /// A setting (key path `field`, its value in the file's units) as the user wrote it:
    /// its name, its value in that name's units, and where.
    fn place(&self, field: String, value: String) -> (String, String, Option<Location>) {
        if let Some((key, written)) = self
            .overrides
            .iter()
            .rev()
            .find(|(key, _)| covers(key, &field))
        {
            return match written {
                Written::Fmu { variable, code } => (
                    format!("FMU parameter {variable}"),
                    match code {
                        Some(code) => format!("{code} ({value})"),
                        None => in_radians(key, value),
                    },
                    None,
                ),
                Written::CaseTable { at, row, column } => (
                    format!("row {row}, column '{column}'"),
                    value,
                    Some(at.clone()),
                ),
            };
        }
        match &self.file {
            Some((path, lines)) => {
                let line = lines
                    .iter()
                    .filter(|(key, _)| covers(key, &field))
                    .max_by_key(|(key, _)| key.len())
                    .map(|(_, line)| *line);
                (
                    file_key(&field),
                    value,
                    Some(Location {
                        path: path.clone(),
                        line,
                    }),
                )
            }
            None => (field, value, None),
        }
    }
}

/// Whether the key path `key` names `field` or a part of it (`platform.stiffness` covers
/// `platform.stiffness[2][2]`, `sea` covers `sea.hs`).
fn covers(key: &str, field: &str) -> bool {
    field
        .strip_prefix(key)
        .is_some_and(|rest| rest.is_empty() || rest.starts_with('.') || rest.starts_with('['))
}

/// A key path as the configuration file spells it: `sea.hs` -> `[sea] hs`.
fn file_key(field: &str) -> String {
    // The format's one nested table, named as the file writes its header.
    const SUBTABLES: [&str; 1] = ["platform.motions"];
    for table in SUBTABLES {
        if let Some(key) = field.strip_prefix(table).and_then(|k| k.strip_prefix('.')) {
            return format!("[{table}] {key}");
        }
    }
    match field.split_once('.') {
        Some((section, key)) if !section.contains('[') => format!("[{section}] {key}"),
        _ => field.to_string(),
    }
}

/// A value of a key in degrees (`..._deg`) as the FMU's radians.
fn in_radians(key: &str, value: String) -> String {
    match value.parse::<f64>() {
        Ok(deg) if key.contains("_deg") => format!("{} rad", readable(deg.to_radians())),
        _ => value,
    }
}

/// Records the line of every key of `table` (and of what it holds) under `prefix`.
fn index_table(
    index: &LineIndex,
    prefix: &str,
    table: &toml::de::DeTable,
    lines: &mut BTreeMap<String, usize>,
) {
    for (key, value) in table.iter() {
        let path = if prefix.is_empty() {
            key.get_ref().to_string()
        } else {
            format!("{prefix}.{}", key.get_ref())
        };
        lines.insert(path.clone(), index.line(key.span().start));
        index_value(index, &path, value.get_ref(), value.span(), lines);
    }
}

fn index_value(
    index: &LineIndex,
    path: &str,
    value: &toml::de::DeValue,
    span: Range<usize>,
    lines: &mut BTreeMap<String, usize>,
) {
    match value {
        toml::de::DeValue::Table(table) => index_table(index, path, table, lines),
        toml::de::DeValue::Array(items) => {
            for (k, item) in items.iter().enumerate() {
                let element = format!("{path}[{k}]");
                let start = if item.span().start < span.start {
                    span.start
                } else {
                    item.span().start
                };
                lines.entry(element.clone()).or_insert(index.line(start));
                index_value(index, &element, item.get_ref(), item.span(), lines);
            }
        }
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "[sea]\nspectrum = \"jonswap\"\nhs = 4.0\n\n[[platform.columns]]\nx = 1\n\n[[platform.columns]]\nx = 2\ndraft = 3\n";

    fn invalid(field: &str) -> Error {
        Error::invalid(field, -1, "must be greater than zero")
    }

    #[test]
    fn a_file_key_is_named_with_its_section_and_line() {
        let origins = Origins::of_file("p.toml", TEXT, &LineIndex::new(TEXT));
        assert_eq!(
            origins.locate(invalid("sea.hs")).to_string(),
            "p.toml:3: invalid [sea] hs = -1: must be greater than zero"
        );
        // An absent key is named at its section.
        assert_eq!(
            origins.locate(invalid("sea.tp")).to_string(),
            "p.toml:1: invalid [sea] tp = -1: must be greater than zero"
        );
        assert_eq!(
            origins
                .locate(invalid("platform.columns[1].draft"))
                .to_string(),
            "p.toml:10: invalid [platform] columns[1].draft = -1: must be greater than zero"
        );
    }

    #[test]
    fn an_override_is_named_where_it_was_written() {
        let mut origins = Origins::of_file("p.toml", TEXT, &LineIndex::new(TEXT));
        origins.record(
            "sea.hs",
            Written::Fmu {
                variable: "Hs",
                code: None,
            },
        );
        assert_eq!(
            origins.locate(invalid("sea.hs")).to_string(),
            "invalid FMU parameter Hs = -1: must be greater than zero"
        );
        origins.record(
            "sea.hs",
            Written::CaseTable {
                at: Location {
                    path: "cases.csv".into(),
                    line: Some(4),
                },
                row: 3,
                column: "hs",
            },
        );
        assert_eq!(
            origins.locate(invalid("sea.hs")).to_string(),
            "cases.csv:4: invalid row 3, column 'hs' = -1: must be greater than zero"
        );
        // Degrees of the file are radians for the FMU.
        let mut fmu = Origins::default();
        fmu.record(
            "current.direction_deg",
            Written::Fmu {
                variable: "currentDirection",
                code: None,
            },
        );
        let e = Error::invalid("current.direction_deg", 180.0, "why");
        assert!(fmu
            .locate(e)
            .to_string()
            .contains("currentDirection = 3.14159"));
    }

    /// The setting of two that do not fit together is the one written last: a case-table
    /// cell over the file, the file over a default, the first named among equals.
    #[test]
    fn the_setting_written_last_is_the_one_named() {
        let text = "[run]\nduration = 10\nblock_duration = 100\n";
        let mut origins = Origins::of_file("p.toml", text, &LineIndex::new(text));
        let (step, block, duration) = ("run.time_step", "run.block_duration", "run.duration");
        assert_eq!(origins.latest(&[block, step]), block);
        assert_eq!(origins.latest(&[step, block]), block);
        assert_eq!(origins.latest(&[step, duration]), duration);
        origins.record(
            step,
            Written::CaseTable {
                at: Location {
                    path: "cases.csv".into(),
                    line: Some(2),
                },
                row: 1,
                column: "time_step",
            },
        );
        assert_eq!(origins.latest(&[block, step]), step);
        assert_eq!(Origins::default().latest(&[block, step]), block);
    }

    /// A setting a message blames is named as written and where; an error located once is
    /// not located again.
    #[test]
    fn a_blamed_setting_is_named_where_it_was_written() {
        let origins = Origins::of_file("p.toml", TEXT, &LineIndex::new(TEXT));
        assert_eq!(origins.name("sea.hs"), "[sea] hs (p.toml:3)");
        assert_eq!(origins.name("sea.tp"), "[sea] tp (p.toml:1)");
        assert_eq!(origins.name("platform"), "[platform] (p.toml:5)");
        assert_eq!(Origins::default().name("sea.hs"), "sea.hs");
        let once = origins.locate(invalid("sea.hs"));
        assert_eq!(origins.locate(once.clone()), once);
    }
}
