//! The FMI 2.0 co-simulation state machine: the states an instance can be in and which
//! call is allowed in which state (the Reference-FMUs' `MASK_fmi2*` table), with no
//! knowledge of the model.

use crate::machine::CallTable;

/// The FMI 2.0 co-simulation states an instance can be in (FMI 2.0.4 figure 8; there is no
/// StepInProgress/StepCanceled: steps are never asynchronous).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MachineState {
    Instantiated = 0,
    InitializationMode = 1,
    StepComplete = 2,
    StepFailed = 3,
    Terminated = 4,
    Error = 5,
}

impl MachineState {
    const fn bit(self) -> u8 {
        1 << self as u8
    }

    /// Whether a parameter of variability `fixed` may still be set: until
    /// `fmi2ExitInitializationMode`.
    pub fn fixed_parameters_settable(self) -> bool {
        matches!(
            self,
            MachineState::Instantiated | MachineState::InitializationMode
        )
    }

    /// The byte of the serialized state.
    pub fn code(self) -> u8 {
        self as u8
    }

    /// Inverse of [`MachineState::code`]; `Error` is never saved, so it is not accepted.
    pub fn from_code(code: u8) -> Option<MachineState> {
        use MachineState::*;
        [
            Instantiated,
            InitializationMode,
            StepComplete,
            StepFailed,
            Terminated,
        ]
        .into_iter()
        .find(|s| s.code() == code)
    }
}

/// Bit masks of states, combined by `|`.
mod mask {
    use super::MachineState::*;
    pub const INSTANTIATED: u8 = Instantiated.bit();
    pub const INIT: u8 = InitializationMode.bit();
    pub const STEP_COMPLETE: u8 = StepComplete.bit();
    pub const STEP_FAILED: u8 = StepFailed.bit();
    pub const TERMINATED: u8 = Terminated.bit();
    pub const ERROR: u8 = Error.bit();
    pub const ALL: u8 = INSTANTIATED | INIT | STEP_COMPLETE | STEP_FAILED | TERMINATED | ERROR;
    /// Where outputs can be read: after EnterInitializationMode, and in Error for debugging.
    pub const GET: u8 = INIT | STEP_COMPLETE | STEP_FAILED | TERMINATED | ERROR;
    pub const SET: u8 = INSTANTIATED | INIT | STEP_COMPLETE;
    pub const STATUS: u8 = STEP_COMPLETE | STEP_FAILED | TERMINATED | ERROR;
}

/// Makes [`Call`] and [`Call::ALL`] from one list, so that `ALL` holds every call.
macro_rules! calls {
    ($(#[$meta:meta])* pub enum Call { $($variant:ident,)+ }) => {
        $(#[$meta])*
        pub enum Call {
            $($variant,)+
        }

        impl Call {
            /// Every call, for tests that try each one in each state.
            pub const ALL: [Call; [$(Call::$variant),+].len()] = [$(Call::$variant),+];
        }
    };
}

calls! {
    /// Every exported function that takes an instance (`fmi2FreeInstance` is always allowed).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub enum Call {
        SetDebugLogging,
        SetupExperiment,
        EnterInitializationMode,
        ExitInitializationMode,
        Terminate,
        Reset,
        GetReal,
        GetInteger,
        GetBoolean,
        GetString,
        SetReal,
        SetInteger,
        SetBoolean,
        SetString,
        GetFMUstate,
        SetFMUstate,
        FreeFMUstate,
        SerializedFMUstateSize,
        SerializeFMUstate,
        DeSerializeFMUstate,
        GetDirectionalDerivative,
        SetRealInputDerivatives,
        GetRealOutputDerivatives,
        DoStep,
        CancelStep,
        GetStatus,
        GetRealStatus,
        GetIntegerStatus,
        GetBooleanStatus,
        GetStringStatus,
    }
}

impl Call {
    /// The states in which the call is allowed (the Reference-FMUs' `MASK_fmi2*`, for
    /// co-simulation without asynchronous steps). The unsupported functions are allowed
    /// everywhere and then answer that they are unsupported.
    pub const fn allowed(self) -> u8 {
        use mask::*;
        use Call::*;
        match self {
            SetDebugLogging
            | Reset
            | SetFMUstate
            | FreeFMUstate
            | SerializedFMUstateSize
            | SerializeFMUstate
            | DeSerializeFMUstate => ALL,
            GetDirectionalDerivative
            | SetRealInputDerivatives
            | GetRealOutputDerivatives
            | CancelStep => ALL,
            SetupExperiment | EnterInitializationMode => INSTANTIATED,
            ExitInitializationMode => INIT,
            Terminate => STEP_COMPLETE | STEP_FAILED,
            GetReal | GetInteger | GetBoolean | GetString => GET,
            SetReal | SetInteger | SetBoolean | SetString => SET,
            GetFMUstate => ALL & !ERROR,
            DoStep => STEP_COMPLETE,
            GetStatus | GetRealStatus | GetIntegerStatus | GetBooleanStatus | GetStringStatus => {
                STATUS
            }
        }
    }

    /// The C function's name.
    pub fn name(self) -> String {
        format!("fmi2{self:?}")
    }
}

impl CallTable for Call {
    type State = MachineState;

    fn c_name(self) -> String {
        self.name()
    }

    fn allowed_in(self, state: MachineState) -> bool {
        self.allowed() & state.bit() != 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn state_codes_round_trip_and_error_is_never_restored() {
        use MachineState::*;
        for s in [
            Instantiated,
            InitializationMode,
            StepComplete,
            StepFailed,
            Terminated,
        ] {
            assert_eq!(MachineState::from_code(s.code()), Some(s));
        }
        assert_eq!(MachineState::from_code(Error.code()), None);
    }

    #[test]
    fn call_names_are_the_c_names() {
        assert_eq!(Call::DoStep.name(), "fmi2DoStep");
        assert_eq!(Call::DeSerializeFMUstate.name(), "fmi2DeSerializeFMUstate");
        assert_eq!(Call::DoStep.c_name(), "fmi2DoStep");
    }

    #[test]
    fn the_table_decides_and_fixed_parameters_close_at_initialization_end() {
        use MachineState::*;
        assert!(Call::DoStep.allowed_in(StepComplete));
        assert!(!Call::DoStep.allowed_in(StepFailed));
        assert!(Call::Reset.allowed_in(Error));
        assert!(!Call::GetFMUstate.allowed_in(Error));
        let settable: Vec<_> = [
            Instantiated,
            InitializationMode,
            StepComplete,
            StepFailed,
            Terminated,
            Error,
        ]
        .into_iter()
        .filter(|s| s.fixed_parameters_settable())
        .collect();
        assert_eq!(settable, [Instantiated, InitializationMode]);
    }
}
