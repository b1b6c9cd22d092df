//! A database from NEMOH v3's results: the readers of this folder's files put together
//! (the table in [`super`] says what is taken from each), in the native database's units,
//! with a line per file.

use super::cal::{FrequencyUnit, Generalised, NemohCal};
use super::{first_order, matrices, qtf};
use crate::error::{Error, Result};
use crate::hydro::io::database::{HydroDatabase, MassProperties, Provenance, FORMAT_VERSION};
use crate::hydro::io::import::{self, drift_points, Import};
use crate::hydro::reference_point::ReferencePoint;
use std::path::{Path, PathBuf};

/// Imports the NEMOH v3 results of the project directory `dir` (the one with `Nemoh.cal`;
/// its `results/` directory is accepted too), each file read within `memory_limit` bytes.
pub fn import(dir: &Path, memory_limit: f64) -> Result<Import> {
    let project = if dir.join("Nemoh.cal").is_file() {
        dir.to_path_buf()
    } else if dir.join("../Nemoh.cal").is_file() {
        dir.join("..")
    } else {
        return Err(Error::Io {
            path: dir.display().to_string(),
            message: "no Nemoh.cal here or in the parent directory (give NEMOH's project \
                      directory)"
                .into(),
        });
    };
    let cal = NemohCal::read(&project.join("Nemoh.cal"), memory_limit)?;
    let mut files = vec![format!(
        "{}: rho = {} kg/m^3, g = {} m/s^2, depth {}; {} DOFs, {} generalised forces",
        cal.path,
        cal.rho,
        cal.gravity,
        if cal.depth == 0.0 {
            "infinite".to_string()
        } else {
            format!("{} m", cal.depth)
        },
        cal.dofs.len(),
        cal.forces.len()
    )];
    let motion = cal.slow_indices(&cal.dofs, "degree of freedom")?;
    let force = cal.slow_indices(&cal.forces, "generalised force")?;
    let point = reference_point(&cal, &cal.dofs[motion[2] - 1], &cal.forces[force[2] - 1])?;
    let moved = if point.is_on_vertical_axis() {
        format!(
            "yaw moments about the vertical axis through ({}, {}, z): the body's z axis, kept",
            point.x, point.y
        )
    } else {
        format!(
            "yaw moments and yaw rows/columns moved from the axis through ({}, {}) m to the \
             origin: M_o = M_r + x_r F_y - y_r F_x, P^T A P",
            point.x, point.y
        )
    };
    files.push(moved);
    let restrict =
        |m: &[Vec<f64>]| -> [[f64; 3]; 3] { motion.map(|i| motion.map(|j| m[i - 1][j - 1])) };

    let mut low_frequency_added_mass = None;
    let mut provenance = Provenance::default();
    let path = project.join("results/CM.dat");
    if path.is_file() {
        let cm = matrices::read_frequency_matrices(&path, cal.dofs.len(), memory_limit)?;
        let (k, lowest) = lowest_frequency(&cm.frequencies, cal.first_order_unit);
        low_frequency_added_mass = Some(point.matrix_to_origin(&restrict(&cm.matrices[k])));
        provenance.low_frequency_added_mass = Some(format!(
            "NEMOH results/CM.dat at its lowest frequency, {lowest:.4} rad/s"
        ));
        let (count, min, max) = cal.first_order;
        files.push(format!(
            "{}: {} frequencies; low-frequency added mass from the lowest, {lowest:.4} rad/s \
             (NEMOH has no omega = 0){}",
            path.display(),
            cm.frequencies.len(),
            if count != cm.frequencies.len() {
                format!(
                    "; note: Nemoh.cal line {} lists {count} frequencies {min} .. {max}: the \
                     file's own are used",
                    cal.first_order_line
                )
            } else {
                String::new()
            }
        ));
    } else {
        files.push(format!("{}: absent", path.display()));
    }

    let mechanics = |name: &str| project.join("Mechanics").join(name);
    let six = |m: [[f64; 6]; 6]| -> Vec<Vec<f64>> { m.iter().map(|r| r.to_vec()).collect() };
    let mut mass_properties = None;
    let path = mechanics("Inertia.dat");
    if path.is_file() {
        let m = point.matrix_to_origin(&restrict(&six(matrices::read_matrix6(
            &path,
            memory_limit,
        )?)));
        let coupled = m[0][2] != 0.0 || m[1][2] != 0.0 || m[0][1] != 0.0;
        if coupled {
            files.push(format!(
                "{}: the centre of gravity is off the body's z axis (surge/sway-yaw coupling \
                 {:.4e}, {:.4e}): mass properties not set (the database holds mass and yaw \
                 inertia only); give them in the configuration",
                path.display(),
                m[0][2],
                m[1][2]
            ));
        } else {
            files.push(format!(
                "{}: mass {:.6e} kg, yaw inertia {:.6e} kg m^2",
                path.display(),
                m[0][0],
                m[2][2]
            ));
            mass_properties = Some(MassProperties {
                mass: m[0][0],
                yaw_inertia: m[2][2],
            });
            provenance.mass_properties = Some("NEMOH Mechanics/Inertia.dat".to_string());
        }
    } else {
        files.push(format!("{}: absent", path.display()));
    }
    let mut stiffness = None;
    let path = mechanics("Kh.dat");
    if path.is_file() {
        let c = point.matrix_to_origin(&restrict(&six(matrices::read_matrix6(
            &path,
            memory_limit,
        )?)));
        files.push(format!(
            "{}: hydrostatic stiffness (surge, sway, yaw diagonal {:.4e}, {:.4e}, {:.4e}; the \
             mooring must add its own)",
            path.display(),
            c[0][0],
            c[1][1],
            c[2][2]
        ));
        stiffness = Some(c);
        provenance.stiffness = Some("NEMOH Mechanics/Kh.dat".to_string());
    } else {
        files.push(format!("{}: absent", path.display()));
    }

    let (first_order, rao) = first_order::import(&project, &cal, memory_limit, &mut files)?;

    let mut drift = Vec::new();
    let mut qtf_data = None;
    let mut bidirectional_drift = None;
    match &cal.qtf {
        None => files.push(format!(
            "{}: no QTF asked for (QTF flag not 1): no drift, no QTF",
            cal.path
        )),
        Some(settings) => {
            let path = qtf_file(&project.join("results/QTF"))?;
            let mut qtf = qtf::read_difference_qtf(&path, &cal, settings, memory_limit)?;
            if !point.is_on_vertical_axis() {
                qtf.move_yaw_moment(force, point)?;
            }
            let headings = qtf.headings();
            drift = drift_points(&qtf.to_drift_table(&headings, force)?);
            bidirectional_drift = qtf.to_bidirectional_table(force)?;
            qtf_data = Some(import::qtf_data(&qtf, force)?);
            files.push(format!(
                "{}: QTF, {} frequencies {:.4} .. {:.4} rad/s (Nemoh.cal's grid; printed in {}), \
                 headings {} deg{}, forces {} = surge, sway, yaw; values x rho g, conjugated \
                 from NEMOH's e^(-i w t) to e^(i w t); {} values filled by Hermitian symmetry{}; \
                 mean drift = the diagonal",
                path.display(),
                qtf.omegas().len(),
                qtf.omegas()[0],
                qtf.omegas()[qtf.omegas().len() - 1],
                settings.output_unit.name(),
                headings
                    .iter()
                    .map(|h| format!("{:.2}", h.to_degrees()))
                    .collect::<Vec<_>>()
                    .join(", "),
                if bidirectional_drift.is_some() {
                    "; bi-directional: every heading pair, its diagonal as bidirectional_drift"
                } else {
                    ""
                },
                force.map(|k| k.to_string()).join(", "),
                qtf.filled_by_symmetry(),
                match qtf.filled_by_interpolation() {
                    0 => String::new(),
                    k => format!(
                        "; warning: a sparse QTF, {k} values filled along difference-frequency \
                         lines"
                    ),
                }
            ));
        }
    }
    let name = project
        .canonicalize()
        .ok()
        .and_then(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .unwrap_or_else(|| "nemoh".to_string());
    let database = HydroDatabase {
        format_version: FORMAT_VERSION,
        name,
        source: format!(
            "NEMOH v3 results {} (Nemoh.cal, CM.dat, the .tec first-order results, Mechanics/, \
             the difference-frequency QTF); \
             rho = {} kg/m^3, g = {} m/s^2 from Nemoh.cal; depth {}; QTF conjugated from \
             e^(-i w t); moments about the body origin; drift from the QTF diagonal",
            project.display(),
            cal.rho,
            cal.gravity,
            if cal.depth == 0.0 {
                "infinite".to_string()
            } else {
                format!("{} m", cal.depth)
            }
        ),
        water_density: cal.rho,
        gravity: cal.gravity,
        mass_properties,
        low_frequency_added_mass,
        stiffness,
        drift,
        qtf: qtf_data,
        bidirectional_drift,
        first_order,
        rao,
        provenance,
    };
    database.validate()?;
    Ok(Import { database, files })
}

/// The horizontal point of the yaw moment's axis; the yaw motion's axis must be the same
/// vertical line (else the file mixes reference points, refused).
fn reference_point(
    cal: &NemohCal,
    motion: &Generalised,
    moment: &Generalised,
) -> Result<ReferencePoint> {
    if motion.point[..2] != moment.point[..2] {
        return Err(Error::Parse {
            path: cal.path.clone(),
            line: Some(moment.line),
            message: format!(
                "the yaw moment is about the axis through ({}, {}) but the yaw motion (line {}) \
                 about ({}, {}): one reference point is needed for both",
                moment.point[0], moment.point[1], motion.line, motion.point[0], motion.point[1]
            ),
        });
    }
    Ok(ReferencePoint {
        x: moment.point[0],
        y: moment.point[1],
    })
}

/// The index and frequency (rad/s) of the lowest frequency of `frequencies` (in `unit`).
fn lowest_frequency(frequencies: &[f64], unit: FrequencyUnit) -> (usize, f64) {
    let omega = |f: f64| match unit {
        FrequencyUnit::RadPerSecond => f,
        FrequencyUnit::Hertz => 2.0 * std::f64::consts::PI * f,
        FrequencyUnit::Second => 2.0 * std::f64::consts::PI / f,
    };
    frequencies
        .iter()
        .enumerate()
        .map(|(k, &f)| (k, omega(f)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .expect("at least one frequency")
}

/// `OUT_QTFM_N.dat` in `dir`, else the one `OUT_QTFM_N*.dat` there.
fn qtf_file(dir: &Path) -> Result<PathBuf> {
    let standard = dir.join("OUT_QTFM_N.dat");
    if standard.is_file() {
        return Ok(standard);
    }
    let mut found: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|e| Error::Io {
            path: dir.display().to_string(),
            message: format!("{e} (Nemoh.cal asks for a QTF: its results are expected here)"),
        })?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with("OUT_QTFM_N") && n.ends_with(".dat"))
        })
        .collect();
    found.sort();
    match found.len() {
        1 => Ok(found.remove(0)),
        0 => Err(Error::Io {
            path: dir.display().to_string(),
            message: "no OUT_QTFM_N.dat (the difference-frequency QTF)".into(),
        }),
        _ => Err(Error::Io {
            path: dir.display().to_string(),
            message: format!(
                "several difference-frequency QTF files, {}: keep one",
                found
                    .iter()
                    .map(|p| p.display().to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        }),
    }
}
