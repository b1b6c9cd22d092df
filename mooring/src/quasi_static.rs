//! The quasi-static mooring: every line a static elastic catenary ([`crate::catenary`])
//! between its anchor and its fairlead on the platform, with no line dynamics (no line
//! inertia, drag or damping). The force on the platform at the 6-DOF position
//! r6 = (x, y, z, roll, pitch, yaw) is the sum of the lines' fairlead tensions, in
//! [`crate::motion`]'s conventions: the fairleads turned by MoorDyn's rotation
//! Rx(roll) Ry(pitch) Rz(yaw) about the platform's reference point (the body frame's origin
//! in the MoorDyn file); the force the lines exert on the platform in the inertial axes,
//! X, Y, Z with Z up, and its moment about the reference point.
//!
//! Each line's catenary lies in the vertical plane through its anchor and its fairlead: the
//! horizontal tension HF pulls the fairlead horizontally towards the anchor and the
//! vertical tension VF pulls it down; its moment is r x F with r the fairlead's position
//! relative to the reference point in inertial axes.

use crate::lines_file::{self, MooringLine};
use crate::motion::{turn, HEAVE, PITCH, ROLL, SURGE, SWAY, YAW};
use std::path::Path;

/// The lines of one mooring, ready to be evaluated at any platform position.
pub struct QuasiStatic {
    lines: Vec<MooringLine>,
}

/// The force of the lines on the platform and their fairlead tensions.
#[derive(Debug, Clone, PartialEq)]
pub struct LineForce {
    /// (Fx, Fy, Fz, Mx, My, Mz): N and N m, inertial axes, about the reference point.
    pub force: [f64; 6],
    /// Each line's fairlead tension sqrt(HF^2 + VF^2), N, in the file's order of lines.
    pub tensions: Vec<f64>,
}

impl QuasiStatic {
    /// The lines of a MoorDyn v2 input file (lines_file's rules).
    pub fn read(path: &Path) -> Result<QuasiStatic, String> {
        Ok(QuasiStatic {
            lines: lines_file::read(path)?,
        })
    }

    pub fn new(lines: Vec<MooringLine>) -> QuasiStatic {
        QuasiStatic { lines }
    }

    /// The number of lines.
    pub fn line_count(&self) -> usize {
        self.lines.len()
    }

    /// The static line force on the platform at r6 = (x, y, z, roll, pitch, yaw) (m, rad).
    pub fn force(&self, r6: [f64; 6]) -> Result<LineForce, String> {
        let mut force = [0.0; 6];
        let mut tensions = Vec::with_capacity(self.lines.len());
        for line in &self.lines {
            // The fairlead relative to the reference point, and the anchor from the fairlead.
            let r = turn(r6, line.fairlead);
            let to_anchor: [f64; 3] = std::array::from_fn(|i| line.anchor[i] - r6[i] - r[i]);
            let xf = to_anchor[0].hypot(to_anchor[1]);
            let zf = -to_anchor[2];
            let t = line.line.solve(xf, zf).map_err(|e| {
                format!(
                    "line {} at X = {}, Y = {}, Z = {}, roll = {}, pitch = {}, theta = {}: {e}",
                    line.id, r6[SURGE], r6[SWAY], r6[HEAVE], r6[ROLL], r6[PITCH], r6[YAW]
                )
            })?;
            // HF pulls the fairlead horizontally towards the anchor, VF pulls it down.
            let f = [
                t.horizontal * to_anchor[0] / xf,
                t.horizontal * to_anchor[1] / xf,
                -t.vertical,
            ];
            force[0] += f[0];
            force[1] += f[1];
            force[2] += f[2];
            force[3] += r[1] * f[2] - r[2] * f[1];
            force[4] += r[2] * f[0] - r[0] * f[2];
            force[5] += r[0] * f[1] - r[1] * f[0];
            tensions.push(t.horizontal.hypot(t.vertical));
        }
        Ok(LineForce { force, tensions })
    }
}

impl LineForce {
    /// The largest fairlead tension, N (0 without lines).
    pub fn max_tension(&self) -> f64 {
        self.tensions.iter().fold(0.0, |m, &t| m.max(t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catenary::Line;

    fn line(anchor: [f64; 3], fairlead: [f64; 3]) -> MooringLine {
        MooringLine {
            id: "1".into(),
            line: Line {
                length: 1000.0,
                ea: 6.03e8,
                weight: 1196.37,
            },
            anchor,
            fairlead,
        }
    }

    const CHAIN: Line = Line {
        length: 1000.0,
        ea: 6.03e8,
        weight: 1196.37,
    };

    fn at(x: f64, y: f64, yaw: f64) -> [f64; 6] {
        [x, y, 0.0, 0.0, 0.0, yaw]
    }

    /// One line along +X: the platform is pulled towards +X with the line's horizontal
    /// tension and down with its vertical one, no sway force, and a moment r x F about the
    /// reference point: the fairlead (45, 35, -20) m gives Mx = 35 Fz, My = -20 Fx - 45 Fz,
    /// Mz = -35 Fx.
    #[test]
    fn one_line_pulls_towards_its_anchor() {
        let m = QuasiStatic::new(vec![line([980.0, 35.0, -300.0], [45.0, 35.0, -20.0])]);
        let f = m.force(at(0.0, 0.0, 0.0)).unwrap();
        let t = CHAIN.solve(935.0, 280.0).unwrap();
        let (h, v) = (t.horizontal, t.vertical);
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * (h + v) * 50.0;
        assert!(close(f.force[0], h) && close(f.force[1], 0.0) && close(f.force[2], -v));
        assert!(close(f.force[3], -35.0 * v), "{f:?}");
        assert!(close(f.force[4], -20.0 * h + 45.0 * v), "{f:?}");
        assert!(close(f.force[5], -35.0 * h), "{f:?}");
        assert_eq!(f.tensions, vec![h.hypot(v)]);
        assert_eq!(f.max_tension(), h.hypot(v));
    }

    /// A roll turns the fairlead (45, 0, -20) about X to (45, 20 sin(roll), -20 cos(roll)):
    /// the line reaches 935 m along X and -20 sin(roll) across to its anchor, 300 -
    /// 20 cos(roll) m below; a heave raises the fairlead by as much.
    #[test]
    fn roll_and_heave_move_the_fairlead() {
        let m = QuasiStatic::new(vec![line([980.0, 0.0, -300.0], [45.0, 0.0, -20.0])]);
        let (roll, heave) = (0.1_f64, 1.5);
        let f = m.force([0.0, 0.0, heave, roll, 0.0, 0.0]).unwrap();
        let (ry, rz) = (20.0 * roll.sin(), -20.0 * roll.cos());
        let xf = 935.0_f64.hypot(ry);
        let t = CHAIN.solve(xf, 300.0 + heave + rz).unwrap();
        let (fx, fy, fz) = (
            t.horizontal * 935.0 / xf,
            -t.horizontal * ry / xf,
            -t.vertical,
        );
        let expected = [
            fx,
            fy,
            fz,
            ry * fz - rz * fy,
            rz * fx - 45.0 * fz,
            45.0 * fy - ry * fx,
        ];
        for (k, (a, b)) in f.force.iter().zip(expected).enumerate() {
            assert!((a - b).abs() <= 1e-9 * t.vertical * 50.0, "{k}: {a} {b}");
        }
    }

    /// A symmetric pair of lines: no horizontal force at the origin; moving towards one
    /// anchor slackens that line and the pair pulls back (a restoring force); a yaw turns
    /// the fairleads and the pair's moment restores it; heaving up lifts more chain (Fz more
    /// negative); a pitch about +Y keeps the pair in the XZ plane of symmetry (no sway
    /// force, no roll or yaw moment) and lowers the +X fairlead: the two tensions differ.
    #[test]
    fn a_symmetric_pair_restores() {
        let m = QuasiStatic::new(vec![
            line([980.0, 0.0, -300.0], [45.0, 0.0, -20.0]),
            line([-980.0, 0.0, -300.0], [-45.0, 0.0, -20.0]),
        ]);
        let f0 = m.force(at(0.0, 0.0, 0.0)).unwrap();
        assert!(f0
            .force
            .iter()
            .enumerate()
            .all(|(k, v)| k == 2 || v.abs() < 1e-6));
        assert!(m.force(at(5.0, 0.0, 0.0)).unwrap().force[0] < 0.0);
        assert!(m.force(at(-5.0, 0.0, 0.0)).unwrap().force[0] > 0.0);
        assert!(m.force(at(0.0, 0.0, 0.05)).unwrap().force[5] < 0.0);
        let up = m.force([0.0, 0.0, 2.0, 0.0, 0.0, 0.0]).unwrap();
        assert!(up.force[2] < f0.force[2]);
        let pitched = m.force([0.0, 0.0, 0.0, 0.0, 0.02, 0.0]).unwrap();
        for k in [1, 3, 5] {
            assert!(pitched.force[k].abs() < 1e-6, "{pitched:?}");
        }
        assert!(
            (pitched.tensions[0] - pitched.tensions[1]).abs() > 1e2,
            "{pitched:?}"
        );
    }

    /// With no heave, roll or pitch the force is bit for bit the planar computation of the
    /// yaw alone (cos and sin of theta, the anchor reached from the reference point).
    #[test]
    fn planar_positions_are_computed_as_in_the_plane() {
        let m = QuasiStatic::new(vec![line([980.0, 35.0, -300.0], [45.0, 35.0, -20.0])]);
        let q = [3.7, -1.2, 0.11];
        let f = m.force(at(q[0], q[1], q[2])).unwrap();
        let (s, c) = q[2].sin_cos();
        let r = [c * 45.0 - s * 35.0, s * 45.0 + c * 35.0];
        let d = [980.0 - q[0] - r[0], 35.0 - q[1] - r[1]];
        let xf = d[0].hypot(d[1]);
        let t = CHAIN.solve(xf, -20.0 - -300.0).unwrap();
        let (fx, fy) = (t.horizontal * d[0] / xf, t.horizontal * d[1] / xf);
        assert_eq!(
            [f.force[0], f.force[1], f.force[5]],
            [fx, fy, r[0] * fy - r[1] * fx]
        );
    }
}
