//! What an `fmi2Component` points to: the logger, the state of the state machine and the
//! model; and the one place where a call's result becomes an `fmi2Status`, a state change and
//! a log line ([`Component::report`]).
//!
//! An error puts the instance into [`MachineState::Error`] (FMI 2.0.4 section 2.1.3:
//! unusable until `fmi2Reset`, `fmi2SetFMUstate` or `fmi2FreeInstance`), a discarded step
//! into [`MachineState::StepFailed`]; a status the FMU cannot answer leaves it as it was.

use super::logger::Logger;
use super::machine::MachineState;
use super::model::Context;
use super::types::fmi2Status;
use crate::error::Outcome;
use crate::log::Category;
use crate::machine::{check, CallTable};
use crate::Error;

/// One instance: its logger, its state and its model.
pub struct Component<M> {
    pub(crate) logger: Logger,
    pub(crate) state: MachineState,
    pub(crate) model: M,
}

impl<M> Component<M> {
    /// A freshly instantiated instance.
    pub(crate) fn new(logger: Logger, model: M) -> Component<M> {
        Component {
            logger,
            state: MachineState::Instantiated,
            model,
        }
    }

    /// Runs `f` on the model with its context.
    pub(crate) fn run<'s, R>(&'s mut self, f: impl FnOnce(&'s mut M, &Context<'s>) -> R) -> R {
        let cx = Context {
            state: self.state,
            logger: &self.logger,
        };
        f(&mut self.model, &cx)
    }

    /// Refuses a call that the table (FMI 2.0's or 3.0's) does not allow in the current
    /// state.
    pub(crate) fn check<C: CallTable<State = MachineState>>(&self, call: C) -> Result<(), Error> {
        check(call, self.state)
    }

    /// The one place where a result becomes a status (FMI 3.0's has the same numbers), a
    /// state change and a log line.
    pub(crate) fn report<C: CallTable<State = MachineState>>(
        &mut self,
        call: C,
        result: Result<(), Error>,
    ) -> fmi2Status {
        match result {
            Ok(()) => {
                if self.logger.enabled(Category::All) {
                    let message = format!("{}: ok", call.c_name());
                    self.logger.log(fmi2Status::fmi2OK, Category::All, &message);
                }
                fmi2Status::fmi2OK
            }
            Err(e) => {
                match e.outcome() {
                    Outcome::Unanswered => {}
                    Outcome::Discarded => self.state = MachineState::StepFailed,
                    Outcome::Failed => self.state = MachineState::Error,
                }
                refuse(&self.logger, &call.c_name(), &e)
            }
        }
    }
}

/// Logs why `function` failed and returns its status.
pub(crate) fn refuse(logger: &Logger, function: &str, e: &Error) -> fmi2Status {
    let outcome = e.outcome();
    let status = status(outcome);
    logger.log(status, outcome.category(), &format!("{function}: {e}"));
    status
}

/// The `fmi2Status` of an outcome.
fn status(outcome: Outcome) -> fmi2Status {
    match outcome {
        Outcome::Unanswered | Outcome::Discarded => fmi2Status::fmi2Discard,
        Outcome::Failed => fmi2Status::fmi2Error,
    }
}
