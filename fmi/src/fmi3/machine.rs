//! The FMI 3.0 co-simulation calls and the states that allow each (the Reference-FMUs'
//! `MASK_fmi3*`, for co-simulation without event mode, intermediate update or clocks), on
//! the one state machine of the layer ([`MachineState`], FMI 2.0's names). FMI 3.0 calls
//! StepComplete "Step Mode"; a discarded step leaves the instance where FMI 2.0 has
//! StepFailed: only a restored state, getters, termination or a reset follow.

use crate::fmi2::machine::MachineState;
use crate::machine::CallTable;

/// Every FMI 3.0 function that takes an instance and that the layer provides; the others
/// are [`Call::Unsupported`] with their C name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Call {
    SetDebugLogging,
    EnterInitializationMode,
    ExitInitializationMode,
    Terminate,
    Reset,
    GetFloat64,
    GetInt32,
    GetBoolean,
    GetString,
    SetFloat64,
    SetInt32,
    SetBoolean,
    SetString,
    GetFMUState,
    SetFMUState,
    FreeFMUState,
    SerializedFMUStateSize,
    SerializeFMUState,
    DeserializeFMUState,
    DoStep,
    /// A function the FMU does not provide (its C name): allowed in every state, it then
    /// answers that it is not supported.
    Unsupported(&'static str),
}

/// Bit masks of states.
mod mask {
    use crate::fmi2::machine::MachineState::*;
    const fn bit(s: crate::fmi2::machine::MachineState) -> u8 {
        1 << s as u8
    }
    pub const INSTANTIATED: u8 = bit(Instantiated);
    pub const INIT: u8 = bit(InitializationMode);
    pub const STEP_MODE: u8 = bit(StepComplete);
    pub const STEP_DISCARDED: u8 = bit(StepFailed);
    pub const TERMINATED: u8 = bit(Terminated);
    pub const ERROR: u8 = bit(Error);
    pub const ALL: u8 = INSTANTIATED | INIT | STEP_MODE | STEP_DISCARDED | TERMINATED | ERROR;
    /// Where values can be read: from initialisation mode on, and in Error for debugging.
    pub const GET: u8 = INIT | STEP_MODE | STEP_DISCARDED | TERMINATED | ERROR;
    pub const SET: u8 = INSTANTIATED | INIT | STEP_MODE;
}

impl Call {
    /// The states in which the call is allowed.
    pub const fn allowed(self) -> u8 {
        use mask::*;
        use Call::*;
        match self {
            SetDebugLogging
            | Reset
            | SetFMUState
            | FreeFMUState
            | SerializedFMUStateSize
            | SerializeFMUState
            | DeserializeFMUState
            | Unsupported(_) => ALL,
            EnterInitializationMode => INSTANTIATED,
            ExitInitializationMode => INIT,
            Terminate => STEP_MODE | STEP_DISCARDED,
            GetFloat64 | GetInt32 | GetBoolean | GetString => GET,
            SetFloat64 | SetInt32 | SetBoolean | SetString => SET,
            GetFMUState => ALL & !ERROR,
            DoStep => STEP_MODE,
        }
    }

    /// The C function's name.
    pub fn name(self) -> String {
        match self {
            Call::Unsupported(name) => name.to_string(),
            other => format!("fmi3{other:?}"),
        }
    }
}

impl CallTable for Call {
    type State = MachineState;

    fn c_name(self) -> String {
        self.name()
    }

    fn allowed_in(self, state: MachineState) -> bool {
        self.allowed() & (1 << state as u8) != 0
    }

    /// FMI 3.0's words for the states.
    fn state_name(state: MachineState) -> String {
        match state {
            MachineState::StepComplete => "Step Mode".into(),
            MachineState::StepFailed => "Step Mode after a discarded step".into(),
            MachineState::InitializationMode => "Initialization Mode".into(),
            MachineState::Instantiated => "Instantiated".into(),
            MachineState::Terminated => "Terminated".into(),
            MachineState::Error => "Error".into(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::machine::check;
    use crate::Error;

    #[test]
    fn names_and_states_are_fmi3s() {
        assert_eq!(Call::DoStep.name(), "fmi3DoStep");
        assert_eq!(Call::GetFMUState.name(), "fmi3GetFMUState");
        assert_eq!(Call::Unsupported("fmi3GetClock").name(), "fmi3GetClock");
        assert_eq!(
            check(Call::DoStep, MachineState::Instantiated),
            Err(Error::IllegalCall {
                call: "fmi3DoStep".into(),
                state: "Instantiated".into()
            })
        );
        assert_eq!(
            check(Call::EnterInitializationMode, MachineState::StepComplete),
            Err(Error::IllegalCall {
                call: "fmi3EnterInitializationMode".into(),
                state: "Step Mode".into()
            })
        );
    }

    /// FMI 3.0 section 4.2's co-simulation state machine, row by row.
    #[test]
    fn the_table_is_the_standards() {
        use MachineState::*;
        assert!(Call::DoStep.allowed_in(StepComplete));
        assert!(!Call::DoStep.allowed_in(StepFailed));
        assert!(!Call::DoStep.allowed_in(InitializationMode));
        assert!(Call::SetFloat64.allowed_in(Instantiated));
        assert!(!Call::SetFloat64.allowed_in(Terminated));
        assert!(!Call::GetFloat64.allowed_in(Instantiated));
        assert!(Call::Terminate.allowed_in(StepFailed));
        assert!(!Call::Terminate.allowed_in(Instantiated));
        assert!(Call::Reset.allowed_in(Error));
        assert!(!Call::GetFMUState.allowed_in(Error));
        assert!(Call::Unsupported("fmi3EnterEventMode").allowed_in(StepComplete));
    }
}
