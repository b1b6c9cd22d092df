//! The `.1` file: added mass and radiation damping.

use super::NumericFile;
use super::WamitOptions;
use crate::error::numbers::written;
use crate::error::Result;
use std::collections::HashMap;
use std::path::Path;

/// Added mass and damping of the six rigid-body DOFs, SI (kg, kg m, kg m^2; N s/m, ...).
///
/// Entries the file does not list are zero (WAMIT omits those that vanish by symmetry).
#[derive(Debug, Clone, PartialEq)]
pub struct AddedMassDamping {
    /// Finite, positive frequencies, rad/s, increasing.
    pub omegas: Vec<f64>,
    /// Added mass A_ij at each of `omegas`.
    pub added_mass: Vec<[[f64; 6]; 6]>,
    /// Radiation damping B_ij at each of `omegas`.
    pub damping: Vec<[[f64; 6]; 6]>,
    /// A_ij at omega = 0 (PER = -1), if the file has it.
    pub zero_frequency_added_mass: Option<[[f64; 6]; 6]>,
    /// A_ij at omega = infinity (PER = 0), if the file has it.
    pub infinite_frequency_added_mass: Option<[[f64; 6]; 6]>,
}

/// Where a row of the `.1` file belongs.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum Slot {
    Zero,
    Infinite,
    /// Index into the sorted finite frequencies.
    Finite(usize),
}

/// Reads a `.1` file: lines `PER I J Abar Bbar`, or `PER I J Abar` at PER = -1 (omega = 0)
/// and PER = 0 (omega = infinity), where the damping is zero. A = rho L^k Abar,
/// B = rho omega L^k Bbar, k = 3 (translation-translation), 4 (mixed), 5 (rotation-rotation).
pub fn read_added_mass_damping(path: &Path, options: &WamitOptions) -> Result<AddedMassDamping> {
    options.validate()?;
    let file = NumericFile::read(path, &[4, 5], "PER I J Abar [Bbar]", options.memory_limit)?;
    let mut finite = Vec::new();
    for r in &file.records {
        let period = r.values[0];
        if period > 0.0 {
            finite.push(file.frequency(r, 0, "PER")?);
        } else if period != 0.0 && period != -1.0 {
            return Err(file.error(
                r.line,
                format!(
                    "PER = {}: a period is positive, or -1 (omega = 0) or 0 (omega = infinity)",
                    written(period)
                ),
            ));
        } else if r.values.len() == 5 && r.values[4] != 0.0 {
            return Err(file.error(
                r.line,
                format!(
                    "PER = {} (omega = {}) has non-zero damping {}",
                    written(period),
                    if period == 0.0 { "infinity" } else { "0" },
                    written(r.values[4])
                ),
            ));
        }
    }
    let omegas = super::unique_sorted(finite, super::same_frequency);
    if omegas.is_empty() {
        return Err(crate::error::Error::Parse {
            path: file.path.clone(),
            line: None,
            message: "no frequency (no line with PER > 0), only the limits PER = -1 (omega = \
                      0) and 0 (omega = infinity): WAMIT writes them beside the frequencies it \
                      computed; is the file cut?"
                .into(),
        });
    }
    let mut zero = None;
    let mut infinite = None;
    let mut added_mass = vec![[[0.0; 6]; 6]; omegas.len()];
    let mut damping = vec![[[0.0; 6]; 6]; omegas.len()];
    let mut seen: HashMap<(Slot, usize, usize), usize> = HashMap::new();
    for r in &file.records {
        let i = file.dof(r, 1, "I")?;
        let j = file.dof(r, 2, "J")?;
        let period = r.values[0];
        let slot = if period == -1.0 {
            Slot::Zero
        } else if period == 0.0 {
            Slot::Infinite
        } else {
            if r.values.len() != 5 {
                return Err(file.error(
                    r.line,
                    format!(
                        "PER = {}: expected 5 numbers (PER I J Abar Bbar), found 4",
                        written(period)
                    ),
                ));
            }
            let omega = super::omega_of_period(period);
            let k = super::grid_index(&omegas, omega, super::same_frequency)
                .expect("frequency collected above");
            Slot::Finite(k)
        };
        if let Some(first) = seen.insert((slot, i, j), r.line) {
            return Err(file.error(
                r.line,
                format!(
                    "entry ({i}, {j}) at PER = {} given twice (first at line {first})",
                    written(period)
                ),
            ));
        }
        let a = options.added_mass_scale(i, j) * r.values[3];
        match slot {
            Slot::Zero => zero.get_or_insert([[0.0; 6]; 6])[i - 1][j - 1] = a,
            Slot::Infinite => infinite.get_or_insert([[0.0; 6]; 6])[i - 1][j - 1] = a,
            Slot::Finite(k) => {
                added_mass[k][i - 1][j - 1] = a;
                damping[k][i - 1][j - 1] = options.added_mass_scale(i, j) * omegas[k] * r.values[4];
            }
        }
    }
    Ok(AddedMassDamping {
        omegas,
        added_mass,
        damping,
        zero_frequency_added_mass: zero,
        infinite_frequency_added_mass: infinite,
    })
}
