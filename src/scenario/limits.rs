//! The bounds on a scenario's sizes: every count the user controls has an upper
//! bound, checked before anything is allocated or computed from it, and the memory a run
//! may take is limited by [`Run::memory_limit`] (the record plan estimates what its records
//! need against it, `record_plan::budget`).
//!
//! The counts' bounds are far beyond what the physics needs (the paper uses 15 directions
//! and 20 strips per column) and small enough that no size computed from them overflows;
//! the column-array solver's work is estimated and bounded too ([`MAX_SOLVER_MINUTES`]), so
//! that no solve runs for hours.

use super::{DriftSource, Run, Scenario};
use crate::error::numbers::readable;
use crate::error::{Error, OverBudget, Result, BYTES_PER_GB, MEMORY_LIMIT_KEY};

pub use crate::files::budget::{check_memory_limit, DEFAULT_MEMORY_LIMIT};

/// The largest memory limit a user may give, GB (a petabyte, beyond any machine): a larger
/// one would overflow in bytes and show as `inf`.
pub const MAX_MEMORY_LIMIT_GB: f64 = 1.0e6;

/// The memory limit in bytes of `gb` as the user gave it (`run.memory_limit_gb`, GB),
/// refused naming its value as written unless 0 < gb <= [`MAX_MEMORY_LIMIT_GB`].
pub fn memory_limit_of_gb(gb: f64) -> Result<f64> {
    if gb > 0.0 && gb <= MAX_MEMORY_LIMIT_GB {
        Ok(gb * BYTES_PER_GB)
    } else {
        Err(Error::invalid(
            MEMORY_LIMIT_KEY,
            gb,
            format!(
                "must be a number of GB greater than zero and at most {} (a petabyte)",
                readable(MAX_MEMORY_LIMIT_GB)
            ),
        ))
    }
}

/// The largest number of discrete directions of a short-crested sea (half a degree apart
/// over the half circle). The cross-direction terms cost D^2 per record component: 1000
/// directions took 7 minutes per block of records on a 2-core machine, 360 take about one
/// (the paper's Table 1 converges from 7).
pub const MAX_DIRECTIONS: usize = 360;
/// The largest number of Morison strips per column.
pub const MAX_STRIPS: usize = 1000;
/// The largest number of body yaw angles of yaw-following records (half a degree apart
/// around the circle; the default is 36).
pub const MAX_YAW_HEADINGS: usize = 720;
/// The largest number of columns of a platform.
pub const MAX_COLUMNS: usize = 100;
/// The largest number of frequencies of a column-solver grid (`[drift] n_omega`).
pub const MAX_SOLVER_FREQUENCIES: usize = 10_000;
/// The largest number of headings of a column-solver grid (360 / `heading_step_deg`).
pub const MAX_SOLVER_HEADINGS: usize = 3600;

/// Bytes of a column solver's drift table per (frequency, heading) node: the mean drift of
/// three DOFs and Aranha's 3 x 3 damping made from it, f64.
const SOLVER_NODE_BYTES: f64 = 12.0 * 8.0;

/// The error of a size beyond the memory limit: names the setting that drives it, its
/// value, the estimate and the limit.
pub fn over_budget(
    key: &str,
    value: impl std::fmt::Display,
    what: &str,
    bytes: f64,
    run: &Run,
) -> Error {
    Error::OverBudget(Box::new(OverBudget {
        field: key.to_string(),
        value: value.to_string(),
        at: None,
        needs: bytes,
        what: what.to_string(),
        limit: run.memory_limit,
    }))
}

/// Checks the memory limit itself and every count of `scenario` against its bound, and the
/// column solver's table (when the drift source is a solver) against the memory limit,
/// before any of them is used. Errors name the setting by its key.
pub fn check_sizes<H>(scenario: &Scenario<H>, source: Option<&DriftSource>) -> Result<()> {
    let run = &scenario.run;
    check_memory_limit(MEMORY_LIMIT_KEY, run.memory_limit)?;
    let count = |key: &str, value: usize, max: usize| {
        if value > max {
            Err(Error::invalid(key, value, format!("must be at most {max}")))
        } else {
            Ok(())
        }
    };
    count(
        "sea.n_directions",
        scenario.sea.n_directions,
        MAX_DIRECTIONS,
    )?;
    count(
        "model.strips_per_column",
        scenario.model.strips_per_column,
        MAX_STRIPS,
    )?;
    if let Some(yaw) = &scenario.model.yaw_following {
        count(
            "model.yaw_following.headings",
            yaw.headings,
            MAX_YAW_HEADINGS,
        )?;
    }
    count(
        "platform.columns",
        scenario.platform.columns.len(),
        MAX_COLUMNS,
    )?;
    if let Some(DriftSource::IsolatedColumns(grid) | DriftSource::ColumnArray { grid, .. }) = source
    {
        count("drift.n_omega", grid.n_omega, MAX_SOLVER_FREQUENCIES)?;
        let headings = 360.0 / grid.heading_step.to_degrees();
        // NaN (a zero or non-finite step) is refused here too.
        if headings.is_nan() || headings.round() > MAX_SOLVER_HEADINGS as f64 {
            return Err(Error::invalid(
                "drift.heading_step_deg",
                readable(grid.heading_step.to_degrees()),
                format!(
                    "makes {} headings; at most {MAX_SOLVER_HEADINGS} (a step of at least {} \
                     deg)",
                    readable(headings.round()),
                    readable(360.0 / MAX_SOLVER_HEADINGS as f64)
                ),
            ));
        }
        let bytes = grid.n_omega as f64 * headings.round() * SOLVER_NODE_BYTES;
        if bytes > run.memory_limit {
            return Err(over_budget(
                "drift.n_omega",
                grid.n_omega,
                &format!(
                    "the column solver's table of {} frequencies and {headings:.0} headings",
                    grid.n_omega
                ),
                bytes,
                run,
            ));
        }
        if let Some(DriftSource::ColumnArray { .. }) = source {
            let columns = scenario.platform.columns.len();
            let minutes = column_array_minutes(grid.n_omega, headings.round(), columns);
            if minutes > MAX_SOLVER_MINUTES {
                return Err(Error::invalid(
                    "drift.n_omega",
                    grid.n_omega,
                    format!(
                        "the column-array solver on {} frequencies x {headings:.0} headings x \
                         {columns} columns would take about {minutes:.0} minutes; at most \
                         {MAX_SOLVER_MINUTES} (fewer frequencies, headings or columns)",
                        grid.n_omega
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// The longest column-array solve accepted, minutes (estimated by
/// [`column_array_minutes`]).
pub const MAX_SOLVER_MINUTES: f64 = 10.0;

/// Seconds per unit of the column-array solver's work n_omega C^2 (C + H/4) (C columns, H
/// headings: a scattering system per frequency whose size grows with the columns, and the
/// drift of every heading from it), measured on a 2-core machine: 0.75 s for 100
/// frequencies x 36 headings x 4 columns, 4.0 s with 8 columns, 3.0 s with 400 frequencies,
/// 2.0 s with 144 headings; 32 s with 16 columns, where the cubic term grows faster (the
/// estimate says 23 s).
const SOLVER_SECONDS_PER_UNIT: f64 = 3.6e-5;

/// The estimated time of a column-array solve, minutes.
pub fn column_array_minutes(n_omega: usize, headings: f64, columns: usize) -> f64 {
    let c = columns as f64;
    n_omega as f64 * c * c * (c + headings / 4.0) * SOLVER_SECONDS_PER_UNIT / 60.0
}
