//! The FMU's `resources/` folder: the default platform with its hydrodynamics precomputed,
//! so that an instance reads them instead of running the column solver. `fmu-pack` writes
//! it; `fmi2::parameters` reads [`RESOURCE_CONFIG`] from it.

use crate::error::{Error, Result};
use crate::hydro::io::database::HydroDatabase;
use crate::problem::resolve;
use crate::scenario::default::{default_scenario, DEFAULT_CONFIG_TOML, DEFAULT_DRIFT_LABEL};
use std::path::Path;

/// The configuration file an FMU carries in its `resources/` folder.
pub const RESOURCE_CONFIG: &str = "platform.toml";
/// The hydro database next to it, holding the default platform's precomputed drift.
pub const RESOURCE_DRIFT: &str = "platform_drift.json";

/// Writes the default platform for an FMU's `resources/` folder: its drift table (the
/// column solver's, computed here once) as the hydro database [`RESOURCE_DRIFT`], and the
/// default configuration as [`RESOURCE_CONFIG`] with its `[drift]` section pointing at that
/// database. The bi-directional drift of spread seas still comes from the column solver
/// (`bidirectional = "column-array"`), at the sea's exact directions when the instance
/// initialises, as in the native default.
pub fn write_resources(dir: &Path) -> Result<()> {
    let problem = resolve(&default_scenario()?)?;
    let database = HydroDatabase::from_drift_table(
        "SlowDrift default platform",
        DEFAULT_DRIFT_LABEL,
        &problem.environment,
        &problem.hydro.drift,
    );
    std::fs::create_dir_all(dir).map_err(|e| Error::Io {
        path: dir.display().to_string(),
        message: e.to_string(),
    })?;
    database.save(&dir.join(RESOURCE_DRIFT))?;
    let drift_section = DEFAULT_CONFIG_TOML
        .find("\n[drift]")
        .expect("default.toml ends with its [drift] section");
    let text = format!(
        "{}\n[drift]\n# precomputed by fmu-pack from the default's column-array source\n\
         source = \"database\"\nfile = \"{RESOURCE_DRIFT}\"\n\
         # spread seas: bi-directional drift from the column solver at the sea's directions\n\
         bidirectional = \"column-array\"\n",
        &DEFAULT_CONFIG_TOML[..drift_section]
    );
    let path = dir.join(RESOURCE_CONFIG);
    std::fs::write(&path, text).map_err(|e| Error::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::file;

    /// The resources an FMU carries describe exactly the default (the database keeps every
    /// bit of the drift and damping).
    #[test]
    fn resources_reproduce_the_default() {
        let dir = std::env::temp_dir().join(format!("slowdrift-resources-{}", std::process::id()));
        write_resources(&dir).unwrap();
        let loaded = resolve(&file::load(&dir.join(RESOURCE_CONFIG)).unwrap()).unwrap();
        std::fs::remove_dir_all(&dir).ok();
        assert_eq!(loaded, resolve(&default_scenario().unwrap()).unwrap());
    }
}
