//! Equations of motion in surge, sway and yaw (E&S 1; docs/theory.md#equations-of-motion):
//!
//!   S (M + A) S^T q'' + S B(t) (S^T q' - u_c) + C q = S (D(t) + f_drag + f_extra + f_wind) + F_ext
//!
//! q = (X, Y, theta) inertial; S = S(theta) rotates body-frame vectors into the inertial
//! frame; M + A the rigid and low-frequency added mass (body frame); B(t) the wave-drift
//! damping acting on the body's velocity relative to the current u_c (E&S section 3);
//! C the mooring stiffness on q; D(t) the slowly varying wave force (body frame);
//! f_drag the Morison drag (body frame); f_extra = -B_lin v - B_quad v|v| the user's extra
//! damping on the body-frame velocity v = S^T q'; f_wind the wind's force from the relative
//! velocity of the wind (mean + gust) and the body (`wind::WindForce`,
//! docs/theory.md#wind-force); F_ext an external force in the inertial frame. Second-order terms in the slow velocities are neglected, as in the paper. Since
//! S is orthogonal, q'' = S (M + A)^{-1} S^T (right-hand side).

use crate::error::numbers::written_matrix;
use crate::error::{Error, Result};
use crate::forces::{
    drag_force, drag_forces, ForceRecords, Isa, LaneDrag, SamplePoint, Value, Wide, YawPoint, LANES,
};
use crate::model::DragModel;
use crate::problem::Problem;
use crate::wind::WindForce;
use nalgebra::{Matrix3, Vector3};

/// Forces acting on the body at one instant, inertial frame (N, N, N m).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ForceBreakdown<V = f64> {
    /// Slowly varying wave force S D(t).
    pub wave: [V; 3],
    /// Wave-drift damping force -S B(t)(S^T q' - u_c).
    pub damping: [V; 3],
    /// Morison drag S f_drag.
    pub drag: [V; 3],
    /// Extra linear and quadratic damping S f_extra.
    pub extra_damping: [V; 3],
    /// Mooring stiffness force -C q.
    pub stiffness: [V; 3],
    /// The wind's force S f_wind.
    pub wind: [V; 3],
}

/// The time-independent parts of the equations of motion.
#[derive(Debug, Clone, PartialEq)]
pub struct SlowDriftModel {
    inverse_mass: [[f64; 3]; 3],
    stiffness: [[f64; 3]; 3],
    linear_damping: [[f64; 3]; 3],
    quadratic_damping: [[f64; 3]; 3],
    drag: DragModel,
    water_density: f64,
    /// Current velocity, inertial frame (X, Y), m/s.
    current: [f64; 2],
    /// The wind's force and its mean speed at the force's height (m/s; `None`: the speed is
    /// the input's); `None` when calm.
    wind: Option<(WindForce, Option<f64>)>,
}

/// What the outside holds constant over a step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Held {
    /// The external force F_ext, inertial frame (N, N, N m).
    pub force: [f64; 3],
    /// The wind speed at the force's height, m/s, used when the wind's source is the input
    /// (`WindSource::Input`).
    pub wind_speed: f64,
}

fn matrix(m: &[[f64; 3]; 3]) -> Matrix3<f64> {
    Matrix3::from_fn(|i, j| m[i][j])
}

/// m v for a matrix common to every lane, each row summed from its first column
/// (((m0 v0) + m1 v1) + m2 v2, nalgebra's order).
#[inline(always)]
fn times<V: Value>(m: &[[f64; 3]; 3], v: &[V; 3]) -> [V; 3] {
    std::array::from_fn(|i| {
        V::splat(m[i][0]) * v[0] + V::splat(m[i][1]) * v[1] + V::splat(m[i][2]) * v[2]
    })
}

/// Below this yaw (rad), sin theta and cos theta round to theta and 1: theta^2 / 6 and
/// theta^2 / 2 are below 2^-55, a quarter of the half-ulp 2^-53 of a double near 1.
const SMALL_YAW: f64 = 1.0 / (1u64 << 27) as f64;

/// (sin theta, cos theta) to the nearest double: (theta, 1) below [`SMALL_YAW`], where
/// libm's `sin_cos` gives the same and costs as much as anywhere (glibc sets the rounding
/// mode on each call); a body that does not yaw (head seas on a platform symmetric about
/// x, its yaw of round-off size) takes this path at every stage.
#[inline(always)]
fn sin_cos(theta: f64) -> (f64, f64) {
    if theta.abs() < SMALL_YAW {
        (theta, 1.0)
    } else {
        theta.sin_cos()
    }
}

/// The rotation S(theta) of E&S 1 between the body and the inertial frame, for
/// (surge, sway, yaw) vectors; sin and cos taken once per instant.
#[derive(Debug, Clone, Copy)]
struct Rotation<V> {
    sin: V,
    cos: V,
}

impl<V: Value> Rotation<V> {
    /// Each lane's S(theta) for its yaw in `theta`.
    #[inline(always)]
    fn of(theta: V) -> Self {
        let [sin, cos] = V::gather(|l| {
            let (s, c) = sin_cos(theta.lane(l));
            [s, c]
        });
        Rotation { sin, cos }
    }

    /// Body to inertial: S v.
    #[inline(always)]
    fn to_inertial(self, v: &[V; 3]) -> [V; 3] {
        let (s, c) = (self.sin, self.cos);
        [c * v[0] - s * v[1], s * v[0] + c * v[1], v[2]]
    }

    /// Inertial to body: S^T v.
    #[inline(always)]
    fn to_body(self, v: &[V; 3]) -> [V; 3] {
        let (s, c) = (self.sin, self.cos);
        [c * v[0] + s * v[1], -s * v[0] + c * v[1], v[2]]
    }
}

/// The rotation S(theta) at an instant, and the body's velocity S^T q' (u, v, r) and the
/// current S^T u_c (x, y, 0) in the body frame: one seed's (`f64`) or lanes' ([`Wide`]).
#[derive(Debug, Clone, Copy)]
pub struct BodyFrame<V = f64> {
    rotation: Rotation<V>,
    velocity: [V; 3],
    current: [V; 3],
}

impl<V: Value> BodyFrame<V> {
    /// Lane `l`'s velocity (u, v, r) and current (x, y), as the drag takes them.
    pub fn drag_velocities(&self, l: usize) -> ([f64; 3], [f64; 2]) {
        (
            self.velocity.map(|v| v.lane(l)),
            [self.current[0].lane(l), self.current[1].lane(l)],
        )
    }
}

/// What the forces read from a seed's records at a located instant and yaw (body frame):
/// the slowly varying wave force D(t), the wave-drift damping B(t) (`None` when off), the
/// Morison drag, and the wind speed at the force's height (m/s).
#[derive(Debug, Clone, Copy)]
pub struct Read<V = f64> {
    pub wave: [V; 3],
    pub damping: Option<[[V; 3]; 3]>,
    pub drag: [V; 3],
    pub wind_speed: V,
}

impl SlowDriftModel {
    /// Builds the model, with the mass and added mass of [`Problem::inertia`]; refuses a
    /// singular mass matrix M + A.
    pub fn new(problem: &Problem) -> Result<Self> {
        let p = &problem.platform;
        let inertia = problem.inertia()?;
        let rigid = Matrix3::from_diagonal(&Vector3::new(
            inertia.mass,
            inertia.mass,
            inertia.yaw_inertia,
        ));
        let total = rigid + matrix(&inertia.added_mass);
        let inverse = total.try_inverse().ok_or_else(|| {
            Error::invalid(
                "platform.added_mass",
                written_matrix(&inertia.added_mass),
                "M + A is singular",
            )
        })?;
        let (s, c) = problem.current.direction.sin_cos();
        Ok(SlowDriftModel {
            inverse_mass: std::array::from_fn(|i| std::array::from_fn(|j| inverse[(i, j)])),
            stiffness: p.stiffness,
            linear_damping: p.linear_damping,
            quadratic_damping: p.quadratic_damping,
            drag: problem.model.drag,
            water_density: problem.environment.water_density,
            current: [problem.current.speed * c, problem.current.speed * s],
            wind: problem
                .run_wind()?
                .map(|w| (w.force, w.gusts.map(|g| g.mean))),
        })
    }

    /// The forces at a located instant and yaw (`records.locate_yaw(t, q[2])`) for state
    /// (q, q') (inertial frame), with the input wind speed `wind_input` (m/s).
    pub fn forces(
        &self,
        records: &ForceRecords,
        at: &SamplePoint,
        yaw: &YawPoint,
        q: &[f64; 3],
        qd: &[f64; 3],
        wind_input: f64,
    ) -> ForceBreakdown {
        let body = self.body_frame(q[2], qd);
        let read = self.read(records, at, yaw, &body, wind_input);
        self.breakdown(&body, &read, q)
    }

    /// The acceleration q'' at a located instant and yaw for state (q, q') and what the
    /// outside holds (the external force, inertial frame; the input wind): E&S 1 solved for
    /// q'', with the forces of [`SlowDriftModel::forces`].
    pub fn acceleration(
        &self,
        records: &ForceRecords,
        at: &SamplePoint,
        yaw: &YawPoint,
        q: &[f64; 3],
        qd: &[f64; 3],
        held: &Held,
    ) -> [f64; 3] {
        let body = self.body_frame(q[2], qd);
        let read = self.read(records, at, yaw, &body, held.wind_speed);
        self.acceleration_of(&body, &read, q, &held.force)
    }

    /// The body's velocity and the current in the body frame, S^T q' and S^T u_c, with
    /// S(theta) at the yaw `theta` and the velocity `qd` (inertial frame): what the drag
    /// takes; each lane's for lanes.
    #[inline(always)]
    pub fn body_frame<V: Value>(&self, theta: V, qd: &[V; 3]) -> BodyFrame<V> {
        let rotation = Rotation::of(theta);
        let current = [
            V::splat(self.current[0]),
            V::splat(self.current[1]),
            V::splat(0.0),
        ];
        BodyFrame {
            rotation,
            velocity: rotation.to_body(qd),
            current: rotation.to_body(&current),
        }
    }

    /// What the forces read from one seed's `records` at a located instant and yaw, its drag
    /// for the body's velocity `body`, and the input wind speed `wind_input` (m/s).
    fn read(
        &self,
        records: &ForceRecords,
        at: &SamplePoint,
        yaw: &YawPoint,
        body: &BodyFrame,
        wind_input: f64,
    ) -> Read {
        let lane = self.lane_drag(records, at, body, 0);
        let drag = drag_force(
            lane.kinematics,
            &lane.at,
            self.drag,
            self.water_density,
            lane.velocity,
            lane.current,
        );
        self.read_with_drag(records, at, yaw, drag, wind_input)
    }

    /// [`Read`] of one seed's `records` with its drag `drag` (body frame) already taken.
    fn read_with_drag(
        &self,
        records: &ForceRecords,
        at: &SamplePoint,
        yaw: &YawPoint,
        drag: [f64; 3],
        wind_input: f64,
    ) -> Read {
        Read {
            wave: records.wave_force_at(at, yaw),
            damping: records.damping_at(at, yaw),
            drag,
            wind_speed: self.wind_speed(records, at, wind_input),
        }
    }

    /// [`Read`] of the lanes side by side, but for the drag (left as it is: the lanes' drag
    /// is taken together, [`SlowDriftModel::lane_drags`], at every stage, where the rest of
    /// a read may be kept from a stage at the same time), written into `read` in place (a
    /// read is large, and moving a new one into place cost a copy of it per instant): lane
    /// l's records, located instant and yaw, and input wind speed (m/s) from `lane(l)`.
    #[inline(always)]
    pub fn lanes_read_into<'a>(
        &self,
        read: &mut Read<Wide>,
        lane: impl Fn(usize) -> (&'a ForceRecords, SamplePoint, YawPoint, f64),
    ) {
        let mut damped = false;
        let flat = Wide::gather(|l| {
            let (records, at, yaw, input) = lane(l);
            let b = records.damping_at(&at, &yaw);
            damped |= b.is_some();
            let b = b.unwrap_or_default();
            let wave = records.wave_force_at(&at, &yaw);
            let wind = self.wind_speed(records, &at, input);
            [
                wave[0], wave[1], wave[2], wind, b[0][0], b[0][1], b[0][2], b[1][0], b[1][1],
                b[1][2], b[2][0], b[2][1], b[2][2],
            ]
        });
        read.wave = [flat[0], flat[1], flat[2]];
        read.wind_speed = flat[3];
        // The lanes are of one model: damped in every lane or in none.
        if damped {
            let b = read.damping.get_or_insert([[Wide::splat(0.0); 3]; 3]);
            for (i, row) in b.iter_mut().enumerate() {
                for (j, v) in row.iter_mut().enumerate() {
                    *v = flat[4 + 3 * i + j];
                }
            }
        } else {
            read.damping = None;
        }
    }

    /// What [`drag_forces`] takes of lane `l` of `body`: its records at a located instant,
    /// its velocity.
    pub fn lane_drag<'a, V: Value>(
        &self,
        records: &'a ForceRecords,
        at: &SamplePoint,
        body: &BodyFrame<V>,
        l: usize,
    ) -> LaneDrag<'a> {
        let (velocity, current) = body.drag_velocities(l);
        LaneDrag {
            kinematics: &records.kinematics,
            at: *at,
            velocity,
            current,
        }
    }

    /// The drag of up to [`LANES`] seeds of this model at one instant, each as
    /// [`SlowDriftModel::acceleration`] takes it, bit for bit (`forces::drag_forces`).
    pub fn lane_drags(&self, lanes: &[LaneDrag], isa: Isa) -> [[f64; 3]; LANES] {
        drag_forces(lanes, self.drag, self.water_density, isa)
    }

    /// E&S 1 solved for q'' in each lane: the forces of [`SlowDriftModel::breakdown`] and
    /// the external force `external` (inertial frame).
    #[inline(always)]
    pub fn acceleration_of<V: Value>(
        &self,
        body: &BodyFrame<V>,
        read: &Read<V>,
        q: &[V; 3],
        external: &[V; 3],
    ) -> [V; 3] {
        let total = self.breakdown(body, read, q).total(external);
        self.solve(body.rotation, &total)
    }

    /// The change of velocity (X', Y', theta') over a time `h` that the force `force`
    /// (inertial frame, N, N, N m) alone gives the body at yaw `theta`: S (M + A)^-1 S^T f h
    /// (E&S 1 without the other terms).
    pub fn velocity_change(&self, theta: f64, force: &[f64; 3], h: f64) -> [f64; 3] {
        self.solve(Rotation::of(theta), force).map(|a| a * h)
    }

    /// S (M + A)^-1 S^T f: the acceleration the force `f` (inertial frame) gives the body
    /// at the rotation S (E&S 1 solved for q'').
    #[inline(always)]
    fn solve<V: Value>(&self, rotation: Rotation<V>, force: &[V; 3]) -> [V; 3] {
        let body = rotation.to_body(force);
        rotation.to_inertial(&times(&self.inverse_mass, &body))
    }

    /// The forces (inertial frame) in each lane from what it read, `read`, at the state
    /// `q` and the body frame `body` (E&S 1's terms).
    #[inline(always)]
    fn breakdown<V: Value>(
        &self,
        body: &BodyFrame<V>,
        read: &Read<V>,
        q: &[V; 3],
    ) -> ForceBreakdown<V> {
        let (rotation, velocity, current) = (body.rotation, body.velocity, body.current);
        let zero = [V::splat(0.0); 3];
        let damping = match &read.damping {
            Some(b) => {
                let relative: [V; 3] = std::array::from_fn(|i| velocity[i] - current[i]);
                std::array::from_fn(|i| {
                    -b[i][0] * relative[0] + -b[i][1] * relative[1] + -b[i][2] * relative[2]
                })
            }
            None => zero,
        };
        let quadratic = velocity.map(|v| v * v.abs());
        let (linear, quadratic) = (
            times(&self.linear_damping, &velocity),
            times(&self.quadratic_damping, &quadratic),
        );
        let extra: [V; 3] = std::array::from_fn(|i| -linear[i] - quadratic[i]);
        let stiffness = times(&self.stiffness, q).map(|f| -f);
        let wind = match &self.wind {
            Some((force, _)) => V::gather(|l| {
                force.force(
                    read.wind_speed.lane(l),
                    q[2].lane(l),
                    velocity.map(|v| v.lane(l)),
                )
            }),
            None => zero,
        };
        ForceBreakdown {
            wave: rotation.to_inertial(&read.wave),
            damping: rotation.to_inertial(&damping),
            drag: rotation.to_inertial(&read.drag),
            extra_damping: rotation.to_inertial(&extra),
            stiffness,
            wind: rotation.to_inertial(&wind),
        }
    }

    /// The wind speed at the force's height at a located instant, m/s: the mean plus the
    /// gust record, or the input `wind_input` when the wind's source is the input; 0 when
    /// calm.
    pub fn wind_speed(&self, records: &ForceRecords, at: &SamplePoint, wind_input: f64) -> f64 {
        match &self.wind {
            Some((_, Some(mean))) => mean + records.gust.as_ref().map_or(0.0, |g| g.at(at)),
            Some((_, None)) => wind_input,
            None => 0.0,
        }
    }
}

impl<V: Value> ForceBreakdown<V> {
    /// Sum of all forces plus the external force, inertial frame.
    #[inline(always)]
    pub fn total(&self, external: &[V; 3]) -> [V; 3] {
        std::array::from_fn(|i| {
            self.wave[i]
                + self.damping[i]
                + self.drag[i]
                + self.extra_damping[i]
                + self.stiffness[i]
                + self.wind[i]
                + external[i]
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Below [`SMALL_YAW`] the yaw's sin and cos are libm's, bit for bit (both are the
    /// nearest doubles to the exact values there), from zero and the smallest subnormal to
    /// the largest yaw below the bound, of both signs; at the bound and above, libm's.
    #[test]
    fn a_small_yaws_sin_and_cos_are_libms() {
        let below = f64::from_bits(SMALL_YAW.to_bits() - 1);
        let yaws = [
            0.0,
            f64::from_bits(1),
            1e-300,
            1e-15,
            3.3e-12,
            1e-9,
            7e-9,
            below,
        ];
        for theta in yaws
            .into_iter()
            .flat_map(|t| [t, -t])
            .chain([SMALL_YAW, 0.1, -2.0])
        {
            let (s, c) = sin_cos(theta);
            let (ls, lc) = theta.sin_cos();
            assert_eq!(
                (s.to_bits(), c.to_bits()),
                (ls.to_bits(), lc.to_bits()),
                "{theta:e}"
            );
        }
    }
}
