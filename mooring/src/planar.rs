//! SlowDrift's planar degrees of freedom against MoorDyn's coupled 6-DOF body.
//!
//! Both use the inertial frame X, Y with Z up and angles in radians, counter-clockwise
//! about +Z. MoorDyn's coupled body takes (x, y, z, roll, pitch, yaw) and returns the force
//! of the lines on the body as (Fx, Fy, Fz, Mx, My, Mz), inertial frame, about the body's
//! reference point; SlowDrift's platform moves in (X, Y, theta) with z, roll and pitch held
//! at zero, and takes the external force (Fx_ext, Fy_ext, Mz_ext) in the same frame about
//! the same point. So the mapping is a selection, with no sign change: positions and
//! velocities go to components 0, 1 and 5 (yaw), the force comes from components 0, 1
//! and 5 (the moment about Z), and the vertical force and the roll and pitch moments are
//! carried by the platform's hydrostatics, which SlowDrift does not model.

/// The 6-DOF vector of a planar state (X, Y, theta): (X, Y, 0, 0, 0, theta).
pub fn body6(q: [f64; 3]) -> [f64; 6] {
    [q[0], q[1], 0.0, 0.0, 0.0, q[2]]
}

/// The planar force (Fx, Fy, Mz) of a 6-DOF force (Fx, Fy, Fz, Mx, My, Mz).
pub fn planar_force(f: [f64; 6]) -> [f64; 3] {
    [f[0], f[1], f[5]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn yaw_is_the_sixth_component_and_nothing_changes_sign() {
        assert_eq!(body6([1.0, -2.0, 0.3]), [1.0, -2.0, 0.0, 0.0, 0.0, 0.3]);
        assert_eq!(
            planar_force([1.0, 2.0, 3.0, 4.0, 5.0, 6.0]),
            [1.0, 2.0, 6.0]
        );
    }
}
