//! The FMI 2.0 common and co-simulation functions for any [`Model`], in the order of the
//! standard's headers. Each cdylib's `#[no_mangle] extern "C" fn fmi2*` calls the function of
//! the same name here with its model type, so every FMU of this layer checks its calls,
//! catches panics, reads the host's pointers and reports failures in the same way.
//!
//! Every function that takes an instance runs `with_component`: the NULL check, the
//! firewall, the call against the state machine, the work, then
//! [`Component::report`](super::component::Component::report). A panic becomes `fmi2Error`
//! (NULL from `fmi2Instantiate`) and a log line, never an unwind into the host. Functions
//! the layer does not provide exist (masters resolve all of them at load time) and answer
//! `fmi2Error` with the reason.
//!
//! # Safety
//!
//! The host must pass pointers as the FMI 2.0 standard describes: an `fmi2Component` that
//! `fmi2Instantiate` of the same model returned and that is not yet freed, arrays of at
//! least the given length, NUL-terminated strings, states from `fmi2GetFMUstate` or
//! `fmi2DeSerializeFMUstate` of the same model. NULL pointers are detected and refused;
//! dangling ones cannot be (see the handle module).

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

use super::component::Component;
use super::handle;
use super::machine::MachineState;
use super::model::Model;
use super::types::{fmi2Component, fmi2Status};
use crate::firewall::{catch, firewall};
use crate::machine::CallTable;
use crate::Error;

/// The body of every function that takes an instance, of either standard (`call` from its
/// table: FMI 2.0's `Call`, or FMI 3.0's, whose functions turn the status into theirs): NULL
/// check, state check, the work, then the report; a panic anywhere is reported as an error.
pub(crate) unsafe fn with_component<M: Model, C: CallTable<State = MachineState>>(
    c: fmi2Component,
    call: C,
    body: impl FnOnce(&mut Component<M>) -> Result<(), Error>,
) -> fmi2Status {
    let Some(component) = (unsafe { handle::component::<M>(c) }) else {
        return fmi2Status::fmi2Error;
    };
    firewall(fmi2Status::fmi2Error, || {
        let result = catch(|| {
            component.check(call)?;
            body(component)
        });
        component.report(call, result)
    })
}
