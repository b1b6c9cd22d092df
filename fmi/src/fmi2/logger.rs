//! The host's logger callback (FMI 2.0's, or FMI 3.0's `fmi3LogMessageCallback`), the
//! instance name and the category switches ([`crate::log`]). The calls of the host's
//! function pointers are this module's only `unsafe` code.

#![allow(unsafe_code)]
#![deny(clippy::undocumented_unsafe_blocks)]

use super::types::{fmi2CallbackLogger, fmi2ComponentEnvironment, fmi2Status};
use crate::fmi3::types::{fmi3InstanceEnvironment, fmi3LogMessageCallback, fmi3Status};
use crate::log::{Category, Switches};
use crate::text::c_text;
use crate::Error;
use std::ffi::CString;

/// The host's logger, the instance name and which categories reach the host.
#[derive(Debug)]
pub struct Logger {
    host: Option<Host>,
    name: CString,
    switches: Switches,
}

/// The host's callback and its environment pointer, by FMI version.
#[derive(Debug)]
enum Host {
    /// FMI 2.0: (environment, instance name, status, category, printf format, ...).
    Fmi2(fmi2CallbackLogger, fmi2ComponentEnvironment),
    /// FMI 3.0: (environment, status, category, message), the message as it is.
    Fmi3(fmi3LogMessageCallback, fmi3InstanceEnvironment),
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
            host: callback.map(|c| Host::Fmi2(c, environment)),
            name: c_text(name),
            switches: Switches::new(logging_on),
        }
    }

    /// An FMI 3.0 host's logger (`logMessage` may be NULL: nothing is sent); `name` is
    /// kept for the messages that name the instance.
    pub(crate) fn fmi3(
        callback: Option<fmi3LogMessageCallback>,
        environment: fmi3InstanceEnvironment,
        name: &str,
        logging_on: bool,
    ) -> Logger {
        Logger {
            host: callback.map(|c| Host::Fmi3(c, environment)),
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
    /// An FMI 3.0 host gets the message as it is, with the status of the same number.
    pub fn log(&self, status: fmi2Status, category: Category, message: &str) {
        let Some(host) = &self.host else {
            return;
        };
        if !self.enabled(category) {
            return;
        }
        let category = c_text(category.name());
        match *host {
            Host::Fmi2(callback, environment) => {
                let text = c_text(&message.replace('%', "%%"));
                // SAFETY: the host gave this callback for this purpose, with its environment
                // pointer; every string is NUL-terminated and outlives the call, and the
                // format has no conversion, so no variadic argument is read.
                unsafe {
                    callback(
                        environment,
                        self.name.as_ptr(),
                        status,
                        category.as_ptr(),
                        text.as_ptr(),
                    )
                };
            }
            Host::Fmi3(callback, environment) => {
                let text = c_text(message);
                // SAFETY: the host gave this callback for this purpose, with its environment
                // pointer; both strings are NUL-terminated and outlive the call.
                unsafe {
                    callback(
                        environment,
                        fmi3Status::from(status),
                        category.as_ptr(),
                        text.as_ptr(),
                    )
                };
            }
        }
    }
}
