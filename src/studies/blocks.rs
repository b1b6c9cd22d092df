//! Statistics of consecutive blocks of a record: how the slow-drift statistics settle
//! after the start (E&S Fig. 11 uses blocks of ten slow-drift cycles).

use crate::error::numbers::readable;
use crate::error::{require_positive, Error, Result};
use crate::stats::{summarize, Summary};

/// [`Summary`] (mean, rms about the block's own mean, extremes) of each whole block of
/// `block` seconds of `record` (sampled every `dt` s, sample m at t = m dt): block b holds
/// the samples with b block <= t < (b + 1) block. A last partial block is dropped.
///
/// Errors: `dt` or `block` not positive, a block shorter than two samples, a record shorter
/// than one block, or a non-finite sample.
pub fn block_summaries(record: &[f64], dt: f64, block: f64) -> Result<Vec<Summary>> {
    require_positive("blocks.dt", dt)?;
    require_positive("blocks.block", block)?;
    let per_block = (block / dt).round() as usize;
    if per_block < 2 {
        return Err(Error::invalid(
            "blocks.block",
            block,
            format!("holds fewer than 2 samples at dt = {} s", readable(dt)),
        ));
    }
    if record.len() < per_block {
        return Err(Error::invalid(
            "blocks.block",
            block,
            format!(
                "is longer than the record ({} samples at dt = {} s)",
                record.len(),
                readable(dt)
            ),
        ));
    }
    record
        .chunks_exact(per_block)
        .map(|chunk| summarize(chunk, dt, 0.0))
        .collect()
}
