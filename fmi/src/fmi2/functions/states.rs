//! Saving, restoring and serializing FMU states, for a model with [`SavedStates`]: the
//! states are boxed behind `fmi2FMUstate` handles (see the handle module).

use super::with_component;
use crate::fmi2::handle;
use crate::fmi2::machine::Call;
use crate::fmi2::model::SavedStates;
use crate::fmi2::types::*;
use crate::Error;

/// `fmi2GetFMUstate` always hands out a new state (like the Reference FMUs): a non-NULL
/// `*FMUstate` on entry is not reused, because a host may pass an uninitialised variable.
pub unsafe fn get_fmu_state<M: SavedStates>(
    c: fmi2Component,
    fmu_state: *mut fmi2FMUstate,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::GetFMUstate, |component| {
            let target = handle::out(fmu_state, "FMUstate")?;
            *target = handle::into_state(component.run(|model, cx| model.get_fmu_state(cx))?);
            Ok(())
        })
    }
}

/// `fmi2SetFMUstate`: the instance takes the state machine's state the model returns.
pub unsafe fn set_fmu_state<M: SavedStates>(
    c: fmi2Component,
    fmu_state: fmi2FMUstate,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::SetFMUstate, |component| {
            let state = handle::state::<M::State>(fmu_state)?;
            component.state = component.run(|model, cx| model.set_fmu_state(cx, state))?;
            Ok(())
        })
    }
}

/// `fmi2FreeFMUstate`: frees `*FMUstate` (NULL is fine) and sets it to NULL.
pub unsafe fn free_fmu_state<M: SavedStates>(
    c: fmi2Component,
    fmu_state: *mut fmi2FMUstate,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::FreeFMUstate, |_| {
            handle::free_state::<M::State>(handle::out(fmu_state, "FMUstate")?);
            Ok(())
        })
    }
}

/// `fmi2SerializedFMUstateSize`.
pub unsafe fn serialized_fmu_state_size<M: SavedStates>(
    c: fmi2Component,
    fmu_state: fmi2FMUstate,
    size: *mut usize,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::SerializedFMUstateSize, |_| {
            let bytes = M::serialized_size(handle::state::<M::State>(fmu_state)?);
            *handle::out(size, "size")? = bytes;
            Ok(())
        })
    }
}

/// `fmi2SerializeFMUstate`: `size` must hold the state's bytes.
pub unsafe fn serialize_fmu_state<M: SavedStates>(
    c: fmi2Component,
    fmu_state: fmi2FMUstate,
    serialized_state: *mut fmi2Byte,
    size: usize,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::SerializeFMUstate, |_| {
            let bytes = M::serialize(handle::state::<M::State>(fmu_state)?)?;
            if size < bytes.len() {
                return Err(Error::Argument(format!(
                    "size = {size} is smaller than the state's {} bytes \
                     (fmi2SerializedFMUstateSize)",
                    bytes.len()
                )));
            }
            let target = handle::bytes_mut(serialized_state, bytes.len(), "serializedState")?;
            target.copy_from_slice(&bytes);
            Ok(())
        })
    }
}

/// `fmi2DeSerializeFMUstate`: a new state from the bytes, checked by the model.
pub unsafe fn deserialize_fmu_state<M: SavedStates>(
    c: fmi2Component,
    serialized_state: *const fmi2Byte,
    size: usize,
    fmu_state: *mut fmi2FMUstate,
) -> fmi2Status {
    unsafe {
        with_component::<M, _>(c, Call::DeSerializeFMUstate, |_| {
            let bytes = handle::bytes(serialized_state, size, "serializedState")?;
            let target = handle::out(fmu_state, "FMUstate")?;
            *target = handle::into_state(M::deserialize(bytes)?);
            Ok(())
        })
    }
}
