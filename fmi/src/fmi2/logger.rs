//! The host's FMI 2.0 logger callback, the instance name and the category switches
//! ([`crate::log`]). The one call of the host's function pointer is this module's only
//! `unsafe` code.

#![allow(unsafe_code)]
#![deny(clippy::undocumented_unsafe_blocks)]

use super::types::{fmi2CallbackLogger, fmi2ComponentEnvironment, fmi2Status};
use crate::log::{Category, Switches};
use crate::text::c_text;
use crate::Error;
use std::ffi::CString;

/// The host's logger, the instance name and which categories reach the host.
#[derive(Debug)]
pub struct Logger {
    callback: Option<fmi2CallbackLogger>,
    environment: fmi2ComponentEnvironment,
    name: CString,
    switches: Switches,
}

impl Logger {
    /// A logger that reports under `name` (interior NULs are shown as `\0`).
    pub(crate) fn new(
        callback: Option<fmi2CallbackLogger>,
        environment: fmi2ComponentEnvironment,
        name: &str,
        logging_on: bool,
    ) -> Logger {
        Logger {
            callback,
            environment,
            name: c_text(name),
            switches: Switches::new(logging_on),
        }
    }

    /// Whether lines of `category` reach the host.
    pub fn enabled(&self, category: Category) -> bool {
        self.switches.enabled(category)
    }

    /// `fmi2SetDebugLogging`.
    pub(crate) fn set(&mut self, on: bool, categories: &[&str]) -> Result<(), Error> {
        self.switches.set(on, categories)
    }

    /// An event line (`logEvents`).
    pub fn event(&self, message: &str) {
        self.log(fmi2Status::fmi2OK, Category::Events, message);
    }

    /// Sends `message` under `category` if enabled. The message is the logger's printf
    /// format, so every `%` is doubled and no further arguments are passed (the standard's
    /// logger is variadic; a format without conversions needs none, and a master that reads
    /// only the format, as fmpy's Python callback does, still gets the text).
    pub fn log(&self, status: fmi2Status, category: Category, message: &str) {
        let Some(callback) = self.callback else {
            return;
        };
        if !self.enabled(category) {
            return;
        }
        let text = c_text(&message.replace('%', "%%"));
        let category = c_text(category.name());
        // SAFETY: the host gave this callback for this purpose, with its environment
        // pointer; every string is NUL-terminated and outlives the call, and the format has
        // no conversion, so no variadic argument is read.
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
