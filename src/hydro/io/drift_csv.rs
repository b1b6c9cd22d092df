//! Drift tables as named fields: a CSV file (a header line of field names, then one numeric
//! row per line), and the same fields of the configuration file's inline table.
//!
//! Fields, in any order: `omega` (rad/s), `beta_deg` (wave heading relative to the body x
//! axis, deg), `surge`, `sway` (N/m^2), `yaw` (N m/m^2), all required; optionally all nine of
//! `b11` .. `b33` (wave-drift damping b_ij: row i = force surge/sway/yaw, field j = velocity
//! surge/sway/yaw rate) or none of them. Every heading must list the same, strictly
//! increasing frequencies. In a CSV file, blank lines and lines starting with `#` are
//! skipped, fields are trimmed, and quoting follows RFC 4180 (the `csv` crate).

use super::written::Written;
use crate::error::{Error, Location, Result};
use crate::files::Cost;
use crate::hydro::{DriftRow, DriftTable};
use std::path::Path;

/// Field: wave frequency, rad/s.
const FIELD_OMEGA: &str = "omega";
/// Field: wave heading relative to the body x axis, deg.
const FIELD_BETA: &str = "beta_deg";
/// Fields: mean drift surge, sway (N/m^2) and yaw (N m/m^2).
const FIELDS_DRIFT: [&str; 3] = ["surge", "sway", "yaw"];
/// Fields: wave-drift damping b_ij, row i = force, column j = velocity.
const FIELDS_DAMPING: [[&str; 3]; 3] = [
    ["b11", "b12", "b13"],
    ["b21", "b22", "b23"],
    ["b31", "b32", "b33"],
];

/// First character of a comment line in a CSV drift file.
const COMMENT: u8 = b'#';

/// Where each quantity sits in a row of the drift table.
#[derive(Debug, Clone, PartialEq)]
pub struct DriftFields {
    width: usize,
    omega: usize,
    beta: usize,
    drift: [usize; 3],
    damping: Option<[[usize; 3]; 3]>,
}

impl DriftFields {
    /// Locates the fields by name; every name must be known and appear once. `at` is where
    /// the names were written.
    pub fn new(names: &[&str], at: &Location) -> Result<Self> {
        let known = |name: &str| {
            name == FIELD_OMEGA
                || name == FIELD_BETA
                || FIELDS_DRIFT.contains(&name)
                || FIELDS_DAMPING.iter().any(|line| line.contains(&name))
        };
        for (k, name) in names.iter().enumerate() {
            if !known(name) {
                return Err(at.error(format!(
                    "unknown drift field \"{name}\"; known: {FIELD_OMEGA}, {FIELD_BETA}, {}, b11 .. b33",
                    FIELDS_DRIFT.join(", ")
                )));
            }
            if names[..k].contains(name) {
                return Err(at.error(format!("drift field \"{name}\" appears twice")));
            }
        }
        let find = |name: &str| names.iter().position(|n| *n == name);
        let require = |name: &str| {
            find(name).ok_or_else(|| {
                at.error(format!(
                    "the drift table has no \"{name}\" field (required)"
                ))
            })
        };
        let omega = require(FIELD_OMEGA)?;
        let beta = require(FIELD_BETA)?;
        let drift = [
            require(FIELDS_DRIFT[0])?,
            require(FIELDS_DRIFT[1])?,
            require(FIELDS_DRIFT[2])?,
        ];
        let damping_given = FIELDS_DAMPING
            .iter()
            .flatten()
            .filter(|n| find(n).is_some())
            .count();
        let damping = if damping_given == 0 {
            None
        } else {
            let mut index = [[0; 3]; 3];
            for (i, line) in FIELDS_DAMPING.iter().enumerate() {
                for (j, name) in line.iter().enumerate() {
                    index[i][j] = find(name).ok_or_else(|| {
                        at.error(format!(
                            "the drift table has {damping_given} of the b_ij fields but no \"{name}\": \
                             give all nine or none"
                        ))
                    })?;
                }
            }
            Some(index)
        };
        Ok(DriftFields {
            width: names.len(),
            omega,
            beta,
            drift,
            damping,
        })
    }

    /// One row of numbers as a [`DriftRow`], the heading converted to radians; `at` is where
    /// the row was written.
    pub fn row(&self, values: &[f64], at: &Location) -> Result<DriftRow> {
        if values.len() != self.width {
            return Err(at.error(format!(
                "{} values, but the drift table has {} fields",
                values.len(),
                self.width
            )));
        }
        Ok(DriftRow {
            omega: values[self.omega],
            heading: values[self.beta].to_radians(),
            drift: self.drift.map(|k| values[k]),
            damping: self
                .damping
                .map(|index| index.map(|line| line.map(|k| values[k]))),
        })
    }
}

/// What reading a CSV drift table costs: up to 23 bytes of memory per byte of the file
/// (measured on its costliest content: rows of five one-digit numbers, each a row of the
/// table, and a header of a million field names), with a margin for the allocator's own
/// overhead.
pub const READING: Cost = Cost {
    format: "CSV drift table",
    per_byte: 34.0,
};

/// Reads a CSV drift table within `memory_limit` bytes: a header line of field names, then
/// numeric rows.
pub fn read(path: &Path, memory_limit: f64) -> Result<DriftTable> {
    let name = path.display().to_string();
    let at = |line: Option<u64>| Location {
        path: name.clone(),
        line: line.and_then(|l| usize::try_from(l).ok()),
    };
    let io = |e: csv::Error| match e.kind() {
        csv::ErrorKind::Io(io) => Error::Io {
            path: name.clone(),
            message: io.to_string(),
        },
        _ => at(e.position().map(csv::Position::line)).error(e.to_string()),
    };
    let text = crate::files::read_text(path, &READING, memory_limit)?;
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(true)
        .comment(Some(COMMENT))
        .trim(csv::Trim::All)
        .flexible(true)
        .from_reader(text.as_bytes());
    let header = reader.headers().map_err(io)?.clone();
    let header_at = at(header.position().map(csv::Position::line));
    if header.is_empty() {
        return Err(at(None).error("no header line of field names"));
    }
    let names: Vec<&str> = header.iter().collect();
    let fields = DriftFields::new(&names, &header_at)?;
    let mut rows = Vec::new();
    let unterminated = !text.ends_with('\n');
    let mut records = reader.records().peekable();
    let mut previous: Option<csv::StringRecord> = None;
    while let Some(record) = records.next() {
        let record = record.map_err(io)?;
        let line_at = at(record.position().map(csv::Position::line));
        if let (true, None, Some(before)) = (unterminated, records.peek(), &previous) {
            let cut = record
                .iter()
                .zip(before.iter())
                .position(|(text, was)| Written::of(text).is_cut(&Written::of(was), true));
            if let Some(f) = cut {
                return Err(line_at.error(format!(
                    "field \"{}\": \"{}\" has fewer digits than on the line before (\"{}\") \
                     and the file ends in this line without a newline: the number looks cut",
                    names.get(f).unwrap_or(&"(extra)"),
                    &record[f],
                    &before[f]
                )));
            }
        }
        let values = record
            .iter()
            .zip(names.iter().chain(std::iter::repeat(&"(extra)")))
            .map(|(text, field)| {
                text.parse::<f64>().map_err(|_| {
                    line_at.error(format!("field \"{field}\": \"{text}\" is not a number"))
                })
            })
            .collect::<Result<Vec<f64>>>()?;
        rows.push(fields.row(&values, &line_at)?);
        previous = Some(record);
    }
    DriftTable::from_rows(&rows)
}
