//! The FMI 2.0 C ABI, called in-process as a master would: the lifecycle, outputs equal to a
//! native `Simulation` bit for bit, variable communication steps, reset, FMU states and
//! their bytes, the end of the records, and instances in parallel threads.

use crate::fmu::*;
use slowdrift::fmi2::exports::*;
use slowdrift::fmi2::machine::MachineState;
use slowdrift::fmi2::model_description::vr;
use slowdrift::fmi2::types::*;
use std::ptr;

const START: f64 = 100.0;
const STOP: f64 = 1300.0;

#[test]
fn types_platform_and_version() {
    let text =
        |p: *const std::ffi::c_char| unsafe { std::ffi::CStr::from_ptr(p) }.to_str().unwrap();
    assert_eq!(text(fmi2GetTypesPlatform()), "default");
    assert_eq!(text(fmi2GetVersion()), "2.0");
}

/// 1000 steps with time-varying external forces: every output equals the native
/// simulation's bit for bit, at the initial point and after every step.
#[test]
fn outputs_equal_the_native_simulation_bit_for_bit() {
    let fmu = Fmu::running("a", 7, 0.4, START, Some(STOP));
    let mut sim = native(7, 0.4, START, STOP);
    assert_eq!(
        bits(&fmu.outputs()),
        bits(&native_outputs(&sim.outputs().unwrap()))
    );
    let mut t = START;
    for n in 0..1000 {
        fmu.step_with(t, 1.0, external(n));
        sim.advance(1.0, external(n)).unwrap();
        t += 1.0;
        assert_eq!(
            bits(&fmu.outputs()),
            bits(&native_outputs(&sim.outputs().unwrap())),
            "step {n}"
        );
    }
    // Sway and yaw move (waves at 0.4 rad and a yaw moment): all outputs were exercised.
    let last = fmu.outputs();
    assert!(last.iter().all(|v| v.is_finite()));
    assert!(last[1] != 0.0 && last[2] != 0.0, "{last:?}");
    assert_eq!(fmu.last_successful_time(), (fmi2Status::fmi2OK, sim.time()));
    assert_eq!(unsafe { fmi2Terminate(fmu.c) }, fmi2Status::fmi2OK);
    assert_eq!(fmu.terminated(), (fmi2Status::fmi2OK, false));
}

/// Communication steps of 0.3, 1.0 and 2.5 s with h = 1 s land exactly where the native
/// `advance` lands, with the same outputs.
#[test]
fn variable_communication_steps_land_exactly() {
    let fmu = Fmu::running("v", 3, 0.0, START, Some(STOP));
    let mut sim = native(3, 0.0, START, STOP);
    let mut t = START;
    for n in 0..120 {
        let h = [0.3, 1.0, 2.5][n % 3];
        fmu.step_with(t, h, external(n));
        sim.advance(h, external(n)).unwrap();
        t += h;
        let (_, last) = fmu.last_successful_time();
        assert_eq!(last.to_bits(), sim.time().to_bits(), "step {n}");
        assert!((last - t).abs() < 1e-9 * t, "{last} vs the master's {t}");
        assert_eq!(
            bits(&fmu.outputs()),
            bits(&native_outputs(&sim.outputs().unwrap())),
            "step {n}"
        );
    }
}

/// Parameters and inputs read back; outputs readable in initialisation mode.
#[test]
fn variables_read_back() {
    let fmu = Fmu::new("r");
    assert_eq!(fmu.setup(0.0, Some(600.0)), fmi2Status::fmi2OK);
    assert_eq!(fmu.set_real(vr::HS, 5.5), fmi2Status::fmi2OK);
    assert_eq!(fmu.set_int(vr::N_DIRECTIONS, 9), fmi2Status::fmi2OK);
    assert_eq!(fmu.set_string(vr::HYDRO_DATABASE, ""), fmi2Status::fmi2OK);
    assert_eq!(
        unsafe { fmi2EnterInitializationMode(fmu.c) },
        fmi2Status::fmi2OK
    );
    assert_eq!(fmu.set_reals(&INPUTS, &[1.0, 2.0, 3.0]), fmi2Status::fmi2OK);
    let (s, v) = fmu.get_reals(&[vr::HS, vr::TP, vr::FX_EXT, vr::MZ_EXT]);
    assert_eq!((s, v), (fmi2Status::fmi2OK, vec![5.5, 12.0, 1.0, 3.0]));
    let mut n = [0; 2];
    let vrs = [vr::N_DIRECTIONS, vr::SEED];
    assert_eq!(
        unsafe { fmi2GetInteger(fmu.c, vrs.as_ptr(), 2, n.as_mut_ptr()) },
        fmi2Status::fmi2OK
    );
    assert_eq!(n, [9, 1]);
    let mut p: fmi2String = ptr::null();
    assert_eq!(
        unsafe { fmi2GetString(fmu.c, &vr::HYDRO_DATABASE, 1, &mut p) },
        fmi2Status::fmi2OK
    );
    assert_eq!(unsafe { std::ffi::CStr::from_ptr(p) }.to_str(), Ok(""));
    // Initial outputs before ExitInitializationMode: the native simulation's at t = 0.
    let mut config = native_problem(1, 0.0, 0.0, 600.0);
    config.sea.spectrum = slowdrift::sea_state::Spectrum::Jonswap {
        hs: 5.5,
        tp: 12.0,
        gamma: None,
    };
    let sim = slowdrift::Simulation::new(config).unwrap();
    assert_eq!(
        bits(&fmu.outputs()),
        bits(&native_outputs(&sim.outputs().unwrap()))
    );
    // A parameter set after that read is not lost: the records are rebuilt.
    let eta = |f: &Fmu| f.get_reals(&[vr::ETA]).1[0];
    let eta_before = eta(&fmu);
    assert_eq!(fmu.set_real(vr::HS, 11.0), fmi2Status::fmi2OK);
    assert_ne!(eta(&fmu), eta_before);
    assert_eq!(fmu.set_real(vr::HS, 5.5), fmi2Status::fmi2OK);
    assert_eq!(eta(&fmu).to_bits(), eta_before.to_bits());
    assert_eq!(
        unsafe { fmi2ExitInitializationMode(fmu.c) },
        fmi2Status::fmi2OK
    );
    assert_eq!(
        bits(&fmu.outputs()),
        bits(&native_outputs(&sim.outputs().unwrap()))
    );
    // nvr = 0 with NULL arrays is a no-op.
    assert_eq!(
        unsafe { fmi2GetReal(fmu.c, ptr::null(), 0, ptr::null_mut()) },
        fmi2Status::fmi2OK
    );
    assert_eq!(
        unsafe { fmi2SetReal(fmu.c, ptr::null(), 0, ptr::null()) },
        fmi2Status::fmi2OK
    );
    assert_eq!(
        unsafe { fmi2GetBoolean(fmu.c, ptr::null(), 0, ptr::null_mut()) },
        fmi2Status::fmi2OK
    );
}

fn run(fmu: &Fmu, from_step: usize, steps: usize) -> Vec<Vec<f64>> {
    (from_step..from_step + steps)
        .map(|n| {
            fmu.step_with(START + n as f64, 1.0, external(n));
            fmu.outputs()
        })
        .collect()
}

/// Reset returns to a fresh instance: start values, time and inputs; the same run again
/// gives the same outputs bit for bit.
#[test]
fn reset_replays_bit_for_bit() {
    let fmu = Fmu::running("reset", 5, 0.2, START, Some(STOP));
    let first = run(&fmu, 0, 200);
    assert_eq!(unsafe { fmi2Reset(fmu.c) }, fmi2Status::fmi2OK);
    assert_eq!(
        unsafe { instance_state(fmu.c) },
        Some(MachineState::Instantiated)
    );
    // Start values are back (seed and direction were changed before).
    let mut seed = 0;
    // Get is not allowed in Instantiated: check after entering initialisation mode.
    assert_eq!(fmu.setup(START, Some(STOP)), fmi2Status::fmi2OK);
    assert_eq!(
        unsafe { fmi2EnterInitializationMode(fmu.c) },
        fmi2Status::fmi2OK
    );
    assert_eq!(
        unsafe { fmi2GetInteger(fmu.c, &vr::SEED, 1, &mut seed) },
        fmi2Status::fmi2OK
    );
    let (_, v) = fmu.get_reals(&[vr::WAVE_DIRECTION, vr::FX_EXT, vr::FY_EXT, vr::MZ_EXT]);
    assert_eq!((seed, v), (1, vec![0.0; 4]));
    assert_eq!(fmu.set_int(vr::SEED, 5), fmi2Status::fmi2OK);
    assert_eq!(fmu.set_real(vr::WAVE_DIRECTION, 0.2), fmi2Status::fmi2OK);
    assert_eq!(
        unsafe { fmi2ExitInitializationMode(fmu.c) },
        fmi2Status::fmi2OK
    );
    let second = run(&fmu, 0, 200);
    assert_eq!(
        first.iter().map(|v| bits(v)).collect::<Vec<_>>(),
        second.iter().map(|v| bits(v)).collect::<Vec<_>>()
    );
}

/// Get the state, run on, set it back, run again: the same trajectory bit for bit; the
/// restored inputs are those at the save.
#[test]
fn rollback_replays_bit_for_bit() {
    let fmu = Fmu::running("rollback", 11, 0.3, START, Some(STOP));
    run(&fmu, 0, 300);
    let state = get_state(&fmu);
    let ahead = run(&fmu, 300, 300);
    assert_eq!(unsafe { fmi2SetFMUstate(fmu.c, state) }, fmi2Status::fmi2OK);
    let (_, inputs) = fmu.get_reals(&INPUTS);
    assert_eq!(bits(&inputs), bits(&external(299)));
    let again = run(&fmu, 300, 300);
    assert_eq!(
        ahead.iter().map(|v| bits(v)).collect::<Vec<_>>(),
        again.iter().map(|v| bits(v)).collect::<Vec<_>>()
    );
    free_state(&fmu, state);
    // Freeing a NULL state is a no-op.
    let mut null: fmi2FMUstate = ptr::null_mut();
    assert_eq!(
        unsafe { fmi2FreeFMUstate(fmu.c, &mut null) },
        fmi2Status::fmi2OK
    );
}

/// A state serialized in one instance, deserialized and set in a fresh instance with the
/// same parameters, continues bit for bit.
#[test]
fn serialized_state_continues_in_a_fresh_instance() {
    let a = Fmu::running("a", 13, 0.5, START, Some(STOP));
    run(&a, 0, 400);
    let state = get_state(&a);
    let bytes = serialize(&a, state);
    assert_eq!(&bytes[..4], b"SDFS");
    free_state(&a, state);
    let ahead = run(&a, 400, 300);

    let b = Fmu::new("b");
    assert_eq!(b.setup(START, Some(STOP)), fmi2Status::fmi2OK);
    assert_eq!(b.set_int(vr::SEED, 13), fmi2Status::fmi2OK);
    assert_eq!(b.set_real(vr::WAVE_DIRECTION, 0.5), fmi2Status::fmi2OK);
    let (s, state) = deserialize(&b, &bytes);
    assert_eq!(s, fmi2Status::fmi2OK, "{}", b.messages());
    assert_eq!(
        unsafe { fmi2SetFMUstate(b.c, state) },
        fmi2Status::fmi2OK,
        "{}",
        b.messages()
    );
    assert_eq!(
        unsafe { instance_state(b.c) },
        Some(MachineState::StepComplete)
    );
    free_state(&b, state);
    let again = run(&b, 400, 300);
    assert_eq!(
        ahead.iter().map(|v| bits(v)).collect::<Vec<_>>(),
        again.iter().map(|v| bits(v)).collect::<Vec<_>>()
    );
}

/// Bytes of another version, truncated, with trailing bytes or with a bit flipped are
/// refused with a log line; a good state still restores afterwards. (A state from a
/// differently configured instance restores: `fmi2_state`.)
#[test]
fn damaged_state_bytes_are_refused() {
    let a = Fmu::running("a", 17, 0.0, START, Some(STOP));
    run(&a, 0, 10);
    let state = get_state(&a);
    let good = serialize(&a, state);
    free_state(&a, state);

    let mut version = good.clone();
    version[4] += 1;
    let mut flipped = good.clone();
    flipped[good.len() / 2] ^= 0x10;
    let cases: [(&str, Vec<u8>); 5] = [
        ("version", version),
        ("bit flipped", flipped),
        ("truncated", good[..good.len() - 3].to_vec()),
        ("trailing", [good.clone(), vec![0]].concat()),
        ("empty", Vec::new()),
    ];
    for (what, bytes) in cases {
        let b = Fmu::running("b", 17, 0.0, START, Some(STOP));
        let (s, p) = deserialize(&b, &bytes);
        assert_eq!((s, p.is_null()), (fmi2Status::fmi2Error, true), "{what}");
        assert!(
            b.last_message().message.contains("FMU state"),
            "{what}: {}",
            b.messages()
        );
        // fmi2Error leaves the instance in Error, from which a good state restores it.
        assert_eq!(unsafe { instance_state(b.c) }, Some(MachineState::Error));
        let (s, p) = deserialize(&b, &good);
        assert_eq!(s, fmi2Status::fmi2OK, "{what}: {}", b.messages());
        assert_eq!(unsafe { fmi2SetFMUstate(b.c, p) }, fmi2Status::fmi2OK);
        free_state(&b, p);
        b.step_with(START + 10.0, 1.0, [0.0; 3]);
    }
}

/// Without a stop time the run is open-ended: it goes on past six hours (the records stream
/// block by block), and over their common span it is bit for bit the run with a stop time
/// (the sea depends on the seed alone). A yaw outside the yaw-following records' range
/// discards the step and keeps the state.
#[test]
fn runs_without_a_stop_time_have_no_end() {
    let hour = 3600.0;
    let open = Fmu::running("open", 3, 0.0, 0.0, None);
    let bounded = Fmu::running("bounded", 3, 0.0, 0.0, Some(2.0 * hour));
    for k in 0..2 {
        let t = k as f64 * hour;
        open.step_with(t, hour, [0.0; 3]);
        bounded.step_with(t, hour, [0.0; 3]);
    }
    assert_eq!(
        bits(&open.outputs()),
        bits(&bounded.outputs()),
        "common span"
    );
    for k in 2..8 {
        open.step_with(k as f64 * hour, hour, [0.0; 3]);
    }
    assert!(open.outputs().iter().all(|v| v.is_finite()));
    assert_eq!(
        open.last_successful_time(),
        (fmi2Status::fmi2OK, 8.0 * hour)
    );
    assert_eq!(open.terminated(), (fmi2Status::fmi2OK, false));
    assert_eq!(
        bounded.step(2.0 * hour, 1.0),
        fmi2Status::fmi2Error,
        "a defined stop time is honoured"
    );
    assert!(
        bounded.last_message().message.contains("stopTime"),
        "{}",
        bounded.messages()
    );

    let yawing = Fmu::new("yawing");
    assert_eq!(yawing.setup(0.0, None), fmi2Status::fmi2OK);
    assert_eq!(
        yawing.set_int(vr::YAW_FOLLOWING_HEADINGS, 3),
        fmi2Status::fmi2OK
    );
    assert_eq!(
        yawing.set_real(vr::YAW_FOLLOWING_RANGE, 0.01),
        fmi2Status::fmi2OK
    );
    assert_eq!(yawing.init(), fmi2Status::fmi2OK);
    let before = yawing.outputs();
    yawing.clear_log();
    assert_eq!(yawing.set_real(vr::MZ_EXT, 1.0e13), fmi2Status::fmi2OK);
    assert_eq!(yawing.step(0.0, 60.0), fmi2Status::fmi2Discard);
    let entry = yawing.last_message();
    assert_eq!(
        (entry.status, entry.category.as_str()),
        (fmi2Status::fmi2Discard, "logStatusDiscard")
    );
    // The remedy is named as the FMU's user sets it.
    assert!(
        entry.message.contains("yaw")
            && entry
                .message
                .contains("widen the parameter yawFollowingRange"),
        "{}",
        entry.message
    );
    assert_eq!(
        unsafe { instance_state(yawing.c) },
        Some(MachineState::StepFailed)
    );
    assert_eq!(yawing.last_successful_time(), (fmi2Status::fmi2OK, 0.0));
    assert_eq!(
        bits(&yawing.outputs()),
        bits(&before),
        "the discarded step changed nothing"
    );
    assert_eq!(unsafe { fmi2Terminate(yawing.c) }, fmi2Status::fmi2OK);
}

/// Across the first join of the record stream (16384 s): a state saved before the join and
/// restored after it (rollback), a state serialized after the join into a fresh instance
/// (which makes that segment straight away) and a reset after the join all replay the
/// uninterrupted run bit for bit.
#[test]
fn states_and_reset_replay_across_a_join() {
    let hour = 3600.0;
    let outputs_after = |fmu: &Fmu, from: f64, steps: usize| -> Vec<Vec<u64>> {
        (0..steps)
            .map(|k| {
                fmu.step_with(from + k as f64 * 600.0, 600.0, [2.0e5, 0.0, 0.0]);
                bits(&fmu.outputs())
            })
            .collect()
    };
    let a = Fmu::running("a", 9, 0.4, 0.0, None);
    a.step_with(0.0, 4.0 * hour, [0.0; 3]);
    let before_join = get_state(&a);
    let crossing = outputs_after(&a, 4.0 * hour, 6);
    let after_join = get_state(&a);
    let bytes = serialize(&a, after_join);
    let ahead = outputs_after(&a, 5.0 * hour, 6);

    assert_eq!(
        unsafe { fmi2SetFMUstate(a.c, before_join) },
        fmi2Status::fmi2OK
    );
    assert_eq!(
        outputs_after(&a, 4.0 * hour, 6),
        crossing,
        "rollback across the join"
    );

    let b = Fmu::new("b");
    let (s, state) = deserialize(&b, &bytes);
    assert_eq!(s, fmi2Status::fmi2OK, "{}", b.messages());
    assert_eq!(unsafe { fmi2SetFMUstate(b.c, state) }, fmi2Status::fmi2OK);
    free_state(&b, state);
    assert_eq!(
        outputs_after(&b, 5.0 * hour, 6),
        ahead,
        "fresh instance after the join"
    );

    free_state(&a, before_join);
    free_state(&a, after_join);
    let first = outputs_after(&Fmu::running("c", 9, 0.4, 0.0, None), 0.0, 3);
    assert_eq!(unsafe { fmi2Reset(b.c) }, fmi2Status::fmi2OK);
    assert_eq!(b.setup(0.0, None), fmi2Status::fmi2OK);
    assert_eq!(b.set_int(vr::SEED, 9), fmi2Status::fmi2OK);
    assert_eq!(b.set_real(vr::WAVE_DIRECTION, 0.4), fmi2Status::fmi2OK);
    assert_eq!(b.init(), fmi2Status::fmi2OK);
    assert_eq!(outputs_after(&b, 0.0, 3), first, "reset after the join");
}

/// Instances in parallel threads: the same seed gives identical outputs, another seed
/// different ones.
#[test]
fn parallel_instances_are_independent_and_reproducible() {
    let seeds = [21, 22, 21, 22];
    let handles: Vec<_> = seeds
        .iter()
        .enumerate()
        .map(|(i, &seed)| {
            std::thread::spawn(move || {
                let fmu = Fmu::running(&format!("thread{i}"), seed, 0.25, START, Some(STOP));
                run(&fmu, 0, 500)
                    .into_iter()
                    .map(|v| bits(&v))
                    .collect::<Vec<_>>()
            })
        })
        .collect();
    let results: Vec<_> = handles.into_iter().map(|h| h.join().unwrap()).collect();
    assert_eq!(results[0], results[2]);
    assert_eq!(results[1], results[3]);
    assert_ne!(results[0], results[1]);
    // And a thread's result is the native simulation's.
    let mut sim = native(21, 0.25, START, STOP);
    let last = (0..500).fold(Vec::new(), |_, n| {
        sim.advance(1.0, external(n)).unwrap();
        bits(&native_outputs(&sim.outputs().unwrap()))
    });
    assert_eq!(results[0].last(), Some(&last));
}
