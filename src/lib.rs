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
//! Conventions (docs/theory.md#conventions): SI units and radians; inertial frame XYZ with Z up
//! and still water at Z = 0; the body frame follows the slow yaw theta; DOF order surge,
//! sway, yaw; wave direction beta = direction of propagation from +X, counter-clockwise;
//! a wave component is Re[a e^{i omega t}].
//!
//! # Example
//!
//! The embedded default platform (the paper's four columns on pontoons) in its JONSWAP sea,
//! Hs 7 m, Tp 12 s, head seas: one hour, sampled every second, and the surge statistics after
//! a transient of 1000 s (five surge periods).
//!
//! ```
//! use slowdrift::{problem, scenario, stats, Simulation};
//!
//! let mut scenario = scenario::default::default_scenario()?; // what the user asks for
//! scenario.run.duration = 3600.0; // s
//! let problem = problem::resolve(&scenario)?; // its hydrodynamic data, read once
//! let mut simulation = Simulation::new(problem)?; // checked; the first block's records
//! let mut surge = vec![simulation.outputs()?.position[0]]; // X at t = 0, m
//! for _ in 0..3600 {
//!     simulation.advance(1.0, [0.0; 3])?; // 1 s, no external force (N, N, N m)
//!     surge.push(simulation.outputs()?.position[0]);
//! }
//! let summary = stats::summarize(&surge, 1.0, 1000.0)?;
//! // Waves push the platform on average down-wave (+X) and it oscillates about that.
//! assert!(summary.mean > 0.0 && summary.rms > 0.0 && summary.max > summary.mean);
//! # Ok::<(), slowdrift::Error>(())
//! ```

// Unsafe code: only the files docs/architecture.md lists allow it (the C ABI, the one
// `mallopt` call of `allocator`, the drag's AVX2 lanes; checked by tests/all/architecture.rs).
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
pub mod wind;

pub use error::{Error, Result};
pub use problem::Problem;
pub use record_plan::{MemoryEstimate, PlanKey, QtfRank, RecordPlan, Term};
pub use scenario::Scenario;
pub use simulation::{
    bounds, reserve_recorded, run_steps, Lockstep, Outputs, Simulation, Snapshot,
};
