//! An FMU state that stands alone: a serialized state carries the
//! parameters and the experiment, so it restores into an instance straight after
//! `fmi2Instantiate`, before any `fmi2Set*` (the order of fmusim's
//! `--initial-fmu-state-file`: instantiate, deserialize, set, free, then sample and step),
//! or into an instance configured otherwise, and continues bit for bit; a state whose
//! `hydroDatabase` file changed or disappeared is refused with a message naming the file.

use crate::fmu::*;
use slowdrift::fmi2::exports::*;
use slowdrift::fmi2::machine::MachineState;
use slowdrift::fmi2::model_description::vr;
use slowdrift::fmi2::parameters::MAX_STRING_BYTES;
use slowdrift::fmi2::types::*;
use std::ffi::{CStr, CString};
use std::path::PathBuf;
use std::ptr;

const START: f64 = 50.0;
const STOP: f64 = 1250.0;
/// Steps before the state is saved, and after.
const BEFORE: usize = 300;
const AFTER: usize = 300;

const EXAMPLE_TOML: &str = include_str!("../data/example.toml");

/// A scratch directory with a copy of tests/data/example.toml, removed on drop.
struct Database {
    dir: PathBuf,
    file: PathBuf,
}

impl Database {
    fn new(tag: &str) -> Database {
        let dir =
            std::env::temp_dir().join(format!("slowdrift state {tag} {}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("platform 50%.toml");
        std::fs::write(&file, EXAMPLE_TOML).unwrap();
        Database { dir, file }
    }

    fn path(&self) -> &str {
        self.file.to_str().unwrap()
    }
}

impl Drop for Database {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

const REALS: [u32; 5] = [vr::HS, vr::TP, vr::WAVE_DIRECTION, vr::CD_SLOW, vr::CD_FAST];
const REAL_VALUES: [f64; 5] = [4.5, 10.0, 0.35, 0.8, 0.5];
const INTEGERS: [u32; 3] = [vr::SEED, vr::DRAG_MODEL, vr::DRIFT_DAMPING];
/// Seed 29, dragModel separate (1), driftDamping aranha (2: example.toml's table has no
/// damping columns, so the start value, table, would not even build).
const INTEGER_VALUES: [i32; 3] = [29, 1, 2];

/// Non-default parameters on `database` and a stop time, set as a master sets them.
fn configure(fmu: &Fmu, database: &str) {
    assert_eq!(fmu.setup(START, Some(STOP)), fmi2Status::fmi2OK);
    assert_eq!(fmu.set_reals(&REALS, &REAL_VALUES), fmi2Status::fmi2OK);
    for (&r, &v) in INTEGERS.iter().zip(&INTEGER_VALUES) {
        assert_eq!(fmu.set_int(r, v), fmi2Status::fmi2OK);
    }
    assert_eq!(
        fmu.set_string(vr::HYDRO_DATABASE, database),
        fmi2Status::fmi2OK
    );
}

/// The parameters as `fmi2GetReal`, `fmi2GetInteger` and `fmi2GetString` return them.
fn read_parameters(fmu: &Fmu) -> (Vec<u64>, Vec<i32>, String) {
    let (s, reals) = fmu.get_reals(&REALS);
    assert_eq!(s, fmi2Status::fmi2OK, "{}", fmu.messages());
    let mut ints = vec![-1; INTEGERS.len()];
    let s = unsafe { fmi2GetInteger(fmu.c, INTEGERS.as_ptr(), INTEGERS.len(), ints.as_mut_ptr()) };
    assert_eq!(s, fmi2Status::fmi2OK, "{}", fmu.messages());
    let mut p: fmi2String = ptr::null();
    let s = unsafe { fmi2GetString(fmu.c, &vr::HYDRO_DATABASE, 1, &mut p) };
    assert_eq!(s, fmi2Status::fmi2OK, "{}", fmu.messages());
    let text = unsafe { CStr::from_ptr(p) }.to_str().unwrap().to_string();
    (bits(&reals), ints, text)
}

/// `n` steps of 1 s from step `from` with varying external forces; the outputs after each.
fn run(fmu: &Fmu, from: usize, n: usize) -> Vec<Vec<u64>> {
    (from..from + n)
        .map(|k| {
            fmu.step_with(START + k as f64, 1.0, external(k));
            bits(&fmu.outputs())
        })
        .collect()
}

/// Instance A on `database`, run for [`BEFORE`] steps: its state's bytes, its outputs at
/// the save and its [`AFTER`] steps after it.
fn saved_run(database: &str) -> (Vec<u8>, Vec<u64>, Vec<Vec<u64>>) {
    let a = Fmu::new("a");
    configure(&a, database);
    assert_eq!(a.init(), fmi2Status::fmi2OK, "{}", a.messages());
    run(&a, 0, BEFORE);
    let at_save = bits(&a.outputs());
    let state = get_state(&a);
    let bytes = serialize(&a, state);
    free_state(&a, state);
    let ahead = run(&a, BEFORE, AFTER);
    (bytes, at_save, ahead)
}

/// fmusim's `--initial-fmu-state-file` order: deserialize, set, free; `Err` with the last
/// log line when deserialize or set answers otherwise than fmi2OK.
pub(crate) fn restore(fmu: &Fmu, bytes: &[u8]) -> Result<(), String> {
    let (s, state) = deserialize(fmu, bytes);
    if s != fmi2Status::fmi2OK {
        return Err(fmu.last_message().message);
    }
    let s = unsafe { fmi2SetFMUstate(fmu.c, state) };
    let message = fmu.last_message().message;
    free_state(fmu, state);
    if s != fmi2Status::fmi2OK {
        return Err(message);
    }
    Ok(())
}

/// A fresh instance (fmi2Instantiate only) takes the state's parameters, experiment, inputs
/// and dynamic state: its outputs at the restored point and after every step equal A's bit
/// for bit, and its parameters read back as A's.
#[test]
fn a_state_restores_into_a_fresh_instance_before_any_set() {
    let db = Database::new("fresh");
    let (bytes, at_save, ahead) = saved_run(db.path());

    let b = Fmu::new("b");
    assert_eq!(
        unsafe { instance_state(b.c) },
        Some(MachineState::Instantiated)
    );
    restore(&b, &bytes).unwrap_or_else(|m| panic!("{m}\n{}", b.messages()));
    assert_eq!(
        unsafe { instance_state(b.c) },
        Some(MachineState::StepComplete)
    );
    assert!(
        b.messages()
            .contains("records rebuilt from the state's parameters and hydroDatabase = "),
        "{}",
        b.messages()
    );
    // What the state carries, read back through the getters.
    let (reals, ints, text) = read_parameters(&b);
    assert_eq!(reals, bits(&REAL_VALUES));
    assert_eq!(ints, INTEGER_VALUES);
    assert_eq!(text, db.path());
    let (_, inputs) = b.get_reals(&INPUTS);
    assert_eq!(bits(&inputs), bits(&external(BEFORE - 1)));
    assert_eq!(
        b.last_successful_time(),
        (fmi2Status::fmi2OK, START + BEFORE as f64)
    );
    // fmusim samples the outputs first, then sets the inputs and steps.
    assert_eq!(bits(&b.outputs()), at_save);
    assert_eq!(run(&b, BEFORE, AFTER), ahead);
    // The experiment came along: its stop time holds.
    let t = START + (BEFORE + AFTER) as f64;
    assert_eq!(b.step(t, STOP - t + 1.0), fmi2Status::fmi2Error);
    assert!(
        b.last_message().message.contains("passes stopTime = 1250"),
        "{}",
        b.messages()
    );
}

/// The comparison above is sensitive to what the state carries: the same run with only
/// the seed changed differs at the save.
#[test]
fn another_seed_changes_the_run() {
    let db = Database::new("control");
    let (_, at_save, _) = saved_run(db.path());
    let other = Fmu::new("other seed");
    configure(&other, db.path());
    assert_eq!(other.set_int(vr::SEED, 30), fmi2Status::fmi2OK);
    assert_eq!(other.init(), fmi2Status::fmi2OK, "{}", other.messages());
    run(&other, 0, BEFORE);
    assert_ne!(bits(&other.outputs()), at_save);
}

/// An instance configured otherwise (another seed, database and stop time, running) takes
/// the state's parameters and experiment, from the bytes and from a state in memory.
#[test]
fn a_state_restores_into_an_instance_configured_otherwise() {
    let db = Database::new("otherwise");
    let (bytes, at_save, ahead) = saved_run(db.path());
    let other = Fmu::running("other", 3, 0.0, 0.0, Some(600.0));
    for k in 0..5 {
        other.step_with(k as f64, 1.0, external(k));
    }
    restore(&other, &bytes).unwrap_or_else(|m| panic!("{m}"));
    assert_eq!(read_parameters(&other).1, INTEGER_VALUES);
    assert_eq!(bits(&other.outputs()), at_save);
    assert_eq!(run(&other, BEFORE, AFTER), ahead);

    // In memory: a state of `other` (now A's configuration) set into a third instance.
    let (_, state) = deserialize(&other, &bytes);
    let third = Fmu::running("third", 4, 0.1, 0.0, None);
    assert_eq!(
        unsafe { fmi2SetFMUstate(third.c, state) },
        fmi2Status::fmi2OK,
        "{}",
        third.messages()
    );
    free_state(&other, state);
    assert_eq!(read_parameters(&third).2, db.path());
    assert_eq!(run(&third, BEFORE, AFTER), ahead);
}

/// A rollback within one instance keeps its records (nothing is read or rebuilt).
#[test]
fn a_rollback_keeps_the_records() {
    let db = Database::new("rollback");
    let a = Fmu::new("a");
    configure(&a, db.path());
    assert_eq!(a.init(), fmi2Status::fmi2OK, "{}", a.messages());
    run(&a, 0, 20);
    let state = get_state(&a);
    let ahead = run(&a, 20, 20);
    // Even with the file gone: the records are those of the state.
    std::fs::remove_file(&db.file).unwrap();
    a.clear_log();
    assert_eq!(unsafe { fmi2SetFMUstate(a.c, state) }, fmi2Status::fmi2OK);
    free_state(&a, state);
    assert!(!a.messages().contains("rebuilt"), "{}", a.messages());
    assert_eq!(run(&a, 20, 20), ahead);
}

/// A state saved before initialisation (its parameters set, no simulation yet) restores
/// into a fresh instance, which then initialises to A's run without any fmi2Set*.
#[test]
fn a_state_saved_before_initialisation_carries_the_parameters() {
    let db = Database::new("instantiated");
    let a = Fmu::new("a");
    configure(&a, db.path());
    let state = get_state(&a);
    let bytes = serialize(&a, state);
    free_state(&a, state);
    assert_eq!(a.init(), fmi2Status::fmi2OK, "{}", a.messages());
    let expected = run(&a, 0, 30);

    let b = Fmu::new("b");
    restore(&b, &bytes).unwrap_or_else(|m| panic!("{m}"));
    assert_eq!(
        unsafe { instance_state(b.c) },
        Some(MachineState::Instantiated)
    );
    assert_eq!(b.init(), fmi2Status::fmi2OK, "{}", b.messages());
    assert_eq!(read_parameters(&b).1, INTEGER_VALUES);
    assert_eq!(run(&b, 0, 30), expected);
}

/// A hydroDatabase whose content changed since the save, or that is gone, refuses the state
/// with a message naming the file; the instance keeps its own parameters (readable in
/// Error) and a good state restores it.
#[test]
fn a_changed_or_missing_database_refuses_the_state() {
    let db = Database::new("changed");
    let (bytes, _, ahead) = saved_run(db.path());
    let heavier = EXAMPLE_TOML.replace("mass = 1.2e7 ", "mass = 1.3e7 ");
    assert_ne!(heavier, EXAMPLE_TOML);
    std::fs::write(&db.file, &heavier).unwrap();

    let b = Fmu::new("b");
    assert_eq!(b.setup(START, Some(STOP)), fmi2Status::fmi2OK);
    assert_eq!(b.set_int(vr::SEED, 3), fmi2Status::fmi2OK);
    let message = restore(&b, &bytes).unwrap_err();
    assert!(
        message.contains(&format!(
            "saved with hydroDatabase = {} whose content",
            db.path()
        )),
        "{message}"
    );
    assert!(
        message.contains("differs from what that file holds now"),
        "{message}"
    );
    let e = b
        .entries()
        .into_iter()
        .rev()
        .find(|e| e.status != fmi2Status::fmi2OK)
        .unwrap();
    assert_eq!(
        (e.status, e.category.as_str()),
        (fmi2Status::fmi2Error, "logStatusError")
    );
    assert!(e.raw.contains("platform 50%%.toml"), "{}", e.raw);
    assert_eq!(unsafe { instance_state(b.c) }, Some(MachineState::Error));
    // Nothing of the state was taken: the seed is still b's own.
    let mut seed = 0;
    assert_eq!(
        unsafe { fmi2GetInteger(b.c, &vr::SEED, 1, &mut seed) },
        fmi2Status::fmi2OK
    );
    assert_eq!(seed, 3);
    // The file back as it was: the same bytes restore and continue bit for bit.
    std::fs::write(&db.file, EXAMPLE_TOML).unwrap();
    restore(&b, &bytes).unwrap_or_else(|m| panic!("{m}"));
    assert_eq!(run(&b, BEFORE, AFTER), ahead);

    // The file gone.
    std::fs::remove_file(&db.file).unwrap();
    let c = Fmu::new("c");
    let message = restore(&c, &bytes).unwrap_err();
    assert!(
        message.contains(&format!(
            "saved with hydroDatabase = {}, which cannot be read now",
            db.path()
        )),
        "{message}"
    );
    assert!(message.contains("No such file"), "{message}");
    assert_eq!(unsafe { instance_state(c.c) }, Some(MachineState::Error));
    // A good state (of the packed default) restores the instance and its parameters.
    let d = Fmu::running("d", 8, 0.2, START, Some(STOP));
    run(&d, 0, 10);
    let state = get_state(&d);
    let good = serialize(&d, state);
    free_state(&d, state);
    let expected = run(&d, 10, 10);
    restore(&c, &good).unwrap_or_else(|m| panic!("{m}"));
    assert_eq!(read_parameters(&c).1[0], 8);
    assert_eq!(read_parameters(&c).2, "");
    assert_eq!(run(&c, 10, 10), expected);
}

/// A String parameter longer than a state can carry is refused when it is set, naming it.
#[test]
fn an_overlong_string_is_refused_when_set() {
    let fmu = Fmu::new("long");
    let long = CString::new("x".repeat(MAX_STRING_BYTES + 1)).unwrap();
    let p = long.as_ptr();
    let s = unsafe { fmi2SetString(fmu.c, &vr::HYDRO_DATABASE, 1, &p) };
    assert_eq!(s, fmi2Status::fmi2Error);
    let message = fmu.last_message().message;
    assert!(
        message.contains("hydroDatabase is 65537 bytes long"),
        "{message}"
    );
    let fmu = Fmu::new("longest");
    let longest = "x".repeat(MAX_STRING_BYTES);
    assert_eq!(
        fmu.set_string(vr::HYDRO_DATABASE, &longest),
        fmi2Status::fmi2OK
    );
}

/// `fmi2DeSerializeFMUstate` checks every field as `fmi2SetFMUstate` does: a snapshot with an infinite external force or a NaN time origin is refused at
/// deserialisation, and a last successful time
/// beyond the snapshot's time is refused (before, it was restored and reported), each with
/// fmi2Error naming the field and its byte offset. The bytes are a real state's, changed
/// and resealed.
#[test]
fn deserialisation_checks_every_field() {
    let a = Fmu::running("saved", 1, 0.0, START, Some(STOP));
    for k in 0..10 {
        a.step_with(START + k as f64, 1.0, external(k));
    }
    let state = get_state(&a);
    let good = serialize(&a, state);
    free_state(&a, state);
    // The snapshot is the 104 bytes before the checksum: 8-byte words origin, count, step,
    // X, Y, theta, X', Y', theta', Fx, Fy, Mz, the wind input; the last successful time is
    // at byte 18.
    let snapshot = good.len() - 8 - 104;
    let word = |k: usize| snapshot + 8 * k;
    let cases = [
        (word(9), f64::INFINITY, "snapshot external_force[0] = inf"),
        (word(0), f64::NAN, "snapshot origin = NaN"),
        (
            18,
            START + 11.0,
            "last successful time 61 s at byte 18: is beyond the instance's time 60 s",
        ),
    ];
    for (at, value, needle) in cases {
        let mut bytes = good.clone();
        bytes[at..at + 8].copy_from_slice(&value.to_le_bytes());
        reseal(&mut bytes);
        let b = Fmu::new("b");
        let (status, state) = deserialize(&b, &bytes);
        assert_eq!(status, fmi2Status::fmi2Error, "{needle}: {}", b.messages());
        assert!(state.is_null());
        let message = b.last_message().message;
        assert!(message.contains(needle), "{needle:?} in {message:?}");
        assert!(message.contains("invalid FMU state"), "{message}");
    }
    let b = Fmu::new("b");
    restore(&b, &good).unwrap_or_else(|m| panic!("{m}"));
    assert_eq!(b.last_successful_time(), (fmi2Status::fmi2OK, START + 10.0));
}
