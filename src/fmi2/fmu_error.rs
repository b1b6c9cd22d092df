//! Why an FMI call failed, and the one place that picks its `fmi2Status`.

use super::machine::{Call, MachineState};
use super::types::fmi2Status;
use crate::error::{bytes_text, Error, Location, OverBudget, BYTES_PER_GB};
use crate::scenario::overrides;
use std::fmt;

/// Why a call failed; [`FmuError::status`] is the one place that picks the `fmi2Status`.
#[derive(Debug, Clone, PartialEq)]
pub enum FmuError {
    /// The call is not allowed in the instance's current state.
    IllegalCall { call: Call, state: MachineState },
    /// A bad argument: NULL pointer, unknown value reference, wrong type, non-finite value.
    Argument(String),
    /// The core refused (invalid configuration, unreadable file, ...).
    Core(Error),
    /// A function this FMU does not implement, and why.
    Unsupported(&'static str),
    /// A status query this FMU cannot answer (FMI 2.0.4 section 4.2.3: "If a status is
    /// required which cannot be retrieved by the slave it returns fmi2Discard"); the
    /// instance's state does not change.
    StatusUnavailable(String),
    /// The step cannot be completed but the instance stays usable, its state unchanged (the
    /// yaw left the yaw-following records; a step longer than one block of the records).
    Discard(Error),
    /// A panic caught at the boundary.
    Panic(String),
}

impl FmuError {
    /// The status this error returns to the host.
    pub fn status(&self) -> fmi2Status {
        match self {
            FmuError::Discard(_) | FmuError::StatusUnavailable(_) => fmi2Status::fmi2Discard,
            _ => fmi2Status::fmi2Error,
        }
    }
}

impl From<Error> for FmuError {
    fn from(e: Error) -> Self {
        FmuError::Core(e)
    }
}

impl fmt::Display for FmuError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FmuError::IllegalCall { call, state } => write!(
                f,
                "illegal call sequence: {} is not allowed in state {state:?}",
                call.name()
            ),
            FmuError::Argument(m) => f.write_str(m),
            FmuError::Core(Error::OverBudget(excess)) if excess.at.is_some() => {
                over_memory_limit(f, excess)
            }
            FmuError::Core(e) => e.describe(f, &fmu_name),
            FmuError::Unsupported(why) => write!(f, "not supported: {why}"),
            FmuError::StatusUnavailable(why) => write!(f, "status not available: {why}"),
            FmuError::Discard(e) => {
                f.write_str("step discarded: ")?;
                e.describe(f, &fmu_name)
            }
            FmuError::Panic(m) => write!(f, "internal error (panic caught): {m}"),
        }
    }
}

/// Records over the memory budget because of a setting of the configuration file (the
/// embedded one, or `hydroDatabase`'s), which the FMU's user may not have written: named
/// by what they set, `memoryLimit`, with what it must be raised to, and the file's setting
/// that makes the estimate as the cause.
fn over_memory_limit(f: &mut fmt::Formatter<'_>, excess: &OverBudget) -> fmt::Result {
    let OverBudget {
        field,
        value,
        at,
        needs,
        what,
        limit,
    } = excess;
    let at = match at {
        Some(Location {
            path,
            line: Some(line),
        }) => format!("{path}:{line}"),
        Some(Location { path, line: None }) => path.clone(),
        None => String::new(),
    };
    write!(
        f,
        "invalid FMU parameter memoryLimit = {} ({}): the records need {} of memory ({what}, \
         from {field} = {value} in {at}); raise memoryLimit to at least {} (GB)",
        limit / BYTES_PER_GB,
        bytes_text(*limit),
        bytes_text(*needs),
        (needs / BYTES_PER_GB * 1000.0).ceil() / 1000.0
    )
}

/// A setting as the FMU's user sets it: its parameter, else its configuration key (set in
/// the `hydroDatabase` file).
fn fmu_name(key: &'static str) -> String {
    match overrides::by_key(key).and_then(|s| s.fmu) {
        Some(parameter) => format!("the parameter {parameter}"),
        None => format!("{key} (hydroDatabase file)"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A runtime error names its remedy by the FMU parameter; `Display` by the key.
    #[test]
    fn remedies_are_named_as_the_fmu_user_sets_them() {
        let diverged = Error::Unphysical {
            time: 3.0,
            what: "the state became X = NaN".into(),
            cause: crate::error::Cause::Step,
        };
        assert!(diverged.to_string().ends_with("reduce run.time_step"));
        let text = FmuError::Core(diverged).to_string();
        assert!(text.ends_with("reduce the parameter stepSize"), "{text}");
        let yaw = FmuError::Discard(Error::YawOutsideRecords {
            time: 10.0,
            yaw: 0.3,
            covered: (-0.2, 0.2),
        })
        .to_string();
        assert!(
            yaw.starts_with("step discarded: yaw 0.300000 rad")
                && yaw.ends_with("widen the parameter yawFollowingRange"),
            "{yaw}"
        );
    }
}
