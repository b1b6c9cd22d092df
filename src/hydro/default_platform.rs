//! The default platform's hydrodynamic data, compiled into the library: the radiation-
//! diffraction solution of the paper's columns on their pontoons (`tests/bem`, Capytaine; the
//! column solver above 1.6-2.0 rad/s; docs/bem.md). Two JSON texts in the native format of
//! `hydro::io::database`: the database without its bi-directional drift (read whenever the
//! default is resolved, about 0.6 MB) and that table alone (about 5.6 MB, read only when a
//! spread sea asks for it, see [`super::bidirectional::BidirectionalSource::Embedded`]).

/// The database (drift table, mass properties, low-frequency added mass), without
/// `bidirectional_drift`.
pub const DATABASE: &str = include_str!("default_platform.json");

/// Its bi-directional drift: a `bidirectional_drift` table.
pub const BIDIRECTIONAL: &str = include_str!("default_platform_bidirectional.json");

/// What errors and fingerprints call [`DATABASE`].
pub const DATABASE_NAME: &str = "the embedded default_platform.json";

/// What errors and fingerprints call [`BIDIRECTIONAL`].
pub const BIDIRECTIONAL_NAME: &str = "the embedded default_platform_bidirectional.json";
