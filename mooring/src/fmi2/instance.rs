//! One instance of the mooring FMU: its FMI state, parameters, inputs and outputs, and the
//! lines it drives: MoorDyn's dynamic lines or the quasi-static catenaries
//! (`mooringModel`).
//!
//! Coupling per communication step (`fmi2DoStep(t, h)`): the fairleads move from the
//! inputs' position at t along their velocity (MoorDyn's coupled-body kinematics are linear
//! over a call) and the outputs become the line force at t + h: MoorDyn advances its lines
//! from t to t + h; the quasi-static lines are in equilibrium at the position reached,
//! q + h qdot. An input set after a step therefore reaches the outputs only through the
//! next step (`dependencies=""`). At initialisation the lines are in static equilibrium at
//! the inputs' position (MoorDyn_Init, or the catenaries), and the outputs are their force
//! there: the lines are made when an output is first read in initialisation mode or at
//! `fmi2ExitInitializationMode`, and made again if an input or a parameter changed since.

use super::logger::Logger;
use super::machine::{Call, MachineState};
use super::variables::{
    Real, DEFAULT_MOORING, DYNAMIC, INPUTS, MOORING_FILE, MOORING_MODEL, OUTPUTS, QUASI_STATIC,
};
use crate::moordyn::{Library, System};
use crate::planar::{body6, planar_force};
use crate::quasi_static::QuasiStatic;
use std::ffi::{c_char, CString};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// `currentCommunicationPoint` must match the instance's time within this, relative to
/// max(1, |t|).
const TIME_TOLERANCE: f64 = 1e-9;

/// The lines of one instance, as `mooringModel` chose.
enum Lines {
    Dynamic(System),
    QuasiStatic(QuasiStatic),
}

pub struct Instance {
    pub logger: Logger,
    state: MachineState,
    library: Arc<Library>,
    /// The unpacked FMU's `resources` folder.
    resources: PathBuf,
    mooring_file: String,
    mooring_model: i32,
    time: f64,
    inputs: [f64; INPUTS.len()],
    outputs: [f64; OUTPUTS.len()],
    lines: Option<Lines>,
    /// The inputs, file and model the lines were made for, while in initialisation mode.
    made_for: Option<([f64; INPUTS.len()], String, i32)>,
    /// The last String handed to the host by `fmi2GetString`.
    string_out: CString,
}

impl Instance {
    pub fn new(logger: Logger, library: Library, resources: PathBuf) -> Instance {
        Instance {
            logger,
            state: MachineState::Instantiated,
            library: Arc::new(library),
            resources,
            mooring_file: String::new(),
            mooring_model: DYNAMIC,
            time: 0.0,
            inputs: [0.0; INPUTS.len()],
            outputs: [0.0; OUTPUTS.len()],
            lines: None,
            made_for: None,
            string_out: CString::default(),
        }
    }

    /// Whether `call` is allowed in the current state; an error naming both otherwise.
    pub fn check(&self, call: Call) -> Result<(), String> {
        if call.allowed() & (1 << self.state.code()) != 0 {
            Ok(())
        } else {
            Err(format!(
                "illegal call sequence: {} is not allowed in state {:?}",
                call.name(),
                self.state
            ))
        }
    }

    /// After a failed call: the instance is unusable until reset or freed.
    pub fn fail(&mut self) {
        self.state = MachineState::Error;
    }

    pub fn setup_experiment(&mut self, start_time: f64) -> Result<(), String> {
        if !start_time.is_finite() {
            return Err(format!("startTime = {start_time} must be finite"));
        }
        self.time = start_time;
        Ok(())
    }

    pub fn enter_initialization_mode(&mut self) {
        self.state = MachineState::InitializationMode;
    }

    pub fn exit_initialization_mode(&mut self) -> Result<(), String> {
        self.make_lines()?;
        self.made_for = None;
        self.state = MachineState::StepComplete;
        Ok(())
    }

    pub fn terminate(&mut self) {
        self.state = MachineState::Terminated;
    }

    /// As freshly instantiated: start values, no lines.
    pub fn reset(&mut self) {
        self.lines = None;
        self.made_for = None;
        self.mooring_file.clear();
        self.mooring_model = DYNAMIC;
        self.time = 0.0;
        self.inputs = [0.0; INPUTS.len()];
        self.outputs = [0.0; OUTPUTS.len()];
        self.state = MachineState::Instantiated;
    }

    pub fn set_real(&mut self, vr: u32, value: f64) -> Result<(), String> {
        match Real::of(vr) {
            Some(Real::Input(i)) if value.is_finite() => {
                self.inputs[i] = value;
                Ok(())
            }
            Some(Real::Input(i)) => Err(format!("{} = {value} must be finite", INPUTS[i])),
            Some(Real::Output(i)) => Err(format!("{} is an output: it cannot be set", OUTPUTS[i])),
            None => Err(format!("no Real variable has value reference {vr}")),
        }
    }

    pub fn get_real(&mut self, vr: u32) -> Result<f64, String> {
        match Real::of(vr) {
            Some(Real::Input(i)) => Ok(self.inputs[i]),
            Some(Real::Output(i)) => {
                if self.state == MachineState::InitializationMode {
                    self.make_lines()?;
                }
                Ok(self.outputs[i])
            }
            None => Err(format!("no Real variable has value reference {vr}")),
        }
    }

    /// Parameters are fixed: settable until `fmi2ExitInitializationMode`.
    fn check_parameter(&self, name: &str) -> Result<(), String> {
        if matches!(
            self.state,
            MachineState::Instantiated | MachineState::InitializationMode
        ) {
            Ok(())
        } else {
            Err(format!(
                "{name} is a fixed parameter: set it before fmi2ExitInitializationMode"
            ))
        }
    }

    pub fn set_integer(&mut self, vr: u32, value: i32) -> Result<(), String> {
        if vr != MOORING_MODEL {
            return Err(format!("no Integer variable has value reference {vr}"));
        }
        self.check_parameter("mooringModel")?;
        if value != DYNAMIC && value != QUASI_STATIC {
            return Err(format!(
                "invalid FMU parameter mooringModel = {value}: must be {DYNAMIC} (dynamic, \
                 MoorDyn's lines) or {QUASI_STATIC} (quasi-static catenaries)"
            ));
        }
        self.mooring_model = value;
        Ok(())
    }

    pub fn get_integer(&self, vr: u32) -> Result<i32, String> {
        if vr == MOORING_MODEL {
            Ok(self.mooring_model)
        } else {
            Err(format!("no Integer variable has value reference {vr}"))
        }
    }

    pub fn set_string(&mut self, vr: u32, value: &str) -> Result<(), String> {
        if vr != MOORING_FILE {
            return Err(format!("no String variable has value reference {vr}"));
        }
        self.check_parameter("mooringFile")?;
        if value.contains('\0') {
            return Err("mooringFile contains a NUL byte".into());
        }
        self.mooring_file = value.to_string();
        Ok(())
    }

    /// The String variable `vr` as C text, valid until the instance's next call.
    pub fn get_string(&mut self, vr: u32) -> Result<*const c_char, String> {
        if vr != MOORING_FILE {
            return Err(format!("no String variable has value reference {vr}"));
        }
        // set_string refuses NUL bytes, so the value converts.
        self.string_out = CString::new(self.mooring_file.as_str()).map_err(|e| e.to_string())?;
        Ok(self.string_out.as_ptr())
    }

    /// The input file: `mooringFile`, or the FMU's default mooring.
    fn input_file(&self) -> PathBuf {
        if self.mooring_file.is_empty() {
            self.resources.join(DEFAULT_MOORING)
        } else {
            PathBuf::from(&self.mooring_file)
        }
    }

    /// Makes the lines at the inputs' position (unless they were made for the same inputs,
    /// file and model) and sets the outputs to their static force.
    fn make_lines(&mut self) -> Result<(), String> {
        let key = (self.inputs, self.mooring_file.clone(), self.mooring_model);
        if self.lines.is_some() && self.made_for.as_ref() == Some(&key) {
            return Ok(());
        }
        self.lines = None;
        let input = self.input_file();
        let lines = if self.mooring_model == QUASI_STATIC {
            let lines = QuasiStatic::read(&input)
                .map_err(|e| with_parameter(&self.mooring_file, &input, e))?;
            let q = [self.inputs[0], self.inputs[1], self.inputs[2]];
            self.set_quasi_static_outputs(&lines, q)?;
            Lines::QuasiStatic(lines)
        } else {
            let (x, xd) = self.kinematics();
            let mut system = System::new(Arc::clone(&self.library), &input, x, xd)
                .map_err(|e| with_parameter(&self.mooring_file, &input, e))?;
            let force = system.step(x, xd, self.time, 0.0)?;
            self.set_outputs(&system, force)?;
            Lines::Dynamic(system)
        };
        self.lines = Some(lines);
        self.made_for = Some(key);
        Ok(())
    }

    fn kinematics(&self) -> ([f64; 6], [f64; 6]) {
        let i = &self.inputs;
        (body6([i[0], i[1], i[2]]), body6([i[3], i[4], i[5]]))
    }

    fn set_outputs(&mut self, system: &System, force: [f64; 6]) -> Result<(), String> {
        let [fx, fy, mz] = planar_force(force);
        let tension = system.max_fairlead_tension()?;
        self.check_and_set([fx, fy, mz, tension], "MoorDyn")
    }

    /// The outputs: the quasi-static lines' force with the platform at q.
    fn set_quasi_static_outputs(&mut self, lines: &QuasiStatic, q: [f64; 3]) -> Result<(), String> {
        let f = lines.force(q)?;
        let [fx, fy, mz] = f.planar;
        self.check_and_set([fx, fy, mz, f.max_tension], "the quasi-static lines")
    }

    fn check_and_set(&mut self, outputs: [f64; OUTPUTS.len()], from: &str) -> Result<(), String> {
        if let Some(i) = outputs.iter().position(|v| !v.is_finite()) {
            return Err(format!(
                "{from} returned {} = {} at t = {} s",
                OUTPUTS[i], outputs[i], self.time
            ));
        }
        self.outputs = outputs;
        Ok(())
    }

    pub fn do_step(&mut self, t: f64, h: f64) -> Result<(), String> {
        if !(h.is_finite() && h > 0.0) {
            return Err(format!("communicationStepSize = {h} must be positive"));
        }
        if !t.is_finite() || (t - self.time).abs() > TIME_TOLERANCE * self.time.abs().max(1.0) {
            return Err(format!(
                "currentCommunicationPoint = {t} is not the instance's time {}",
                self.time
            ));
        }
        let mut lines = self.lines.take().ok_or("no mooring lines")?;
        let result = match &mut lines {
            Lines::Dynamic(system) => {
                let (x, xd) = self.kinematics();
                system
                    .step(x, xd, t, h)
                    .map_err(|e| format!("{e} in the step from t = {t} s"))
                    .and_then(|force| self.set_outputs(system, force))
            }
            Lines::QuasiStatic(quasi_static) => {
                // The position the fairleads reach at t + h, as MoorDyn moves them.
                let i = self.inputs;
                let q = [i[0] + h * i[3], i[1] + h * i[4], i[2] + h * i[5]];
                self.set_quasi_static_outputs(quasi_static, q)
                    .map_err(|e| format!("{e} in the step from t = {t} s"))
            }
        };
        self.lines = Some(lines);
        result?;
        self.time = t + h;
        Ok(())
    }

    pub fn time(&self) -> f64 {
        self.time
    }
}

/// A MoorDyn error, naming the parameter when the user set the file.
fn with_parameter(parameter: &str, input: &Path, e: String) -> String {
    if parameter.is_empty() {
        format!("the FMU's default mooring ({}): {e}", input.display())
    } else {
        format!("invalid FMU parameter mooringFile = {parameter}: {e}")
    }
}
