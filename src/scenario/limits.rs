//! The bounds on a scenario's sizes (issue #15): every count the user controls has an upper
//! bound, checked before anything is allocated or computed from it, and the memory a run
//! may take is limited by [`Run::memory_limit`] (the record plan estimates what its records
//! need against it, `record_plan::budget`).
//!
//! The counts' bounds are far beyond what the physics needs (the paper uses 15 directions
//! and 20 strips per column) and small enough that no size computed from them overflows
//! and no solver runs for hours before the memory budget is consulted.

use super::{DriftSource, Run, Scenario};
use crate::error::{Error, OverBudget, Result, BYTES_PER_GB, MEMORY_LIMIT_KEY};

/// Default [`Run::memory_limit`]: 4 GB (4e9 bytes), for a workstation that runs a few
/// simulations at once.
pub const DEFAULT_MEMORY_LIMIT: f64 = 4.0e9;

/// The largest number of discrete directions of a short-crested sea.
pub const MAX_DIRECTIONS: usize = 1000;
/// The largest number of Morison strips per column.
pub const MAX_STRIPS: usize = 1000;
/// The largest number of body yaw angles of yaw-following records.
pub const MAX_YAW_HEADINGS: usize = 3600;
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
    if !(run.memory_limit.is_finite() && run.memory_limit > 0.0) {
        return Err(Error::invalid(
            MEMORY_LIMIT_KEY,
            run.memory_limit / BYTES_PER_GB,
            "must be a finite number greater than zero",
        ));
    }
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
                grid.heading_step.to_degrees(),
                format!(
                    "makes {headings:.0} headings; at most {MAX_SOLVER_HEADINGS} (a step of at \
                     least {} deg)",
                    360.0 / MAX_SOLVER_HEADINGS as f64
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
    }
    Ok(())
}
