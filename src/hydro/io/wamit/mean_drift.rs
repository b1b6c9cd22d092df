//! The `.8` (momentum) and `.9` (pressure) files: mean drift forces.

use super::{
    grid_index, require_present, same_frequency, same_heading, unique_sorted, NumericFile,
    WamitOptions,
};
use crate::error::{Error, Result};
use crate::hydro::bidirectional::BidirectionalTable;
use crate::hydro::{DriftRow, DriftTable};
use rustfft::num_complex::Complex64;
use std::path::Path;

/// Mean drift of one DOF at one heading over the file's frequencies.
#[derive(Debug, Clone, PartialEq)]
pub struct DriftBlock {
    /// WAMIT DOF, 1 ..= 6.
    pub dof: usize,
    /// Heading, rad.
    pub heading: f64,
    /// Mean drift per unit amplitude squared (N/m^2 or N m/m^2) at each frequency.
    pub values: Vec<f64>,
}

/// The mean drift of a `.8` or `.9` file: uni-directional (beta1 = beta2) and, when the
/// file has them, bi-directional entries (beta1 != beta2).
#[derive(Debug, Clone, PartialEq)]
pub struct MeanDrift {
    path: String,
    omegas: Vec<f64>,
    blocks: Vec<DriftBlock>,
    pairs: Vec<PairBlock>,
}

/// Bi-directional mean drift of one DOF for one heading pair (beta1 != beta2) over the
/// file's frequencies: T(omega; beta1, beta2), complex.
#[derive(Debug, Clone, PartialEq)]
pub struct PairBlock {
    /// WAMIT DOF, 1 ..= 6.
    pub dof: usize,
    /// (beta1, beta2), rad.
    pub headings: (f64, f64),
    /// Re + i Im, scaled (N/m^2 or N m/m^2 per unit amplitude squared).
    pub values: Vec<Complex64>,
}

/// Reads a `.8` or `.9` file: lines `PER beta1 beta2 I |F| phase Re Im`, F = rho g L^k
/// (Re + i Im) (k = 1 forces, 2 moments) per unit amplitude squared. Uni-directional
/// entries (beta1 = beta2) keep the real part (the mean drift in one regular wave);
/// bi-directional entries (beta1 != beta2) are T(omega; beta1, beta2) of two regular waves
/// of one frequency with amplitudes a_1, a_2 (the crate's e^{i omega t}), whose mean force is
/// sum_{p,q} a_p a_q* T(beta_p, beta_q) ([`crate::hydro::bidirectional`]): beta1 goes with
/// the amplitude that is not conjugated, as PER1 in the QTF files. Every (DOF, heading or
/// heading pair) in the file must cover all of the file's frequencies.
pub fn read_mean_drift(path: &Path, options: &WamitOptions) -> Result<MeanDrift> {
    options.validate()?;
    let file = NumericFile::read(
        path,
        &[8],
        "PER beta1 beta2 I |F| phase Re Im",
        options.memory_limit,
    )?;
    struct Entry {
        line: usize,
        omega: f64,
        headings: (f64, f64),
        dof: usize,
        value: Complex64,
    }
    let mut entries = Vec::new();
    for r in &file.records {
        let omega = file.frequency(r, 0, "PER")?;
        let dof = file.dof(r, 3, "I")?;
        file.check_polar(r, 4)?;
        let (b1, b2) = (r.values[1].to_radians(), r.values[2].to_radians());
        entries.push(Entry {
            line: r.line,
            omega,
            headings: (b1, if same_heading(b1, b2) { b1 } else { b2 }),
            dof,
            value: Complex64::new(r.values[6], r.values[7]) * options.force_scale(dof),
        });
    }
    let omegas = unique_sorted(entries.iter().map(|e| e.omega).collect(), same_frequency);
    type Slots = (usize, (f64, f64), Vec<Complex64>, Vec<Option<usize>>);
    let mut blocks: Vec<Slots> = Vec::new();
    for e in &entries {
        let k = match blocks.iter().position(|(dof, h, _, _)| {
            *dof == e.dof && same_heading(h.0, e.headings.0) && same_heading(h.1, e.headings.1)
        }) {
            Some(k) => k,
            None => {
                blocks.push((
                    e.dof,
                    e.headings,
                    vec![Complex64::default(); omegas.len()],
                    vec![None; omegas.len()],
                ));
                blocks.len() - 1
            }
        };
        let iw = grid_index(&omegas, e.omega, same_frequency).expect("frequency collected");
        let (_, _, values, lines) = &mut blocks[k];
        if let Some(first) = lines[iw].replace(e.line) {
            return Err(file.error(
                e.line,
                format!(
                    "DOF {} at headings ({}, {}) deg and omega {:.6} rad/s given twice (first at \
                     line {first})",
                    e.dof,
                    e.headings.0.to_degrees(),
                    e.headings.1.to_degrees(),
                    e.omega
                ),
            ));
        }
        values[iw] = e.value;
    }
    for (dof, headings, _, lines) in &blocks {
        let holes: Vec<String> = lines
            .iter()
            .zip(&omegas)
            .filter(|(l, _)| l.is_none())
            .map(|(_, w)| format!("{w:.6}"))
            .collect();
        if !holes.is_empty() {
            return Err(Error::Parse {
                path: file.path.clone(),
                line: None,
                message: format!(
                    "DOF {dof} at {} lacks {} of the file's {} frequencies: {} rad/s",
                    if headings.0 == headings.1 {
                        format!("heading {:.3} deg", headings.0.to_degrees())
                    } else {
                        format!(
                            "headings ({:.3}, {:.3}) deg",
                            headings.0.to_degrees(),
                            headings.1.to_degrees()
                        )
                    },
                    holes.len(),
                    omegas.len(),
                    holes.join(", ")
                ),
            });
        }
    }
    let mut uni = Vec::new();
    let mut pairs = Vec::new();
    for (dof, headings, values, _) in blocks {
        if headings.0 == headings.1 {
            uni.push(DriftBlock {
                dof,
                heading: headings.0,
                values: values.iter().map(|v| v.re).collect(),
            });
        } else {
            pairs.push(PairBlock {
                dof,
                headings,
                values,
            });
        }
    }
    if uni.is_empty() {
        return Err(Error::Parse {
            path: file.path,
            line: None,
            message: "no uni-directional entries (beta1 = beta2)".into(),
        });
    }
    uni.sort_by(|a, b| a.dof.cmp(&b.dof).then(a.heading.total_cmp(&b.heading)));
    pairs.sort_by(|a, b| {
        a.dof
            .cmp(&b.dof)
            .then(a.headings.0.total_cmp(&b.headings.0))
            .then(a.headings.1.total_cmp(&b.headings.1))
    });
    Ok(MeanDrift {
        path: file.path,
        omegas,
        blocks: uni,
        pairs,
    })
}

impl MeanDrift {
    /// Frequencies, rad/s, increasing.
    pub fn omegas(&self) -> &[f64] {
        &self.omegas
    }

    /// Every (DOF, heading) block, sorted by DOF then heading.
    pub fn blocks(&self) -> &[DriftBlock] {
        &self.blocks
    }

    /// The bi-directional blocks (beta1 != beta2), sorted by DOF, beta1, beta2.
    pub fn pairs(&self) -> &[PairBlock] {
        &self.pairs
    }

    /// The bi-directional drift T(omega; beta_p, beta_q) of `dofs` (WAMIT numbering; surge,
    /// sway, yaw = `[1, 2, 6]`) on every pair of the file's headings, or `None` when the file
    /// has no bi-directional entries. The diagonal is the uni-directional drift; a pair the
    /// file gives in one order only is completed by Hermitian symmetry
    /// T(beta_q, beta_p) = conj T(beta_p, beta_q); a file that gives both orders must give
    /// conjugates (within 1e-6 of the table's largest value, checked by
    /// [`BidirectionalTable::validate`]). The error lists every (DOF, heading pair) missing.
    pub fn to_bidirectional_table(&self, dofs: [usize; 3]) -> Result<Option<BidirectionalTable>> {
        if self.pairs.is_empty() {
            return Ok(None);
        }
        let mut headings: Vec<f64> = self.blocks.iter().map(|b| b.heading).collect();
        headings.extend(self.pairs.iter().flat_map(|p| [p.headings.0, p.headings.1]));
        let headings = unique_sorted(headings, same_heading);
        let nw = self.omegas.len();
        let nh = headings.len();
        let mut re = vec![vec![vec![[0.0; 3]; nh]; nh]; nw];
        let mut im = vec![vec![vec![[0.0; 3]; nh]; nh]; nw];
        let mut missing = Vec::new();
        for (i, &dof) in dofs.iter().enumerate() {
            for (p, &hp) in headings.iter().enumerate() {
                for (q, &hq) in headings.iter().enumerate() {
                    let values: Option<Vec<Complex64>> = if p == q {
                        self.block(dof, hp)
                            .map(|b| b.values.iter().map(|&v| Complex64::new(v, 0.0)).collect())
                    } else {
                        self.pair(dof, (hp, hq))
                            .map(|b| b.values.clone())
                            .or_else(|| {
                                self.pair(dof, (hq, hp))
                                    .map(|b| b.values.iter().map(|v| v.conj()).collect())
                            })
                    };
                    match values {
                        Some(values) => {
                            for (n, v) in values.iter().enumerate() {
                                re[n][p][q][i] = v.re;
                                im[n][p][q][i] = v.im;
                            }
                        }
                        None => missing.push(format!(
                            "DOF {dof} at ({:.3}, {:.3}) deg",
                            hp.to_degrees(),
                            hq.to_degrees()
                        )),
                    }
                }
            }
        }
        if !missing.is_empty() {
            return Err(Error::Parse {
                path: self.path.clone(),
                line: None,
                message: format!(
                    "bi-directional drift: {} of the {} (DOF, heading pair) blocks on the file's \
                     headings {} deg are missing in both orders: {}",
                    missing.len(),
                    3 * nh * nh,
                    headings
                        .iter()
                        .map(|h| format!("{:.3}", h.to_degrees()))
                        .collect::<Vec<_>>()
                        .join(", "),
                    missing.join("; ")
                ),
            });
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

    fn pair(&self, dof: usize, headings: (f64, f64)) -> Option<&PairBlock> {
        self.pairs.iter().find(|b| {
            b.dof == dof
                && same_heading(b.headings.0, headings.0)
                && same_heading(b.headings.1, headings.1)
        })
    }

    /// Headings present for any DOF, rad, increasing.
    pub fn headings(&self) -> Vec<f64> {
        unique_sorted(
            self.blocks.iter().map(|b| b.heading).collect(),
            same_heading,
        )
    }

    /// The drift of `dof` at `heading` (rad) over [`Self::omegas`]; the error lists what
    /// is missing.
    pub fn values(&self, dof: usize, heading: f64) -> Result<&[f64]> {
        self.require(&[dof], &[heading])?;
        Ok(&self.block(dof, heading).expect("checked").values)
    }

    /// The drift table of `dofs` (WAMIT numbering; surge, sway, yaw = `[1, 2, 6]`) at
    /// `headings` (rad); no damping. The error lists every missing DOF and heading.
    pub fn to_drift_table(&self, headings: &[f64], dofs: [usize; 3]) -> Result<DriftTable> {
        self.require(&dofs, headings)?;
        let mut rows = Vec::with_capacity(headings.len() * self.omegas.len());
        for &heading in headings {
            let columns = dofs.map(|d| &self.block(d, heading).expect("checked").values);
            for (iw, &omega) in self.omegas.iter().enumerate() {
                rows.push(DriftRow {
                    omega,
                    heading,
                    drift: columns.map(|c| c[iw]),
                    damping: None,
                });
            }
        }
        DriftTable::from_rows(&rows)
    }

    fn block(&self, dof: usize, heading: f64) -> Option<&DriftBlock> {
        self.blocks
            .iter()
            .find(|b| b.dof == dof && same_heading(b.heading, heading))
    }

    fn require(&self, dofs: &[usize], headings: &[f64]) -> Result<()> {
        let present: Vec<(usize, f64)> = self.blocks.iter().map(|b| (b.dof, b.heading)).collect();
        require_present(&self.path, dofs, headings, &present)
    }
}
