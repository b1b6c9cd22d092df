//! What a simulation's records need besides the seed, computed once (E&S section 2: the
//! records are built at the mean position): the frequency grid and its planned inverse FFT,
//! the wave-drift damping table, the drift and damping coefficients on the grid, the
//! bi-directional drift of a spread sea, and the factorised full QTF.
//!
//! [`crate::Simulation::new`] makes a plan for itself. A Monte Carlo campaign makes one per
//! group of cases that the same plan serves, and every seed of those cases reuses it
//! ([`crate::Simulation::with_plan`]): the records of a seed then cost only what depends on
//! the seed's wave amplitudes (the transforms, the kinematics, the yaw-following records).
//!
//! A plan is keyed by exactly what it holds depends on ([`PlanKey`]): the run's times, the
//! sea's band and directions, the water, the hydrodynamic data, the columns (Aranha's
//! damping) and the modelling choices of the records. Cases that differ in anything else (the
//! seed, the wave height, the drag coefficients, the current, the mass or the mooring) share
//! one plan.

mod budget;

pub use budget::{MemoryEstimate, Term};

use crate::error::numbers::readable;
use crate::error::{Error, Result};
use crate::forces::{
    direction_pairs, motion_transfers, plan_inverse_fft, refine, take_negligible_as_zero,
    transfers_on_grid, yaw_transfers, DepthBasis, DirectionTransfer, ForceRecords, GustStream,
    Halves, InverseFft, Join, KinematicsWork, MotionTransfer, NewmanTransfer, QtfFactorisation,
    QtfGroup, Record, RecordOptions, RecordWork, Segments, Synthesizer, YawGrid,
};
use crate::wind::GustSpectrum;

use crate::hydro::bidirectional::DirectionPairs;
use crate::hydro::DriftTable;
use crate::model::{
    Cylinder, Dof, DriftDamping, Environment, Interaction, Mode, NewmanForm, SecondOrder,
    WaveFrequencyMotion, YawFollowing,
};
use crate::problem::{Hydro, Problem};
use crate::scenario::Motions;
use crate::sea_state::{Direction, FrequencyGrid, SeaState, Spreading, WaveComponents};
use serde::Serialize;
use std::sync::Arc;

/// Duration of the cross-fade between two blocks of the stream, s: far longer than the
/// correlation time of the wave-frequency signals (tens of seconds), and a small fraction of
/// a block (docs/theory.md, "Open-ended records").
pub const JOIN_DURATION: f64 = 512.0;

/// What a plan's contents depend on: a plan serves every problem with the same key. It
/// borrows from the problem, so that comparing a problem with a plan's copies nothing.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlanKey<'a> {
    start_time: f64,
    block_duration: f64,
    time_step: f64,
    band: (f64, f64),
    spreading: &'a Spreading,
    mean_direction: f64,
    n_directions: usize,
    environment: &'a Environment,
    hydro: &'a Hydro,
    columns: &'a [Cylinder],
    second_order: SecondOrder,
    newman: NewmanForm,
    qtf_tolerance: f64,
    interaction: Interaction,
    drift_damping: DriftDamping,
    yaw_following: &'a Option<YawFollowing>,
    wave_frequency_motion: WaveFrequencyMotion,
    /// The rigid body the RAOs are solved with, and the mass it takes (`problem::motions`).
    motions: Option<(&'a Motions, Option<f64>)>,
    /// The gust spectrum at the force's height (`None`: calm, or a wind the check refuses).
    gust: Option<GustSpectrum>,
}

impl PlanKey<'_> {
    /// The key of `problem`.
    pub fn of(problem: &Problem) -> PlanKey<'_> {
        PlanKey {
            start_time: problem.run.start_time,
            block_duration: problem.run.block_duration,
            time_step: problem.run.time_step,
            band: problem.band(),
            spreading: &problem.sea.spreading,
            mean_direction: problem.sea.mean_direction,
            n_directions: problem.sea.n_directions,
            environment: &problem.environment,
            hydro: &problem.hydro,
            columns: &problem.platform.columns,
            second_order: problem.model.second_order,
            newman: problem.model.newman,
            qtf_tolerance: problem.model.qtf_tolerance,
            interaction: problem.model.interaction,
            drift_damping: problem.model.drift_damping,
            yaw_following: &problem.model.yaw_following,
            wave_frequency_motion: problem.model.wave_frequency_motion,
            motions: problem
                .platform
                .motions
                .as_ref()
                .map(|m| (m, problem.platform.mass)),
            gust: problem
                .run_wind()
                .ok()
                .flatten()
                .and_then(|w| w.gusts)
                .map(|g| g.spectrum),
        }
    }
}

/// The seed-independent part of a problem's records. It serves every problem with the key
/// of the one it was made from ([`PlanKey`]).
pub struct RecordPlan {
    /// The problem the plan was made from (its [`PlanKey`] is the plan's).
    problem: Problem,
    /// Records sampled at h/2, so that every RK4 stage of a regular step is a sample; one
    /// block's span long (`forces::stream`).
    grid: FrequencyGrid,
    /// The stream's segments on this grid.
    segments: Segments,
    fft: InverseFft,
    /// The transform of N/2 points that makes the wave force and damping records at every
    /// second sample, when their band admits it (`forces::refine::admits`).
    half_fft: Option<InverseFft>,
    /// The elevation's transform of N/2 points, when the band allows
    /// (`forces::synthesis::Halves`).
    halves: Option<Halves>,
    /// Per direction: the coefficients of the mean-position records (none with yaw
    /// following, whose records carry the force and damping), prepared for the problem's
    /// Newman form.
    transfers: Vec<NewmanTransfer>,
    /// The records of `transfers` taken as zero, of round-off size
    /// (`forces::take_negligible_as_zero`), by name.
    negligible: Vec<&'static str>,
    /// Cross-direction terms of a spread sea (`None`: long-crested or interaction "none").
    pairs: Option<DirectionPairs>,
    /// The yaw-following grid and the coefficients of every yaw and direction (and, under
    /// the full QTF, its factors at every yaw's relative headings).
    yaw: Option<YawRecordsPlan>,
    /// The full QTF on the grid by groups of directions (second_order = "full-qtf").
    full_qtf: Option<Vec<QtfGroup>>,
    ranks: Vec<QtfRank>,
    /// The drag kinematics' depth kernels of the problem's drafts on the grid and spectrum
    /// and the columns' phases on its frequencies (made once here, not per seed); a seed
    /// whose spectrum, strips, drafts or columns differ makes its own.
    kinematics: KinematicsWork,
    /// The RAOs on the grid, per body yaw (zero, or the yaw-following grid's) and direction
    /// (`forces::motion`); `None` without wave-frequency motion.
    motion: Option<Vec<Vec<MotionTransfer>>>,
    /// The gusts of the wind (`forces::gust`), their spectrum on the grid; `None` when calm.
    gust: Option<GustStream>,
    /// The wave components of the plan's own sea on the grid, not drawn (their scales
    /// computed once): a seed of the same sea draws a copy instead of evaluating the
    /// spectrum again.
    components: WaveComponents,
}

/// What the yaw-following records need besides the seed.
struct YawRecordsPlan {
    grid: YawGrid,
    /// Per yaw and direction, prepared for the problem's Newman form.
    transfers: Vec<Vec<NewmanTransfer>>,
    /// Under the full QTF: per yaw theta_j, the QTF at the relative headings beta_k - theta_j.
    full_qtf: Option<Vec<Vec<QtfGroup>>>,
}

/// The truncation of one full-QTF factorisation: one DOF of one wave direction, or of every
/// direction of a spread sea jointly (`directions` > 1: the cross terms from the
/// bi-directional QTF).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QtfRank {
    /// Index of the (first) wave direction.
    pub direction: usize,
    /// Wave heading of that direction, rad.
    pub heading: f64,
    /// How many directions the factorisation spans.
    pub directions: usize,
    pub dof: Dof,
    /// Retained rank R and the QTF's full rank n.
    pub rank: usize,
    pub size: usize,
    /// Trace-norm share of the discarded eigenvalues (<= `model.qtf_tolerance`).
    pub discarded: f64,
}

impl RecordPlan {
    /// Checks `problem` and computes everything of its records that the seed does not change.
    pub fn new(problem: &Problem) -> Result<Self> {
        problem.check()?;
        Self::of_checked(problem)
    }

    /// [`RecordPlan::new`] of a problem already checked: refused before anything is
    /// allocated when the records of one simulation would exceed the memory limit
    /// ([`MemoryEstimate`]).
    pub(crate) fn of_checked(problem: &Problem) -> Result<Self> {
        let locate = |e| problem.origins.locate(e);
        MemoryEstimate::of(problem)
            .map_err(locate)?
            .check(problem)?;
        Self::plan(problem).map_err(locate)
    }

    /// [`RecordPlan::of_checked`] within the memory limit, its errors naming settings by
    /// their key paths.
    fn plan(problem: &Problem) -> Result<Self> {
        let sea = &problem.sea;
        let dt = 0.5 * problem.run.time_step;
        let segments = segments_of(problem.run.block_duration, dt);
        let grid = FrequencyGrid::new(
            problem.run.start_time,
            segments.span() as f64 * dt,
            dt,
            problem.band(),
        )?;
        let directions = sea.directions();
        let damping_table = problem.damping_table()?;
        if problem.model.yaw_following.is_none() {
            let table = damping_table.as_ref().unwrap_or(&problem.hydro.drift);
            directions_covered(table, sea, &directions)?;
        }
        // The cross terms of a spread sea: from the bi-directional QTF itself (in the joint
        // factorisation below), else by the Newman-type rule of `forces::directional`.
        let pairs = if problem.cross_terms_from_qtf() {
            None
        } else {
            direction_pairs(problem, &grid, &directions)?
        };
        if let (Some(options), Some(_)) = (&problem.model.yaw_following, &pairs) {
            return Err(Error::invalid(
                "model.yaw_following",
                format!("{} headings", options.headings),
                format!(
                    "the yaw-following records do not carry the cross-direction terms of a \
                     spread sea ({} directions, [model] interaction = {}): use a long-crested \
                     sea or [model] interaction = \"none\"",
                    directions.len(),
                    problem.interaction().word()
                ),
            ));
        }
        // With yaw following the force and damping come from its records alone: the
        // mean-position build gets no coefficients (it still makes the elevation and
        // kinematics).
        let mut transfers = match problem.model.yaw_following {
            None => transfers_on_grid(
                damping_table.as_ref().unwrap_or(&problem.hydro.drift),
                &grid,
                &directions,
                damping_table.is_some(),
            )?,
            Some(_) => vec![DirectionTransfer::none(grid.count); directions.len()],
        };
        // Under Newman's approximation, the records of round-off size are not made; the
        // moments compared as forces at the radius of gyration.
        let negligible = match problem.model.second_order {
            SecondOrder::Newman => {
                let inertia = problem.inertia()?;
                let gyration = (inertia.yaw_inertia / inertia.mass).sqrt();
                take_negligible_as_zero(&mut transfers, gyration)
            }
            SecondOrder::FullQtf => Vec::new(),
        };
        let yaw = match &problem.model.yaw_following {
            None => None,
            Some(options) => {
                let yaw_grid = YawGrid::new(options);
                let transfers = yaw_transfers(
                    damping_table.as_ref().unwrap_or(&problem.hydro.drift),
                    &grid,
                    &directions,
                    &yaw_grid,
                    damping_table.is_some(),
                )?;
                let full_qtf = match problem.model.second_order {
                    SecondOrder::Newman => None,
                    SecondOrder::FullQtf => Some(
                        (0..yaw_grid.len())
                            .map(|j| {
                                let theta = yaw_grid.yaw(j);
                                let relative: Vec<Direction> = directions
                                    .iter()
                                    .map(|d| Direction {
                                        heading: d.heading - theta,
                                        weight: d.weight,
                                    })
                                    .collect();
                                full_qtf_on_grid(problem, &grid, &relative)
                                    .map(|(q, _)| q)
                                    .map_err(|e| {
                                        Error::invalid(
                                            "model.yaw_following",
                                            format!("{} headings", options.headings),
                                            format!(
                                                "the full QTF at the body yaw {:.3} deg: {e}",
                                                theta.to_degrees()
                                            ),
                                        )
                                    })
                            })
                            .collect::<Result<Vec<_>>>()?,
                    ),
                };
                let form = problem.model.newman;
                Some(YawRecordsPlan {
                    grid: yaw_grid,
                    transfers: transfers
                        .iter()
                        .map(|t| NewmanTransfer::all(form, t))
                        .collect(),
                    full_qtf,
                })
            }
        };
        let (full_qtf, ranks) = match problem.model.second_order {
            SecondOrder::Newman => (None, Vec::new()),
            SecondOrder::FullQtf => {
                // With yaw following the force comes from the yaw records alone (their QTF
                // at the relative headings); the mean position's ranks are still reported.
                let (qtf, ranks) = full_qtf_on_grid(problem, &grid, &directions)?;
                (problem.model.yaw_following.is_none().then_some(qtf), ranks)
            }
        };
        let components = WaveComponents::undrawn(sea, grid.clone());
        let kinematics = KinematicsWork::for_plan(
            depth_bases(problem, &grid, components.expected_power()),
            &components,
            drag_columns(problem),
            problem.environment.gravity,
        );
        let yaws: Vec<f64> = match &yaw {
            Some(y) => (0..y.grid.len()).map(|j| y.grid.yaw(j)).collect(),
            None => vec![0.0],
        };
        let motion = motion_on_grid(problem, &grid, &directions, &yaws)?;
        let fft = plan_inverse_fft(&grid);
        // The transform of N/2 points, planned once for the quadratic records and the
        // elevation's halves, where either is made so.
        let (refines, by_halves) = (refine::admits(&grid, segments), Halves::allows(&grid));
        let half = (refines || by_halves)
            .then(|| rustfft::FftPlanner::new().plan_fft_inverse(grid.len / 2));
        let halves = half
            .clone()
            .filter(|_| by_halves)
            .map(|half| Halves::new(&grid, half));
        let half_fft = half.filter(|_| refines);
        let gust = problem
            .run_wind()?
            .and_then(|w| w.gusts)
            .map(|g| GustStream::new(&g.spectrum, &grid, segments, fft.clone()));
        Ok(RecordPlan {
            components,
            motion,
            gust,
            problem: problem.clone(),
            kinematics,
            segments,
            fft,
            half_fft,
            halves,
            grid,
            transfers: NewmanTransfer::all(problem.model.newman, &transfers),
            negligible,
            pairs,
            yaw,
            full_qtf,
            ranks,
        })
    }

    /// Whether this plan serves `problem` (it has the plan's key).
    pub fn serves(&self, problem: &Problem) -> bool {
        PlanKey::of(problem) == PlanKey::of(&self.problem)
    }

    /// The frequency grid of the records (one block's span).
    pub fn grid(&self) -> &FrequencyGrid {
        &self.grid
    }

    /// The segments of the records this plan makes.
    pub fn segments(&self) -> Segments {
        self.segments
    }

    /// Whether the wave force and damping records are made at every second sample and
    /// refined (`forces::refine`).
    pub fn refines(&self) -> bool {
        self.half_fft.is_some()
    }

    /// The wave force and damping records not made, their coefficients of round-off size
    /// (`forces::take_negligible_as_zero`), by name.
    pub fn negligible(&self) -> &[&'static str] {
        &self.negligible
    }

    /// The truncation of every full-QTF block (empty under Newman's approximation).
    pub fn ranks(&self) -> &[QtfRank] {
        &self.ranks
    }

    /// The first segment of `problem`'s records (which the plan serves), with the buffers the
    /// next segments are made in.
    pub(crate) fn first_segment(&self, problem: &Problem) -> Segment {
        let mut synth =
            Synthesizer::with_fft(&self.grid, self.fft.clone()).with_join(Join::new(self.segments));
        if let Some(halves) = &self.halves {
            synth = synth.with_halves(halves.clone());
        }
        let mut work = RecordWork::with_kinematics(synth, &self.grid, self.kinematics.clone());
        if let Some(half) = &self.half_fft {
            let join = Join::with_sampling(self.segments, refine::SAMPLING);
            let synth = Synthesizer::every_second_sample(&self.grid, half.clone()).with_join(join);
            work = work.at_their_bandwidth(synth);
        }
        let mut segment = Segment {
            index: 0,
            records: ForceRecords::empty(),
            work,
            components: self.components_of(&problem.sea),
            gust: self.gust.clone(),
        };
        self.build(problem, &mut segment, 0, true);
        segment
    }

    /// Moves `segment` to segment `k` of `problem`'s records: the next one from the current
    /// one's tails; any other after making its predecessor for its tails. Writes into the
    /// segment's buffers: once the first segment is made, this allocates nothing.
    pub(crate) fn move_segment(&self, problem: &Problem, segment: &mut Segment, k: u64) {
        if k == segment.index {
            return;
        }
        if k != segment.index + 1 && k > 0 {
            segment.components.regenerate(problem.sea.seed, k - 1);
            self.build(problem, segment, k - 1, false);
        }
        segment.components.regenerate(problem.sea.seed, k);
        self.build(problem, segment, k, true);
        segment.index = k;
    }

    /// Block 0's wave components of `sea` (a sea this plan serves): a redrawn copy of the
    /// plan's own when `sea` differs from the plan's in its seed alone, else made anew.
    fn components_of(&self, sea: &SeaState) -> WaveComponents {
        let own = &self.problem.sea;
        let same_sea = SeaState {
            seed: own.seed,
            ..sea.clone()
        } == *own;
        if same_sea {
            let mut components = self.components.clone();
            components.regenerate(sea.seed, 0);
            components
        } else {
            WaveComponents::generate(sea, self.grid.clone())
        }
    }

    /// Builds segment `k` into `segment` from its components (block k's), joined to block
    /// k - 1's tails when `after_previous` (forces::stream).
    fn build(&self, problem: &Problem, segment: &mut Segment, k: u64, after_previous: bool) {
        let Segment {
            records,
            work,
            components,
            gust,
            ..
        } = segment;
        work.begin(k, after_previous);
        records.rebuild(
            components,
            &self.transfers,
            &RecordOptions {
                newman: problem.model.newman,
                full_qtf: self.full_qtf.as_deref(),
                drag_columns: drag_columns(problem),
                strips_per_column: problem.model.strips_per_column,
                gravity: problem.environment.gravity,
                fft: Some(&self.fft),
            },
            work,
        );
        if let Some(pairs) = &self.pairs {
            work.cross_terms(records, components, pairs);
        }
        match &self.yaw {
            Some(yaw) => work.yaw_following(
                &mut records.yaw_following,
                components,
                &yaw.grid,
                &yaw.transfers,
                yaw.full_qtf.as_deref(),
                problem.model.newman,
            ),
            None => records.yaw_following = None,
        }
        match &self.motion {
            Some(transfers) => work.motion(&mut records.motion, components, transfers),
            None => records.motion = None,
        }
        match gust {
            Some(gust) => gust.build(
                problem.sea.seed,
                k,
                after_previous,
                records.gust.get_or_insert_with(Record::zero),
            ),
            None => records.gust = None,
        }
    }
}

/// The records of a stream's current segment, and what the next segment is made with.
#[derive(Clone)]
pub(crate) struct Segment {
    /// The segment's index k.
    pub index: u64,
    pub records: ForceRecords,
    work: RecordWork,
    components: WaveComponents,
    /// The gust records' stream (the plan's, with its own join and buffers).
    gust: Option<GustStream>,
}

impl Segment {
    /// The expected power of the run's sea on the plan's grid, per component
    /// ([`WaveComponents::expected_power`]: the same for every block and seed).
    pub fn expected_power(&self) -> &[f64] {
        self.components.expected_power()
    }
}

/// The columns whose kinematics the drag takes: none without drag.
fn drag_columns(problem: &Problem) -> &[Cylinder] {
    match problem.model.drag {
        crate::model::DragModel::Off => &[],
        _ => &problem.platform.columns,
    }
}

/// The depth kernel of every distinct draft of `problem`'s drag columns on `grid` (none
/// without drag), `power` the expected power of its sea's components on the grid.
fn depth_bases(problem: &Problem, grid: &FrequencyGrid, power: &[f64]) -> Vec<Arc<DepthBasis>> {
    let (strips, gravity) = (problem.model.strips_per_column, problem.environment.gravity);
    distinct_drafts(drag_columns(problem))
        .into_iter()
        .map(|draft| Arc::new(DepthBasis::new(grid, power, draft, strips, gravity)))
        .collect()
}

/// The drafts of `columns`, each once, in the order they first come: one depth kernel each
/// (every column has the same strips).
pub(crate) fn distinct_drafts(columns: &[Cylinder]) -> Vec<f64> {
    let mut drafts: Vec<f64> = Vec::new();
    for column in columns {
        if !drafts.contains(&column.draft) {
            drafts.push(column.draft);
        }
    }
    drafts
}

/// The RAOs of `problem` on `grid` at every body yaw of `yaws` and wave direction, when its
/// wave-frequency motion is on and it has RAOs (`problem::motions`).
fn motion_on_grid(
    problem: &Problem,
    grid: &FrequencyGrid,
    directions: &[Direction],
    yaws: &[f64],
) -> Result<Option<Vec<Vec<MotionTransfer>>>> {
    if problem.model.wave_frequency_motion == WaveFrequencyMotion::Off {
        return Ok(None);
    }
    let Some(motions) = problem.first_order_motions()? else {
        return Ok(None);
    };
    problem.check_rao_gap(&motions.rao)?;
    yaws.iter()
        .map(|&yaw| motion_transfers(&motions.rao, grid, directions, yaw))
        .collect::<Result<Vec<_>>>()
        .map(Some)
}

/// The sea's wave directions against the drift data's headings: a direction the data do
/// not reach (nothing is extrapolated) is the sea's doing, refused naming
/// `sea.direction_deg` (the mean direction; a spread sea adds +-90 deg around it) with the
/// directions outside and the data's headings.
fn directions_covered(table: &DriftTable, sea: &SeaState, directions: &[Direction]) -> Result<()> {
    let deg = |h: f64| readable(h.to_degrees());
    let outside: Vec<String> = directions
        .iter()
        .filter(|d| !table.covers_heading(d.heading))
        .map(|d| deg(d.heading))
        .collect();
    if outside.is_empty() {
        return Ok(());
    }
    let headings = table.headings();
    Err(Error::invalid(
        "sea.direction_deg",
        deg(sea.mean_direction),
        format!(
            "{} of the sea's {} wave direction(s) ({} deg) are outside the drift data's \
             headings {} .. {} deg (nothing is extrapolated): turn the sea, or give the data \
             those headings",
            outside.len(),
            directions.len(),
            outside.join(", "),
            deg(headings[0]),
            deg(headings[headings.len() - 1])
        ),
    ))
}

/// The segments of a stream with blocks of `block_duration` seconds sampled at `dt`: B =
/// round(block_duration / dt) samples, and a cross-fade of [`JOIN_DURATION`] (at most a
/// quarter of a block).
pub fn segments_of(block_duration: f64, dt: f64) -> Segments {
    let block = (block_duration / dt).round().max(1.0) as usize;
    let ramp = ((JOIN_DURATION / dt).round() as usize).min(block / 4);
    Segments { block, ramp }
}

/// The full QTF on `grid`: with the cross terms from a bi-directional QTF
/// ([`Problem::cross_terms_from_qtf`]), one factorisation per DOF over (frequency, direction)
/// pairs of every direction; otherwise one per direction and DOF. The sea's headings are
/// interpolated bilinearly in the heading pair between the data's (`Qtf::interpolated`).
fn full_qtf_on_grid(
    problem: &Problem,
    grid: &FrequencyGrid,
    directions: &[Direction],
) -> Result<(Vec<QtfGroup>, Vec<QtfRank>)> {
    let qtf = problem
        .hydro
        .qtf
        .as_ref()
        .expect("Problem::validate requires the QTF for full-qtf");
    let tolerance = problem.model.qtf_tolerance;
    let n = qtf.omegas.len();
    let mut ranks = Vec::new();
    let mut groups = Vec::new();
    let rank = |factors: &QtfFactorisation, direction: usize, dof: Dof| QtfRank {
        direction,
        heading: directions[direction].heading,
        directions: factors.directions(),
        dof,
        rank: factors.rank(),
        size: factors.size(),
        discarded: factors.discarded(),
    };
    if problem.cross_terms_from_qtf() {
        let nd = directions.len();
        let m = n * nd;
        let mut dofs = Vec::with_capacity(3);
        for dof in Dof::ALL {
            let mut matrix = vec![rustfft::num_complex::Complex64::default(); m * m];
            for (k, dk) in directions.iter().enumerate() {
                for (l, dl) in directions.iter().enumerate() {
                    let block = qtf.interpolated(dof, (dk.heading, dl.heading))?;
                    for i in 0..n {
                        let row = (k * n + i) * m + l * n;
                        matrix[row..row + n].copy_from_slice(&block[i * n..(i + 1) * n]);
                    }
                }
            }
            let factors = QtfFactorisation::across_directions(&qtf.omegas, nd, &matrix, tolerance)?;
            ranks.push(rank(&factors, 0, dof));
            dofs.push(factors.on_grid(grid)?);
        }
        groups.push(QtfGroup {
            first_direction: 0,
            dofs: dofs.try_into().expect("three DOFs"),
        });
        return Ok((groups, ranks));
    }
    for (k, direction) in directions.iter().enumerate() {
        let mut dofs = Vec::with_capacity(3);
        for dof in Dof::ALL {
            let block = qtf.interpolated(dof, (direction.heading, direction.heading))?;
            let factors = QtfFactorisation::new(&qtf.omegas, &block, tolerance)?;
            ranks.push(rank(&factors, k, dof));
            dofs.push(factors.on_grid(grid)?);
        }
        groups.push(QtfGroup {
            first_direction: k,
            dofs: dofs.try_into().expect("three DOFs"),
        });
    }
    Ok((groups, ranks))
}

#[cfg(test)]
impl RecordPlan {
    /// This plan making every record on the records' clock (the path before records at
    /// their bandwidth: the tests' independent route).
    fn every_record_at_every_sample(mut self) -> Self {
        self.half_fft = None;
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::forces::SINGLE_PRECISION_ERROR;
    use crate::problem::default_problem;
    use crate::Simulation;

    /// The default problem's wave force and damping made at every second sample and refined
    /// (`forces::refine`) against the same records made at every sample, for the first
    /// segment and the joined second: equal at the step ends (the coarse samples, to the
    /// transforms' rounding), and at the midpoints within the plan's estimate of the
    /// interpolation error; the elevation and the kinematics untouched, bit for bit.
    #[test]
    fn records_at_their_bandwidth_are_the_records_at_every_sample_within_the_estimate() {
        let problem = default_problem().unwrap();
        let coarse = RecordPlan::new(&problem).unwrap();
        assert!(coarse.half_fft.is_some(), "the default band is admitted");
        let fine = RecordPlan::new(&problem)
            .unwrap()
            .every_record_at_every_sample();
        let power = WaveComponents::expected_power_of(&problem.sea, &coarse.grid);
        let estimate = refine::midpoint_error(&power, coarse.grid.d_omega, problem.run.time_step);
        assert!(estimate < 2e-3, "{estimate}");
        let mut a = coarse.first_segment(&problem);
        let mut b = fine.first_segment(&problem);
        for k in 0..2 {
            if k > 0 {
                coarse.move_segment(&problem, &mut a, k);
                fine.move_segment(&problem, &mut b, k);
            }
            let (a, b) = (&a.records, &b.records);
            assert_eq!(a.clock, b.clock);
            assert_eq!(a.elevation, b.elevation);
            assert_eq!(a.kinematics, b.kinematics);
            let damping = |r: &'_ ForceRecords| r.damping.clone().unwrap();
            let (da, db) = (damping(a), damping(b));
            let pairs = a.wave_force.iter().zip(&b.wave_force);
            for (x, y) in pairs.chain(da.iter().flatten().zip(db.iter().flatten())) {
                let (x, y) = (x.samples(), y.samples());
                assert_eq!(x.len(), y.len());
                if y.is_empty() {
                    continue;
                }
                let mean = y.iter().sum::<f64>() / y.len() as f64;
                let std =
                    (y.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / y.len() as f64).sqrt();
                let scale = y.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                // Record sample 2i + 1 is a step end (global kB + 2i), 2i a midpoint.
                let (mut squares, mut midpoints) = (0.0, 0);
                for (r, (x, y)) in x.iter().zip(y).enumerate() {
                    if r % 2 == 1 {
                        assert!(
                            (x - y).abs() <= 4.0 * SINGLE_PRECISION_ERROR * scale,
                            "k {k}, sample {r}: {x} vs {y}"
                        );
                    } else {
                        squares += (x - y).powi(2);
                        midpoints += 1;
                    }
                }
                let rms = (squares / midpoints as f64).sqrt() / std;
                assert!(rms <= 2.0 * estimate, "k {k}: {rms} vs estimate {estimate}");
            }
        }
    }

    /// The slow drift of the default problem in waves from 30 deg over 20 000 s (two segments) with its records
    /// at their bandwidth against the records at every sample: the interpolation's error,
    /// filtered by the slowly responding body, moves the motion by a small fraction of its
    /// standard deviation (the design's response-weighted estimate is 3e-7; asserted with
    /// margin).
    #[test]
    fn the_drift_with_records_at_their_bandwidth_is_the_drift_with_records_at_every_sample() {
        let mut problem = default_problem().unwrap();
        // Waves from 30 deg: surge, sway and yaw all respond.
        problem.sea.mean_direction = 30f64.to_radians();
        let plans = [
            RecordPlan::new(&problem).unwrap(),
            RecordPlan::new(&problem)
                .unwrap()
                .every_record_at_every_sample(),
        ];
        let runs: Vec<Vec<[f64; 3]>> = plans
            .into_iter()
            .map(|plan| {
                let mut sim = Simulation::with_plan(problem.clone(), &Arc::new(plan)).unwrap();
                (0..20_000)
                    .map(|_| {
                        sim.step([0.0; 3]).unwrap();
                        sim.position()
                    })
                    .collect()
            })
            .collect();
        for dof in 0..3 {
            let y: Vec<f64> = runs[1].iter().map(|p| p[dof]).collect();
            let mean = y.iter().sum::<f64>() / y.len() as f64;
            let std = (y.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / y.len() as f64).sqrt();
            let differences = runs[0].iter().zip(&runs[1]).map(|(a, b)| a[dof] - b[dof]);
            let worst = differences.clone().fold(0.0, |m: f64, d| m.max(d.abs()));
            let rms = (differences.map(|d| d * d).sum::<f64>() / y.len() as f64).sqrt();
            assert!(rms <= 1e-5 * std, "dof {dof}: rms {rms} vs std {std}");
            assert!(worst <= 5e-5 * std, "dof {dof}: worst {worst} vs std {std}");
        }
    }
}
