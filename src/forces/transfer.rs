//! Drift and damping coefficients interpolated onto the simulation's frequency grid, one
//! set per wave direction (docs/theory.md#the-slowly-varying-force,
//! docs/theory.md#wave-drift-damping-and-current).

use crate::error::Result;
use crate::hydro::DriftTable;
use crate::sea_state::{Direction, FrequencyGrid};

/// Coefficients of one wave direction at the grid's components j = 0 .. count.
#[derive(Debug, Clone, PartialEq)]
pub struct DirectionTransfer {
    /// T_i(omega_j, beta) for i = surge, sway, yaw (body frame).
    pub drift: [Vec<f64>; 3],
    /// b_ij(omega_j, beta), when wave-drift damping is on.
    pub damping: Option<[[Vec<f64>; 3]; 3]>,
}

impl DirectionTransfer {
    /// No coefficients (zero drift, no damping) for `count` components: a direction that
    /// adds nothing to the force and damping records.
    pub fn none(count: usize) -> Self {
        DirectionTransfer {
            drift: std::array::from_fn(|_| vec![0.0; count]),
            damping: None,
        }
    }
}

/// Interpolates the table at every component frequency and direction. The records are
/// computed for the body at zero yaw, so the table heading is the wave direction itself.
pub fn transfers_on_grid(
    table: &DriftTable,
    grid: &FrequencyGrid,
    directions: &[Direction],
    with_damping: bool,
) -> Result<Vec<DirectionTransfer>> {
    let headings: Vec<f64> = directions.iter().map(|d| d.heading).collect();
    table.check_covers((grid.omega(0), grid.omega(grid.count - 1)), &headings)?;
    let omegas: Vec<f64> = (0..grid.count).map(|j| grid.omega(j)).collect();
    directions
        .iter()
        .map(|dir| {
            let mut drift: [Vec<f64>; 3] = std::array::from_fn(|_| Vec::with_capacity(grid.count));
            let capacity = if with_damping { grid.count } else { 0 };
            let mut damping: [[Vec<f64>; 3]; 3] =
                std::array::from_fn(|_| std::array::from_fn(|_| Vec::with_capacity(capacity)));
            table.for_each_along_heading(dir.heading, &omegas, |t, b| {
                for (column, value) in drift.iter_mut().zip(t) {
                    column.push(value);
                }
                if let (true, Some(b)) = (with_damping, b) {
                    for (rows, b_row) in damping.iter_mut().zip(b) {
                        for (column, value) in rows.iter_mut().zip(b_row) {
                            column.push(value);
                        }
                    }
                }
            })?;
            debug_assert!(!with_damping || damping[0][0].len() == grid.count);
            Ok(DirectionTransfer {
                drift,
                damping: with_damping.then_some(damping),
            })
        })
        .collect()
}
