//! SlowDrift's errors in the words of the FMU's user, as errors of the FMI layer
//! ([`FmuError`], which decides their status and log category): a setting is named by its FMU
//! parameter where it has one, and records over the memory budget by `memoryLimit`.

use crate::error::{bytes_text, Error, Location, OverBudget, BYTES_PER_GB};
use crate::scenario::overrides;
use slowdrift_fmi::Error as FmuError;
use std::fmt;

/// A refusal of the core (an invalid configuration, an unreadable file, a diverging state).
impl From<Error> for FmuError {
    fn from(e: Error) -> Self {
        FmuError::Model(Words(&e).to_string())
    }
}

/// A step that cannot be completed while the instance stays usable, its state unchanged (the
/// yaw left the yaw-following records; a step longer than one block of the records).
pub fn discarded(e: Error) -> FmuError {
    FmuError::Discard(Words(&e).to_string())
}

/// An error as the FMU's user reads it.
struct Words<'a>(&'a Error);

impl fmt::Display for Words<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            Error::OverBudget(excess) if excess.at.is_some() => over_memory_limit(f, excess),
            e => e.describe(f, &fmu_name),
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
        let text = FmuError::from(diverged).to_string();
        assert!(text.ends_with("reduce the parameter stepSize"), "{text}");
        let yaw = discarded(Error::YawOutsideRecords {
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
