//! The per-run CSV of a campaign: one line per finished run, appended and flushed as runs
//! finish, so that an interrupted campaign keeps them and a restart skips them.
//!
//! Columns: `case`, `seed`, `fingerprint` ([`Case::fingerprint`]), `status` (`ok` or
//! `failed`), then for surge, sway and yaw the mean, rms, max and min after the transient
//! (`surge_mean_m`, ..., `yaw_min_deg`; empty for a failed run), and `error` (the message
//! of a failed run, in double quotes with inner quotes doubled; empty otherwise). Numbers
//! are written in Rust's shortest form that reads back to the same bits.
//!
//! Reading keeps the last line of each (case, seed): a run that failed and was run again
//! counts once. A last line without its newline (the process was killed while writing it)
//! is dropped, and cut off before anything is appended.
//!
//! One process at a time: [`RunsFile::open`] takes the file's exclusive lock
//! ([`crate::files::lock`], `NAME.lock` beside it) before reading it, and holds it until
//! the [`RunsFile`] is dropped; a second process is refused at once, naming the first.

use super::{Case, DofStats, DOFS, STATISTICS};
use crate::error::{Error, Result};
use crate::files::{Cost, Lock};
use std::fs::{File, OpenOptions};
use std::io::{Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// What reading a per-run file costs: up to 12 bytes of memory per byte of the file
/// (measured on its costliest content: the shortest lines of failed runs, each a run), with
/// a margin for the allocator's own overhead.
pub const READING: Cost = Cost {
    format: "per-run file",
    per_byte: 18.0,
};

/// One line of the per-run file.
#[derive(Debug, Clone, PartialEq)]
pub struct RunRow {
    pub case: String,
    pub seed: u64,
    pub fingerprint: String,
    pub result: std::result::Result<[DofStats; 3], String>,
}

/// The header line (without its newline).
pub fn header() -> String {
    let mut columns = vec![
        "case".to_string(),
        "seed".into(),
        "fingerprint".into(),
        "status".into(),
    ];
    for (dof, unit) in DOFS {
        for stat in STATISTICS {
            columns.push(format!("{dof}_{stat}_{unit}"));
        }
    }
    columns.push("error".into());
    columns.join(",")
}

/// A line of the file, newline included.
pub fn format_row(row: &RunRow) -> String {
    let mut fields = vec![
        row.case.clone(),
        row.seed.to_string(),
        row.fingerprint.clone(),
    ];
    match &row.result {
        Ok(stats) => {
            fields.push("ok".into());
            for s in stats {
                fields.extend(s.values().iter().map(|v| v.to_string()));
            }
            fields.push(String::new());
        }
        Err(message) => {
            fields.push("failed".into());
            fields.extend(std::iter::repeat_n(String::new(), 12));
            fields.push(quote(message));
        }
    }
    fields.join(",") + "\n"
}

/// A row for `case` (whose [`Case::fingerprint`] is `fingerprint`: computed once per case,
/// it formats the whole configuration) and `seed`.
pub fn row(
    case: &Case,
    fingerprint: &str,
    seed: u64,
    result: std::result::Result<[DofStats; 3], String>,
) -> RunRow {
    RunRow {
        case: case.name.clone(),
        seed,
        fingerprint: fingerprint.into(),
        result,
    }
}

fn quote(text: &str) -> String {
    format!("\"{}\"", text.replace('"', "\"\""))
}

/// A per-run file open for appending, locked against other processes.
#[derive(Debug)]
pub struct RunsFile {
    /// The memory reading the file may take, bytes.
    memory_limit: f64,
    path: PathBuf,
    file: File,
    _lock: Lock,
}

impl RunsFile {
    /// Locks the per-run file at `path` (an error naming the process that holds it), opens
    /// or creates it for appending (a cut-off last line removed, a header written to a new
    /// file) and returns the runs it already holds (the last line of each (case, seed), in
    /// file order). The file is read within `memory_limit` bytes, whenever it is read.
    pub fn open(path: &Path, memory_limit: f64) -> Result<(Vec<RunRow>, RunsFile)> {
        let lock = crate::files::lock(path)?;
        let io = |e: std::io::Error| Error::Io {
            path: path.display().to_string(),
            message: e.to_string(),
        };
        let text =
            crate::files::read_text_if_exists(path, &READING, memory_limit)?.unwrap_or_default();
        let complete = text.rfind('\n').map_or(0, |i| i + 1);
        let runs = parse(&text[..complete], &path.display().to_string())?;
        let mut file = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .open(path)
            .map_err(io)?;
        file.set_len(complete as u64).map_err(io)?;
        file.seek(SeekFrom::End(0)).map_err(io)?;
        if complete == 0 {
            writeln!(file, "{}", header()).map_err(io)?;
            file.flush().map_err(io)?;
        }
        let runs_file = RunsFile {
            memory_limit,
            path: path.to_path_buf(),
            file,
            _lock: lock,
        };
        Ok((runs, runs_file))
    }

    /// Appends `row` as one write of its whole line, flushed: a kill leaves the line whole
    /// or cut (and a cut line is dropped on the next open).
    pub fn append(&mut self, row: &RunRow) -> Result<()> {
        self.file
            .write_all(format_row(row).as_bytes())
            .and_then(|()| self.file.flush())
            .map_err(|e| Error::Io {
                path: self.path.display().to_string(),
                message: e.to_string(),
            })
    }

    /// Every run the file holds now ([`parse`]).
    pub fn runs(&self) -> Result<Vec<RunRow>> {
        let text = crate::files::read_text(&self.path, &READING, self.memory_limit)?;
        parse(&text, &self.path.display().to_string())
    }
}

/// Reads the runs of a per-run file's text (RFC 4180 quoting, the `csv` crate); `source`
/// names it in errors. A later line for the same (case, seed) replaces the earlier one: the
/// runs come in the order of their last lines (found in one pass and an index, so a long
/// file costs its length, not its square).
pub fn parse(text: &str, source: &str) -> Result<Vec<RunRow>> {
    let error = |line: u64, message: String| Error::Parse {
        path: source.to_string(),
        line: usize::try_from(line).ok(),
        message,
    };
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .from_reader(text.as_bytes());
    let mut records = reader.records();
    let csv_error = |e: csv::Error| {
        let line = e.position().map_or(1, csv::Position::line);
        error(line, e.to_string())
    };
    match records.next() {
        None => return Ok(Vec::new()),
        Some(first) => {
            let first = first.map_err(csv_error)?;
            if first.iter().collect::<Vec<_>>().join(",") != header() {
                return Err(error(
                    1,
                    format!(
                        "not a per-run file of this version: the header must be {}",
                        header()
                    ),
                ));
            }
        }
    }
    let mut runs: Vec<RunRow> = Vec::new();
    for record in records {
        let record = record.map_err(csv_error)?;
        let line = record.position().map_or(1, csv::Position::line);
        let fields: Vec<&str> = record.iter().collect();
        if fields.len() != 17 {
            return Err(error(line, format!("{} fields, expected 17", fields.len())));
        }
        let seed = fields[1]
            .parse()
            .map_err(|_| error(line, format!("seed '{}' is not a whole number", fields[1])))?;
        let result = match fields[3] {
            "ok" => {
                let mut v = [0.0; 12];
                for (k, value) in v.iter_mut().enumerate() {
                    *value = fields[4 + k].parse().map_err(|_| {
                        error(
                            line,
                            format!("field {} '{}' is not a number", 5 + k, fields[4 + k]),
                        )
                    })?;
                }
                Ok(std::array::from_fn(|d| DofStats {
                    mean: v[4 * d],
                    rms: v[4 * d + 1],
                    max: v[4 * d + 2],
                    min: v[4 * d + 3],
                }))
            }
            "failed" => Err(fields[16].to_string()),
            other => {
                return Err(error(
                    line,
                    format!("status '{other}' is neither 'ok' nor 'failed'"),
                ))
            }
        };
        let row = RunRow {
            case: fields[0].to_string(),
            seed,
            fingerprint: fields[2].to_string(),
            result,
        };
        runs.push(row);
    }
    let last: std::collections::HashMap<(&str, u64), usize> = runs
        .iter()
        .enumerate()
        .map(|(i, r)| ((r.case.as_str(), r.seed), i))
        .collect();
    let kept: Vec<bool> = runs
        .iter()
        .enumerate()
        .map(|(i, r)| last[&(r.case.as_str(), r.seed)] == i)
        .collect();
    let mut kept = kept.into_iter();
    runs.retain(|_| kept.next().unwrap_or(false));
    Ok(runs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_read_back_bit_for_bit() {
        let stats = [
            DofStats {
                mean: 0.1 + 0.2,
                rms: 1.0 / 3.0,
                max: 1e-300,
                min: -2.5e10,
            },
            DofStats {
                mean: 0.0,
                rms: 0.0,
                max: 0.0,
                min: -0.0,
            },
            DofStats {
                mean: std::f64::consts::PI,
                rms: 7.0,
                max: 8.0,
                min: -9.0,
            },
        ];
        let ok = RunRow {
            case: "sea 1".into(),
            seed: 7,
            fingerprint: "00ff".into(),
            result: Ok(stats),
        };
        let failed = RunRow {
            case: "bad".into(),
            seed: u64::MAX,
            fingerprint: "abcd".into(),
            result: Err("invalid x = \"-1\", y: must be, positive".into()),
        };
        let text = format!("{}\n{}{}", header(), format_row(&ok), format_row(&failed));
        assert_eq!(
            parse(&text, "runs.csv").unwrap(),
            vec![ok.clone(), failed.clone()]
        );
        // A later line for the same (case, seed) replaces the earlier one.
        let rerun = RunRow {
            result: Ok(stats),
            ..failed
        };
        let again = format!("{text}{}", format_row(&rerun));
        assert_eq!(
            parse(&again, "runs.csv").unwrap(),
            vec![ok.clone(), rerun.clone()]
        );
        // The first run again, last: the runs in the order of their last lines.
        let ok_again = RunRow {
            fingerprint: "0100".into(),
            ..ok.clone()
        };
        let last = format!("{again}{}", format_row(&ok_again));
        assert_eq!(parse(&last, "runs.csv").unwrap(), vec![rerun, ok_again]);
        let bad = format!("{text}{}", format_row(&ok).replace(",7,", ",u,"));
        assert!(parse(&bad, "runs.csv")
            .unwrap_err()
            .to_string()
            .contains("runs.csv:4: seed 'u'"));
    }
}
