//! The FMI 3.0 co-simulation layer: a thin adapter beside [`crate::fmi2`], with no model
//! and no physics.
//!
//! - [`types`]: the C types of the FMI 3.0 headers, written by hand;
//! - [`machine`]: the FMI 3.0 calls and the states that allow each, on the layer's one
//!   state machine;
//! - [`functions`]: every FMI 3.0 function for any [`crate::fmi2::Model`]: an FMI 3.0
//!   instance is the FMI 2.0 layer's (its model, state, logger and report), so one model
//!   serves both standards; the functions the FMU does not provide answer `fmi3Error`;
//! - [`crate::fmi3_exports`]: the `#[no_mangle] extern "C" fn fmi3*` shims of a cdylib, all
//!   of them, made for its model by one macro call.
//!
//! The variables are the FMI 2.0 model description's, with one more: the independent
//! variable `time` ([`TIME_VALUE_REFERENCE`]), which FMI 3.0 requires of every model
//! description and which these functions answer themselves.

pub mod functions;
pub mod machine;
pub mod types;
#[macro_use]
mod exports;

/// The value reference of the independent variable `time` in every FMI 3.0 model
/// description of the layer (no FMI 2.0 variable may take it).
pub const TIME_VALUE_REFERENCE: u32 = 999_999;
