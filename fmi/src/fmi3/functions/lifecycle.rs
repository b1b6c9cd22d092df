//! The common functions of an instance's life: the version, debug logging, instantiation
//! (co-simulation only) and freeing, initialisation (with the experiment FMI 3.0 passes to
//! `fmi3EnterInitializationMode`), termination and reset.

use super::with_instance;
use crate::firewall::firewall;
use crate::fmi2::component::{refuse, Component};
use crate::fmi2::handle;
use crate::fmi2::logger::Logger;
use crate::fmi2::machine::MachineState;
use crate::fmi2::model::{Instantiation, Model};
use crate::fmi3::machine::Call;
use crate::fmi3::types::*;
use crate::log::Category;
use crate::Error;
use std::ffi::c_char;
use std::path::PathBuf;
use std::ptr;

/// `fmi3GetVersion`.
pub fn get_version() -> *const c_char {
    c"3.0".as_ptr()
}

/// `fmi3SetDebugLogging`: no category names them all ([`crate::log`]).
pub unsafe fn set_debug_logging<M: Model>(
    instance: fmi3Instance,
    logging_on: fmi3Boolean,
    n_categories: usize,
    categories: *const fmi3String,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::SetDebugLogging, |component| {
            let pointers = handle::slice(categories, n_categories, "categories")?;
            let mut names = Vec::with_capacity(pointers.len());
            for &p in pointers {
                names.push(handle::text(p, "a category")?);
            }
            component.logger.set(logging_on, &names)
        })
    }
}

/// `fmi3InstantiateCoSimulation`: an instance with a name, its resources folder
/// (`resourcePath`, a native path; NULL: none) and the model [`Model::instantiate`] makes
/// for the `instantiationToken`; NULL, with a log line, when any of them fails or the host
/// asks for what the FMU does not do (event mode, early return: the model description
/// declares `hasEventMode` and `mightReturnEarlyFromDoStep` false).
#[allow(clippy::too_many_arguments)]
pub unsafe fn instantiate_co_simulation<M: Model>(
    instance_name: fmi3String,
    instantiation_token: fmi3String,
    resource_path: fmi3String,
    logging_on: fmi3Boolean,
    event_mode_used: fmi3Boolean,
    early_return_allowed: fmi3Boolean,
    n_required_intermediate_variables: usize,
    instance_environment: fmi3InstanceEnvironment,
    log_message: Option<fmi3LogMessageCallback>,
) -> fmi3Instance {
    firewall(ptr::null_mut(), || {
        let name = unsafe { handle::text(instance_name, "instanceName") };
        let logger = Logger::fmi3(
            log_message,
            instance_environment,
            name.as_ref()
                .ok()
                .filter(|n| !n.is_empty())
                .map_or(M::MODEL_IDENTIFIER, |n| n),
            logging_on,
        );
        let refused = |e: Error| {
            refuse(&logger, "fmi3InstantiateCoSimulation", &e);
            ptr::null_mut()
        };
        let name = match name {
            Ok(n) if !n.is_empty() => n,
            Ok(_) => return refused(Error::Argument("instanceName is empty".into())),
            Err(e) => return refused(e),
        };
        if event_mode_used {
            return refused(Error::Argument(format!(
                "eventModeUsed = true: {name} has no event mode (hasEventMode=\"false\")"
            )));
        }
        if early_return_allowed {
            logger.log(
                crate::fmi2::types::fmi2Status::fmi2OK,
                Category::Events,
                "earlyReturnAllowed = true: this FMU never returns early from fmi3DoStep",
            );
        }
        if n_required_intermediate_variables > 0 {
            return refused(Error::Argument(format!(
                "{n_required_intermediate_variables} required intermediate variables: {name} \
                 provides no intermediate update (providesIntermediateUpdate=\"false\")"
            )));
        }
        let resources = if resource_path.is_null() {
            None
        } else {
            match unsafe { handle::text(resource_path, "resourcePath") } {
                Ok(path) if !path.is_empty() => Some(PathBuf::from(path)),
                Ok(_) => None,
                Err(e) => return refused(e),
            }
        };
        if resources.is_none() {
            logger.log(
                crate::fmi2::types::fmi2Status::fmi2Warning,
                Category::StatusWarning,
                &format!(
                    "fmi3InstantiateCoSimulation: no resourcePath; {}",
                    M::WITHOUT_RESOURCES
                ),
            );
        }
        let token = match unsafe { handle::text(instantiation_token, "instantiationToken") } {
            Ok(token) => token,
            Err(e) => return refused(e),
        };
        match M::instantiate(Instantiation {
            name,
            guid: token,
            resources,
        }) {
            Ok(model) => handle::into_component(Component::new(logger, model)),
            Err(e) => refused(e),
        }
    })
}

/// `fmi3FreeInstance` (NULL is ignored).
pub unsafe fn free_instance<M: Model>(instance: fmi3Instance) {
    if let Some(component) = unsafe { handle::take_component::<M>(instance) } {
        firewall((), || drop(component));
    }
}

/// `fmi3EnterInitializationMode`: the experiment (start time, stop time when
/// `stopTimeDefined`; the tolerance is not used: RK4 has a fixed step), then Initialization
/// Mode.
pub unsafe fn enter_initialization_mode<M: Model>(
    instance: fmi3Instance,
    start_time: fmi3Float64,
    stop_time_defined: fmi3Boolean,
    stop_time: fmi3Float64,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::EnterInitializationMode, |component| {
            let stop = stop_time_defined.then_some(stop_time);
            component.model.setup_experiment(start_time, stop)?;
            component.state = MachineState::InitializationMode;
            component.logger.event("entered initialization mode");
            Ok(())
        })
    }
}

/// `fmi3ExitInitializationMode`: [`Model::exit_initialization_mode`], then Step Mode (no
/// event mode).
pub unsafe fn exit_initialization_mode<M: Model>(instance: fmi3Instance) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::ExitInitializationMode, |component| {
            component.run(|model, cx| model.exit_initialization_mode(cx))?;
            component.state = MachineState::StepComplete;
            Ok(())
        })
    }
}

/// `fmi3Terminate`.
pub unsafe fn terminate<M: Model>(instance: fmi3Instance) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::Terminate, |component| {
            component.state = MachineState::Terminated;
            component.logger.event("terminated");
            Ok(())
        })
    }
}

/// `fmi3Reset`: a freshly instantiated instance; the name, callback, logging switches and
/// the model's resources stay.
pub unsafe fn reset<M: Model>(instance: fmi3Instance) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::Reset, |component| {
            component.model.reset();
            component.state = MachineState::Instantiated;
            component.logger.event("reset");
            Ok(())
        })
    }
}
