//! Hydrodynamic data: the drift table, wave-drift damping by Aranha's formula, the
//! closed-form drift of isolated vertical columns, and the interaction theory of column
//! arrays.

pub mod aranha;
pub mod column_drift;
pub mod columns;
mod drift_table;

pub use drift_table::{DriftRow, DriftTable};
