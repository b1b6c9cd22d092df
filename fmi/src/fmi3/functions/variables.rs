//! Getting and setting variables: FMI 3.0's (value references, values, nValues) as slices,
//! then the model's getter or setter. Every variable of the layer's FMUs is a scalar, so
//! nValues must equal nValueReferences. The independent variable `time`
//! ([`TIME_VALUE_REFERENCE`]) is answered here: the instance's time (the last successful
//! time), and it cannot be set. The model's types map one to one: Float64 to Real, Int32 to
//! Integer, Boolean (C `bool`) to Boolean, String to String; each value reference becomes
//! the model's FMI 2.0 one by its type's offset ([`Numbering`]).

use super::with_instance;
use crate::fmi2::handle;
use crate::fmi2::model::Model;
use crate::fmi3::machine::Call;
use crate::fmi3::types::*;
use crate::fmi3::{Numbering, TIME_VALUE_REFERENCE};
use crate::Error;
use std::borrow::Cow;

/// Refuses `n_values` other than the value references' count.
fn scalars(nvr: usize, n_values: usize) -> Result<(), Error> {
    if n_values == nvr {
        Ok(())
    } else {
        Err(Error::Argument(format!(
            "nValues = {n_values} differs from nValueReferences = {nvr}: every variable of \
             this FMU is a scalar"
        )))
    }
}

/// The model's (FMI 2.0) value references of the FMI 3.0 ones `vrs` of a type whose offset
/// is `offset`; one below the offset names no variable of the type.
fn fmi2_references<'a>(vrs: &'a [u32], offset: u32, ty: &str) -> Result<Cow<'a, [u32]>, Error> {
    if offset == 0 {
        return Ok(Cow::Borrowed(vrs));
    }
    vrs.iter()
        .map(|&vr| {
            vr.checked_sub(offset).ok_or_else(|| {
                Error::Argument(format!("no {ty} variable has value reference {vr}"))
            })
        })
        .collect::<Result<Vec<u32>, Error>>()
        .map(Cow::Owned)
}

/// `fmi3GetFloat64`.
pub unsafe fn get_float64<M: Model>(
    instance: fmi3Instance,
    numbering: Numbering,
    vr: *const fmi3ValueReference,
    nvr: usize,
    values: *mut fmi3Float64,
    n_values: usize,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::GetFloat64, |component| {
            scalars(nvr, n_values)?;
            let vrs = handle::slice(vr, nvr, "valueReferences")?;
            let values = handle::slice_mut(values, nvr, "values")?;
            // The model's variables in one call; `time` from the instance.
            if !vrs.contains(&TIME_VALUE_REFERENCE) {
                let vrs = &*fmi2_references(vrs, numbering.real, "Float64")?;
                return component.run(|model, cx| model.get_real(cx, vrs, values));
            }
            for (r, value) in vrs.iter().zip(values) {
                if *r == TIME_VALUE_REFERENCE {
                    *value = component.model.last_successful_time();
                } else {
                    let one = std::slice::from_mut(value);
                    let r = &*fmi2_references(std::slice::from_ref(r), numbering.real, "Float64")?;
                    component.run(|model, cx| model.get_real(cx, r, one))?;
                }
            }
            Ok(())
        })
    }
}

/// `fmi3GetInt32`.
pub unsafe fn get_int32<M: Model>(
    instance: fmi3Instance,
    numbering: Numbering,
    vr: *const fmi3ValueReference,
    nvr: usize,
    values: *mut fmi3Int32,
    n_values: usize,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::GetInt32, |component| {
            scalars(nvr, n_values)?;
            let vrs = handle::slice(vr, nvr, "valueReferences")?;
            let vrs = &*fmi2_references(vrs, numbering.integer, "Int32")?;
            let values = handle::slice_mut(values, nvr, "values")?;
            component.run(|model, cx| model.get_integer(cx, vrs, values))
        })
    }
}

/// `fmi3GetBoolean`.
pub unsafe fn get_boolean<M: Model>(
    instance: fmi3Instance,
    numbering: Numbering,
    vr: *const fmi3ValueReference,
    nvr: usize,
    values: *mut fmi3Boolean,
    n_values: usize,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::GetBoolean, |component| {
            scalars(nvr, n_values)?;
            let vrs = handle::slice(vr, nvr, "valueReferences")?;
            let vrs = &*fmi2_references(vrs, numbering.boolean, "Boolean")?;
            let values = handle::slice_mut(values, nvr, "values")?;
            let mut integers = vec![0; nvr];
            component.run(|model, cx| model.get_boolean(cx, vrs, &mut integers))?;
            for (v, i) in values.iter_mut().zip(integers) {
                *v = i != 0;
            }
            Ok(())
        })
    }
}

/// `fmi3GetString`: the strings live in the model until the instance's next call.
pub unsafe fn get_string<M: Model>(
    instance: fmi3Instance,
    numbering: Numbering,
    vr: *const fmi3ValueReference,
    nvr: usize,
    values: *mut fmi3String,
    n_values: usize,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::GetString, |component| {
            scalars(nvr, n_values)?;
            let vrs = handle::slice(vr, nvr, "valueReferences")?;
            let vrs = &*fmi2_references(vrs, numbering.string, "String")?;
            let values = handle::slice_mut(values, nvr, "values")?;
            let strings = component.run(|model, cx| model.get_string(cx, vrs))?;
            for (v, s) in values.iter_mut().zip(strings) {
                *v = s.as_ptr();
            }
            Ok(())
        })
    }
}

/// Refuses to set the independent variable.
fn not_time(vrs: &[u32]) -> Result<(), Error> {
    if vrs.contains(&TIME_VALUE_REFERENCE) {
        return Err(Error::Argument(format!(
            "value reference {TIME_VALUE_REFERENCE} is the independent variable time: it \
             cannot be set"
        )));
    }
    Ok(())
}

/// `fmi3SetFloat64`.
pub unsafe fn set_float64<M: Model>(
    instance: fmi3Instance,
    numbering: Numbering,
    vr: *const fmi3ValueReference,
    nvr: usize,
    values: *const fmi3Float64,
    n_values: usize,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::SetFloat64, |component| {
            scalars(nvr, n_values)?;
            let vrs = handle::slice(vr, nvr, "valueReferences")?;
            not_time(vrs)?;
            let vrs = &*fmi2_references(vrs, numbering.real, "Float64")?;
            let values = handle::slice(values, nvr, "values")?;
            component.run(|model, cx| model.set_real(cx, vrs, values))
        })
    }
}

/// `fmi3SetInt32`.
pub unsafe fn set_int32<M: Model>(
    instance: fmi3Instance,
    numbering: Numbering,
    vr: *const fmi3ValueReference,
    nvr: usize,
    values: *const fmi3Int32,
    n_values: usize,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::SetInt32, |component| {
            scalars(nvr, n_values)?;
            let vrs = handle::slice(vr, nvr, "valueReferences")?;
            let vrs = &*fmi2_references(vrs, numbering.integer, "Int32")?;
            let values = handle::slice(values, nvr, "values")?;
            component.run(|model, cx| model.set_integer(cx, vrs, values))
        })
    }
}

/// `fmi3SetBoolean`.
pub unsafe fn set_boolean<M: Model>(
    instance: fmi3Instance,
    numbering: Numbering,
    vr: *const fmi3ValueReference,
    nvr: usize,
    values: *const fmi3Boolean,
    n_values: usize,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::SetBoolean, |component| {
            scalars(nvr, n_values)?;
            let vrs = handle::slice(vr, nvr, "valueReferences")?;
            let vrs = &*fmi2_references(vrs, numbering.boolean, "Boolean")?;
            let integers: Vec<i32> = handle::slice(values, nvr, "values")?
                .iter()
                .map(|&b| i32::from(b))
                .collect();
            component.run(|model, cx| model.set_boolean(cx, vrs, &integers))
        })
    }
}

/// `fmi3SetString`.
pub unsafe fn set_string<M: Model>(
    instance: fmi3Instance,
    numbering: Numbering,
    vr: *const fmi3ValueReference,
    nvr: usize,
    values: *const fmi3String,
    n_values: usize,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::SetString, |component| {
            scalars(nvr, n_values)?;
            let vrs = handle::slice(vr, nvr, "valueReferences")?;
            let vrs = &*fmi2_references(vrs, numbering.string, "String")?;
            let mut texts = Vec::with_capacity(nvr);
            for &s in handle::slice(values, nvr, "values")? {
                texts.push(handle::text(s, "a String value")?);
            }
            component.run(|model, cx| model.set_string(cx, vrs, &texts))
        })
    }
}
