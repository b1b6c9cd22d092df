//! The hydrodynamic file formats: the native database ([`database`]), WAMIT output
//! ([`wamit`]), NEMOH v3 results ([`nemoh`]) and CSV drift tables ([`drift_csv`]). Each
//! reader names the file and line of what it refuses; the data it gives are SI, radians, and
//! the crate's frames.

pub mod database;
pub mod drift_csv;
pub mod import;
mod json_position;
pub mod nemoh;
pub mod wamit;
mod written;
