//! The FMU's `resources/` folder: the default platform's configuration and a copy of its
//! hydro database, so that a user of the FMU can read, copy and change them. `fmu-pack`
//! writes it; `fmi2::parameters` reads [`RESOURCE_CONFIG`] from it.

use crate::error::{Error, Result};
use crate::hydro::default_platform;
use crate::scenario::default::DEFAULT_CONFIG_TOML;
use std::path::Path;

/// The configuration file an FMU carries in its `resources/` folder.
pub const RESOURCE_CONFIG: &str = "platform.toml";
/// The hydro database next to it: the default platform's data, bi-directional drift
/// included, as one native database file.
pub const RESOURCE_DRIFT: &str = "platform_drift.json";

/// Writes the default platform for an FMU's `resources/` folder: the default configuration
/// as [`RESOURCE_CONFIG`], which reads the data compiled into the library (an instance then
/// reads the 5.6 MB bi-directional table only for a spread sea), and the same data as one
/// database file, [`RESOURCE_DRIFT`], that a configuration can name instead
/// (`source = "database"`) to use a changed copy.
pub fn write_resources(dir: &Path) -> Result<()> {
    let database = default_platform::database()?;
    std::fs::create_dir_all(dir).map_err(|e| Error::Io {
        path: dir.display().to_string(),
        message: e.to_string(),
    })?;
    database.save(&dir.join(RESOURCE_DRIFT))?;
    let path = dir.join(RESOURCE_CONFIG);
    std::fs::write(&path, DEFAULT_CONFIG_TOML).map_err(|e| Error::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problem::resolve;
    use crate::scenario::default::default_scenario;
    use crate::scenario::file;
    use crate::scenario::limits::DEFAULT_MEMORY_LIMIT;

    /// The resources an FMU carries describe exactly the default: its configuration
    /// resolves to the default problem, and the database file, used in its place, gives the
    /// same drift table and every bit of the bi-directional table.
    #[test]
    fn resources_reproduce_the_default() {
        let dir = std::env::temp_dir().join(format!("slowdrift-resources-{}", std::process::id()));
        write_resources(&dir).unwrap();
        let default = resolve(&default_scenario().unwrap()).unwrap();
        let loaded =
            resolve(&file::load(&dir.join(RESOURCE_CONFIG), DEFAULT_MEMORY_LIMIT).unwrap())
                .unwrap();
        assert_eq!(loaded, default);
        let copy = dir.join("copy.toml");
        let text = DEFAULT_CONFIG_TOML.replace(
            "source = \"default-platform\"",
            &format!("source = \"database\"\nfile = \"{RESOURCE_DRIFT}\""),
        );
        assert_ne!(text, DEFAULT_CONFIG_TOML);
        std::fs::write(&copy, text).unwrap();
        let from_file = resolve(&file::load(&copy, DEFAULT_MEMORY_LIMIT).unwrap()).unwrap();
        std::fs::remove_dir_all(&dir).ok();
        assert_eq!(from_file.hydro.drift, default.hydro.drift);
        let Some(crate::hydro::bidirectional::BidirectionalSource::Table(table)) =
            &from_file.hydro.bidirectional
        else {
            panic!("the database file has its bi-directional table");
        };
        assert_eq!(
            Some(table),
            default_platform::database()
                .unwrap()
                .bidirectional_drift
                .as_ref()
        );
    }
}
