//! The typed handles: every pointer the host passes becomes a Rust reference here, and every
//! value the host keeps becomes a pointer here. An `fmi2Component` is a
//! `Box<Component<M>>`, an `fmi2FMUstate` a `Box` of the model's saved state; arrays, output
//! arguments, strings and the serialized bytes become slices, references and `&str`. These
//! are the crate's only pointer casts, and each `unsafe` block says why it is sound.
//!
//! # Safety
//!
//! Every function here relies on the host passing pointers as the FMI 2.0 standard says: an
//! `fmi2Component` that `fmi2Instantiate` of the same model returned and that is not yet
//! freed, an `fmi2FMUstate` that `fmi2GetFMUstate` or `fmi2DeSerializeFMUstate` of the same
//! model returned and that is not yet freed, arrays of at least the given length,
//! NUL-terminated strings, output arguments the host owns. NULL pointers are detected and
//! refused (and misaligned arrays and outputs); dangling ones cannot be.

#![allow(unsafe_code)]
#![deny(clippy::undocumented_unsafe_blocks)]

use super::component::Component;
use super::types::{fmi2Byte, fmi2CallbackFunctions, fmi2Component, fmi2FMUstate, fmi2String};
use crate::Error;
use std::ffi::CStr;

/// Hands a new instance to the host (freed by [`take_component`]).
pub(crate) fn into_component<M>(component: Component<M>) -> fmi2Component {
    Box::into_raw(Box::new(component)).cast()
}

/// The instance behind `c`; `None` for NULL.
///
/// # Safety
/// `c` is NULL or a live instance of `M` from [`into_component`] (module docs), and the
/// host makes no other call on it while the reference lives.
pub(crate) unsafe fn component<'a, M>(c: fmi2Component) -> Option<&'a mut Component<M>> {
    // SAFETY: a non-NULL component is a live `Box<Component<M>>` from `into_component`,
    // not aliased during the call (the caller's contract).
    unsafe { c.cast::<Component<M>>().as_mut() }
}

/// Takes the instance back from the host, to drop it; `None` for NULL.
///
/// # Safety
/// `c` is NULL or a live instance of `M` from [`into_component`], freed once.
pub(crate) unsafe fn take_component<M>(c: fmi2Component) -> Option<Box<Component<M>>> {
    if c.is_null() {
        return None;
    }
    // SAFETY: a live `Box<Component<M>>` from `into_component`, which the host frees once.
    Some(unsafe { Box::from_raw(c.cast::<Component<M>>()) })
}

/// Hands a saved state to the host (freed by [`free_state`]).
pub(crate) fn into_state<S>(state: S) -> fmi2FMUstate {
    Box::into_raw(Box::new(state)).cast()
}

/// The saved state behind `s`; NULL is an error.
///
/// # Safety
/// `s` is NULL or a live state of type `S` from [`into_state`].
pub(crate) unsafe fn state<'a, S>(s: fmi2FMUstate) -> Result<&'a S, Error> {
    // SAFETY: a non-NULL state is a live `Box<S>` from `into_state` (the caller's contract);
    // it is only read.
    unsafe { s.cast::<S>().as_ref() }.ok_or_else(|| Error::Argument("FMUstate is NULL".into()))
}

/// Frees the saved state in `*handle`, if any, and sets it to NULL.
///
/// # Safety
/// `*handle` is NULL or a live state of type `S` from [`into_state`], freed once.
pub(crate) unsafe fn free_state<S>(handle: &mut fmi2FMUstate) {
    if !handle.is_null() {
        // SAFETY: a live `Box<S>` from `into_state`, freed once (the caller's contract).
        drop(unsafe { Box::from_raw(handle.cast::<S>()) });
        *handle = std::ptr::null_mut();
    }
}

/// The host's callbacks, copied; `None` for NULL.
///
/// # Safety
/// `functions` is NULL or points to an `fmi2CallbackFunctions` valid for the call.
pub(crate) unsafe fn callbacks(
    functions: *const fmi2CallbackFunctions,
) -> Option<fmi2CallbackFunctions> {
    // SAFETY: non-NULL is the host's struct, valid during fmi2Instantiate; it is copied.
    unsafe { functions.as_ref() }.copied()
}

/// `(pointer, n)` as a slice: NULL is fine only when n = 0.
///
/// # Safety
/// A non-NULL `p` points to `n` initialised values that outlive `'a`.
pub(crate) unsafe fn slice<'a, T>(p: *const T, n: usize, what: &str) -> Result<&'a [T], Error> {
    if n == 0 {
        Ok(&[])
    } else if p.is_null() || !p.is_aligned() {
        Err(Error::Argument(format!(
            "{what} is NULL or misaligned but its length is {n}"
        )))
    } else {
        // SAFETY: non-NULL and aligned; the host promises n elements (the caller's contract).
        Ok(unsafe { std::slice::from_raw_parts(p, n) })
    }
}

/// `(pointer, n)` as a mutable slice: NULL is fine only when n = 0.
///
/// # Safety
/// A non-NULL `p` points to `n` values the host owns and does not read during `'a`.
pub(crate) unsafe fn slice_mut<'a, T>(
    p: *mut T,
    n: usize,
    what: &str,
) -> Result<&'a mut [T], Error> {
    if n == 0 {
        Ok(&mut [])
    } else if p.is_null() || !p.is_aligned() {
        Err(Error::Argument(format!(
            "{what} is NULL or misaligned but its length is {n}"
        )))
    } else {
        // SAFETY: non-NULL and aligned; the host promises n elements (the caller's contract).
        Ok(unsafe { std::slice::from_raw_parts_mut(p, n) })
    }
}

/// Serialized state bytes as `u8` (`fmi2Byte` is a C `char`: the same size and alignment).
///
/// # Safety
/// As [`slice`].
pub(crate) unsafe fn bytes<'a>(
    p: *const fmi2Byte,
    n: usize,
    what: &str,
) -> Result<&'a [u8], Error> {
    // SAFETY: `fmi2Byte` and `u8` have the same size and alignment, and every bit pattern
    // is valid in both; the rest is `slice`'s contract, which the caller keeps.
    unsafe { slice(p.cast::<u8>(), n, what) }
}

/// A buffer for serialized state bytes, as `u8`.
///
/// # Safety
/// As [`slice_mut`].
pub(crate) unsafe fn bytes_mut<'a>(
    p: *mut fmi2Byte,
    n: usize,
    what: &str,
) -> Result<&'a mut [u8], Error> {
    // SAFETY: as in `bytes`; the rest is `slice_mut`'s contract, which the caller keeps.
    unsafe { slice_mut(p.cast::<u8>(), n, what) }
}

/// An output argument as a reference.
///
/// # Safety
/// A non-NULL `p` points to a value the host owns and does not read during `'a`.
pub(crate) unsafe fn out<'a, T>(p: *mut T, what: &str) -> Result<&'a mut T, Error> {
    if !p.is_aligned() {
        return Err(Error::Argument(format!("{what} is misaligned")));
    }
    // SAFETY: aligned; NULL is checked by `as_mut`; the host owns the memory.
    unsafe { p.as_mut() }.ok_or_else(|| Error::Argument(format!("{what} is NULL")))
}

/// A C string argument as UTF-8 text; NULL is an error.
///
/// # Safety
/// A non-NULL `s` is NUL-terminated and outlives `'a`.
pub(crate) unsafe fn text<'a>(s: fmi2String, what: &str) -> Result<&'a str, Error> {
    if s.is_null() {
        return Err(Error::Argument(format!("{what} is NULL")));
    }
    // SAFETY: non-NULL and NUL-terminated (the caller's contract).
    unsafe { CStr::from_ptr(s) }
        .to_str()
        .map_err(|_| Error::Argument(format!("{what} is not UTF-8")))
}

#[cfg(test)]
mod tests {
    // Every pointer below is NULL or a live local of the right type and length.
    #![allow(clippy::undocumented_unsafe_blocks)]

    use super::*;
    use std::ptr;

    #[test]
    fn null_arrays_are_refused_unless_empty() {
        let empty: &[f64] = unsafe { slice(ptr::null(), 0, "value") }.unwrap();
        assert!(empty.is_empty());
        assert_eq!(
            unsafe { slice::<f64>(ptr::null(), 2, "value") },
            Err(Error::Argument(
                "value is NULL or misaligned but its length is 2".into()
            ))
        );
        assert!(unsafe { slice_mut::<i32>(ptr::null_mut(), 1, "value") }.is_err());
        let values = [1.0, 2.0];
        assert_eq!(
            unsafe { slice(values.as_ptr(), 2, "value") }.unwrap(),
            &values
        );
    }

    #[test]
    fn outputs_strings_and_states() {
        assert_eq!(
            unsafe { out::<f64>(ptr::null_mut(), "value") },
            Err(Error::Argument("value is NULL".into()))
        );
        let mut x = 0.0;
        *unsafe { out(&mut x, "value") }.unwrap() = 2.0;
        assert_eq!(x, 2.0);
        assert_eq!(
            unsafe { text(ptr::null(), "fmuGUID") },
            Err(Error::Argument("fmuGUID is NULL".into()))
        );
        assert_eq!(unsafe { text(c"abc".as_ptr(), "x") }, Ok("abc"));
        let not_utf8 = [0xffu8, 0];
        assert_eq!(
            unsafe { text(not_utf8.as_ptr().cast(), "x") },
            Err(Error::Argument("x is not UTF-8".into()))
        );
        let mut handle = into_state(vec![1u8, 2, 3]);
        assert_eq!(unsafe { state::<Vec<u8>>(handle) }.unwrap(), &[1, 2, 3]);
        unsafe { free_state::<Vec<u8>>(&mut handle) };
        assert!(handle.is_null());
        assert!(unsafe { state::<Vec<u8>>(handle) }.is_err());
        // Freeing NULL does nothing.
        unsafe { free_state::<Vec<u8>>(&mut handle) };
    }
}
