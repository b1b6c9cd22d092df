//! Every FMI 2.0 common and co-simulation function, as `extern "C"` symbols: thin shims that
//! call the function of the same name of the shared FMI layer
//! (`slowdrift_fmi::fmi2::functions`) with this FMU's model, [`Instance`]. The layer checks
//! the call against the state machine, turns the pointers into references, runs the model
//! behind its panic firewall and reports the result; this file has no logic of its own.
//!
//! # Safety
//!
//! The host must pass pointers as the FMI 2.0 standard describes: an `fmi2Component` that
//! `fmi2Instantiate` returned and that is not yet freed, arrays of at least the given
//! length, NUL-terminated strings, states from `fmi2GetFMUstate`/`fmi2DeSerializeFMUstate`
//! of this library. NULL pointers are detected and refused; dangling ones cannot be.

#![allow(unsafe_code)]
#![allow(non_snake_case)]
#![allow(clippy::missing_safety_doc)] // the module documentation above states the contract

use super::instance::Instance;
use slowdrift_fmi::fmi2::functions as fmi2;
use slowdrift_fmi::fmi2::machine::MachineState;
use slowdrift_fmi::fmi2::types::*;
use std::ffi::c_char;

// ---------------------------------------------------------------------------------------
// Common functions

#[no_mangle]
pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
    fmi2::get_types_platform()
}

#[no_mangle]
pub extern "C" fn fmi2GetVersion() -> *const c_char {
    fmi2::get_version()
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetDebugLogging(
    c: fmi2Component,
    loggingOn: fmi2Boolean,
    nCategories: usize,
    categories: *const fmi2String,
) -> fmi2Status {
    unsafe { fmi2::set_debug_logging::<Instance>(c, loggingOn, nCategories, categories) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2Instantiate(
    instanceName: fmi2String,
    fmuType: fmi2Type,
    fmuGUID: fmi2String,
    fmuResourceLocation: fmi2String,
    functions: *const fmi2CallbackFunctions,
    _visible: fmi2Boolean,
    loggingOn: fmi2Boolean,
) -> fmi2Component {
    unsafe {
        fmi2::instantiate::<Instance>(
            instanceName,
            fmuType,
            fmuGUID,
            fmuResourceLocation,
            functions,
            loggingOn,
        )
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2FreeInstance(c: fmi2Component) {
    unsafe { fmi2::free_instance::<Instance>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetupExperiment(
    c: fmi2Component,
    _toleranceDefined: fmi2Boolean,
    _tolerance: fmi2Real,
    startTime: fmi2Real,
    stopTimeDefined: fmi2Boolean,
    stopTime: fmi2Real,
) -> fmi2Status {
    unsafe { fmi2::setup_experiment::<Instance>(c, startTime, stopTimeDefined, stopTime) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2EnterInitializationMode(c: fmi2Component) -> fmi2Status {
    unsafe { fmi2::enter_initialization_mode::<Instance>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2ExitInitializationMode(c: fmi2Component) -> fmi2Status {
    unsafe { fmi2::exit_initialization_mode::<Instance>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2Terminate(c: fmi2Component) -> fmi2Status {
    unsafe { fmi2::terminate::<Instance>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2Reset(c: fmi2Component) -> fmi2Status {
    unsafe { fmi2::reset::<Instance>(c) }
}

// ---------------------------------------------------------------------------------------
// Getting and setting variables

#[no_mangle]
pub unsafe extern "C" fn fmi2GetReal(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Real,
) -> fmi2Status {
    unsafe { fmi2::get_real::<Instance>(c, vr, nvr, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetInteger(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Integer,
) -> fmi2Status {
    unsafe { fmi2::get_integer::<Instance>(c, vr, nvr, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetBoolean(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    unsafe { fmi2::get_boolean::<Instance>(c, vr, nvr, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetString(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2String,
) -> fmi2Status {
    unsafe { fmi2::get_string::<Instance>(c, vr, nvr, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetReal(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Real,
) -> fmi2Status {
    unsafe { fmi2::set_real::<Instance>(c, vr, nvr, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetInteger(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Integer,
) -> fmi2Status {
    unsafe { fmi2::set_integer::<Instance>(c, vr, nvr, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetBoolean(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Boolean,
) -> fmi2Status {
    unsafe { fmi2::set_boolean::<Instance>(c, vr, nvr, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetString(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2String,
) -> fmi2Status {
    unsafe { fmi2::set_string::<Instance>(c, vr, nvr, value) }
}

// ---------------------------------------------------------------------------------------
// FMU state

#[no_mangle]
pub unsafe extern "C" fn fmi2GetFMUstate(
    c: fmi2Component,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    unsafe { fmi2::get_fmu_state::<Instance>(c, FMUstate) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetFMUstate(c: fmi2Component, FMUstate: fmi2FMUstate) -> fmi2Status {
    unsafe { fmi2::set_fmu_state::<Instance>(c, FMUstate) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2FreeFMUstate(
    c: fmi2Component,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    unsafe { fmi2::free_fmu_state::<Instance>(c, FMUstate) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
    c: fmi2Component,
    FMUstate: fmi2FMUstate,
    size: *mut usize,
) -> fmi2Status {
    unsafe { fmi2::serialized_fmu_state_size::<Instance>(c, FMUstate, size) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SerializeFMUstate(
    c: fmi2Component,
    FMUstate: fmi2FMUstate,
    serializedState: *mut fmi2Byte,
    size: usize,
) -> fmi2Status {
    unsafe { fmi2::serialize_fmu_state::<Instance>(c, FMUstate, serializedState, size) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: fmi2Component,
    serializedState: *const fmi2Byte,
    size: usize,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    unsafe { fmi2::deserialize_fmu_state::<Instance>(c, serializedState, size, FMUstate) }
}

// ---------------------------------------------------------------------------------------
// Not supported (declared false in modelDescription.xml)

#[no_mangle]
pub unsafe extern "C" fn fmi2GetDirectionalDerivative(
    c: fmi2Component,
    _vUnknown_ref: *const fmi2ValueReference,
    _nUnknown: usize,
    _vKnown_ref: *const fmi2ValueReference,
    _nKnown: usize,
    _dvKnown: *const fmi2Real,
    _dvUnknown: *mut fmi2Real,
) -> fmi2Status {
    unsafe { fmi2::get_directional_derivative::<Instance>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetRealInputDerivatives(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    _nvr: usize,
    _order: *const fmi2Integer,
    _value: *const fmi2Real,
) -> fmi2Status {
    unsafe { fmi2::set_real_input_derivatives::<Instance>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    _nvr: usize,
    _order: *const fmi2Integer,
    _value: *mut fmi2Real,
) -> fmi2Status {
    unsafe { fmi2::get_real_output_derivatives::<Instance>(c) }
}

// ---------------------------------------------------------------------------------------
// Co-simulation

#[no_mangle]
pub unsafe extern "C" fn fmi2DoStep(
    c: fmi2Component,
    currentCommunicationPoint: fmi2Real,
    communicationStepSize: fmi2Real,
    _noSetFMUStatePriorToCurrentPoint: fmi2Boolean,
) -> fmi2Status {
    unsafe { fmi2::do_step::<Instance>(c, currentCommunicationPoint, communicationStepSize) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2CancelStep(c: fmi2Component) -> fmi2Status {
    unsafe { fmi2::cancel_step::<Instance>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetStatus(
    c: fmi2Component,
    _s: fmi2StatusKind,
    _value: *mut fmi2Status,
) -> fmi2Status {
    unsafe { fmi2::get_status::<Instance>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetRealStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Real,
) -> fmi2Status {
    unsafe { fmi2::get_real_status::<Instance>(c, s, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetIntegerStatus(
    c: fmi2Component,
    _s: fmi2StatusKind,
    _value: *mut fmi2Integer,
) -> fmi2Status {
    unsafe { fmi2::get_integer_status::<Instance>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetBooleanStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    unsafe { fmi2::get_boolean_status::<Instance>(c, s, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetStringStatus(
    c: fmi2Component,
    _s: fmi2StatusKind,
    _value: *mut fmi2String,
) -> fmi2Status {
    unsafe { fmi2::get_string_status::<Instance>(c) }
}

/// The state of an instance, for tests of the state machine (NULL: `None`).
///
/// # Safety
/// `c` is NULL or a live instance from [`fmi2Instantiate`].
pub unsafe fn instance_state(c: fmi2Component) -> Option<MachineState> {
    unsafe { fmi2::machine_state::<Instance>(c) }
}
