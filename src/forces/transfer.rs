//! Drift and damping coefficients interpolated onto the simulation's frequency grid, one
//! set per wave direction (docs/theory.md#the-slowly-varying-force,
//! docs/theory.md#wave-drift-damping-and-current).

use super::synthesis::SINGLE_PRECISION_ERROR;
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

/// A record whose coefficients are all, over every direction and component, below this
/// fraction of the largest coefficient of its kind is round-off of the table it was
/// interpolated from and is taken as zero ([`take_negligible_as_zero`]): a symmetric
/// platform's sway and yaw drift in head seas, or the damping entries that couple them to
/// surge, are 1e-16 to 1e-13 of the surge's. A record scales with its coefficients, so it
/// would be below this fraction of the largest record of its kind, far below the error
/// that largest record carries from the transforms' single precision
/// ([`SINGLE_PRECISION_ERROR`], 5e-6 of its rms at most).
pub const NEGLIGIBLE_TRANSFER: f64 = 1e-10;

const _: () = assert!(NEGLIGIBLE_TRANSFER < 1e-3 * SINGLE_PRECISION_ERROR);

/// The drift records' names, surge, sway and yaw (body frame).
const DRIFT_NAMES: [&str; 3] = ["surge drift", "sway drift", "yaw drift"];
/// The damping records' names, b_ij with the velocity j = surge (1), sway (2), yaw rate (6).
const DAMPING_NAMES: [[&str; 3]; 3] = [
    ["b_11", "b_12", "b_16"],
    ["b_21", "b_22", "b_26"],
    ["b_61", "b_62", "b_66"],
];

/// Sets to zero every record of `transfers` that is negligible ([`NEGLIGIBLE_TRANSFER`]),
/// so that it is not made: the drift T_i against the largest of T_surge, T_sway and
/// T_yaw / `length`, the damping b_ij against the largest b_ij / `length`^(n_i + n_j),
/// n = 1 for the yaw row or the yaw-rate column (the units of a force per m/s). `length`
/// (m) turns moments into forces: the caller's radius of gyration. Returns the names of
/// the records taken as zero, drift first, in index order.
pub fn take_negligible_as_zero(
    transfers: &mut [DirectionTransfer],
    length: f64,
) -> Vec<&'static str> {
    // Each record's largest coefficient over every direction, in force units.
    let scale = |i: usize| if i == 2 { length } else { 1.0 };
    let largest = |values: &mut dyn Iterator<Item = &Vec<f64>>| {
        values.flatten().fold(0.0f64, |m, v| m.max(v.abs()))
    };
    let drift: [f64; 3] =
        std::array::from_fn(|i| largest(&mut transfers.iter().map(|t| &t.drift[i])) / scale(i));
    let damping: [[f64; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            largest(
                &mut transfers
                    .iter()
                    .filter_map(|t| t.damping.as_ref().map(|b| &b[i][j])),
            ) / (scale(i) * scale(j))
        })
    });
    let negligible = |size: f64, of: f64| size < NEGLIGIBLE_TRANSFER * of;
    let mut names = Vec::new();
    let drift_of = drift.iter().fold(0.0f64, |m, &v| m.max(v));
    for (i, &size) in drift.iter().enumerate() {
        if size > 0.0 && negligible(size, drift_of) {
            transfers.iter_mut().for_each(|t| t.drift[i].fill(0.0));
            names.push(DRIFT_NAMES[i]);
        }
    }
    let damping_of = damping.iter().flatten().fold(0.0f64, |m, &v| m.max(v));
    for (i, row) in damping.iter().enumerate() {
        for (j, &size) in row.iter().enumerate() {
            if size > 0.0 && negligible(size, damping_of) {
                for b in transfers.iter_mut().filter_map(|t| t.damping.as_mut()) {
                    b[i][j].fill(0.0);
                }
                names.push(DAMPING_NAMES[i][j]);
            }
        }
    }
    names
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two directions of 3 components: surge drift 3.6e5, sway of round-off size in one
    /// direction (1e-10), yaw of 1.4e-6 N m (1e-13 of the surge per 10 m); damping b_11
    /// 1.5e5, b_66 8e7 (8e5 per 10 m squared), b_16 1e-6 (1e-7 per 10 m: round-off), b_22
    /// 1e-4 (1.25e-10 of b_66's 8e5 per 10 m squared: just above the fraction, kept).
    #[test]
    fn only_records_below_the_fraction_of_their_kind_are_taken_as_zero() {
        let direction = |sway: f64| {
            let mut b: [[Vec<f64>; 3]; 3] =
                std::array::from_fn(|_| std::array::from_fn(|_| vec![0.0; 3]));
            b[0][0] = vec![1.5e5, -2.0e4, 3.0];
            b[2][2] = vec![8.0e7, 1.0, 0.0];
            b[0][2] = vec![1.0e-6, -1.0e-7, 0.0];
            b[1][1] = vec![1.0e-4, 0.0, 0.0];
            DirectionTransfer {
                drift: [
                    vec![3.6e5, 1.0, -2.0],
                    vec![sway, 0.0, 0.0],
                    vec![0.0, 1.4e-6, 0.0],
                ],
                damping: Some(b),
            }
        };
        let mut transfers = vec![direction(1e-10), direction(0.0)];
        let names = take_negligible_as_zero(&mut transfers, 10.0);
        assert_eq!(names, ["sway drift", "yaw drift", "b_16"]);
        for t in &transfers {
            assert!(t.drift[1].iter().chain(&t.drift[2]).all(|&v| v == 0.0));
            let b = t.damping.as_ref().unwrap();
            assert!(b[0][2].iter().all(|&v| v == 0.0));
            // The others as they were.
            assert_eq!(t.drift[0], [3.6e5, 1.0, -2.0]);
            assert_eq!(b[1][1], [1.0e-4, 0.0, 0.0]);
            assert_eq!(b[2][2], [8.0e7, 1.0, 0.0]);
        }
        // A sway drift of 1e-4 of the surge's is a record, not round-off.
        let mut real = vec![direction(36.0)];
        assert_eq!(
            take_negligible_as_zero(&mut real, 10.0),
            ["yaw drift", "b_16"]
        );
        // With no coefficient at all nothing is negligible.
        let mut zero = vec![DirectionTransfer::none(3)];
        assert!(take_negligible_as_zero(&mut zero, 10.0).is_empty());
    }
}
