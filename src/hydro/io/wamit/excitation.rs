//! The `.2` (Haskind) and `.3` (diffraction) files, first-order wave excitation, and the `.4`
//! file, first-order body motions (RAOs): one layout, `PER BETA I |X| phase Re Im`.

use super::{grid_index, same_frequency, same_heading, unique_sorted, NumericFile, WamitOptions};
use crate::error::{Error, Result};
use rustfft::num_complex::Complex64;
use std::path::Path;

/// A complex amplitude per frequency, heading and DOF, per unit incident-wave amplitude,
/// SI: the excitation X (N/m, N m/m) of a `.2` or `.3` file or the motion xi (m/m, rad/m) of
/// a `.4` file, for WAMIT's (and the crate's) time convention Re{X e^{i omega t}}, the phase
/// relative to the incident-wave elevation at the body origin (WAMIT manual v7.4, eq. 3.1:
/// a positive phase leads the wave).
#[derive(Debug, Clone, PartialEq)]
pub struct LinearResponse {
    /// Frequencies, rad/s, increasing.
    pub omegas: Vec<f64>,
    /// Headings (direction of propagation from the body x axis, counter-clockwise), rad,
    /// increasing.
    pub headings: Vec<f64>,
    /// The DOFs (1 ..= 6: surge, sway, heave, roll, pitch, yaw) the file lists; the others
    /// are zero in `values`.
    pub dofs: Vec<usize>,
    /// `values[omega][heading][dof - 1]`.
    pub values: Vec<Vec<[Complex64; 6]>>,
}

/// Reads a `.2` or `.3` file: lines `PER BETA I |Xbar| phase Re Im`; X = rho g L^m Xbar per
/// unit wave amplitude, m = 2 for forces (DOFs 1 to 3), 3 for moments (DOFs 4 to 6) (WAMIT
/// manual v7.4 §3.3 and §4.3).
pub fn read_excitation(path: &Path, options: &WamitOptions) -> Result<LinearResponse> {
    options.validate()?;
    read(path, options, |dof| options.excitation_scale(dof))
}

/// Reads a `.4` file: lines `PER BETA I |xibar| phase Re Im`; xi = L^n xibar per unit wave
/// amplitude, n = 0 for translations (m/m), -1 for rotations (rad/m) (WAMIT manual v7.4
/// §3.4 and §4.4). The motions are about the body origin, as WAMIT solved them with the mass
/// and stiffness of its run's force control file.
pub fn read_motions(path: &Path, options: &WamitOptions) -> Result<LinearResponse> {
    options.validate()?;
    read(path, options, |dof| options.motion_scale(dof))
}

/// The common reader: every (frequency, heading) of the file must list every DOF the file
/// lists somewhere, once.
fn read(
    path: &Path,
    options: &WamitOptions,
    scale: impl Fn(usize) -> f64,
) -> Result<LinearResponse> {
    let file = NumericFile::read(
        path,
        &[7],
        "PER BETA I |X| phase Re Im",
        options.memory_limit,
    )?;
    struct Entry {
        line: usize,
        omega: f64,
        heading: f64,
        dof: usize,
        value: Complex64,
    }
    let mut entries = Vec::with_capacity(file.records.len());
    for r in &file.records {
        let omega = file.frequency(r, 0, "PER")?;
        let dof = file.dof(r, 2, "I")?;
        file.check_polar(r, 3)?;
        entries.push(Entry {
            line: r.line,
            omega,
            heading: r.values[1].to_radians(),
            dof,
            value: Complex64::new(r.values[5], r.values[6]) * scale(dof),
        });
    }
    let omegas = unique_sorted(entries.iter().map(|e| e.omega).collect(), same_frequency);
    let headings = unique_sorted(entries.iter().map(|e| e.heading).collect(), same_heading);
    let mut dofs: Vec<usize> = entries.iter().map(|e| e.dof).collect();
    dofs.sort_unstable();
    dofs.dedup();
    let (nw, nh) = (omegas.len(), headings.len());
    let mut values = vec![vec![[Complex64::default(); 6]; nh]; nw];
    let mut lines = vec![[None::<usize>; 6]; nw * nh];
    for e in &entries {
        let iw = grid_index(&omegas, e.omega, same_frequency).expect("frequency collected");
        let ih = grid_index(&headings, e.heading, same_heading).expect("heading collected");
        if let Some(first) = lines[iw * nh + ih][e.dof - 1].replace(e.line) {
            return Err(file.error(
                e.line,
                format!(
                    "DOF {} at heading {:.3} deg and omega {:.6} rad/s given twice (first at \
                     line {first})",
                    e.dof,
                    e.heading.to_degrees(),
                    e.omega
                ),
            ));
        }
        values[iw][ih][e.dof - 1] = e.value;
    }
    let mut holes = Vec::new();
    for (iw, &omega) in omegas.iter().enumerate() {
        for (ih, &heading) in headings.iter().enumerate() {
            for &dof in &dofs {
                if lines[iw * nh + ih][dof - 1].is_none() {
                    holes.push(format!(
                        "DOF {dof} at {:.3} deg, {omega:.6} rad/s",
                        heading.to_degrees()
                    ));
                }
            }
        }
    }
    if !holes.is_empty() {
        let shown = holes.len().min(5);
        return Err(Error::Parse {
            path: file.path,
            line: None,
            message: format!(
                "{} of the {} (frequency, heading, DOF) entries of the file's grid ({nw} \
                 frequencies, {nh} headings, DOFs {}) are missing: {}{}",
                holes.len(),
                nw * nh * dofs.len(),
                super::join(dofs.iter()),
                holes[..shown].join("; "),
                if holes.len() > shown { "; ..." } else { "" }
            ),
        });
    }
    Ok(LinearResponse {
        omegas,
        headings,
        dofs,
        values,
    })
}
