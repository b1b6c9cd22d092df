//! The C types of the FMI 3.0 headers (`fmi3PlatformTypes.h`, `fmi3FunctionTypes.h` of
//! modelica/fmi-standard v3.0.2) that the co-simulation functions use, written by hand (no
//! bindings generator: plain cargo builds it). Unlike FMI 2.0, `fmi3Boolean` is C `bool`
//! (one byte) and the value arrays of the getters and setters carry their own length.

#![allow(non_camel_case_types)]
#![allow(non_upper_case_globals)]

use crate::fmi2::types::fmi2Status;
use std::ffi::{c_char, c_void};

/// `fmi3Instance`.
pub type fmi3Instance = *mut c_void;
/// `fmi3InstanceEnvironment`.
pub type fmi3InstanceEnvironment = *mut c_void;
/// `fmi3FMUState`.
pub type fmi3FMUState = *mut c_void;
/// `fmi3ValueReference`.
pub type fmi3ValueReference = u32;
/// `fmi3Float32`.
pub type fmi3Float32 = f32;
/// `fmi3Float64`.
pub type fmi3Float64 = f64;
/// `fmi3Int8` .. `fmi3UInt64`.
pub type fmi3Int8 = i8;
pub type fmi3UInt8 = u8;
pub type fmi3Int16 = i16;
pub type fmi3UInt16 = u16;
pub type fmi3Int32 = i32;
pub type fmi3UInt32 = u32;
pub type fmi3Int64 = i64;
pub type fmi3UInt64 = u64;
/// `fmi3Boolean`: C `bool`.
pub type fmi3Boolean = bool;
/// `fmi3Char`.
pub type fmi3Char = c_char;
/// `fmi3String`.
pub type fmi3String = *const fmi3Char;
/// `fmi3Byte`.
pub type fmi3Byte = u8;
/// `fmi3Binary`.
pub type fmi3Binary = *const fmi3Byte;
/// `fmi3Clock`: C `bool`.
pub type fmi3Clock = bool;

/// `fmi3Status`: the same numbers as `fmi2Status` (FMI 3.0 has no `Pending`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum fmi3Status {
    fmi3OK = 0,
    fmi3Warning = 1,
    fmi3Discard = 2,
    fmi3Error = 3,
    fmi3Fatal = 4,
}

impl From<fmi2Status> for fmi3Status {
    /// The status of the same number (`fmi2Pending`, which no function of this layer
    /// returns, as an error).
    fn from(status: fmi2Status) -> fmi3Status {
        match status {
            fmi2Status::fmi2OK => fmi3Status::fmi3OK,
            fmi2Status::fmi2Warning => fmi3Status::fmi3Warning,
            fmi2Status::fmi2Discard => fmi3Status::fmi3Discard,
            fmi2Status::fmi2Error | fmi2Status::fmi2Pending => fmi3Status::fmi3Error,
            fmi2Status::fmi2Fatal => fmi3Status::fmi3Fatal,
        }
    }
}

/// `fmi3DependencyKind` (a C enum).
pub type fmi3DependencyKind = i32;
/// `fmi3IntervalQualifier` (a C enum).
pub type fmi3IntervalQualifier = i32;

/// `fmi3LogMessageCallback`: (environment, status, category, message), not variadic.
pub type fmi3LogMessageCallback =
    unsafe extern "C" fn(fmi3InstanceEnvironment, fmi3Status, fmi3String, fmi3String);

/// `fmi3IntermediateUpdateCallback` (never called: `providesIntermediateUpdate="false"`).
pub type fmi3IntermediateUpdateCallback = unsafe extern "C" fn(
    fmi3InstanceEnvironment,
    fmi3Float64,
    fmi3Boolean,
    fmi3Boolean,
    fmi3Boolean,
    fmi3Boolean,
    *mut fmi3Boolean,
    *mut fmi3Float64,
);

/// `fmi3ClockUpdateCallback` (scheduled execution, not provided).
pub type fmi3ClockUpdateCallback = unsafe extern "C" fn(fmi3InstanceEnvironment);
/// `fmi3LockPreemptionCallback` (scheduled execution, not provided).
pub type fmi3LockPreemptionCallback = unsafe extern "C" fn();
/// `fmi3UnlockPreemptionCallback` (scheduled execution, not provided).
pub type fmi3UnlockPreemptionCallback = unsafe extern "C" fn();

#[cfg(test)]
mod tests {
    use super::*;
    use std::mem::size_of;

    /// The sizes the C headers give on the 64-bit platforms the FMU is built for.
    #[test]
    fn sizes_are_the_c_headers() {
        assert_eq!(size_of::<fmi3Boolean>(), 1, "C bool");
        assert_eq!(size_of::<fmi3Status>(), 4, "a C enum");
        assert_eq!(size_of::<fmi3ValueReference>(), 4);
        assert_eq!(size_of::<fmi3Instance>(), size_of::<*const c_void>());
        assert_eq!(
            size_of::<Option<fmi3LogMessageCallback>>(),
            size_of::<usize>()
        );
    }

    #[test]
    fn statuses_keep_their_numbers() {
        for (two, three) in [
            (fmi2Status::fmi2OK, 0),
            (fmi2Status::fmi2Warning, 1),
            (fmi2Status::fmi2Discard, 2),
            (fmi2Status::fmi2Error, 3),
            (fmi2Status::fmi2Fatal, 4),
        ] {
            assert_eq!(fmi3Status::from(two) as i32, three);
            assert_eq!(two as i32, three);
        }
    }
}
