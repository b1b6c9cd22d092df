//! The host's logger callback: error lines always (`logStatusError`), every call when the
//! host turned `logAll` on. The message goes out as the printf format with every `%`
//! doubled and no further argument, as SlowDrift's does: a C master's vsnprintf prints it
//! unchanged, and a master that reads only the format argument (fmpy's Python callback
//! type) still gets the text.

#![allow(unsafe_code)]

use super::types::{fmi2CallbackLogger, fmi2ComponentEnvironment, fmi2Status};
use super::variables::LOG_CATEGORIES;
use std::ffi::CString;

pub struct Logger {
    callback: Option<fmi2CallbackLogger>,
    environment: fmi2ComponentEnvironment,
    instance_name: CString,
    /// `logAll` turned on (fmi2Instantiate's loggingOn, or fmi2SetDebugLogging).
    pub log_all: bool,
}

/// Text for C: NUL bytes replaced, so that nothing is cut.
fn c_text(s: &str) -> CString {
    CString::new(s.replace('\0', "\\0")).expect("NUL bytes replaced")
}

impl Logger {
    pub fn new(
        callback: Option<fmi2CallbackLogger>,
        environment: fmi2ComponentEnvironment,
        instance_name: &str,
        log_all: bool,
    ) -> Logger {
        Logger {
            callback,
            environment,
            instance_name: c_text(instance_name),
            log_all,
        }
    }

    /// An error line (always sent).
    pub fn error(&self, message: &str) {
        self.send(fmi2Status::fmi2Error, LOG_CATEGORIES[0], message);
    }

    /// A call, when `logAll` is on.
    pub fn call(&self, message: &str) {
        if self.log_all {
            self.send(fmi2Status::fmi2OK, LOG_CATEGORIES[1], message);
        }
    }

    fn send(&self, status: fmi2Status, category: &str, message: &str) {
        let Some(callback) = self.callback else {
            return;
        };
        let (category, format) = (c_text(category), c_text(&message.replace('%', "%%")));
        // SAFETY: the host's callback with its environment pointer, NUL-terminated strings
        // that live across the call, and a format without conversions.
        unsafe {
            callback(
                self.environment,
                self.instance_name.as_ptr(),
                status,
                category.as_ptr(),
                format.as_ptr(),
            )
        }
    }
}
