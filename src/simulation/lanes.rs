//! Seeds in lanes: up to [`LANES`] simulations of one case (seeds of one sea) stepped in
//! lockstep, their drag taken together (`forces::drag_forces`;
//! docs/architecture.md#seeds-in-lanes). Each lane's step is the one-seed
//! [`Simulation::step`] bit for bit: the same RK4 (E&S 1; `dynamics::rk4_step` on the
//! lanes' states side by side), the same forces, the same refusals; a lane whose step fails
//! gets the one-seed path's error and its state back, and the others go on.

use super::Simulation;
use crate::dynamics::{rk4_step, BodyFrame, Held};
use crate::error::{Error, Result};
use crate::forces::{Isa, LaneDrag, SamplePoint, YawPoint, LANES};

/// The state of [`LANES`] lanes as one RK4 vector: lane l's (X, Y, theta, X', Y', theta')
/// at 6 l.
const WIDTH: usize = 6 * LANES;

/// Simulations of one case's seeds, stepped together.
#[derive(Debug)]
pub struct Lockstep {
    lanes: Vec<Simulation>,
    isa: Isa,
}

impl Lockstep {
    /// The simulations `lanes` (1 to [`LANES`], of one model and time step, at one time),
    /// their drag summed with the widest instruction set the CPU runs.
    pub fn new(lanes: Vec<Simulation>) -> Result<Self> {
        Self::with_isa(lanes, Isa::detect())
    }

    /// [`Lockstep::new`] with the drag's lanes summed by `isa` (the tests run each).
    pub fn with_isa(lanes: Vec<Simulation>, isa: Isa) -> Result<Self> {
        let refuse = |reason: &str| Error::invalid("lanes", lanes.len(), reason.to_string());
        let Some(first) = lanes.first() else {
            return Err(refuse("must hold at least one simulation"));
        };
        if lanes.len() > LANES {
            return Err(refuse(&format!("must hold at most {LANES} simulations")));
        }
        let alike = lanes.iter().all(|s| {
            s.model == first.model
                && s.problem.run.time_step == first.problem.run.time_step
                && s.time() == first.time()
        });
        if !alike {
            return Err(refuse(
                "must hold simulations of one model and time step at one time",
            ));
        }
        Ok(Lockstep { lanes, isa })
    }

    /// The lanes' simulations, in the order given.
    pub fn lanes(&self) -> &[Simulation] {
        &self.lanes
    }

    /// Takes lane `l`'s simulation out (the lanes after it move down one).
    pub fn remove(&mut self, l: usize) -> Simulation {
        self.lanes.remove(l)
    }

    /// One RK4 step of the configured h for every lane, with no external force: each
    /// lane's outcome as [`Simulation::step`] gives it alone (a failed lane keeps its
    /// state before the step).
    pub fn step(&mut self) -> Vec<Result<()>> {
        let Some(first) = self.lanes.first() else {
            return Vec::new();
        };
        let (t, h) = (first.time(), first.problem.run.time_step);
        let external = [0.0; 3];
        let mut outcome: Vec<Result<()>> = self
            .lanes
            .iter_mut()
            .map(|s| s.ensure_records(t, h))
            .collect();
        let mut y = [0.0; WIDTH];
        for (l, sim) in self.lanes.iter().enumerate() {
            y[6 * l..6 * l + 6].copy_from_slice(&sim.state_vector());
        }
        let mut held = [Held::default(); LANES];
        for (h, sim) in held.iter_mut().zip(&self.lanes) {
            *h = sim.held(external);
        }
        let (lanes, isa) = (&self.lanes, self.isa);
        let next = rk4_step(t, &y, h, |time, y| {
            Ok::<_, std::convert::Infallible>(derivatives(lanes, isa, time, y, &held, &mut outcome))
        });
        let Ok(next) = next;
        for (l, sim) in self.lanes.iter_mut().enumerate() {
            if outcome[l].is_ok() {
                let end: [f64; 6] = std::array::from_fn(|i| next[6 * l + i]);
                outcome[l] = sim.end_step(t, h, &external, &end).map(|()| {
                    sim.state.count += 1;
                    sim.state.external_force = external;
                });
            }
        }
        outcome
    }
}

/// The lanes' derivatives (q', q'') at `time` for the states `y`, each lane's as
/// [`Simulation::derivative`] gives it: the lanes that have not failed (`outcome` Ok)
/// located and put in the body frame one by one, their drag taken together, the rest of
/// their forces one by one. A lane that fails here gets its error in `outcome` and zero
/// derivatives from then on.
fn derivatives(
    lanes: &[Simulation],
    isa: Isa,
    time: f64,
    y: &[f64; WIDTH],
    held: &[Held; LANES],
    outcome: &mut [Result<()>],
) -> [f64; WIDTH] {
    // The lanes located at `time` (their index, records' point, yaw, state, body frame),
    // in lane order, in the first `count` entries.
    let mut located: [Option<Located>; LANES] = [None; LANES];
    let mut count = 0;
    for (l, sim) in lanes.iter().enumerate() {
        if outcome[l].is_err() {
            continue;
        }
        let (q, qd) = (
            [y[6 * l], y[6 * l + 1], y[6 * l + 2]],
            [y[6 * l + 3], y[6 * l + 4], y[6 * l + 5]],
        );
        match sim.located(time, q[2]) {
            Ok((at, yaw)) => {
                let body = sim.model.body_frame(&q, &qd);
                located[count] = Some(Located {
                    lane: l,
                    at,
                    yaw,
                    q,
                    qd,
                    body,
                });
                count += 1;
            }
            Err(e) => outcome[l] = Err(e),
        }
    }
    let mut out = [0.0; WIDTH];
    let Some(first) = located[0] else {
        return out;
    };
    let drag_of = |found: &Option<Located>| {
        let it = found.as_ref().unwrap_or(&first);
        let records = &lanes[it.lane].segment.records;
        lanes[it.lane].model.lane_drag(records, &it.at, &it.body)
    };
    let drag_lanes: [LaneDrag; LANES] = std::array::from_fn(|i| drag_of(&located[i]));
    let drags = lanes[first.lane]
        .model
        .lane_drags(&drag_lanes[..count], isa);
    for (it, drag) in located.iter().flatten().zip(drags) {
        let (l, sim) = (it.lane, &lanes[it.lane]);
        let qdd = sim.model.acceleration_with_drag(
            &it.body,
            drag,
            &sim.segment.records,
            &it.at,
            &it.yaw,
            &it.q,
            &held[l],
        );
        let qd = it.qd;
        out[6 * l..6 * l + 6].copy_from_slice(&[qd[0], qd[1], qd[2], qdd[0], qdd[1], qdd[2]]);
    }
    out
}

/// A lane located at an instant of a stage: what its drag and forces read.
#[derive(Clone, Copy)]
struct Located {
    lane: usize,
    at: SamplePoint,
    yaw: YawPoint,
    q: [f64; 3],
    qd: [f64; 3],
    body: BodyFrame,
}
