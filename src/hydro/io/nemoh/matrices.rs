//! NEMOH's matrix files: `results/CM.dat` (added mass) and `results/CA.dat` (radiation
//! damping), one matrix per frequency, and the 6 x 6 matrices of `Mechanics/`
//! (`Inertia.dat`, `Kh.dat`). All are dimensional (kg, kg m, kg m^2; N/m, ...); rows and
//! columns follow Nemoh.cal's degrees of freedom. Errors name `file:line` and the field.

use crate::error::{Error, Result};
use crate::files::Cost;
use crate::hydro::io::written::first_cut;
use std::path::Path;

/// What reading a matrix file costs: up to 36 bytes of memory per byte of the file
/// (measured on its costliest content: the 1 x 1 matrices of a one-DOF body, each number a
/// line, a row and a matrix of the reader's), with a margin for the allocator's own
/// overhead.
pub const READING: Cost = Cost {
    format: "NEMOH matrix file",
    per_byte: 54.0,
};

/// Matrices at frequencies, as `CM.dat` and `CA.dat` hold them: a header line ending with
/// the count ("Nb de frequency : 128"), then per frequency a line with the frequency and
/// one line per row.
#[derive(Debug, Clone, PartialEq)]
pub struct FrequencyMatrices {
    /// Frequencies as written (in Nemoh.cal's first-order unit).
    pub frequencies: Vec<f64>,
    /// `matrices[k][i][j]`, square.
    pub matrices: Vec<Vec<Vec<f64>>>,
}

/// How the first row of a file writes its numbers: a later row's number written
/// with less (its exponent lost; on a last line without a newline, fewer digits) is cut.
pub(super) struct Reference<'a> {
    line: usize,
    fields: Vec<&'a str>,
}

/// A file's text split into its non-empty lines (1-based line numbers), and whether the
/// file ends without a newline (so its last line may be cut inside a number).
pub(super) struct Lines<'a> {
    pub(super) path: String,
    pub(super) rows: Vec<(usize, &'a str)>,
    unterminated_last: Option<usize>,
}

impl<'a> Lines<'a> {
    pub(super) fn new(path: String, text: &'a str) -> Self {
        let rows: Vec<(usize, &str)> = text
            .lines()
            .enumerate()
            .map(|(k, l)| (k + 1, l))
            .filter(|(_, l)| !l.trim().is_empty())
            .collect();
        let unterminated_last = if text.ends_with('\n') {
            None
        } else {
            rows.last().map(|&(line, _)| line)
        };
        Lines {
            path,
            rows,
            unterminated_last,
        }
    }

    /// The numbers of `line`, or an error naming `path:line` and the field: not a finite
    /// number, or a cut copy of the same field of `reference`'s row. The first row read
    /// becomes the reference.
    pub(super) fn numbers(
        &self,
        line: usize,
        text: &'a str,
        reference: &mut Option<Reference<'a>>,
    ) -> Result<Vec<f64>> {
        let at = |message: String| Error::Parse {
            path: self.path.clone(),
            line: Some(line),
            message,
        };
        let fields: Vec<&str> = text.split_whitespace().collect();
        let values = fields
            .iter()
            .enumerate()
            .map(|(k, t)| match t.parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(v),
                _ => Err(at(format!(
                    "field {} (\"{t}\") is not a finite number",
                    k + 1
                ))),
            })
            .collect::<Result<Vec<f64>>>()?;
        match reference {
            None => *reference = Some(Reference { line, fields }),
            Some(r) => {
                let last = self.unterminated_last == Some(line);
                if let Some(cut) = first_cut(&fields, &r.fields, last) {
                    return Err(at(cut.message(r.line, last)));
                }
            }
        }
        Ok(values)
    }
}

/// Reads `CM.dat` or `CA.dat` within `memory_limit` bytes: `size` x `size` matrices (the
/// body's DOF count).
pub fn read_frequency_matrices(
    path: &Path,
    size: usize,
    memory_limit: f64,
) -> Result<FrequencyMatrices> {
    let name = path.display().to_string();
    let text = crate::files::read_text(path, &READING, memory_limit)?;
    let file = Lines::new(name.clone(), &text);
    let mut lines = file.rows.iter().copied();
    let mut frequency_reference = None;
    let mut row_reference = None;
    let at = |line: usize, message: String| Error::Parse {
        path: name.clone(),
        line: Some(line),
        message,
    };
    let (line, header) = lines.next().ok_or_else(|| Error::Parse {
        path: name.clone(),
        line: None,
        message: "empty file".into(),
    })?;
    let count = header
        .split_whitespace()
        .last()
        .and_then(|t| t.parse::<usize>().ok())
        .filter(|&c| (1..=1_000_000).contains(&c))
        .ok_or_else(|| {
            at(
                line,
                format!(
                    "the header \"{}\" does not end with the number of frequencies",
                    header.trim()
                ),
            )
        })?;
    // The header's count, but no more than the file's lines can hold (a header that
    // announces a million frequencies in a short file reserves nothing for them).
    let announced = count.min(file.rows.len() / (1 + size));
    let mut frequencies = Vec::with_capacity(announced);
    let mut matrices = Vec::with_capacity(announced);
    for k in 0..count {
        let (line, text) = lines.next().ok_or_else(|| Error::Parse {
            path: name.clone(),
            line: None,
            message: format!("the header announces {count} frequencies, the file ends after {k}"),
        })?;
        let w = file.numbers(line, text, &mut frequency_reference)?;
        if w.len() != 1 {
            return Err(at(
                line,
                format!("expected the frequency alone, found {} fields", w.len()),
            ));
        }
        frequencies.push(w[0]);
        let mut matrix = Vec::with_capacity(size);
        for _ in 0..size {
            let (line, text) = lines.next().ok_or_else(|| Error::Parse {
                path: name.clone(),
                line: None,
                message: format!("the matrix at frequency {} ends early", w[0]),
            })?;
            let row = file.numbers(line, text, &mut row_reference)?;
            if row.len() != size {
                return Err(at(
                    line,
                    format!(
                        "expected {size} numbers (one per DOF of Nemoh.cal), found {}",
                        row.len()
                    ),
                ));
            }
            matrix.push(row);
        }
        matrices.push(matrix);
    }
    if let Some((line, _)) = lines.next() {
        return Err(at(
            line,
            format!("more lines than the {count} frequencies the header announces"),
        ));
    }
    Ok(FrequencyMatrices {
        frequencies,
        matrices,
    })
}

/// Reads a 6 x 6 matrix of `Mechanics/` (six lines of six numbers) within `memory_limit`
/// bytes.
pub fn read_matrix6(path: &Path, memory_limit: f64) -> Result<[[f64; 6]; 6]> {
    let name = path.display().to_string();
    let text = crate::files::read_text(path, &READING, memory_limit)?;
    let file = Lines::new(name.clone(), &text);
    let rows = &file.rows;
    if rows.len() != 6 {
        return Err(Error::Parse {
            path: name,
            line: None,
            message: format!(
                "expected 6 rows of 6 numbers, found {} non-empty lines",
                rows.len()
            ),
        });
    }
    let mut out = [[0.0; 6]; 6];
    let mut reference = None;
    for (i, &(line, text)) in rows.iter().enumerate() {
        let v = file.numbers(line, text, &mut reference)?;
        if v.len() != 6 {
            return Err(Error::Parse {
                path: name,
                line: Some(line),
                message: format!("expected 6 numbers, found {}", v.len()),
            });
        }
        out[i].copy_from_slice(&v);
    }
    Ok(out)
}
