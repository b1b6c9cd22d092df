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

use super::record::Record;
use super::synthesis::Synthesizer;
use crate::config::Column;
use crate::sea_state::WaveComponents;
use rustfft::num_complex::Complex64;

/// Records of one column: surface elevation and strip velocities at the stretched levels.
#[derive(Debug, Clone, PartialEq)]
pub struct ColumnKinematics {
    pub column: Column,
    /// Free-surface elevation at the column centre, m.
    pub eta: Record,
    /// Horizontal velocity at strip j, body x and y, m/s.
    pub ux: Vec<Record>,
    pub uy: Vec<Record>,
}

impl ColumnKinematics {
    /// Number of strips.
    pub fn strips(&self) -> usize {
        self.ux.len()
    }
}

/// Builds the kinematics records of every column with `strips` strips each.
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
    let mut series = vec![Complex64::default(); grid.len];
    let zero = vec![Complex64::default(); grid.count];
    columns
        .iter()
        .map(|column| {
            let phased = phased_amplitudes(components, column, gravity);
            let sum_over_directions =
                |profile: &dyn Fn(f64) -> f64, axis: usize| -> Vec<Complex64> {
                    (0..grid.count)
                        .map(|j| {
                            phased
                                .iter()
                                .map(|(dir_cos_sin, a)| {
                                    a[j] * profile(grid.omega(j)) * dir_cos_sin[axis]
                                })
                                .sum()
                        })
                        .collect()
                };
            let eta_coefficients = sum_over_directions(&|_| 1.0, 2);
            synth.two_real_series(&eta_coefficients, &zero, &mut series);
            let eta = Record::new(series.iter().map(|c| c.re).collect());
            let mut ux = Vec::with_capacity(strips);
            let mut uy = Vec::with_capacity(strips);
            for j in 0..strips {
                let level = -column.draft + (j as f64 + 0.5) * column.draft / strips as f64;
                let profile = |w: f64| w * (w * w / gravity * level).exp();
                let cx = sum_over_directions(&profile, 0);
                let cy = sum_over_directions(&profile, 1);
                synth.two_real_series(&cx, &cy, &mut series);
                ux.push(Record::new(series.iter().map(|c| c.re).collect()));
                uy.push(Record::new(series.iter().map(|c| c.im).collect()));
            }
            ColumnKinematics {
                column: column.clone(),
                eta,
                ux,
                uy,
            }
        })
        .collect()
}

/// Per direction: (cos b, sin b, 1) and the amplitudes with the phase of the column centre.
fn phased_amplitudes(
    components: &WaveComponents,
    column: &Column,
    gravity: f64,
) -> Vec<([f64; 3], Vec<Complex64>)> {
    let grid = &components.grid;
    components
        .directions
        .iter()
        .enumerate()
        .map(|(k, dir)| {
            let (sin, cos) = dir.heading.sin_cos();
            let along = column.x * cos + column.y * sin;
            let amps = components
                .of_direction(k)
                .iter()
                .enumerate()
                .map(|(j, a)| {
                    let wavenumber = grid.omega(j).powi(2) / gravity;
                    a * Complex64::from_polar(1.0, -wavenumber * along)
                })
                .collect();
            ([cos, sin, 1.0], amps)
        })
        .collect()
}
