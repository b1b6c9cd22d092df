//! The model-free FMI layer of SlowDrift's FMUs (`slowdrift` and `slowdrift-mooring`): what
//! every FMU needs between the host's C calls and its model, written once.
//!
//! Independent of the FMI version:
//! - [`error`]: why a call failed ([`Error`]), and the one policy that decides its outcome
//!   (status and log category);
//! - [`firewall`]: `catch_unwind` around every call, a panic made an [`Error::Panic`];
//! - [`machine`]: the check of a call against a version's table of allowed calls;
//! - [`log`]: the log categories and which of them reach the host;
//! - [`resource_location`]: the local path of `fmuResourceLocation` (a `file:` URI);
//! - [`text`]: Rust text as C text.
//!
//! FMI 2.0 ([`fmi2`]): its C types, its call-state machine, the typed handles that turn the
//! host's pointers into references (the crate's only pointer casts), its logger, the
//! [`fmi2::Model`] trait a model implements and the functions the cdylibs' `fmi2*` shims call.
//!
//! FMI 3.0 ([`fmi3`]): a thin adapter beside it on the same instance (model, state machine,
//! logger, error, firewall and log policy): its C types, its call table, its functions and
//! the macro [`fmi3_exports`] that makes a cdylib's 75 `fmi3*` shims.
//!
//! The crate exports no symbol: it has no `#[no_mangle]` item (the macro's shims are
//! expanded in the cdylib), and each FMU's cdylib exports only its own `fmi2*` and `fmi3*`
//! functions (the linker version script `src/fmi2/exports.map`, which the cdylibs' build
//! scripts pass).

// Unsafe code: only the handles (`fmi2::handle`), the host's logger callback
// (`fmi2::logger`) and the functions that take the host's pointers (`fmi2::functions`,
// `fmi3::functions`) allow it (checked by the workspace's tests/all/architecture.rs).
#![deny(unsafe_code)]

pub mod error;
pub mod firewall;
pub mod fmi2;
pub mod fmi3;
pub mod log;
pub mod machine;
pub mod resource_location;
pub mod text;

pub use error::Error;
