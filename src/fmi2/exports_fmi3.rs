//! Every FMI 3.0 function as an `extern "C"` symbol, for SlowDrift's model ([`Instance`]):
//! the shared FMI layer's shims (`slowdrift_fmi::fmi3_exports`), which run the same instance
//! as the `fmi2*` functions of [`super::exports`]. The FMI 3.0 model description is
//! generated from modelDescription.xml (docs/fmu.md#fmi-30).
//!
//! # Safety
//!
//! The host must pass pointers as the FMI 3.0 standard describes (the layer's
//! `fmi3::functions` states the contract); NULL pointers are detected and refused.

#![allow(unsafe_code)]
#![allow(non_snake_case)]
#![allow(clippy::missing_safety_doc)] // the module documentation above states the contract

use super::instance::Instance;

slowdrift_fmi::fmi3_exports!(Instance, super::fmi3_description::NUMBERING);
