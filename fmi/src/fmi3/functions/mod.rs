//! The FMI 3.0 functions of a co-simulation FMU for any [`Model`] of the layer, in the order
//! of the standard's header `fmi3Functions.h`. Each cdylib's `#[no_mangle] extern "C" fn
//! fmi3*` (made by [`crate::fmi3_exports`]) calls the function of the same name here.
//!
//! The instance is the FMI 2.0 layer's (`fmi2::component::Component`: the same model, state
//! machine, logger and report), so one model serves both standards: these functions turn
//! the FMI 3.0 arguments into the model's calls and [`fmi3Status`] comes from the same
//! outcome policy. Every function that takes an instance runs `with_instance`: the NULL
//! check, the firewall, the call against the FMI 3.0 table ([`Call`]), the work, the report.
//! The functions the FMU does not provide exist (FMI 3.0 section 2.5: every function is
//! exported) and answer `fmi3Error` with the reason.
//!
//! # Safety
//!
//! The host must pass pointers as the FMI 3.0 standard describes: an `fmi3Instance` that
//! `fmi3InstantiateCoSimulation` of the same model returned and that is not yet freed,
//! arrays of at least the given length, NUL-terminated strings, states from
//! `fmi3GetFMUState` or `fmi3DeserializeFMUState` of the same model. NULL pointers are
//! detected and refused; dangling ones cannot be.

#![allow(unsafe_code)]
#![allow(clippy::missing_safety_doc)] // the module documentation above states the contract

mod co_simulation;
mod lifecycle;
mod states;
mod unsupported;
mod variables;

pub use co_simulation::*;
pub use lifecycle::*;
pub use states::*;
pub use unsupported::*;
pub use variables::*;

use super::machine::Call;
use super::types::{fmi3Instance, fmi3Status};
use crate::fmi2::component::Component;
use crate::fmi2::functions::with_component;
use crate::fmi2::model::Model;
use crate::Error;

/// The body of every function that takes an instance: the FMI 2.0 layer's (NULL check,
/// the call against FMI 3.0's table, the work, the report, a panic an error), its status as
/// FMI 3.0's.
unsafe fn with_instance<M: Model>(
    instance: fmi3Instance,
    call: Call,
    body: impl FnOnce(&mut Component<M>) -> Result<(), Error>,
) -> fmi3Status {
    unsafe { with_component::<M, Call>(instance, call, body) }.into()
}
