//! Every misuse of the FMI 2.0 C ABI answers fmi2Error (or fmi2Discard) with a log line,
//! never a crash: calls out of sequence in every state, NULL pointers, unknown and mistyped
//! value references, bad instantiation arguments, bad parameters, inputs and step
//! arguments, unreadable configuration files; and none of it disturbs another instance.

use crate::fmu::*;
use slowdrift::fmi2::exports::*;
use slowdrift::fmi2::machine::{Call, MachineState};
use slowdrift::fmi2::model_description::{vr, GUID, MODEL_IDENTIFIER};
use slowdrift::fmi2::types::*;
use slowdrift::problem;
use slowdrift::Simulation;
use std::ffi::{c_char, CString};
use std::path::{Path, PathBuf};
use std::ptr;

const START: f64 = 100.0;
const STOP: f64 = 700.0;
const ALL_STATES: [MachineState; 6] = [
    MachineState::Instantiated,
    MachineState::InitializationMode,
    MachineState::StepComplete,
    MachineState::StepFailed,
    MachineState::Terminated,
    MachineState::Error,
];

fn state_of(fmu: &Fmu) -> Option<MachineState> {
    unsafe { instance_state(fmu.c) }
}

/// A fresh instance brought into `state` by legal calls (Error: by a bad value reference),
/// with an empty log.
fn in_state(state: MachineState) -> Fmu {
    let fmu = Fmu::new("probe");
    let ok = fmi2Status::fmi2OK;
    match state {
        MachineState::Instantiated => {}
        MachineState::InitializationMode => {
            assert_eq!(fmu.setup(START, Some(STOP)), ok);
            assert_eq!(unsafe { fmi2EnterInitializationMode(fmu.c) }, ok);
        }
        MachineState::StepComplete | MachineState::Terminated => {
            assert_eq!(fmu.setup(START, Some(STOP)), ok);
            assert_eq!(fmu.init(), ok);
            if state == MachineState::Terminated {
                assert_eq!(unsafe { fmi2Terminate(fmu.c) }, ok);
            }
        }
        MachineState::StepFailed => {
            // A yaw moment that turns the platform out of its yaw-following records' range:
            // the step is discarded, the state kept.
            assert_eq!(fmu.setup(0.0, None), ok);
            assert_eq!(fmu.set_int(vr::YAW_FOLLOWING_HEADINGS, 3), ok);
            assert_eq!(fmu.set_real(vr::YAW_FOLLOWING_RANGE, 0.01), ok);
            assert_eq!(fmu.init(), ok);
            assert_eq!(fmu.set_real(vr::MZ_EXT, 1.0e13), ok);
            assert_eq!(fmu.step(0.0, 60.0), fmi2Status::fmi2Discard);
        }
        MachineState::Error => {
            assert_eq!(fmu.set_real(999, 1.0), fmi2Status::fmi2Error);
        }
    }
    assert_eq!(state_of(&fmu), Some(state));
    fmu.clear_log();
    fmu
}

/// Calls `call` on `c` with arguments that are valid apart from the instance's state.
fn invoke(c: fmi2Component, call: Call) -> fmi2Status {
    let mut real = 0.0;
    let mut integer = 0;
    let mut string: fmi2String = ptr::null();
    let mut status = fmi2Status::fmi2OK;
    let mut size = 0usize;
    let mut state: fmi2FMUstate = ptr::null_mut();
    let empty = CString::new("").unwrap();
    let empty_ptr = empty.as_ptr();
    unsafe {
        match call {
            Call::SetDebugLogging => fmi2SetDebugLogging(c, fmi2True, 0, ptr::null()),
            Call::SetupExperiment => fmi2SetupExperiment(c, fmi2False, 0.0, START, fmi2True, STOP),
            Call::EnterInitializationMode => fmi2EnterInitializationMode(c),
            Call::ExitInitializationMode => fmi2ExitInitializationMode(c),
            Call::Terminate => fmi2Terminate(c),
            Call::Reset => fmi2Reset(c),
            Call::GetReal => fmi2GetReal(c, &vr::X, 1, &mut real),
            Call::GetInteger => fmi2GetInteger(c, &vr::SEED, 1, &mut integer),
            Call::GetBoolean => fmi2GetBoolean(c, ptr::null(), 0, ptr::null_mut()),
            Call::GetString => fmi2GetString(c, &vr::HYDRO_DATABASE, 1, &mut string),
            Call::SetReal => fmi2SetReal(c, &vr::FX_EXT, 1, &1.0),
            Call::SetInteger => fmi2SetInteger(c, &vr::SEED, 1, &3),
            Call::SetBoolean => fmi2SetBoolean(c, ptr::null(), 0, ptr::null()),
            Call::SetString => fmi2SetString(c, &vr::HYDRO_DATABASE, 1, &empty_ptr),
            Call::GetFMUstate => {
                let s = fmi2GetFMUstate(c, &mut state);
                if !state.is_null() {
                    assert_eq!(fmi2FreeFMUstate(c, &mut state), fmi2Status::fmi2OK);
                }
                s
            }
            Call::SetFMUstate => fmi2SetFMUstate(c, ptr::null_mut()),
            Call::FreeFMUstate => fmi2FreeFMUstate(c, &mut state),
            Call::SerializedFMUstateSize => {
                fmi2SerializedFMUstateSize(c, ptr::null_mut(), &mut size)
            }
            Call::SerializeFMUstate => {
                fmi2SerializeFMUstate(c, ptr::null_mut(), ptr::null_mut(), 0)
            }
            Call::DeSerializeFMUstate => fmi2DeSerializeFMUstate(c, ptr::null(), 0, &mut state),
            Call::GetDirectionalDerivative => {
                fmi2GetDirectionalDerivative(c, &vr::X, 1, &vr::FX_EXT, 1, &1.0, &mut real)
            }
            Call::SetRealInputDerivatives => {
                fmi2SetRealInputDerivatives(c, &vr::FX_EXT, 1, &1, &1.0)
            }
            Call::GetRealOutputDerivatives => {
                fmi2GetRealOutputDerivatives(c, &vr::X, 1, &1, &mut real)
            }
            Call::DoStep => fmi2DoStep(c, START, 1.0, fmi2False),
            Call::CancelStep => fmi2CancelStep(c),
            Call::GetStatus => fmi2GetStatus(c, fmi2StatusKind::fmi2DoStepStatus, &mut status),
            Call::GetRealStatus => {
                fmi2GetRealStatus(c, fmi2StatusKind::fmi2LastSuccessfulTime, &mut real)
            }
            Call::GetIntegerStatus => {
                fmi2GetIntegerStatus(c, fmi2StatusKind::fmi2DoStepStatus, &mut integer)
            }
            Call::GetBooleanStatus => {
                fmi2GetBooleanStatus(c, fmi2StatusKind::fmi2Terminated, &mut integer)
            }
            Call::GetStringStatus => {
                fmi2GetStringStatus(c, fmi2StatusKind::fmi2PendingStatus, &mut string)
            }
        }
    }
}

/// Asserts fmi2Error and an error log line that contains every piece of `needles`.
fn assert_error(fmu: &Fmu, status: fmi2Status, needles: &[&str]) {
    assert_eq!(
        status,
        fmi2Status::fmi2Error,
        "{needles:?}\n{}",
        fmu.messages()
    );
    let e = fmu.last_message();
    assert_eq!(
        (e.status, e.category.as_str()),
        (fmi2Status::fmi2Error, "logStatusError")
    );
    for n in needles {
        assert!(e.message.contains(n), "{:?} lacks {n:?}", e.message);
    }
    assert_eq!(state_of(fmu), Some(MachineState::Error), "{needles:?}");
}

/// Each function in each state: out of sequence it answers fmi2Error with an "illegal call
/// sequence" line naming the function and the state and leaves the instance in Error;
/// in sequence it never says so.
#[test]
fn every_call_in_every_state_follows_the_table() {
    let mut illegal = 0;
    for state in ALL_STATES {
        for call in Call::ALL {
            let fmu = in_state(state);
            let status = invoke(fmu.c, call);
            let allowed = call.allowed() & (1 << state as u8) != 0;
            if allowed {
                let said = fmu
                    .entries()
                    .iter()
                    .any(|e| e.message.contains("illegal call sequence"));
                assert!(!said, "{call:?} in {state:?}: {}", fmu.messages());
            } else {
                illegal += 1;
                let name = call.name();
                assert_error(
                    &fmu,
                    status,
                    &["illegal call sequence", &name, &format!("{state:?}")],
                );
            }
        }
    }
    assert!(illegal > 0);
}

/// The table against pairs read off FMI 2.0.4's co-simulation state machine (section 4.2.4).
#[test]
fn the_table_agrees_with_the_standard() {
    use MachineState::*;
    let allowed = |call: Call, state: MachineState| call.allowed() & (1 << state as u8) != 0;
    let pairs: [(Call, MachineState, bool); 20] = [
        (Call::SetupExperiment, Instantiated, true),
        (Call::SetupExperiment, InitializationMode, false),
        (Call::EnterInitializationMode, Instantiated, true),
        (Call::EnterInitializationMode, StepComplete, false),
        (Call::ExitInitializationMode, InitializationMode, true),
        (Call::ExitInitializationMode, Instantiated, false),
        (Call::DoStep, StepComplete, true),
        (Call::DoStep, InitializationMode, false),
        (Call::DoStep, StepFailed, false),
        (Call::DoStep, Terminated, false),
        (Call::Terminate, StepComplete, true),
        (Call::Terminate, StepFailed, true),
        (Call::Terminate, Instantiated, false),
        (Call::GetReal, Instantiated, false),
        (Call::GetReal, Error, true),
        (Call::SetReal, StepComplete, true),
        (Call::SetReal, Terminated, false),
        (Call::GetBooleanStatus, StepFailed, true),
        (Call::Reset, Error, true),
        (Call::SetFMUstate, Error, true),
    ];
    for (call, state, expected) in pairs {
        assert_eq!(allowed(call, state), expected, "{call:?} in {state:?}");
    }
}

/// The legal path through the table, state by state.
#[test]
fn legal_transitions() {
    let fmu = in_state(MachineState::Instantiated);
    let steps: [(Call, MachineState); 4] = [
        (Call::SetupExperiment, MachineState::Instantiated),
        (
            Call::EnterInitializationMode,
            MachineState::InitializationMode,
        ),
        (Call::ExitInitializationMode, MachineState::StepComplete),
        (Call::DoStep, MachineState::StepComplete),
    ];
    for (call, after) in steps {
        assert_eq!(
            invoke(fmu.c, call),
            fmi2Status::fmi2OK,
            "{call:?}: {}",
            fmu.messages()
        );
        assert_eq!(state_of(&fmu), Some(after), "{call:?}");
    }
    assert_eq!(unsafe { fmi2Terminate(fmu.c) }, fmi2Status::fmi2OK);
    assert_eq!(state_of(&fmu), Some(MachineState::Terminated));
    for state in ALL_STATES {
        let fmu = in_state(state);
        assert_eq!(
            unsafe { fmi2Reset(fmu.c) },
            fmi2Status::fmi2OK,
            "reset from {state:?}"
        );
        assert_eq!(state_of(&fmu), Some(MachineState::Instantiated));
    }
}

/// A NULL instance: fmi2Error from every function (nothing to log to), no crash.
#[test]
fn null_instance_is_refused() {
    for call in Call::ALL {
        assert_eq!(
            invoke(ptr::null_mut(), call),
            fmi2Status::fmi2Error,
            "{call:?}"
        );
    }
    unsafe { fmi2FreeInstance(ptr::null_mut()) };
}

fn instantiate(log: &Log, name: Option<&str>, ty: fmi2Type, guid: Option<&str>) -> fmi2Component {
    let name = name.map(|n| CString::new(n).unwrap());
    let guid = guid.map(|g| CString::new(g).unwrap());
    let functions = callbacks(log);
    let p = |s: &Option<CString>| s.as_ref().map_or(ptr::null(), |s| s.as_ptr());
    unsafe {
        fmi2Instantiate(
            p(&name),
            ty,
            p(&guid),
            ptr::null(),
            &functions,
            fmi2False,
            fmi2False,
        )
    }
}

/// NULL or empty names, a wrong or NULL GUID and other FMU types give NULL and a log line
/// through the host's logger with its environment; NULL callbacks are fine.
#[test]
fn instantiate_refuses_bad_arguments() {
    let cs = fmi2Type::fmi2CoSimulation;
    let cases: [(Option<&str>, fmi2Type, Option<&str>, &str); 6] = [
        (None, cs, Some(GUID), "instanceName is NULL"),
        (Some(""), cs, Some(GUID), "instanceName is empty"),
        (
            Some("x"),
            cs,
            Some("{00000000-0000-0000-0000-000000000000}"),
            "is neither this binary's",
        ),
        (Some("x"), cs, None, "fmuGUID is NULL"),
        (
            Some("x"),
            fmi2Type::fmi2ModelExchange,
            Some(GUID),
            "fmuType 0 is not supported",
        ),
        (
            Some("x"),
            fmi2Type(7),
            Some(GUID),
            "fmuType 7 is not supported",
        ),
    ];
    for (name, ty, guid, expected) in cases {
        let log = Log::default();
        let c = instantiate(&log, name, ty, guid);
        assert!(c.is_null(), "{expected}");
        let entries = log.lock().unwrap().clone();
        assert_eq!(entries.len(), 1, "{expected}: {entries:?}");
        let e = &entries[0];
        assert_eq!(
            (e.status, e.category.as_str()),
            (fmi2Status::fmi2Error, "logStatusError")
        );
        assert!(
            e.message.contains(expected),
            "{:?} lacks {expected:?}",
            e.message
        );
        assert_eq!(
            e.name,
            name.filter(|n| !n.is_empty())
                .map_or(MODEL_IDENTIFIER, |_| "x")
        );
    }
    // No callbacks at all, or a NULL logger: the instance works and errors go nowhere.
    let guid = CString::new(GUID).unwrap();
    let name = CString::new("quiet").unwrap();
    let no_logger = fmi2CallbackFunctions {
        logger: None,
        allocateMemory: None,
        freeMemory: None,
        stepFinished: None,
        componentEnvironment: ptr::null_mut(),
    };
    for functions in [ptr::null(), &no_logger as *const _] {
        let c = unsafe {
            fmi2Instantiate(
                name.as_ptr(),
                fmi2Type::fmi2CoSimulation,
                guid.as_ptr(),
                ptr::null(),
                functions,
                fmi2False,
                fmi2True,
            )
        };
        assert!(!c.is_null());
        assert_eq!(
            unsafe { fmi2SetReal(c, &999, 1, &1.0) },
            fmi2Status::fmi2Error
        );
        assert_eq!(unsafe { fmi2Reset(c) }, fmi2Status::fmi2OK);
        unsafe { fmi2FreeInstance(c) };
    }
}

/// NULL arrays with a nonzero length, NULL strings, NULL output pointers and NULL states.
#[test]
fn null_arguments_are_refused() {
    type Case = (&'static str, fn(fmi2Component) -> fmi2Status, &'static str);
    let cases: [Case; 14] = [
        (
            "GetReal vr",
            |c| unsafe { fmi2GetReal(c, ptr::null(), 2, [0.0; 2].as_mut_ptr()) },
            "vr is NULL",
        ),
        (
            "GetReal value",
            |c| unsafe { fmi2GetReal(c, [vr::X, vr::Y].as_ptr(), 2, ptr::null_mut()) },
            "value is NULL",
        ),
        (
            "SetReal value",
            |c| unsafe { fmi2SetReal(c, &vr::FX_EXT, 1, ptr::null()) },
            "value is NULL",
        ),
        (
            "GetInteger value",
            |c| unsafe { fmi2GetInteger(c, &vr::SEED, 1, ptr::null_mut()) },
            "value is NULL",
        ),
        (
            "SetInteger vr",
            |c| unsafe { fmi2SetInteger(c, ptr::null(), 1, &1) },
            "vr is NULL",
        ),
        (
            "GetString value",
            |c| unsafe { fmi2GetString(c, &vr::HYDRO_DATABASE, 1, ptr::null_mut()) },
            "value is NULL",
        ),
        (
            "SetString NULL string",
            |c| unsafe { fmi2SetString(c, &vr::HYDRO_DATABASE, 1, &ptr::null()) },
            "String value is NULL",
        ),
        (
            "SetDebugLogging categories",
            |c| unsafe { fmi2SetDebugLogging(c, fmi2True, 1, ptr::null()) },
            "categories is NULL",
        ),
        (
            "GetFMUstate",
            |c| unsafe { fmi2GetFMUstate(c, ptr::null_mut()) },
            "FMUstate is NULL",
        ),
        (
            "SetFMUstate",
            |c| unsafe { fmi2SetFMUstate(c, ptr::null_mut()) },
            "FMUstate is NULL",
        ),
        (
            "FreeFMUstate",
            |c| unsafe { fmi2FreeFMUstate(c, ptr::null_mut()) },
            "FMUstate is NULL",
        ),
        (
            "SerializedFMUstateSize",
            |c| unsafe { fmi2SerializedFMUstateSize(c, ptr::null_mut(), &mut 0) },
            "FMUstate is NULL",
        ),
        (
            "DeSerializeFMUstate bytes",
            |c| unsafe { fmi2DeSerializeFMUstate(c, ptr::null(), 8, &mut ptr::null_mut()) },
            "serializedState is NULL",
        ),
        (
            "GetRealStatus value",
            |c| unsafe {
                fmi2GetRealStatus(c, fmi2StatusKind::fmi2LastSuccessfulTime, ptr::null_mut())
            },
            "value is NULL",
        ),
    ];
    for (what, f, expected) in cases {
        let fmu = in_state(MachineState::StepComplete);
        let status = f(fmu.c);
        assert_error(&fmu, status, &[expected]);
        let _ = what;
    }
}

/// Unknown value references, a value reference of another type, setting an output or a
/// fixed parameter after initialisation: fmi2Error naming the variable.
#[test]
fn unknown_and_mistyped_value_references() {
    type Case = (fn(&Fmu) -> fmi2Status, &'static [&'static str]);
    let cases: [Case; 8] = [
        (
            |f| f.get_reals(&[vr::X, 999]).0,
            &["no Real variable has value reference 999"],
        ),
        (
            |f| f.get_reals(&[vr::N_DIRECTIONS]).0,
            &["no Real variable", "nDirections is Integer"],
        ),
        (
            |f| f.set_int(vr::HS, 3),
            &["no Integer variable", "Hs is Real"],
        ),
        (
            |f| f.set_real(vr::X, 1.0),
            &["X (value reference 30) is an Output and cannot be set"],
        ),
        (|f| f.set_real(vr::HS, 3.0), &["parameter Hs is fixed"]),
        (|f| f.set_int(vr::SEED, 3), &["parameter seed is fixed"]),
        (
            |f| unsafe { fmi2GetBoolean(f.c, &vr::HS, 1, &mut 0) },
            &["no Boolean variable", "Hs is Real"],
        ),
        (|f| f.set_string(vr::HS, "x"), &["no String variable"]),
    ];
    for (f, needles) in cases {
        let fmu = in_state(MachineState::StepComplete);
        let status = f(&fmu);
        assert_error(&fmu, status, needles);
    }
}

/// A refused SetReal sets none of its values.
#[test]
fn a_refused_set_changes_nothing() {
    let fmu = in_state(MachineState::InitializationMode);
    let status = fmu.set_reals(&[vr::FX_EXT, vr::FY_EXT], &[5.0, f64::NAN]);
    assert_error(&fmu, status, &["Fy_ext", "NaN"]);
    assert_eq!(fmu.get_reals(&[vr::FX_EXT]).1, vec![0.0]);
}

/// NaN and infinite inputs and parameters are refused at SetReal; out-of-range parameters
/// at initialisation, with the core's message naming field and value.
#[test]
fn bad_values_are_refused() {
    for (vr, value, expected) in [
        (vr::FX_EXT, f64::NAN, "input Fx_ext = NaN is not finite"),
        (
            vr::MZ_EXT,
            f64::INFINITY,
            "input Mz_ext = inf is not finite",
        ),
        (
            vr::HS,
            f64::NEG_INFINITY,
            "invalid Hs = -inf: must be a finite number",
        ),
        (
            vr::STEP_SIZE,
            f64::NAN,
            "invalid stepSize = NaN: must be a finite number",
        ),
    ] {
        let fmu = in_state(MachineState::InitializationMode);
        let status = fmu.set_real(vr, value);
        assert_error(&fmu, status, &[expected]);
    }
    type Case = (fn(&Fmu) -> fmi2Status, &'static [&'static str]);
    let cases: [Case; 9] = [
        (|f| f.set_real(vr::HS, -1.0), &["FMU parameter Hs = -1"]),
        (|f| f.set_int(vr::INTERACTION, 5), &["interaction = 5"]),
        (
            |f| f.set_int(vr::YAW_FOLLOWING_HEADINGS, 1),
            &["yawFollowingHeadings = 1"],
        ),
        (
            |f| {
                f.set_int(vr::YAW_FOLLOWING_HEADINGS, 4);
                f.set_real(vr::YAW_FOLLOWING_RANGE, -0.2)
            },
            &["FMU parameter yawFollowingRange = -0.2"],
        ),
        (
            |f| f.set_real(vr::STEP_SIZE, 0.0),
            &["FMU parameter stepSize = 0"],
        ),
        (|f| f.set_int(vr::N_DIRECTIONS, 0), &["nDirections = 0"]),
        (|f| f.set_int(vr::SEED, -1), &["seed = -1"]),
        (|f| f.set_int(vr::DRAG_MODEL, 3), &["dragModel = 3"]),
        (|f| f.set_int(vr::DRIFT_DAMPING, 7), &["driftDamping = 7"]),
    ];
    for (set, needles) in cases {
        let fmu = in_state(MachineState::Instantiated);
        assert_eq!(fmu.setup(START, Some(STOP)), fmi2Status::fmi2OK);
        assert_eq!(set(&fmu), fmi2Status::fmi2OK);
        let status = fmu.init();
        assert_error(&fmu, status, needles);
    }
    // fmi2SetupExperiment checks its times.
    for (start, stop) in [
        (f64::NAN, None),
        (10.0, Some(10.0)),
        (0.0, Some(f64::INFINITY)),
    ] {
        let fmu = in_state(MachineState::Instantiated);
        let status = fmu.setup(start, stop);
        assert_error(&fmu, status, &["Time"]);
    }
}

/// Step sizes that are not positive and finite, a communication point away from the
/// instance's time, and a step past stopTime are errors; a point within the relative
/// tolerance is accepted.
#[test]
fn bad_step_arguments_are_refused() {
    for h in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let fmu = in_state(MachineState::StepComplete);
        let status = fmu.step(START, h);
        assert_error(&fmu, status, &["communicationStepSize"]);
    }
    let fmu = in_state(MachineState::StepComplete);
    let status = fmu.step(START + 1e-3, 1.0);
    assert_error(&fmu, status, &["currentCommunicationPoint", "differs"]);
    let fmu = in_state(MachineState::StepComplete);
    assert_eq!(fmu.step(START * (1.0 + 1e-12), 1.0), fmi2Status::fmi2OK);
    let status = fmu.step(START + 1.0, STOP);
    assert_error(&fmu, status, &["passes stopTime"]);
}

/// A scratch directory whose name holds a space, removed on drop.
struct Scratch(PathBuf);

impl Scratch {
    fn new(tag: &str) -> Scratch {
        let dir = std::env::temp_dir().join(format!("slowdrift fmi2 {tag} {}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        Scratch(dir)
    }

    fn write(&self, name: &str, text: &str) -> PathBuf {
        let path = self.0.join(name);
        std::fs::write(&path, text).unwrap();
        path
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn file_uri(path: &Path) -> String {
    format!("file://{}", path.display().to_string().replace(' ', "%20"))
}

const DEFAULT_TOML: &str = include_str!("../../src/scenario/default.toml");

/// Outputs after 50 steps of an instance that is set up by `prepare`.
fn fifty_steps(fmu: &Fmu, prepare: impl Fn(&Fmu)) -> (fmi2Status, Vec<f64>) {
    assert_eq!(fmu.setup(START, Some(STOP)), fmi2Status::fmi2OK);
    prepare(fmu);
    let status = fmu.init();
    if status != fmi2Status::fmi2OK {
        return (status, Vec::new());
    }
    for n in 0..50 {
        fmu.step_with(START + n as f64, 1.0, external(n));
    }
    (status, fmu.outputs())
}

fn native_fifty_steps(mut config: slowdrift::Problem) -> Vec<f64> {
    config.run.start_time = START;
    config.run.duration = STOP - START;
    let mut sim = Simulation::new(config).unwrap();
    for n in 0..50 {
        sim.advance(1.0, external(n)).unwrap();
    }
    native_outputs(&sim.outputs().unwrap())
}

/// hydroDatabase: a missing file and a malformed one are errors naming the file (and a
/// `%` in a message reaches the logger escaped); a valid file, as a path or a file URI with
/// %20, gives the native simulation of that file.
#[test]
fn hydro_database_files() {
    let scratch = Scratch::new("hydro");
    let missing = scratch.0.join("50%-missing.toml");
    let fmu = Fmu::new("missing");
    let (status, _) = fifty_steps(&fmu, |f| {
        assert_eq!(
            f.set_string(vr::HYDRO_DATABASE, missing.to_str().unwrap()),
            fmi2Status::fmi2OK
        )
    });
    assert_error(&fmu, status, &["50%-missing.toml"]);
    assert!(fmu.last_message().raw.contains("50%%-missing.toml"));

    let bad = scratch.write("bad.toml", "[sea]\nhs = 7.0\ntp = \n");
    let fmu = Fmu::new("malformed");
    let (status, _) = fifty_steps(&fmu, |f| {
        assert_eq!(
            f.set_string(vr::HYDRO_DATABASE, bad.to_str().unwrap()),
            fmi2Status::fmi2OK
        )
    });
    assert_error(&fmu, status, &["bad.toml:3"]);

    // Files are files: a FIFO (which would block the read until a writer came), a
    // character device (which /dev/zero would fill memory from) and a directory are refused
    // by what they are, at once, and so is a database a configuration names.
    let fifo = scratch.0.join("pipe.toml");
    assert!(std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let zero_database = scratch.write(
        "zero.toml",
        &DEFAULT_TOML.replace(
            "source = \"default-platform\"",
            "source = \"database\"\nfile = \"/dev/zero\"",
        ),
    );
    for (reference, expected) in [
        (fifo.clone(), "is a FIFO (named pipe), not a regular file"),
        (
            PathBuf::from("/dev/zero"),
            "is a character device, not a regular file",
        ),
        (scratch.0.clone(), "is a directory, not a regular file"),
        (zero_database, "/dev/zero: is a character device"),
    ] {
        let fmu = Fmu::new("not a file");
        let start = std::time::Instant::now();
        let (status, _) = fifty_steps(&fmu, |f| {
            assert_eq!(
                f.set_string(vr::HYDRO_DATABASE, reference.to_str().unwrap()),
                fmi2Status::fmi2OK
            )
        });
        assert!(start.elapsed() < std::time::Duration::from_secs(10));
        assert_error(&fmu, status, &[expected]);
    }

    let heavy = DEFAULT_TOML.replace(
        "\nstiffness = [[1.5807e5",
        "\nmass = 2.0e8\nstiffness = [[1.5807e5",
    );
    assert_ne!(heavy, DEFAULT_TOML);
    let good = scratch.write("heavy platform.toml", &heavy);
    let expected = native_fifty_steps(problem::load(&good).unwrap());
    for reference in [good.display().to_string(), file_uri(&good)] {
        let fmu = Fmu::new("file");
        let (status, outputs) = fifty_steps(&fmu, |f| {
            assert_eq!(
                f.set_string(vr::HYDRO_DATABASE, &reference),
                fmi2Status::fmi2OK
            )
        });
        assert_eq!(
            status,
            fmi2Status::fmi2OK,
            "{reference}: {}",
            fmu.messages()
        );
        assert_eq!(bits(&outputs), bits(&expected), "{reference}");
        let mut p: fmi2String = ptr::null();
        assert_eq!(
            unsafe { fmi2GetString(fmu.c, &vr::HYDRO_DATABASE, 1, &mut p) },
            fmi2Status::fmi2OK
        );
        assert_eq!(
            unsafe { std::ffi::CStr::from_ptr(p) }.to_str(),
            Ok(reference.as_str())
        );
    }
}

/// `resources/platform.toml` is the default configuration in every URI form masters send;
/// without it (or without a resource location) the embedded default is.
#[test]
fn resources_platform_toml_is_the_default() {
    let scratch = Scratch::new("resources");
    let heavy = DEFAULT_TOML.replace(
        "\nstiffness = [[1.5807e5",
        "\nmass = 2.0e8\nstiffness = [[1.5807e5",
    );
    let path = scratch.write(slowdrift::fmi2::resources::RESOURCE_CONFIG, &heavy);
    let expected = native_fifty_steps(problem::load(&path).unwrap());
    let dir = scratch.0.display().to_string();
    for uri in [
        file_uri(&scratch.0),
        format!("{}/", file_uri(&scratch.0)),
        format!("file:{}", dir.replace(' ', "%20")),
        format!("file://localhost{}", dir.replace(' ', "%20")),
    ] {
        let fmu = Fmu::with_resources("res", Some(&uri));
        let (status, outputs) = fifty_steps(&fmu, |_| {});
        assert_eq!(status, fmi2Status::fmi2OK, "{uri}: {}", fmu.messages());
        assert_eq!(bits(&outputs), bits(&expected), "{uri}");
    }
    let embedded = native_fifty_steps(slowdrift::problem::default_problem().unwrap());
    assert_ne!(bits(&embedded), bits(&expected));
    let empty = Scratch::new("no resources");
    for location in [
        Some(file_uri(&empty.0)),
        None,
        Some("http://example.com/resources".into()),
    ] {
        let fmu = Fmu::with_resources("embedded", location.as_deref());
        let (status, outputs) = fifty_steps(&fmu, |_| {});
        assert_eq!(status, fmi2Status::fmi2OK);
        assert_eq!(bits(&outputs), bits(&embedded), "{location:?}");
    }
}

fn categories(names: &[&str]) -> (Vec<CString>, Vec<*const c_char>) {
    let owned: Vec<CString> = names.iter().map(|n| CString::new(*n).unwrap()).collect();
    let pointers = owned.iter().map(|c| c.as_ptr()).collect();
    (owned, pointers)
}

/// fmi2SetDebugLogging: unknown categories are errors; the categories switch messages on
/// and off; errors are always reported.
#[test]
fn debug_logging_categories() {
    let log = Log::default();
    let functions = callbacks(&log);
    let name = CString::new("quiet").unwrap();
    let guid = CString::new(GUID).unwrap();
    let c = unsafe {
        fmi2Instantiate(
            name.as_ptr(),
            fmi2Type::fmi2CoSimulation,
            guid.as_ptr(),
            ptr::null(),
            &functions,
            fmi2False,
            fmi2False,
        )
    };
    let entries = || log.lock().unwrap().clone();
    assert_eq!(
        unsafe { fmi2EnterInitializationMode(c) },
        fmi2Status::fmi2OK
    );
    assert!(entries().is_empty(), "logging off: no events");
    let (_keep, events) = categories(&["logEvents"]);
    assert_eq!(
        unsafe { fmi2SetDebugLogging(c, fmi2True, 1, events.as_ptr()) },
        fmi2Status::fmi2OK
    );
    assert_eq!(unsafe { fmi2Reset(c) }, fmi2Status::fmi2OK);
    let e = entries();
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(
        (
            e[0].category.as_str(),
            e[0].message.as_str(),
            e[0].name.as_str()
        ),
        ("logEvents", "reset", "quiet")
    );
    // All categories on: every call is logged under logAll.
    assert_eq!(
        unsafe { fmi2SetDebugLogging(c, fmi2True, 0, ptr::null()) },
        fmi2Status::fmi2OK
    );
    assert_eq!(
        unsafe { fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2True, 60.0) },
        fmi2Status::fmi2OK
    );
    assert!(entries()
        .iter()
        .any(|e| e.category == "logAll" && e.message == "fmi2SetupExperiment: ok"));
    // All off: errors still reach the logger.
    assert_eq!(
        unsafe { fmi2SetDebugLogging(c, fmi2False, 0, ptr::null()) },
        fmi2Status::fmi2OK
    );
    log.lock().unwrap().clear();
    let (_keep, unknown) = categories(&["logEvents", "logNothing"]);
    assert_eq!(
        unsafe { fmi2SetDebugLogging(c, fmi2True, 2, unknown.as_ptr()) },
        fmi2Status::fmi2Error
    );
    let e = entries();
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(
        e[0].message.contains("unknown log category \"logNothing\""),
        "{}",
        e[0].message
    );
    unsafe { fmi2FreeInstance(c) };
}

/// A second instance stepping alongside every kind of misuse of others ends exactly where
/// a native simulation does.
#[test]
fn misuse_leaves_a_neighbour_untouched() {
    let neighbour = Fmu::running("neighbour", 9, 0.1, START, Some(STOP));
    let mut sim = native(9, 0.1, START, STOP);
    let mut n = 0;
    let mut step_neighbour = || {
        neighbour.step_with(START + n as f64, 1.0, external(n));
        sim.advance(1.0, external(n)).unwrap();
        n += 1;
        assert_eq!(
            bits(&neighbour.outputs()),
            bits(&native_outputs(&sim.outputs().unwrap()))
        );
    };
    for state in ALL_STATES {
        for call in Call::ALL {
            let fmu = in_state(state);
            invoke(fmu.c, call);
            let _ = fmu.set_real(vr::FX_EXT, f64::NAN);
            let _ = fmu.step(START + 0.5, -1.0);
            step_neighbour();
        }
    }
    assert_eq!(state_of(&neighbour), Some(MachineState::StepComplete));
}

/// A status this FMU cannot give answers fmi2Discard, as FMI 2.0.4 section 4.2.3 asks ("If
/// a status is required which cannot be retrieved by the slave it returns fmi2Discard"),
/// with a logStatusDiscard line, and leaves the instance where it was: the run goes on.
#[test]
fn unanswerable_status_queries_discard_and_change_nothing() {
    type Query = (&'static str, fn(fmi2Component) -> fmi2Status);
    let queries: [Query; 5] = [
        ("fmi2GetStatus", |c| {
            let mut v = fmi2Status::fmi2OK;
            unsafe { fmi2GetStatus(c, fmi2StatusKind::fmi2DoStepStatus, &mut v) }
        }),
        ("fmi2GetRealStatus", |c| {
            let mut v = 0.0;
            unsafe { fmi2GetRealStatus(c, fmi2StatusKind::fmi2Terminated, &mut v) }
        }),
        ("fmi2GetIntegerStatus", |c| {
            let mut v = 0;
            unsafe { fmi2GetIntegerStatus(c, fmi2StatusKind::fmi2DoStepStatus, &mut v) }
        }),
        ("fmi2GetBooleanStatus", |c| {
            let mut v = 0;
            unsafe { fmi2GetBooleanStatus(c, fmi2StatusKind::fmi2LastSuccessfulTime, &mut v) }
        }),
        ("fmi2GetStringStatus", |c| {
            let mut v: fmi2String = ptr::null();
            unsafe { fmi2GetStringStatus(c, fmi2StatusKind::fmi2PendingStatus, &mut v) }
        }),
    ];
    let fmu = in_state(MachineState::StepComplete);
    for (name, query) in queries {
        assert_eq!(query(fmu.c), fmi2Status::fmi2Discard, "{name}");
        let e = fmu.last_message();
        assert_eq!(
            (e.status, e.category.as_str()),
            (fmi2Status::fmi2Discard, "logStatusDiscard"),
            "{name}"
        );
        assert!(e.message.contains(name), "{:?} lacks {name}", e.message);
        assert_eq!(state_of(&fmu), Some(MachineState::StepComplete), "{name}");
    }
    assert_eq!(fmu.step(START, 1.0), fmi2Status::fmi2OK);
    assert_eq!(
        fmu.last_successful_time(),
        (fmi2Status::fmi2OK, START + 1.0)
    );
}
