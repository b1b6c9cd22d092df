//! The functions the FMU does not provide: they exist (FMI 3.0 section 2.5: an FMU exports
//! every function; fmpy, for one, resolves them all at load) and answer `fmi3Error` saying
//! why, or, for the other interface types' instantiation, NULL with a log line.

use super::with_instance;
use crate::firewall::firewall;
use crate::fmi2::component::refuse;
use crate::fmi2::logger::Logger;
use crate::fmi2::model::Model;
use crate::fmi3::machine::Call;
use crate::fmi3::types::*;
use crate::Error;
use std::ptr;

/// Why each kind of function is missing, as the model description declares it.
pub mod why {
    pub const MODEL_EXCHANGE: &str =
        "this FMU is co-simulation only (no <ModelExchange> in its model description)";
    pub const SCHEDULED_EXECUTION: &str =
        "this FMU is co-simulation only (no <ScheduledExecution> in its model description)";
    pub const EVENT_MODE: &str = "hasEventMode=\"false\": the FMU has no event mode";
    pub const DEPENDENCIES: &str =
        "providesPerElementDependencies=\"false\": the ModelStructure gives the dependencies";
    pub const DERIVATIVES: &str =
        "providesDirectionalDerivatives and providesAdjointDerivatives are false";
    pub const CONFIGURATION: &str = "the FMU has no structural parameter";
    pub const CLOCKS: &str = "the FMU has no clock";
    pub const STATES: &str = "canGetAndSetFMUState=\"false\": this FMU's states cannot be saved";
    pub const OUTPUT_DERIVATIVES: &str =
        "maxOutputDerivativeOrder=\"0\": no output derivative is computed";
}

/// A function that takes an instance and that the FMU does not provide: `fmi3Error` (after
/// the NULL and panic checks) and why.
pub unsafe fn unsupported<M: Model>(
    instance: fmi3Instance,
    name: &'static str,
    why: &'static str,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::Unsupported(name), |_| {
            Err(Error::Unsupported(why))
        })
    }
}

/// A getter or setter of a type the FMU has no variable of: nothing to do for no value
/// reference, else `fmi3Error` (every value reference is unknown).
pub unsafe fn no_variable_of_type<M: Model>(
    instance: fmi3Instance,
    name: &'static str,
    nvr: usize,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::Unsupported(name), |_| {
            if nvr == 0 {
                Ok(())
            } else {
                Err(Error::Argument(format!(
                    "{nvr} value references: this FMU has no variable of the type of {name}"
                )))
            }
        })
    }
}

/// `fmi3InstantiateModelExchange` and `fmi3InstantiateScheduledExecution`: NULL, with the
/// reason logged to the host's `logMessage`.
pub fn refuse_instantiation<M: Model>(
    name: &'static str,
    why: &'static str,
    instance_environment: fmi3InstanceEnvironment,
    log_message: Option<fmi3LogMessageCallback>,
) -> fmi3Instance {
    firewall(ptr::null_mut(), || {
        let logger = Logger::fmi3(log_message, instance_environment, M::MODEL_IDENTIFIER, true);
        refuse(&logger, name, &Error::Unsupported(why));
        ptr::null_mut()
    })
}
