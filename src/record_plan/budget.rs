//! The memory a problem's records take, estimated before any of it is allocated, against
//! the run's memory limit (`run.memory_limit_gb`, [`crate::scenario::limits`]).
//!
//! The estimate adds the buffers the plan and a simulation hold at their peak, from the
//! sizes they are made with: L samples per record (the stream segment's span at h/2), G
//! wave components (the band on the grid), D directions, Y yaw-following headings, C drag
//! columns of S strips, the full QTF's n data frequencies. Each term is an upper bound of
//! what the code allocates for it (f64 = 8 bytes, complex f64 = 16, the kinematics in
//! single precision: 4 per float of a row, 8 per complex sample of a depth term's series);
//! `tests/all/budget.rs` checks that the estimate bounds the peak the counting allocator
//! measures while a simulation is made, and is within a small factor of it, over
//! configurations that stress each term. The data the problem already holds (its drift
//! table, QTF, bi-directional table) are not counted: they were bounded by the file-size
//! limit when read.
//!
//! Once the estimate is within the limit, the memory is reserved and released again
//! ([`MemoryEstimate::check`]): a process whose own limit (`setrlimit`, a container) leaves
//! less room gets a typed error here instead of an allocation failure later, which would
//! abort the process (and, in an FMU, the master with it).

use crate::error::numbers::written;
use crate::error::{bytes_text, Error, Result};
use crate::forces::{
    distinct_kinematics, kinematics_row_floats, refine, Halves, MAX_RANK, ROWS_WINDOW,
};
use crate::hydro::bidirectional::BidirectionalSource;
use crate::model::{DragModel, Interaction, Mode, NewmanForm, SecondOrder, WaveFrequencyMotion};
use crate::problem::Problem;
use crate::scenario::limits::over_budget;
use crate::sea_state::FrequencyGrid;

const F64: f64 = 8.0;
const C64: f64 = 16.0;
/// Bytes of one float of a kinematics row.
const F32: f64 = 4.0;
/// Bytes of one sample of a depth term's series (single-precision complex).
const C32: f64 = 8.0;
/// Records of the force (3) and the damping (3 x 3) per set, and the elevation.
const FORCE_AND_DAMPING: f64 = 12.0;

/// Frequencies of the embedded default platform's bi-directional table (checked against
/// the table by a test), which the estimate cannot read without parsing it.
pub const EMBEDDED_BIDIRECTIONAL_OMEGAS: usize = 75;

/// The estimated peak memory of a problem's records, bytes, by what drives it.
#[derive(Debug, Clone, PartialEq)]
pub struct MemoryEstimate {
    /// The plan's share, held once for every simulation it serves.
    pub plan: f64,
    /// One simulation's records and buffers.
    pub per_run: f64,
    /// The largest term: the setting that drives it (its key and value) and what it is.
    pub largest: Term,
}

/// One term of an estimate.
#[derive(Debug, Clone, PartialEq)]
pub struct Term {
    pub key: &'static str,
    pub value: String,
    pub what: String,
    pub bytes: f64,
}

impl MemoryEstimate {
    /// The estimate for a checked problem (its counts bounded, `Problem::check`).
    pub fn of(problem: &Problem) -> Result<MemoryEstimate> {
        let dt = 0.5 * problem.run.time_step;
        let segments = super::segments_of(problem.run.block_duration, dt);
        let grid = FrequencyGrid::new(
            problem.run.start_time,
            segments.span() as f64 * dt,
            dt,
            problem.band(),
        )?;
        let l = grid.len as f64;
        let g = grid.count as f64;
        let directions = problem.sea.directions();
        let d = directions.len() as f64;
        let model = &problem.model;
        // The stream's join (`forces::stream`) keeps the tail of every linear series of a
        // segment for the next: each term below adds its series' tails.
        let tail = segments.tail_len() as f64 * C64;
        // Linear series per direction and set of records: Newman's P+ and P- of the force
        // and damping records (the geometric form; the arithmetic form has one and the
        // elevation).
        let newman_series = 2.0 * FORCE_AND_DAMPING + 1.0;
        let mut plan = Vec::new();
        let mut run = Vec::new();
        // The records of a block grow with block_duration / time_step: named by the one of
        // the two the user wrote last.
        let block_key = problem
            .origins
            .latest(&["run.block_duration", "run.time_step"]);
        let block = || {
            written(match block_key {
                "run.time_step" => problem.run.time_step,
                _ => problem.run.block_duration,
            })
        };
        // The planned transform (twiddles and its scratch) and the per-direction drift and
        // damping coefficients on the grid.
        plan.push(term(block_key, block(), "the planned FFT", 2.0 * C64 * l));
        // (And the scale of every component's draw, kept for the plan's seeds.)
        plan.push(term(
            "sea.n_directions",
            problem.sea.n_directions.to_string(),
            format!("{d} directions' coefficients on {g} components"),
            d * (FORCE_AND_DAMPING + 1.0) * F64 * g,
        ));
        // The synthesizer's scratch, join and pair buffers, the full QTF's series, the
        // elevation and force and damping records, the wave components; the arithmetic
        // form's Newman series and elevation series.
        let arithmetic = match problem.model.newman {
            NewmanForm::Arithmetic => 2.0,
            NewmanForm::Geometric => 0.0,
        };
        let series =
            (4.0 + arithmetic) * C64 * l + (1.0 + FORCE_AND_DAMPING) * F64 * l + 4.0 * C64 * g;
        run.push(term(
            block_key,
            block(),
            "the records of one block",
            series + tail,
        ));
        let refines = refine::admits(&grid, segments);
        if refines || Halves::allows(&grid) {
            // A transform of L/2 points, its twiddles and scratch in the plan.
            plan.push(term(
                block_key,
                block(),
                "the planned FFT of half length",
                C64 * l,
            ));
        }
        if Halves::allows(&grid) {
            // `forces::synthesis::Halves`: the elevation's samples in single precision, its
            // band's rotations (in the plan) and rotated coefficients (per run).
            plan.push(term(
                "sea.band",
                format!("{g} components"),
                "the elevation's rotations",
                C64 * g,
            ));
            run.push(term(
                block_key,
                block(),
                "the elevation by halves",
                F32 * l + C64 * g,
            ));
        }
        if refines {
            // `forces::refine`: the quadratic records made at every second sample (in their
            // own buffers, refined through one spare record), by a transform of L/2 points:
            // its output and scratch and the spare per run.
            run.push(term(
                block_key,
                block(),
                "the transform of the quadratic records",
                C64 * l + F64 * l,
            ));
        }
        // The wave components: each draw's amplitude and scale.
        run.push(term(
            "sea.n_directions",
            problem.sea.n_directions.to_string(),
            format!("{d} directions' wave components and series"),
            d * (C64 + F64) * g + d * newman_series * tail,
        ));
        if d >= 2.0 && problem.interaction() != Interaction::None {
            let omegas = match &problem.hydro.bidirectional {
                Some(source) if problem.interaction() == Interaction::Bidirectional => {
                    bidirectional_omegas(source)
                }
                _ => problem.hydro.drift.omegas().len(),
            } as f64;
            plan.push(term(
                "sea.n_directions",
                problem.sea.n_directions.to_string(),
                format!("the drift of {d} x {d} direction pairs at {omegas} frequencies"),
                d * d * omegas * 3.0 * C64,
            ));
            if let Some(BidirectionalSource::Embedded { json, .. }) = &problem.hydro.bidirectional {
                // The compiled-in table is parsed when the pairs are made (its numbers take
                // fewer bytes parsed than as text).
                plan.push(term(
                    "sea.n_directions",
                    problem.sea.n_directions.to_string(),
                    "the embedded bi-directional table, parsed",
                    json.len() as f64,
                ));
            }
            run.push(term(
                "sea.n_directions",
                problem.sea.n_directions.to_string(),
                "the cross-direction terms".to_string(),
                3.0 * C64 * l + 3.0 * F64 * l + 2.0 * C64 * g + 4.0 * d * tail,
            ));
        }
        if let Some(yaw) = &model.yaw_following {
            let y = yaw.headings as f64;
            plan.push(term(
                "model.yaw_following.headings",
                yaw.headings.to_string(),
                format!("the coefficients of {y} yaw angles"),
                y * d * FORCE_AND_DAMPING * F64 * g,
            ));
            let eta = match model.newman {
                NewmanForm::Arithmetic => d * C64 * l,
                NewmanForm::Geometric => 0.0,
            };
            run.push(term(
                "model.yaw_following.headings",
                yaw.headings.to_string(),
                format!("the records at {y} yaw angles"),
                y * FORCE_AND_DAMPING * F64 * l + eta + y * d * newman_series * tail,
            ));
        }
        let has_raos = problem.platform.motions.is_some() || problem.hydro.body.rao.is_some();
        if model.wave_frequency_motion == WaveFrequencyMotion::On && has_raos {
            // `forces::motion`: the RAOs of every direction per body yaw on the grid; per
            // yaw the position and velocity of six DOFs (their records, six joined pair
            // series' tails), the twelve coefficient rows and one pair series.
            let sets = model
                .yaw_following
                .as_ref()
                .map_or(1.0, |y| y.headings as f64);
            let key = "model.wave_frequency_motion";
            let word = || WaveFrequencyMotion::On.word().to_string();
            plan.push(term(
                key,
                word(),
                format!("the RAOs of {d} directions at {sets} body yaw angles"),
                sets * d * 6.0 * C64 * g,
            ));
            run.push(term(
                key,
                word(),
                format!("the wave-frequency motion records at {sets} body yaw angles"),
                sets * (12.0 * F64 * l + 6.0 * tail) + 12.0 * C64 * g + C64 * l,
            ));
        }
        if problem.wind.has_gusts() {
            // `forces::gust`, in the plan and in the simulation's segment: the amplitudes'
            // scale (half the grid), the joined synthesizer's block and the series (one
            // grid each), the amplitudes (half a grid), the record and its tail.
            run.push(term(
                "wind.speed",
                written(problem.wind.speed),
                "the gust records".to_string(),
                2.0 * ((0.5 * F64 + 2.5 * C64) * l + F64 * l + tail),
            ));
        }
        if model.drag != DragModel::Off {
            let c = distinct_kinematics(&problem.platform.columns, &directions) as f64;
            let s = model.strips_per_column as f64;
            let row = kinematics_row_floats(model.strips_per_column, &directions) as f64;
            // The depth terms per distinct column: at most the kernel's cap, and never more
            // than the strips.
            let r = s.min(MAX_RANK as f64);
            let drafts = super::distinct_drafts(&problem.platform.columns).len() as f64;
            // Per distinct column (`forces::distinct_kinematics`): a window of its rows (the
            // elevation and every strip's velocity, `forces::kinematics_row_floats`), its
            // depth terms' series (one per term) and its elevation (single precision), and
            // the join's tails of its series; the columns' elevations two to a series; per
            // distinct draft the depth kernel while its basis is made (`forces::DepthBasis`:
            // the kernel and the kept profiles over the grid, the Gram matrix and its
            // eigenvectors).
            run.push(term(
                "model.strips_per_column",
                model.strips_per_column.to_string(),
                format!("the kinematics of {c} distinct columns of {s} strips"),
                c * row * F32 * (ROWS_WINDOW as f64).min(l)
                    + c * (r * C32 + F32) * l
                    + (c / 2.0).ceil() * C32 * l
                    + drafts * ((s + r) * F64 * g + 4.0 * s * s * F64)
                    + c * (1.0 + r) * tail,
            ));
            // Per distinct column and direction, the phase of its centre at every component
            // (`forces::KinematicsWork::for_plan`), made once in the plan.
            plan.push(term(
                "sea.n_directions",
                problem.sea.n_directions.to_string(),
                format!("the phases of {c} distinct columns in {d} directions"),
                c * d * C64 * g,
            ));
        }
        if model.second_order == SecondOrder::FullQtf {
            if let Some(qtf) = &problem.hydro.qtf {
                let n = qtf.omegas.len() as f64;
                // Per direction and DOF: at most n factors of n values (on the QTF's own
                // frequencies) with the grid's brackets (16 B per component), and the
                // factorisation's matrices; jointly over the directions (the cross terms from
                // the bi-directional QTF): at most n d factors of n d values per DOF, and
                // matrices of (n d)^2.
                // The join's tails: one per factor series.
                let brackets = 16.0 * g;
                let bytes = if problem.cross_terms_from_qtf() {
                    let m = n * d;
                    3.0 * (5.0 * m * m * C64 + brackets + m * tail)
                } else {
                    d * 3.0 * (5.0 * n * n * C64 + brackets + n * tail)
                };
                // With yaw following: the factors again at every yaw's relative headings.
                let copies = model
                    .yaw_following
                    .as_ref()
                    .map_or(1.0, |y| 1.0 + y.headings as f64);
                plan.push(term(
                    "model.second_order",
                    SecondOrder::FullQtf.word().to_string(),
                    format!("the full QTF's factors ({n} frequencies) on the grid"),
                    copies * bytes,
                ));
            }
        }
        let largest = plan
            .iter()
            .chain(&run)
            .max_by(|a, b| a.bytes.total_cmp(&b.bytes))
            .cloned()
            .expect("the records always have terms");
        Ok(MemoryEstimate {
            plan: plan.iter().map(|t| t.bytes).sum(),
            per_run: run.iter().map(|t| t.bytes).sum(),
            largest,
        })
    }

    /// The memory of one simulation and its plan, bytes.
    pub fn total(&self) -> f64 {
        self.plan + self.per_run
    }

    /// Refuses the records of one simulation beyond the problem's memory limit, naming the
    /// setting of the largest term; then reserves the memory once and frees it, so that a
    /// process that cannot hold it gets an error here rather than an abort later. (The
    /// limit is per simulation; a campaign's thread steps together only the runs whose
    /// records fit it together, `montecarlo::lane_width`.)
    pub fn check(&self, problem: &Problem) -> Result<()> {
        let total = self.total();
        let run = &problem.run;
        if total > run.memory_limit {
            let what = format!(
                "of which {}: {}",
                bytes_text(self.largest.bytes),
                self.largest.what
            );
            return Err(problem.origins.locate(over_budget(
                self.largest.key,
                &self.largest.value,
                &what,
                total,
                run,
            )));
        }
        if !crate::allocator::can_allocate(total as usize) {
            return Err(Error::OutOfMemory {
                needs: total,
                limit: run.memory_limit,
            });
        }
        Ok(())
    }
}

fn term(key: &'static str, value: String, what: impl Into<String>, bytes: f64) -> Term {
    Term {
        key,
        value,
        what: what.into(),
        bytes,
    }
}

/// The data frequencies a bi-directional source gives pairs at (at most).
fn bidirectional_omegas(source: &BidirectionalSource) -> usize {
    match source {
        BidirectionalSource::ColumnArray { omegas, .. } => omegas.len(),
        BidirectionalSource::Table(table) => table.omegas.len(),
        BidirectionalSource::Embedded { .. } => EMBEDDED_BIDIRECTIONAL_OMEGAS,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hydro::bidirectional::BidirectionalTable;
    use crate::hydro::default_platform;

    #[test]
    fn the_embedded_table_has_the_frequencies_the_estimate_assumes() {
        let table = BidirectionalTable::parse(
            default_platform::BIDIRECTIONAL,
            default_platform::BIDIRECTIONAL_NAME,
        )
        .unwrap();
        assert_eq!(table.omegas.len(), EMBEDDED_BIDIRECTIONAL_OMEGAS);
    }
}
