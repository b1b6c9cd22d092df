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

/// The elevation record of `config`'s sea (its seed) over `length` seconds: the record that
/// [`Simulation::new`] synthesises by one inverse FFT (E&S 6) for a run of that length,
/// its first `length / dt` samples. The drag kinematics are not built (they do not change
/// the elevation). Errors: `length` not positive, or what [`Simulation::new`] refuses.
pub fn elevation_record(config: &Problem, length: f64) -> Result<ElevationRecord> {
    require_positive("study.record_length", length)?;
    let mut config = config.clone();
    config.run.duration = length;
    config.model.drag = DragModel::Off;
    let sim = Simulation::new(config)?;
    let records = sim.records();
    let dt = records.clock.dt;
    let count = ((length / dt).round() as usize).min(records.elevation.samples().len());
    Ok(ElevationRecord {
        dt,
        samples: records.elevation.samples()[..count].to_vec(),
    })
}
