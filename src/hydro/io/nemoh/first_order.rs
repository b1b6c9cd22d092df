//! The database's `first_order` and `rao` from NEMOH v3: `results/RadiationCoefficients.tec`
//! and `results/ExcitationForce.tec` ([`super::tec`]) with `Mechanics/` (`Inertia.dat`,
//! `Kh.dat`, `Km.dat`, `Badd.dat`), turned into the crate's conventions
//! ([`crate::hydro::rao`]):
//!
//! - DOFs: Nemoh.cal's six (translations along x, y, z; rotations about x, y, z) in the
//!   database's order, whatever their order in Nemoh.cal; A[i][j] is the force i due to the
//!   motion j (NEMOH writes a zone per motion: [`super::tec`]).
//! - Time: NEMOH's e^{-i w t} (its incident potential -i g / w e^{k z} e^{i k (x cos b + y
//!   sin b)}, elevation e^{i k x}, real at the origin); the crate's e^{+i w t}: the excitation
//!   is conjugated, A and B are real and unchanged (NEMOH's own RAO solves
//!   -w^2 (M + A) - i w (B + Badd) + Kh + Km, the conjugate of the crate's equation).
//! - Units: dimensional as NEMOH writes them (N/m, N m/m; kg ...); frequencies in the unit
//!   the .tec header names, to rad/s; headings (propagation direction from +x, as WAMIT's
//!   beta) in degrees, to rad.
//! - Reference point: NEMOH's rotations and moments are about the point Nemoh.cal names (the
//!   OC3 spar's (0, 0, -78) m), the same for the three rotations and three moments; A, B,
//!   the mass, Kh, Km and Badd are moved to the body origin by P^T A P and the excitation by
//!   M_o = M_r + r x F ([`crate::hydro::reference_point::matrix6_to_origin`]), so the
//!   database's coefficients and RAOs are about the origin as WAMIT's are.
//! - Mechanics: `Inertia.dat` is M about the point; `Kh.dat` is the restoring of buoyancy
//!   and weight together (NEMOH's hydrosCal: rho g V (z_B - z_G) in roll and pitch, the
//!   centre of gravity taken at the rotations' point), moved to the origin as a whole; the
//!   database's `hydrostatics` are the buoyancy's alone, as for WAMIT (the weight's restoring
//!   of Inertia.dat's mass at that point taken out), and the RAOs solved here add it back
//!   with C_ext; `Km.dat` is NEMOH's
//!   additional (mooring) stiffness, C_ext; `Badd.dat` its additional damping, B_ext. Absent
//!   Km or Badd are zero (NEMOH writes zeros when they are absent).

use super::cal::NemohCal;
use super::{matrices, tec};
use crate::error::Result;
use crate::hydro::rao::{self, BodyMatrices, FirstOrder, RaoTable};
use crate::hydro::reference_point::{force6_to_origin, matrix6_to_origin};
use crate::hydro::rigid_body::RigidBody;
use rustfft::num_complex::Complex64;
use std::path::Path;

/// `first_order` and `rao` when the files allow, with a line per file in `files` (what was
/// taken, or why not).
pub(crate) fn import(
    project: &Path,
    cal: &NemohCal,
    memory_limit: f64,
    files: &mut Vec<String>,
) -> Result<(Option<FirstOrder>, Option<RaoTable>)> {
    let radiation_path = project.join("results/RadiationCoefficients.tec");
    let excitation_path = project.join("results/ExcitationForce.tec");
    let (rd, ed) = (radiation_path.display(), excitation_path.display());
    if !radiation_path.is_file() || !excitation_path.is_file() {
        for path in [&radiation_path, &excitation_path] {
            if !path.is_file() {
                files.push(format!(
                    "{}: absent: no first_order, no rao",
                    path.display()
                ));
            }
        }
        return Ok((None, None));
    }
    let not_set = |files: &mut Vec<String>, why: String| {
        files.push(format!("{rd}: first_order and rao not set: {why}"));
        Ok((None, None))
    };
    if cal.dofs.len() != 6 || cal.forces.len() != 6 {
        return not_set(
            files,
            format!(
                "the body has {} DOFs and {} generalised forces in Nemoh.cal; the six rigid-body \
                 ones are needed",
                cal.dofs.len(),
                cal.forces.len()
            ),
        );
    }
    let (motion, point) = match NemohCal::six_indices(&cal.dofs) {
        Ok(found) => found,
        Err(why) => return not_set(files, format!("Nemoh.cal's DOFs: {why}")),
    };
    let (force, force_point) = match NemohCal::six_indices(&cal.forces) {
        Ok(found) => found,
        Err(why) => return not_set(files, format!("Nemoh.cal's generalised forces: {why}")),
    };
    if force_point != point {
        return not_set(
            files,
            format!(
                "the rotations are about ({}, {}, {}) but the moments about ({}, {}, {}) \
                 (Nemoh.cal lines {} and {})",
                point[0],
                point[1],
                point[2],
                force_point[0],
                force_point[1],
                force_point[2],
                cal.dofs[motion[3]].line,
                cal.forces[force[3]].line
            ),
        );
    }
    let mechanics = |name: &str| project.join("Mechanics").join(name);
    let kh_path = mechanics("Kh.dat");
    let inertia_path = mechanics("Inertia.dat");
    for (path, what) in [
        (&kh_path, "the hydrostatics"),
        (&inertia_path, "the mass, whose weight Kh.dat holds"),
    ] {
        if !path.is_file() {
            return not_set(files, format!("{} is absent ({what})", path.display()));
        }
    }
    let radiation = tec::read_radiation(&radiation_path, 6, 6, memory_limit)?;
    let excitation = tec::read_excitation(&excitation_path, 6, memory_limit)?;
    // Mechanics' matrices are Nemoh.cal's DOFs by DOFs, about the point.
    let about_point = |m: [[f64; 6]; 6]| -> [[f64; 6]; 6] {
        let ordered = motion.map(|i| motion.map(|j| m[i][j]));
        matrix6_to_origin(point, &ordered)
    };
    // Kh.dat is the restoring of buoyancy and weight together (NEMOH's hydrosCal, the
    // centre of gravity at the rotations' point, where the weight's own restoring is zero);
    // their sum has no net static force, so P^T K P moves it to the origin exactly. The
    // database's hydrostatics are the buoyancy's alone (the WAMIT .hst convention of
    // `crate::problem::motions`): the weight's restoring about the origin, with the mass of
    // Inertia.dat at the rotations' point, is taken out.
    let combined = about_point(matrices::read_matrix6(&kh_path, memory_limit)?);
    let mass = about_point(matrices::read_matrix6(&inertia_path, memory_limit)?);
    let weight = RigidBody {
        mass: mass[0][0],
        centre_of_gravity: point,
        inertia: [[0.0; 3]; 3],
    }
    .weight_stiffness(cal.gravity);
    let hydrostatics: [[f64; 6]; 6] =
        std::array::from_fn(|i| std::array::from_fn(|j| combined[i][j] - weight[i][j]));
    let optional = |name: &str, files: &mut Vec<String>, what: &str| -> Result<[[f64; 6]; 6]> {
        let path = mechanics(name);
        if path.is_file() {
            files.push(format!("{}: {what}, moved to the origin", path.display()));
            Ok(about_point(matrices::read_matrix6(&path, memory_limit)?))
        } else {
            files.push(format!(
                "{}: absent: {what} zero (NEMOH writes zeros when absent)",
                path.display()
            ));
            Ok([[0.0; 6]; 6])
        }
    };
    let mooring = optional("Km.dat", files, "the additional (mooring) stiffness C_ext")?;
    let viscous = optional("Badd.dat", files, "the additional damping B_ext")?;

    // The grids in increasing order (a file in periods lists them decreasing).
    let mut by_omega: Vec<usize> = (0..radiation.omegas.len()).collect();
    by_omega.sort_by(|&a, &b| radiation.omegas[a].total_cmp(&radiation.omegas[b]));
    let mut by_heading: Vec<usize> = (0..excitation.headings.len()).collect();
    by_heading.sort_by(|&a, &b| excitation.headings[a].total_cmp(&excitation.headings[b]));
    let omegas: Vec<f64> = by_omega.iter().map(|&k| radiation.omegas[k]).collect();
    let mut added_mass = Vec::with_capacity(omegas.len());
    let mut damping = Vec::with_capacity(omegas.len());
    for &k in &by_omega {
        let part = |which: fn((f64, f64)) -> f64| -> [[f64; 6]; 6] {
            let m = std::array::from_fn(|i| {
                std::array::from_fn(|j| which(radiation.coefficients(k, force[i], motion[j])))
            });
            matrix6_to_origin(point, &m)
        };
        added_mass.push(part(|(a, _)| a));
        damping.push(part(|(_, b)| b));
    }
    let mut excitation_omegas = excitation.omegas.clone();
    excitation_omegas.sort_by(f64::total_cmp);
    let headings: Vec<f64> = by_heading.iter().map(|&h| excitation.headings[h]).collect();
    let excitation_values: Vec<Vec<[Complex64; 6]>> = excitation_omegas
        .iter()
        .map(|&w| {
            let k = excitation
                .omegas
                .iter()
                .position(|&v| v == w)
                .expect("a frequency of the file");
            by_heading
                .iter()
                .map(|&h| {
                    let nemoh: [Complex64; 6] =
                        std::array::from_fn(|i| excitation.force(k, h, force[i]).conj());
                    force6_to_origin(point, nemoh)
                })
                .collect()
        })
        .collect();
    let first_order = FirstOrder::from_parts(
        &omegas,
        &added_mass,
        &damping,
        &excitation_omegas,
        &headings,
        &excitation_values,
        hydrostatics,
    )?;
    let moved = format!(
        "about ({}, {}, {}) m (Nemoh.cal line {}), moved to the origin",
        point[0], point[1], point[2], cal.dofs[motion[3]].line
    );
    files.push(format!(
        "{rd}: added mass and damping, {} frequencies {:.4} .. {:.4} rad/s, A[i][j] the force \
         i of zone (motion) j; {moved} (P^T A P)",
        omegas.len(),
        omegas[0],
        omegas[omegas.len() - 1]
    ));
    files.push(format!(
        "{ed}: excitation, headings {} deg; conjugated from NEMOH's e^(-i w t) to e^(i w t); \
         moments {moved} (M_o = M_r + r x F)",
        headings
            .iter()
            .map(|h| format!("{:.2}", h.to_degrees()))
            .collect::<Vec<_>>()
            .join(", ")
    ));
    files.push(format!(
        "{}: buoyancy and weight (the centre of gravity at the rotations' point), moved to \
         the origin; first_order's hydrostatics the buoyancy's alone (the weight's restoring \
         of Inertia.dat's mass {} kg taken out)",
        kh_path.display(),
        mass[0][0]
    ));
    let body = BodyMatrices {
        mass,
        stiffness: std::array::from_fn(|i| std::array::from_fn(|j| mooring[i][j] + weight[i][j])),
        damping: viscous,
    };
    match rao::solve(&first_order, &body) {
        Ok(solved) => {
            files.push(format!(
                "{}: the mass matrix, moved to the origin; rao solved from first_order with \
                 it, C_ext = Km + the weight's restoring, B_ext = Badd",
                inertia_path.display()
            ));
            Ok((Some(first_order), Some(RaoTable::from(&solved))))
        }
        Err(e) => {
            files.push(format!("{}: rao not set: {e}", inertia_path.display()));
            Ok((Some(first_order), None))
        }
    }
}
