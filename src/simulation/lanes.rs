//! Seeds in lanes: up to [`LANES`] simulations of one case (seeds of one sea) stepped in
//! lockstep, their drag taken together (`forces::drag_forces`;
//! docs/architecture.md#seeds-in-lanes). Each lane's step is the one-seed
//! [`Simulation::step`] bit for bit: the same RK4 (E&S 1; `dynamics::rk4_step` on the
//! lanes' states side by side), the same forces, the same refusals; a lane whose step fails
//! gets the one-seed path's error and its state back, and the others go on. What the lanes
//! read at a time that their states do not change is read once for the two RK4 stages at
//! that time ([`Instant`]).

use super::Simulation;
use crate::dynamics::{rk4_step, Held, Read};
use crate::error::{Error, Result};
use crate::forces::{Isa, LaneDrag, RecordClock, SamplePoint, Value, Wide, YawPoint, LANES};

/// The state of [`LANES`] lanes as one RK4 vector: lane l's (X, Y, theta, X', Y', theta')
/// at 6 l.
const WIDTH: usize = 6 * LANES;

/// Simulations of one case's seeds, stepped together.
#[derive(Debug)]
pub struct Lockstep {
    lanes: Vec<Simulation>,
    isa: Isa,
    /// The last stage's reads, for the next stage at the same time.
    instant: Option<Instant>,
}

/// What the lanes read at one time that their states do not change: the instant located
/// on each lane's records, and the wave force, damping and wind speed read there. The RK4
/// stages come at the same time in pairs (stages 2 and 3 of a step at t + h/2, a step's
/// last stage and the next step's first at t + h), and the second of a pair takes the
/// first's reads: the same numbers, read once. Kept only without yaw following, whose
/// reads depend on each stage's yaw.
#[derive(Debug, Clone, Copy)]
struct Instant {
    key: InstantKey,
    /// The lanes located, in lane order, in `live[..count]`.
    live: [usize; LANES],
    count: usize,
    /// Vector lane i's instant and yaw on its records: lane `live[i]`'s (past `count`, the
    /// first lane's again, not kept).
    located: [(SamplePoint, YawPoint); LANES],
    /// What the vector lanes read there (no drag).
    read: Read<Wide>,
}

/// What an [`Instant`]'s reads depend on: the time (its bits), the lanes not failed before
/// they were located, each lane's records (its segment's clock) and the wind input it
/// holds (its bits).
#[derive(Debug, Clone, Copy)]
struct InstantKey {
    time: u64,
    ok: [bool; LANES],
    clocks: [Option<RecordClock>; LANES],
    wind: [u64; LANES],
}

/// An instant's key is compared and written field by field, in place: it is large enough
/// that building one and moving it cost a copy.
impl InstantKey {
    /// Whether this is the key of `time` for `lanes`, their held inputs and outcomes.
    fn is(
        &self,
        lanes: &[Simulation],
        time: f64,
        held: &[Held; LANES],
        outcome: &[Result<()>],
    ) -> bool {
        self.time == time.to_bits()
            && (0..LANES).all(|l| {
                self.ok[l] == Self::ok_of(outcome, l)
                    && self.clocks[l] == Self::clock_of(lanes, l)
                    && self.wind[l] == held[l].wind_speed.to_bits()
            })
    }

    /// Makes this the key of `time` for `lanes`, their held inputs, and `ok`, whether each
    /// lane had not failed before it was located.
    fn set(&mut self, lanes: &[Simulation], time: f64, held: &[Held; LANES], ok: [bool; LANES]) {
        self.time = time.to_bits();
        self.ok = ok;
        for (l, clock) in self.clocks.iter_mut().enumerate() {
            *clock = Self::clock_of(lanes, l);
        }
        for (wind, held) in self.wind.iter_mut().zip(held) {
            *wind = held.wind_speed.to_bits();
        }
    }

    fn ok_of(outcome: &[Result<()>], l: usize) -> bool {
        outcome.get(l).is_some_and(|o| o.is_ok())
    }

    fn clock_of(lanes: &[Simulation], l: usize) -> Option<RecordClock> {
        lanes.get(l).map(|s| s.segment.records.clock)
    }
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
        Ok(Lockstep {
            lanes,
            isa,
            instant: None,
        })
    }

    /// The lanes' simulations, in the order given.
    pub fn lanes(&self) -> &[Simulation] {
        &self.lanes
    }

    /// Takes lane `l`'s simulation out (the lanes after it move down one).
    pub fn remove(&mut self, l: usize) -> Simulation {
        // The lanes after it move: the reads kept are no longer theirs.
        self.instant = None;
        self.lanes.remove(l)
    }

    /// One RK4 step of the configured h for every lane, with no external force: each
    /// lane's outcome as [`Simulation::step`] gives it alone (a failed lane keeps its
    /// state before the step).
    pub fn step(&mut self) -> Vec<Result<()>> {
        let mut outcome = Vec::with_capacity(LANES);
        self.step_into(&mut outcome);
        outcome
    }

    /// [`Lockstep::step`], its outcomes written into `outcome` (cleared first: a campaign
    /// reuses one buffer, and its steps allocate nothing).
    pub fn step_into(&mut self, outcome: &mut Vec<Result<()>>) {
        outcome.clear();
        let Some(first) = self.lanes.first() else {
            return;
        };
        let (t, h) = (first.time(), first.problem.run.time_step);
        let external = [0.0; 3];
        outcome.extend(self.lanes.iter_mut().map(|s| s.ensure_records(t, h)));
        let mut y = [0.0; WIDTH];
        for (l, sim) in self.lanes.iter().enumerate() {
            y[6 * l..6 * l + 6].copy_from_slice(&sim.state_vector());
        }
        let mut held = [Held::default(); LANES];
        for (h, sim) in held.iter_mut().zip(&self.lanes) {
            *h = sim.held(external);
        }
        let (lanes, isa, instant) = (&self.lanes, self.isa, &mut self.instant);
        let next = rk4_step(t, &y, h, |time, y| {
            Ok::<_, std::convert::Infallible>(derivatives(
                lanes, isa, time, y, &held, outcome, instant,
            ))
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
    }
}

/// The lanes' derivatives (q', q'') at `time` for the states `y`, each lane's as
/// [`Simulation::derivative`] gives it: the lanes that have not failed (`outcome` Ok)
/// located one by one, their equations of motion taken side by side ([`Wide`], the
/// one-seed code on the lanes' numbers) with their drag taken together. A lane that fails
/// here gets its error in `outcome` and zero derivatives from then on. What the lanes read
/// at `time` is `instant`'s when it was read for the same (its key), else read here and
/// kept in `instant`.
fn derivatives(
    lanes: &[Simulation],
    isa: Isa,
    time: f64,
    y: &[f64; WIDTH],
    held: &[Held; LANES],
    outcome: &mut [Result<()>],
    instant: &mut Option<Instant>,
) -> [f64; WIDTH] {
    if !matches!(instant, Some(i) if i.key.is(lanes, time, held, outcome)) {
        read_at(lanes, time, y, held, outcome, instant);
    }
    let mut out = [0.0; WIDTH];
    let Some(Instant {
        live,
        count,
        located,
        read,
        ..
    }) = instant.as_mut()
    else {
        return out;
    };
    let (live, count) = (*live, *count);
    // Vector lane i holds lanes[live[i]]; past `count`, the first again (not kept).
    let lane = |i: usize| live[if i < count { i } else { 0 }];
    let model = &lanes[live[0]].model;
    let [x, yy, theta, xd, yd, thetad] = Wide::gather(|i| {
        let l = lane(i);
        std::array::from_fn(|k| y[6 * l + k])
    });
    let body = model.body_frame(theta, &[xd, yd, thetad]);
    let drag_lanes: [LaneDrag; LANES] = std::array::from_fn(|i| {
        let (l, (at, _)) = (lane(i), located[i]);
        model.lane_drag(&lanes[l].segment.records, &at, &body, i)
    });
    let drags = model.lane_drags(&drag_lanes[..count], isa);
    // This stage's drag, in place of the last stage's (the rest is this time's).
    read.drag = Wide::gather(|i| drags[i]);
    let external = Wide::gather(|i| held[lane(i)].force);
    let qdd = model.acceleration_of(&body, read, &[x, yy, theta], &external);
    for (i, &l) in live[..count].iter().enumerate() {
        let derivative = [xd, yd, thetad, qdd[0], qdd[1], qdd[2]].map(|v| v.lane(i));
        out[6 * l..6 * l + 6].copy_from_slice(&derivative);
    }
    if lanes[live[0]].segment.records.yaw_following.is_some() {
        // Read at this stage's yaw: not for another stage.
        *instant = None;
    }
    out
}

/// The lanes not failed (`outcome` Ok) located at `time`, each at its yaw in `y`, and
/// what they read there, written into `instant` in place with the key they depend on (an
/// instant is large: building a new one and moving it into place copied it); `None` when
/// no lane is located (a lane that cannot be gets its error in `outcome`).
fn read_at(
    lanes: &[Simulation],
    time: f64,
    y: &[f64; WIDTH],
    held: &[Held; LANES],
    outcome: &mut [Result<()>],
    instant: &mut Option<Instant>,
) {
    // The key of the lanes as they were before they were located.
    let ok_before: [bool; LANES] = std::array::from_fn(|l| InstantKey::ok_of(outcome, l));
    let mut count = 0;
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
                let slot = instant.get_or_insert_with(|| Instant::first(point));
                slot.located[count] = point;
                slot.live[count] = l;
                count += 1;
            }
            Err(e) => outcome[l] = Err(e),
        }
    }
    let Some(slot) = instant.as_mut().filter(|_| count > 0) else {
        *instant = None;
        return;
    };
    slot.key.set(lanes, time, held, ok_before);
    slot.count = count;
    // Vector lane i: lane live[i]; past `count`, the first again.
    for i in count..LANES {
        slot.located[i] = slot.located[0];
        slot.live[i] = 0;
    }
    let (read, live, located) = (&mut slot.read, &slot.live, &slot.located);
    lanes[live[0]].model.lanes_read_into(read, |i| {
        let (l, (at, yaw)) = (live[if i < count { i } else { 0 }], located[i]);
        (&lanes[l].segment.records, at, yaw, held[l].wind_speed)
    });
}

impl Instant {
    /// An instant whose every vector lane is at `point`, to be written by [`read_at`].
    fn first(point: (SamplePoint, YawPoint)) -> Self {
        Instant {
            key: InstantKey {
                time: 0,
                ok: [false; LANES],
                clocks: [None; LANES],
                wind: [0; LANES],
            },
            live: [0; LANES],
            count: 0,
            located: [point; LANES],
            read: Read {
                wave: [Wide::splat(0.0); 3],
                damping: None,
                drag: [Wide::splat(0.0); 3],
                wind_speed: Wide::splat(0.0),
            },
        }
    }
}
