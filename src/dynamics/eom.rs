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
    drag_force, drag_forces, ForceRecords, Isa, LaneDrag, SamplePoint, YawPoint, LANES,
};
use crate::model::DragModel;
use crate::problem::Problem;
use crate::wind::WindForce;
use nalgebra::{Matrix3, Vector3};

/// Forces acting on the body at one instant, inertial frame (N, N, N m).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ForceBreakdown {
    /// Slowly varying wave force S D(t).
    pub wave: [f64; 3],
    /// Wave-drift damping force -S B(t)(S^T q' - u_c).
    pub damping: [f64; 3],
    /// Morison drag S f_drag.
    pub drag: [f64; 3],
    /// Extra linear and quadratic damping S f_extra.
    pub extra_damping: [f64; 3],
    /// Mooring stiffness force -C q.
    pub stiffness: [f64; 3],
    /// The wind's force S f_wind.
    pub wind: [f64; 3],
}

/// The time-independent parts of the equations of motion.
#[derive(Debug, Clone, PartialEq)]
pub struct SlowDriftModel {
    inverse_mass: Matrix3<f64>,
    stiffness: Matrix3<f64>,
    linear_damping: Matrix3<f64>,
    quadratic_damping: Matrix3<f64>,
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

/// The rotation S(theta) of E&S 1 between the body and the inertial frame, for
/// (surge, sway, yaw) vectors; sin and cos taken once per instant.
#[derive(Debug, Clone, Copy)]
struct Rotation {
    sin: f64,
    cos: f64,
}

impl Rotation {
    fn new(theta: f64) -> Self {
        let (sin, cos) = theta.sin_cos();
        Rotation { sin, cos }
    }

    /// Body to inertial: S v.
    fn to_inertial(self, v: &Vector3<f64>) -> Vector3<f64> {
        let (s, c) = (self.sin, self.cos);
        Vector3::new(c * v[0] - s * v[1], s * v[0] + c * v[1], v[2])
    }

    /// Inertial to body: S^T v.
    fn to_body(self, v: &Vector3<f64>) -> Vector3<f64> {
        let (s, c) = (self.sin, self.cos);
        Vector3::new(c * v[0] + s * v[1], -s * v[0] + c * v[1], v[2])
    }
}

/// The rotation S(theta) at an instant, and the body's velocity S^T q' (u, v, r) and the
/// current S^T u_c (x, y, 0) in the body frame.
#[derive(Debug, Clone, Copy)]
pub struct BodyFrame {
    rotation: Rotation,
    velocity: Vector3<f64>,
    current: Vector3<f64>,
}

impl BodyFrame {
    /// The current's (x, y), as the drag takes it.
    fn drag_current(&self) -> [f64; 2] {
        [self.current[0], self.current[1]]
    }
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
        let inverse_mass = total.try_inverse().ok_or_else(|| {
            Error::invalid(
                "platform.added_mass",
                written_matrix(&inertia.added_mass),
                "M + A is singular",
            )
        })?;
        let (s, c) = problem.current.direction.sin_cos();
        Ok(SlowDriftModel {
            inverse_mass,
            stiffness: matrix(&p.stiffness),
            linear_damping: matrix(&p.linear_damping),
            quadratic_damping: matrix(&p.quadratic_damping),
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
        let body = self.body_frame(q, qd);
        let drag = self.drag(records, at, &body);
        self.forces_with_drag(&body, drag, records, at, yaw, q, wind_input)
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
        let body = self.body_frame(q, qd);
        let drag = self.drag(records, at, &body);
        self.acceleration_with_drag(&body, drag, records, at, yaw, q, held)
    }

    /// The state's velocity and the current in the body frame, S^T q' and S^T u_c, with
    /// S(theta): what the drag takes.
    pub fn body_frame(&self, q: &[f64; 3], qd: &[f64; 3]) -> BodyFrame {
        let rotation = Rotation::new(q[2]);
        BodyFrame {
            rotation,
            velocity: rotation.to_body(&Vector3::from(*qd)),
            current: rotation.to_body(&Vector3::new(self.current[0], self.current[1], 0.0)),
        }
    }

    /// The Morison drag f_drag (body frame) at a located instant for the body's velocity
    /// `body`.
    fn drag(&self, records: &ForceRecords, at: &SamplePoint, body: &BodyFrame) -> [f64; 3] {
        let lane = self.lane_drag(records, at, body);
        drag_force(
            lane.kinematics,
            &lane.at,
            self.drag,
            self.water_density,
            lane.velocity,
            lane.current,
        )
    }

    /// What [`drag_forces`] takes of one lane: its records at a located instant, its
    /// velocity `body`.
    pub fn lane_drag<'a>(
        &self,
        records: &'a ForceRecords,
        at: &SamplePoint,
        body: &BodyFrame,
    ) -> LaneDrag<'a> {
        LaneDrag {
            kinematics: &records.kinematics,
            at: *at,
            velocity: body.velocity.into(),
            current: body.drag_current(),
        }
    }

    /// The drag of up to [`LANES`] seeds of this model at one instant, each as
    /// [`SlowDriftModel::acceleration`] takes it, bit for bit (`forces::drag_forces`).
    pub fn lane_drags(&self, lanes: &[LaneDrag], isa: Isa) -> [[f64; 3]; LANES] {
        drag_forces(lanes, self.drag, self.water_density, isa)
    }

    /// [`SlowDriftModel::acceleration`] with the body frame and the drag `drag` (body frame)
    /// already taken.
    #[allow(clippy::too_many_arguments)]
    pub fn acceleration_with_drag(
        &self,
        body: &BodyFrame,
        drag: [f64; 3],
        records: &ForceRecords,
        at: &SamplePoint,
        yaw: &YawPoint,
        q: &[f64; 3],
        held: &Held,
    ) -> [f64; 3] {
        let total = self
            .forces_with_drag(body, drag, records, at, yaw, q, held.wind_speed)
            .total(&held.force);
        self.solve(&body.rotation, &total).into()
    }

    /// The change of velocity (X', Y', theta') over a time `h` that the force `force`
    /// (inertial frame, N, N, N m) alone gives the body at yaw `theta`: S (M + A)^-1 S^T f h
    /// (E&S 1 without the other terms).
    pub fn velocity_change(&self, theta: f64, force: &[f64; 3], h: f64) -> [f64; 3] {
        (self.solve(&Rotation::new(theta), force) * h).into()
    }

    /// S (M + A)^-1 S^T f: the acceleration the force `f` (inertial frame) gives the body
    /// at the rotation S (E&S 1 solved for q'').
    fn solve(&self, rotation: &Rotation, force: &[f64; 3]) -> Vector3<f64> {
        let body = rotation.to_body(&Vector3::from(*force));
        rotation.to_inertial(&(self.inverse_mass * body))
    }

    /// [`SlowDriftModel::forces`] with the body frame and the drag (body frame) already
    /// taken.
    #[allow(clippy::too_many_arguments)]
    fn forces_with_drag(
        &self,
        body: &BodyFrame,
        drag: [f64; 3],
        records: &ForceRecords,
        at: &SamplePoint,
        yaw: &YawPoint,
        q: &[f64; 3],
        wind_input: f64,
    ) -> ForceBreakdown {
        let (rotation, velocity, current) = (body.rotation, body.velocity, body.current);
        let wave = Vector3::from(records.wave_force_at(at, yaw));
        let damping = match records.damping_at(at, yaw) {
            Some(b) => {
                let relative = velocity - current;
                -Matrix3::from_fn(|i, j| b[i][j]) * relative
            }
            None => Vector3::zeros(),
        };
        let drag = Vector3::from(drag);
        let quadratic = velocity.map(|v| v * v.abs());
        let extra = -(self.linear_damping * velocity) - self.quadratic_damping * quadratic;
        let stiffness = -(self.stiffness * Vector3::from(*q));
        let wind = match &self.wind {
            Some((force, _)) => Vector3::from(force.force(
                self.wind_speed(records, at, wind_input),
                q[2],
                velocity.into(),
            )),
            None => Vector3::zeros(),
        };
        ForceBreakdown {
            wave: rotation.to_inertial(&wave).into(),
            damping: rotation.to_inertial(&damping).into(),
            drag: rotation.to_inertial(&drag).into(),
            extra_damping: rotation.to_inertial(&extra).into(),
            stiffness: stiffness.into(),
            wind: rotation.to_inertial(&wind).into(),
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

impl ForceBreakdown {
    /// Sum of all forces plus the external force, inertial frame.
    pub fn total(&self, external: &[f64; 3]) -> [f64; 3] {
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
