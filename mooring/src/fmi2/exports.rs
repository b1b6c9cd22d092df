//! The 34 FMI 2.0 common and co-simulation functions of the mooring FMU.
//!
//! Every body runs inside `catch_unwind`: a panic becomes `fmi2Error` (NULL from
//! `fmi2Instantiate`) and a log line, never an unwind into the host. A call out of sequence
//! (the state table of `machine.rs`), a NULL array, an unknown value reference or a
//! non-finite input is refused with `fmi2Error` and a log line, and the instance then
//! accepts only `fmi2Reset`, `fmi2FreeInstance`, getters and logging calls. FMU states,
//! directional derivatives, input derivatives and asynchronous steps are not provided:
//! those functions exist (masters resolve all of them) and answer `fmi2Error` saying so.
//!
//! # Safety
//!
//! The host passes pointers as FMI 2.0 describes: an `fmi2Component` from `fmi2Instantiate`
//! not yet freed, arrays of at least the given length, NUL-terminated strings. NULL pointers
//! are detected and refused; dangling ones cannot be.

#![allow(unsafe_code)]
#![allow(non_snake_case)]
#![allow(clippy::missing_safety_doc)] // the module documentation states the contract

use super::instance::Instance;
use super::logger::Logger;
use super::machine::Call;
use super::types::*;
use super::variables::{GUID, LOG_CATEGORIES};
use crate::moordyn::{this_library_dir, Library, LIBRARY_FILE};
use std::ffi::{c_char, CStr};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;

/// The text of a panic payload.
fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".into())
}

/// NULL check, state check, the work; an error (or a panic) is logged and puts the
/// instance in the Error state.
unsafe fn with_instance(
    c: fmi2Component,
    call: Call,
    body: impl FnOnce(&mut Instance) -> Result<(), String>,
) -> fmi2Status {
    // SAFETY: a non-NULL component is a live instance from fmi2Instantiate (module docs).
    let Some(instance) = (unsafe { c.cast::<Instance>().as_mut() }) else {
        return fmi2Status::fmi2Error;
    };
    let result = catch_unwind(AssertUnwindSafe(|| {
        instance.logger.call(&call.name());
        instance.check(call)?;
        body(instance)
    }))
    .unwrap_or_else(|payload| Err(format!("panic: {}", panic_text(payload.as_ref()))));
    match result {
        Ok(()) => fmi2Status::fmi2OK,
        Err(message) => {
            let _ = catch_unwind(AssertUnwindSafe(|| {
                instance
                    .logger
                    .error(&format!("{}: {message}", call.name()));
                // Getters and refused calls out of sequence leave a usable instance as it was.
                if !matches!(
                    call,
                    Call::GetReal | Call::GetString | Call::GetInteger | Call::GetBoolean
                ) && !message.starts_with("illegal call sequence")
                {
                    instance.fail();
                }
            }));
            fmi2Status::fmi2Error
        }
    }
}

/// `(pointer, n)` as a slice: NULL is fine only when n = 0.
unsafe fn slice<'a, T>(p: *const T, n: usize, what: &str) -> Result<&'a [T], String> {
    if n == 0 {
        Ok(&[])
    } else if p.is_null() || !p.is_aligned() {
        Err(format!(
            "{what} is NULL or misaligned but its length is {n}"
        ))
    } else {
        // SAFETY: non-NULL and aligned; the host promises n elements (module docs).
        Ok(unsafe { std::slice::from_raw_parts(p, n) })
    }
}

/// `(pointer, n)` as a mutable slice: NULL is fine only when n = 0.
unsafe fn slice_mut<'a, T>(p: *mut T, n: usize, what: &str) -> Result<&'a mut [T], String> {
    if n == 0 {
        Ok(&mut [])
    } else if p.is_null() || !p.is_aligned() {
        Err(format!(
            "{what} is NULL or misaligned but its length is {n}"
        ))
    } else {
        // SAFETY: non-NULL and aligned; the host promises n elements (module docs).
        Ok(unsafe { std::slice::from_raw_parts_mut(p, n) })
    }
}

/// A C string argument as UTF-8 text; NULL is an error.
unsafe fn text<'a>(s: fmi2String, what: &str) -> Result<&'a str, String> {
    if s.is_null() {
        return Err(format!("{what} is NULL"));
    }
    // SAFETY: non-NULL and NUL-terminated (module docs).
    unsafe { CStr::from_ptr(s) }
        .to_str()
        .map_err(|_| format!("{what} is not UTF-8"))
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
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, Call::SetDebugLogging, |inst| {
            let names = slice(categories, nCategories, "categories")?;
            let mut all = names.is_empty();
            for &name in names {
                let name = text(name, "a category")?;
                if !LOG_CATEGORIES.contains(&name) {
                    return Err(format!(
                        "unknown log category {name:?} (this FMU has {})",
                        LOG_CATEGORIES.join(", ")
                    ));
                }
                all |= name == "logAll";
            }
            if all {
                inst.logger.log_all = loggingOn != fmi2False;
            }
            Ok(())
        })
    }
}

/// The FMU's `resources` folder: `<unpacked FMU>/resources`, two levels above this library
/// (`binaries/linux64/Mooring.so`), where every master unpacks it.
fn resources_beside(library_dir: &std::path::Path) -> Option<PathBuf> {
    Some(library_dir.parent()?.parent()?.join("resources"))
}

#[no_mangle]
pub unsafe extern "C" fn fmi2Instantiate(
    instanceName: fmi2String,
    fmuType: fmi2Type,
    fmuGUID: fmi2String,
    _fmuResourceLocation: fmi2String,
    functions: *const fmi2CallbackFunctions,
    _visible: fmi2Boolean,
    loggingOn: fmi2Boolean,
) -> fmi2Component {
    catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: a NULL pointer is checked; else the host's struct (module docs).
        let callbacks = unsafe { functions.as_ref() }.copied();
        let (logger_fn, environment) = callbacks
            .map(|f| (f.logger, f.componentEnvironment))
            .unwrap_or((None, std::ptr::null_mut()));
        // SAFETY: see text.
        let name = unsafe { text(instanceName, "instanceName") }.unwrap_or("");
        let logger = Logger::new(logger_fn, environment, name, loggingOn != fmi2False);
        let refuse = |why: String| {
            logger.error(&format!("fmi2Instantiate: {why}"));
            std::ptr::null_mut()
        };
        if name.is_empty() {
            return refuse("instanceName is NULL or empty".into());
        }
        if fmuType != fmi2Type::fmi2CoSimulation {
            return refuse("this FMU supports co-simulation only".into());
        }
        // SAFETY: see text.
        match unsafe { text(fmuGUID, "fmuGUID") } {
            Ok(guid) if guid == GUID => {}
            Ok(guid) => return refuse(format!("fmuGUID {guid} is not this FMU's {GUID}")),
            Err(e) => return refuse(e),
        }
        let located = this_library_dir().and_then(|dir| {
            let library = Library::load(&dir.join(LIBRARY_FILE))?;
            let resources = resources_beside(&dir)
                .ok_or_else(|| format!("{} has no resources folder above it", dir.display()))?;
            Ok((library, resources))
        });
        match located {
            Ok((library, resources)) => {
                Box::into_raw(Box::new(Instance::new(logger, library, resources))).cast()
            }
            Err(e) => refuse(e),
        }
    }))
    .unwrap_or(std::ptr::null_mut())
}

#[no_mangle]
pub unsafe extern "C" fn fmi2FreeInstance(c: fmi2Component) {
    if !c.is_null() {
        // SAFETY: a live instance from fmi2Instantiate, freed once (module docs).
        let instance = unsafe { Box::from_raw(c.cast::<Instance>()) };
        let _ = catch_unwind(AssertUnwindSafe(move || drop(instance)));
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetupExperiment(
    c: fmi2Component,
    _toleranceDefined: fmi2Boolean,
    _tolerance: fmi2Real,
    startTime: fmi2Real,
    _stopTimeDefined: fmi2Boolean,
    _stopTime: fmi2Real,
) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, Call::SetupExperiment, |inst| {
            inst.setup_experiment(startTime)
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2EnterInitializationMode(c: fmi2Component) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, Call::EnterInitializationMode, |inst| {
            inst.enter_initialization_mode();
            Ok(())
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2ExitInitializationMode(c: fmi2Component) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe {
        with_instance(
            c,
            Call::ExitInitializationMode,
            Instance::exit_initialization_mode,
        )
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2Terminate(c: fmi2Component) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, Call::Terminate, |inst| {
            inst.terminate();
            Ok(())
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2Reset(c: fmi2Component) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, Call::Reset, |inst| {
            inst.reset();
            Ok(())
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetReal(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Real,
) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, Call::GetReal, |inst| {
            let vr = slice(vr, nvr, "vr")?;
            let value = slice_mut(value, nvr, "value")?;
            for (v, out) in vr.iter().zip(value) {
                *out = inst.get_real(*v)?;
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
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, Call::SetReal, |inst| {
            let vr = slice(vr, nvr, "vr")?;
            let value = slice(value, nvr, "value")?;
            vr.iter()
                .zip(value)
                .try_for_each(|(v, x)| inst.set_real(*v, *x))
        })
    }
}

/// This FMU has no Boolean variable: any value reference is unknown.
unsafe fn no_variable(c: fmi2Component, call: Call, nvr: usize, kind: &str) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, call, |_| {
            if nvr == 0 {
                Ok(())
            } else {
                Err(format!("this FMU has no {kind} variable"))
            }
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
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, Call::GetInteger, |inst| {
            let vr = slice(vr, nvr, "vr")?;
            let value = slice_mut(value, nvr, "value")?;
            for (v, out) in vr.iter().zip(value) {
                *out = inst.get_integer(*v)?;
            }
            Ok(())
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
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, Call::SetInteger, |inst| {
            let vr = slice(vr, nvr, "vr")?;
            let value = slice(value, nvr, "value")?;
            vr.iter()
                .zip(value)
                .try_for_each(|(v, x)| inst.set_integer(*v, *x))
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetBoolean(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    nvr: usize,
    _value: *mut fmi2Boolean,
) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe { no_variable(c, Call::GetBoolean, nvr, "Boolean") }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetBoolean(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    nvr: usize,
    _value: *const fmi2Boolean,
) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe { no_variable(c, Call::SetBoolean, nvr, "Boolean") }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetString(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2String,
) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, Call::GetString, |inst| {
            let vr = slice(vr, nvr, "vr")?;
            let value = slice_mut(value, nvr, "value")?;
            for (v, out) in vr.iter().zip(value) {
                // The string lives in the instance until its next call.
                *out = inst.get_string(*v)?;
            }
            Ok(())
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
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, Call::SetString, |inst| {
            let vr = slice(vr, nvr, "vr")?;
            let value = slice(value, nvr, "value")?;
            for (v, s) in vr.iter().zip(value) {
                inst.set_string(*v, text(*s, "value")?)?;
            }
            Ok(())
        })
    }
}

/// A function this FMU does not provide: `fmi2Error` and the reason.
unsafe fn unsupported(c: fmi2Component, call: Call, why: &str) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe { with_instance(c, call, |_| Err(format!("not supported: {why}"))) }
}

const NO_STATES: &str = "canGetAndSetFMUstate and canSerializeFMUstate are false";

#[no_mangle]
pub unsafe extern "C" fn fmi2GetFMUstate(c: fmi2Component, _s: *mut fmi2FMUstate) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe { unsupported(c, Call::GetFMUstate, NO_STATES) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetFMUstate(c: fmi2Component, _s: fmi2FMUstate) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe { unsupported(c, Call::SetFMUstate, NO_STATES) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2FreeFMUstate(c: fmi2Component, _s: *mut fmi2FMUstate) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe { unsupported(c, Call::FreeFMUstate, NO_STATES) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
    c: fmi2Component,
    _s: fmi2FMUstate,
    _size: *mut usize,
) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe { unsupported(c, Call::SerializedFMUstateSize, NO_STATES) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SerializeFMUstate(
    c: fmi2Component,
    _s: fmi2FMUstate,
    _bytes: *mut fmi2Byte,
    _size: usize,
) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe { unsupported(c, Call::SerializeFMUstate, NO_STATES) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: fmi2Component,
    _bytes: *const fmi2Byte,
    _size: usize,
    _s: *mut fmi2FMUstate,
) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe { unsupported(c, Call::DeSerializeFMUstate, NO_STATES) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetDirectionalDerivative(
    c: fmi2Component,
    _vu: *const fmi2ValueReference,
    _nu: usize,
    _vk: *const fmi2ValueReference,
    _nk: usize,
    _dvk: *const fmi2Real,
    _dvu: *mut fmi2Real,
) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe {
        unsupported(
            c,
            Call::GetDirectionalDerivative,
            "providesDirectionalDerivative is false",
        )
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
    // SAFETY: see the module docs.
    unsafe {
        unsupported(
            c,
            Call::SetRealInputDerivatives,
            "canInterpolateInputs is false",
        )
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
    // SAFETY: see the module docs.
    unsafe {
        unsupported(
            c,
            Call::GetRealOutputDerivatives,
            "maxOutputDerivativeOrder is 0",
        )
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2DoStep(
    c: fmi2Component,
    currentCommunicationPoint: fmi2Real,
    communicationStepSize: fmi2Real,
    _noSetFMUStatePriorToCurrentPoint: fmi2Boolean,
) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, Call::DoStep, |inst| {
            inst.do_step(currentCommunicationPoint, communicationStepSize)
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2CancelStep(c: fmi2Component) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe { unsupported(c, Call::CancelStep, "steps are never asynchronous") }
}

/// A status query this FMU has no answer for (steps are never asynchronous).
unsafe fn no_status(c: fmi2Component, call: Call) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe { unsupported(c, call, "steps are never asynchronous") }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetStatus(
    c: fmi2Component,
    _s: fmi2StatusKind,
    _value: *mut fmi2Status,
) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe { no_status(c, Call::GetStatus) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetRealStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Real,
) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, Call::GetRealStatus, |inst| {
            if s != fmi2StatusKind::fmi2LastSuccessfulTime {
                return Err(format!("no Real status of kind {}", s.0));
            }
            let out = slice_mut(value, 1, "value")?;
            out[0] = inst.time();
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
    // SAFETY: see the module docs.
    unsafe { no_status(c, Call::GetIntegerStatus) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetBooleanStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    // SAFETY: see the module docs.
    unsafe {
        with_instance(c, Call::GetBooleanStatus, |_| {
            if s != fmi2StatusKind::fmi2Terminated {
                return Err(format!("no Boolean status of kind {}", s.0));
            }
            // The FMU never ends a run itself.
            slice_mut(value, 1, "value")?[0] = fmi2False;
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
    // SAFETY: see the module docs.
    unsafe { no_status(c, Call::GetStringStatus) }
}
