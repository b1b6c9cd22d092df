//! The FMI 2.0 co-simulation C ABI, and no physics. The crate denies `unsafe` code; only
//! [`exports`] (C pointers) and the one call of the host's logger in `logger` allow it.
//!
//! - [`types`]: the C types of the FMI 2.0 headers, written by hand;
//! - [`exports`]: every `fmi2*` function, each behind a panic firewall;
//! - [`machine`]: the FMI state machine (states, which call is allowed where);
//! - `logger`: the host's logger and the debug-logging categories;
//! - `fmu_error`: why a call failed, and its `fmi2Status`;
//! - `instance`: one instance's parameters, inputs, outputs and simulation (safe Rust);
//! - [`parameters`]: FMU parameters and experiment -> [`crate::Scenario`];
//! - [`campaign`]: the FMU parameters that run each case of a campaign (`--print-cases`);
//! - [`resources`]: the `resources/` folder of the packed FMU;
//! - `state`: saved states and their versioned byte format.
//!
//! The cdylib exports the `fmi2*` symbols only (`exports.map`, a linker version script
//! that build.rs passes on Linux).

pub mod campaign;
pub mod exports;
mod fmu_error;
mod instance;
mod logger;
pub mod machine;
pub mod model_description;
pub mod parameters;
pub mod resources;
mod state;
pub mod types;
