//! NEMOH's matrix files: `results/CM.dat` (added mass) and `results/CA.dat` (radiation
//! damping), one matrix per frequency, and the 6 x 6 matrices of `Mechanics/`
//! (`Inertia.dat`, `Kh.dat`). All are dimensional (kg, kg m, kg m^2; N/m, ...); rows and
//! columns follow Nemoh.cal's degrees of freedom. Errors name `file:line` and the field.

use crate::error::{Error, Result};
use std::path::Path;

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

/// The numbers of one line, or an error naming `path:line` and the token.
fn numbers(path: &str, line: usize, text: &str) -> Result<Vec<f64>> {
    text.split_whitespace()
        .enumerate()
        .map(|(k, t)| match t.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(Error::Parse {
                path: path.to_string(),
                line: Some(line),
                message: format!("field {} (\"{t}\") is not a finite number", k + 1),
            }),
        })
        .collect()
}

/// Reads `CM.dat` or `CA.dat`: `size` x `size` matrices (the body's DOF count).
pub fn read_frequency_matrices(path: &Path, size: usize) -> Result<FrequencyMatrices> {
    let name = path.display().to_string();
    let text = crate::files::read_text(path)?;
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(k, l)| (k + 1, l))
        .filter(|(_, l)| !l.trim().is_empty());
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
    let mut frequencies = Vec::with_capacity(count);
    let mut matrices = Vec::with_capacity(count);
    for k in 0..count {
        let (line, text) = lines.next().ok_or_else(|| Error::Parse {
            path: name.clone(),
            line: None,
            message: format!("the header announces {count} frequencies, the file ends after {k}"),
        })?;
        let w = numbers(&name, line, text)?;
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
            let row = numbers(&name, line, text)?;
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

/// Reads a 6 x 6 matrix of `Mechanics/` (six lines of six numbers).
pub fn read_matrix6(path: &Path) -> Result<[[f64; 6]; 6]> {
    let name = path.display().to_string();
    let text = crate::files::read_text(path)?;
    let rows: Vec<(usize, &str)> = text
        .lines()
        .enumerate()
        .map(|(k, l)| (k + 1, l))
        .filter(|(_, l)| !l.trim().is_empty())
        .collect();
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
    for (i, &(line, text)) in rows.iter().enumerate() {
        let v = numbers(&name, line, text)?;
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
