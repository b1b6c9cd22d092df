//! The FMI 2.0 co-simulation C ABI: the only `unsafe` code of the crate, and no physics.
//!
//! - [`types`]: the C types of the FMI 2.0 headers, written by hand;
//! - [`exports`]: every `fmi2*` function, each behind a panic firewall;
//! - [`instance`]: one instance's state machine, variables and logger (safe Rust);
//! - [`parameters`]: FMU parameters and experiment -> [`crate::Config`];
//! - [`state`]: saved states and their versioned byte format.
//!
//! The cdylib exports the `fmi2*` symbols only (`exports.map`, a linker version script
//! that build.rs passes on Linux).

#![allow(unsafe_code)]

pub mod exports;
pub mod instance;
pub mod parameters;
pub mod state;
pub mod types;
