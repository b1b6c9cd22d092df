//! The mooring FMU's FMI 2.0 co-simulation model. The C types, the state machine, the
//! panic firewall, the handles of the host's pointers, the logger and the status policy are
//! the shared FMI layer's (the workspace's `slowdrift-fmi` crate, as for SlowDrift's FMU):
//! `exports` are the `fmi2*` symbols, thin shims into it, `exports_fmi3` the `fmi3*` ones
//! (the layer's macro), and `instance` is the model both run.

pub mod variables;

mod exports;
mod exports_fmi3;
mod instance;
