//! The functions the layer does not provide (declared so in every model description): they
//! exist, because masters resolve all of them at load time, and answer `fmi2Error` saying
//! why.

use super::with_component;
use crate::fmi2::machine::Call;
use crate::fmi2::model::Model;
use crate::fmi2::types::{fmi2Component, fmi2Status};
use crate::Error;

/// A function the FMU does not provide: `fmi2Error` and `why`.
unsafe fn unsupported<M: Model>(c: fmi2Component, call: Call, why: &'static str) -> fmi2Status {
    unsafe { with_component::<M, _>(c, call, |_| Err(Error::Unsupported(why))) }
}

/// `fmi2GetDirectionalDerivative`.
pub unsafe fn get_directional_derivative<M: Model>(c: fmi2Component) -> fmi2Status {
    unsafe {
        unsupported::<M>(
            c,
            Call::GetDirectionalDerivative,
            "providesDirectionalDerivative=\"false\": no Jacobian is computed",
        )
    }
}

/// `fmi2SetRealInputDerivatives`.
pub unsafe fn set_real_input_derivatives<M: Model>(c: fmi2Component) -> fmi2Status {
    unsafe {
        unsupported::<M>(
            c,
            Call::SetRealInputDerivatives,
            "canInterpolateInputs=\"false\": inputs are held constant over a step",
        )
    }
}

/// `fmi2GetRealOutputDerivatives`.
pub unsafe fn get_real_output_derivatives<M: Model>(c: fmi2Component) -> fmi2Status {
    unsafe {
        unsupported::<M>(
            c,
            Call::GetRealOutputDerivatives,
            "maxOutputDerivativeOrder=\"0\": no output derivatives",
        )
    }
}

/// `fmi2CancelStep`.
pub unsafe fn cancel_step<M: Model>(c: fmi2Component) -> fmi2Status {
    unsafe {
        unsupported::<M>(
            c,
            Call::CancelStep,
            "steps are never asynchronous (fmi2DoStep never returns fmi2Pending)",
        )
    }
}

/// The six FMU-state functions of a model without [`SavedStates`](crate::fmi2::SavedStates)
/// (`canGetAndSetFMUstate` and `canSerializeFMUstate` false): `call` says which.
pub unsafe fn without_saved_states<M: Model>(c: fmi2Component, call: Call) -> fmi2Status {
    unsafe {
        unsupported::<M>(
            c,
            call,
            "canGetAndSetFMUstate=\"false\" and canSerializeFMUstate=\"false\": FMU states \
             are not saved",
        )
    }
}
