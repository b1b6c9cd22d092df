//! The host's logger callback, the instance name and the debug-logging categories. The
//! one call of the host's function pointer is this module's only `unsafe` code.

use super::fmu_error::FmuError;
use super::types::{fmi2CallbackLogger, fmi2ComponentEnvironment, fmi2Status};
use crate::fmi2::model_description::{log_category, LOG_CATEGORIES};
use std::ffi::CString;

/// The host's logger, the instance name and the debug-logging switches.
#[derive(Debug)]
pub struct Logger {
    callback: Option<fmi2CallbackLogger>,
    environment: fmi2ComponentEnvironment,
    name: CString,
    enabled: [bool; LOG_CATEGORIES.len()],
}

impl Logger {
    /// A logger that reports under `name` (interior NULs are replaced).
    pub fn new(
        callback: Option<fmi2CallbackLogger>,
        environment: fmi2ComponentEnvironment,
        name: &str,
        logging_on: bool,
    ) -> Logger {
        let mut enabled = [logging_on; LOG_CATEGORIES.len()];
        enabled[log_category::LOG_ALL] = false;
        Logger {
            callback,
            environment,
            name: c_text(name),
            enabled,
        }
    }

    /// Whether messages of `category` go to the host. Errors, warnings and discards always
    /// do (they say why a call did not return fmi2OK); events obey `loggingOn` and
    /// `fmi2SetDebugLogging`; the trace of every call (`logAll`, a line per call and so
    /// per step) only `fmi2SetDebugLogging`, which switches it on when it names it or names
    /// no category. `loggingOn = fmi2True` alone leaves it off: masters such as libcosim
    /// instantiate with logging on and write every line the FMU sends (FMI 2.0.4 section
    /// 2.1.5 leaves the categories that `loggingOn` enables to the FMU).
    pub fn enabled(&self, category: usize) -> bool {
        matches!(
            category,
            log_category::LOG_STATUS_ERROR
                | log_category::LOG_STATUS_WARNING
                | log_category::LOG_STATUS_DISCARD
        ) || self.enabled[category]
    }

    /// `fmi2SetDebugLogging`: no categories = all of them; an unknown one changes nothing
    /// and is an error.
    pub fn set(&mut self, on: bool, categories: &[&str]) -> Result<(), FmuError> {
        if categories.is_empty() {
            self.enabled = [on; LOG_CATEGORIES.len()];
            return Ok(());
        }
        let mut indices = Vec::with_capacity(categories.len());
        for c in categories {
            let i = LOG_CATEGORIES.iter().position(|k| k == c).ok_or_else(|| {
                FmuError::Argument(format!(
                    "unknown log category {c:?}; the categories are {LOG_CATEGORIES:?}"
                ))
            })?;
            indices.push(i);
        }
        for i in indices {
            self.enabled[i] = on;
        }
        Ok(())
    }

    /// Sends `message` under `category` if enabled. The message is the logger's printf
    /// format, so every `%` is doubled and no further arguments are passed (the standard's
    /// logger is variadic; a format without conversions needs none).
    pub fn log(&self, status: fmi2Status, category: usize, message: &str) {
        let Some(callback) = self.callback else {
            return;
        };
        if !self.enabled(category) {
            return;
        }
        let text = c_text(&message.replace('%', "%%"));
        let category = c_text(LOG_CATEGORIES[category]);
        #[allow(unsafe_code)]
        // SAFETY: the host gave this callback for this purpose; every pointer is a valid
        // NUL-terminated string that outlives the call.
        unsafe {
            callback(
                self.environment,
                self.name.as_ptr(),
                status,
                category.as_ptr(),
                text.as_ptr(),
            )
        };
    }
}

/// A C string of `s`, with interior NULs shown as `\0`.
pub(super) fn c_text(s: &str) -> CString {
    CString::new(s.replace('\0', "\\0")).expect("no interior NUL left")
}
