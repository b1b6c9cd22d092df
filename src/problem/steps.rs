//! The run's time step against the two spans it divides: a block of the record stream
//! (`run.block_duration`, at least [`MIN_BLOCK_STEPS`] steps and at most
//! [`MAX_BLOCK_SAMPLES`] samples at half a step) and the run (`run.duration`, at least one
//! step). A pair that does not fit is refused naming the one of the two the user wrote last
//! ([`crate::scenario::Origins::latest`]; the block, and the step against the duration,
//! where both were written alike): `time_step = 500` over the default block names
//! `time_step` with the largest step the block takes, not the block the user never wrote.

use super::Problem;
use crate::error::numbers::{readable, written};
use crate::error::{Error, Result};

/// The shortest block of the record stream, in RK4 steps (the cross-fade takes a quarter of
/// a block at most; `forces::stream`).
pub const MIN_BLOCK_STEPS: f64 = 64.0;

/// The longest block of the record stream, in samples (2^22: 24 days at 0.5 s, about 32 MiB
/// per record), so that a huge block is a clear error instead of an allocation failure.
pub const MAX_BLOCK_SAMPLES: f64 = 4_194_304.0;

const STEP: &str = "run.time_step";
const BLOCK: &str = "run.block_duration";
const DURATION: &str = "run.duration";

/// Checks the step against the block and the run (both positive, checked before).
pub fn check_steps(problem: &Problem) -> Result<()> {
    let run = &problem.run;
    let (step, block) = (run.time_step, run.block_duration);
    let blame_block = problem.origins.latest(&[BLOCK, STEP]) == BLOCK;
    let samples = block / (0.5 * step);
    if samples > MAX_BLOCK_SAMPLES {
        let held = "the records of one block are held at once";
        return Err(if blame_block {
            Error::invalid(
                BLOCK,
                block,
                format!(
                    "needs {} record samples at time_step/2; at most {MAX_BLOCK_SAMPLES} per \
                     block ({held}): at most {} s with time_step = {} s",
                    readable(samples.ceil()),
                    readable(MAX_BLOCK_SAMPLES * 0.5 * step),
                    written(step)
                ),
            )
        } else {
            Error::invalid(
                STEP,
                step,
                // Worded without the keys: the FMU names the step `stepSize` and has no
                // block to set.
                format!(
                    "must be at least {} s: it makes {} record samples (at half a step) in a \
                     block of the records ({} s), at most {MAX_BLOCK_SAMPLES} ({held})",
                    readable(2.0 * block / MAX_BLOCK_SAMPLES),
                    readable(samples.ceil()),
                    written(block)
                ),
            )
        });
    }
    if block < MIN_BLOCK_STEPS * step {
        return Err(if blame_block {
            Error::invalid(
                BLOCK,
                block,
                format!(
                    "must be at least {MIN_BLOCK_STEPS} time steps ({} s with time_step = {} s)",
                    readable(MIN_BLOCK_STEPS * step),
                    written(step)
                ),
            )
        } else {
            let largest = block / MIN_BLOCK_STEPS;
            Error::invalid(
                STEP,
                step,
                format!(
                    "must be at most {} s: a block of the records ({} s) holds at least \
                     {MIN_BLOCK_STEPS} steps",
                    readable(largest),
                    written(block)
                ),
            )
        });
    }
    Ok(())
}

/// Checks that the run is at least one step long (a finite duration; an open-ended run has
/// none to check).
pub fn check_duration(problem: &Problem) -> Result<()> {
    let run = &problem.run;
    if run.time_step <= run.duration {
        return Ok(());
    }
    Err(if problem.origins.latest(&[STEP, DURATION]) == DURATION {
        Error::invalid(
            DURATION,
            run.duration,
            format!(
                "is shorter than one time step ({} s); use a duration of at least {} s",
                written(run.time_step),
                written(run.time_step)
            ),
        )
    } else {
        Error::invalid(
            STEP,
            run.time_step,
            format!(
                "is longer than the run (duration {} s): at most {} s",
                written(run.duration),
                written(run.duration)
            ),
        )
    })
}
