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
        let state = col.at(at);
        let wetted = (c.draft + state.eta()).max(0.0);
        let dz = wetted / col.strips() as f64;
        let scale = 0.5 * water_density * c.diameter * dz;
        let f = match state.velocities_on_sample() {
            Some(pairs) => strip_sum(
                model,
                slow,
                col.strips(),
                pairs.chunks_exact(2).map(|p| [p[0], p[1]]),
            ),
            None => strip_sum(
                model,
                slow,
                col.strips(),
                (0..col.strips()).map(|j| state.velocity(j)),
            ),
        };
        total[0] += scale * f[0];
        total[1] += scale * f[1];
        total[2] += scale * (c.x * f[1] - c.y * f[0]);
    }
    total
}

/// Sum over a column's `strips` strips of the C w|w| terms, before the factor
/// 1/2 rho D dz. The norms are sqrt(x^2 + y^2), not `hypot`: velocities cannot overflow the
/// squares, and libm's hypot was a fifth of a drag run's time.
#[inline]
fn strip_sum(
    model: DragModel,
    slow: [f64; 2],
    strips: usize,
    fast: impl Iterator<Item = [f64; 2]>,
) -> [f64; 2] {
    let norm = |w: [f64; 2]| (w[0] * w[0] + w[1] * w[1]).sqrt();
    match model {
        DragModel::Off => [0.0; 2],
        DragModel::Combined { cd } => {
            let mut f = [0.0; 2];
            for u in fast {
                let w = [u[0] - slow[0], u[1] - slow[1]];
                let n = norm(w);
                f[0] += w[0] * n;
                f[1] += w[1] * n;
            }
            [cd * f[0], cd * f[1]]
        }
        DragModel::Separate {
            slow: cds,
            fast: cdl,
        } => {
            let mut f = [0.0; 2];
            for u in fast {
                let n = norm(u);
                f[0] += u[0] * n;
                f[1] += u[1] * n;
            }
            // The slow term is the same on every strip.
            let s = strips as f64 * cds * norm(slow);
            [-s * slow[0] + cdl * f[0], -s * slow[1] + cdl * f[1]]
        }
    }
}
