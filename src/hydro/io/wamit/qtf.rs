//! The `.10d`, `.11d` and `.12d` files: difference-frequency quadratic transfer functions.

use super::{
    grid_index, require_present, same_frequency, same_heading, unique_sorted, NumericFile,
    WamitOptions,
};
use crate::error::{Error, Result};
use crate::files::afford;
use crate::hydro::bidirectional::BidirectionalTable;
use crate::hydro::reference_point::ReferencePoint;
use crate::hydro::{DriftRow, DriftTable};
use rustfft::num_complex::Complex64;
use std::collections::{HashMap, HashSet};
use std::path::Path;

/// The QTF of one DOF for one heading pair on the full frequency grid.
#[derive(Debug, Clone, PartialEq)]
pub struct QtfBlock {
    /// WAMIT DOF, 1 ..= 6.
    pub dof: usize,
    /// (beta1, beta2), rad: the headings of the waves at w_i and w_j.
    pub headings: (f64, f64),
    /// Row-major n x n: `values[i * n + j]` = T(w_i, w_j), N/m^2 or N m/m^2.
    pub values: Vec<Complex64>,
}

/// A difference-frequency QTF, complete on its grid: T(w_i, w_j; beta1, beta2) for every
/// DOF and heading pair of the file, with the triangle the file omits filled by Hermitian
/// symmetry T(w_j, w_i; beta2, beta1) = conj T(w_i, w_j; beta1, beta2).
///
/// Values follow F(t) = Re sum_i sum_j a_i a_j* T(w_i, w_j) e^{i (w_i - w_j) t}
/// (docs/theory.md#the-slowly-varying-force; WAMIT's own definition, see the module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct DifferenceQtf {
    path: String,
    omegas: Vec<f64>,
    blocks: Vec<QtfBlock>,
    filled_by_symmetry: usize,
    filled_by_interpolation: usize,
}

/// Memory per frequency pair of a block of a QTF being read, bytes: its value (complex, 16)
/// and the line that gave it (16) while the blocks are assembled, the flag of the sparse
/// fill; then the value and the database's copy of it (16 + 16) when it is imported. The
/// measured peak of a file whose every line has its own frequencies is 33 n^2 per block.
pub const BYTES_PER_PAIR: f64 = 40.0;

/// One line of the file, scaled.
struct Entry {
    line: usize,
    dof: usize,
    heading_index: (usize, usize),
    omega_index: (usize, usize),
    value: Complex64,
}

/// Reads a `.10d`, `.11d` or `.12d` file: lines `PER1 PER2 beta1 beta2 I |F| phase Re Im`,
/// T = rho g L^k (Re + i Im), k = 1 forces, 2 moments, per unit amplitude squared. One
/// triangle or both may be given, in any order.
///
/// A file with bi-directional blocks (beta1 != beta2) must have, after the Hermitian fill
/// (which makes (beta2, beta1) from (beta1, beta2)), a block for every DOF it lists and every
/// pair of its headings; the error lists the missing (DOF, heading pair) blocks.
///
/// Sparse files (pairs missing off the diagonal, as in QTFs converted from other codes):
/// after the Hermitian fill, a pair (i, j) still missing is filled by linear interpolation
/// in the mean frequency (w_i + w_j)/2 along its difference-frequency line (the matrix diagonal j - i = const, constant
/// w_i - w_j on a uniform grid) between the nearest given pairs of that line on either
/// side, and counted ([`DifferenceQtf::filled_by_interpolation`], which the import reports
/// as a warning). A pair with no given pair on one side of its line (beyond the largest
/// difference frequency the file gives, or at the grid's ends) is not extrapolated: the
/// error lists every such pair.
pub fn read_difference_qtf(path: &Path, options: &WamitOptions) -> Result<DifferenceQtf> {
    options.validate()?;
    let file = NumericFile::read(
        path,
        &[9],
        "PER1 PER2 beta1 beta2 I |F| phase Re Im",
        options.memory_limit,
    )?;
    let mut entries = Vec::with_capacity(file.records.len());
    for r in &file.records {
        let omegas = (file.frequency(r, 0, "PER1")?, file.frequency(r, 1, "PER2")?);
        let dof = file.dof(r, 4, "I")?;
        file.check_polar(r, 5)?;
        let v = &r.values;
        entries.push(QtfEntry {
            line: r.line,
            dof,
            omegas,
            headings: (v[2].to_radians(), v[3].to_radians()),
            value: Complex64::new(v[7], v[8]) * options.force_scale(dof),
        });
    }
    assemble_qtf(file.path, entries, options.memory_limit)
}

/// One value of a QTF file in the crate's units and convention: T(w_i, w_j; beta1, beta2)
/// of a DOF, per unit amplitude squared, and the 1-based line it came from.
pub(in crate::hydro::io) struct QtfEntry {
    pub line: usize,
    pub dof: usize,
    /// (w_i, w_j), rad/s.
    pub omegas: (f64, f64),
    /// (beta1, beta2), rad.
    pub headings: (f64, f64),
    pub value: Complex64,
}

/// The QTF of a file's entries (WAMIT's, NEMOH's): the frequency and heading grids (values
/// within the match tolerances are one node), entries given twice refused naming both
/// lines, the Hermitian fill, the sparse fill and the checks of [`read_difference_qtf`].
///
/// The matrices are budgeted before they are made: n x n frequency pairs for each block
/// (DOF and heading pair, mirrors included), [`BYTES_PER_PAIR`] each, within `memory_limit`
/// bytes (a file of a few thousand lines, each at its own frequencies, would otherwise ask
/// for terabytes).
pub(in crate::hydro::io) fn assemble_qtf(
    path: String,
    lines: Vec<QtfEntry>,
    memory_limit: f64,
) -> Result<DifferenceQtf> {
    let omegas = unique_sorted(
        lines
            .iter()
            .flat_map(|e| [e.omegas.0, e.omegas.1])
            .collect(),
        same_frequency,
    );
    let headings = unique_sorted(
        lines
            .iter()
            .flat_map(|e| [e.headings.0, e.headings.1])
            .collect(),
        same_heading,
    );
    let frequency = |v: f64| grid_index(&omegas, v, same_frequency).expect("collected");
    let heading = |v: f64| grid_index(&headings, v, same_heading).expect("collected");
    let entries: Vec<Entry> = lines
        .iter()
        .map(|e| Entry {
            line: e.line,
            dof: e.dof,
            heading_index: (heading(e.headings.0), heading(e.headings.1)),
            omega_index: (frequency(e.omegas.0), frequency(e.omegas.1)),
            value: e.value,
        })
        .collect();
    let error = |line: usize, message: String| Error::Parse {
        path: path.clone(),
        line: Some(line),
        message,
    };
    let n = omegas.len();
    let keys: HashSet<(usize, usize, usize)> = entries
        .iter()
        .flat_map(|e| {
            let (b1, b2) = e.heading_index;
            [(e.dof, b1, b2), (e.dof, b2, b1)]
        })
        .collect();
    let pairs = (n * n) as f64;
    afford(
        &path,
        keys.len() as f64 * pairs * BYTES_PER_PAIR,
        || {
            format!(
                "a QTF of {n} x {n} frequency pairs in {} blocks (DOF and heading pair, \
                 mirrors included), {BYTES_PER_PAIR} bytes per pair",
                keys.len()
            )
        },
        memory_limit,
    )?;
    // Block key (dof, beta1 index, beta2 index) -> (values, line of each value; 0 = filled).
    type Slots = (Vec<Complex64>, Vec<Option<usize>>);
    let mut blocks: HashMap<(usize, usize, usize), Slots> = HashMap::new();
    for e in &entries {
        let key = (e.dof, e.heading_index.0, e.heading_index.1);
        let (values, lines) = blocks
            .entry(key)
            .or_insert_with(|| (vec![Complex64::new(0.0, 0.0); n * n], vec![None; n * n]));
        let (i, j) = e.omega_index;
        if let Some(first) = lines[i * n + j].replace(e.line) {
            return Err(error(
                e.line,
                format!(
                    "DOF {} at headings ({:.3}, {:.3}) deg and frequencies ({:.6}, {:.6}) rad/s \
                     given twice (first at line {first})",
                    e.dof,
                    headings[key.1].to_degrees(),
                    headings[key.2].to_degrees(),
                    omegas[i],
                    omegas[j]
                ),
            ));
        }
        values[i * n + j] = e.value;
    }
    let mut filled_by_symmetry = 0;
    for e in &entries {
        let mirror = (e.dof, e.heading_index.1, e.heading_index.0);
        let (i, j) = e.omega_index;
        let (values, lines) = blocks
            .entry(mirror)
            .or_insert_with(|| (vec![Complex64::new(0.0, 0.0); n * n], vec![None; n * n]));
        if lines[j * n + i].is_none() {
            lines[j * n + i] = Some(0);
            values[j * n + i] = e.value.conj();
            filled_by_symmetry += 1;
        }
    }
    let mut keys: Vec<(usize, usize, usize)> = blocks.keys().copied().collect();
    keys.sort_unstable();
    let mut out = Vec::with_capacity(keys.len());
    let mut filled_by_interpolation = 0;
    for key in keys {
        let (mut values, lines) = blocks.remove(&key).expect("key listed");
        let mut given: Vec<bool> = lines.iter().map(Option::is_some).collect();
        drop(lines);
        let missing = given.iter().filter(|g| !**g).count();
        let (unfilled, first) = fill_along_difference_lines(&omegas, &mut values, &mut given);
        if unfilled > 0 {
            return Err(Error::Parse {
                path: path.clone(),
                line: None,
                message: format!(
                    "DOF {} at headings ({:.3}, {:.3}) deg: {unfilled} of {} frequency pairs \
                     missing even with Hermitian symmetry and not between two given pairs of \
                     their difference-frequency line (nothing is extrapolated): {}{}",
                    key.0,
                    headings[key.1].to_degrees(),
                    headings[key.2].to_degrees(),
                    n * n,
                    list_pairs(&omegas, &first),
                    if unfilled > first.len() {
                        format!(" and {} more", unfilled - first.len())
                    } else {
                        String::new()
                    }
                ),
            });
        }
        filled_by_interpolation += missing;
        out.push(QtfBlock {
            dof: key.0,
            headings: (headings[key.1], headings[key.2]),
            values,
        });
    }
    if out.iter().any(|b| b.headings.0 != b.headings.1) {
        require_every_pair(&path, &headings, &out)?;
    }
    Ok(DifferenceQtf {
        path,
        omegas,
        blocks: out,
        filled_by_symmetry,
        filled_by_interpolation,
    })
}

impl DifferenceQtf {
    /// Frequencies, rad/s, increasing and unique.
    pub fn omegas(&self) -> &[f64] {
        &self.omegas
    }

    /// Index of `omega` (rad/s) in [`Self::omegas`], within the relative tolerance.
    pub fn omega_index(&self, omega: f64) -> Option<usize> {
        grid_index(&self.omegas, omega, same_frequency)
    }

    /// Every (DOF, heading pair) block, sorted by DOF, then beta1, then beta2.
    pub fn blocks(&self) -> &[QtfBlock] {
        &self.blocks
    }

    /// DOFs present, increasing.
    pub fn dofs(&self) -> Vec<usize> {
        let mut dofs: Vec<usize> = self.blocks.iter().map(|b| b.dof).collect();
        dofs.dedup();
        dofs
    }

    /// Headings of the uni-directional blocks (beta1 = beta2), rad, increasing.
    pub fn headings(&self) -> Vec<f64> {
        unique_sorted(
            self.blocks
                .iter()
                .filter(|b| same_heading(b.headings.0, b.headings.1))
                .map(|b| b.headings.0)
                .collect(),
            same_heading,
        )
    }

    /// How many values were filled in by Hermitian symmetry (0 when the file has both
    /// triangles).
    pub fn filled_by_symmetry(&self) -> usize {
        self.filled_by_symmetry
    }

    /// How many values were missing even with Hermitian symmetry and were filled by linear
    /// interpolation along their difference-frequency line ([`read_difference_qtf`]).
    pub fn filled_by_interpolation(&self) -> usize {
        self.filled_by_interpolation
    }

    /// T(w_i, w_j) of `dof` for waves at `headings` = (beta1, beta2), rad.
    pub fn value(&self, dof: usize, headings: (f64, f64), i: usize, j: usize) -> Option<Complex64> {
        let n = self.omegas.len();
        self.block(dof, headings)
            .filter(|_| i < n && j < n)
            .map(|b| b.values[i * n + j])
    }

    /// The uni-directional n x n matrix of `dof` at `heading` (rad), row-major
    /// (`[i * n + j]` = T(w_i, w_j)); the error lists what is missing.
    pub fn matrix(&self, dof: usize, heading: f64) -> Result<&[Complex64]> {
        self.require(&[dof], &[heading])?;
        Ok(&self.block(dof, (heading, heading)).expect("checked").values)
    }

    /// The diagonal (omega, Re T(omega, omega)) of `dof` at `heading` (rad): the mean drift
    /// in regular waves of unit amplitude. The imaginary part of the diagonal is numerical
    /// noise in WAMIT's output and is dropped here (it stays in the stored QTF).
    pub fn diagonal(&self, dof: usize, heading: f64) -> Result<Vec<(f64, f64)>> {
        let n = self.omegas.len();
        let m = self.matrix(dof, heading)?;
        Ok((0..n).map(|i| (self.omegas[i], m[i * n + i].re)).collect())
    }

    /// The mean drift table from the diagonal of `dofs` (WAMIT numbering; surge, sway,
    /// yaw = `[1, 2, 6]`) at `headings` (rad); no damping. The error lists every missing
    /// DOF and heading.
    pub fn to_drift_table(&self, headings: &[f64], dofs: [usize; 3]) -> Result<DriftTable> {
        self.require(&dofs, headings)?;
        let n = self.omegas.len();
        let mut rows = Vec::with_capacity(headings.len() * n);
        for &heading in headings {
            let m = dofs.map(|d| &self.block(d, (heading, heading)).expect("checked").values);
            for (i, &omega) in self.omegas.iter().enumerate() {
                rows.push(DriftRow {
                    omega,
                    heading,
                    drift: m.map(|v| v[i * n + i].re),
                    damping: None,
                });
            }
        }
        DriftTable::from_rows(&rows)
    }

    /// Moves the yaw moments of every heading pair from the vertical axis through `point`
    /// to the body origin: T_yaw += x_r T_sway - y_r T_surge ([`ReferencePoint`]), with
    /// `dofs` the file's DOF numbers of surge, sway and yaw; the error lists the missing
    /// blocks a moved yaw block needs.
    pub fn move_yaw_moment(&mut self, dofs: [usize; 3], point: ReferencePoint) -> Result<()> {
        let pairs: Vec<(f64, f64)> = self
            .blocks
            .iter()
            .filter(|b| b.dof == dofs[2])
            .map(|b| b.headings)
            .collect();
        for headings in pairs {
            let force = |d: usize| -> Result<Vec<Complex64>> {
                self.block(d, headings)
                    .map(|b| b.values.clone())
                    .ok_or_else(|| Error::Parse {
                        path: self.path.clone(),
                        line: None,
                        message: format!(
                            "moving the yaw moment to the origin needs DOF {d} at headings \
                         ({:.3}, {:.3}) deg, which the file lacks",
                            headings.0.to_degrees(),
                            headings.1.to_degrees()
                        ),
                    })
            };
            let (surge, sway) = (force(dofs[0])?, force(dofs[1])?);
            let yaw = self
                .blocks
                .iter_mut()
                .find(|b| b.dof == dofs[2] && b.headings == headings)
                .expect("listed");
            for ((m, fx), fy) in yaw.values.iter_mut().zip(&surge).zip(&sway) {
                *m = point.complex_force_to_origin([*fx, *fy, *m])[2];
            }
        }
        Ok(())
    }

    /// The bi-directional mean drift T(w; beta_p, beta_q) = the diagonal T(w, w; beta_p,
    /// beta_q) of every heading pair, for `dofs` (the file's numbers of surge, sway, yaw),
    /// or `None` when the QTF has no bi-directional blocks (the reader made sure that a
    /// bi-directional file has every pair).
    pub fn to_bidirectional_table(&self, dofs: [usize; 3]) -> Result<Option<BidirectionalTable>> {
        if self.blocks.iter().all(|b| b.headings.0 == b.headings.1) {
            return Ok(None);
        }
        let headings = unique_sorted(
            self.blocks.iter().map(|b| b.headings.0).collect(),
            same_heading,
        );
        let (nw, nh) = (self.omegas.len(), headings.len());
        let mut re = vec![vec![vec![[0.0; 3]; nh]; nh]; nw];
        let mut im = re.clone();
        for (p, &bp) in headings.iter().enumerate() {
            for (q, &bq) in headings.iter().enumerate() {
                for (i, &dof) in dofs.iter().enumerate() {
                    let block = self.block(dof, (bp, bq)).ok_or_else(|| Error::Parse {
                        path: self.path.clone(),
                        line: None,
                        message: format!(
                            "no DOF {dof} at headings ({:.3}, {:.3}) deg for the bi-directional drift",
                            bp.to_degrees(),
                            bq.to_degrees()
                        ),
                    })?;
                    for n in 0..nw {
                        let v = block.values[n * nw + n];
                        re[n][p][q][i] = v.re;
                        im[n][p][q][i] = v.im;
                    }
                }
            }
        }
        let table = BidirectionalTable {
            omegas: self.omegas.clone(),
            headings,
            re,
            im,
        };
        table.validate().map_err(|e| Error::Parse {
            path: self.path.clone(),
            line: None,
            message: e.to_string(),
        })?;
        Ok(Some(table))
    }

    fn block(&self, dof: usize, headings: (f64, f64)) -> Option<&QtfBlock> {
        self.blocks.iter().find(|b| {
            b.dof == dof
                && same_heading(b.headings.0, headings.0)
                && same_heading(b.headings.1, headings.1)
        })
    }

    fn require(&self, dofs: &[usize], headings: &[f64]) -> Result<()> {
        let present: Vec<(usize, f64)> = self
            .blocks
            .iter()
            .filter(|b| same_heading(b.headings.0, b.headings.1))
            .map(|b| (b.dof, b.headings.0))
            .collect();
        require_present(&self.path, dofs, headings, &present)
    }
}

/// Fills the values of an n x n block (row-major) that are not `given`, each by linear
/// interpolation in the mean frequency (w_i + w_j)/2 between the nearest given values on
/// either side along its diagonal (j - i constant); the mirror (j, i) of a cell has the same
/// mean frequency and mirrored neighbours, so a Hermitian block stays Hermitian. Marks each
/// value it fills in `given`. Returns how many values have no given value on one side, and
/// the (i, j) of the first [`LISTED`] of them in row order (a sparse file of n frequencies
/// may leave n^2 of them: they are counted, not collected).
fn fill_along_difference_lines(
    omegas: &[f64],
    values: &mut [Complex64],
    given: &mut [bool],
) -> (usize, Vec<(usize, usize)>) {
    let n = omegas.len();
    for d in -(n as isize - 1)..=(n as isize - 1) {
        // The line's cells (i, i + d), by increasing i.
        let cells: Vec<(usize, usize)> = (0..n)
            .filter_map(|i| {
                let j = i as isize + d;
                (0..n as isize).contains(&j).then_some((i, j as usize))
            })
            .collect();
        let known: Vec<usize> = (0..cells.len())
            .filter(|&k| given[cells[k].0 * n + cells[k].1])
            .collect();
        for (k, &(i, j)) in cells.iter().enumerate() {
            if given[i * n + j] {
                continue;
            }
            let after = known.partition_point(|&m| m < k);
            if after == 0 || after == known.len() {
                continue;
            }
            let (a, b) = (cells[known[after - 1]], cells[known[after]]);
            let mean = |(i, j): (usize, usize)| omegas[i] + omegas[j];
            let s = (mean((i, j)) - mean(a)) / (mean(b) - mean(a));
            values[i * n + j] = values[a.0 * n + a.1] * (1.0 - s) + values[b.0 * n + b.1] * s;
            // `known` was taken before this line's fills: they do not feed each other.
            given[i * n + j] = true;
        }
    }
    let unfilled = given.iter().filter(|g| !**g).count();
    let first = (0..n * n)
        .filter(|&k| !given[k])
        .take(LISTED)
        .map(|k| (k / n, k % n))
        .collect();
    (unfilled, first)
}

/// How many missing frequency pairs an error lists (the rest are counted).
const LISTED: usize = 20;

/// Pairs of frequencies, rad/s, grouped by their first frequency: "w1 = 0.25: w2 = 1.5, 1.6;
/// w1 = 0.3: ...".
fn list_pairs(omegas: &[f64], pairs: &[(usize, usize)]) -> String {
    let mut rows: Vec<String> = Vec::new();
    let mut k = 0;
    while k < pairs.len() {
        let i = pairs[k].0;
        let end = k + pairs[k..].iter().take_while(|p| p.0 == i).count();
        let seconds: Vec<String> = pairs[k..end]
            .iter()
            .map(|&(_, j)| format!("{:.6}", omegas[j]))
            .collect();
        rows.push(format!(
            "w1 = {:.6}: w2 = {}",
            omegas[i],
            seconds.join(", ")
        ));
        k = end;
    }
    format!("{} rad/s", rows.join("; "))
}

/// Every (DOF, beta1, beta2) on `headings` for the DOFs of `blocks`; the error lists the
/// missing ones.
fn require_every_pair(path: &str, headings: &[f64], blocks: &[QtfBlock]) -> Result<()> {
    let mut dofs: Vec<usize> = blocks.iter().map(|b| b.dof).collect();
    dofs.dedup();
    let mut missing = Vec::new();
    for &dof in &dofs {
        for &b1 in headings {
            for &b2 in headings {
                let present = blocks.iter().any(|b| {
                    b.dof == dof && same_heading(b.headings.0, b1) && same_heading(b.headings.1, b2)
                });
                if !present {
                    missing.push(format!(
                        "DOF {dof} at ({:.3}, {:.3}) deg",
                        b1.to_degrees(),
                        b2.to_degrees()
                    ));
                }
            }
        }
    }
    if missing.is_empty() {
        return Ok(());
    }
    Err(Error::Parse {
        path: path.to_string(),
        line: None,
        message: format!(
            "a bi-directional QTF needs every pair of its headings {} deg for DOFs {}: {} of \
             the {} (DOF, heading pair) blocks are missing even with Hermitian symmetry: {}",
            headings
                .iter()
                .map(|h| format!("{:.3}", h.to_degrees()))
                .collect::<Vec<_>>()
                .join(", "),
            dofs.iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", "),
            missing.len(),
            dofs.len() * headings.len() * headings.len(),
            missing.join("; ")
        ),
    })
}
