//! Every FMI 2.0 common and co-simulation function, as `extern "C"` symbols.
//!
//! Each body runs inside `firewall` (`catch_unwind`): a panic becomes `fmi2Error` (NULL
//! from `fmi2Instantiate`) and a log line, never an unwind into the host. Pointers become
//! references and slices here, checked (`slice`, `slice_mut`, `out`); the work is done
//! by the safe `Instance`. Functions this FMU does not support exist (masters resolve all
//! of them at load time) and answer `fmi2Error` with the reason.
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

use super::fmu_error::FmuError;
use super::instance::Instance;
use super::logger::Logger;
use super::machine::{Call, MachineState};
use super::parameters::file_uri_to_path;
use super::resources::{holds_configuration_of, RESOURCE_CONFIG};
use super::state::FmuState;
use super::types::*;
use crate::fmi2::model_description::{log_category, GUID, MODEL_IDENTIFIER};
use std::ffi::{c_char, CStr};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::ptr;

/// Runs `f`, turning a panic into `fallback`.
fn firewall<R>(fallback: R, f: impl FnOnce() -> R) -> R {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or(fallback)
}

/// The text of a panic payload.
fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    crate::error::panic_message(payload).unwrap_or_else(|| "unknown panic".into())
}

/// The body of every function that takes an instance: NULL check, state check, the work,
/// then [`Instance::report`]; a panic anywhere is reported as an error.
unsafe fn with_instance(
    c: fmi2Component,
    call: Call,
    body: impl FnOnce(&mut Instance) -> Result<(), FmuError>,
) -> fmi2Status {
    // SAFETY: a non-NULL component is a live instance from fmi2Instantiate (module docs).
    let Some(instance) = (unsafe { c.cast::<Instance>().as_mut() }) else {
        return fmi2Status::fmi2Error;
    };
    firewall(fmi2Status::fmi2Error, || {
        let result = catch_unwind(AssertUnwindSafe(|| {
            instance.check(call)?;
            body(instance)
        }))
        .unwrap_or_else(|payload| Err(FmuError::Panic(panic_text(payload.as_ref()))));
        instance.report(call, result)
    })
}

/// `(pointer, n)` as a slice: NULL is fine only when n = 0.
unsafe fn slice<'a, T>(p: *const T, n: usize, what: &str) -> Result<&'a [T], FmuError> {
    if n == 0 {
        Ok(&[])
    } else if p.is_null() || !p.is_aligned() {
        Err(FmuError::Argument(format!(
            "{what} is NULL or misaligned but its length is {n}"
        )))
    } else {
        // SAFETY: non-NULL and aligned; the host promises n elements (module docs).
        Ok(unsafe { std::slice::from_raw_parts(p, n) })
    }
}

/// `(pointer, n)` as a mutable slice: NULL is fine only when n = 0.
unsafe fn slice_mut<'a, T>(p: *mut T, n: usize, what: &str) -> Result<&'a mut [T], FmuError> {
    if n == 0 {
        Ok(&mut [])
    } else if p.is_null() || !p.is_aligned() {
        Err(FmuError::Argument(format!(
            "{what} is NULL or misaligned but its length is {n}"
        )))
    } else {
        // SAFETY: non-NULL and aligned; the host promises n elements (module docs).
        Ok(unsafe { std::slice::from_raw_parts_mut(p, n) })
    }
}

/// An output argument as a reference.
unsafe fn out<'a, T>(p: *mut T, what: &str) -> Result<&'a mut T, FmuError> {
    if !p.is_aligned() {
        return Err(FmuError::Argument(format!("{what} is misaligned")));
    }
    // SAFETY: aligned; non-NULL checked by as_mut; the host owns the memory.
    unsafe { p.as_mut() }.ok_or_else(|| FmuError::Argument(format!("{what} is NULL")))
}

/// A C string argument as UTF-8 text; NULL is an error.
unsafe fn text<'a>(s: fmi2String, what: &str) -> Result<&'a str, FmuError> {
    if s.is_null() {
        return Err(FmuError::Argument(format!("{what} is NULL")));
    }
    // SAFETY: non-NULL and NUL-terminated (module docs).
    unsafe { CStr::from_ptr(s) }
        .to_str()
        .map_err(|_| FmuError::Argument(format!("{what} is not UTF-8")))
}

/// A saved state argument.
unsafe fn fmu_state<'a>(s: fmi2FMUstate) -> Result<&'a FmuState, FmuError> {
    // SAFETY: a non-NULL state came from fmi2GetFMUstate/fmi2DeSerializeFMUstate (module docs).
    unsafe { s.cast::<FmuState>().as_ref() }
        .ok_or_else(|| FmuError::Argument("FMUstate is NULL".into()))
}

/// Hands a saved state to the host.
fn into_handle(state: FmuState) -> fmi2FMUstate {
    Box::into_raw(Box::new(state)).cast()
}

unsafe fn value_references<'a>(
    vr: *const fmi2ValueReference,
    nvr: usize,
) -> Result<&'a [u32], FmuError> {
    // SAFETY: see slice.
    unsafe { slice(vr, nvr, "vr") }
}

// ---------------------------------------------------------------------------------------
// Common functions

#[no_mangle]
pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
    c"default".as_ptr()
}

#[no_mangle]
pub extern "C" fn fmi2GetVersion() -> *const c_char {
    c"2.0".as_ptr()
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetDebugLogging(
    c: fmi2Component,
    loggingOn: fmi2Boolean,
    nCategories: usize,
    categories: *const fmi2String,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::SetDebugLogging, |inst| {
            let pointers = slice(categories, nCategories, "categories")?;
            let mut names = Vec::with_capacity(pointers.len());
            for &p in pointers {
                names.push(text(p, "a category")?);
            }
            inst.logger.set(loggingOn != fmi2False, &names)
        })
    }
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
    firewall(ptr::null_mut(), || {
        // SAFETY: the callbacks struct, when given, is valid for this call (module docs).
        let callbacks = unsafe { functions.as_ref() }.copied();
        let name = unsafe { text(instanceName, "instanceName") };
        let logger = Logger::new(
            callbacks.and_then(|f| f.logger),
            callbacks.map_or(ptr::null_mut(), |f| f.componentEnvironment),
            // Messages about a missing name go out under the model identifier.
            name.as_ref()
                .ok()
                .filter(|n| !n.is_empty())
                .map_or(MODEL_IDENTIFIER, |n| n),
            loggingOn != fmi2False,
        );
        let refuse = |message: String| {
            logger.log(
                fmi2Status::fmi2Error,
                log_category::LOG_STATUS_ERROR,
                &format!("fmi2Instantiate: {message}"),
            );
            ptr::null_mut()
        };
        let name = match name {
            Ok(n) if !n.is_empty() => n,
            Ok(_) => return refuse("instanceName is empty".into()),
            Err(e) => return refuse(e.to_string()),
        };
        if fmuType != fmi2Type::fmi2CoSimulation {
            return refuse(format!(
                "fmuType {} is not supported: {name} is a co-simulation FMU (fmi2CoSimulation = 1)",
                fmuType.0
            ));
        }
        let resources = if fmuResourceLocation.is_null() {
            None
        } else {
            let location = unsafe { text(fmuResourceLocation, "fmuResourceLocation") };
            match location.ok().and_then(file_uri_to_path) {
                Some(path) => Some(path),
                None => {
                    logger.log(
                        fmi2Status::fmi2Warning,
                        log_category::LOG_STATUS_WARNING,
                        "fmi2Instantiate: fmuResourceLocation is not a local file URI; \
                         the embedded default platform is the default configuration",
                    );
                    None
                }
            }
        };
        // This binary's GUID, or that of a user's configuration packed in the resources
        // (`fmu-pack --config`: its modelDescription.xml carries that configuration's start
        // values, and a GUID of its own).
        match unsafe { text(fmuGUID, "fmuGUID") } {
            Ok(guid) if guid == GUID => {}
            Ok(guid)
                if resources
                    .as_deref()
                    .is_some_and(|r| holds_configuration_of(r, guid)) => {}
            Ok(guid) => {
                return refuse(format!(
                    "fmuGUID {guid:?} is neither this binary's {GUID:?} nor that of the \
                     configuration in the FMU's resources: the modelDescription.xml does not \
                     belong to this FMU (was resources/{RESOURCE_CONFIG} changed after \
                     fmu-pack packed it? pack it again)"
                ))
            }
            Err(e) => return refuse(e.to_string()),
        }
        let instance = Instance::new(logger, resources);
        Box::into_raw(Box::new(instance)).cast()
    })
}

#[no_mangle]
pub unsafe extern "C" fn fmi2FreeInstance(c: fmi2Component) {
    if c.is_null() {
        return;
    }
    // SAFETY: a live instance from fmi2Instantiate, freed once (module docs).
    let instance = unsafe { Box::from_raw(c.cast::<Instance>()) };
    firewall((), || drop(instance));
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
    unsafe {
        with_instance(c, Call::SetupExperiment, |inst| {
            inst.setup_experiment(
                startTime,
                (stopTimeDefined != fmi2False).then_some(stopTime),
            )
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2EnterInitializationMode(c: fmi2Component) -> fmi2Status {
    unsafe {
        with_instance(c, Call::EnterInitializationMode, |inst| {
            inst.enter_initialization_mode()
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2ExitInitializationMode(c: fmi2Component) -> fmi2Status {
    unsafe {
        with_instance(c, Call::ExitInitializationMode, |inst| {
            inst.exit_initialization_mode()
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2Terminate(c: fmi2Component) -> fmi2Status {
    unsafe { with_instance(c, Call::Terminate, |inst| inst.terminate()) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2Reset(c: fmi2Component) -> fmi2Status {
    unsafe { with_instance(c, Call::Reset, |inst| inst.reset()) }
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
    unsafe {
        with_instance(c, Call::GetReal, |inst| {
            let vrs = value_references(vr, nvr)?;
            inst.get_real(vrs, slice_mut(value, nvr, "value")?)
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetInteger(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Integer,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::GetInteger, |inst| {
            let vrs = value_references(vr, nvr)?;
            inst.get_integer(vrs, slice_mut(value, nvr, "value")?)
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetBoolean(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::GetBoolean, |inst| {
            let vrs = value_references(vr, nvr)?;
            slice_mut(value, nvr, "value")?;
            inst.boolean(vrs)
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetString(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2String,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::GetString, |inst| {
            let vrs = value_references(vr, nvr)?;
            let values = slice_mut(value, nvr, "value")?;
            let strings = inst.get_string(vrs)?;
            for (v, s) in values.iter_mut().zip(strings) {
                *v = s.as_ptr();
            }
            Ok(())
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetReal(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Real,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::SetReal, |inst| {
            let vrs = value_references(vr, nvr)?;
            inst.set_real(vrs, slice(value, nvr, "value")?)
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetInteger(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Integer,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::SetInteger, |inst| {
            let vrs = value_references(vr, nvr)?;
            inst.set_integer(vrs, slice(value, nvr, "value")?)
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetBoolean(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Boolean,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::SetBoolean, |inst| {
            let vrs = value_references(vr, nvr)?;
            slice(value, nvr, "value")?;
            inst.boolean(vrs)
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetString(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2String,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::SetString, |inst| {
            let vrs = value_references(vr, nvr)?;
            let mut texts = Vec::with_capacity(nvr);
            for &s in slice(value, nvr, "value")? {
                texts.push(text(s, "a String value")?);
            }
            inst.set_string(vrs, &texts)
        })
    }
}

// ---------------------------------------------------------------------------------------
// FMU state

/// `fmi2GetFMUstate` always hands out a new state (like the Reference FMUs): a non-NULL
/// `*FMUstate` on entry is not reused, because a host may pass an uninitialised variable.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetFMUstate(
    c: fmi2Component,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::GetFMUstate, |inst| {
            let target = out(FMUstate, "FMUstate")?;
            *target = into_handle(inst.get_fmu_state()?);
            Ok(())
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetFMUstate(c: fmi2Component, FMUstate: fmi2FMUstate) -> fmi2Status {
    unsafe {
        with_instance(c, Call::SetFMUstate, |inst| {
            inst.set_fmu_state(fmu_state(FMUstate)?)
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2FreeFMUstate(
    c: fmi2Component,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::FreeFMUstate, |_| {
            let handle = out(FMUstate, "FMUstate")?;
            if !handle.is_null() {
                // SAFETY: a state from this library, freed once (module docs).
                drop(Box::from_raw(handle.cast::<FmuState>()));
                *handle = ptr::null_mut();
            }
            Ok(())
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
    c: fmi2Component,
    FMUstate: fmi2FMUstate,
    size: *mut usize,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::SerializedFMUstateSize, |_| {
            *out(size, "size")? = fmu_state(FMUstate)?.byte_len();
            Ok(())
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SerializeFMUstate(
    c: fmi2Component,
    FMUstate: fmi2FMUstate,
    serializedState: *mut fmi2Byte,
    size: usize,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::SerializeFMUstate, |_| {
            let bytes = fmu_state(FMUstate)?.to_bytes()?;
            if size < bytes.len() {
                return Err(FmuError::Argument(format!(
                    "size = {size} is smaller than the state's {} bytes \
                     (fmi2SerializedFMUstateSize)",
                    bytes.len()
                )));
            }
            let target = slice_mut(serializedState.cast::<u8>(), bytes.len(), "serializedState")?;
            target.copy_from_slice(&bytes);
            Ok(())
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: fmi2Component,
    serializedState: *const fmi2Byte,
    size: usize,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::DeSerializeFMUstate, |inst| {
            let bytes = slice(serializedState.cast::<u8>(), size, "serializedState")?;
            let target = out(FMUstate, "FMUstate")?;
            *target = into_handle(inst.deserialize(bytes)?);
            Ok(())
        })
    }
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
    unsafe {
        with_instance(c, Call::GetDirectionalDerivative, |_| {
            Err(FmuError::Unsupported(
                "providesDirectionalDerivative=\"false\": no Jacobian is computed",
            ))
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetRealInputDerivatives(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    _nvr: usize,
    _order: *const fmi2Integer,
    _value: *const fmi2Real,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::SetRealInputDerivatives, |_| {
            Err(FmuError::Unsupported(
                "canInterpolateInputs=\"false\": inputs are held constant over a step",
            ))
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    _nvr: usize,
    _order: *const fmi2Integer,
    _value: *mut fmi2Real,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::GetRealOutputDerivatives, |_| {
            Err(FmuError::Unsupported(
                "maxOutputDerivativeOrder=\"0\": no output derivatives",
            ))
        })
    }
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
    unsafe {
        with_instance(c, Call::DoStep, |inst| {
            inst.do_step(currentCommunicationPoint, communicationStepSize)
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2CancelStep(c: fmi2Component) -> fmi2Status {
    unsafe {
        with_instance(c, Call::CancelStep, |_| {
            Err(FmuError::Unsupported(
                "steps are never asynchronous (fmi2DoStep never returns fmi2Pending)",
            ))
        })
    }
}

const NO_PENDING: &str = "steps are never asynchronous, so there is no pending status";

#[no_mangle]
pub unsafe extern "C" fn fmi2GetStatus(
    c: fmi2Component,
    _s: fmi2StatusKind,
    _value: *mut fmi2Status,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::GetStatus, |_| {
            Err(FmuError::StatusUnavailable(NO_PENDING.into()))
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetRealStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Real,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::GetRealStatus, |inst| {
            let answer = inst.real_status(s == fmi2StatusKind::fmi2LastSuccessfulTime)?;
            *out(value, "value")? = answer;
            Ok(())
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetIntegerStatus(
    c: fmi2Component,
    _s: fmi2StatusKind,
    _value: *mut fmi2Integer,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::GetIntegerStatus, |_| {
            Err(FmuError::StatusUnavailable(
                "FMI 2.0 defines no Integer status".into(),
            ))
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetBooleanStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::GetBooleanStatus, |inst| {
            let answer = inst.boolean_status(s == fmi2StatusKind::fmi2Terminated)?;
            *out(value, "value")? = if answer { fmi2True } else { fmi2False };
            Ok(())
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetStringStatus(
    c: fmi2Component,
    _s: fmi2StatusKind,
    _value: *mut fmi2String,
) -> fmi2Status {
    unsafe {
        with_instance(c, Call::GetStringStatus, |_| {
            Err(FmuError::StatusUnavailable(NO_PENDING.into()))
        })
    }
}

/// The state of an instance, for tests of the state machine (NULL: `None`).
///
/// # Safety
/// `c` is NULL or a live instance from [`fmi2Instantiate`].
pub unsafe fn instance_state(c: fmi2Component) -> Option<MachineState> {
    firewall(None, || {
        unsafe { c.cast::<Instance>().as_ref() }.map(Instance::state)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::ffi::c_void;
    use std::sync::Mutex;

    /// Records messages into the `Mutex<Vec<String>>` behind `env` (five fixed arguments:
    /// the FMU passes no variadic ones, see `Logger::log`).
    unsafe extern "C" fn record(
        env: *mut c_void,
        _name: fmi2String,
        _status: fmi2Status,
        _category: fmi2String,
        message: fmi2String,
    ) {
        let log = unsafe { &*(env as *const Mutex<Vec<String>>) };
        let text = unsafe { CStr::from_ptr(message) }.to_string_lossy();
        log.lock().unwrap().push(text.into_owned());
    }

    #[test]
    fn a_panic_becomes_an_error_and_a_log_line() {
        type Fixed =
            unsafe extern "C" fn(*mut c_void, fmi2String, fmi2Status, fmi2String, fmi2String);
        let log = Mutex::new(Vec::<String>::new());
        let functions = fmi2CallbackFunctions {
            // SAFETY: a call with the five fixed arguments only has the same ABI.
            logger: Some(unsafe { std::mem::transmute::<Fixed, fmi2CallbackLogger>(record) }),
            allocateMemory: None,
            freeMemory: None,
            stepFinished: None,
            componentEnvironment: &log as *const _ as *mut c_void,
        };
        let guid = std::ffi::CString::new(GUID).unwrap();
        let c = unsafe {
            fmi2Instantiate(
                c"p".as_ptr(),
                fmi2Type::fmi2CoSimulation,
                guid.as_ptr(),
                ptr::null(),
                &functions,
                fmi2False,
                fmi2False,
            )
        };
        assert!(!c.is_null());
        let status = unsafe { with_instance(c, Call::Reset, |_| panic!("boom 100%")) };
        assert_eq!(status, fmi2Status::fmi2Error);
        assert_eq!(unsafe { instance_state(c) }, Some(MachineState::Error));
        let messages = log.lock().unwrap().clone();
        assert_eq!(
            messages,
            ["fmi2Reset: internal error (panic caught): boom 100%%"]
        );
        // The instance is still usable after a reset.
        assert_eq!(unsafe { fmi2Reset(c) }, fmi2Status::fmi2OK);
        unsafe { fmi2FreeInstance(c) };
    }
}
