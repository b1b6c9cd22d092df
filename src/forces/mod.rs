//! Everything that depends only on time, for the body at its mean position and zero yaw
//! (E&S section 2): the wave elevation, the slowly varying wave force D(t), the wave-drift
//! damping B(t), and the columns' fast kinematics. They are made block by block as the run
//! reaches them (`stream`: one block at initialisation, the next when a step enters it), so
//! a run of any length holds one block's records (docs/theory.md#open-ended-records).

mod depth_basis;
mod directional;
mod gust;
mod isa;
mod kinematics;
mod motion;
mod newman;
mod prefetch;
mod qtf;
mod record;
pub mod refine;
mod stream;
mod synthesis;
mod transfer;
mod value;
mod viscous;
mod yaw_following;

pub use depth_basis::MAX_RANK;
pub use depth_basis::{DepthBasis, KINEMATICS_TOLERANCE};
pub use directional::{add_cross_terms, cross_direction_force, direction_pairs, CrossWork};
pub use gust::GustStream;
pub use isa::Isa;
pub use kinematics::{
    distinct_kinematics, kinematics_row_floats, ColumnKinematics, Kinematics, KinematicsWork,
    ROWS_WINDOW,
};
pub use motion::{motion_transfers, MotionRecords, MotionTransfer, RaoAlong, WholeMotion};
pub use newman::{Diagonal, NewmanBuilder, NewmanTransfer};
pub use qtf::{GridQtf, QtfFactorisation, QtfGroup};
pub use record::{Record, RecordClock, SamplePoint};
pub use stream::{Join, Sampling, Segments};
pub use synthesis::{plan_inverse_fft, Halves, InverseFft, Synthesizer, SINGLE_PRECISION_ERROR};
pub use transfer::{
    take_negligible_as_zero, transfers_on_grid, DirectionTransfer, NEGLIGIBLE_TRANSFER,
};
pub use value::{Value, Wide};
pub use viscous::{drag_force, drag_forces, LaneDrag, LANES};
pub use yaw_following::{
    yaw_transfers, SlowRecords, YawFollowingRecords, YawGrid, YawPoint, YawWork,
};

use crate::model::{Cylinder, NewmanForm};
use crate::sea_state::{FrequencyGrid, WaveComponents};
use rustfft::num_complex::Complex64;

/// What to precompute besides the elevation and the wave force.
pub struct RecordOptions<'a> {
    pub newman: NewmanForm,
    /// The full QTF (surge, sway, yaw), factorised on the grid, by groups of directions
    /// (one per direction, or one for every direction of a spread sea with the cross terms):
    /// when given, the wave force comes from it instead of Newman's approximation (the
    /// damping records stay Newman's, from the transfers' b_ij).
    pub full_qtf: Option<&'a [QtfGroup]>,
    /// Columns (and strips per column) whose kinematics the drag needs; empty = no drag.
    pub drag_columns: &'a [Cylinder],
    pub strips_per_column: usize,
    pub gravity: f64,
    /// The inverse FFT of the grid's record length when already planned (`None`: plan it).
    pub fft: Option<&'a InverseFft>,
}

/// The precomputed records on one clock.
#[derive(Debug, Clone, PartialEq)]
pub struct ForceRecords {
    pub clock: RecordClock,
    /// Wave elevation at the body origin, m.
    pub elevation: Record,
    /// Slowly varying wave force D(t), body frame: surge, sway (N), yaw (N m).
    pub wave_force: [Record; 3],
    /// Wave-drift damping B_ij(t), rows force, columns velocity; `None` when off.
    pub damping: Option<[[Record; 3]; 3]>,
    /// Fast kinematics of the drag columns (empty without drag).
    pub kinematics: Kinematics,
    /// Force and damping records at a set of body yaw angles (`model.yaw_following`);
    /// when set, they replace `wave_force` and `damping` (see [`ForceRecords::wave_force_at`]).
    pub yaw_following: Option<YawFollowingRecords>,
    /// The wave-frequency motion of the body (`forces::motion`), when the problem has RAOs
    /// and the motion is on.
    pub motion: Option<MotionRecords>,
    /// The gust of the wind about its mean at the force's height, m/s (`forces::gust`),
    /// when there is wind.
    pub gust: Option<Record>,
}

/// The buffers of a build of records, kept from one build to the next: the records of a
/// stream's next segment are written into those of the previous one with these, and
/// allocate nothing once the first segment is made.
#[derive(Clone)]
pub struct RecordWork {
    synth: Synthesizer,
    newman: NewmanBuilder,
    /// The arithmetic form's complex elevation series of one direction.
    eta_c: Vec<Complex64>,
    elevation_coefficients: Vec<Complex64>,
    /// Scratch of the full-QTF synthesis.
    qtf_coefficients: Vec<Complex64>,
    qtf_series: Vec<Complex64>,
    kinematics: KinematicsWork,
    /// Scratch of the cross-direction terms (`forces::directional`).
    cross: CrossWork,
    /// Scratch of the yaw-following records.
    yaw: YawWork,
    /// Scratch of the wave-frequency motion records.
    motion: motion::MotionWork,
    /// The synthesizer of every second sample, when the quadratic records are made at
    /// their bandwidth (`forces::refine`).
    coarse: Option<Synthesizer>,
    /// The buffer a record is refined into (`forces::refine::refine`'s spare).
    refined: Vec<f64>,
}

impl RecordWork {
    /// The buffers of builds through `synth` on `grid`.
    pub fn new(synth: Synthesizer, grid: &FrequencyGrid) -> Self {
        Self::with_kinematics(synth, grid, KinematicsWork::default())
    }

    /// [`RecordWork::new`] whose kinematics start from `kinematics` (a record plan's depth
    /// kernels and phases, taken where they fit: [`KinematicsWork::for_plan`]).
    pub fn with_kinematics(
        synth: Synthesizer,
        grid: &FrequencyGrid,
        kinematics: KinematicsWork,
    ) -> Self {
        RecordWork {
            synth,
            newman: NewmanBuilder::new(grid.count),
            eta_c: Vec::new(),
            elevation_coefficients: Vec::new(),
            qtf_coefficients: Vec::new(),
            qtf_series: Vec::new(),
            kinematics,
            cross: CrossWork::default(),
            yaw: YawWork::default(),
            motion: motion::MotionWork::default(),
            coarse: None,
            refined: Vec::new(),
        }
    }

    /// These buffers making the quadratic records (the wave force and damping, Newman's or
    /// the full QTF's, the cross-direction terms, the yaw-following records) at every
    /// second sample through `synth` ([`Synthesizer::every_second_sample`], joined on
    /// `refine::SAMPLING`) and refining them to the records' clock (`forces::refine`).
    pub fn at_their_bandwidth(mut self, synth: Synthesizer) -> Self {
        self.coarse = Some(synth);
        self
    }

    /// Starts segment `k` on every joined synthesizer (`Join::begin`).
    pub fn begin(&mut self, k: u64, after_previous: bool) {
        for synth in std::iter::once(&mut self.synth).chain(&mut self.coarse) {
            synth
                .join_mut()
                .expect("a segment's synthesizer is joined")
                .begin(k, after_previous);
        }
    }

    /// The synthesizer the builds write through (a stream's segments when joined).
    pub fn synth(&mut self) -> &mut Synthesizer {
        &mut self.synth
    }

    /// The yaw-following records of `grid` into `records` (their buffers reused), from the
    /// transfers of every yaw ([`yaw_following::yaw_transfers`]) prepared for `form`
    /// ([`NewmanTransfer`]).
    pub fn yaw_following(
        &mut self,
        records: &mut Option<YawFollowingRecords>,
        components: &WaveComponents,
        grid: &YawGrid,
        transfers: &[Vec<NewmanTransfer>],
        full_qtf: Option<&[Vec<QtfGroup>]>,
        form: NewmanForm,
    ) {
        let records = records.get_or_insert_with(|| YawFollowingRecords {
            grid: *grid,
            sets: Vec::new(),
        });
        let (synth, refining) = quadratic(&mut self.synth, &mut self.coarse);
        records.rebuild(
            components,
            transfers,
            full_qtf,
            form,
            synth,
            &mut self.newman,
            &mut self.yaw,
        );
        if refining {
            let len = self.synth.output_len();
            for set in &mut records.sets {
                let damping = set.damping.iter_mut().flatten().flatten();
                set.wave_force
                    .iter_mut()
                    .chain(damping)
                    .for_each(|r| refine_record(r, len, &mut self.refined));
            }
        }
    }

    /// The wave-frequency motion records of `components` into `records` (their buffers
    /// reused), one set per body yaw of `transfers` (`forces::motion`).
    pub fn motion(
        &mut self,
        records: &mut Option<MotionRecords>,
        components: &WaveComponents,
        transfers: &[Vec<MotionTransfer>],
    ) {
        records.get_or_insert_with(MotionRecords::default).rebuild(
            components,
            transfers,
            &mut self.synth,
            &mut self.motion,
        );
    }

    /// Adds the cross-direction terms of a spread sea to the records' wave force.
    pub fn cross_terms(
        &mut self,
        records: &mut ForceRecords,
        components: &WaveComponents,
        pairs: &crate::hydro::bidirectional::DirectionPairs,
    ) {
        let len = self.synth.output_len();
        let (synth, refining) = quadratic(&mut self.synth, &mut self.coarse);
        let refined = refining.then_some((len, &mut self.refined));
        add_cross_terms(records, components, pairs, synth, refined, &mut self.cross);
    }
}

impl ForceRecords {
    /// Builds every record from the wave components and the per-direction coefficients
    /// (from [`transfers_on_grid`]), over the grid's period (N samples). Cost: one FFT for
    /// the elevation (of N/2 points where the band allows and `options.fft` is not given:
    /// [`Halves`]), one or two per non-zero coefficient record and direction
    /// (with the full QTF: one per retained term, DOF and direction instead, for the force;
    /// `build` makes them all at every sample: the route the stream's records at their
    /// bandwidth are checked against),
    /// per group of columns that share their kinematics (same phases) one per retained depth
    /// term and half a transform for the elevation (`forces::kinematics`).
    /// `options.full_qtf`, when given, covers every direction of `components`.
    pub fn build(
        components: &WaveComponents,
        transfers: &[DirectionTransfer],
        options: &RecordOptions,
    ) -> Self {
        let grid = &components.grid;
        let synth = match options.fft {
            Some(fft) => Synthesizer::with_fft(grid, fft.clone()),
            None => Synthesizer::new(grid),
        };
        let mut work = RecordWork::new(synth, grid);
        let mut records = ForceRecords::empty();
        let transfers = NewmanTransfer::all(options.newman, transfers);
        records.rebuild(components, &transfers, options, &mut work);
        records
    }

    /// Records with no samples, to be written by [`ForceRecords::rebuild`].
    pub fn empty() -> Self {
        ForceRecords {
            clock: RecordClock {
                start_time: 0.0,
                dt: 1.0,
                len: 0,
            },
            elevation: Record::zero(),
            wave_force: Default::default(),
            damping: None,
            kinematics: Kinematics::default(),
            yaw_following: None,
            motion: None,
            gust: None,
        }
    }

    /// [`ForceRecords::build`] into these records, reusing their buffers and `work`'s:
    /// through a joined synthesizer, the records of the stream segment its join is building
    /// (`forces::stream`: the segment's record length, on the segment's clock); with
    /// [`RecordWork::at_their_bandwidth`], the force and damping at every second sample,
    /// refined (`forces::refine`). The yaw-following, wave-frequency motion and gust records
    /// are left as they are.
    pub fn rebuild(
        &mut self,
        components: &WaveComponents,
        transfers: &[NewmanTransfer],
        options: &RecordOptions,
        work: &mut RecordWork,
    ) {
        let grid = &components.grid;
        self.clock = match work.synth.join() {
            Some(join) => join.segments().clock(grid, join.segment()),
            None => RecordClock {
                start_time: grid.start_time,
                dt: grid.dt,
                len: grid.len,
            },
        };
        let n = work.synth.output_len();
        let coefficients = &mut work.elevation_coefficients;
        coefficients.clear();
        coefficients.resize(grid.count, Complex64::default());
        // The previous records' buffers, emptied: records are filled by the first direction
        // that adds to them.
        let mut force: [Vec<f64>; 3] =
            std::array::from_fn(|i| take_samples(&mut self.wave_force[i]));
        let mut damping: [[Vec<f64>; 3]; 3] = match &mut self.damping {
            Some(d) => std::array::from_fn(|i| std::array::from_fn(|j| take_samples(&mut d[i][j]))),
            None => Default::default(),
        };
        {
            // The quadratic records, on the records' clock or at every second sample.
            let (synth, refining) = quadratic(&mut work.synth, &mut work.coarse);
            let len = synth.output_len();
            let eta_c = &mut work.eta_c;
            eta_c.resize(
                match options.newman {
                    NewmanForm::Arithmetic => len,
                    NewmanForm::Geometric => 0,
                },
                Complex64::default(),
            );
            if options.full_qtf.is_some() {
                work.qtf_coefficients
                    .resize(grid.count, Complex64::default());
                work.qtf_series.resize(len, Complex64::default());
            }
            let builder = &mut work.newman;
            for (k, transfer) in transfers.iter().enumerate() {
                let amplitudes = components.of_direction(k);
                for (sum, a) in coefficients.iter_mut().zip(amplitudes) {
                    *sum += a;
                }
                if options.newman == NewmanForm::Arithmetic {
                    synth.complex_series(amplitudes, eta_c);
                }
                if options.full_qtf.is_none() {
                    builder.accumulate_force(synth, amplitudes, eta_c, transfer, &mut force);
                }
                builder.accumulate_damping(synth, amplitudes, eta_c, transfer, &mut damping);
            }
            for group in options.full_qtf.unwrap_or_default() {
                group.accumulate(
                    synth,
                    components,
                    &mut work.qtf_coefficients,
                    &mut work.qtf_series,
                    &mut force,
                );
            }
            if refining {
                let records = force.iter_mut().chain(damping.iter_mut().flatten());
                records.for_each(|samples| refine::refine(samples, n, &mut work.refined));
            }
        }
        let synth = &mut work.synth;
        let mut elevation = take_samples(&mut self.elevation);
        synth.real_series_into(coefficients, &mut elevation);
        self.elevation = Record::new(elevation);
        let with_damping = transfers.iter().any(|t| t.damping.is_some());
        work.kinematics.build(
            components,
            options.drag_columns,
            options.strips_per_column,
            options.gravity,
            synth,
            &mut self.kinematics,
        );
        self.wave_force = force.map(record_or_zero);
        self.damping = with_damping.then(|| damping.map(|row| row.map(record_or_zero)));
    }
}

/// The synthesizer the quadratic records are made with, and whether it makes them at every
/// second sample (to be refined): `coarse` when there is one, else the records' own.
fn quadratic<'a>(
    synth: &'a mut Synthesizer,
    coarse: &'a mut Option<Synthesizer>,
) -> (&'a mut Synthesizer, bool) {
    match coarse {
        Some(coarse) => (coarse, true),
        None => (synth, false),
    }
}

/// A record made at every second sample, refined to `len` samples (through `spare`)
/// (`forces::refine`; a zero record stays zero).
fn refine_record(record: &mut Record, len: usize, spare: &mut Vec<f64>) {
    let mut samples = std::mem::take(record).into_samples();
    refine::refine(&mut samples, len, spare);
    *record = Record::new(samples);
}

/// The samples' buffer of `record`, emptied (its capacity kept), the record left zero.
fn take_samples(record: &mut Record) -> Vec<f64> {
    let mut samples = std::mem::take(record).into_samples();
    samples.clear();
    samples
}

/// A record, or the empty zero record when no direction added to it or every sample is
/// exactly zero.
fn record_or_zero(mut samples: Vec<f64>) -> Record {
    if samples.iter().all(|&v| v == 0.0) {
        // Zero, keeping the buffer for the next segment.
        samples.clear();
    }
    Record::new(samples)
}
