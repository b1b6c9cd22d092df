//! Subcommands of the `slowdrift` tool other than `simulate`.

pub mod args;
pub mod hydro;
pub mod montecarlo;
pub mod study;
