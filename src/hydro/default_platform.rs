//! The default platform's hydrodynamic data, compiled into the library: the radiation-
//! diffraction solution of the paper's columns on their pontoons (`tests/bem`, Capytaine; the
//! column solver above 1.6-2.0 rad/s; docs/bem.md). Two JSON texts in the native format of
//! `hydro::io::database`: the database without its bi-directional drift (read whenever the
//! default is resolved, about 1.0 MB, of which 0.43 MB are its RAOs) and that table alone
//! (about 5.6 MB, read only when a spread sea asks for it, see
//! [`super::bidirectional::BidirectionalSource::Embedded`]).

use super::bidirectional::BidirectionalTable;
use super::io::database::HydroDatabase;
use crate::error::Result;

/// The database (drift table, mass properties, low-frequency added mass, RAOs), without
/// `bidirectional_drift`.
pub const DATABASE: &str = include_str!("default_platform.json");

/// Its bi-directional drift: a `bidirectional_drift` table.
pub const BIDIRECTIONAL: &str = include_str!("default_platform_bidirectional.json");

/// What errors and fingerprints call [`DATABASE`].
pub const DATABASE_NAME: &str = "the embedded default_platform.json";

/// What errors and fingerprints call [`BIDIRECTIONAL`].
pub const BIDIRECTIONAL_NAME: &str = "the embedded default_platform_bidirectional.json";

/// The default platform's data as one database: [`DATABASE`] with [`BIDIRECTIONAL`] as its
/// `bidirectional_drift` (what `fmu-pack` packs, and what a configuration naming that file
/// reads).
pub fn database() -> Result<HydroDatabase> {
    let mut database = HydroDatabase::parse(DATABASE, DATABASE_NAME)?;
    database.bidirectional_drift = Some(BidirectionalTable::parse(
        BIDIRECTIONAL,
        BIDIRECTIONAL_NAME,
    )?);
    Ok(database)
}
