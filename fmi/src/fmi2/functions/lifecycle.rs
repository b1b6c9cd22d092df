//! The common functions of an instance's life: the platform and version, debug logging,
//! instantiation and freeing, the experiment, initialisation, termination and reset.

use super::with_component;
use crate::firewall::firewall;
use crate::fmi2::component::{refuse, Component};
use crate::fmi2::handle;
use crate::fmi2::logger::Logger;
use crate::fmi2::machine::{Call, MachineState};
use crate::fmi2::model::{Instantiation, Model};
use crate::fmi2::types::*;
use crate::log::Category;
use crate::resource_location::file_uri_to_path;
use crate::Error;
use std::ffi::c_char;
use std::ptr;

/// `fmi2GetTypesPlatform`.
pub fn get_types_platform() -> *const c_char {
    c"default".as_ptr()
}

/// `fmi2GetVersion`.
pub fn get_version() -> *const c_char {
    c"2.0".as_ptr()
}

/// `fmi2SetDebugLogging`: no category names them all ([`crate::log`]).
pub unsafe fn set_debug_logging<M: Model>(
    c: fmi2Component,
    logging_on: fmi2Boolean,
    n_categories: usize,
    categories: *const fmi2String,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::SetDebugLogging, |component| {
            let pointers = handle::slice(categories, n_categories, "categories")?;
            let mut names = Vec::with_capacity(pointers.len());
            for &p in pointers {
                names.push(handle::text(p, "a category")?);
            }
            component.logger.set(logging_on != fmi2False, &names)
        })
    }
}

/// `fmi2Instantiate`: a co-simulation instance with a name, its resources folder (a local
/// `fmuResourceLocation`; else a warning and [`Model::WITHOUT_RESOURCES`]) and the model
/// [`Model::instantiate`] makes; NULL, with a log line, when any of them fails.
pub unsafe fn instantiate<M: Model>(
    instance_name: fmi2String,
    fmu_type: fmi2Type,
    fmu_guid: fmi2String,
    fmu_resource_location: fmi2String,
    functions: *const fmi2CallbackFunctions,
    logging_on: fmi2Boolean,
) -> fmi2Component {
    firewall(ptr::null_mut(), || {
        let callbacks = unsafe { handle::callbacks(functions) };
        let name = unsafe { handle::text(instance_name, "instanceName") };
        let logger = Logger::new(
            callbacks.and_then(|f| f.logger),
            callbacks.map_or(ptr::null_mut(), |f| f.componentEnvironment),
            // Messages about a missing name go out under the model identifier.
            name.as_ref()
                .ok()
                .filter(|n| !n.is_empty())
                .map_or(M::MODEL_IDENTIFIER, |n| n),
            logging_on != fmi2False,
        );
        let refused = |e: Error| {
            refuse(&logger, "fmi2Instantiate", &e);
            ptr::null_mut()
        };
        let name = match name {
            Ok(n) if !n.is_empty() => n,
            Ok(_) => return refused(Error::Argument("instanceName is empty".into())),
            Err(e) => return refused(e),
        };
        if fmu_type != fmi2Type::fmi2CoSimulation {
            return refused(Error::Argument(format!(
                "fmuType {} is not supported: {name} is a co-simulation FMU (fmi2CoSimulation = 1)",
                fmu_type.0
            )));
        }
        let resources = if fmu_resource_location.is_null() {
            None
        } else {
            let location = unsafe { handle::text(fmu_resource_location, "fmuResourceLocation") };
            let path = location.ok().and_then(file_uri_to_path);
            if path.is_none() {
                logger.log(
                    fmi2Status::fmi2Warning,
                    Category::StatusWarning,
                    &format!(
                        "fmi2Instantiate: fmuResourceLocation is not a local file URI; {}",
                        M::WITHOUT_RESOURCES
                    ),
                );
            }
            path
        };
        let guid = match unsafe { handle::text(fmu_guid, "fmuGUID") } {
            Ok(guid) => guid,
            Err(e) => return refused(e),
        };
        match M::instantiate(Instantiation {
            name,
            guid,
            resources,
        }) {
            Ok(model) => handle::into_component(Component::new(logger, model)),
            Err(e) => refused(e),
        }
    })
}

/// `fmi2FreeInstance` (NULL is ignored).
pub unsafe fn free_instance<M: Model>(c: fmi2Component) {
    if let Some(component) = unsafe { handle::take_component::<M>(c) } {
        firewall((), || drop(component));
    }
}

/// The state of an instance, for tests of the state machine (NULL: `None`).
pub unsafe fn machine_state<M: Model>(c: fmi2Component) -> Option<MachineState> {
    firewall(None, || {
        unsafe { handle::component::<M>(c) }.map(|component| component.state)
    })
}

/// `fmi2SetupExperiment` (the tolerance is not used).
pub unsafe fn setup_experiment<M: Model>(
    c: fmi2Component,
    start_time: fmi2Real,
    stop_time_defined: fmi2Boolean,
    stop_time: fmi2Real,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::SetupExperiment, |component| {
            let stop = (stop_time_defined != fmi2False).then_some(stop_time);
            component.model.setup_experiment(start_time, stop)
        })
    }
}

/// `fmi2EnterInitializationMode`.
pub unsafe fn enter_initialization_mode<M: Model>(c: fmi2Component) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::EnterInitializationMode, |component| {
            component.state = MachineState::InitializationMode;
            component.logger.event("entered initialization mode");
            Ok(())
        })
    }
}

/// `fmi2ExitInitializationMode`: [`Model::exit_initialization_mode`], then StepComplete.
pub unsafe fn exit_initialization_mode<M: Model>(c: fmi2Component) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::ExitInitializationMode, |component| {
            component.run(|model, cx| model.exit_initialization_mode(cx))?;
            component.state = MachineState::StepComplete;
            Ok(())
        })
    }
}

/// `fmi2Terminate`.
pub unsafe fn terminate<M: Model>(c: fmi2Component) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::Terminate, |component| {
            component.state = MachineState::Terminated;
            component.logger.event("terminated");
            Ok(())
        })
    }
}

/// `fmi2Reset`: a freshly instantiated instance; the name, callbacks, logging switches and
/// the model's resources stay.
pub unsafe fn reset<M: Model>(c: fmi2Component) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::Reset, |component| {
            component.model.reset();
            component.state = MachineState::Instantiated;
            component.logger.event("reset");
            Ok(())
        })
    }
}
