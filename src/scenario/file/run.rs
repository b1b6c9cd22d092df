//! The run: `[run]` (its times, its block and its memory limit) and `[initial]` (the state
//! it starts from).

use crate::error::Result;
use crate::scenario::{limits, InitialCondition, Run, DEFAULT_BLOCK_DURATION};
use serde::Deserialize;

/// Default RK4 time step, s.
pub const DEFAULT_TIME_STEP: f64 = 1.0;

/// `[run]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RunFile {
    /// s.
    duration: f64,
    /// s.
    #[serde(default = "default_time_step")]
    time_step: f64,
    /// s.
    #[serde(default)]
    start_time: f64,
    /// s.
    #[serde(default = "default_block_duration")]
    block_duration: f64,
    /// GB (1e9 bytes).
    #[serde(default = "default_memory_limit_gb")]
    memory_limit_gb: f64,
}

fn default_time_step() -> f64 {
    DEFAULT_TIME_STEP
}

fn default_block_duration() -> f64 {
    DEFAULT_BLOCK_DURATION
}

fn default_memory_limit_gb() -> f64 {
    limits::DEFAULT_MEMORY_LIMIT / crate::error::BYTES_PER_GB
}

impl RunFile {
    pub(super) fn into_core(self) -> Result<Run> {
        Ok(Run {
            duration: self.duration,
            time_step: self.time_step,
            start_time: self.start_time,
            block_duration: self.block_duration,
            memory_limit: limits::memory_limit_of_gb(self.memory_limit_gb)?,
        })
    }
}

/// `[initial]`, inertial frame.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub(super) struct InitialFile {
    /// X, Y in m.
    position: [f64; 2],
    /// Yaw angle theta, deg.
    heading_deg: f64,
    /// dX/dt, dY/dt in m/s.
    velocity: [f64; 2],
    /// d theta/dt, deg/s.
    yaw_rate_deg: f64,
}

impl InitialFile {
    pub(super) fn into_core(self) -> InitialCondition {
        let [x, y] = self.position;
        let [vx, vy] = self.velocity;
        InitialCondition {
            position: [x, y, self.heading_deg.to_radians()],
            velocity: [vx, vy, self.yaw_rate_deg.to_radians()],
        }
    }
}
