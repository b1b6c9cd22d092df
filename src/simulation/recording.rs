//! A run's steps to its end, and recording every one of them (a Monte Carlo run's
//! statistics): the output buffer reserved before the run, within the memory limit.

use crate::error::numbers::{readable, written};
use crate::error::{Error, Result};
use crate::problem::Problem;
use crate::scenario::limits;

/// The steps of `problem`'s run to its end, round(duration / time_step) (`slowdrift
/// simulate`'s, which keeps none of them). Refused, located where the user wrote the
/// duration, for an open-ended run (that is the FMU's).
pub fn run_steps(problem: &Problem) -> Result<u64> {
    let run = &problem.run;
    if !run.duration.is_finite() {
        return Err(problem.origins.locate(Error::invalid(
            "run.duration",
            run.duration,
            "is not finite: a run to its end has one (the FMU runs without one)",
        )));
    }
    // The problem's check bounds the duration where a double resolves the step.
    Ok((run.duration / run.time_step).round() as u64)
}

/// The steps of `problem`'s run when it keeps every step's output (a Monte Carlo run's
/// statistics), round(duration / time_step), with a buffer for them reserved in `buffer`
/// (one entry per sample: the steps and the initial state). Refused, located where the
/// user wrote the duration, for an open-ended run ([`run_steps`]) and for one whose samples
/// cannot be allocated.
pub fn reserve_recorded<T>(problem: &Problem, buffer: &mut Vec<T>) -> Result<usize> {
    let run = &problem.run;
    let refuse = |reason: String| {
        problem
            .origins
            .locate(Error::invalid("run.duration", run.duration, reason))
    };
    let steps = run_steps(problem)? as f64;
    let bytes = (steps + 1.0) * std::mem::size_of::<T>() as f64;
    if bytes > run.memory_limit {
        return Err(problem.origins.locate(limits::over_budget(
            "run.duration",
            run.duration,
            &format!(
                "the output of {} steps of {} s",
                readable(steps),
                written(run.time_step)
            ),
            bytes,
            run,
        )));
    }
    let samples = steps as usize + 1;
    if steps >= usize::MAX as f64 || buffer.try_reserve_exact(samples).is_err() {
        return Err(refuse(format!(
            "needs {} steps of {} s whose {} of output cannot be allocated",
            readable(steps),
            written(run.time_step),
            crate::error::bytes_text(steps * std::mem::size_of::<T>() as f64)
        )));
    }
    Ok(steps as usize)
}
