//! Every FMI 3.0 function as an `extern "C"` symbol, for the mooring model ([`Instance`]):
//! the shared FMI layer's shims (`slowdrift_fmi::fmi3_exports`) on the same instance as the
//! `fmi2*` functions; its states cannot be saved (MoorDyn's cannot), as in FMI 2.0.
//!
//! # Safety
//!
//! The host must pass pointers as the FMI 3.0 standard describes (the layer's
//! `fmi3::functions` states the contract); NULL pointers are detected and refused.

#![allow(unsafe_code)]
#![allow(non_snake_case)]
#![allow(clippy::missing_safety_doc)] // the module documentation above states the contract

use super::instance::Instance;

slowdrift_fmi::fmi3_exports!(
    Instance,
    crate::fmi3_description::NUMBERING,
    without_saved_states
);
