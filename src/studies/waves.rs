//! The wave elevation record of a configuration, for the elevation statistics of E&S
//! Figs 7 and 8 (pdf against the Gaussian, spectrum against the input).

use crate::error::{require_positive, Result};
use crate::model::DragModel;
use crate::problem::Problem;
use crate::Simulation;

/// A sampled elevation record at the body origin.
#[derive(Debug, Clone, PartialEq)]
pub struct ElevationRecord {
    /// Sample spacing, s (the records' h/2).
    pub dt: f64,
    /// eta(t_m), m, t_m = start_time + m dt, covering `length` seconds.
    pub samples: Vec<f64>,
}

/// The elevation record of `problem`'s sea (its seed) over `length` seconds: the elevation
/// records that [`Simulation::new`] synthesises (E&S 6: one inverse FFT per block of the
/// record stream, consecutive blocks joined by the cross-fade of `forces::stream`), taken
/// segment by segment, the first `length / dt` samples from t = 0. The drag kinematics are
/// not built (they do not change the elevation). Errors: `length` not positive, or what
/// [`Simulation::new`] refuses.
pub fn elevation_record(problem: &Problem, length: f64) -> Result<ElevationRecord> {
    require_positive("study.record_length", length)?;
    let mut problem = problem.clone();
    problem.run.duration = length;
    problem.model.drag = DragModel::Off;
    let mut sim = Simulation::new(problem)?;
    let block = sim.segments().block;
    let (start_time, dt) = (sim.grid().start_time, sim.grid().dt);
    let count = (length / dt).round() as usize;
    let mut samples = Vec::new();
    while samples.len() < count {
        // Global sample m = kB + j lies in segment k; its records start a halo earlier.
        let m = samples.len();
        let t = start_time + (m - m % block) as f64 * dt;
        let records = sim.records_at(t)?;
        let first = ((t - records.clock.start_time) / dt).round() as usize;
        let take = (count - m).min(block);
        samples.extend_from_slice(&records.elevation.samples()[first..first + take]);
    }
    Ok(ElevationRecord { dt, samples })
}
