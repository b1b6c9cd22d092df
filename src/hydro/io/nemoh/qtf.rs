//! NEMOH v3's difference-frequency QTF, `results/QTF/OUT_QTFM_N.dat`.
//!
//! Lines `w1 w2 beta1 beta2 DOF |Q|/(rho g) phase(deg) Re(Q)/(rho g) Im(Q)/(rho g)` after
//! one header line; w1 >= w2 (the lower triangle); DOF is the index of the generalised
//! force in Nemoh.cal; frequencies in Nemoh.cal's QTF output unit, printed with three
//! decimals; headings in degrees (NEMOH's beta is the crate's: the direction of propagation
//! from x, counter-clockwise).
//!
//! Convention. NEMOH's time factor is e^{-i omega t} (its potentials are
//! Re{Phi e^{-i omega t}}), and its difference-frequency product takes the value at w1 times
//! the conjugate at w2, so its QTF Q pairs with F(t) = Re sum A_i A_j* Q_ij e^{-i (w_i - w_j) t}
//! (w_i = w1). With the crate's a = conj A (e^{i omega t}), F = Re sum a_i a_j* conj(Q_ij)
//! e^{i (w_i - w_j) t}: the crate's T is rho g conj(Q), with PER1 -> w1 as in WAMIT's
//! files. The importer says so in its report.
//!
//! Frequencies: each printed value must round to one node of Nemoh.cal's QTF grid
//! (count, min, max in rad/s, converted to the output unit) to its printed decimals, and is
//! replaced by that node: the grid's exact values, not the three-decimal text. A value that
//! matches no node (a unit other than the one Nemoh.cal names, or results of another
//! Nemoh.cal) is refused naming the line.

use super::cal::{NemohCal, QtfSettings};
use crate::error::{Error, Result};
use crate::hydro::io::wamit::{assemble_qtf, DifferenceQtf, NumericFile, QtfEntry, READING};
use rustfft::num_complex::Complex64;
use std::path::Path;

/// Reads the QTF of `path` with the settings of `cal` within `memory_limit` bytes: T = rho g
/// conj(Re + i Im) in the crate's convention, completed by Hermitian symmetry (and, for a
/// sparse file, along difference-frequency lines) as WAMIT's files are.
pub fn read_difference_qtf(
    path: &Path,
    cal: &NemohCal,
    settings: &QtfSettings,
    memory_limit: f64,
) -> Result<DifferenceQtf> {
    let file = NumericFile::read(
        path,
        &[9],
        "w1 w2 beta1 beta2 DOF |QTF|/(rho g) phase Re/(rho g) Im/(rho g)",
        memory_limit,
    )?;
    // The text again, for the decimals each frequency is printed with (within the numeric
    // file's cost, which covers its records, this text and its lines: measured).
    let text = crate::files::read_text(path, &READING, memory_limit)?;
    let lines: Vec<&str> = text.lines().collect();
    let nodes = settings.omegas();
    let unit = settings.output_unit;
    let in_unit: Vec<f64> = nodes.iter().map(|&w| unit.of_omega(w)).collect();
    let scale = cal.rho * cal.gravity;
    let mut entries = Vec::with_capacity(file.records.len());
    for r in &file.records {
        let tokens: Vec<&str> = lines[r.line - 1].split_whitespace().collect();
        let node = |k: usize, field: &str| -> Result<f64> {
            let value = r.values[k];
            let decimals = tokens[k].split_once('.').map_or(0, |(_, d)| {
                d.chars().take_while(char::is_ascii_digit).count()
            });
            let half = 0.5 * 10f64.powi(-(decimals as i32)) * (1.0 + 1e-9) + 1e-12;
            let matching: Vec<usize> = (0..nodes.len())
                .filter(|&n| (in_unit[n] - value).abs() <= half)
                .collect();
            match matching.as_slice() {
                [n] => Ok(nodes[*n]),
                [] => Err(file_error(
                    &file,
                    r.line,
                    format!(
                        "{field} = {} {}: none of Nemoh.cal's QTF frequencies ({} from {} to \
                         {} rad/s, {}:{}) in the QTF output unit ({}:{}) rounds to it",
                        tokens[k],
                        unit.name(),
                        settings.count,
                        settings.min,
                        settings.max,
                        cal.path,
                        settings.grid_line,
                        cal.path,
                        settings.unit_line
                    ),
                )),
                _ => Err(file_error(
                    &file,
                    r.line,
                    format!(
                        "{field} = {}: {} of Nemoh.cal's QTF frequencies round to it; the \
                         printed decimals cannot tell them apart",
                        tokens[k],
                        matching.len()
                    ),
                )),
            }
        };
        let omegas = (node(0, "w1")?, node(1, "w2")?);
        let dof = r.values[4];
        if dof.fract() != 0.0 || !(1.0..=cal.forces.len() as f64).contains(&dof) {
            return Err(file_error(
                &file,
                r.line,
                format!(
                    "DOF = {dof}: must be the index of a generalised force of Nemoh.cal (1 to {})",
                    cal.forces.len()
                ),
            ));
        }
        file.check_polar(r, 5)?;
        entries.push(QtfEntry {
            line: r.line,
            dof: dof as usize,
            omegas,
            headings: (r.values[2].to_radians(), r.values[3].to_radians()),
            value: Complex64::new(r.values[7], r.values[8]).conj() * scale,
        });
    }
    assemble_qtf(file.path.clone(), entries, memory_limit)
}

fn file_error(file: &NumericFile, line: usize, message: String) -> Error {
    Error::Parse {
        path: file.path.clone(),
        line: Some(line),
        message,
    }
}
