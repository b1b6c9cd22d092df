//! Getting and setting variables: FMI 3.0's (value references, values, nValues) as slices,
//! then the model's getter or setter. A Float64 array ([`crate::fmi3::ArrayVariable`]) is its
//! FMI 2.0 scalars, in order; every other variable is a scalar; nValues must equal the
//! values of the value references. The independent variable `time`
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

/// Refuses `n_values` other than `count`, the values of the value references (one each:
/// the Int32, Boolean and String variables are scalars).
fn scalars(count: usize, n_values: usize) -> Result<(), Error> {
    if n_values == count {
        Ok(())
    } else {
        Err(Error::Argument(format!(
            "nValues = {n_values} differs from the {count} values of the value references"
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

/// The model's (FMI 2.0) Real value references of the Float64 value references `vrs`, an
/// array's expanded into its scalars ([`Numbering::reals`]); refuses `n_values` other than
/// their count and a value reference that names no Float64. Without arrays or offset they
/// are `vrs` themselves (no allocation in a master's per-step getter).
fn fmi2_reals<'a>(
    vrs: &'a [u32],
    numbering: &Numbering,
    n_values: usize,
) -> Result<Cow<'a, [u32]>, Error> {
    if numbering.real == 0 && numbering.arrays.is_empty() {
        scalars(vrs.len(), n_values)?;
        return Ok(Cow::Borrowed(vrs));
    }
    let mut out = Vec::with_capacity(vrs.len());
    for &vr in vrs {
        let reals = numbering.reals(vr).ok_or_else(|| {
            Error::Argument(format!("no Float64 variable has value reference {vr}"))
        })?;
        out.extend(reals);
    }
    if out.len() != n_values {
        return Err(Error::Argument(format!(
            "nValues = {n_values} differs from the {} values of the {} value references",
            out.len(),
            vrs.len()
        )));
    }
    Ok(Cow::Owned(out))
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
            let vrs = handle::slice(vr, nvr, "valueReferences")?;
            if !vrs.contains(&TIME_VALUE_REFERENCE) {
                let reals = fmi2_reals(vrs, &numbering, n_values)?;
                let values = handle::slice_mut(values, n_values, "values")?;
                return component.run(|model, cx| model.get_real(cx, &reals, values));
            }
            // With `time` (a scalar, from the instance): one variable at a time.
            let counts = vrs
                .iter()
                .map(|&r| match r {
                    TIME_VALUE_REFERENCE => Ok(1),
                    _ => numbering.reals(r).map(|reals| reals.len()).ok_or_else(|| {
                        Error::Argument(format!("no Float64 variable has value reference {r}"))
                    }),
                })
                .collect::<Result<Vec<usize>, Error>>()?;
            scalars(counts.iter().sum(), n_values)?;
            let values = handle::slice_mut(values, n_values, "values")?;
            let mut at = 0;
            for (r, count) in vrs.iter().zip(counts) {
                let out = &mut values[at..at + count];
                at += count;
                if *r == TIME_VALUE_REFERENCE {
                    out[0] = component.model.last_successful_time();
                } else {
                    let reals = fmi2_reals(std::slice::from_ref(r), &numbering, count)?;
                    component.run(|model, cx| model.get_real(cx, &reals, out))?;
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
            let vrs = handle::slice(vr, nvr, "valueReferences")?;
            not_time(vrs)?;
            let reals = fmi2_reals(vrs, &numbering, n_values)?;
            let values = handle::slice(values, n_values, "values")?;
            component.run(|model, cx| model.set_real(cx, &reals, values))
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
