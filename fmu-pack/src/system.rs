//! The coupled system, ready for a co-simulation master: `target/fmu/system/` holds
//! SlowDrift.fmu and Mooring.fmu, each with its OSP model description beside it
//! (`<modelName>_OspModelDescription.xml`, where libcosim looks for it), the OSP system
//! structure (`OspSystemStructure.xml`, libcosim and ecos) and the SSP package of the same
//! system (`MooredPlatform.ssp`: `SystemStructure.ssd` with the two FMUs under `resources/`).
//!
//! The system's SlowDrift.fmu is not the default one: it is packed from the default
//! platform's configuration with zero stiffness ([`LINES_ONLY_CONFIG`], [`lines_only`]), so
//! that the lines of Mooring.fmu are its only mooring by construction, in every master,
//! with no parameter binding a master could skip (fmpy's `simulate_ssp` applies none, ecos
//! only a parameter set it is told to). Its start values say stiffness 0.
//!
//! The XML sources are the repository's (`modelDescription/SlowDrift_OspModelDescription.xml`,
//! `mooring/Mooring_OspModelDescription.xml`, `fmu-pack/system/`); the FMUs are the ones just
//! packed and checked. Nothing here interprets them: `tests/clients/test_system_files.py`
//! validates them against their schemas and the FMUs' model descriptions, and
//! `tests/clients/test_system_masters.py` runs the folder in libcosim, ecos and fmpy.

use crate::{archive, pack_configuration, read, write_fmu, MODEL_IDENTIFIER};
use slowdrift::scenario::default::DEFAULT_CONFIG_TOML;
use std::path::Path;

/// The file name of the system platform's configuration (written under the FMU folder).
const LINES_ONLY_CONFIG: &str = "platform_on_lines.toml";

/// The folder under the FMU folder that holds the system.
const SYSTEM_DIR: &str = "system";
/// The SSP package's file name.
const SSP_FILE: &str = "MooredPlatform.ssp";

/// The embedded default configuration with its internal linear mooring removed (every
/// stiffness 0), the text otherwise the default's.
pub fn lines_only() -> Result<String, String> {
    let line = DEFAULT_CONFIG_TOML
        .lines()
        .find(|l| l.starts_with("stiffness = "))
        .ok_or("the default configuration has no stiffness line")?;
    Ok(DEFAULT_CONFIG_TOML.replacen(
        line,
        "stiffness = [[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]   # none inside: \
         the lines of Mooring.fmu moor it (the system of fmu-pack)",
        1,
    ))
}

/// Writes `fmu_dir/system/` from the packed Mooring.fmu in `fmu_dir`, the system's own
/// SlowDrift.fmu (packed here from [`lines_only`] with `library`) and the sources under
/// `root`.
pub fn write(root: &Path, library: &Path, fmu_dir: &Path) -> Result<(), String> {
    let dir = fmu_dir.join(SYSTEM_DIR);
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let config = fmu_dir.join(LINES_ONLY_CONFIG);
    std::fs::write(&config, lines_only()?).map_err(|e| format!("{}: {e}", config.display()))?;
    let fmus = ["SlowDrift.fmu", "Mooring.fmu"];
    println!(
        "packing the system's platform from {LINES_ONLY_CONFIG} (stiffness 0: Mooring.fmu is its \
         only mooring); its self-check below runs it alone, unmoored, so it drifts freely"
    );
    pack_configuration(
        root,
        library,
        &config,
        MODEL_IDENTIFIER,
        // FMI 2.0 only: libcosim and ecos read no other.
        (&dir.join(fmus[0]), false),
        fmu_dir,
    )?;
    let copies = [
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
            data: read(&dir.join(fmu))?,
        });
    }
    write_fmu(&dir.join(SSP_FILE), &entries)?;
    println!(
        "wrote {} (the two FMUs, their OSP model descriptions, OspSystemStructure.xml and {SSP_FILE})",
        dir.display()
    );
    Ok(())
}
