//! The `.8` (momentum) and `.9` (pressure) files: mean drift forces.

use super::{
    grid_index, require_present, same_frequency, same_heading, unique_sorted, NumericFile,
    WamitOptions,
};
use crate::error::{Error, Result};
use crate::hydro::{DriftRow, DriftTable};
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

/// Uni-directional mean drift (entries with beta1 = beta2) of a `.8` or `.9` file.
#[derive(Debug, Clone, PartialEq)]
pub struct MeanDrift {
    path: String,
    omegas: Vec<f64>,
    blocks: Vec<DriftBlock>,
}

/// Reads a `.8` or `.9` file: lines `PER beta1 beta2 I |F| phase Re Im`, F = rho g L^k Re
/// (k = 1 forces, 2 moments) per unit amplitude squared. Bi-directional entries
/// (beta1 != beta2) are skipped. Every (DOF, heading) in the file must cover all of the
/// file's frequencies.
pub fn read_mean_drift(path: &Path, options: &WamitOptions) -> Result<MeanDrift> {
    options.validate()?;
    let file = NumericFile::read(path, &[8], "PER beta1 beta2 I |F| phase Re Im")?;
    struct Entry {
        line: usize,
        omega: f64,
        heading: f64,
        dof: usize,
        value: f64,
    }
    let mut entries = Vec::new();
    for r in &file.records {
        let omega = file.frequency(r, 0, "PER")?;
        let dof = file.dof(r, 3, "I")?;
        let (b1, b2) = (r.values[1].to_radians(), r.values[2].to_radians());
        if !same_heading(b1, b2) {
            continue;
        }
        entries.push(Entry {
            line: r.line,
            omega,
            heading: b1,
            dof,
            value: options.force_scale(dof) * r.values[6],
        });
    }
    if entries.is_empty() {
        return Err(Error::Parse {
            path: file.path,
            line: None,
            message: "no uni-directional entries (beta1 = beta2)".into(),
        });
    }
    let omegas = unique_sorted(entries.iter().map(|e| e.omega).collect(), same_frequency);
    let mut blocks: Vec<(DriftBlock, Vec<Option<usize>>)> = Vec::new();
    for e in &entries {
        let k = match blocks
            .iter()
            .position(|(b, _)| b.dof == e.dof && same_heading(b.heading, e.heading))
        {
            Some(k) => k,
            None => {
                blocks.push((
                    DriftBlock {
                        dof: e.dof,
                        heading: e.heading,
                        values: vec![0.0; omegas.len()],
                    },
                    vec![None; omegas.len()],
                ));
                blocks.len() - 1
            }
        };
        let iw = grid_index(&omegas, e.omega, same_frequency).expect("frequency collected");
        let (block, lines) = &mut blocks[k];
        if let Some(first) = lines[iw].replace(e.line) {
            return Err(file.error(
                e.line,
                format!(
                    "DOF {} at heading {} deg and omega {:.6} rad/s given twice (first at line {first})",
                    e.dof,
                    e.heading.to_degrees(),
                    e.omega
                ),
            ));
        }
        block.values[iw] = e.value;
    }
    for (block, lines) in &blocks {
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
                    "DOF {} at heading {:.3} deg lacks {} of the file's {} frequencies: {} rad/s",
                    block.dof,
                    block.heading.to_degrees(),
                    holes.len(),
                    omegas.len(),
                    holes.join(", ")
                ),
            });
        }
    }
    let mut blocks: Vec<DriftBlock> = blocks.into_iter().map(|(b, _)| b).collect();
    blocks.sort_by(|a, b| a.dof.cmp(&b.dof).then(a.heading.total_cmp(&b.heading)));
    Ok(MeanDrift {
        path: file.path,
        omegas,
        blocks,
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
