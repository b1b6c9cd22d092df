//! The FMI 2.0 C types, written by hand from the standard's `fmi2TypesPlatform.h` and
//! `fmi2FunctionTypes.h` (FMI 2.0.4, sections 2.1.2 and 2.1.3). Names follow the headers so
//! that the exported signatures read like the standard.
//!
//! The enums the host passes in (`fmi2Type`, `fmi2StatusKind`) are plain `c_int` wrappers
//! with named constants, not Rust enums: a host may pass any integer, and an out-of-range
//! value in a Rust enum would be undefined behaviour. `fmi2Status`, which the FMUs only
//! produce, is a `#[repr(C)]` enum.
#![allow(non_camel_case_types, non_snake_case, non_upper_case_globals)]

use std::ffi::{c_char, c_int, c_uint, c_void};

/// `fmi2Component`: the opaque instance handle (a `Box<Component<M>>` behind it: the
/// typed handles of handle.rs).
pub type fmi2Component = *mut c_void;
/// `fmi2ComponentEnvironment`: the host's pointer, handed back to its callbacks unchanged.
pub type fmi2ComponentEnvironment = *mut c_void;
/// `fmi2FMUstate`: an opaque saved state (a box of the model's saved state behind it).
pub type fmi2FMUstate = *mut c_void;
/// `fmi2ValueReference`.
pub type fmi2ValueReference = c_uint;
/// `fmi2Real`.
pub type fmi2Real = f64;
/// `fmi2Integer`.
pub type fmi2Integer = c_int;
/// `fmi2Boolean`: `fmi2True` (1) or `fmi2False` (0).
pub type fmi2Boolean = c_int;
/// `fmi2Char`.
pub type fmi2Char = c_char;
/// `fmi2String`: a NUL-terminated string, or NULL.
pub type fmi2String = *const fmi2Char;
/// `fmi2Byte`: one byte of a serialized FMU state.
pub type fmi2Byte = c_char;

/// `fmi2True`.
pub const fmi2True: fmi2Boolean = 1;
/// `fmi2False`.
pub const fmi2False: fmi2Boolean = 0;

/// `fmi2Status`, the return value of nearly every function.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum fmi2Status {
    fmi2OK = 0,
    fmi2Warning = 1,
    fmi2Discard = 2,
    fmi2Error = 3,
    fmi2Fatal = 4,
    fmi2Pending = 5,
}

/// `fmi2Type`, as the host passes it to `fmi2Instantiate`.
#[repr(transparent)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct fmi2Type(pub c_int);

impl fmi2Type {
    pub const fmi2ModelExchange: fmi2Type = fmi2Type(0);
    pub const fmi2CoSimulation: fmi2Type = fmi2Type(1);
}

/// `fmi2StatusKind`, as the host passes it to the `fmi2Get*Status` functions.
#[repr(transparent)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct fmi2StatusKind(pub c_int);

impl fmi2StatusKind {
    pub const fmi2DoStepStatus: fmi2StatusKind = fmi2StatusKind(0);
    pub const fmi2PendingStatus: fmi2StatusKind = fmi2StatusKind(1);
    pub const fmi2LastSuccessfulTime: fmi2StatusKind = fmi2StatusKind(2);
    pub const fmi2Terminated: fmi2StatusKind = fmi2StatusKind(3);
}

/// `fmi2CallbackLogger`: the message is a printf format followed by its arguments.
pub type fmi2CallbackLogger = unsafe extern "C" fn(
    fmi2ComponentEnvironment,
    fmi2String,
    fmi2Status,
    fmi2String,
    fmi2String,
    ...
);
/// `fmi2CallbackAllocateMemory`.
pub type fmi2CallbackAllocateMemory = unsafe extern "C" fn(usize, usize) -> *mut c_void;
/// `fmi2CallbackFreeMemory`.
pub type fmi2CallbackFreeMemory = unsafe extern "C" fn(*mut c_void);
/// `fmi2StepFinished`.
pub type fmi2StepFinished = unsafe extern "C" fn(fmi2ComponentEnvironment, fmi2Status);

/// `fmi2CallbackFunctions`. Every field may be NULL; the FMUs use only `logger` and
/// `componentEnvironment` (they allocate with Rust's allocator:
/// `canNotUseMemoryManagementFunctions="true"`, and they never step asynchronously).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct fmi2CallbackFunctions {
    pub logger: Option<fmi2CallbackLogger>,
    pub allocateMemory: Option<fmi2CallbackAllocateMemory>,
    pub freeMemory: Option<fmi2CallbackFreeMemory>,
    pub stepFinished: Option<fmi2StepFinished>,
    pub componentEnvironment: fmi2ComponentEnvironment,
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::mem::{align_of, size_of};

    const POINTER: usize = size_of::<*const c_void>();

    #[test]
    fn status_values_are_the_headers() {
        let values = [
            (fmi2Status::fmi2OK, 0),
            (fmi2Status::fmi2Warning, 1),
            (fmi2Status::fmi2Discard, 2),
            (fmi2Status::fmi2Error, 3),
            (fmi2Status::fmi2Fatal, 4),
            (fmi2Status::fmi2Pending, 5),
        ];
        for (status, value) in values {
            assert_eq!(status as c_int, value);
        }
        assert_eq!(size_of::<fmi2Status>(), size_of::<c_int>());
        assert_eq!(fmi2Type::fmi2ModelExchange.0, 0);
        assert_eq!(fmi2Type::fmi2CoSimulation.0, 1);
        let kinds = [
            fmi2StatusKind::fmi2DoStepStatus,
            fmi2StatusKind::fmi2PendingStatus,
            fmi2StatusKind::fmi2LastSuccessfulTime,
            fmi2StatusKind::fmi2Terminated,
        ];
        assert_eq!(kinds.map(|k| k.0), [0, 1, 2, 3]);
        assert_eq!((fmi2True, fmi2False), (1, 0));
    }

    #[test]
    fn scalar_types_have_the_c_sizes() {
        assert_eq!(size_of::<fmi2Real>(), 8);
        assert_eq!(size_of::<fmi2Integer>(), 4);
        assert_eq!(size_of::<fmi2Boolean>(), 4);
        assert_eq!(size_of::<fmi2ValueReference>(), 4);
        assert_eq!(size_of::<fmi2Byte>(), 1);
        assert_eq!(size_of::<fmi2Type>(), size_of::<c_int>());
        assert_eq!(size_of::<fmi2StatusKind>(), size_of::<c_int>());
        assert_eq!(size_of::<fmi2String>(), POINTER);
        assert_eq!(size_of::<fmi2Component>(), POINTER);
        assert_eq!(size_of::<fmi2FMUstate>(), POINTER);
    }

    #[test]
    fn callback_struct_is_five_pointers_in_header_order() {
        assert_eq!(size_of::<fmi2CallbackFunctions>(), 5 * POINTER);
        assert_eq!(
            align_of::<fmi2CallbackFunctions>(),
            align_of::<*const c_void>()
        );
        // A NULL function pointer is None: Option<fn> has the pointer's size.
        assert_eq!(size_of::<Option<fmi2CallbackLogger>>(), POINTER);
        assert_eq!(std::mem::offset_of!(fmi2CallbackFunctions, logger), 0);
        assert_eq!(
            std::mem::offset_of!(fmi2CallbackFunctions, allocateMemory),
            POINTER
        );
        assert_eq!(
            std::mem::offset_of!(fmi2CallbackFunctions, freeMemory),
            2 * POINTER
        );
        assert_eq!(
            std::mem::offset_of!(fmi2CallbackFunctions, stepFinished),
            3 * POINTER
        );
        assert_eq!(
            std::mem::offset_of!(fmi2CallbackFunctions, componentEnvironment),
            4 * POINTER
        );
    }
}
