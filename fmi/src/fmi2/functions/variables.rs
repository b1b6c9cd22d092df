//! Getting and setting variables: the value references and values as slices (NULL only with
//! nothing to pass), strings as text, then the model's getter or setter.

use super::with_component;
use crate::fmi2::handle;
use crate::fmi2::machine::Call;
use crate::fmi2::model::Model;
use crate::fmi2::types::*;

/// `fmi2GetReal`.
pub unsafe fn get_real<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Real,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::GetReal, |component| {
            let vrs = handle::slice(vr, nvr, "vr")?;
            let values = handle::slice_mut(value, nvr, "value")?;
            component.run(|model, cx| model.get_real(cx, vrs, values))
        })
    }
}

/// `fmi2GetInteger`.
pub unsafe fn get_integer<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Integer,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::GetInteger, |component| {
            let vrs = handle::slice(vr, nvr, "vr")?;
            let values = handle::slice_mut(value, nvr, "value")?;
            component.run(|model, cx| model.get_integer(cx, vrs, values))
        })
    }
}

/// `fmi2GetBoolean`.
pub unsafe fn get_boolean<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::GetBoolean, |component| {
            let vrs = handle::slice(vr, nvr, "vr")?;
            let values = handle::slice_mut(value, nvr, "value")?;
            component.run(|model, cx| model.get_boolean(cx, vrs, values))
        })
    }
}

/// `fmi2GetString`: the strings live in the model until the instance's next call.
pub unsafe fn get_string<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2String,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::GetString, |component| {
            let vrs = handle::slice(vr, nvr, "vr")?;
            let values = handle::slice_mut(value, nvr, "value")?;
            let strings = component.run(|model, cx| model.get_string(cx, vrs))?;
            for (v, s) in values.iter_mut().zip(strings) {
                *v = s.as_ptr();
            }
            Ok(())
        })
    }
}

/// `fmi2SetReal`.
pub unsafe fn set_real<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Real,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::SetReal, |component| {
            let vrs = handle::slice(vr, nvr, "vr")?;
            let values = handle::slice(value, nvr, "value")?;
            component.run(|model, cx| model.set_real(cx, vrs, values))
        })
    }
}

/// `fmi2SetInteger`.
pub unsafe fn set_integer<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Integer,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::SetInteger, |component| {
            let vrs = handle::slice(vr, nvr, "vr")?;
            let values = handle::slice(value, nvr, "value")?;
            component.run(|model, cx| model.set_integer(cx, vrs, values))
        })
    }
}

/// `fmi2SetBoolean`.
pub unsafe fn set_boolean<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Boolean,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::SetBoolean, |component| {
            let vrs = handle::slice(vr, nvr, "vr")?;
            let values = handle::slice(value, nvr, "value")?;
            component.run(|model, cx| model.set_boolean(cx, vrs, values))
        })
    }
}

/// `fmi2SetString`.
pub unsafe fn set_string<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2String,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::SetString, |component| {
            let vrs = handle::slice(vr, nvr, "vr")?;
            let mut texts = Vec::with_capacity(nvr);
            for &s in handle::slice(value, nvr, "value")? {
                texts.push(handle::text(s, "a String value")?);
            }
            component.run(|model, cx| model.set_string(cx, vrs, &texts))
        })
    }
}
