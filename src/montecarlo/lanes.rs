//! A campaign's runs of one case in lanes: up to [`LANES`] seeds stepped in lockstep
//! ([`Lockstep`], docs/architecture.md#seeds-in-lanes), each run's result that of
//! [`super::run_seed`] for its seed, bit for bit.

use super::{positions_reserved, seed_simulation, summarize_positions, Case, DofStats};
use crate::error::Result;
use crate::forces::LANES;
use crate::{Lockstep, RecordPlan, Simulation};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// Runs `case` for each of `seeds` (at most [`LANES`]) in lanes and summarises each run as
/// [`super::run_seed`] does; `None` when a step finds `stop` set (checked before every
/// step). A run that fails (its records, its memory, a step) ends with its error; the
/// others go on.
pub(super) fn run_lanes(
    case: &Case,
    plan: &Arc<RecordPlan>,
    seeds: &[u64],
    stop: &AtomicBool,
) -> Option<Vec<Result<[DofStats; 3]>>> {
    assert!(seeds.len() <= LANES, "at most {LANES} seeds in lanes");
    let mut results: Vec<Option<Result<[DofStats; 3]>>> = seeds.iter().map(|_| None).collect();
    // The lanes' simulations with their records of (X, Y, theta), and which run each is.
    let mut sims: Vec<Simulation> = Vec::with_capacity(LANES);
    let mut records: Vec<([Vec<f64>; 3], usize)> = Vec::with_capacity(LANES);
    let mut steps = 0;
    for (run, &seed) in seeds.iter().enumerate() {
        let started = seed_simulation(case, plan, seed).and_then(|sim| {
            let (recorded, count) = positions_reserved(&sim)?;
            Ok((sim, recorded, count))
        });
        match started {
            Ok((sim, recorded, count)) => {
                steps = count;
                sims.push(sim);
                records.push((recorded, run));
            }
            Err(e) => results[run] = Some(Err(e)),
        }
    }
    if !sims.is_empty() {
        let mut lockstep = Lockstep::new(sims).expect("seeds of one case at their start");
        let mut outcome = Vec::with_capacity(LANES);
        for _ in 0..steps {
            if stop.load(Ordering::Relaxed) {
                return None;
            }
            lockstep.step_into(&mut outcome);
            for (l, step) in outcome.drain(..).enumerate().rev() {
                match step {
                    Ok(()) => {
                        let q = lockstep.lanes()[l].position();
                        records[l].0.iter_mut().zip(q).for_each(|(r, v)| r.push(v));
                    }
                    Err(e) => {
                        lockstep.remove(l);
                        let (_, run) = records.remove(l);
                        results[run] = Some(Err(e));
                    }
                }
            }
            if lockstep.lanes().is_empty() {
                break;
            }
        }
    }
    for (recorded, run) in &records {
        results[*run] = Some(summarize_positions(case, recorded));
    }
    Some(
        results
            .into_iter()
            .map(|r| r.expect("every run ends with its result or its error"))
            .collect(),
    )
}
