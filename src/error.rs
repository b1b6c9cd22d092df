//! Typed errors of the core. Every variant names the offending field or input and its
//! value, so that a user (or the FMU's log) can tell exactly what to fix.

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
    /// The state became NaN or infinite (the step is too large for the system).
    Diverged { time: f64 },
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
    pub fn invalid(
        field: impl Into<String>,
        value: impl fmt::Display,
        reason: impl Into<String>,
    ) -> Self {
        Error::InvalidValue {
            field: field.into(),
            value: value.to_string(),
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
                match at {
                    Some(Location {
                        path,
                        line: Some(line),
                    }) => write!(f, "{path}:{line}: ")?,
                    Some(Location { path, line: None }) => write!(f, "{path}: ")?,
                    None => {}
                }
                write!(f, "invalid {field} = {value}: {reason}")
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
                "time {time} s is past the end of the records ({record_end} s)"
            ),
            Error::BeforeStart { time, start } => write!(
                f,
                "time {time} s is before the start of the run ({start} s)"
            ),
            Error::Diverged { time } => write!(
                f,
                "the state became non-finite at t = {time} s; reduce {}",
                name("run.time_step")
            ),
            Error::YawOutsideRecords { time, yaw, covered } => write!(
                f,
                "yaw {yaw:.6} rad ({:.4} deg) at t = {time} s is outside the yaw-following \
                 records' range [{:.6}, {:.6}] rad ([{:.4}, {:.4}] deg; never extrapolated); \
                 widen {}",
                yaw.to_degrees(),
                covered.0,
                covered.1,
                covered.0.to_degrees(),
                covered.1.to_degrees(),
                name("model.yaw_following.range_deg")
            ),
        }
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

/// Checks every entry of a 3x3 matrix for finiteness, naming the entry on failure.
pub fn require_finite_matrix(field: impl fmt::Display, m: &[[f64; 3]; 3]) -> Result<()> {
    for (i, row) in m.iter().enumerate() {
        for (j, v) in row.iter().enumerate() {
            require_finite(format_args!("{field}[{i}][{j}]"), *v)?;
        }
    }
    Ok(())
}
