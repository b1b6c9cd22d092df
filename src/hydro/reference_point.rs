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

/// The 6-DOF rigid-body transfer from a point r = (x_r, y_r, z_r) to the origin, for the
/// first-order coefficients (surge, sway, heave, roll, pitch, yaw): a small motion
/// q_o = (u, theta) of the origin moves r by u + theta x r, q_r = P q_o with
/// P = [[I, -S(r)], [0, I]] (S(a) b = a x b); forces move with P^T, F_o = (F, M_r + r x F),
/// and a matrix about r (mass, added mass, damping, stiffness) is P^T A_r P about the origin.
///
/// For a stiffness this is the linearisation about an equilibrium where the generalised
/// force is zero (a freely floating body whose weight balances its buoyancy, the
/// hydrostatics and the weight together): with a static force F_0 the moment arm's rotation
/// would add theta x r terms times F_0.
pub fn matrix6_to_origin(r: [f64; 3], a: &[[f64; 6]; 6]) -> [[f64; 6]; 6] {
    let p = transfer6(r);
    let mut ap = [[0.0; 6]; 6];
    for i in 0..6 {
        for j in 0..6 {
            ap[i][j] = (0..6).map(|k| a[i][k] * p[k][j]).sum();
        }
    }
    let mut out = [[0.0; 6]; 6];
    for i in 0..6 {
        for j in 0..6 {
            out[i][j] = (0..6).map(|k| p[k][i] * ap[k][j]).sum();
        }
    }
    out
}

/// P^T F: a 6-DOF force (complex amplitudes) about r as one about the origin
/// ([`matrix6_to_origin`]): the force kept, the moment M_r + r x F.
pub fn force6_to_origin(r: [f64; 3], f: [Complex64; 6]) -> [Complex64; 6] {
    let [x, y, z] = r;
    [
        f[0],
        f[1],
        f[2],
        f[3] + f[2] * y - f[1] * z,
        f[4] + f[0] * z - f[2] * x,
        f[5] + f[1] * x - f[0] * y,
    ]
}

/// P = [[I, -S(r)], [0, I]]: q_r = P q_o.
fn transfer6(r: [f64; 3]) -> [[f64; 6]; 6] {
    let [x, y, z] = r;
    // S(r) = [[0, -z, y], [z, 0, -x], [-y, x, 0]].
    let s = [[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]];
    let mut p = [[0.0; 6]; 6];
    for (i, row) in p.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    for i in 0..3 {
        for j in 0..3 {
            p[i][3 + j] = -s[i][j];
        }
    }
    p
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

    /// The 6-DOF transfer: the moment about the origin of a force F at a point c plus a
    /// couple is r x F more than about r; a matrix moved by P^T A P keeps the power of every
    /// rigid-body velocity (v_r = v_o + w x r); a point on the z axis leaves heave and yaw
    /// rows alone and gives the mass matrix's m z coupling (M15 = m z_r of a mass at r).
    #[test]
    fn six_dof_transfer_is_rigid_body_mechanics() {
        let r = [2.0, -3.0, -78.0];
        let (c, force, couple) = ([5.0, 1.0, -20.0], [3.0, -2.0, 7.0], [0.5, -0.25, 1.0]);
        let cross = |a: [f64; 3], b: [f64; 3]| {
            [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ]
        };
        let about = |p: [f64; 3]| {
            let m = cross([c[0] - p[0], c[1] - p[1], c[2] - p[2]], force);
            [m[0] + couple[0], m[1] + couple[1], m[2] + couple[2]]
        };
        let m_r = about(r);
        let f_r: [Complex64; 6] =
            std::array::from_fn(|i| Complex64::new(if i < 3 { force[i] } else { m_r[i - 3] }, 0.0));
        let moved = force6_to_origin(r, f_r);
        let m_o = about([0.0; 3]);
        for i in 0..3 {
            assert!((moved[i].re - force[i]).abs() < 1e-12);
            assert!(
                (moved[3 + i].re - m_o[i]).abs() < 1e-9,
                "{i}: {moved:?} vs {m_o:?}"
            );
        }
        let mut a = [[0.0; 6]; 6];
        for (i, row) in a.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v = 1.0 + (i * 7 + j * 3) as f64 % 5.0 + if i == j { 20.0 } else { 0.0 };
            }
        }
        let v_o = [0.3, -0.7, 0.2, 0.01, -0.02, 0.015];
        let w = [v_o[3], v_o[4], v_o[5]];
        let wr = cross(w, r);
        let v_r = [
            v_o[0] + wr[0],
            v_o[1] + wr[1],
            v_o[2] + wr[2],
            w[0],
            w[1],
            w[2],
        ];
        let quad = |m: &[[f64; 6]; 6], x: &[f64; 6]| -> f64 {
            (0..6)
                .map(|i| (0..6).map(|j| x[i] * m[i][j] * x[j]).sum::<f64>())
                .sum()
        };
        let a_o = matrix6_to_origin(r, &a);
        assert!((quad(&a_o, &v_o) - quad(&a, &v_r)).abs() < 1e-9 * quad(&a, &v_r).abs());
        let mut mass = [[0.0; 6]; 6];
        for (i, row) in mass.iter_mut().enumerate() {
            row[i] = if i < 3 { 10.0 } else { 100.0 };
        }
        let m_o = matrix6_to_origin([0.0, 0.0, -78.0], &mass);
        assert_eq!(m_o[0][4], 10.0 * -78.0);
        assert_eq!(m_o[1][3], -10.0 * -78.0);
        assert_eq!(m_o[4][4], 100.0 + 10.0 * 78.0 * 78.0);
        assert_eq!(m_o[2], mass[2]);
        assert_eq!(m_o[5], mass[5]);
    }
}
