//! The step: `fmi3DoStep`, synchronous and whole (no early return, no event, never the end
//! of the run from the FMU's side).

use super::with_instance;
use crate::fmi2::handle;
use crate::fmi2::model::Model;
use crate::fmi3::machine::Call;
use crate::fmi3::types::*;

/// `fmi3DoStep`: [`Model::do_step`]; then `eventHandlingNeeded`, `terminateSimulation` and
/// `earlyReturn` false and `lastSuccessfulTime` the model's (the end of the step, or where a
/// discarded step left it). A discarded step leaves the instance for a rollback.
#[allow(clippy::too_many_arguments)]
pub unsafe fn do_step<M: Model>(
    instance: fmi3Instance,
    current_communication_point: fmi3Float64,
    communication_step_size: fmi3Float64,
    event_handling_needed: *mut fmi3Boolean,
    terminate_simulation: *mut fmi3Boolean,
    early_return: *mut fmi3Boolean,
    last_successful_time: *mut fmi3Float64,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::DoStep, |component| {
            let flags = [
                handle::out(event_handling_needed, "eventHandlingNeeded")?,
                handle::out(terminate_simulation, "terminateSimulation")?,
                handle::out(early_return, "earlyReturn")?,
            ];
            let time = handle::out(last_successful_time, "lastSuccessfulTime")?;
            for flag in flags {
                *flag = false;
            }
            let result = component
                .model
                .do_step(current_communication_point, communication_step_size);
            *time = component.model.last_successful_time();
            result
        })
    }
}
