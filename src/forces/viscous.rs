//! Morison drag on vertical columns in strips from the keel to the instantaneous free
//! surface (E&S 8, 9; physics.md section 6).
//!
//! On a strip of height dz and diameter D, with U the column's slow velocity relative to
//! the current (body motion minus current, including the yaw-rate term) and u the fast
//! wave-particle velocity, the force on the body is
//! - separate model (E&S 8): dF = 1/2 rho D dz (C_DS (-U)|U| + C_DL u|u|)
//! - combined model (E&S 9): dF = 1/2 rho D dz C_D w|w|, w = u - U
//!
//! with |.| the horizontal vector norm. Everything is in the body frame.

use super::kinematics::ColumnKinematics;
use super::record::SamplePoint;
use crate::config::DragModel;

/// Drag on the body, body frame: (Fx, Fy, Mz).
///
/// `velocity` is the body's slow velocity in the body frame (u, v, r) and `current` the
/// current velocity in the body frame (x, y components).
pub fn drag_force(
    columns: &[ColumnKinematics],
    at: &SamplePoint,
    model: DragModel,
    water_density: f64,
    velocity: [f64; 3],
    current: [f64; 2],
) -> [f64; 3] {
    let mut total = [0.0; 3];
    if model == DragModel::Off {
        return total;
    }
    let [u, v, r] = velocity;
    for col in columns {
        let c = &col.column;
        let slow = [u - r * c.y - current[0], v + r * c.x - current[1]];
        let wetted = (c.draft + col.eta.at(at)).max(0.0);
        let dz = wetted / col.strips() as f64;
        let scale = 0.5 * water_density * c.diameter * dz;
        let mut f = [0.0; 2];
        for (ux, uy) in col.ux.iter().zip(&col.uy) {
            let fast = [ux.at(at), uy.at(at)];
            let strip = strip_force(model, slow, fast);
            f[0] += strip[0];
            f[1] += strip[1];
        }
        total[0] += scale * f[0];
        total[1] += scale * f[1];
        total[2] += scale * (c.x * f[1] - c.y * f[0]);
    }
    total
}

/// C w|w| terms of one strip, before the factor 1/2 rho D dz. The norms are
/// sqrt(x^2 + y^2), not `hypot`: velocities cannot overflow the squares, and libm's hypot
/// was a fifth of a drag run's time.
#[inline]
fn strip_force(model: DragModel, slow: [f64; 2], fast: [f64; 2]) -> [f64; 2] {
    match model {
        DragModel::Off => [0.0; 2],
        DragModel::Combined { cd } => {
            let w = [fast[0] - slow[0], fast[1] - slow[1]];
            let norm = (w[0] * w[0] + w[1] * w[1]).sqrt();
            [cd * w[0] * norm, cd * w[1] * norm]
        }
        DragModel::Separate {
            slow: cds,
            fast: cdl,
        } => {
            let slow_norm = (slow[0] * slow[0] + slow[1] * slow[1]).sqrt();
            let fast_norm = (fast[0] * fast[0] + fast[1] * fast[1]).sqrt();
            [
                -cds * slow[0] * slow_norm + cdl * fast[0] * fast_norm,
                -cds * slow[1] * slow_norm + cdl * fast[1] * fast_norm,
            ]
        }
    }
}
