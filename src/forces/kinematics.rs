//! Fast (wave-frequency) kinematics at the columns, precomputed as records for the Morison
//! drag (E&S 8, 9; physics.md section 6).
//!
//! Deep-water linear theory, at the columns' mean positions with the body at zero yaw:
//!   eta_c(t) = Re sum a_n e^{-i k_n (x_c cos b + y_c sin b)} e^{i omega_n t},
//!   u(z, t)  = Re sum a_n omega_n e^{k_n z} (cos b, sin b) e^{-i k_n (...)} e^{i omega_n t},
//! k_n = omega_n^2 / g, summed over the directions of the sea.
//!
//! Stretching: the wetted column, from the keel z = -d to the instantaneous surface
//! z = eta, is mapped linearly onto [-d, 0] (Wheeler's rule anchored at the keel instead of
//! the sea bed). Strip j of n then always sits at the fixed stretched level
//! z'_j = -d + (j + 1/2) d / n, so its velocity record is computed exactly once, and the
//! velocity at the surface is the linear-theory value at z = 0.

use super::record::{RecordBlock, RowAt, SamplePoint};
use super::synthesis::Synthesizer;
use crate::config::Column;
use crate::sea_state::WaveComponents;
use rustfft::num_complex::Complex64;

/// Records of one column, in one [`RecordBlock`] (the drag reads them all at every stage):
/// record 0 is the free-surface elevation at the column centre (m), records 1 + 2j and
/// 2 + 2j the horizontal velocity (body x, y; m/s) at strip j's stretched level.
#[derive(Debug, Clone, PartialEq)]
pub struct ColumnKinematics {
    pub column: Column,
    records: RecordBlock,
}

/// A column's kinematics at one located time.
#[derive(Debug, Clone, Copy)]
pub struct ColumnState<'a> {
    row: RowAt<'a>,
}

impl ColumnKinematics {
    /// Number of strips.
    pub fn strips(&self) -> usize {
        (self.records.width() - 1) / 2
    }

    /// The records at a located time.
    #[inline]
    pub fn at(&self, p: &SamplePoint) -> ColumnState<'_> {
        ColumnState {
            row: self.records.row_at(p),
        }
    }

    /// Number of samples of each record.
    pub fn len(&self) -> usize {
        self.records.len()
    }

    /// Whether the records have no samples.
    pub fn is_empty(&self) -> bool {
        self.records.is_empty()
    }
}

impl<'a> ColumnState<'a> {
    /// The strips' velocities (u_x, u_y pairs in strip order) when the time falls on a
    /// sample: one contiguous slice.
    #[inline]
    pub fn velocities_on_sample(&self) -> Option<&'a [f64]> {
        self.row.on_sample().map(|row| &row[1..])
    }

    /// Free-surface elevation at the column centre, m.
    #[inline]
    pub fn eta(&self) -> f64 {
        self.row.value(0)
    }

    /// Horizontal velocity (body x, y) at strip j, m/s.
    #[inline]
    pub fn velocity(&self, j: usize) -> [f64; 2] {
        [self.row.value(1 + 2 * j), self.row.value(2 + 2 * j)]
    }
}

/// Builds the kinematics records of every column with `strips` strips each.
///
/// The depth profile omega e^{k z} is real and the same for every direction, so each
/// column's direction sums are taken once (A_x, A_y for the velocity, A for the elevation)
/// and strip j's coefficients are omega_n e^{k_n z_j} (A_x, A_y)_n: one transform per strip
/// gives u_x + i u_y ([`Synthesizer::two_real_series`]).
pub fn column_kinematics(
    components: &WaveComponents,
    columns: &[Column],
    strips: usize,
    gravity: f64,
    synth: &mut Synthesizer,
) -> Vec<ColumnKinematics> {
    if columns.is_empty() {
        // No drag: no records, and no record-length scratch to allocate and fault in.
        return Vec::new();
    }
    let grid = &components.grid;
    let omegas: Vec<f64> = (0..grid.count).map(|j| grid.omega(j)).collect();
    let zero = vec![Complex64::default(); grid.count];
    let mut eta = vec![Complex64::default(); grid.len];
    let mut velocities = vec![vec![Complex64::default(); grid.len]; strips];
    let (mut cx, mut cy) = (zero.clone(), zero.clone());
    columns
        .iter()
        .map(|column| {
            let [ax, ay, a] = direction_sums(components, column, gravity);
            synth.two_real_series(&a, &zero, &mut eta);
            for (j, series) in velocities.iter_mut().enumerate() {
                let level = -column.draft + (j as f64 + 0.5) * column.draft / strips as f64;
                for (n, &w) in omegas.iter().enumerate() {
                    let profile = w * (w * w / gravity * level).exp();
                    cx[n] = ax[n] * profile;
                    cy[n] = ay[n] * profile;
                }
                synth.two_real_series(&cx, &cy, series);
            }
            ColumnKinematics {
                column: column.clone(),
                records: interleave(&eta, &velocities),
            }
        })
        .collect()
}

/// The block with rows [eta, u_x0, u_y0, u_x1, u_y1, ...], written row by row (reading the
/// strip series in parallel keeps every write sequential).
fn interleave(eta: &[Complex64], velocities: &[Vec<Complex64>]) -> RecordBlock {
    let width = 1 + 2 * velocities.len();
    let mut samples = Vec::with_capacity(width * eta.len());
    for (m, e) in eta.iter().enumerate() {
        samples.push(e.re);
        for series in velocities {
            samples.extend([series[m].re, series[m].im]);
        }
    }
    RecordBlock::from_rows(width, samples)
}

/// sum over directions of the amplitudes with the phase of the column centre, times
/// (cos b, sin b, 1).
fn direction_sums(
    components: &WaveComponents,
    column: &Column,
    gravity: f64,
) -> [Vec<Complex64>; 3] {
    let grid = &components.grid;
    let mut sums: [Vec<Complex64>; 3] =
        std::array::from_fn(|_| vec![Complex64::default(); grid.count]);
    for (k, dir) in components.directions.iter().enumerate() {
        let (sin, cos) = dir.heading.sin_cos();
        let along = column.x * cos + column.y * sin;
        for (j, a) in components.of_direction(k).iter().enumerate() {
            let wavenumber = grid.omega(j).powi(2) / gravity;
            let phased = a * Complex64::from_polar(1.0, -wavenumber * along);
            sums[0][j] += phased * cos;
            sums[1][j] += phased * sin;
            sums[2][j] += phased;
        }
    }
    sums
}
