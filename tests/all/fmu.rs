//! Drives the exported `fmi2*` functions in-process, as a C master would, with a logger
//! that records every message per instance; and the independent route for the expected
//! values: a native [`Simulation`] built from a [`Problem`] written here field by field.
#![allow(dead_code)] // each test binary uses a different subset

use slowdrift::fmi2::exports::*;
use slowdrift::fmi2::model_description::{vr, Causality, GUID, VARIABLES};
use slowdrift::fmi2::resources::write_resources;
use slowdrift::fmi2::types::*;
use slowdrift::problem::default_problem;
use slowdrift::{Outputs, Problem, Simulation};
use std::ffi::{c_char, c_void, CStr, CString};
use std::ptr;
use std::sync::{Mutex, OnceLock};

/// The embedded default, computed once per test binary (the column solver takes about 1 s).
pub fn default_platform() -> &'static Problem {
    static DEFAULT: OnceLock<Problem> = OnceLock::new();
    DEFAULT.get_or_init(|| default_problem().unwrap())
}

/// A `resources` folder as fmu-pack writes it (the default with its drift precomputed),
/// made once per test binary, as a file URI.
pub fn packed_resources() -> &'static str {
    static URI: OnceLock<String> = OnceLock::new();
    URI.get_or_init(|| {
        let dir =
            std::env::temp_dir().join(format!("slowdrift-fmu-resources-{}", std::process::id()));
        write_resources(&dir).unwrap();
        format!("file://{}", dir.display())
    })
}

/// One message the FMU sent to the logger.
#[derive(Debug, Clone)]
pub struct Entry {
    pub name: String,
    pub status: fmi2Status,
    pub category: String,
    /// The message as the printf format the FMU passed (`%` doubled).
    pub raw: String,
    /// The message as printf would print it.
    pub message: String,
}

/// The messages of one instance (its componentEnvironment points here).
pub type Log = Mutex<Vec<Entry>>;

/// The test's logger. The FMU passes the message as the printf format (every `%` doubled)
/// and no variadic arguments, so a callee with the five fixed parameters reads it directly;
/// on the SysV x86-64 and AAPCS64 (Linux) ABIs a variadic call with only fixed arguments
/// passes them exactly as a non-variadic call does.
unsafe extern "C" fn record(
    env: *mut c_void,
    name: *const c_char,
    status: fmi2Status,
    category: *const c_char,
    message: *const c_char,
) {
    let text = |p: *const c_char| unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned();
    assert!(!category.is_null() && !name.is_null() && !message.is_null());
    let log = unsafe { &*(env as *const Log) };
    log.lock().unwrap().push(Entry {
        name: text(name),
        status,
        category: text(category),
        raw: text(message),
        message: text(message).replace("%%", "%"),
    });
}

/// The callbacks with [`record`] as the logger and `log` as the environment.
pub fn callbacks(log: &Log) -> fmi2CallbackFunctions {
    type Fixed =
        unsafe extern "C" fn(*mut c_void, *const c_char, fmi2Status, *const c_char, *const c_char);
    // SAFETY: see `record`: same ABI for a call with the five fixed arguments only.
    let logger = unsafe { std::mem::transmute::<Fixed, fmi2CallbackLogger>(record) };
    fmi2CallbackFunctions {
        logger: Some(logger),
        allocateMemory: None,
        freeMemory: None,
        stepFinished: None,
        componentEnvironment: log as *const Log as *mut c_void,
    }
}

/// Every output value reference, in the XML's order.
pub fn output_vrs() -> Vec<u32> {
    VARIABLES
        .iter()
        .filter(|v| v.causality == Causality::Output)
        .map(|v| v.value_reference)
        .collect()
}

/// The outputs of a native simulation in the order of [`output_vrs`], by variable name.
pub fn native_outputs(o: &Outputs) -> Vec<f64> {
    VARIABLES
        .iter()
        .filter(|v| v.causality == Causality::Output)
        .map(|v| match v.name {
            "X" => o.position[0],
            "Y" => o.position[1],
            "theta" => o.position[2],
            "Xdot" => o.velocity[0],
            "Ydot" => o.velocity[1],
            "thetadot" => o.velocity[2],
            "eta" => o.wave_elevation,
            "Fx_wave" => o.forces.wave[0],
            "Fy_wave" => o.forces.wave[1],
            "Mz_wave" => o.forces.wave[2],
            "Fx_damping" => o.forces.damping[0],
            "Fy_damping" => o.forces.damping[1],
            "Mz_damping" => o.forces.damping[2],
            "Fx_drag" => o.forces.drag[0],
            "Fy_drag" => o.forces.drag[1],
            "Mz_drag" => o.forces.drag[2],
            "X_wf" => o.motion.wave_frequency[0],
            "Y_wf" => o.motion.wave_frequency[1],
            "Z_wf" => o.motion.wave_frequency[2],
            "roll_wf" => o.motion.wave_frequency[3],
            "pitch_wf" => o.motion.wave_frequency[4],
            "yaw_wf" => o.motion.wave_frequency[5],
            "X_total" => o.motion.total[0],
            "Y_total" => o.motion.total[1],
            "Z_total" => o.motion.total[2],
            "roll_total" => o.motion.total[3],
            "pitch_total" => o.motion.total[4],
            "yaw_total" => o.motion.total[5],
            "Xdot_total" => o.motion.total_rate[0],
            "Ydot_total" => o.motion.total_rate[1],
            "Zdot_total" => o.motion.total_rate[2],
            "rolldot_total" => o.motion.total_rate[3],
            "pitchdot_total" => o.motion.total_rate[4],
            "yawdot_total" => o.motion.total_rate[5],
            "windVelocity" => o.wind_speed,
            "Fx_wind" => o.forces.wind[0],
            "Fy_wind" => o.forces.wind[1],
            "Mz_wind" => o.forces.wind[2],
            other => panic!("unknown output {other}"),
        })
        .collect()
}

/// The native configuration of the embedded default with a seed, a wave direction and a
/// run, as the FMU parameters and `fmi2SetupExperiment` describe them.
pub fn native_problem(seed: u64, direction: f64, start: f64, stop: f64) -> Problem {
    let mut c = default_platform().clone();
    c.sea.seed = seed;
    c.sea.mean_direction = direction;
    c.run.start_time = start;
    c.run.duration = stop - start;
    c
}

pub fn native(seed: u64, direction: f64, start: f64, stop: f64) -> Simulation {
    Simulation::new(native_problem(seed, direction, start, stop)).unwrap()
}

/// Bit patterns, so that comparisons are exact and NaN-safe.
pub fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// An external force that varies from step to step.
pub fn external(n: usize) -> [f64; 3] {
    let s = n as f64 * 0.037;
    [
        2.0e5 * s.sin(),
        -1.5e5 * (0.7 * s).cos(),
        3.0e7 * (1.3 * s).sin(),
    ]
}

pub const INPUTS: [u32; 3] = [vr::FX_EXT, vr::FY_EXT, vr::MZ_EXT];

/// One instance and its log. Freed on drop.
pub struct Fmu {
    pub c: fmi2Component,
    pub log: Box<Log>,
}

impl Fmu {
    /// A co-simulation instance with logging on and the packed default's resources.
    pub fn new(name: &str) -> Fmu {
        Fmu::with_resources(name, Some(packed_resources()))
    }

    pub fn with_resources(name: &str, resources: Option<&str>) -> Fmu {
        Fmu::instantiate(name, resources, true)
    }

    pub fn instantiate(name: &str, resources: Option<&str>, logging_on: bool) -> Fmu {
        let log: Box<Log> = Box::default();
        let functions = callbacks(&log);
        let name = CString::new(name).unwrap();
        let guid = CString::new(GUID).unwrap();
        let resources = resources.map(|r| CString::new(r).unwrap());
        let c = unsafe {
            fmi2Instantiate(
                name.as_ptr(),
                fmi2Type::fmi2CoSimulation,
                guid.as_ptr(),
                resources.as_ref().map_or(ptr::null(), |r| r.as_ptr()),
                &functions,
                fmi2False,
                if logging_on { fmi2True } else { fmi2False },
            )
        };
        assert!(!c.is_null(), "{:?}", log.lock().unwrap());
        Fmu { c, log }
    }

    /// Instantiated, parameters set, initialised: ready to step at `start`.
    pub fn running(name: &str, seed: i32, direction: f64, start: f64, stop: Option<f64>) -> Fmu {
        let fmu = Fmu::new(name);
        assert_eq!(fmu.setup(start, stop), fmi2Status::fmi2OK);
        assert_eq!(fmu.set_int(vr::SEED, seed), fmi2Status::fmi2OK);
        assert_eq!(
            fmu.set_real(vr::WAVE_DIRECTION, direction),
            fmi2Status::fmi2OK
        );
        assert_eq!(fmu.init(), fmi2Status::fmi2OK, "{}", fmu.messages());
        fmu
    }

    pub fn setup(&self, start: f64, stop: Option<f64>) -> fmi2Status {
        unsafe {
            fmi2SetupExperiment(
                self.c,
                fmi2False,
                0.0,
                start,
                if stop.is_some() { fmi2True } else { fmi2False },
                stop.unwrap_or(0.0),
            )
        }
    }

    pub fn init(&self) -> fmi2Status {
        let s = unsafe { fmi2EnterInitializationMode(self.c) };
        if s != fmi2Status::fmi2OK {
            return s;
        }
        unsafe { fmi2ExitInitializationMode(self.c) }
    }

    pub fn set_real(&self, vr: u32, value: f64) -> fmi2Status {
        unsafe { fmi2SetReal(self.c, &vr, 1, &value) }
    }

    pub fn set_reals(&self, vrs: &[u32], values: &[f64]) -> fmi2Status {
        assert_eq!(vrs.len(), values.len());
        unsafe { fmi2SetReal(self.c, vrs.as_ptr(), vrs.len(), values.as_ptr()) }
    }

    pub fn set_int(&self, vr: u32, value: i32) -> fmi2Status {
        unsafe { fmi2SetInteger(self.c, &vr, 1, &value) }
    }

    pub fn set_string(&self, vr: u32, value: &str) -> fmi2Status {
        let s = CString::new(value).unwrap();
        let p = s.as_ptr();
        unsafe { fmi2SetString(self.c, &vr, 1, &p) }
    }

    pub fn get_reals(&self, vrs: &[u32]) -> (fmi2Status, Vec<f64>) {
        let mut values = vec![f64::NAN; vrs.len()];
        let s = unsafe { fmi2GetReal(self.c, vrs.as_ptr(), vrs.len(), values.as_mut_ptr()) };
        (s, values)
    }

    /// Every output; panics unless fmi2OK.
    pub fn outputs(&self) -> Vec<f64> {
        let (s, v) = self.get_reals(&output_vrs());
        assert_eq!(s, fmi2Status::fmi2OK, "{}", self.messages());
        v
    }

    pub fn step(&self, t: f64, h: f64) -> fmi2Status {
        unsafe { fmi2DoStep(self.c, t, h, fmi2False) }
    }

    /// Sets the inputs and steps; panics unless fmi2OK.
    pub fn step_with(&self, t: f64, h: f64, inputs: [f64; 3]) {
        assert_eq!(self.set_reals(&INPUTS, &inputs), fmi2Status::fmi2OK);
        assert_eq!(self.step(t, h), fmi2Status::fmi2OK, "{}", self.messages());
    }

    pub fn last_successful_time(&self) -> (fmi2Status, f64) {
        let mut t = f64::NAN;
        let s =
            unsafe { fmi2GetRealStatus(self.c, fmi2StatusKind::fmi2LastSuccessfulTime, &mut t) };
        (s, t)
    }

    pub fn terminated(&self) -> (fmi2Status, bool) {
        let mut b = -1;
        let s = unsafe { fmi2GetBooleanStatus(self.c, fmi2StatusKind::fmi2Terminated, &mut b) };
        (s, b == fmi2True)
    }

    /// A copy of the messages.
    pub fn entries(&self) -> Vec<Entry> {
        self.log.lock().unwrap().clone()
    }

    /// The messages as one text, for assertion output.
    pub fn messages(&self) -> String {
        self.entries()
            .iter()
            .map(|e| format!("[{:?} {}] {}", e.status, e.category, e.message))
            .collect::<Vec<_>>()
            .join("\n")
    }

    /// The last message; panics if there is none.
    pub fn last_message(&self) -> Entry {
        self.entries().last().cloned().expect("a log message")
    }

    pub fn clear_log(&self) {
        self.log.lock().unwrap().clear();
    }
}

/// `fmi2GetFMUstate`; panics unless fmi2OK.
pub fn get_state(fmu: &Fmu) -> fmi2FMUstate {
    let mut state: fmi2FMUstate = ptr::null_mut();
    assert_eq!(
        unsafe { fmi2GetFMUstate(fmu.c, &mut state) },
        fmi2Status::fmi2OK
    );
    assert!(!state.is_null());
    state
}

/// `fmi2FreeFMUstate`; panics unless fmi2OK and the pointer is NULL after.
pub fn free_state(fmu: &Fmu, mut state: fmi2FMUstate) {
    assert_eq!(
        unsafe { fmi2FreeFMUstate(fmu.c, &mut state) },
        fmi2Status::fmi2OK
    );
    assert!(state.is_null(), "FreeFMUstate sets the pointer to NULL");
}

/// `fmi2SerializedFMUstateSize` and `fmi2SerializeFMUstate`; panics unless fmi2OK.
pub fn serialize(fmu: &Fmu, state: fmi2FMUstate) -> Vec<u8> {
    let mut size = 0usize;
    assert_eq!(
        unsafe { fmi2SerializedFMUstateSize(fmu.c, state, &mut size) },
        fmi2Status::fmi2OK
    );
    let mut bytes = vec![0u8; size];
    let status = unsafe { fmi2SerializeFMUstate(fmu.c, state, bytes.as_mut_ptr().cast(), size) };
    assert_eq!(status, fmi2Status::fmi2OK);
    bytes
}

/// `fmi2DeSerializeFMUstate`: the status and the state (NULL unless fmi2OK).
pub fn deserialize(fmu: &Fmu, bytes: &[u8]) -> (fmi2Status, fmi2FMUstate) {
    let mut state: fmi2FMUstate = ptr::null_mut();
    let s =
        unsafe { fmi2DeSerializeFMUstate(fmu.c, bytes.as_ptr().cast(), bytes.len(), &mut state) };
    (s, state)
}

/// FNV-1a, 64 bits: the checksum at the end of a serialized FMU state (docs/fmu.md),
/// written out here.
pub fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ b as u64).wrapping_mul(0x0100_0000_01b3)
    })
}

/// Rewrites the checksum of serialized state bytes after a change, so that the check
/// behind it answers.
pub fn reseal(bytes: &mut [u8]) {
    let n = bytes.len() - 8;
    let sum = fnv1a(&bytes[..n]);
    bytes[n..].copy_from_slice(&sum.to_le_bytes());
}

impl Drop for Fmu {
    fn drop(&mut self) {
        unsafe { fmi2FreeInstance(self.c) };
    }
}

// Instances are used by one thread at a time; the log is a Mutex.
unsafe impl Send for Fmu {}
