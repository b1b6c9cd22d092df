//! The `.hst` file: hydrostatic restoring coefficients.

use super::{NumericFile, WamitOptions};
use crate::error::Result;
use std::path::Path;

/// Hydrostatic stiffness of the six rigid-body DOFs, SI (N/m, N, N m/rad).
///
/// Hydrostatics alone give no surge, sway or yaw stiffness for a floating body: those come
/// from the mooring.
#[derive(Debug, Clone, PartialEq)]
pub struct Hydrostatics {
    /// C_ij; entries the file does not list are zero.
    pub c: [[f64; 6]; 6],
}

/// Reads a `.hst` file: lines `I J Cbar`; C = rho g L^k Cbar, k = 2 (translation-translation),
/// 3 (mixed), 4 (rotation-rotation).
pub fn read_hydrostatics(path: &Path, options: &WamitOptions) -> Result<Hydrostatics> {
    options.validate()?;
    let file = NumericFile::read(path, &[3], "I J Cbar", options.memory_limit)?;
    let mut c = [[0.0; 6]; 6];
    let mut seen = [[None::<usize>; 6]; 6];
    for r in &file.records {
        let i = file.dof(r, 0, "I")?;
        let j = file.dof(r, 1, "J")?;
        if let Some(first) = seen[i - 1][j - 1].replace(r.line) {
            return Err(file.error(
                r.line,
                format!("entry ({i}, {j}) given twice (first at line {first})"),
            ));
        }
        c[i - 1][j - 1] = options.stiffness_scale(i, j) * r.values[2];
    }
    Ok(Hydrostatics { c })
}
