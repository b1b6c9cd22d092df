//! Moving surge, sway and yaw quantities from the point a diffraction code took moments
//! about to the body origin (the platform's reference point, where SlowDrift's yaw moment and
//! yaw motion are taken).
//!
//! A code may take moments about a reference point r = (x_r, y_r, z_r) other than the body
//! origin: NEMOH's Nemoh.cal names one per generalised force (the OC3 spar's moments are
//! about (0, 0, -78) m). In the horizontal plane (docs/theory.md#conventions; surge, sway, yaw):
//! - the yaw moment about the vertical axis through r is that about the origin less the
//!   moment of the force about the origin's axis: M_o = M_r + x_r F_y - y_r F_x. A point on
//!   the vertical axis through the origin (x_r = y_r = 0, any z_r) changes nothing;
//! - a motion q_o = (x, y, theta) of the origin moves r by q_r = P q_o with
//!   P = [[1, 0, -y_r], [0, 1, x_r], [0, 0, 1]]; forces transform with P^T (F_o = P^T F_r),
//!   so a matrix about r (added mass, damping, stiffness, mass) is P^T A_r P about the origin.
//!
//! Both are linear, so they hold for complex amplitudes and QTF values alike.

use rustfft::num_complex::Complex64;

/// A horizontal reference point (x_r, y_r), m, in the body frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReferencePoint {
    pub x: f64,
    pub y: f64,
}

impl ReferencePoint {
    /// Whether the point lies on the vertical axis through the origin (nothing changes).
    pub fn is_on_vertical_axis(&self) -> bool {
        self.x == 0.0 && self.y == 0.0
    }

    /// The (surge, sway, yaw) force about the origin of one about this point:
    /// M_o = M_r + x_r F_y - y_r F_x.
    pub fn force_to_origin(&self, f: [f64; 3]) -> [f64; 3] {
        [f[0], f[1], f[2] + self.x * f[1] - self.y * f[0]]
    }

    /// [`Self::force_to_origin`] for complex amplitudes (QTF values, bi-directional drift).
    pub fn complex_force_to_origin(&self, f: [Complex64; 3]) -> [Complex64; 3] {
        [f[0], f[1], f[2] + f[1] * self.x - f[0] * self.y]
    }

    /// P^T A P: a (surge, sway, yaw) matrix about this point as one about the origin.
    pub fn matrix_to_origin(&self, a: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
        let p = [[1.0, 0.0, -self.y], [0.0, 1.0, self.x], [0.0, 0.0, 1.0]];
        let mut ap = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                ap[i][j] = (0..3).map(|k| a[i][k] * p[k][j]).sum();
            }
        }
        let mut out = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                out[i][j] = (0..3).map(|k| p[k][i] * ap[k][j]).sum();
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The moment about the origin of a force F applied at a point c is x_c F_y - y_c F_x
    /// (plus any couple); about r it is (x_c - x_r) F_y - (y_c - y_r) F_x. The translation
    /// must turn the second into the first, and the matrix rule must preserve the power
    /// F . v of a force and a velocity field of the rigid body.
    #[test]
    fn moments_and_matrices_move_as_rigid_body_mechanics_says() {
        let r = ReferencePoint { x: 3.0, y: -7.0 };
        let (c, force, couple) = ([11.0, 5.0], [2.0, -4.0], 1.5);
        let about = |p: [f64; 2]| (c[0] - p[0]) * force[1] - (c[1] - p[1]) * force[0] + couple;
        let moved = r.force_to_origin([force[0], force[1], about([r.x, r.y])]);
        assert!((moved[2] - about([0.0, 0.0])).abs() < 1e-12);
        assert_eq!(&moved[..2], &force);
        let z = r.complex_force_to_origin([
            Complex64::new(force[0], 1.0),
            Complex64::new(force[1], -2.0),
            Complex64::new(about([r.x, r.y]), 0.5),
        ]);
        assert!((z[2].re - about([0.0, 0.0])).abs() < 1e-12);
        assert!((z[2].im - (0.5 + r.x * -2.0 - r.y * 1.0)).abs() < 1e-12);
        // Power: v_r = P v_o, F_o = P^T F_r, so v_o . (P^T A_r P) v_o = v_r . A_r v_r.
        let a = [[2.0, 0.3, -1.0], [0.3, 5.0, 0.7], [-1.0, 0.7, 40.0]];
        let v = [0.4, -1.1, 0.05];
        let v_r = [v[0] - r.y * v[2], v[1] + r.x * v[2], v[2]];
        let quad = |m: &[[f64; 3]; 3], x: &[f64; 3]| -> f64 {
            (0..3)
                .map(|i| (0..3).map(|j| x[i] * m[i][j] * x[j]).sum::<f64>())
                .sum()
        };
        let moved = r.matrix_to_origin(&a);
        assert!((quad(&moved, &v) - quad(&a, &v_r)).abs() < 1e-12);
        assert_eq!(
            ReferencePoint { x: 0.0, y: 0.0 }.matrix_to_origin(&a),
            a,
            "a point on the vertical axis changes nothing"
        );
    }
}
