//! The coupled system, ready for a co-simulation master: `target/fmu/system/` holds
//! SlowDrift.fmu and Mooring.fmu, each with its OSP model description beside it
//! (`<modelName>_OspModelDescription.xml`, where libcosim looks for it), the OSP system
//! structure (`OspSystemStructure.xml`, libcosim and ecos) and the SSP package of the same
//! system (`MooredPlatform.ssp`: `SystemStructure.ssd` with the two FMUs under `resources/`).
//!
//! The XML sources are the repository's (`modelDescription/SlowDrift_OspModelDescription.xml`,
//! `mooring/Mooring_OspModelDescription.xml`, `fmu-pack/system/`); the FMUs are the ones just
//! packed and checked. Nothing here interprets them: `tests/clients/test_system_files.py`
//! validates them against their schemas and the FMUs' model descriptions, and
//! `tests/clients/test_system_masters.py` runs the folder in libcosim, ecos and fmpy.

use crate::{archive, read, write_fmu};
use std::path::Path;

/// The folder under the FMU folder that holds the system.
const SYSTEM_DIR: &str = "system";
/// The SSP package's file name.
const SSP_FILE: &str = "MooredPlatform.ssp";

/// Writes `fmu_dir/system/` from the packed FMUs in `fmu_dir` and the sources under `root`.
pub fn write(root: &Path, fmu_dir: &Path) -> Result<(), String> {
    let dir = fmu_dir.join(SYSTEM_DIR);
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let fmus = ["SlowDrift.fmu", "Mooring.fmu"];
    let copies = [
        (fmu_dir.join(fmus[0]), fmus[0]),
        (fmu_dir.join(fmus[1]), fmus[1]),
        (
            root.join("modelDescription/SlowDrift_OspModelDescription.xml"),
            "SlowDrift_OspModelDescription.xml",
        ),
        (
            root.join("mooring/Mooring_OspModelDescription.xml"),
            "Mooring_OspModelDescription.xml",
        ),
        (
            root.join("fmu-pack/system/OspSystemStructure.xml"),
            "OspSystemStructure.xml",
        ),
    ];
    for (from, name) in &copies {
        let to = dir.join(name);
        std::fs::write(&to, read(from)?).map_err(|e| format!("{}: {e}", to.display()))?;
    }
    // SSP 1.0 section 6: the SSD at the root of the archive, the FMUs it names
    // (source="resources/...") under resources/.
    let mut entries = vec![archive::Entry {
        path: "SystemStructure.ssd".into(),
        data: read(&root.join("fmu-pack/system/SystemStructure.ssd"))?,
    }];
    for fmu in fmus {
        entries.push(archive::Entry {
            path: format!("resources/{fmu}"),
            data: read(&fmu_dir.join(fmu))?,
        });
    }
    write_fmu(&dir.join(SSP_FILE), &entries)?;
    println!(
        "wrote {} (the two FMUs, their OSP model descriptions, OspSystemStructure.xml and {SSP_FILE})",
        dir.display()
    );
    Ok(())
}
