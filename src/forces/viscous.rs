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
use super::strip_sum::StripKernel;
use crate::model::DragModel;

/// Drag on the body, body frame: (Fx, Fy, Mz).
///
/// `velocity` is the body's slow velocity in the body frame (u, v, r) and `current` the
/// current velocity in the body frame (x, y components); `kernel` the loop that takes the
/// strip sums ([`StripKernel::detect`]: packed where the CPU allows).
pub fn drag_force(
    columns: &[ColumnKinematics],
    at: &SamplePoint,
    model: DragModel,
    kernel: StripKernel,
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
        let strips = col.strips();
        let wetted = (c.draft + state.eta()).max(0.0);
        let dz = wetted / strips as f64;
        let scale = 0.5 * water_density * c.diameter * dz;
        // The combined model's w = u - U; the separate model's fast term u|u|.
        let offset = match model {
            DragModel::Combined { .. } => slow,
            _ => [0.0; 2],
        };
        // sum_j w_j |w_j| over the strips, before the coefficient and 1/2 rho D dz.
        let fast = kernel.sum(state.strip_rows(), offset);
        let f = match model {
            DragModel::Off => [0.0; 2],
            DragModel::Combined { cd } => [cd * fast[0], cd * fast[1]],
            DragModel::Separate {
                slow: cds,
                fast: cdl,
            } => {
                // The slow term is the same on every strip.
                let s = strips as f64 * cds * (slow[0] * slow[0] + slow[1] * slow[1]).sqrt();
                [-s * slow[0] + cdl * fast[0], -s * slow[1] + cdl * fast[1]]
            }
        };
        total[0] += scale * f[0];
        total[1] += scale * f[1];
        total[2] += scale * (c.x * f[1] - c.y * f[0]);
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::forces::kinematics::column_kinematics;
    use crate::forces::{RecordClock, Synthesizer};
    use crate::model::Cylinder;
    use crate::sea_state::{FrequencyGrid, SeaState, Spectrum, Spreading, WaveComponents};

    /// E&S 8 and 9 strip by strip, written out with `hypot` on each strip's velocities as
    /// the records give them (no chunks, no separate norm pass).
    fn by_strips(
        columns: &[ColumnKinematics],
        at: &SamplePoint,
        model: DragModel,
        velocity: [f64; 3],
        current: [f64; 2],
    ) -> [f64; 3] {
        let mut total = [0.0; 3];
        for col in columns {
            let c = &col.column;
            let state = col.at(at);
            let n = col.strips();
            let dz = (c.draft + state.eta()).max(0.0) / n as f64;
            let slow = [
                velocity[0] - velocity[2] * c.y - current[0],
                velocity[1] + velocity[2] * c.x - current[1],
            ];
            for j in 0..n {
                let u = state.velocity(j);
                let f = match model {
                    DragModel::Off => [0.0; 2],
                    DragModel::Combined { cd } => {
                        let w = [u[0] - slow[0], u[1] - slow[1]];
                        let m = w[0].hypot(w[1]);
                        [cd * w[0] * m, cd * w[1] * m]
                    }
                    DragModel::Separate { slow: cds, fast } => {
                        let (ms, mf) = (slow[0].hypot(slow[1]), u[0].hypot(u[1]));
                        [
                            -cds * slow[0] * ms + fast * u[0] * mf,
                            -cds * slow[1] * ms + fast * u[1] * mf,
                        ]
                    }
                };
                let scale = 0.5 * 1025.0 * c.diameter * dz;
                total[0] += scale * f[0];
                total[1] += scale * f[1];
                total[2] += scale * (c.x * f[1] - c.y * f[0]);
            }
        }
        total
    }

    /// The drag from the scalar loop and from the packed loop this CPU runs
    /// ([`StripKernel::detect`]) equals the plain strip-by-strip sum, and the two agree to
    /// round-off, for strip counts below, at and above a vector (4, 8 strips) and the scalar
    /// loop's chunk (32), on samples and between them, for both drag models.
    #[test]
    fn drag_equals_the_strip_by_strip_sum() {
        let sea = SeaState {
            spectrum: Spectrum::Jonswap {
                hs: 8.0,
                tp: 11.0,
                gamma: None,
            },
            spreading: Spreading::CosN { n: 4.0 },
            mean_direction: 0.4,
            n_directions: 3,
            seed: 3,
            band: None,
        };
        let grid = FrequencyGrid::new(0.0, 400.0, 0.5, sea.band()).unwrap();
        let components = WaveComponents::generate(&sea, grid);
        let grid = &components.grid;
        let clock = RecordClock {
            start_time: 0.0,
            dt: grid.dt,
            len: grid.len,
        };
        let columns = [(30.0, 10.0, 25.0), (-20.0, 15.0, 18.0)].map(|(x, y, draft)| Cylinder {
            x,
            y,
            diameter: 12.0,
            draft,
        });
        let mut synth = Synthesizer::new(grid);
        let packed = StripKernel::detect();
        for strips in [3, 7, 8, 20, 32, 37] {
            let kinematics = column_kinematics(&components, &columns, strips, 9.81, &mut synth);
            for model in [
                DragModel::Combined { cd: 0.7 },
                DragModel::Separate {
                    slow: 0.9,
                    fast: 0.6,
                },
            ] {
                for t in [12.0, 100.5, 233.7] {
                    let at = clock.locate(t).unwrap();
                    let (velocity, current) = ([0.3, -0.2, 0.004], [0.5, 0.1]);
                    let drag = |kernel| {
                        drag_force(&kinematics, &at, model, kernel, 1025.0, velocity, current)
                    };
                    let (got, scalar) = (drag(packed), drag(StripKernel::SCALAR));
                    let want = by_strips(&kinematics, &at, model, velocity, current);
                    let scale = want.iter().map(|f| f.abs()).fold(1.0, f64::max);
                    for i in 0..3 {
                        assert!(
                            (scalar[i] - want[i]).abs() < 1e-12 * scale,
                            "scalar, {strips} strips, {model:?}, t {t}, dof {i}: {} vs {}",
                            scalar[i],
                            want[i]
                        );
                        assert!(
                            (got[i] - scalar[i]).abs() < 1e-13 * scale,
                            "{packed:?}, {strips} strips, {model:?}, t {t}, dof {i}: {} vs {}",
                            got[i],
                            scalar[i]
                        );
                    }
                }
            }
        }
    }
}
