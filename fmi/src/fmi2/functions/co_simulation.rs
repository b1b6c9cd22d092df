//! The co-simulation functions: the step, and the status queries (steps are synchronous, so
//! the only statuses are the last successful time and whether the run ended: never).

use super::with_component;
use crate::fmi2::handle;
use crate::fmi2::machine::Call;
use crate::fmi2::model::Model;
use crate::fmi2::types::*;
use crate::Error;

/// `fmi2DoStep`: [`Model::do_step`]; a discarded step leaves the instance in StepFailed.
pub unsafe fn do_step<M: Model>(
    c: fmi2Component,
    current_communication_point: fmi2Real,
    communication_step_size: fmi2Real,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::DoStep, |component| {
            component
                .model
                .do_step(current_communication_point, communication_step_size)
        })
    }
}

const NO_PENDING: &str = "steps are never asynchronous, so there is no pending status";

/// `fmi2GetStatus`: `fmi2Discard`, there is no pending status.
pub unsafe fn get_status<M: Model>(c: fmi2Component) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::GetStatus, |_| {
            Err(Error::StatusUnavailable(NO_PENDING.into()))
        })
    }
}

/// `fmi2GetRealStatus`: `fmi2LastSuccessfulTime` only.
pub unsafe fn get_real_status<M: Model>(
    c: fmi2Component,
    kind: fmi2StatusKind,
    value: *mut fmi2Real,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::GetRealStatus, |component| {
            if kind != fmi2StatusKind::fmi2LastSuccessfulTime {
                return Err(Error::StatusUnavailable(
                    "fmi2GetRealStatus answers fmi2LastSuccessfulTime only".into(),
                ));
            }
            let answer = component.model.last_successful_time();
            *handle::out(value, "value")? = answer;
            Ok(())
        })
    }
}

/// `fmi2GetIntegerStatus`: `fmi2Discard`, FMI 2.0 defines none.
pub unsafe fn get_integer_status<M: Model>(c: fmi2Component) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::GetIntegerStatus, |_| {
            Err(Error::StatusUnavailable(
                "FMI 2.0 defines no Integer status".into(),
            ))
        })
    }
}

/// `fmi2GetBooleanStatus`: `fmi2Terminated` only, always false (a model of this layer never
/// ends a run itself; a discarded step can be rolled back).
pub unsafe fn get_boolean_status<M: Model>(
    c: fmi2Component,
    kind: fmi2StatusKind,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::GetBooleanStatus, |_| {
            if kind != fmi2StatusKind::fmi2Terminated {
                return Err(Error::StatusUnavailable(
                    "fmi2GetBooleanStatus answers fmi2Terminated only".into(),
                ));
            }
            *handle::out(value, "value")? = fmi2False;
            Ok(())
        })
    }
}

/// `fmi2GetStringStatus`: `fmi2Discard`, there is no pending status.
pub unsafe fn get_string_status<M: Model>(c: fmi2Component) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::GetStringStatus, |_| {
            Err(Error::StatusUnavailable(NO_PENDING.into()))
        })
    }
}
