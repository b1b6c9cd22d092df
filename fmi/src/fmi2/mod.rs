//! The FMI 2.0 co-simulation layer, and no model:
//!
//! - [`types`]: the C types of the FMI 2.0 headers, written by hand (no bindings
//!   generator: plain cargo builds it);
//! - [`machine`]: the states of an instance and which call is allowed in which;
//! - `handle`: the host's pointers as Rust references (instances, saved states, arrays,
//!   outputs, strings): the crate's only pointer casts;
//! - `logger`: the host's logger callback under the category policy of [`crate::log`];
//! - [`model`]: the [`Model`] and [`SavedStates`] traits a model implements;
//! - `component`: an instance (logger, state, model) and the one report of a call's result;
//! - [`functions`]: the FMI 2.0 functions, generic over the model, each behind the
//!   [firewall](crate::firewall), which the cdylibs' `#[no_mangle] extern "C" fn fmi2*`
//!   shims call;
//! - `exports`: [`crate::fmi2_exports`], the macro that writes those shims in a cdylib.
//!
//! `exports.map` beside this file is the linker version script of every FMU's cdylib: the
//! `fmi2*` symbols global, everything else local.

pub(crate) mod component;
mod exports;
pub mod functions;
pub(crate) mod handle;
pub(crate) mod logger;
pub mod machine;
pub mod model;
pub mod types;

pub use model::{Context, Instantiation, Model, SavedStates};
