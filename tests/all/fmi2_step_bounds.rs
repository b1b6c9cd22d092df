//! A communication step is bounded in time: without a stop time,
//! `fmi2DoStep(t, 1e308)` or a step of 5e9 s ran for hours; now a step longer than one block
//! of the records (the default platform's 16384 s, docs/fmu.md "Time") is discarded at once
//! with a logStatusDiscard line that names the bound, the state unchanged, and a step of
//! exactly one block is taken. A step too small to advance the time (1e-300 s at t = 100 s,
//! where t + h == t) is refused with fmi2Error instead of returning fmi2OK having done
//! nothing.

use crate::fmu::*;
use slowdrift::fmi2::exports::*;
use slowdrift::fmi2::machine::MachineState;
use slowdrift::fmi2::types::*;
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// The default platform's block of records, s (`run.block_duration` in
/// src/scenario/default.toml, docs/configuration.md: 2^14 s).
const BLOCK: f64 = 16384.0;

/// Longest time a refused or discarded step may take before it answers.
const PROMPT: Duration = Duration::from_secs(30);

fn state_of(fmu: &Fmu) -> Option<MachineState> {
    unsafe { instance_state(fmu.c) }
}

/// `fmi2DoStep(t, h)` on another thread, its status and how long it took; `None` when it
/// has not answered within [`PROMPT`] (the instance is then left to that thread, which the
/// test process ends with it).
fn step_promptly(fmu: Fmu, t: f64, h: f64) -> Option<(Fmu, fmi2Status, Duration)> {
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let start = Instant::now();
        let status = fmu.step(t, h);
        send.send((fmu, status, start.elapsed())).ok();
    });
    receive.recv_timeout(PROMPT).ok()
}

#[test]
fn a_step_longer_than_one_block_is_discarded_at_once() {
    assert_eq!(default_platform().run.block_duration, BLOCK);
    let mut fmu = Fmu::new("long steps");
    assert_eq!(fmu.setup(0.0, None), fmi2Status::fmi2OK);
    assert_eq!(fmu.init(), fmi2Status::fmi2OK, "{}", fmu.messages());
    let saved = get_state(&fmu);
    for (h, shown) in [(1e308, "1e308 s"), (5e9, "5e9 s"), (BLOCK + 1.0, "16385 s")] {
        let (back, status, took) = step_promptly(fmu, 0.0, h)
            .unwrap_or_else(|| panic!("fmi2DoStep(0, {h:e}) did not answer within {PROMPT:?}"));
        fmu = back;
        println!("fmi2DoStep(0, {h:e}): {status:?} in {took:.2?}");
        assert_eq!(status, fmi2Status::fmi2Discard, "{h:e}: {}", fmu.messages());
        let e = fmu.last_message();
        assert_eq!(
            (e.status, e.category.as_str()),
            (fmi2Status::fmi2Discard, "logStatusDiscard")
        );
        for needle in [
            "fmi2DoStep: step discarded",
            &format!("communicationStepSize = {shown}"),
            "longer than one block of the records, 16384 s",
            "16384 RK4 steps of stepSize = 1 s",
            "the state is unchanged",
        ] {
            assert!(e.message.contains(needle), "{needle:?} in {:?}", e.message);
        }
        assert_eq!(state_of(&fmu), Some(MachineState::StepFailed));
        assert_eq!(fmu.last_successful_time(), (fmi2Status::fmi2OK, 0.0));
        // The state saved before the step restores, and the run goes on.
        assert_eq!(
            unsafe { fmi2SetFMUstate(fmu.c, saved) },
            fmi2Status::fmi2OK,
            "{}",
            fmu.messages()
        );
    }
    // One block exactly is taken (from a time within the first block, so that it ends in
    // the next: a new segment of records), and ends where it should.
    fmu.step_with(0.0, 100.0, [0.0; 3]);
    let (fmu, status, took) =
        step_promptly(fmu, 100.0, BLOCK).expect("a step of one block answers");
    println!("fmi2DoStep(100, {BLOCK}): {status:?} in {took:.2?}");
    assert_eq!(status, fmi2Status::fmi2OK, "{}", fmu.messages());
    assert_eq!(
        fmu.last_successful_time(),
        (fmi2Status::fmi2OK, 100.0 + BLOCK)
    );
    free_state(&fmu, saved);
}

#[test]
fn a_step_that_does_not_advance_the_time_is_refused() {
    const START: f64 = 100.0;
    let fmu = Fmu::new("tiny steps");
    assert_eq!(fmu.setup(START, None), fmi2Status::fmi2OK);
    assert_eq!(fmu.init(), fmi2Status::fmi2OK, "{}", fmu.messages());
    // Doubles near 100 are 2^-46 = 1.42e-14 s apart: 100 + 1e-300 == 100.
    let spacing = 2f64.powi(-46);
    assert_eq!(START + 1e-300, START);
    assert_eq!(START + 0.4 * spacing, START);
    assert!(START + spacing > START);
    let status = fmu.step(START, 1e-300);
    assert_eq!(status, fmi2Status::fmi2Error, "{}", fmu.messages());
    let e = fmu.last_message();
    assert_eq!(
        (e.status, e.category.as_str()),
        (fmi2Status::fmi2Error, "logStatusError")
    );
    for needle in [
        "communicationStepSize = 1e-300 s does not advance the time",
        "at t = 100 s, t + h == t in double precision",
        "1.4210854715202004e-14 s apart",
    ] {
        assert!(e.message.contains(needle), "{needle:?} in {:?}", e.message);
    }
    assert_eq!(state_of(&fmu), Some(MachineState::Error));

    // A step of one spacing advances the time by it and is taken.
    let fmu = Fmu::new("the smallest step");
    assert_eq!(fmu.setup(START, None), fmi2Status::fmi2OK);
    assert_eq!(fmu.init(), fmi2Status::fmi2OK, "{}", fmu.messages());
    assert_eq!(fmu.step(START, spacing), fmi2Status::fmi2OK);
    assert_eq!(
        fmu.last_successful_time(),
        (fmi2Status::fmi2OK, START + spacing)
    );
}
