//! SlowDrift's FMI 3.0 functions through its C ABI, in-process (`slowdrift::fmi2::
//! exports_fmi3`), against the FMI 2.0 functions of the same library: the same parameters,
//! inputs and steps give every output bit for bit; a state saved, serialized, deserialized
//! and restored in a fresh instance continues bit for bit; and the misuse of FMI 3.0
//! section 2.3 (calls out of their state, NULL pointers, unknown value references, nValues
//! that are not the value references' count, the independent variable set) answers
//! `fmi3Error` with a log line, as the standard says.

use crate::fmu::{bits, external, output_vrs, Fmu, INPUTS};
use slowdrift::fmi2::exports_fmi3::*;
use slowdrift::fmi2::model_description::{vr, GUID};
use slowdrift::fmi2::types::fmi2Status;
use slowdrift_fmi::fmi3::types::*;
use slowdrift_fmi::fmi3::TIME_VALUE_REFERENCE;
use std::ffi::{c_void, CStr, CString};
use std::ptr;
use std::sync::Mutex;

/// The messages of one instance: (status, category, message).
type Log = Mutex<Vec<(fmi3Status, String, String)>>;

unsafe extern "C" fn record(
    env: fmi3InstanceEnvironment,
    status: fmi3Status,
    category: fmi3String,
    message: fmi3String,
) {
    let text = |p: *const i8| unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned();
    let log = unsafe { &*(env as *const Log) };
    log.lock()
        .unwrap()
        .push((status, text(category), text(message)));
}

/// One FMI 3.0 instance and its log.
struct Fmu3 {
    instance: fmi3Instance,
    log: Box<Log>,
}

impl Drop for Fmu3 {
    fn drop(&mut self) {
        unsafe { fmi3FreeInstance(self.instance) };
    }
}

impl Fmu3 {
    /// Instantiated with the library's token and no resources (the embedded default).
    fn new(name: &str) -> Fmu3 {
        Self::instantiate(name, GUID, false).expect("instantiated")
    }

    fn instantiate(name: &str, token: &str, event_mode: bool) -> Result<Fmu3, String> {
        let log: Box<Log> = Box::new(Mutex::new(Vec::new()));
        let (name, token) = (CString::new(name).unwrap(), CString::new(token).unwrap());
        let instance = unsafe {
            fmi3InstantiateCoSimulation(
                name.as_ptr(),
                token.as_ptr(),
                ptr::null(),
                false,
                false,
                event_mode,
                false,
                ptr::null(),
                0,
                &*log as *const Log as *mut c_void,
                Some(record),
                None,
            )
        };
        if instance.is_null() {
            let last = log.lock().unwrap().last().map(|e| e.2.clone());
            return Err(last.unwrap_or_default());
        }
        Ok(Fmu3 { instance, log })
    }

    fn last_message(&self) -> String {
        self.log
            .lock()
            .unwrap()
            .last()
            .map(|e| e.2.clone())
            .unwrap_or_default()
    }

    fn init(&self, stop: Option<f64>) -> fmi3Status {
        let s = unsafe {
            fmi3EnterInitializationMode(
                self.instance,
                false,
                0.0,
                0.0,
                stop.is_some(),
                stop.unwrap_or(0.0),
            )
        };
        if s != fmi3Status::fmi3OK {
            return s;
        }
        unsafe { fmi3ExitInitializationMode(self.instance) }
    }

    fn set_f64(&self, vrs: &[u32], values: &[f64]) -> fmi3Status {
        unsafe {
            fmi3SetFloat64(
                self.instance,
                vrs.as_ptr(),
                vrs.len(),
                values.as_ptr(),
                values.len(),
            )
        }
    }

    fn set_i32(&self, vrs: &[u32], values: &[i32]) -> fmi3Status {
        unsafe {
            fmi3SetInt32(
                self.instance,
                vrs.as_ptr(),
                vrs.len(),
                values.as_ptr(),
                values.len(),
            )
        }
    }

    fn get_f64(&self, vrs: &[u32]) -> (fmi3Status, Vec<f64>) {
        let mut values = vec![f64::NAN; vrs.len()];
        let s = unsafe {
            fmi3GetFloat64(
                self.instance,
                vrs.as_ptr(),
                vrs.len(),
                values.as_mut_ptr(),
                values.len(),
            )
        };
        (s, values)
    }

    /// Every output of the FMI 2.0 description (the same value references).
    fn outputs(&self) -> Vec<f64> {
        let (s, v) = self.get_f64(&output_vrs());
        assert_eq!(s, fmi3Status::fmi3OK, "{}", self.last_message());
        v
    }

    /// One step; (status, lastSuccessfulTime, the three flags).
    fn step(&self, t: f64, h: f64) -> (fmi3Status, f64, [bool; 3]) {
        let (mut event, mut terminate, mut early, mut last) = (true, true, true, f64::NAN);
        let s = unsafe {
            fmi3DoStep(
                self.instance,
                t,
                h,
                true,
                &mut event,
                &mut terminate,
                &mut early,
                &mut last,
            )
        };
        (s, last, [event, terminate, early])
    }

    fn saved_bytes(&self) -> Vec<u8> {
        let mut state: fmi3FMUState = ptr::null_mut();
        assert_eq!(
            unsafe { fmi3GetFMUState(self.instance, &mut state) },
            fmi3Status::fmi3OK
        );
        let mut size = 0;
        assert_eq!(
            unsafe { fmi3SerializedFMUStateSize(self.instance, state, &mut size) },
            fmi3Status::fmi3OK
        );
        let mut bytes = vec![0u8; size];
        assert_eq!(
            unsafe { fmi3SerializeFMUState(self.instance, state, bytes.as_mut_ptr(), size) },
            fmi3Status::fmi3OK
        );
        assert_eq!(
            unsafe { fmi3FreeFMUState(self.instance, &mut state) },
            fmi3Status::fmi3OK
        );
        assert!(state.is_null());
        bytes
    }

    fn restore(&self, bytes: &[u8]) -> fmi3Status {
        let mut state: fmi3FMUState = ptr::null_mut();
        let s = unsafe {
            fmi3DeserializeFMUState(self.instance, bytes.as_ptr(), bytes.len(), &mut state)
        };
        if s != fmi3Status::fmi3OK {
            return s;
        }
        let s = unsafe { fmi3SetFMUState(self.instance, state) };
        unsafe { fmi3FreeFMUState(self.instance, &mut state) };
        s
    }
}

/// The parameters both instances take: seed 3, an oblique sea, wind 15 m/s.
fn configure2(fmu: &Fmu) {
    assert_eq!(fmu.set_int(vr::SEED, 3), fmi2Status::fmi2OK);
    assert_eq!(fmu.set_real(vr::WAVE_DIRECTION, 0.4), fmi2Status::fmi2OK);
    assert_eq!(fmu.set_real(vr::WIND_SPEED, 15.0), fmi2Status::fmi2OK);
}

fn configure3(fmu: &Fmu3) {
    assert_eq!(fmu.set_i32(&[vr::SEED], &[3]), fmi3Status::fmi3OK);
    assert_eq!(
        fmu.set_f64(&[vr::WAVE_DIRECTION, vr::WIND_SPEED], &[0.4, 15.0]),
        fmi3Status::fmi3OK
    );
}

/// 300 steps of 1 s under a varying external force, with and without a stop time: every
/// output of the FMI 3.0 instance equals the FMI 2.0 instance's bit for bit at every
/// communication point; `lastSuccessfulTime` is the step's end and no flag is raised; the
/// independent variable `time` reads the instance's time.
#[test]
fn fmi3_runs_are_the_fmi2_runs_bit_for_bit() {
    for stop in [Some(300.0), None] {
        let two = Fmu::new("two");
        assert_eq!(two.setup(0.0, stop), fmi2Status::fmi2OK);
        configure2(&two);
        assert_eq!(two.init(), fmi2Status::fmi2OK, "{}", two.messages());
        let three = Fmu3::new("three");
        configure3(&three);
        assert_eq!(
            three.init(stop),
            fmi3Status::fmi3OK,
            "{}",
            three.last_message()
        );
        for n in 0..300 {
            let t = n as f64;
            assert_eq!(bits(&three.outputs()), bits(&two.outputs()), "t = {t} s");
            assert_eq!(three.get_f64(&[TIME_VALUE_REFERENCE]).1, [t]);
            two.step_with(t, 1.0, external(n));
            assert_eq!(three.set_f64(&INPUTS, &external(n)), fmi3Status::fmi3OK);
            let (s, last, flags) = three.step(t, 1.0);
            assert_eq!(s, fmi3Status::fmi3OK, "{}", three.last_message());
            assert_eq!((last, flags), (t + 1.0, [false; 3]));
        }
    }
}

/// A state saved at 100 s, serialized, deserialized and restored in a fresh FMI 3.0
/// instance continues as the saving instance does, bit for bit, for 50 steps; the bytes are
/// the FMI 2.0 format (an FMI 2.0 instance restores them too).
#[test]
fn fmi3_states_continue_in_a_fresh_instance() {
    let a = Fmu3::new("a");
    configure3(&a);
    assert_eq!(a.init(Some(200.0)), fmi3Status::fmi3OK);
    for n in 0..100 {
        a.set_f64(&INPUTS, &external(n));
        assert_eq!(a.step(n as f64, 1.0).0, fmi3Status::fmi3OK);
    }
    let bytes = a.saved_bytes();
    let b = Fmu3::new("b");
    assert_eq!(
        b.restore(&bytes),
        fmi3Status::fmi3OK,
        "{}",
        b.last_message()
    );
    let c = Fmu::new("c");
    assert_eq!(
        crate::fmi2_state::restore(&c, &bytes),
        Ok(()),
        "an FMI 2.0 instance takes the same bytes"
    );
    assert_eq!(bits(&b.outputs()), bits(&a.outputs()));
    assert_eq!(bits(&c.outputs()), bits(&a.outputs()));
    for n in 100..150 {
        let t = n as f64;
        for fmu in [&a, &b] {
            fmu.set_f64(&INPUTS, &external(n));
            assert_eq!(fmu.step(t, 1.0).0, fmi3Status::fmi3OK);
        }
        assert_eq!(bits(&b.outputs()), bits(&a.outputs()), "t = {t} s");
    }
}

/// Misuse answered with `fmi3Error` and a log line naming the call and why; the harmless
/// cases (nothing asked of a type without variables) with `fmi3OK`.
#[test]
fn fmi3_misuse_is_refused() {
    // Instantiation: another token, event mode asked for, the other interface types.
    let wrong = Fmu3::instantiate("x", "{not-this-fmu}", false)
        .err()
        .unwrap();
    assert!(wrong.contains("not-this-fmu"), "{wrong}");
    let events = Fmu3::instantiate("x", GUID, true).err().unwrap();
    assert!(events.contains("eventModeUsed"), "{events}");
    let me = fmi3InstantiateModelExchange(
        c"x".as_ptr(),
        ptr::null(),
        ptr::null(),
        false,
        false,
        ptr::null_mut(),
        None,
    );
    assert!(me.is_null());
    // NULL instance.
    assert_eq!(
        unsafe { fmi3Terminate(ptr::null_mut()) },
        fmi3Status::fmi3Error
    );
    // A step before initialisation.
    let fmu = Fmu3::new("misuse");
    assert_eq!(fmu.step(0.0, 1.0).0, fmi3Status::fmi3Error);
    assert!(
        fmu.last_message()
            .contains("fmi3DoStep is not allowed in state Instantiated"),
        "{}",
        fmu.last_message()
    );
    let fmu = Fmu3::new("misuse");
    assert_eq!(fmu.init(Some(10.0)), fmi3Status::fmi3OK);
    // nValues that is not the value references' count.
    let mut values = [0.0; 2];
    let s = unsafe { fmi3GetFloat64(fmu.instance, [vr::X].as_ptr(), 1, values.as_mut_ptr(), 2) };
    assert_eq!(s, fmi3Status::fmi3Error);
    assert!(
        fmu.last_message().contains("nValues = 2"),
        "{}",
        fmu.last_message()
    );
    for check in [
        // An unknown value reference.
        |f: &Fmu3| f.get_f64(&[123_456]).0,
        // The independent variable cannot be set.
        |f: &Fmu3| f.set_f64(&[TIME_VALUE_REFERENCE], &[5.0]),
        // A type without variables, asked for one.
        |f: &Fmu3| {
            let mut v = [0.0f32];
            unsafe { fmi3GetFloat32(f.instance, [0u32].as_ptr(), 1, v.as_mut_ptr(), 1) }
        },
        // Event mode.
        |f: &Fmu3| unsafe { fmi3EnterEventMode(f.instance) },
        // NULL output arguments of the step.
        |f: &Fmu3| unsafe {
            fmi3DoStep(
                f.instance,
                0.0,
                1.0,
                false,
                ptr::null_mut(),
                ptr::null_mut(),
                ptr::null_mut(),
                ptr::null_mut(),
            )
        },
    ] {
        let fmu = Fmu3::new("misuse");
        assert_eq!(fmu.init(Some(10.0)), fmi3Status::fmi3OK);
        assert_eq!(check(&fmu), fmi3Status::fmi3Error, "{}", fmu.last_message());
        assert!(
            fmu.log
                .lock()
                .unwrap()
                .iter()
                .any(|e| e.0 == fmi3Status::fmi3Error && e.1 == "logStatusError"),
            "an error line"
        );
    }
    // Nothing asked of a type without variables: nothing to do.
    let fmu = Fmu3::new("empty");
    assert_eq!(fmu.init(Some(10.0)), fmi3Status::fmi3OK);
    let s = unsafe { fmi3GetInt64(fmu.instance, ptr::null(), 0, ptr::null_mut(), 0) };
    assert_eq!(s, fmi3Status::fmi3OK);
    // A reset instance initialises again.
    assert_eq!(unsafe { fmi3Reset(fmu.instance) }, fmi3Status::fmi3OK);
    assert_eq!(fmu.init(Some(10.0)), fmi3Status::fmi3OK);
    assert_eq!(fmu.step(0.0, 1.0).0, fmi3Status::fmi3OK);
    assert_eq!(unsafe { fmi3Terminate(fmu.instance) }, fmi3Status::fmi3OK);
}

/// Logging by category through `fmi3SetDebugLogging`: with logging off no event line reaches
/// the host; with `logEvents` on, initialisation's event does (category and status OK); an
/// unknown category is refused with `fmi3Error`.
#[test]
fn fmi3_logging_by_category() {
    let quiet = Fmu3::new("quiet");
    assert_eq!(quiet.init(Some(10.0)), fmi3Status::fmi3OK);
    assert!(quiet.log.lock().unwrap().iter().all(|e| e.1 != "logEvents"));
    let loud = Fmu3::new("loud");
    let events = [c"logEvents".as_ptr()];
    assert_eq!(
        unsafe { fmi3SetDebugLogging(loud.instance, true, 1, events.as_ptr()) },
        fmi3Status::fmi3OK
    );
    assert_eq!(loud.init(Some(10.0)), fmi3Status::fmi3OK);
    assert!(
        loud.log
            .lock()
            .unwrap()
            .iter()
            .any(|e| e.0 == fmi3Status::fmi3OK
                && e.1 == "logEvents"
                && e.2.contains("initialized")),
        "{:?}",
        loud.log.lock().unwrap()
    );
    let unknown = [c"logNothingSuch".as_ptr()];
    assert_eq!(
        unsafe { fmi3SetDebugLogging(loud.instance, true, 1, unknown.as_ptr()) },
        fmi3Status::fmi3Error
    );
}
