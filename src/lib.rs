//! # SlowDrift
//!
//! Slow-drift motions (surge, sway, yaw) of moored floating platforms in random waves,
//! after Emmerhoff & Sclavounos, "The simulation of slow-drift motions of offshore
//! structures", Applied Ocean Research 18 (1996) 55-64 ("E&S n" = their equation n).
//!
//! Data flow (docs/architecture.md): a [`Scenario`] (what the user asked for: the TOML
//! reader [`scenario::file`], the embedded default, the override table
//! [`scenario::overrides`] that the FMU parameters and the case table write) is resolved
//! once into a [`Problem`] ([`problem::resolve`]: the hydrodynamic data of [`hydro`] read or
//! solved); [`RecordPlan`] and [`forces`] precompute the records at the mean position by
//! FFT, which [`dynamics`] (equations of motion, RK4) integrates; [`Simulation`] is the one
//! safe API over all of it, used by [`montecarlo`], [`studies`], the CLI and [`fmi2`], the
//! FMI 2.0 co-simulation C ABI. [`model`] is the vocabulary everything shares.
//!
//! Conventions (physics.md section 1): SI units and radians; inertial frame XYZ with Z up
//! and still water at Z = 0; the body frame follows the slow yaw theta; DOF order surge,
//! sway, yaw; wave direction beta = direction of propagation from +X, counter-clockwise;
//! a wave component is Re[a e^{i omega t}].

// Unsafe code: only `fmi2::exports` (the C ABI), the logger callback in `fmi2::logger` and
// the one `mallopt` call of `allocator` allow it (checked by tests/all/architecture.rs).
#![deny(unsafe_code)]

pub mod allocator;
pub mod dynamics;
pub mod error;
pub mod files;
mod fingerprint;
pub mod fmi2;
pub mod forces;
pub mod hydro;
pub mod model;
pub mod montecarlo;
mod parallel;
pub mod problem;
mod record_plan;
pub mod scenario;
pub mod sea_state;
mod simulation;
mod special;
pub mod stats;
pub mod studies;

pub use error::{Error, Result};
pub use problem::Problem;
pub use record_plan::{MemoryEstimate, PlanKey, QtfRank, RecordPlan, Term};
pub use scenario::Scenario;
pub use simulation::{bounds, Outputs, Simulation, Snapshot};
