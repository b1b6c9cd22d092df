//! Everything that depends only on time, computed once at initialisation for the body at
//! its mean position and zero yaw (E&S section 2): the wave elevation, the slowly varying
//! wave force D(t), the wave-drift damping B(t), and the columns' fast kinematics.

mod directional;
mod kinematics;
mod newman;
mod qtf;
mod record;
mod stream;
mod synthesis;
mod transfer;
mod viscous;
mod yaw_following;

pub use directional::{add_cross_terms, cross_direction_force, direction_pairs};
pub use kinematics::ColumnKinematics;
pub use newman::NewmanBuilder;
pub use qtf::{GridQtf, QtfFactorisation};
pub use record::{Record, RecordClock, SamplePoint};
pub use stream::{Join, Segments};
pub use synthesis::{plan_inverse_fft, InverseFft, Synthesizer};
pub use transfer::{transfers_on_grid, DirectionTransfer};
pub use viscous::drag_force;
pub use yaw_following::{SlowRecords, YawFollowingRecords, YawGrid, YawPoint};

use crate::model::{Cylinder, NewmanForm};
use crate::sea_state::WaveComponents;
use rustfft::num_complex::Complex64;

/// What to precompute besides the elevation and the wave force.
pub struct RecordOptions<'a> {
    pub newman: NewmanForm,
    /// The full QTF of every direction (surge, sway, yaw), factorised on the grid: when
    /// given, the wave force comes from it instead of Newman's approximation (the damping
    /// records stay Newman's, from the transfers' b_ij).
    pub full_qtf: Option<&'a [[GridQtf; 3]]>,
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
    pub kinematics: Vec<ColumnKinematics>,
    /// Force and damping records at a set of body yaw angles (`model.yaw_following`);
    /// when set, they replace `wave_force` and `damping` (see [`ForceRecords::wave_force_at`]).
    pub yaw_following: Option<YawFollowingRecords>,
}

impl ForceRecords {
    /// Builds every record from the wave components and the per-direction coefficients
    /// (from [`transfers_on_grid`]). Cost: one FFT per direction for the elevation, one or
    /// two per non-zero coefficient record and direction (with the full QTF: one per
    /// retained term, DOF and direction instead, for the force), one per strip and column
    /// (columns with the same phases share theirs). `options.full_qtf`, when given, holds one
    /// entry per direction of `components`.
    ///
    /// With a `join`, the records are those of the stream segment it is building
    /// (`forces::stream`): the joined series of the segment's record length, on the segment's
    /// clock. Without, the N samples of the grid's periodic records.
    pub fn build(
        components: &WaveComponents,
        transfers: &[DirectionTransfer],
        options: &RecordOptions,
        join: Option<&mut Join>,
    ) -> Self {
        let grid = &components.grid;
        let clock = match &join {
            Some(join) => join.segments().clock(grid, join.segment()),
            None => RecordClock {
                start_time: grid.start_time,
                dt: grid.dt,
                len: grid.len,
            },
        };
        let mut synth = match options.fft {
            Some(fft) => Synthesizer::with_fft(grid, fft.clone()),
            None => Synthesizer::new(grid),
        }
        .joined(join);
        let n = synth.output_len();
        let mut builder = NewmanBuilder::new(grid.count, n);
        // The arithmetic form needs each direction's complex elevation series.
        let mut eta_c = match options.newman {
            NewmanForm::Arithmetic => vec![Complex64::default(); n],
            NewmanForm::Geometric => Vec::new(),
        };
        let mut elevation_coefficients = vec![Complex64::default(); grid.count];
        // Scratch of the full-QTF synthesis.
        let (mut qtf_coefficients, mut qtf_series) = match options.full_qtf {
            Some(_) => (
                vec![Complex64::default(); grid.count],
                vec![Complex64::default(); n],
            ),
            None => (Vec::new(), Vec::new()),
        };
        // Records are allocated by the first direction that adds to them.
        let mut force: [Vec<f64>; 3] = Default::default();
        let mut damping: [[Vec<f64>; 3]; 3] = Default::default();
        for (k, transfer) in transfers.iter().enumerate() {
            let amplitudes = components.of_direction(k);
            for (sum, a) in elevation_coefficients.iter_mut().zip(amplitudes) {
                *sum += a;
            }
            if options.newman == NewmanForm::Arithmetic {
                synth.complex_series(amplitudes, &mut eta_c);
            }
            match options.full_qtf {
                Some(qtf) => {
                    for (out, t) in force.iter_mut().zip(&qtf[k]) {
                        t.accumulate(
                            &mut synth,
                            amplitudes,
                            &mut qtf_coefficients,
                            &mut qtf_series,
                            out,
                        );
                    }
                }
                None => builder.accumulate_force(
                    &mut synth,
                    options.newman,
                    amplitudes,
                    &eta_c,
                    transfer,
                    &mut force,
                ),
            }
            builder.accumulate_damping(
                &mut synth,
                options.newman,
                amplitudes,
                &eta_c,
                transfer,
                &mut damping,
            );
        }
        let elevation = builder.real_series(&mut synth, &elevation_coefficients);
        let with_damping = transfers.iter().any(|t| t.damping.is_some());
        let kinematics = kinematics::column_kinematics(
            components,
            options.drag_columns,
            options.strips_per_column,
            options.gravity,
            &mut synth,
        );
        ForceRecords {
            clock,
            elevation: Record::new(elevation),
            wave_force: force.map(record_or_zero),
            damping: with_damping.then(|| damping.map(|row| row.map(record_or_zero))),
            kinematics,
            yaw_following: None,
        }
    }
}

/// A record, or the empty zero record when no direction added to it or every sample is
/// exactly zero.
fn record_or_zero(samples: Vec<f64>) -> Record {
    if samples.iter().all(|&v| v == 0.0) {
        Record::zero()
    } else {
        Record::new(samples)
    }
}
