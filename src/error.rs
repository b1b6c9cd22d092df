//! Typed errors of the core. Every variant names the offending field or input and its
//! value, so that a user (or the FMU's log) can tell exactly what to fix; numbers are
//! written by one rule ([`numbers`]).

pub mod numbers;

use numbers::{readable, Shown};
use std::fmt;

/// Everything that can go wrong in SlowDrift's core and its file readers.
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// A configuration value is out of range, not finite, or inconsistent.
    InvalidValue {
        /// The setting: its configuration-file key path (`sea.hs`), or, once located by the
        /// scenario's origins, its name where the user wrote it (`[sea] hs`, `FMU parameter
        /// Hs`, `row 3, column 'hs'`).
        field: String,
        /// The offending value, as text, in the units of the name.
        value: String,
        /// Why it is refused.
        reason: String,
        /// The file and line where the value was written, when known.
        at: Option<Location>,
    },
    /// A size beyond the memory budget ([`OverBudget`]).
    OverBudget(Box<OverBudget>),
    /// Memory within the budget that this process cannot allocate (its own limit, a
    /// container's or the machine's is lower than the budget).
    OutOfMemory {
        /// Bytes, the estimate that could not be allocated.
        needs: f64,
        /// The memory limit, bytes.
        limit: f64,
    },
    /// Reading a file would take more memory than the limit allows, or than this process
    /// can allocate ([`FileOverBudget`]).
    FileOverBudget(Box<FileOverBudget>),
    /// A file could not be read or written.
    Io { path: String, message: String },
    /// A file could be read but not understood (`line` is 1-based when known).
    Parse {
        path: String,
        line: Option<usize>,
        message: String,
    },
    /// An input handed to a running simulation is NaN or infinite.
    NonFiniteInput { field: String, value: f64 },
    /// A time past the last sample of a set of records (a segment read outside its span).
    BeyondRecord { time: f64, record_end: f64 },
    /// A time before the run's start, where there are no records.
    BeforeStart { time: f64, start: f64 },
    /// The state or an output became non-finite or left the bounds of a physical state
    /// (`simulation::bounds`): `what` says which value, `cause` which force, input or
    /// setting made it.
    Unphysical {
        time: f64,
        what: String,
        cause: Cause,
    },
    /// A time where a double no longer resolves the step (`problem::time_resolved`): the
    /// run cannot go on.
    TimeUnresolved { time: f64, step: f64 },
    /// The body's yaw left the range covered by the yaw-following records (rad); they are
    /// never extrapolated.
    YawOutsideRecords {
        time: f64,
        yaw: f64,
        covered: (f64, f64),
    },
}

impl Error {
    /// Shorthand for [`Error::InvalidValue`].
    pub fn invalid(field: impl Into<String>, value: impl Shown, reason: impl Into<String>) -> Self {
        Error::InvalidValue {
            field: field.into(),
            value: value.shown(),
            reason: reason.into(),
            at: None,
        }
    }
}

impl Error {
    /// The message, with the setting whose change avoids the error (the errors of a running
    /// simulation) named by `name` from its configuration-file key: `Display` names the key,
    /// the FMU its parameter.
    pub fn describe(
        &self,
        f: &mut fmt::Formatter<'_>,
        name: &dyn Fn(&'static str) -> String,
    ) -> fmt::Result {
        match self {
            Error::InvalidValue {
                field,
                value,
                reason,
                at,
            } => {
                write_location(f, at)?;
                write!(f, "invalid {field} = {value}: {reason}")
            }
            Error::OverBudget(excess) => {
                let OverBudget {
                    field,
                    value,
                    at,
                    needs,
                    what,
                    limit,
                } = excess.as_ref();
                write_location(f, at)?;
                write!(
                    f,
                    "invalid {field} = {value}: needs {} of memory ({what}); the limit is {} \
                     ({} = {})",
                    bytes_text(*needs),
                    bytes_text(*limit),
                    name(MEMORY_LIMIT_KEY),
                    readable(limit / BYTES_PER_GB)
                )
            }
            Error::OutOfMemory { needs, limit } => write!(
                f,
                "the records need {} and this process cannot allocate them: its own memory \
                 limit (ulimit, a container) or the machine's is lower than {} = {} GB",
                bytes_text(*needs),
                name(MEMORY_LIMIT_KEY),
                readable(limit / BYTES_PER_GB)
            ),
            Error::FileOverBudget(excess) => {
                let FileOverBudget {
                    path,
                    what,
                    needs,
                    limit,
                    process,
                } = excess.as_ref();
                write!(
                    f,
                    "{path}: reading it needs {} of memory ({what})",
                    bytes_text(*needs)
                )?;
                if *process {
                    write!(
                        f,
                        " and this process cannot allocate them: its own memory limit (ulimit, \
                         a container) or the machine's is lower than {} = {} GB",
                        name(MEMORY_LIMIT_KEY),
                        limit / BYTES_PER_GB
                    )
                } else {
                    write!(
                        f,
                        "; the limit is {} ({} = {})",
                        bytes_text(*limit),
                        name(MEMORY_LIMIT_KEY),
                        limit / BYTES_PER_GB
                    )
                }
            }
            Error::Io { path, message } => write!(f, "{path}: {message}"),
            Error::Parse {
                path,
                line: Some(line),
                message,
            } => write!(f, "{path}:{line}: {message}"),
            Error::Parse {
                path,
                line: None,
                message,
            } => write!(f, "{path}: {message}"),
            Error::NonFiniteInput { field, value } => {
                write!(f, "input {field} = {value} is not finite; refused")
            }
            Error::BeyondRecord { time, record_end } => write!(
                f,
                "time {} s is past the end of the records ({} s)",
                readable(*time),
                readable(*record_end)
            ),
            Error::BeforeStart { time, start } => write!(
                f,
                "time {} s is before the start of the run ({} s)",
                readable(*time),
                readable(*start)
            ),
            Error::Unphysical { time, what, cause } => {
                write!(f, "{what} at t = {} s: ", readable(*time))?;
                cause.describe(f, name)
            }
            Error::TimeUnresolved { time, step } => write!(
                f,
                "the run reached t = {} s, where a double resolves time only to {} s: too \
                 coarse for steps of {} s ({}); the run cannot go on",
                readable(*time),
                readable(time.abs() * f64::EPSILON),
                readable(*step),
                name("run.time_step")
            ),
            Error::YawOutsideRecords { time, yaw, covered } => write!(
                f,
                "yaw {yaw:.6} rad ({:.4} deg) at t = {} s is outside the yaw-following \
                 records' range [{:.6}, {:.6}] rad ([{:.4}, {:.4}] deg; never extrapolated); \
                 widen {}",
                yaw.to_degrees(),
                readable(*time),
                covered.0,
                covered.1,
                covered.0.to_degrees(),
                covered.1.to_degrees(),
                name("model.yaw_following.range_deg")
            ),
        }
    }
}

/// `path:line: `, `path: ` or nothing.
fn write_location(f: &mut fmt::Formatter<'_>, at: &Option<Location>) -> fmt::Result {
    match at {
        Some(Location {
            path,
            line: Some(line),
        }) => write!(f, "{path}:{line}: "),
        Some(Location { path, line: None }) => write!(f, "{path}: "),
        None => Ok(()),
    }
}

/// The configuration key of the memory limit (`run.memory_limit_gb`, GB).
pub const MEMORY_LIMIT_KEY: &str = "run.memory_limit_gb";

/// Bytes in the unit of [`MEMORY_LIMIT_KEY`] (decimal gigabytes).
pub const BYTES_PER_GB: f64 = 1.0e9;

/// A memory size for a message: "302 GB", "12.500 MB".
pub fn bytes_text(bytes: f64) -> String {
    let (scale, unit) = [(1e12, "TB"), (1e9, "GB"), (1e6, "MB"), (1e3, "kB")]
        .into_iter()
        .find(|&(scale, _)| bytes >= scale)
        .unwrap_or((1.0, "bytes"));
    let value = bytes / scale;
    if value >= 100.0 || scale == 1.0 {
        format!("{value:.0} {unit}")
    } else {
        format!("{value:.3} {unit}")
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.describe(f, &|key| key.to_string())
    }
}

impl std::error::Error for Error {}

/// A place in a file: the file's name and, when known, the 1-based line.
#[derive(Debug, Clone, PartialEq)]
pub struct Location {
    pub path: String,
    pub line: Option<usize>,
}

impl Location {
    /// A parse error at this place.
    pub fn error(&self, message: impl Into<String>) -> Error {
        Error::Parse {
            path: self.path.clone(),
            line: self.line,
            message: message.into(),
        }
    }
}

/// What made a state or an output unphysical ([`Error::Unphysical`]).
#[derive(Debug, Clone, PartialEq)]
pub enum Cause {
    /// A force at the step's start (inertial frame): not finite, or enough alone to change
    /// the velocity beyond its bound within the step. `dof`: 0 X, 1 Y, 2 yaw; `settings`:
    /// the configuration keys it grows with.
    Force {
        force: &'static str,
        dof: usize,
        value: f64,
        settings: &'static [&'static str],
    },
    /// The external force input, likewise.
    External { dof: usize, value: f64 },
    /// Nothing at the step's start explains it: the step is too large for the system.
    Step,
}

impl Cause {
    fn describe(
        &self,
        f: &mut fmt::Formatter<'_>,
        name: &dyn Fn(&'static str) -> String,
    ) -> fmt::Result {
        const DOF: [(&str, &str); 3] = [("X", "N"), ("Y", "N"), ("yaw", "N m")];
        match self {
            Cause::Force {
                force,
                dof,
                value,
                settings,
            } => {
                let (axis, unit) = DOF[*dof];
                let names: Vec<String> = settings.iter().map(|key| name(key)).collect();
                write!(
                    f,
                    "the {force} there is {} {unit} in {axis}, enough alone to leave the \
                     bounds within a step; it grows with {}",
                    readable(*value),
                    names.join(", ")
                )
            }
            Cause::External { dof, value } => {
                let (axis, unit) = DOF[*dof];
                write!(
                    f,
                    "the external force input there is {} {unit} in {axis}, enough alone to \
                     leave the bounds within a step",
                    readable(*value)
                )
            }
            Cause::Step => write!(f, "reduce {}", name("run.time_step")),
        }
    }
}

/// A size beyond the memory budget: the setting that drives the largest part of the
/// estimate (named and located as [`Error::InvalidValue`]'s), what the estimate holds, and
/// the limit (the setting [`MEMORY_LIMIT_KEY`]).
#[derive(Debug, Clone, PartialEq)]
pub struct OverBudget {
    pub field: String,
    pub value: String,
    pub at: Option<Location>,
    /// The estimated memory, bytes.
    pub needs: f64,
    /// What the estimate is made of (its largest part).
    pub what: String,
    /// The memory limit, bytes.
    pub limit: f64,
}

/// A file whose reading would take more memory than allowed: its size times the most its
/// reader holds per byte, or what its content makes (a QTF's frequency grid), against the
/// limit (the setting [`MEMORY_LIMIT_KEY`]); or within the limit, but more than this process
/// can allocate.
#[derive(Debug, Clone, PartialEq)]
pub struct FileOverBudget {
    pub path: String,
    /// What the estimate is made of (the file's size and format, or its content).
    pub what: String,
    /// The estimated memory, bytes.
    pub needs: f64,
    /// The memory limit, bytes.
    pub limit: f64,
    /// Within the limit, but this process cannot allocate it.
    pub process: bool,
}

/// Result with the core's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;

/// The message of a caught panic's payload (`panic!` with a literal or a formatted text).
pub(crate) fn panic_message(payload: &(dyn std::any::Any + Send)) -> Option<String> {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
}

/// Checks that `value` is finite and strictly positive.
pub fn require_positive(field: &str, value: f64) -> Result<()> {
    require_finite(field, value)?;
    if value > 0.0 {
        Ok(())
    } else {
        Err(Error::invalid(field, value, "must be greater than zero"))
    }
}

/// Checks that `value` is finite and not negative.
pub fn require_non_negative(field: &str, value: f64) -> Result<()> {
    require_finite(field, value)?;
    if value >= 0.0 {
        Ok(())
    } else {
        Err(Error::invalid(field, value, "must not be negative"))
    }
}

/// Checks that `value` is neither NaN nor infinite.
pub fn require_finite(field: impl fmt::Display, value: f64) -> Result<()> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(Error::invalid(
            field.to_string(),
            value,
            "must be a finite number",
        ))
    }
}

/// Checks every entry of a square matrix (3x3, 6x6) for finiteness, naming the entry on
/// failure.
pub fn require_finite_matrix<const N: usize>(
    field: impl fmt::Display,
    m: &[[f64; N]; N],
) -> Result<()> {
    for (i, row) in m.iter().enumerate() {
        for (j, v) in row.iter().enumerate() {
            require_finite(format_args!("{field}[{i}][{j}]"), *v)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_read_in_their_units() {
        assert_eq!(bytes_text(3.02e11), "302 GB");
        assert_eq!(bytes_text(4.0e9), "4.000 GB");
        assert_eq!(bytes_text(12.5e6), "12.500 MB");
        assert_eq!(bytes_text(512.0), "512 bytes");
    }
}
