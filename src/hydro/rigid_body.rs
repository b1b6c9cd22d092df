//! A rigid body's mass properties as the 6x6 matrices of the first-order equation of motion
//! (docs/theory.md#first-order-motions-raos): the mass matrix and the restoring of its weight, about the body
//! reference point (WAMIT's body origin), DOFs surge, sway, heave, roll, pitch, yaw.
//!
//! With S(a) the skew matrix of a (S(a) b = a x b) and r_g the centre of gravity from the
//! reference point, the velocity of a point r of the body is U + Omega x r = U - S(r) Omega;
//! the kinetic energy (1/2) sum m_k |U - S(r_k) Omega|^2 is (1/2) v^T M v with
//!
//! ```text
//! M = [[ m I,       -m S(r_g) ],
//!      [ m S(r_g),   I_o      ]],     I_o = I_g - m S(r_g)^2
//! ```
//!
//! (Fossen, "Handbook of Marine Craft Hydrodynamics and Motion Control", 2011, eq. 3.44;
//! Newman, "Marine Hydrodynamics", 1977, §6.16; I_o is the parallel-axis theorem:
//! -m S(r)^2 = m (|r|^2 I - r r^T)). In WAMIT's notation M15 = m z_g, M16 = -m y_g,
//! M24 = -m z_g, M26 = m x_g, M34 = m y_g, M35 = -m x_g (WAMIT manual v7.4 §3.4).
//!
//! The weight m g, fixed in space and applied at r_g, gives under small rotations theta the
//! moment (theta x r_g) x (-m g e_z) about the reference point: restoring terms
//! C44 = C55 = -m g z_g, C46 = m g x_g, C56 = m g y_g (the gravity terms of WAMIT's
//! hydrostatic matrix, manual v7.4 §3.1). A `.hst` file holds them only when WAMIT's run
//! knew the centre of gravity (OpenFAST's files, run with it at the origin, hold buoyancy
//! alone): add [`RigidBody::weight_stiffness`] when it does not.

use crate::error::{require_finite, require_non_negative, require_positive, Error, Result};

/// Mass, centre of gravity and inertia of a rigid body.
#[derive(Debug, Clone, PartialEq)]
pub struct RigidBody {
    /// Mass m, kg.
    pub mass: f64,
    /// Centre of gravity (x_g, y_g, z_g) from the reference point, body axes, m.
    pub centre_of_gravity: [f64; 3],
    /// Inertia tensor about the centre of gravity, body axes, kg m^2 (symmetric; the
    /// off-diagonal entries are the products of inertia with their minus sign:
    /// I_xy = -sum m x y).
    pub inertia: [[f64; 3]; 3],
}

impl RigidBody {
    /// A body whose inertia about its centre of gravity is m r_i^2 on the axes (radii of
    /// gyration r_x, r_y, r_z, m), no products of inertia.
    pub fn from_radii_of_gyration(mass: f64, centre_of_gravity: [f64; 3], radii: [f64; 3]) -> Self {
        let mut inertia = [[0.0; 3]; 3];
        for (i, r) in radii.iter().enumerate() {
            inertia[i][i] = mass * r * r;
        }
        RigidBody {
            mass,
            centre_of_gravity,
            inertia,
        }
    }

    /// Checks the mass (positive), the centre of gravity (finite) and the inertia
    /// (finite, symmetric, non-negative moments on the axes).
    pub fn validate(&self) -> Result<()> {
        require_positive("rigid_body.mass", self.mass)?;
        for (k, v) in self.centre_of_gravity.iter().enumerate() {
            require_finite(format_args!("rigid_body.centre_of_gravity[{k}]"), *v)?;
        }
        crate::error::require_finite_matrix("rigid_body.inertia", &self.inertia)?;
        for i in 0..3 {
            require_non_negative(&format!("rigid_body.inertia[{i}][{i}]"), self.inertia[i][i])?;
            for j in 0..i {
                let (a, b) = (self.inertia[i][j], self.inertia[j][i]);
                if (a - b).abs() > 1e-12 * a.abs().max(b.abs()) {
                    return Err(Error::invalid(
                        format!("rigid_body.inertia[{i}][{j}]"),
                        a,
                        format!("the inertia tensor must be symmetric: [{j}][{i}] = {b}"),
                    ));
                }
            }
        }
        Ok(())
    }

    /// The 6x6 rigid-body mass matrix about the reference point (the module's equation).
    pub fn mass_matrix(&self) -> [[f64; 6]; 6] {
        let m = self.mass;
        let s = skew(self.centre_of_gravity);
        let s2 = product(&s, &s);
        let mut out = [[0.0; 6]; 6];
        for i in 0..3 {
            out[i][i] = m;
            for j in 0..3 {
                out[i][3 + j] = -m * s[i][j];
                out[3 + i][j] = m * s[i][j];
                out[3 + i][3 + j] = self.inertia[i][j] - m * s2[i][j];
            }
        }
        out
    }

    /// The restoring of the body's weight about the reference point, gravity `g` (m/s^2):
    /// C44 = C55 = -m g z_g, C46 = m g x_g, C56 = m g y_g, the rest zero.
    pub fn weight_stiffness(&self, g: f64) -> [[f64; 6]; 6] {
        let w = self.mass * g;
        let [x, y, z] = self.centre_of_gravity;
        let mut c = [[0.0; 6]; 6];
        c[3][3] = -w * z;
        c[4][4] = -w * z;
        c[3][5] = w * x;
        c[4][5] = w * y;
        c
    }
}

/// S(a), with S(a) b = a x b.
fn skew([x, y, z]: [f64; 3]) -> [[f64; 3]; 3] {
    [[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]]
}

fn product(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let mut c = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            c[i][j] = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    c
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cloud of point masses: its mass, centre, inertia about the centre, and the mass
    /// matrix summed point by point from the kinetic energy,
    /// m_k [[I, -S(r_k)], [S(r_k), -S(r_k)^2]] written out entry by entry.
    const POINTS: [(f64, [f64; 3]); 5] = [
        (2.0, [1.0, -0.5, 3.0]),
        (1.5, [-2.0, 0.7, -1.0]),
        (3.0, [0.3, 2.0, -4.0]),
        (0.5, [4.0, -3.0, 0.5]),
        (1.0, [-1.0, -1.0, -2.5]),
    ];

    fn cloud() -> (RigidBody, [[f64; 6]; 6]) {
        let points = POINTS;
        let m: f64 = points.iter().map(|p| p.0).sum();
        let mut g = [0.0; 3];
        for (mk, r) in &points {
            for i in 0..3 {
                g[i] += mk * r[i] / m;
            }
        }
        let mut inertia = [[0.0; 3]; 3];
        let mut big = [[0.0; 6]; 6];
        for (mk, r) in &points {
            let d = [r[0] - g[0], r[1] - g[1], r[2] - g[2]];
            let d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            let r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
            let [x, y, z] = *r;
            // m [[I, -S(r)], [S(r), |r|^2 I - r r^T]]
            let block: [[f64; 6]; 6] = [
                [1.0, 0.0, 0.0, 0.0, z, -y],
                [0.0, 1.0, 0.0, -z, 0.0, x],
                [0.0, 0.0, 1.0, y, -x, 0.0],
                [0.0, -z, y, r2 - x * x, -x * y, -x * z],
                [z, 0.0, -x, -y * x, r2 - y * y, -y * z],
                [-y, x, 0.0, -z * x, -z * y, r2 - z * z],
            ];
            for i in 0..6 {
                for j in 0..6 {
                    big[i][j] += mk * block[i][j];
                }
            }
            for i in 0..3 {
                for j in 0..3 {
                    let delta = if i == j { d2 } else { 0.0 };
                    inertia[i][j] += mk * (delta - d[i] * d[j]);
                }
            }
        }
        (
            RigidBody {
                mass: m,
                centre_of_gravity: g,
                inertia,
            },
            big,
        )
    }

    #[test]
    fn mass_matrix_is_the_point_clouds() {
        let (body, expected) = cloud();
        body.validate().unwrap();
        let got = body.mass_matrix();
        for i in 0..6 {
            for j in 0..6 {
                assert!(
                    (got[i][j] - expected[i][j]).abs() <= 1e-12 * 100.0,
                    "M[{i}][{j}] = {} vs the cloud's {}",
                    got[i][j],
                    expected[i][j]
                );
            }
        }
    }

    /// The moment of the cloud's weights (each at its own point) about the origin after a finite rotation (Rodrigues),
    /// differentiated by central differences: -dM/dtheta is the weight's restoring matrix.
    #[test]
    fn weight_stiffness_is_the_rotated_weights_moment() {
        let (body, _) = cloud();
        let g = 9.80665;
        let points = POINTS;
        let moment = |theta: [f64; 3]| -> [f64; 3] {
            let angle = (theta[0].powi(2) + theta[1].powi(2) + theta[2].powi(2)).sqrt();
            let mut total = [0.0; 3];
            for (mk, r) in &points {
                let rotated = if angle == 0.0 {
                    *r
                } else {
                    let k = theta.map(|t| t / angle);
                    let kxr = [
                        k[1] * r[2] - k[2] * r[1],
                        k[2] * r[0] - k[0] * r[2],
                        k[0] * r[1] - k[1] * r[0],
                    ];
                    let kdr = k[0] * r[0] + k[1] * r[1] + k[2] * r[2];
                    let (s, c) = angle.sin_cos();
                    [0, 1, 2].map(|i| r[i] * c + kxr[i] * s + k[i] * kdr * (1.0 - c))
                };
                let f = [0.0, 0.0, -mk * g];
                total[0] += rotated[1] * f[2] - rotated[2] * f[1];
                total[1] += rotated[2] * f[0] - rotated[0] * f[2];
                total[2] += rotated[0] * f[1] - rotated[1] * f[0];
            }
            total
        };
        let c = body.weight_stiffness(g);
        let h = 1e-6;
        for j in 0..3 {
            let mut plus = [0.0; 3];
            let mut minus = [0.0; 3];
            plus[j] = h;
            minus[j] = -h;
            let (mp, mm) = (moment(plus), moment(minus));
            for i in 0..3 {
                let expected = -(mp[i] - mm[i]) / (2.0 * h);
                assert!(
                    (c[3 + i][3 + j] - expected).abs() <= 1e-6 * body.mass * g,
                    "C[{}][{}] = {} vs {expected}",
                    3 + i,
                    3 + j,
                    c[3 + i][3 + j]
                );
            }
        }
    }

    #[test]
    fn radii_of_gyration_and_bad_inertia() {
        let body = RigidBody::from_radii_of_gyration(4.0, [0.0, 0.0, -1.0], [2.0, 3.0, 1.0]);
        body.validate().unwrap();
        let m = body.mass_matrix();
        // Roll about the reference point: m (r_x^2 + z_g^2) = 4 (4 + 1).
        assert_eq!(m[3][3], 20.0);
        assert_eq!(m[4][4], 4.0 * (9.0 + 1.0));
        assert_eq!(m[5][5], 4.0);
        assert_eq!(m[0][4], -4.0);
        let mut bad = body.clone();
        bad.inertia[0][1] = 1.0;
        let err = bad.validate().unwrap_err().to_string();
        assert!(err.contains("rigid_body.inertia[1][0]"), "{err}");
    }
}
