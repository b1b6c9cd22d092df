//! The platform's motion and force against MoorDyn's coupled 6-DOF body: the frame, the
//! angles and the signs, in one place.
//!
//! **The FMU's inputs** (SlowDrift's convention for the platform's whole motion, slow drift
//! plus wave-frequency motion): the inertial frame X, Y, Z with Z up, at the platform's
//! reference point (the origin of body 1's frame in the MoorDyn file); `theta` the yaw, a
//! rotation about +Z of any size, counter-clockwise from +X; `roll` and `pitch` SMALL
//! rotations about the INERTIAL X and Y axes (the components of the small wave-frequency
//! rotation vector a = (roll, pitch, 0) in inertial axes). The platform's orientation is
//! R = (I + [a]x) Rz(theta) to first order in roll and pitch, [a]x the cross-product
//! matrix. The rates are the time derivatives of these six numbers.
//!
//! **MoorDyn's coupled body** (MoorDyn 2.7, `source/Misc.hpp`, `Euler2Quat`: the quaternion
//! `AngleAxis(r6[3], UnitX) * AngleAxis(r6[4], UnitY) * AngleAxis(r6[5], UnitZ)`, made by
//! `XYZQuat::fromVec6` in `Body::updateFairlead`, `source/Body.cpp`, and applied to the
//! body-frame points by `transformKinematics`, `source/Misc.cpp`) takes
//! r6 = (x, y, z, roll, pitch, yaw) with the rotation
//! R = Rx(roll) Ry(pitch) Rz(yaw): a point p of the body frame is at x + R p. Checked against
//! the `moordyn` 2.7.2 wheel by `tests/clients/test_mooring_file.py`. Since
//! Rx(roll) Ry(pitch) = I + [(roll, pitch, 0)]x + O(roll^2, pitch^2, roll pitch), MoorDyn's
//! rotation of the inputs' six numbers taken as they are IS the inputs' orientation to first
//! order in roll and pitch (exactly for the yaw): the map is the identity,
//! r6 = (X, Y, Z, roll, pitch, theta), and the difference is of second order, below what the
//! inputs' first-order convention defines.
//!
//! **Velocities.** MoorDyn moves a coupled body along its velocity during a step,
//! r6(t) = r6 + t v6 (`Body::updateFairlead`), so v6 must be the time derivative of r6: the
//! inputs' rates, (Xdot, Ydot, Zdot, rolldot, pitchdot, thetadot). MoorDyn also takes the
//! last three as the angular velocity w for the points' velocities
//! (v + w x R p, `transformKinematics`); the platform's angular velocity in inertial axes is
//! (rolldot + pitch thetadot, pitchdot - roll thetadot, thetadot) to first order, so the
//! fairlead velocities MoorDyn uses for line drag miss terms of the order angle x rate.
//!
//! **The force** MoorDyn returns for the body, (Fx, Fy, Fz, Mx, My, Mz), is the force the
//! lines exert on the platform, in the inertial axes, and its moment about the platform's
//! reference point (`Point::getNetForceAndMass` about `r7.pos`): the FMU's outputs as they
//! are, Fz positive up, the moments right-handed about +X, +Y, +Z.
//!
//! The quasi-static lines use the same rotation ([`rotation`]), so both line models put
//! the fairleads at the same place.

/// The index of each of MoorDyn's six coupled degrees of freedom (and force components).
pub const SURGE: usize = 0;
pub const SWAY: usize = 1;
pub const HEAVE: usize = 2;
pub const ROLL: usize = 3;
pub const PITCH: usize = 4;
pub const YAW: usize = 5;

/// MoorDyn's rotation matrix Rx(roll) Ry(pitch) Rz(yaw) of a 6-DOF position
/// (x, y, z, roll, pitch, yaw), rows of the inertial axes: `R[i][j]` is the inertial
/// component i of the body axis j. With roll = pitch = 0 its entries are exactly the yaw's
/// cos and sin (no rounding from the zero angles).
pub fn rotation(r6: [f64; 6]) -> [[f64; 3]; 3] {
    let (sr, cr) = r6[ROLL].sin_cos();
    let (sp, cp) = r6[PITCH].sin_cos();
    let (sy, cy) = r6[YAW].sin_cos();
    [
        [cp * cy, -(cp * sy), sp],
        [cr * sy + sr * sp * cy, cr * cy - sr * sp * sy, -(sr * cp)],
        [sr * sy - cr * sp * cy, sr * cy + cr * sp * sy, cr * cp],
    ]
}

/// The body-frame point `p` turned with the body at `r6`: R p, its position relative to the
/// reference point in inertial axes (the point is at x + R p).
pub fn turn(r6: [f64; 6], p: [f64; 3]) -> [f64; 3] {
    let r = rotation(r6);
    std::array::from_fn(|i| r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn product(a: [[f64; 3]; 3], b: [[f64; 3]; 3]) -> [[f64; 3]; 3] {
        std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
    }

    /// The closed form is the product of the three elementary rotations, in MoorDyn's order.
    #[test]
    fn rotation_is_rx_ry_rz() {
        let (r, p, y): (f64, f64, f64) = (0.07, -0.05, 2.3);
        let rx = [
            [1.0, 0.0, 0.0],
            [0.0, r.cos(), -r.sin()],
            [0.0, r.sin(), r.cos()],
        ];
        let ry = [
            [p.cos(), 0.0, p.sin()],
            [0.0, 1.0, 0.0],
            [-p.sin(), 0.0, p.cos()],
        ];
        let rz = [
            [y.cos(), -y.sin(), 0.0],
            [y.sin(), y.cos(), 0.0],
            [0.0, 0.0, 1.0],
        ];
        let expected = product(rx, product(ry, rz));
        let got = rotation([0.0, 0.0, 0.0, r, p, y]);
        for i in 0..3 {
            for j in 0..3 {
                assert!((got[i][j] - expected[i][j]).abs() < 1e-15, "{i} {j}");
            }
        }
    }

    /// To first order in roll and pitch it is the inputs' (I + [(roll, pitch, 0)]x) Rz(yaw):
    /// the difference shrinks as the square of the angles.
    #[test]
    fn first_order_is_the_inputs_convention() {
        let y: f64 = 0.8;
        let error = |e: f64| {
            let (r, p) = (3.0 * e, -2.0 * e);
            let skew = [[1.0, 0.0, p], [0.0, 1.0, -r], [-p, r, 1.0]];
            let rz = [
                [y.cos(), -y.sin(), 0.0],
                [y.sin(), y.cos(), 0.0],
                [0.0, 0.0, 1.0],
            ];
            let first = product(skew, rz);
            let exact = rotation([0.0, 0.0, 0.0, r, p, y]);
            (0..9)
                .map(|k| (exact[k / 3][k % 3] - first[k / 3][k % 3]).abs())
                .fold(0.0, f64::max)
        };
        let (coarse, fine) = (error(1e-2), error(1e-3));
        assert!(coarse < 2e-3, "{coarse}");
        assert!((fine / coarse - 1e-2).abs() < 2e-3, "{fine} {coarse}");
    }

    /// In the plane the point turns counter-clockwise by the yaw, exactly as cos/sin do.
    #[test]
    fn planar_yaw_is_exact_and_counter_clockwise() {
        let y: f64 = 0.3;
        let (s, c) = y.sin_cos();
        let p = turn([1.0, -2.0, 0.0, 0.0, 0.0, y], [45.0, 35.0, -20.0]);
        assert_eq!(p, [c * 45.0 - s * 35.0, s * 45.0 + c * 35.0, -20.0]);
        let up = turn(
            [0.0, 0.0, 0.0, 0.0, 0.0, std::f64::consts::FRAC_PI_2],
            [1.0, 0.0, 0.0],
        );
        assert!((up[0]).abs() < 1e-15 && (up[1] - 1.0).abs() < 1e-15);
    }
}
