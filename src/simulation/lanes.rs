//! Seeds in lanes: up to [`LANES`] simulations of one case (seeds of one sea) stepped in
//! lockstep, their drag taken together (`forces::drag_forces`;
//! docs/architecture.md#seeds-in-lanes). Each lane's step is the one-seed
//! [`Simulation::step`] bit for bit: the same RK4 (E&S 1; `dynamics::rk4_step` on the
//! lanes' states side by side), the same forces, the same refusals; a lane whose step fails
//! gets the one-seed path's error and its state back, and the others go on.

use super::Simulation;
use crate::dynamics::{rk4_step, Held};
use crate::error::{Error, Result};
use crate::forces::{Isa, LaneDrag, Value, Wide, LANES};

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
/// located one by one, their equations of motion taken side by side ([`Wide`], the
/// one-seed code on the lanes' numbers) with their drag taken together. A lane that fails
/// here gets its error in `outcome` and zero derivatives from then on.
fn derivatives(
    lanes: &[Simulation],
    isa: Isa,
    time: f64,
    y: &[f64; WIDTH],
    held: &[Held; LANES],
    outcome: &mut [Result<()>],
) -> [f64; WIDTH] {
    // Each lane's records' point and yaw at `time`; the lanes located, in lane order, in
    // `live[..count]`.
    let mut located = [None; LANES];
    let (mut live, mut count) = ([0; LANES], 0);
    // `time` as the lane before located it, on its records' clock: the lanes' clocks are
    // alike (their segments' starts and lengths), and a lane whose clock is not locates anew.
    let mut known = None;
    for (l, sim) in lanes.iter().enumerate() {
        if outcome[l].is_err() {
            continue;
        }
        match sim.located_as(time, y[6 * l + 2], known) {
            Ok(point) => {
                known = Some((&sim.segment.records.clock, point.0));
                located[l] = Some(point);
                live[count] = l;
                count += 1;
            }
            Err(e) => outcome[l] = Err(e),
        }
    }
    let mut out = [0.0; WIDTH];
    let Some(first) = located[live[0]] else {
        return out;
    };
    // Vector lane i holds lanes[live[i]]; past `count`, the first again (not kept).
    let lane = |i: usize| live[if i < count { i } else { 0 }];
    let point = |l: usize| located[l].unwrap_or(first);
    let model = &lanes[live[0]].model;
    let [x, yy, theta, xd, yd, thetad] = Wide::gather(|i| {
        let l = lane(i);
        std::array::from_fn(|k| y[6 * l + k])
    });
    let body = model.body_frame(theta, &[xd, yd, thetad]);
    let drag_lanes: [LaneDrag; LANES] = std::array::from_fn(|i| {
        let l = lane(i);
        model.lane_drag(&lanes[l].segment.records, &point(l).0, &body, i)
    });
    let drags = model.lane_drags(&drag_lanes[..count], isa);
    let read = model.lanes_read(
        |i| {
            let l = lane(i);
            let (at, yaw) = point(l);
            (&lanes[l].segment.records, at, yaw, held[l].wind_speed)
        },
        &drags,
    );
    let external = Wide::gather(|i| held[lane(i)].force);
    let qdd = model.acceleration_of(&body, &read, &[x, yy, theta], &external);
    for (i, &l) in live[..count].iter().enumerate() {
        let derivative = [xd, yd, thetad, qdd[0], qdd[1], qdd[2]].map(|v| v.lane(i));
        out[6 * l..6 * l + 6].copy_from_slice(&derivative);
    }
    out
}
