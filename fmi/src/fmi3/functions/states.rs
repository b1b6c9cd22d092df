//! Saving, restoring and serializing FMU states, for a model with [`SavedStates`]: the
//! FMI 2.0 layer's boxed states behind `fmi3FMUState` handles, and the model's bytes.

use super::with_instance;
use crate::fmi2::handle;
use crate::fmi2::model::SavedStates;
use crate::fmi3::machine::Call;
use crate::fmi3::types::*;
use crate::Error;

/// `fmi3GetFMUState`: always a new state (a non-NULL `*FMUState` on entry is not reused).
pub unsafe fn get_fmu_state<M: SavedStates>(
    instance: fmi3Instance,
    fmu_state: *mut fmi3FMUState,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::GetFMUState, |component| {
            let target = handle::out(fmu_state, "FMUState")?;
            *target = handle::into_state(component.run(|model, cx| model.get_fmu_state(cx))?);
            Ok(())
        })
    }
}

/// `fmi3SetFMUState`: the instance takes the state machine's state the model returns.
pub unsafe fn set_fmu_state<M: SavedStates>(
    instance: fmi3Instance,
    fmu_state: fmi3FMUState,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::SetFMUState, |component| {
            let state = handle::state::<M::State>(fmu_state)?;
            component.state = component.run(|model, cx| model.set_fmu_state(cx, state))?;
            Ok(())
        })
    }
}

/// `fmi3FreeFMUState`: frees `*FMUState` (NULL is fine) and sets it to NULL.
pub unsafe fn free_fmu_state<M: SavedStates>(
    instance: fmi3Instance,
    fmu_state: *mut fmi3FMUState,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::FreeFMUState, |_| {
            handle::free_state::<M::State>(handle::out(fmu_state, "FMUState")?);
            Ok(())
        })
    }
}

/// `fmi3SerializedFMUStateSize`.
pub unsafe fn serialized_fmu_state_size<M: SavedStates>(
    instance: fmi3Instance,
    fmu_state: fmi3FMUState,
    size: *mut usize,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::SerializedFMUStateSize, |_| {
            let bytes = M::serialized_size(handle::state::<M::State>(fmu_state)?);
            *handle::out(size, "size")? = bytes;
            Ok(())
        })
    }
}

/// `fmi3SerializeFMUState`: `size` must hold the state's bytes.
pub unsafe fn serialize_fmu_state<M: SavedStates>(
    instance: fmi3Instance,
    fmu_state: fmi3FMUState,
    serialized_state: *mut fmi3Byte,
    size: usize,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::SerializeFMUState, |_| {
            let bytes = M::serialize(handle::state::<M::State>(fmu_state)?)?;
            if size < bytes.len() {
                return Err(Error::Argument(format!(
                    "size = {size} is smaller than the state's {} bytes \
                     (fmi3SerializedFMUStateSize)",
                    bytes.len()
                )));
            }
            let target = handle::slice_mut(serialized_state, bytes.len(), "serializedState")?;
            target.copy_from_slice(&bytes);
            Ok(())
        })
    }
}

/// `fmi3DeserializeFMUState`: a new state from the bytes, checked by the model.
pub unsafe fn deserialize_fmu_state<M: SavedStates>(
    instance: fmi3Instance,
    serialized_state: *const fmi3Byte,
    size: usize,
    fmu_state: *mut fmi3FMUState,
) -> fmi3Status {
    unsafe {
        with_instance::<M>(instance, Call::DeserializeFMUState, |_| {
            let bytes = handle::slice(serialized_state, size, "serializedState")?;
            let target = handle::out(fmu_state, "FMUState")?;
            *target = handle::into_state(M::deserialize(bytes)?);
            Ok(())
        })
    }
}
