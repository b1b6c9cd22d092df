//! The mooring FMU's FMI 2.0 C ABI. The C types and the state machine are SlowDrift's
//! (model-agnostic files of the workspace root's `src/fmi2`, compiled here as this crate's
//! own modules): one source for the standard's types and its table of allowed calls.

#[path = "../../../src/fmi2/machine.rs"]
pub mod machine;
#[path = "../../../src/fmi2/types.rs"]
pub mod types;
pub mod variables;

mod exports;
mod instance;
mod logger;
