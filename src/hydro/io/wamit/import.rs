//! A database from WAMIT's output files: the readers of this folder's files put together,
//! restricted to surge, sway and yaw (WAMIT DOFs 1, 2, 6), in the native database's units
//! (SI, rad/s, rad), with a line per file looked for.

use super::{
    read_added_mass_damping, read_difference_qtf, read_hydrostatics, read_mean_drift, WamitOptions,
};
use crate::error::{Error, Result};
use crate::hydro::io::database::{HydroDatabase, Provenance, FORMAT_VERSION};
use crate::hydro::io::import::{drift_points, qtf_data, Import};
use std::ffi::OsString;
use std::path::{Path, PathBuf};

/// WAMIT DOFs of surge, sway and yaw.
const SLOW_DOFS: [usize; 3] = [1, 2, 6];

/// Imports the WAMIT files `<root>.1`, `.hst`, `.8`, `.9` and `.12d` (else `.11d`, else
/// `.10d`) that exist, restricted to surge, sway and yaw (WAMIT DOFs 1, 2, 6):
/// - `.1`: the PER = -1 (omega = 0) added mass;
/// - `.hst`: the hydrostatic stiffness (zero in these DOFs for a floater);
/// - drift from `.8` (momentum), else `.9` (pressure), else the QTF diagonal; the
///   bi-directional drift from the same file's beta1 != beta2 entries, on every pair of
///   its headings (the error lists the pairs missing in both orders);
/// - the QTF: every uni-directional heading and, when the file has them, every
///   bi-directional heading pair (the reader requires all pairs of its headings).
///
/// At least one file must exist.
pub fn import(root: &Path, options: &WamitOptions) -> Result<Import> {
    options.validate()?;
    let file = |ext: &str| -> PathBuf {
        let mut s = OsString::from(root.as_os_str());
        s.push(".");
        s.push(ext);
        PathBuf::from(s)
    };
    let mut files = Vec::new();
    let mut used = Vec::new();

    let mut low_frequency_added_mass = None;
    let path = file("1");
    if path.exists() {
        let amd = read_added_mass_damping(&path, options)?;
        low_frequency_added_mass = amd.zero_frequency_added_mass.map(|a| restrict(&a));
        files.push(format!(
            "{}: {} frequencies{}",
            path.display(),
            amd.omegas.len(),
            if low_frequency_added_mass.is_some() {
                "; low-frequency added mass from PER = -1 (omega = 0)"
            } else {
                "; no PER = -1 rows: low-frequency added mass not set"
            }
        ));
        used.push(".1");
    } else {
        files.push(format!("{}: absent", path.display()));
    }

    let mut stiffness = None;
    let path = file("hst");
    if path.exists() {
        let c = restrict(&read_hydrostatics(&path, options)?.c);
        files.push(format!(
            "{}: hydrostatic stiffness (surge, sway, yaw diagonal {:.4e}, {:.4e}, {:.4e}; \
             the mooring must add its own)",
            path.display(),
            c[0][0],
            c[1][1],
            c[2][2]
        ));
        stiffness = Some(c);
        used.push(".hst");
    } else {
        files.push(format!("{}: absent", path.display()));
    }

    let mut qtf = None;
    for ext in ["12d", "11d", "10d"] {
        let path = file(ext);
        if !path.exists() {
            files.push(format!("{}: absent", path.display()));
            continue;
        }
        let read = read_difference_qtf(&path, options)?;
        let headings = read.headings();
        let bidirectional = read
            .blocks()
            .iter()
            .filter(|b| b.headings.0 != b.headings.1)
            .count();
        files.push(format!(
            "{}: QTF, {} frequencies {:.4} .. {:.4} rad/s, headings {} deg, DOFs {} \
             (kept 1, 2, 6), {} values filled by Hermitian symmetry{}{}",
            path.display(),
            read.omegas().len(),
            read.omegas()[0],
            read.omegas()[read.omegas().len() - 1],
            degrees(&headings),
            read.dofs()
                .iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", "),
            read.filled_by_symmetry(),
            match read.filled_by_interpolation() {
                0 => String::new(),
                k => format!(
                    "; warning: a sparse QTF, {k} values missing from the file filled by \
                     linear interpolation along their difference-frequency lines"
                ),
            },
            if bidirectional > 0 {
                format!(
                    "; {bidirectional} bi-directional blocks on every pair of the headings \
                     (those of DOFs 1, 2, 6 kept)"
                )
            } else {
                String::new()
            }
        ));
        used.push(match ext {
            "12d" => ".12d",
            "11d" => ".11d",
            _ => ".10d",
        });
        qtf = Some(read);
        break;
    }

    let mut drift_from = "none";
    let mut drift = Vec::new();
    let mut bidirectional_drift = None;
    for (ext, label) in [("8", ".8"), ("9", ".9")] {
        let path = file(ext);
        if !path.exists() {
            files.push(format!("{}: absent", path.display()));
            continue;
        }
        let mean = read_mean_drift(&path, options)?;
        let headings = mean.headings();
        drift = drift_points(&mean.to_drift_table(&headings, SLOW_DOFS)?);
        bidirectional_drift = mean.to_bidirectional_table(SLOW_DOFS)?;
        files.push(format!(
            "{}: mean drift, {} frequencies, headings {} deg{}",
            path.display(),
            mean.omegas().len(),
            degrees(&headings),
            match &bidirectional_drift {
                Some(t) => format!(
                    "; bi-directional drift on every pair of the headings {} deg ({} blocks \
                     given, the other order by Hermitian symmetry)",
                    degrees(&t.headings),
                    mean.pairs().len()
                ),
                None => "; no bi-directional entries (beta1 != beta2)".to_string(),
            }
        ));
        drift_from = label;
        used.push(label);
        break;
    }
    if drift.is_empty() {
        if let Some(q) = &qtf {
            drift = drift_points(&q.to_drift_table(&q.headings(), SLOW_DOFS)?);
            drift_from = "the QTF diagonal";
        }
    }
    if used.is_empty() {
        return Err(Error::Io {
            path: root.display().to_string(),
            message: "no WAMIT file found (.1, .hst, .8, .9, .12d, .11d, .10d)".into(),
        });
    }
    let mut bidirectional_from = if bidirectional_drift.is_some() {
        drift_from
    } else {
        "none"
    };
    if bidirectional_drift.is_none() {
        if let Some(q) = &qtf {
            bidirectional_drift = q.to_bidirectional_table(SLOW_DOFS)?;
            if bidirectional_drift.is_some() {
                bidirectional_from = "the QTF's heading pairs' diagonals";
            }
        }
    }
    let qtf = qtf.as_ref().map(|q| qtf_data(q, SLOW_DOFS)).transpose()?;
    let source = format!(
        "WAMIT output {} ({}); ULEN = {} m, rho = {} kg/m^3, g = {} m/s^2; drift from {}; \
         bi-directional drift from {}",
        root.display(),
        used.join(", "),
        options.ulen,
        options.rho,
        options.gravity,
        drift_from,
        bidirectional_from
    );
    let name = root.file_name().map_or_else(
        || root.display().to_string(),
        |n| n.to_string_lossy().into(),
    );
    let database = HydroDatabase {
        format_version: FORMAT_VERSION,
        name,
        source,
        water_density: options.rho,
        gravity: options.gravity,
        mass_properties: None,
        low_frequency_added_mass,
        stiffness,
        drift,
        qtf,
        bidirectional_drift,
        provenance: Provenance {
            mass_properties: None,
            low_frequency_added_mass: low_frequency_added_mass
                .is_some()
                .then(|| "WAMIT .1 at omega = 0 (PER = -1)".to_string()),
            stiffness: stiffness.is_some().then(|| "WAMIT .hst".to_string()),
        },
    };
    database.validate()?;
    Ok(Import { database, files })
}

/// The (surge, sway, yaw) = WAMIT (1, 2, 6) rows and columns of a 6x6 matrix.
fn restrict(m: &[[f64; 6]; 6]) -> [[f64; 3]; 3] {
    SLOW_DOFS.map(|i| SLOW_DOFS.map(|j| m[i - 1][j - 1]))
}

fn degrees(headings: &[f64]) -> String {
    headings
        .iter()
        .map(|h| format!("{:.2}", h.to_degrees()))
        .collect::<Vec<_>>()
        .join(", ")
}
