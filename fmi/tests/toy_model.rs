//! The FMI 2.0 layer on a toy model, through its functions as a cdylib's shims call them:
//! instantiation (GUID, name, resource location), the state machine, the panic firewall, the
//! one status and log policy (errors, discards, unanswered status queries), the log
//! categories, the unsupported functions and saved states.

use slowdrift_fmi::fmi2::functions as fmi2;
use slowdrift_fmi::fmi2::machine::{Call, MachineState};
use slowdrift_fmi::fmi2::types::*;
use slowdrift_fmi::fmi2::{Context, Instantiation, Model, SavedStates};
use slowdrift_fmi::text::c_text;
use slowdrift_fmi::Error;
use std::ffi::{c_void, CStr, CString};
use std::ptr;
use std::sync::Mutex;

const GUID: &CStr = c"{toy}";

/// One variable, `x` (Real, value reference 0; 99 panics when set), and the resources folder
/// as a String (value reference 0). A step longer than 10 s is discarded.
struct Toy {
    x: f64,
    time: f64,
    resources: String,
    strings: Vec<CString>,
}

impl Model for Toy {
    const MODEL_IDENTIFIER: &'static str = "Toy";
    const WITHOUT_RESOURCES: &'static str = "the toy has none";

    fn instantiate(i: Instantiation<'_>) -> Result<Toy, Error> {
        if i.guid != GUID.to_str().unwrap() {
            return Err(Error::Argument(format!(
                "fmuGUID {} is not the toy's",
                i.guid
            )));
        }
        Ok(Toy {
            x: 0.0,
            time: 0.0,
            resources: i
                .resources
                .map(|p| p.display().to_string())
                .unwrap_or_default(),
            strings: Vec::new(),
        })
    }

    fn setup_experiment(&mut self, start: f64, _stop: Option<f64>) -> Result<(), Error> {
        self.time = start;
        Ok(())
    }

    fn exit_initialization_mode(&mut self, cx: &Context) -> Result<(), Error> {
        cx.event("initialized");
        Ok(())
    }

    fn reset(&mut self) {
        self.x = 0.0;
        self.time = 0.0;
    }

    fn get_real(&mut self, _cx: &Context, vrs: &[u32], values: &mut [f64]) -> Result<(), Error> {
        for (&vr, v) in vrs.iter().zip(values) {
            match vr {
                0 => *v = self.x,
                _ => return Err(Error::Argument(format!("no Real has value reference {vr}"))),
            }
        }
        Ok(())
    }

    fn get_integer(&mut self, _: &Context, vrs: &[u32], _: &mut [i32]) -> Result<(), Error> {
        none("Integer", vrs)
    }

    fn get_boolean(&mut self, _: &Context, vrs: &[u32], _: &mut [i32]) -> Result<(), Error> {
        none("Boolean", vrs)
    }

    fn get_string(&mut self, _: &Context, vrs: &[u32]) -> Result<&[CString], Error> {
        self.strings = vrs.iter().map(|_| c_text(&self.resources)).collect();
        Ok(&self.strings)
    }

    fn set_real(&mut self, cx: &Context, vrs: &[u32], values: &[f64]) -> Result<(), Error> {
        for (&vr, &v) in vrs.iter().zip(values) {
            match vr {
                0 if cx.state().fixed_parameters_settable() => self.x = v,
                0 => return Err(Error::Argument("x is fixed".into())),
                99 => panic!("boom 100%"),
                _ => return Err(Error::Argument(format!("no Real has value reference {vr}"))),
            }
        }
        Ok(())
    }

    fn set_integer(&mut self, _: &Context, vrs: &[u32], _: &[i32]) -> Result<(), Error> {
        none("Integer", vrs)
    }

    fn set_boolean(&mut self, _: &Context, vrs: &[u32], _: &[i32]) -> Result<(), Error> {
        none("Boolean", vrs)
    }

    fn set_string(&mut self, _: &Context, vrs: &[u32], _: &[&str]) -> Result<(), Error> {
        none("String", vrs)
    }

    fn do_step(&mut self, point: f64, h: f64) -> Result<(), Error> {
        if point != self.time {
            return Err(Error::Argument("not the toy's time".into()));
        }
        if h > 10.0 {
            return Err(Error::Discard(format!("a step of {h} s is too long")));
        }
        self.time += h;
        Ok(())
    }

    fn last_successful_time(&self) -> f64 {
        self.time
    }
}

impl SavedStates for Toy {
    type State = (f64, f64, MachineState);

    fn get_fmu_state(&mut self, cx: &Context) -> Result<Self::State, Error> {
        Ok((self.x, self.time, cx.state()))
    }

    fn set_fmu_state(&mut self, _: &Context, s: &Self::State) -> Result<MachineState, Error> {
        (self.x, self.time) = (s.0, s.1);
        Ok(s.2)
    }

    fn serialized_size(_: &Self::State) -> usize {
        16
    }

    fn serialize(s: &Self::State) -> Result<Vec<u8>, Error> {
        Ok([s.0.to_le_bytes(), s.1.to_le_bytes()].concat())
    }

    fn deserialize(bytes: &[u8]) -> Result<Self::State, Error> {
        let number = |i: usize| f64::from_le_bytes(bytes[i..i + 8].try_into().unwrap());
        match bytes.len() {
            16 => Ok((number(0), number(8), MachineState::StepComplete)),
            n => Err(Error::Argument(format!("{n} bytes: not a toy state"))),
        }
    }
}

fn none(kind: &str, vrs: &[u32]) -> Result<(), Error> {
    match vrs.first() {
        Some(vr) => Err(Error::Argument(format!(
            "no {kind} variable has value reference {vr}"
        ))),
        None => Ok(()),
    }
}

/// One logged line: status, category, message.
type Line = (fmi2Status, String, String);

/// Records every line into the `Mutex<Vec<Line>>` behind `env` (the five fixed arguments:
/// the layer passes no variadic ones).
unsafe extern "C" fn record(
    env: *mut c_void,
    _name: fmi2String,
    status: fmi2Status,
    category: fmi2String,
    message: fmi2String,
) {
    let log = unsafe { &*(env as *const Mutex<Vec<Line>>) };
    let text = |p| unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned();
    log.lock()
        .unwrap()
        .push((status, text(category), text(message)));
}

/// An instance of the toy with a recording logger.
struct Instance {
    c: fmi2Component,
    log: Box<Mutex<Vec<Line>>>,
}

impl Instance {
    fn new(guid: &CStr, location: Option<&CStr>, logging_on: bool) -> Instance {
        let log = Box::new(Mutex::new(Vec::new()));
        let c = instantiate(guid, location, logging_on, &log);
        Instance { c, log }
    }

    fn take(&self) -> Vec<Line> {
        std::mem::take(&mut *self.log.lock().unwrap())
    }

    fn state(&self) -> Option<MachineState> {
        unsafe { fmi2::machine_state::<Toy>(self.c) }
    }

    fn initialized(&self) {
        unsafe {
            assert_eq!(
                fmi2::setup_experiment::<Toy>(self.c, 0.0, fmi2False, 0.0),
                fmi2Status::fmi2OK
            );
            assert_eq!(
                fmi2::enter_initialization_mode::<Toy>(self.c),
                fmi2Status::fmi2OK
            );
            assert_eq!(
                fmi2::exit_initialization_mode::<Toy>(self.c),
                fmi2Status::fmi2OK
            );
        }
    }
}

impl Drop for Instance {
    fn drop(&mut self) {
        unsafe { fmi2::free_instance::<Toy>(self.c) };
    }
}

fn instantiate(
    guid: &CStr,
    location: Option<&CStr>,
    logging_on: bool,
    log: &Mutex<Vec<Line>>,
) -> fmi2Component {
    type Fixed = unsafe extern "C" fn(*mut c_void, fmi2String, fmi2Status, fmi2String, fmi2String);
    let functions = fmi2CallbackFunctions {
        // SAFETY: a call with the five fixed arguments only has the same ABI.
        logger: Some(unsafe { std::mem::transmute::<Fixed, fmi2CallbackLogger>(record) }),
        allocateMemory: None,
        freeMemory: None,
        stepFinished: None,
        componentEnvironment: log as *const _ as *mut c_void,
    };
    unsafe {
        fmi2::instantiate::<Toy>(
            c"toy".as_ptr(),
            fmi2Type::fmi2CoSimulation,
            guid.as_ptr(),
            location.map_or(ptr::null(), CStr::as_ptr),
            &functions,
            if logging_on { fmi2True } else { fmi2False },
        )
    }
}

fn category(c: &str) -> String {
    c.to_string()
}

#[test]
fn instantiation_checks_its_arguments_and_passes_the_resources() {
    let refused = Instance::new(c"{other}", None, false);
    assert!(refused.c.is_null());
    assert_eq!(
        refused.take(),
        [(
            fmi2Status::fmi2Error,
            category("logStatusError"),
            "fmi2Instantiate: fmuGUID {other} is not the toy's".into()
        )]
    );

    let located = Instance::new(GUID, Some(c"file:///tmp/toy%20fmu/resources"), false);
    assert!(!located.c.is_null());
    assert!(located.take().is_empty());
    unsafe { fmi2::enter_initialization_mode::<Toy>(located.c) };
    let mut value: fmi2String = ptr::null();
    assert_eq!(
        unsafe { fmi2::get_string::<Toy>(located.c, &0, 1, &mut value) },
        fmi2Status::fmi2OK
    );
    assert_eq!(
        unsafe { CStr::from_ptr(value) }.to_str(),
        Ok("/tmp/toy fmu/resources")
    );

    let remote = Instance::new(GUID, Some(c"http://host/resources"), false);
    assert!(!remote.c.is_null());
    assert_eq!(
        remote.take(),
        [(
            fmi2Status::fmi2Warning,
            category("logStatusWarning"),
            "fmi2Instantiate: fmuResourceLocation is not a local file URI; the toy has none".into()
        )]
    );

    // Without a logger: NULL for model exchange and for a missing name, and nothing crosses.
    let functions = fmi2CallbackFunctions {
        logger: None,
        allocateMemory: None,
        freeMemory: None,
        stepFinished: None,
        componentEnvironment: ptr::null_mut(),
    };
    let c = unsafe {
        fmi2::instantiate::<Toy>(
            c"toy".as_ptr(),
            fmi2Type::fmi2ModelExchange,
            GUID.as_ptr(),
            ptr::null(),
            &functions,
            fmi2False,
        )
    };
    assert!(c.is_null(), "model exchange is refused");
    let c = unsafe {
        fmi2::instantiate::<Toy>(
            ptr::null(),
            fmi2Type::fmi2CoSimulation,
            GUID.as_ptr(),
            ptr::null(),
            &functions,
            fmi2False,
        )
    };
    assert!(c.is_null());
    assert_eq!(unsafe { fmi2::machine_state::<Toy>(ptr::null_mut()) }, None);
    unsafe { fmi2::free_instance::<Toy>(ptr::null_mut()) };
    assert_eq!(
        unsafe { fmi2::do_step::<Toy>(ptr::null_mut(), 0.0, 1.0) },
        fmi2Status::fmi2Error
    );
}

#[test]
fn an_illegal_call_is_an_error_that_puts_the_instance_in_error() {
    let toy = Instance::new(GUID, None, false);
    assert_eq!(
        unsafe { fmi2::do_step::<Toy>(toy.c, 0.0, 1.0) },
        fmi2Status::fmi2Error
    );
    assert_eq!(
        toy.take(),
        [(
            fmi2Status::fmi2Error,
            category("logStatusError"),
            "fmi2DoStep: illegal call sequence: fmi2DoStep is not allowed in state Instantiated"
                .into()
        )]
    );
    assert_eq!(toy.state(), Some(MachineState::Error));
    // In Error only a reset, a restored state, getters and logging calls are allowed.
    let mut x = f64::NAN;
    assert_eq!(
        unsafe { fmi2::get_real::<Toy>(toy.c, &0, 1, &mut x) },
        fmi2Status::fmi2OK
    );
    assert_eq!(x, 0.0);
    assert_eq!(unsafe { fmi2::reset::<Toy>(toy.c) }, fmi2Status::fmi2OK);
    assert_eq!(toy.state(), Some(MachineState::Instantiated));
}

#[test]
fn a_panic_becomes_an_error_and_a_log_line() {
    let toy = Instance::new(GUID, None, false);
    assert_eq!(
        unsafe { fmi2::set_real::<Toy>(toy.c, &99, 1, &1.0) },
        fmi2Status::fmi2Error
    );
    assert_eq!(toy.state(), Some(MachineState::Error));
    assert_eq!(
        toy.take(),
        [(
            fmi2Status::fmi2Error,
            category("logStatusError"),
            // The message is a printf format: its % doubled.
            "fmi2SetReal: internal error (panic caught): boom 100%%".into()
        )]
    );
    // The instance is still usable after a reset.
    assert_eq!(unsafe { fmi2::reset::<Toy>(toy.c) }, fmi2Status::fmi2OK);
    assert_eq!(
        unsafe { fmi2::set_real::<Toy>(toy.c, &0, 1, &2.0) },
        fmi2Status::fmi2OK
    );
}

#[test]
fn arguments_are_checked_before_the_model_runs() {
    let toy = Instance::new(GUID, None, false);
    assert_eq!(
        unsafe { fmi2::set_real::<Toy>(toy.c, ptr::null(), 1, &1.0) },
        fmi2Status::fmi2Error
    );
    assert_eq!(
        toy.take()[0].2,
        "fmi2SetReal: vr is NULL or misaligned but its length is 1"
    );
    unsafe { fmi2::reset::<Toy>(toy.c) };
    let values = [c"a".as_ptr(), ptr::null()];
    assert_eq!(
        unsafe { fmi2::set_string::<Toy>(toy.c, [0, 0].as_ptr(), 2, values.as_ptr()) },
        fmi2Status::fmi2Error
    );
    assert_eq!(toy.take()[0].2, "fmi2SetString: a String value is NULL");
    // Nothing to pass: NULL arrays are fine.
    unsafe { fmi2::reset::<Toy>(toy.c) };
    assert_eq!(
        unsafe { fmi2::set_boolean::<Toy>(toy.c, ptr::null(), 0, ptr::null()) },
        fmi2Status::fmi2OK
    );
}

#[test]
fn a_discarded_step_fails_the_step_and_an_unanswered_status_changes_nothing() {
    let toy = Instance::new(GUID, None, false);
    toy.initialized();
    toy.take();
    assert_eq!(
        unsafe { fmi2::do_step::<Toy>(toy.c, 0.0, 60.0) },
        fmi2Status::fmi2Discard
    );
    assert_eq!(toy.state(), Some(MachineState::StepFailed));
    assert_eq!(
        toy.take(),
        [(
            fmi2Status::fmi2Discard,
            category("logStatusDiscard"),
            "fmi2DoStep: step discarded: a step of 60 s is too long".into()
        )]
    );
    let mut time = f64::NAN;
    assert_eq!(
        unsafe {
            fmi2::get_real_status::<Toy>(toy.c, fmi2StatusKind::fmi2LastSuccessfulTime, &mut time)
        },
        fmi2Status::fmi2OK
    );
    assert_eq!(time, 0.0);
    let mut terminated = fmi2True;
    assert_eq!(
        unsafe {
            fmi2::get_boolean_status::<Toy>(toy.c, fmi2StatusKind::fmi2Terminated, &mut terminated)
        },
        fmi2Status::fmi2OK
    );
    assert_eq!(terminated, fmi2False);
    for status in [
        unsafe { fmi2::get_status::<Toy>(toy.c) },
        unsafe { fmi2::get_integer_status::<Toy>(toy.c) },
        unsafe { fmi2::get_string_status::<Toy>(toy.c) },
        unsafe { fmi2::get_real_status::<Toy>(toy.c, fmi2StatusKind::fmi2DoStepStatus, &mut time) },
    ] {
        assert_eq!(status, fmi2Status::fmi2Discard);
        assert_eq!(toy.state(), Some(MachineState::StepFailed));
    }
    let lines = toy.take();
    assert_eq!(lines.len(), 4);
    assert!(lines
        .iter()
        .all(|l| l.1 == "logStatusDiscard" && l.2.contains("status not available")));
}

#[test]
fn logging_on_gives_the_events_and_the_trace_only_when_named() {
    let toy = Instance::new(GUID, None, true);
    toy.initialized();
    let lines: Vec<_> = toy.take().into_iter().map(|l| (l.1, l.2)).collect();
    assert_eq!(
        lines,
        [
            (category("logEvents"), "entered initialization mode".into()),
            (category("logEvents"), "initialized".into())
        ]
    );
    let all = [c"logAll".as_ptr()];
    assert_eq!(
        unsafe { fmi2::set_debug_logging::<Toy>(toy.c, fmi2True, 1, all.as_ptr()) },
        fmi2Status::fmi2OK
    );
    assert_eq!(
        unsafe { fmi2::do_step::<Toy>(toy.c, 0.0, 1.0) },
        fmi2Status::fmi2OK
    );
    assert_eq!(
        toy.take(),
        [
            (
                fmi2Status::fmi2OK,
                category("logAll"),
                "fmi2SetDebugLogging: ok".into()
            ),
            (
                fmi2Status::fmi2OK,
                category("logAll"),
                "fmi2DoStep: ok".into()
            )
        ]
    );
    let none = [c"logNothing".as_ptr()];
    assert_eq!(
        unsafe { fmi2::set_debug_logging::<Toy>(toy.c, fmi2False, 1, none.as_ptr()) },
        fmi2Status::fmi2Error
    );
    assert!(toy.take()[0]
        .2
        .contains("unknown log category \"logNothing\""));
}

#[test]
fn unsupported_functions_say_why() {
    let toy = Instance::new(GUID, None, false);
    type Function = unsafe fn(fmi2Component) -> fmi2Status;
    let calls: [(Function, &str); 4] = [
        (
            fmi2::get_directional_derivative::<Toy>,
            "fmi2GetDirectionalDerivative: not supported: providesDirectionalDerivative",
        ),
        (
            fmi2::set_real_input_derivatives::<Toy>,
            "fmi2SetRealInputDerivatives: not supported: canInterpolateInputs",
        ),
        (
            fmi2::get_real_output_derivatives::<Toy>,
            "fmi2GetRealOutputDerivatives: not supported: maxOutputDerivativeOrder",
        ),
        (
            fmi2::cancel_step::<Toy>,
            "fmi2CancelStep: not supported: steps are never asynchronous",
        ),
    ];
    for (call, said) in calls {
        assert_eq!(unsafe { call(toy.c) }, fmi2Status::fmi2Error);
        let lines = toy.take();
        assert!(lines[0].2.starts_with(said), "{lines:?}");
        unsafe { fmi2::reset::<Toy>(toy.c) };
    }
    assert_eq!(
        unsafe { fmi2::without_saved_states::<Toy>(toy.c, Call::GetFMUstate) },
        fmi2Status::fmi2Error
    );
    assert!(toy.take()[0]
        .2
        .starts_with("fmi2GetFMUstate: not supported: canGetAndSetFMUstate=\"false\""));
}

#[test]
fn saved_states_round_trip_through_their_handles_and_bytes() {
    let toy = Instance::new(GUID, None, false);
    unsafe { fmi2::set_real::<Toy>(toy.c, &0, 1, &4.5) };
    toy.initialized();
    assert_eq!(
        unsafe { fmi2::do_step::<Toy>(toy.c, 0.0, 2.0) },
        fmi2Status::fmi2OK
    );
    let mut state: fmi2FMUstate = ptr::null_mut();
    assert_eq!(
        unsafe { fmi2::get_fmu_state::<Toy>(toy.c, &mut state) },
        fmi2Status::fmi2OK
    );
    let mut size = 0;
    assert_eq!(
        unsafe { fmi2::serialized_fmu_state_size::<Toy>(toy.c, state, &mut size) },
        fmi2Status::fmi2OK
    );
    let mut bytes = vec![0 as fmi2Byte; size];
    assert_eq!(
        unsafe { fmi2::serialize_fmu_state::<Toy>(toy.c, state, bytes.as_mut_ptr(), size - 1) },
        fmi2Status::fmi2Error,
        "a buffer too small"
    );
    unsafe { fmi2::reset::<Toy>(toy.c) };
    assert_eq!(
        unsafe { fmi2::serialize_fmu_state::<Toy>(toy.c, state, bytes.as_mut_ptr(), size) },
        fmi2Status::fmi2OK
    );
    let mut copy: fmi2FMUstate = ptr::null_mut();
    assert_eq!(
        unsafe { fmi2::deserialize_fmu_state::<Toy>(toy.c, bytes.as_ptr(), size, &mut copy) },
        fmi2Status::fmi2OK
    );
    // The reset instance takes the state: its time, its x and the state machine's state.
    assert_eq!(
        unsafe { fmi2::set_fmu_state::<Toy>(toy.c, copy) },
        fmi2Status::fmi2OK
    );
    assert_eq!(toy.state(), Some(MachineState::StepComplete));
    let mut x = 0.0;
    unsafe { fmi2::get_real::<Toy>(toy.c, &0, 1, &mut x) };
    assert_eq!(x, 4.5);
    assert_eq!(
        unsafe { fmi2::do_step::<Toy>(toy.c, 2.0, 1.0) },
        fmi2Status::fmi2OK
    );
    for handle in [&mut state, &mut copy] {
        assert_eq!(
            unsafe { fmi2::free_fmu_state::<Toy>(toy.c, handle) },
            fmi2Status::fmi2OK
        );
        assert!(handle.is_null());
    }
    assert_eq!(
        unsafe { fmi2::set_fmu_state::<Toy>(toy.c, ptr::null_mut()) },
        fmi2Status::fmi2Error
    );
    assert_eq!(
        toy.take().last().unwrap().2,
        "fmi2SetFMUstate: FMUstate is NULL"
    );
}
