//! The quasi-static mooring: every line a static elastic catenary ([`crate::catenary`])
//! between its anchor and its fairlead on the platform, with no line dynamics (no line
//! inertia, drag or damping). The force on the platform at (X, Y, theta) is the sum of the
//! lines' fairlead tensions, in SlowDrift's frame and signs ([`crate::planar`]'s
//! conventions): the inertial frame X, Y with Z up, theta counter-clockwise from +X, the
//! force the lines exert on the platform and its moment about the vertical through the
//! platform's reference point (the body frame's origin in the MoorDyn file).

use crate::lines_file::{self, MooringLine};
use std::path::Path;

/// The lines of one mooring, ready to be evaluated at any platform position.
pub struct QuasiStatic {
    lines: Vec<MooringLine>,
}

/// The force of the lines on the platform and their largest fairlead tension.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineForce {
    /// (Fx, Fy, Mz): N, N, N m.
    pub planar: [f64; 3],
    /// The largest fairlead tension sqrt(HF^2 + VF^2) of the lines, N.
    pub max_tension: f64,
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

    /// The static line force on the platform at q = (X, Y, theta) (m, m, rad).
    pub fn force(&self, q: [f64; 3]) -> Result<LineForce, String> {
        let (sin, cos) = q[2].sin_cos();
        let mut planar = [0.0; 3];
        let mut max_tension: f64 = 0.0;
        for line in &self.lines {
            // The fairlead relative to the reference point, turned by the yaw.
            let f = line.fairlead;
            let r = [cos * f[0] - sin * f[1], sin * f[0] + cos * f[1]];
            let to_anchor = [line.anchor[0] - q[0] - r[0], line.anchor[1] - q[1] - r[1]];
            let xf = to_anchor[0].hypot(to_anchor[1]);
            let zf = f[2] - line.anchor[2];
            let t = line.line.solve(xf, zf).map_err(|e| {
                format!(
                    "line {} at X = {}, Y = {}, theta = {}: {e}",
                    line.id, q[0], q[1], q[2]
                )
            })?;
            // The horizontal tension pulls the fairlead towards the anchor.
            let (fx, fy) = (
                t.horizontal * to_anchor[0] / xf,
                t.horizontal * to_anchor[1] / xf,
            );
            planar[0] += fx;
            planar[1] += fy;
            planar[2] += r[0] * fy - r[1] * fx;
            max_tension = max_tension.max(t.horizontal.hypot(t.vertical));
        }
        Ok(LineForce {
            planar,
            max_tension,
        })
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

    /// One line along +X: the platform is pulled towards +X with the line's horizontal
    /// tension, no sway force, and a moment r x F about the reference point when the
    /// fairlead is off the line of action.
    #[test]
    fn one_line_pulls_towards_its_anchor() {
        let m = QuasiStatic::new(vec![line([980.0, 35.0, -300.0], [45.0, 35.0, -20.0])]);
        let f = m.force([0.0, 0.0, 0.0]).unwrap();
        let t = Line {
            length: 1000.0,
            ea: 6.03e8,
            weight: 1196.37,
        }
        .solve(935.0, 280.0)
        .unwrap();
        assert!((f.planar[0] - t.horizontal).abs() < 1e-9 * t.horizontal);
        assert!(f.planar[1].abs() < 1e-9 * t.horizontal);
        assert!((f.planar[2] - (-35.0 * t.horizontal)).abs() < 1e-9 * 35.0 * t.horizontal);
        assert_eq!(f.max_tension, t.horizontal.hypot(t.vertical));
    }

    /// A symmetric pair of lines: no force at the origin; moving towards one anchor slackens
    /// that line and the pair pulls back (a restoring force); a yaw turns the fairleads and
    /// the pair's moment restores it.
    #[test]
    fn a_symmetric_pair_restores() {
        let m = QuasiStatic::new(vec![
            line([980.0, 0.0, -300.0], [45.0, 0.0, -20.0]),
            line([-980.0, 0.0, -300.0], [-45.0, 0.0, -20.0]),
        ]);
        let f0 = m.force([0.0, 0.0, 0.0]).unwrap();
        assert!(f0.planar.iter().all(|v| v.abs() < 1e-6));
        assert!(m.force([5.0, 0.0, 0.0]).unwrap().planar[0] < 0.0);
        assert!(m.force([-5.0, 0.0, 0.0]).unwrap().planar[0] > 0.0);
        assert!(m.force([0.0, 0.0, 0.05]).unwrap().planar[2] < 0.0);
    }
}
