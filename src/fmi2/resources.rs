//! The FMU's `resources/` folder: the default platform's configuration and a copy of its
//! hydro database, so that a user of the FMU can read, copy and change them; or, in an FMU
//! packed from a user's configuration (`fmu-pack --config`), that configuration and the
//! drift file it names. `fmu-pack` writes it; `fmi2::parameters` reads [`RESOURCE_CONFIG`]
//! from it, and `fmi2Instantiate` accepts the GUID of the configuration it holds
//! ([`configuration_guid`]).

use crate::error::{Error, Result};
use crate::fingerprint;
use crate::hydro::default_platform;
use crate::scenario::default::DEFAULT_CONFIG_TOML;
use crate::scenario::limits::DEFAULT_MEMORY_LIMIT;
use crate::scenario::{file, DriftSource, Scenario};
use std::path::{Path, PathBuf};

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

/// The GUID of an FMU packed from a user's configuration whose embedded configuration text
/// is `text`: two FNV-1a hashes of its bytes (the second over the bytes after a one-byte
/// prefix) written as a GUID, `{xxxxxxxx-xxxx-xxxx-xxxx-xxxxxxxxxxxx}`. FMUs of different
/// configurations thus have different GUIDs, as their model descriptions (start values)
/// differ: masters such as libcosim keep one unpacked FMU per GUID.
pub fn configuration_guid(text: &str) -> String {
    let a = fingerprint::of_bytes(text.as_bytes());
    let mut prefixed = Vec::with_capacity(text.len() + 1);
    prefixed.push(b'G');
    prefixed.extend_from_slice(text.as_bytes());
    let b = fingerprint::of_bytes(&prefixed);
    format!(
        "{{{:08x}-{:04x}-{:04x}-{:04x}-{:012x}}}",
        a >> 32,
        (a >> 16) & 0xffff,
        a & 0xffff,
        b >> 48,
        b & 0xffff_ffff_ffff
    )
}

/// Whether `guid` is that of the configuration packed in the resources folder `dir`
/// ([`configuration_guid`] of its [`RESOURCE_CONFIG`]); false when it cannot be read.
pub fn holds_configuration_of(dir: &Path, guid: &str) -> bool {
    // Read before any parameter is set: within the default memory limit.
    crate::files::read_text(
        &dir.join(RESOURCE_CONFIG),
        &file::READING,
        DEFAULT_MEMORY_LIMIT,
    )
    .is_ok_and(|text| configuration_guid(&text) == guid)
}

/// A user's configuration packed as an FMU's embedded one ([`write_configuration`]).
#[derive(Debug)]
pub struct PackedConfiguration {
    /// The configuration read back from the folder (its drift file there).
    pub scenario: Scenario,
    /// The FMU's GUID ([`configuration_guid`] of the packed text).
    pub guid: String,
}

/// Writes the configuration file `config` into the FMU resources folder `dir` as
/// [`RESOURCE_CONFIG`], with the drift file it names (`[drift] file`, a CSV table or a
/// native database) copied beside it under its own file name and the `file` value rewritten
/// to that name: every other byte of the text is the user's, so a line a message names is
/// the line of their file. The packed configuration is read back, so a file that does not
/// read is refused here, naming the user's file. Read within the default memory limit.
pub fn write_configuration(config: &Path, dir: &Path) -> Result<PackedConfiguration> {
    let text = crate::files::read_text(config, &file::READING, DEFAULT_MEMORY_LIMIT)?;
    let scenario = file::load(config, DEFAULT_MEMORY_LIMIT)?;
    let io = |path: &Path, e: std::io::Error| Error::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    };
    std::fs::create_dir_all(dir).map_err(|e| io(dir, e))?;
    let packed = match drift_file(&scenario.hydro) {
        Some(data) => {
            let name = data
                .file_name()
                .filter(|n| *n != RESOURCE_CONFIG)
                .ok_or_else(|| Error::Parse {
                    path: config.display().to_string(),
                    line: None,
                    message: format!(
                        "[drift] file = {}: an FMU packs it under its own file name, which must \
                         not be {RESOURCE_CONFIG}",
                        data.display()
                    ),
                })?;
            let to = dir.join(name);
            std::fs::copy(data, &to).map_err(|e| io(data, e))?;
            with_drift_file(&text, &name.to_string_lossy(), config)?
        }
        None => text,
    };
    let path = dir.join(RESOURCE_CONFIG);
    std::fs::write(&path, &packed).map_err(|e| io(&path, e))?;
    Ok(PackedConfiguration {
        scenario: file::load_named(&path, &config.display().to_string(), DEFAULT_MEMORY_LIMIT)?,
        guid: configuration_guid(&packed),
    })
}

/// The file a drift source reads, if it reads one.
fn drift_file(source: &DriftSource) -> Option<&PathBuf> {
    match source {
        DriftSource::Csv(path) | DriftSource::Database { path, .. } => Some(path),
        _ => None,
    }
}

/// `text` with its `[drift] file` value replaced by `name` (a TOML string), nothing else
/// changed.
fn with_drift_file(text: &str, name: &str, config: &Path) -> Result<String> {
    let document = toml::de::DeTable::parse(text).map_err(|e| Error::Parse {
        path: config.display().to_string(),
        line: None,
        message: e.to_string(),
    })?;
    let span = document
        .get_ref()
        .get("drift")
        .and_then(|drift| match drift.get_ref() {
            toml::de::DeValue::Table(table) => table.get("file").map(|f| f.span()),
            _ => None,
        })
        .expect("a configuration whose drift source reads a file has [drift] file");
    let quoted = toml::Value::String(name.to_string()).to_string();
    Ok(format!(
        "{}{quoted}{}",
        &text[..span.start],
        &text[span.end..]
    ))
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

    /// A user's configuration with a CSV drift file elsewhere: packed with the file beside
    /// it, every other byte kept, the same problem as the original, and a GUID of its own
    /// that changes with the text and that the folder answers to.
    #[test]
    fn a_users_configuration_is_packed_with_its_drift_file() {
        let base = std::env::temp_dir().join(format!("slowdrift-pack-{}", std::process::id()));
        let data = base.join("data");
        std::fs::create_dir_all(&data).unwrap();
        std::fs::write(
            data.join("drift.csv"),
            "omega,beta_deg,surge,sway,yaw\n0.3,0,1500,0,0\n2.0,0,66000,0,0\n\
             0.3,90,0,1600,0\n2.0,90,0,68000,0\n",
        )
        .unwrap();
        let example = include_str!("../../tests/data/example.toml");
        let drift = example.find("[drift]").unwrap();
        let text = format!(
            "{}[drift]\nsource = \"csv\"\nfile = 'data/drift.csv' # the table\n",
            &example[..drift]
        );
        let config = base.join("mine.toml");
        std::fs::write(&config, &text).unwrap();
        let dir = base.join("resources");
        let packed = write_configuration(&config, &dir).unwrap();
        let written = std::fs::read_to_string(dir.join(RESOURCE_CONFIG)).unwrap();
        assert_eq!(
            written,
            text.replace("'data/drift.csv'", "\"drift.csv\""),
            "only the file value changes"
        );
        assert!(dir.join("drift.csv").is_file());
        let original = resolve(&file::load(&config, DEFAULT_MEMORY_LIMIT).unwrap()).unwrap();
        let mut from_pack = resolve(&packed.scenario).unwrap();
        assert!(from_pack.hydro.source.ends_with("resources/drift.csv"));
        from_pack.hydro.source = original.hydro.source.clone();
        assert_eq!(from_pack, original);
        assert_eq!(packed.guid, configuration_guid(&written));
        assert_ne!(packed.guid, configuration_guid(&text));
        assert!(holds_configuration_of(&dir, &packed.guid));
        assert!(!holds_configuration_of(
            &dir,
            crate::fmi2::model_description::GUID
        ));
        let guid = &packed.guid;
        assert!(
            guid.len() == 38
                && guid.starts_with('{')
                && guid.ends_with('}')
                && guid[1..37]
                    .char_indices()
                    .all(|(i, c)| if [8, 13, 18, 23].contains(&i) {
                        c == '-'
                    } else {
                        c.is_ascii_hexdigit()
                    }),
            "{guid}"
        );
        std::fs::remove_dir_all(&base).ok();
    }
}
