//! Why an FMI call failed ([`Error`]), and the one place that decides what follows: its
//! [`Outcome`], which gives the status returned to the host and the category of the log line
//! (each FMI version maps the outcome onto its status type and its states).

use crate::log::Category;
use std::fmt;

/// Why a call failed. [`Error::outcome`] is the one place that decides the status and the
/// log category; `Display` is the log line's text after the function's name.
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// The call is not allowed in the instance's current state (the version's call table):
    /// the function's C name and the state's name.
    IllegalCall { call: String, state: String },
    /// A bad argument: NULL pointer, unknown value reference, wrong type, non-finite value,
    /// a call the arguments make impossible.
    Argument(String),
    /// The model refused (an invalid configuration, an unreadable file, a diverging state...),
    /// in the FMU user's words.
    Model(String),
    /// A function the FMU does not implement, and why.
    Unsupported(&'static str),
    /// A status query the FMU cannot answer (FMI 2.0.4 section 4.2.3: "If a status is
    /// required which cannot be retrieved by the slave it returns fmi2Discard"); the
    /// instance's state does not change.
    StatusUnavailable(String),
    /// The step cannot be completed but the instance stays usable, its state unchanged; the
    /// model's reason.
    Discard(String),
    /// A panic caught at the boundary, and its message.
    Panic(String),
}

/// What a failed call means for the host and the instance, whatever the FMI version.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// A discard that leaves the instance as it was (a status it cannot answer).
    Unanswered,
    /// A discarded step: the instance waits for a rollback or a reset.
    Discarded,
    /// An error: the instance accepts only a reset, a restored state, getters and freeing.
    Failed,
}

impl Error {
    /// The outcome of this error: the one status and log policy of every FMU of this layer.
    pub fn outcome(&self) -> Outcome {
        match self {
            Error::StatusUnavailable(_) => Outcome::Unanswered,
            Error::Discard(_) => Outcome::Discarded,
            Error::IllegalCall { .. }
            | Error::Argument(_)
            | Error::Model(_)
            | Error::Unsupported(_)
            | Error::Panic(_) => Outcome::Failed,
        }
    }
}

impl Outcome {
    /// The log category of the line that says why (always reported, see [`Category`]).
    pub fn category(self) -> Category {
        match self {
            Outcome::Unanswered | Outcome::Discarded => Category::StatusDiscard,
            Outcome::Failed => Category::StatusError,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::IllegalCall { call, state } => write!(
                f,
                "illegal call sequence: {call} is not allowed in state {state}"
            ),
            Error::Argument(m) | Error::Model(m) => f.write_str(m),
            Error::Unsupported(why) => write!(f, "not supported: {why}"),
            Error::StatusUnavailable(why) => write!(f, "status not available: {why}"),
            Error::Discard(why) => write!(f, "step discarded: {why}"),
            Error::Panic(m) => write!(f, "internal error (panic caught): {m}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_error_has_its_outcome_and_category() {
        let cases = [
            (
                Error::IllegalCall {
                    call: "fmi2DoStep".into(),
                    state: "Instantiated".into(),
                },
                Outcome::Failed,
                "illegal call sequence: fmi2DoStep is not allowed in state Instantiated",
            ),
            (
                Error::Argument("vr is NULL".into()),
                Outcome::Failed,
                "vr is NULL",
            ),
            (
                Error::Model("invalid FMU parameter Hs = -1".into()),
                Outcome::Failed,
                "invalid FMU parameter Hs = -1",
            ),
            (
                Error::Unsupported("no Jacobian"),
                Outcome::Failed,
                "not supported: no Jacobian",
            ),
            (
                Error::StatusUnavailable("no pending status".into()),
                Outcome::Unanswered,
                "status not available: no pending status",
            ),
            (
                Error::Discard("yaw outside the records".into()),
                Outcome::Discarded,
                "step discarded: yaw outside the records",
            ),
            (
                Error::Panic("boom".into()),
                Outcome::Failed,
                "internal error (panic caught): boom",
            ),
        ];
        for (error, outcome, text) in cases {
            assert_eq!(error.outcome(), outcome, "{error:?}");
            assert_eq!(error.to_string(), text);
        }
        assert_eq!(Outcome::Failed.category(), Category::StatusError);
        assert_eq!(Outcome::Discarded.category(), Category::StatusDiscard);
        assert_eq!(Outcome::Unanswered.category(), Category::StatusDiscard);
    }
}
