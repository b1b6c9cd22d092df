//! The default platform's hydrodynamic data, compiled into the library: the radiation-
//! diffraction solution of the paper's columns on their pontoons (`tests/bem`, Capytaine; the
//! column solver above 1.6-2.0 rad/s; docs/bem.md). Two JSON texts in the native format of
//! `hydro::io::database`: the database without its bi-directional drift (read whenever the
//! default is resolved, about 1.0 MB, of which 0.43 MB are its RAOs) and that table alone
//! (about 5.6 MB, read only when a spread sea asks for it, see
//! [`super::bidirectional::BidirectionalSource::Embedded`]). The first is read from its
//! MessagePack twin, which build.rs makes from it: the same numbers without their decimal
//! parsing (2.5 ms of an FMU's initialisation as JSON, 0.9 ms as MessagePack;
//! docs/benchmarks.md#the-default-platform-read-as-messagepack).

use super::bidirectional::BidirectionalTable;
use super::io::database::{self, HydroDatabase};
use crate::error::{Error, Result};

/// The database (drift table, mass properties, low-frequency added mass, RAOs), without
/// `bidirectional_drift`.
pub const DATABASE: &str = include_str!("default_platform.json");

/// Its bi-directional drift: a `bidirectional_drift` table.
pub const BIDIRECTIONAL: &str = include_str!("default_platform_bidirectional.json");

/// [`DATABASE`] as MessagePack (build.rs): every number the correctly rounded value of its
/// decimal text, as [`HydroDatabase::parse`] reads it.
const DATABASE_MESSAGEPACK: &[u8] =
    include_bytes!(concat!(env!("OUT_DIR"), "/default_platform.msgpack"));

/// What errors and fingerprints call [`DATABASE`].
pub const DATABASE_NAME: &str = "the embedded default_platform.json";

/// What errors and fingerprints call [`BIDIRECTIONAL`].
pub const BIDIRECTIONAL_NAME: &str = "the embedded default_platform_bidirectional.json";

/// The default platform's data as one database: [`DATABASE`] with [`BIDIRECTIONAL`] as its
/// `bidirectional_drift` (what `fmu-pack` packs, and what a configuration naming that file
/// reads).
pub fn database() -> Result<HydroDatabase> {
    let mut database = without_bidirectional()?;
    database.bidirectional_drift = Some(BidirectionalTable::parse(
        BIDIRECTIONAL,
        BIDIRECTIONAL_NAME,
    )?);
    Ok(database)
}

/// [`DATABASE`], read from its MessagePack twin and validated as [`HydroDatabase::parse`]
/// validates (errors located in [`DATABASE`]'s lines).
pub fn without_bidirectional() -> Result<HydroDatabase> {
    let database: HydroDatabase =
        rmp_serde::from_slice(DATABASE_MESSAGEPACK).map_err(|e| Error::Parse {
            path: DATABASE_NAME.to_string(),
            line: None,
            message: format!("its MessagePack twin (build.rs): {e}"),
        })?;
    database
        .validate()
        .map_err(|e| database::locate(e, DATABASE, DATABASE_NAME))?;
    Ok(database)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The MessagePack twin holds what the JSON text says, bit for bit (every number, the
    /// optional fields, the order of the drift table), read by serde_json's correctly
    /// rounded parser on the one side.
    #[test]
    fn the_messagepack_twin_reads_as_the_json() {
        let from_json = HydroDatabase::parse(DATABASE, DATABASE_NAME).unwrap();
        let from_messagepack = without_bidirectional().unwrap();
        assert!(from_json == from_messagepack);
        // PartialEq on f64 would let -0.0 equal 0.0: the bits as well.
        let bits = |d: &HydroDatabase| -> Vec<u64> {
            let mut bits = Vec::new();
            let value = serde_json::to_value(d).unwrap();
            collect_bits(&value, &mut bits);
            bits
        };
        assert_eq!(bits(&from_json), bits(&from_messagepack));
        assert!(from_json.rao.is_some() && from_json.drift.len() > 1000);
    }

    fn collect_bits(value: &serde_json::Value, out: &mut Vec<u64>) {
        match value {
            serde_json::Value::Number(n) => out.push(n.as_f64().unwrap().to_bits()),
            serde_json::Value::Array(items) => items.iter().for_each(|v| collect_bits(v, out)),
            serde_json::Value::Object(map) => map.values().for_each(|v| collect_bits(v, out)),
            _ => {}
        }
    }
}
