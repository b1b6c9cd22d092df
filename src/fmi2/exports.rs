//! Every FMI 2.0 common and co-simulation function, as `extern "C"` symbols, for SlowDrift's
//! model ([`Instance`]): the shared FMI layer's shims (`slowdrift_fmi::fmi2_exports`), which
//! call the function of the same name of `slowdrift_fmi::fmi2::functions`. The layer checks
//! the call against the state machine, turns the pointers into references, runs the model
//! behind its panic firewall and reports the result; this file has no logic of its own.
//!
//! # Safety
//!
//! The host must pass pointers as the FMI 2.0 standard describes: an `fmi2Component` that
//! `fmi2Instantiate` returned and that is not yet freed, arrays of at least the given
//! length, NUL-terminated strings, states from `fmi2GetFMUstate`/`fmi2DeSerializeFMUstate`
//! of this library. NULL pointers are detected and refused; dangling ones cannot be.

#![allow(unsafe_code)]
#![allow(non_snake_case)]
#![allow(clippy::missing_safety_doc)] // the module documentation above states the contract

use super::instance::Instance;
use slowdrift_fmi::fmi2::machine::MachineState;

slowdrift_fmi::fmi2_exports!(Instance);

/// The state of an instance, for tests of the state machine (NULL: `None`).
///
/// # Safety
/// `c` is NULL or a live instance from [`fmi2Instantiate`].
pub unsafe fn instance_state(c: fmi2Component) -> Option<MachineState> {
    unsafe { fmi2::machine_state::<Instance>(c) }
}
