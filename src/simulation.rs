//! [`Simulation`]: the one safe Rust API over the core, used by the CLI, the FMU, the tests
//! and the benchmarks.
//!
//! `new` precomputes every record (E&S section 2: forces at the mean position); `step`
//! advances one RK4 step h, `advance` any interval in equal substeps no longer than h.
//! Time is always origin + count * step from an integer count, never an accumulated sum.

pub mod bounds;
mod lanes;
mod recording;
pub use lanes::Lockstep;
pub use recording::{reserve_recorded, run_steps};

pub use crate::dynamics::Held;
use crate::dynamics::{rk4_step, ForceBreakdown, SlowDriftModel};
use crate::error::numbers::written;
use crate::error::{Error, Result};
use crate::forces::{
    refine, ForceRecords, RecordClock, SamplePoint, Segments, WholeMotion, YawPoint,
};
use crate::problem::Problem;
use crate::record_plan::{QtfRank, RecordPlan, Segment};
use crate::sea_state::FrequencyGrid;
use std::sync::Arc;

/// How far ahead of a step its records are prefetched, samples
/// ([`ForceRecords::prefetch`]): at the default 0.5-s samples and 1-s step, 32 steps. A
/// sample arrives long before it is read (a step takes about a microsecond) and is still
/// in the cache when it is (a seed's 13 records x 64 samples x 8 B = 6.7 kB).
const PREFETCH_AHEAD: usize = 64;

/// Relative tolerance for deciding that an interval is a whole number of steps.
const WHOLE_STEPS_TOLERANCE: f64 = 1e-9;

/// The complete dynamic state: what a snapshot holds and a restore brings back.
/// (The records are a pure function of the configuration and are not part of it.)
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    /// Time = origin + count * step, with the configured step h.
    origin: f64,
    count: u64,
    step: f64,
    /// (X, Y, theta), m, m, rad; inertial frame.
    position: [f64; 3],
    /// (X', Y', theta'), m/s, m/s, rad/s.
    velocity: [f64; 3],
    /// The external force of the last step, inertial frame (N, N, N m).
    external_force: [f64; 3],
    /// The input wind speed at the force's height, m/s, held from [`Simulation::hold_wind_input`]
    /// on (used when the wind's source is the input).
    wind_input: f64,
}

impl Snapshot {
    /// Length of [`Snapshot::to_bytes`]: 13 little-endian 8-byte fields.
    pub const BYTES: usize = 13 * 8;

    /// Current time, s.
    pub fn time(&self) -> f64 {
        self.origin + self.count as f64 * self.step
    }

    /// The RK4 step h the snapshot was taken with, s.
    pub fn step(&self) -> f64 {
        self.step
    }

    /// Refuses a snapshot that no simulation can be in: a value that is not finite (the
    /// time, its origin and step, the external force, the wind input), a step that is not
    /// positive, a negative wind input, a state
    /// beyond the bounds of a physical state ([`bounds`]). [`Snapshot::from_bytes`] and
    /// [`Simulation::restore`] both check it; whether it suits a simulation (its step, the
    /// records at its time) is the restore's question.
    pub fn check(&self) -> Result<()> {
        bounds::check_restored(&self.position, &self.velocity)?;
        let f = &self.external_force;
        let named = [
            ("origin", self.origin),
            ("step", self.step),
            ("external_force[0]", f[0]),
            ("external_force[1]", f[1]),
            ("external_force[2]", f[2]),
            ("wind_input", self.wind_input),
            ("time", self.time()),
        ];
        for (name, value) in named {
            if !value.is_finite() {
                return Err(Error::invalid(
                    format!("snapshot {name}"),
                    value,
                    "must be a finite number",
                ));
            }
        }
        if self.step <= 0.0 {
            return Err(Error::invalid(
                "snapshot step",
                self.step,
                "must be greater than zero",
            ));
        }
        if self.wind_input < 0.0 {
            return Err(Error::invalid(
                "snapshot wind_input",
                self.wind_input,
                "must be at least 0 m/s",
            ));
        }
        Ok(())
    }

    /// Position-independent bytes, little-endian, in this order: origin (f64), count (u64),
    /// step (f64), position (3 f64), velocity (3 f64), external force (3 f64), wind input
    /// (f64).
    pub fn to_bytes(&self) -> [u8; Self::BYTES] {
        let mut out = [0u8; Self::BYTES];
        let words = [self.origin.to_bits(), self.count, self.step.to_bits()]
            .into_iter()
            .chain(self.position.iter().map(|v| v.to_bits()))
            .chain(self.velocity.iter().map(|v| v.to_bits()))
            .chain(self.external_force.iter().map(|v| v.to_bits()))
            .chain(std::iter::once(self.wind_input.to_bits()));
        for (chunk, word) in out.chunks_exact_mut(8).zip(words) {
            chunk.copy_from_slice(&word.to_le_bytes());
        }
        out
    }

    /// Reads [`Snapshot::to_bytes`]; refuses any other length and what [`Snapshot::check`]
    /// refuses. (Whether the values suit a simulation is [`Simulation::restore`]'s check.)
    pub fn from_bytes(bytes: &[u8]) -> Result<Snapshot> {
        if bytes.len() != Self::BYTES {
            return Err(Error::invalid(
                "snapshot bytes",
                bytes.len(),
                format!("a snapshot is {} bytes", Self::BYTES),
            ));
        }
        let mut words = bytes
            .chunks_exact(8)
            .map(|c| u64::from_le_bytes(c.try_into().expect("chunks of 8")));
        let mut next = || words.next().expect("13 words");
        let mut real = || f64::from_bits(next());
        let origin = real();
        let count = real().to_bits();
        let step = real();
        let mut triple = || [real(), real(), real()];
        let position = triple();
        let velocity = triple();
        let external_force = triple();
        let wind_input = real();
        let snapshot = Snapshot {
            origin,
            count,
            step,
            position,
            velocity,
            external_force,
            wind_input,
        };
        snapshot.check()?;
        Ok(snapshot)
    }
}

/// Everything a user reads at an instant. Forces act on the body, inertial frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outputs {
    pub time: f64,
    /// (X, Y, theta), m, m, rad.
    pub position: [f64; 3],
    /// (X', Y', theta'), m/s, m/s, rad/s.
    pub velocity: [f64; 3],
    /// Wave elevation at the origin of the mean position, m.
    pub wave_elevation: f64,
    /// Forces at this instant for the current state (see [`ForceBreakdown`]).
    pub forces: ForceBreakdown,
    /// The external force last applied.
    pub external_force: [f64; 3],
    /// The slow drift with the wave-frequency motion on it (`forces::motion`; the slow
    /// drift alone where there is none).
    pub motion: WholeMotion,
    /// The wind speed at the height of the wind force (mean + gust, or the input held), m/s;
    /// 0 when calm.
    pub wind_speed: f64,
}

impl Outputs {
    /// The first force or elevation output that is not finite, by its FMU name (the state
    /// is bounded by the steps).
    fn first_non_finite(&self) -> Option<&'static str> {
        let f = &self.forces;
        let named: [(&'static str, &[f64]); 9] = [
            ("eta", std::slice::from_ref(&self.wave_elevation)),
            ("windVelocity", std::slice::from_ref(&self.wind_speed)),
            ("Fx_wind", &f.wind),
            ("X_wf", &self.motion.wave_frequency),
            ("Xdot_total", &self.motion.total_rate),
            ("F_wave", &f.wave),
            ("F_damping", &f.damping),
            ("F_drag", &f.drag),
            ("F_extra_damping", &f.extra_damping),
        ];
        named
            .into_iter()
            .find(|(_, values)| values.iter().any(|v| !v.is_finite()))
            .map(|(name, _)| name)
    }
}

/// One slow-drift simulation.
///
/// The records stream in segments of one block each (`forces::stream`): the simulation
/// holds the segment its time is in, and makes the next one when a step starts in it (or
/// any one, when a snapshot is restored there). A segment depends only on the seed and its
/// index, so the trajectory does not depend on the run's duration.
///
/// An external force closes the loop with a mooring model: here a linear spring on X of
/// 1e5 N/m applied from outside (`advance` holds the force over its interval, as a
/// co-simulation master holds an input over a communication step):
///
/// ```
/// use slowdrift::{problem, Simulation};
///
/// let mut problem = problem::default_problem()?; // the embedded default platform
/// problem.platform.stiffness = [[0.0; 3]; 3]; // no internal mooring
/// problem.run.duration = 600.0; // s
/// let mut simulation = Simulation::new(problem)?;
/// for _ in 0..600 {
///     let x = simulation.outputs()?.position[0]; // m
///     simulation.advance(1.0, [-1.0e5 * x, 0.0, 0.0])?; // Fx_ext, Fy_ext (N), Mz_ext (N m)
/// }
/// assert_eq!(simulation.time(), 600.0);
/// # Ok::<(), slowdrift::Error>(())
/// ```
#[derive(Clone)]
pub struct Simulation {
    problem: Problem,
    model: SlowDriftModel,
    plan: Arc<RecordPlan>,
    /// The current segment of the records, and the buffers the next one is made in.
    segment: Segment,
    state: Snapshot,
}

impl std::fmt::Debug for Simulation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Simulation")
            .field("segment", &self.segment.index)
            .field("state", &self.state)
            .finish_non_exhaustive()
    }
}

impl Simulation {
    /// Checks the problem ([`Problem::check`]) and makes the records of its first segment.
    pub fn new(problem: Problem) -> Result<Self> {
        problem.check()?;
        let plan = Arc::new(RecordPlan::of_checked(&problem)?);
        Self::built(problem, &plan)
    }

    /// A simulation of `problem` whose seed-independent record work comes from `plan`, made
    /// from a problem with the same [`crate::record_plan::PlanKey`] (else an error naming the
    /// plan). The problem is checked here. The same records, bit for bit, as
    /// [`Simulation::new`].
    pub fn with_plan(problem: Problem, plan: &Arc<RecordPlan>) -> Result<Self> {
        problem.check()?;
        if !plan.serves(&problem) {
            return Err(Error::invalid(
                "plan",
                "RecordPlan",
                "was made for a problem whose records differ from this one's (another run, \
                 sea band or directions, hydrodynamic data or record model)",
            ));
        }
        Self::built(problem, plan)
    }

    /// The simulation of a checked problem from a plan that serves it.
    fn built(problem: Problem, plan: &Arc<RecordPlan>) -> Result<Self> {
        let model = SlowDriftModel::new(&problem)?;
        let segment = plan.first_segment(&problem);
        let state = initial_state(&problem);
        Ok(Simulation {
            problem,
            model,
            plan: Arc::clone(plan),
            segment,
            state,
        })
    }

    /// The segment of the records that time `t` is in: the one of the sample at or below t.
    fn segment_of(&self, t: f64) -> Result<u64> {
        let grid = self.plan.grid();
        let position = (t - grid.start_time) / grid.dt;
        if !(position >= -1e-9 && position.is_finite()) {
            return Err(Error::BeforeStart {
                time: t,
                start: grid.start_time,
            });
        }
        Ok(self
            .plan
            .segments()
            .of_sample((position + 1e-9).floor() as u64))
    }

    /// Makes the records of the segment that time `t` is in, if they are not the current
    /// ones ([`RecordPlan::move_segment`]: no allocation).
    /// An open-ended run stops where a double no longer resolves its time
    /// ([`crate::problem::time_resolved`]), checked when a segment is entered.
    fn ensure_segment(&mut self, t: f64) -> Result<()> {
        let k = self.segment_of(t)?;
        if k != self.segment.index {
            let step = self.problem.run.time_step;
            if !crate::problem::time_resolved(t, step) {
                return Err(Error::TimeUnresolved { time: t, step });
            }
            self.plan.move_segment(&self.problem, &mut self.segment, k);
        }
        Ok(())
    }

    /// Makes the records of the segment that time `t` is in ([`Simulation::ensure_segment`])
    /// and the drag kinematics' rows that a step from t over `ahead` seconds reads (its
    /// samples from the one before t to t + ahead and the interpolation's stencil after
    /// them): rows not made are read all the same, only slower
    /// (`forces::Kinematics::make_rows`).
    fn ensure_records(&mut self, t: f64, ahead: f64) -> Result<()> {
        self.ensure_segment(t)?;
        let records = &mut self.segment.records;
        records.prefetch(records.clock.sample_at_or_below(t) + PREFETCH_AHEAD);
        if !records.kinematics.is_empty() {
            let clock = records.clock;
            // The stencil reads from one sample before the one at or below a time to two
            // after it.
            let start = clock.sample_at_or_below(t).saturating_sub(1);
            let end = clock.sample_at_or_below(t + ahead) + 3;
            records.kinematics.make_rows(start, end);
        }
        Ok(())
    }

    /// The problem this simulation was built from.
    pub fn problem(&self) -> &Problem {
        &self.problem
    }

    /// The records of the current segment.
    pub fn records(&self) -> &ForceRecords {
        &self.segment.records
    }

    /// The records of the segment that time `t` is in, made now if they are not the
    /// current ones (the state is kept: the next step or restore makes the state's segment
    /// again; until then [`Simulation::outputs`] refuses a state outside these records).
    pub fn records_at(&mut self, t: f64) -> Result<&ForceRecords> {
        self.ensure_segment(t)?;
        Ok(&self.segment.records)
    }

    /// The frequency grid of the records (one block's span long).
    pub fn grid(&self) -> &FrequencyGrid {
        self.plan.grid()
    }

    /// The segments of the record stream.
    pub fn segments(&self) -> Segments {
        self.plan.segments()
    }

    /// The index of the current segment of the records.
    pub fn segment(&self) -> u64 {
        self.segment.index
    }

    /// How the wave force and damping records are sampled (`forces::refine`): `Some(e)`
    /// when they are made at every second record sample (the step h) and refined, e the
    /// estimated rms error at the midpoints relative to their standard deviation for this
    /// sea; `None` when they are made at every record sample.
    pub fn refined_force_records(&self) -> Option<f64> {
        self.plan.refines().then(|| {
            let power = self.segment.expected_power();
            refine::midpoint_error(power, self.plan.grid().d_omega, self.problem.run.time_step)
        })
    }

    /// The summary line of [`Simulation::refined_force_records`] and of the records not
    /// made, their coefficients of round-off size ([`RecordPlan::negligible`])
    /// (`Problem::summary`'s companion: printed by `slowdrift simulate`, logged by the FMU).
    pub fn records_line(&self) -> String {
        let h = self.problem.run.time_step;
        let sampling = match self.refined_force_records() {
            Some(error) => format!(
                "slowly varying records (wave force, damping): made every {} s (the step) and \
                 refined to its midpoints by 8-point interpolation, their band allowing it \
                 (estimated error {error:.1e} of their standard deviation)",
                written(h)
            ),
            None => format!(
                "slowly varying records (wave force, damping): made every {} s (half the step \
                 {} s): their band is too wide to make them every step",
                written(0.5 * h),
                written(h)
            ),
        };
        match self.plan.negligible() {
            [] => sampling,
            names => format!(
                "{sampling}; not made, their coefficients of round-off size (each below {:.0e} \
                 of the largest of its kind, moments as forces at the radius of gyration): {}",
                crate::forces::NEGLIGIBLE_TRANSFER,
                names.join(", ")
            ),
        }
    }

    /// The rank kept for every full-QTF block (empty under Newman's approximation).
    pub fn qtf_ranks(&self) -> &[QtfRank] {
        self.plan.ranks()
    }

    /// Current time, s.
    pub fn time(&self) -> f64 {
        self.state.time()
    }

    /// Position (X, Y, theta).
    pub fn position(&self) -> [f64; 3] {
        self.state.position
    }

    /// Velocity (X', Y', theta').
    pub fn velocity(&self) -> [f64; 3] {
        self.state.velocity
    }

    /// One RK4 step of the configured h with the external force `external` (inertial frame,
    /// held constant over the step).
    pub fn step(&mut self, external: [f64; 3]) -> Result<()> {
        check_external(&external)?;
        self.whole_steps(1, external)
    }

    /// Holds the input wind speed `speed` (m/s, at the height of the wind force) from now
    /// on, for the steps and the outputs: the wind's speed when its source is the input
    /// (`[wind] source = "input"`), unused otherwise. Refused: a speed that is not finite or
    /// is negative (the state unchanged).
    pub fn hold_wind_input(&mut self, speed: f64) -> Result<()> {
        if !speed.is_finite() {
            return Err(Error::NonFiniteInput {
                field: "wind_input".into(),
                value: speed,
            });
        }
        if speed < 0.0 {
            return Err(Error::invalid(
                "wind_input",
                speed,
                "must be at least 0 m/s (the wind speed at the force's height)",
            ));
        }
        self.state.wind_input = speed;
        Ok(())
    }

    /// Advances by `interval` with the external force held constant: whole steps of h when
    /// the interval is a whole number of them, else ceil(interval/h) equal substeps that end
    /// exactly at the old time + interval.
    pub fn advance(&mut self, interval: f64, external: [f64; 3]) -> Result<()> {
        check_external(&external)?;
        if !(interval.is_finite() && interval > 0.0) {
            return Err(Error::invalid(
                "interval",
                interval,
                "must be a finite positive time",
            ));
        }
        let ratio = interval / self.problem.run.time_step;
        let whole = ratio.round();
        if whole >= 1.0 && (ratio - whole).abs() <= WHOLE_STEPS_TOLERANCE * whole {
            return self.whole_steps(whole as u64, external);
        }
        let saved = self.state.clone();
        let start = self.time();
        let substeps = ratio.ceil().max(1.0) as u64;
        let h = interval / substeps as f64;
        for i in 0..substeps {
            if let Err(e) = self.rk4(start + i as f64 * h, h, external) {
                self.state = saved;
                return Err(e);
            }
        }
        // Land exactly on the requested time; the regular steps count from there.
        self.state.origin = start + interval;
        self.state.count = 0;
        self.state.external_force = external;
        Ok(())
    }

    /// `count` steps of h at times origin + n h; all or nothing.
    fn whole_steps(&mut self, count: u64, external: [f64; 3]) -> Result<()> {
        let saved = self.state.clone();
        let h = self.problem.run.time_step;
        for _ in 0..count {
            if let Err(e) = self.rk4(self.time(), h, external) {
                self.state = saved;
                return Err(e);
            }
            self.state.count += 1;
        }
        self.state.external_force = external;
        Ok(())
    }

    /// One RK4 step of the position and velocity from time t over h.
    fn rk4(&mut self, t: f64, h: f64, external: [f64; 3]) -> Result<()> {
        self.ensure_records(t, h)?;
        let y = self.state_vector();
        let held = self.held(external);
        let next = rk4_step(t, &y, h, |time, y| self.derivative(time, y, &held))?;
        self.end_step(t, h, &external, &next)
    }

    /// The state (X, Y, theta, X', Y', theta') as RK4 takes it.
    fn state_vector(&self) -> [f64; 6] {
        let s = &self.state;
        [
            s.position[0],
            s.position[1],
            s.position[2],
            s.velocity[0],
            s.velocity[1],
            s.velocity[2],
        ]
    }

    /// What the outside holds over a step with the external force `external`.
    fn held(&self, external: [f64; 3]) -> Held {
        Held {
            force: external,
            wind_speed: self.state.wind_input,
        }
    }

    /// The state's derivative (q', q'') at `time` for the state `y` (RK4's right-hand side).
    fn derivative(&self, time: f64, y: &[f64; 6], held: &Held) -> Result<[f64; 6]> {
        let (at, yaw) = self.located(time, y[2])?;
        let (q, qd) = ([y[0], y[1], y[2]], [y[3], y[4], y[5]]);
        let qdd = self
            .model
            .acceleration(&self.segment.records, &at, &yaw, &q, &qd, held);
        Ok([qd[0], qd[1], qd[2], qdd[0], qdd[1], qdd[2]])
    }

    /// Where `time` falls in the records, and the yaw `theta` in the yaw-following ones.
    fn located(&self, time: f64, theta: f64) -> Result<(SamplePoint, YawPoint)> {
        self.located_as(time, theta, None)
    }

    /// [`Simulation::located`], taking `known` (`time` located on a clock) as it is when
    /// the records' clock is that clock.
    #[inline(always)]
    fn located_as(
        &self,
        time: f64,
        theta: f64,
        known: Option<(&RecordClock, SamplePoint)>,
    ) -> Result<(SamplePoint, YawPoint)> {
        let records = &self.segment.records;
        let at = match known {
            Some((clock, at)) if *clock == records.clock => at,
            _ => records.clock.locate(time)?,
        };
        Ok((at, records.locate_yaw(time, theta)?))
    }

    /// Ends a step from `t` over `h` on the state `next`: refused if it is unphysical or
    /// leaves the yaw-following records (the state unchanged), else taken.
    fn end_step(&mut self, t: f64, h: f64, external: &[f64; 3], next: &[f64; 6]) -> Result<()> {
        let (position, velocity) = ([next[0], next[1], next[2]], [next[3], next[4], next[5]]);
        if let Some(what) = bounds::violation(&position, &velocity) {
            return Err(self.unphysical(t, h, external, format!("the state became {what}")));
        }
        // The state a step ends on stays inside the yaw-following records, so `outputs`
        // can always read them.
        self.segment.records.locate_yaw(t + h, next[2])?;
        self.state.position = position;
        self.state.velocity = velocity;
        Ok(())
    }

    /// The error of a step from time `t` over `h` (or of the outputs at `t`, h the step)
    /// that made `what` unphysical, with its cause from the forces at `t`.
    fn unphysical(&self, t: f64, h: f64, external: &[f64; 3], what: String) -> Error {
        let s = &self.state;
        let records = &self.segment.records;
        let forces = records.clock.locate(t).and_then(|at| {
            let yaw = records.locate_yaw(t, s.position[2])?;
            Ok(self
                .model
                .forces(records, &at, &yaw, &s.position, &s.velocity, s.wind_input))
        });
        let cause = match forces {
            Ok(forces) => bounds::cause(&self.model, &forces, external, s.position[2], h),
            Err(_) => crate::error::Cause::Step,
        };
        Error::Unphysical {
            time: t,
            what,
            cause,
        }
    }

    /// Outputs at the current time.
    pub fn outputs(&self) -> Result<Outputs> {
        let t = self.time();
        let at = self.segment.records.clock.locate(t)?;
        let yaw = self.segment.records.locate_yaw(t, self.state.position[2])?;
        let forces = self.model.forces(
            &self.segment.records,
            &at,
            &yaw,
            &self.state.position,
            &self.state.velocity,
            self.state.wind_input,
        );
        let (position, velocity) = (self.state.position, self.state.velocity);
        let motion = match &self.segment.records.motion {
            Some(records) => {
                let (x, v) = records.at(&at, &yaw);
                WholeMotion::of(position, velocity, x, v)
            }
            None => WholeMotion::slow_drift(position, velocity),
        };
        let outputs = Outputs {
            time: t,
            position,
            velocity,
            wave_elevation: self.segment.records.elevation.at(&at),
            forces,
            external_force: self.state.external_force,
            motion,
            wind_speed: self
                .model
                .wind_speed(&self.segment.records, &at, self.state.wind_input),
        };
        match outputs.first_non_finite() {
            None => Ok(outputs),
            Some(what) => Err(self.unphysical(
                t,
                self.problem.run.time_step,
                &self.state.external_force,
                format!("the output {what} is not finite"),
            )),
        }
    }

    /// The complete dynamic state.
    pub fn snapshot(&self) -> Snapshot {
        self.state.clone()
    }

    /// Restores a state taken from a simulation of the same configuration.
    pub fn restore(&mut self, snapshot: &Snapshot) -> Result<()> {
        snapshot.check()?;
        bounds::check_restored(&snapshot.position, &snapshot.velocity)?;
        if snapshot.step != self.problem.run.time_step {
            return Err(Error::invalid(
                "snapshot.step",
                snapshot.step,
                format!(
                    "differs from this simulation's run.time_step = {}",
                    written(self.problem.run.time_step)
                ),
            ));
        }
        self.ensure_records(snapshot.time(), 0.0)?;
        self.segment.records.clock.locate(snapshot.time())?;
        self.segment
            .records
            .locate_yaw(snapshot.time(), snapshot.position[2])?;
        self.state = snapshot.clone();
        Ok(())
    }

    /// Back to the initial condition at the start time (and to the first segment of the
    /// records).
    pub fn reset(&mut self) -> Result<()> {
        let initial = initial_state(&self.problem);
        self.ensure_records(initial.time(), 0.0)?;
        self.state = initial;
        Ok(())
    }
}

fn check_external(external: &[f64; 3]) -> Result<()> {
    for (i, &v) in external.iter().enumerate() {
        if !v.is_finite() {
            return Err(Error::NonFiniteInput {
                field: format!("external_force[{i}]"),
                value: v,
            });
        }
    }
    Ok(())
}

fn initial_state(problem: &Problem) -> Snapshot {
    Snapshot {
        origin: problem.run.start_time,
        count: 0,
        step: problem.run.time_step,
        position: problem.initial.position,
        velocity: problem.initial.velocity,
        external_force: [0.0; 3],
        wind_input: 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn snapshot_bytes_round_trip_bit_for_bit() {
        let snapshot = Snapshot {
            origin: -12.5,
            count: 0x0123_4567_89ab_cdef,
            step: 0.1,
            position: [1.0 / 3.0, -0.0, f64::MIN_POSITIVE],
            velocity: [999.5, -2.5e-7, 7.0],
            external_force: [3e6, -4e6, 5e9],
            wind_input: 17.25,
        };
        let bytes = snapshot.to_bytes();
        assert_eq!(&bytes[96..], &17.25f64.to_le_bytes());
        assert_eq!(&bytes[..8], &(-12.5f64).to_le_bytes());
        assert_eq!(&bytes[8..16], &0x0123_4567_89ab_cdefu64.to_le_bytes());
        let back = Snapshot::from_bytes(&bytes).unwrap();
        assert_eq!(back.to_bytes(), bytes);
        assert_eq!(back.position[1].to_bits(), (-0.0f64).to_bits());
        assert_eq!(back, snapshot);
    }

    #[test]
    fn snapshot_bytes_of_the_wrong_length_are_refused() {
        let bytes = Snapshot {
            origin: 0.0,
            count: 0,
            step: 1.0,
            position: [0.0; 3],
            velocity: [0.0; 3],
            external_force: [0.0; 3],
            wind_input: 0.0,
        }
        .to_bytes();
        assert!(Snapshot::from_bytes(&bytes).is_ok());
        let mut negative = bytes;
        negative[96..].copy_from_slice(&(-1.0f64).to_le_bytes());
        let err = Snapshot::from_bytes(&negative).unwrap_err().to_string();
        assert!(err.contains("wind_input"), "{err}");
        for len in [0, Snapshot::BYTES - 1, Snapshot::BYTES + 1] {
            let mut v = bytes.to_vec();
            v.resize(len, 0);
            assert!(Snapshot::from_bytes(&v).is_err(), "length {len}");
        }
    }
}
