//! The 34 FMI 2.0 common and co-simulation functions of the mooring FMU, as `extern "C"`
//! symbols, for its model ([`Instance`]): the shared FMI layer's shims
//! (`slowdrift_fmi::fmi2_exports`, as SlowDrift's FMU has them), which call the function of
//! the same name of `slowdrift_fmi::fmi2::functions`. FMU states are not provided
//! (`canGetAndSetFMUstate="false"`: MoorDyn's cannot be saved): those six functions answer
//! `fmi2Error` saying so.
//!
//! # Safety
//!
//! The host passes pointers as FMI 2.0 describes: an `fmi2Component` from `fmi2Instantiate`
//! not yet freed, arrays of at least the given length, NUL-terminated strings. NULL pointers
//! are detected and refused; dangling ones cannot be.

#![allow(unsafe_code)]
#![allow(non_snake_case)]
#![allow(clippy::missing_safety_doc)] // the module documentation above states the contract

use super::instance::Instance;

slowdrift_fmi::fmi2_exports!(Instance, without_saved_states);
