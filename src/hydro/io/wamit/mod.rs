//! Readers for WAMIT's numeric output files (the industry's exchange format;
//! docs/file-formats.md#wamit-import-and-the-hydro-database), dimensionalised with the options'
//! ULEN, rho and g.
//!
//! | file | reader | content |
//! |---|---|---|
//! | `.1` | [`read_added_mass_damping`] | PER I J Abar (Bbar): A = rho L^k Abar, B = rho w L^k Bbar, k = 3, 4, 5 |
//! | `.hst` | [`read_hydrostatics`] | I J Cbar: C = rho g L^k Cbar, k = 2, 3, 4 |
//! | `.8`, `.9` | [`read_mean_drift`] | PER beta1 beta2 I abs(F) phase Re Im: F = rho g L^k Fbar |
//! | `.10d`, `.11d`, `.12d` | [`read_difference_qtf`] | PER1 PER2 beta1 beta2 I abs(F) phase Re Im, same scaling |
//!
//! k grows by one per rotational index (DOFs 4, 5, 6): forces k = 1, moments k = 2 for the
//! drift and the QTF. Periods become frequencies omega = 2 pi / PER; in the `.1` file
//! PER = -1 means omega = 0 and PER = 0 means omega = infinity. Headings are read in degrees
//! and returned in radians, measured like the crate's beta (direction of propagation from
//! the body x axis, counter-clockwise), which is WAMIT's definition. Forces are per unit
//! wave amplitude squared (N/m^2, N m/m^2): the A^2 of WAMIT's scaling is left to the sea.
//!
//! What the readers assume about a file: nothing about the order of its lines or of its
//! DOFs. A first line that does not start with a number is a header and is skipped; blank
//! lines are skipped; any other line must hold the documented count of numbers, or the
//! error names the file, the 1-based line and what is wrong. A number written without the
//! exponent that the same field of the first line of its length has (an exponent lost:
//! `6.273170` where the column writes `6.273170E+09`), or, on a last line that ends the
//! file without a newline, with fewer exponent digits or decimals, is cut: an error. An entry given twice is an
//! error naming both lines. Only single-body files (DOFs 1 to 6) are read.
//!
//! Time convention: WAMIT writes complex amplitudes for e^{i omega t}, the crate's own
//! convention (docs/theory.md#conventions), and defines the difference-frequency force as
//! Re sum_i sum_j A_i A_j* F-(w_i, w_j) e^{i (w_i - w_j) t}, the definition of
//! docs/theory.md#the-slowly-varying-force. QTF values are therefore stored as given (Re + i Im of
//! the file,
//! scaled), with PER1 giving w_i and PER2 giving w_j; nothing is conjugated. A file written
//! for e^{-i omega t} would need its QTF conjugated before use.

mod added_mass;
mod hydrostatics;
mod import;
mod mean_drift;
mod qtf;

pub use added_mass::{read_added_mass_damping, AddedMassDamping};
pub use hydrostatics::{read_hydrostatics, Hydrostatics};
pub use import::import;
pub use mean_drift::{read_mean_drift, DriftBlock, MeanDrift, PairBlock};
pub(in crate::hydro::io) use qtf::{assemble_qtf, QtfEntry};
pub use qtf::{read_difference_qtf, DifferenceQtf, QtfBlock};

use super::written::first_cut;
use crate::error::numbers::written;
use crate::error::MEMORY_LIMIT_KEY;
use crate::error::{require_positive, Error, Result};
use crate::files::budget::{check_memory_limit, Cost, DEFAULT_MEMORY_LIMIT};
use crate::model::{FREQUENCY_MATCH_TOLERANCE, HEADING_MATCH_TOLERANCE};
use std::f64::consts::PI;
use std::path::Path;

/// Default WAMIT length scale ULEN, m.
pub const DEFAULT_ULEN: f64 = 1.0;
/// Default water density, kg/m^3 (docs/theory.md#conventions).
pub const DEFAULT_RHO: f64 = 1025.0;
/// Default acceleration of gravity, m/s^2 (docs/theory.md#conventions).
pub const DEFAULT_GRAVITY: f64 = 9.80665;

/// How closely a line's polar columns (abs(F), phase) must give its Cartesian ones (Re, Im),
/// relative to the modulus: files print five to seven significant digits (the OC4 `.12d`
/// agrees within 1.3e-5, the NEMOH OC3 QTF within 1.3e-6).
pub const POLAR_TOLERANCE: f64 = 1e-3;

/// How WAMIT's files are read: the scales that make their nondimensional numbers
/// dimensional, and the memory reading them may take.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WamitOptions {
    /// WAMIT's length scale ULEN (L), m.
    pub ulen: f64,
    /// Water density rho, kg/m^3.
    pub rho: f64,
    /// Acceleration of gravity g, m/s^2.
    pub gravity: f64,
    /// The memory a file's reading may take, bytes (its text and what is made of it: the
    /// records of [`NumericFile`], a QTF's matrices).
    pub memory_limit: f64,
}

impl Default for WamitOptions {
    fn default() -> Self {
        WamitOptions {
            ulen: DEFAULT_ULEN,
            rho: DEFAULT_RHO,
            gravity: DEFAULT_GRAVITY,
            memory_limit: DEFAULT_MEMORY_LIMIT,
        }
    }
}

impl WamitOptions {
    /// Checks that every scale and the memory limit are finite and positive.
    pub fn validate(&self) -> Result<()> {
        require_positive("wamit.ulen", self.ulen)?;
        require_positive("wamit.rho", self.rho)?;
        require_positive("wamit.g", self.gravity)?;
        check_memory_limit(MEMORY_LIMIT_KEY, self.memory_limit)
    }

    /// rho L^k for added mass (k = 3 + number of rotational indices).
    fn added_mass_scale(&self, i: usize, j: usize) -> f64 {
        self.rho * self.ulen.powi(3 + rotations(i, j))
    }

    /// rho g L^k for hydrostatic stiffness (k = 2 + number of rotational indices).
    fn stiffness_scale(&self, i: usize, j: usize) -> f64 {
        self.rho * self.gravity * self.ulen.powi(2 + rotations(i, j))
    }

    /// rho g L^k for drift forces (k = 1) and moments (k = 2), per unit amplitude squared.
    fn force_scale(&self, i: usize) -> f64 {
        self.rho * self.gravity * self.ulen.powi(1 + i32::from(i >= 4))
    }
}

/// Number of rotational DOFs (4, 5, 6) among i and j.
fn rotations(i: usize, j: usize) -> i32 {
    i32::from(i >= 4) + i32::from(j >= 4)
}

/// Frequency of a positive period, rad/s.
fn omega_of_period(period: f64) -> f64 {
    2.0 * PI / period
}

/// Two frequencies of a file (or of two files) are one node within
/// [`FREQUENCY_MATCH_TOLERANCE`]: the same period printed to different precision.
fn same_frequency(a: f64, b: f64) -> bool {
    (a - b).abs() <= FREQUENCY_MATCH_TOLERANCE * a.abs().max(b.abs())
}

fn same_heading(a: f64, b: f64) -> bool {
    (a - b).abs() <= HEADING_MATCH_TOLERANCE
}

/// Sorted values with near-duplicates (by `same`) merged.
fn unique_sorted(mut values: Vec<f64>, same: fn(f64, f64) -> bool) -> Vec<f64> {
    values.sort_by(f64::total_cmp);
    values.dedup_by(|b, a| same(*a, *b));
    values
}

/// Index of `value` in `grid` (increasing, made by [`unique_sorted`]): the neighbour on
/// either side of the insertion point that is the same value, if any.
fn grid_index(grid: &[f64], value: f64, same: fn(f64, f64) -> bool) -> Option<usize> {
    let k = grid.partition_point(|&g| g < value);
    [k.checked_sub(1), Some(k)]
        .into_iter()
        .flatten()
        .find(|&i| i < grid.len() && same(grid[i], value))
}

/// What reading a numeric file costs ([`NumericFile::read`], and what its readers make of
/// the records but a QTF's matrices, which are budgeted where they are made): up to 22
/// bytes of memory per byte of the file (measured on its costliest content: lines of nine
/// one-digit numbers of a `.12d` file, each an entry; `.1` lines at distinct periods), with
/// a margin for the allocator's own overhead.
pub const READING: Cost = Cost {
    format: "numeric file (WAMIT's layout)",
    per_byte: 32.0,
};

/// One numeric line of a file: its 1-based line number and its numbers.
pub(in crate::hydro::io) struct Record {
    pub line: usize,
    pub values: Vec<f64>,
}

/// The numeric lines of a WAMIT file (or of another code's file of the same shape).
pub(in crate::hydro::io) struct NumericFile {
    pub path: String,
    pub records: Vec<Record>,
}

impl NumericFile {
    /// Reads `path` within `memory_limit` bytes: skips blank lines and a first line that
    /// does not start with a number; every other line must hold one of `counts` numbers,
    /// laid out as `layout` says.
    pub fn read(path: &Path, counts: &[usize], layout: &str, memory_limit: f64) -> Result<Self> {
        let name = path.display().to_string();
        let text = crate::files::read_text(path, &READING, memory_limit)?;
        let mut records = Vec::new();
        let mut seen_content = false;
        // How the first numeric line of each field count writes its numbers: a later number
        // written with less than that is cut.
        let mut references: Vec<(usize, Vec<&str>)> = Vec::new();
        let unterminated = !text.ends_with('\n');
        let last_line = text.lines().count();
        for (k, line) in text.lines().enumerate() {
            let fields: Vec<&str> = line.split_whitespace().collect();
            if fields.is_empty() {
                continue;
            }
            let first_content = !seen_content;
            seen_content = true;
            if first_content && fields[0].parse::<f64>().is_err() {
                continue;
            }
            let at = |message: String| Error::Parse {
                path: name.clone(),
                line: Some(k + 1),
                message,
            };
            if !counts.contains(&fields.len()) {
                return Err(at(format!(
                    "expected {} numbers ({layout}), found {} fields",
                    counts
                        .iter()
                        .map(usize::to_string)
                        .collect::<Vec<_>>()
                        .join(" or "),
                    fields.len()
                )));
            }
            let values = fields
                .iter()
                .enumerate()
                .map(|(f, text)| match text.parse::<f64>() {
                    Ok(v) if v.is_finite() => Ok(v),
                    _ => Err(at(format!(
                        "field {} (\"{text}\") is not a finite number",
                        f + 1
                    ))),
                })
                .collect::<Result<Vec<f64>>>()?;
            match references.iter().find(|(_, r)| r.len() == fields.len()) {
                None => references.push((k + 1, fields.clone())),
                Some((reference_line, reference)) => {
                    let last = unterminated && k + 1 == last_line;
                    if let Some(cut) = first_cut(&fields, reference, last) {
                        return Err(at(cut.message(*reference_line, last)));
                    }
                }
            }
            records.push(Record {
                line: k + 1,
                values,
            });
        }
        if records.is_empty() {
            return Err(Error::Parse {
                path: name,
                line: None,
                message: format!("no numeric lines ({layout})"),
            });
        }
        Ok(NumericFile {
            path: name,
            records,
        })
    }

    fn error(&self, line: usize, message: impl Into<String>) -> Error {
        Error::Parse {
            path: self.path.clone(),
            line: Some(line),
            message: message.into(),
        }
    }

    /// Field `k` (0-based) of `record` as a DOF index 1 ..= 6.
    fn dof(&self, record: &Record, k: usize, name: &str) -> Result<usize> {
        let v = record.values[k];
        if v.fract() == 0.0 && (1.0..=6.0).contains(&v) {
            Ok(v as usize)
        } else {
            Err(self.error(
                record.line,
                format!(
                    "{name} = {}: a DOF index must be an integer from 1 to 6 (single-body \
                     files only)",
                    written(v)
                ),
            ))
        }
    }

    /// Checks that the polar columns `first`, `first + 1` (abs(F), phase in degrees) and the
    /// Cartesian columns `first + 2`, `first + 3` (Re, Im) of `record` are the same complex
    /// number, within [`POLAR_TOLERANCE`] of its modulus. A line whose polar form is the
    /// conjugate of its Cartesian form mixes the time conventions e^{i omega t} and
    /// e^{-i omega t} (a converter that flipped one pair and not the other) and is refused:
    /// which of the two is meant cannot be told from the line. abs(F) = phase = 0 with a
    /// non-zero Re, Im is taken as a file that leaves the polar form out.
    pub fn check_polar(&self, record: &Record, first: usize) -> Result<()> {
        let v = &record.values;
        let (modulus, phase) = (v[first], v[first + 1]);
        let cartesian = rustfft::num_complex::Complex64::new(v[first + 2], v[first + 3]);
        if modulus == 0.0 && phase == 0.0 {
            return Ok(());
        }
        let polar = rustfft::num_complex::Complex64::from_polar(modulus, phase.to_radians());
        let scale = modulus.abs().max(cartesian.norm());
        if (polar - cartesian).norm() <= POLAR_TOLERANCE * scale {
            return Ok(());
        }
        let conjugate = (polar - cartesian.conj()).norm() <= POLAR_TOLERANCE * scale;
        Err(self.error(
            record.line,
            if conjugate {
                format!(
                    "abs(F) = {}, phase = {} deg is the conjugate of Re, Im = {}, {}: the line \
                     mixes the time conventions e^(i w t) and e^(-i w t); convert the file to \
                     one of them (WAMIT's is e^(i w t), Re + i Im = abs(F) e^(i phase))",
                    written(modulus),
                    written(phase),
                    written(v[first + 2]),
                    written(v[first + 3])
                )
            } else {
                format!(
                    "abs(F) = {}, phase = {} deg and Re, Im = {}, {} are not the same complex \
                     number (fields {} to {})",
                    written(modulus),
                    written(phase),
                    written(v[first + 2]),
                    written(v[first + 3]),
                    first + 1,
                    first + 4
                )
            },
        ))
    }

    /// Field `k` of `record` as a positive period, converted to omega = 2 pi / PER.
    fn frequency(&self, record: &Record, k: usize, name: &str) -> Result<f64> {
        let period = record.values[k];
        let omega = omega_of_period(period);
        if period > 0.0 && omega.is_finite() {
            Ok(omega)
        } else {
            Err(self.error(
                record.line,
                format!(
                    "{name} = {}: the period must be greater than zero (and give a finite \
                     frequency 2 pi / PER)",
                    written(period)
                ),
            ))
        }
    }
}

/// Checks that every (DOF, heading) asked for is present; the error lists what is missing
/// and what the file has.
fn require_present(
    path: &str,
    dofs: &[usize],
    headings: &[f64],
    present: &[(usize, f64)],
) -> Result<()> {
    let has = |dof: usize, heading: f64| {
        present
            .iter()
            .any(|&(d, h)| d == dof && same_heading(h, heading))
    };
    let deg = |h: f64| format!("{:.3} deg", h.to_degrees());
    let mut missing = Vec::new();
    let absent_dofs: Vec<usize> = dofs
        .iter()
        .copied()
        .filter(|&d| !present.iter().any(|&(p, _)| p == d))
        .collect();
    let absent_headings: Vec<f64> = headings
        .iter()
        .copied()
        .filter(|&h| !present.iter().any(|&(_, p)| same_heading(p, h)))
        .collect();
    if !absent_dofs.is_empty() {
        missing.push(format!("DOF {}", join(absent_dofs.iter())));
    }
    if !absent_headings.is_empty() {
        missing.push(format!(
            "heading {}",
            absent_headings
                .iter()
                .map(|&h| deg(h))
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    for &d in dofs.iter().filter(|d| !absent_dofs.contains(d)) {
        for &h in headings
            .iter()
            .filter(|&&h| !absent_headings.iter().any(|&a| same_heading(a, h)))
        {
            if !has(d, h) {
                missing.push(format!("DOF {d} at {}", deg(h)));
            }
        }
    }
    if missing.is_empty() {
        return Ok(());
    }
    let mut file_dofs: Vec<usize> = present.iter().map(|&(d, _)| d).collect();
    file_dofs.sort_unstable();
    file_dofs.dedup();
    let file_headings = unique_sorted(present.iter().map(|&(_, h)| h).collect(), same_heading);
    Err(Error::Parse {
        path: path.to_string(),
        line: None,
        message: format!(
            "missing {}; the file has DOF {} at headings {}",
            missing.join("; "),
            join(file_dofs.iter()),
            file_headings
                .iter()
                .map(|&h| deg(h))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    })
}

fn join<T: ToString>(items: impl Iterator<Item = T>) -> String {
    items.map(|v| v.to_string()).collect::<Vec<_>>().join(", ")
}
