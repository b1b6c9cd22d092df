//! What an import from a diffraction code's output gives (the same for every code: the
//! WAMIT and the NEMOH importers return it), and the conversions from the readers' tables to the native database that both use.

use super::database::{DriftPoint, HydroDatabase, QtfData, QtfMatrix};
use super::wamit::DifferenceQtf;
use crate::error::Result;
use crate::hydro::DriftTable;
use crate::model::Dof;
use rustfft::num_complex::Complex64;

/// A database made from a diffraction code's output files, and what was found.
#[derive(Debug, Clone, PartialEq)]
pub struct Import {
    pub database: HydroDatabase,
    /// One line per file looked for: what was taken from it, absent, or why not.
    pub files: Vec<String>,
}

/// Every node of a drift table, heading-major.
pub(crate) fn drift_points(table: &DriftTable) -> Vec<DriftPoint> {
    let mut points = Vec::new();
    for (ih, &heading) in table.headings().iter().enumerate() {
        for (iw, &omega) in table.omegas().iter().enumerate() {
            let [surge, sway, yaw] = table.drift_at_node(ih, iw);
            points.push(DriftPoint {
                omega,
                heading,
                surge,
                sway,
                yaw,
                damping: None,
            });
        }
    }
    points
}

/// The surge, sway and yaw blocks of a QTF (`dofs`: the file's numbers of the three): the
/// uni-directional ones (which must have all three DOFs at every heading), then the
/// bi-directional ones.
pub(crate) fn qtf_data(qtf: &DifferenceQtf, dofs: [usize; 3]) -> Result<QtfData> {
    let n = qtf.omegas().len();
    let matrix = |dof: Dof, headings: (f64, f64), m: &[Complex64]| {
        let part = |f: fn(&Complex64) -> f64| -> Vec<Vec<f64>> {
            m.chunks(n).map(|row| row.iter().map(f).collect()).collect()
        };
        QtfMatrix {
            dof,
            heading: headings.0,
            second_heading: (headings.0 != headings.1).then_some(headings.1),
            re: part(|z| z.re),
            im: part(|z| z.im),
        }
    };
    let mut blocks = Vec::new();
    for heading in qtf.headings() {
        for (dof, wamit_dof) in Dof::ALL.into_iter().zip(dofs) {
            blocks.push(matrix(
                dof,
                (heading, heading),
                qtf.matrix(wamit_dof, heading)?,
            ));
        }
    }
    for block in qtf.blocks().iter().filter(|b| b.headings.0 != b.headings.1) {
        if let Some(k) = dofs.iter().position(|&d| d == block.dof) {
            blocks.push(matrix(Dof::ALL[k], block.headings, &block.values));
        }
    }
    Ok(QtfData {
        omegas: qtf.omegas().to_vec(),
        blocks,
    })
}
