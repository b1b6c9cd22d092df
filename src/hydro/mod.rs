//! Hydrodynamic data: the drift table, wave-drift damping by Aranha's formula, the
//! closed-form drift of isolated vertical columns, the interaction theory of column arrays,
//! the first-order motions (RAOs) of a rigid body, WAMIT readers and the native database.

pub mod aranha;
pub mod bidirectional;
pub mod column_drift;
pub mod columns;
pub mod default_platform;
mod drift_table;
pub(crate) mod heading_grid;
pub mod io;
pub mod qtf;
pub mod rao;
pub mod reference_point;
pub mod rigid_body;

pub use drift_table::{DriftRow, DriftTable};
