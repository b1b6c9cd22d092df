//! The check of a call against its FMI version's state machine: a version gives its calls,
//! their C names and the states that allow each ([`CallTable`]); [`check`] refuses the
//! others with the one typed error, [`Error::IllegalCall`].

use crate::Error;
use std::fmt::Debug;

/// One FMI version's table of calls (FMI 2.0: `fmi2::machine::Call`).
pub trait CallTable: Copy {
    /// The states of the version's state machine.
    type State: Copy + Debug;
    /// The call's C name (`fmi2DoStep`).
    fn c_name(self) -> String;
    /// Whether the table allows the call in `state`.
    fn allowed_in(self, state: Self::State) -> bool;
    /// The state's name in the version's words (the Rust name unless the version renames
    /// it).
    fn state_name(state: Self::State) -> String {
        format!("{state:?}")
    }
}

/// Refuses a call that the table does not allow in `state`.
pub fn check<C: CallTable>(call: C, state: C::State) -> Result<(), Error> {
    if call.allowed_in(state) {
        Ok(())
    } else {
        Err(Error::IllegalCall {
            call: call.c_name(),
            state: C::state_name(state),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, Clone, Copy)]
    enum State {
        Idle,
        Busy,
    }

    #[derive(Debug, Clone, Copy)]
    struct Start;

    impl CallTable for Start {
        type State = State;
        fn c_name(self) -> String {
            "fmiStart".into()
        }
        fn allowed_in(self, state: State) -> bool {
            matches!(state, State::Idle)
        }
    }

    #[test]
    fn a_call_outside_its_states_is_an_illegal_call() {
        assert_eq!(check(Start, State::Idle), Ok(()));
        assert_eq!(
            check(Start, State::Busy),
            Err(Error::IllegalCall {
                call: "fmiStart".into(),
                state: "Busy".into()
            })
        );
    }
}
