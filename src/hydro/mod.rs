//! Hydrodynamic data: the drift table, wave-drift damping by Aranha's formula, and the
//! closed-form drift of isolated vertical columns.

pub mod aranha;
pub mod column_drift;
mod drift_table;

pub use drift_table::{DriftRow, DriftTable};
