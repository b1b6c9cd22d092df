//! One instance of the mooring FMU: its FMI state, parameter, inputs and outputs, and the
//! MoorDyn system it drives.
//!
//! Coupling per communication step (`fmi2DoStep(t, h)`): MoorDyn advances its lines from t
//! to t + h while it moves the fairleads from the inputs' position at t along their velocity
//! (its coupled-body kinematics are linear over a call), and the outputs become the line
//! force at t + h. An input set after a step therefore reaches the outputs only through the
//! next step (`dependencies=""`). At initialisation the lines are brought to static
//! equilibrium (MoorDyn_Init) at the inputs' position, and the outputs are their force there:
//! the system is made when an output is first read in initialisation mode or at
//! `fmi2ExitInitializationMode`, and made again if an input or the parameter changed since.

use super::logger::Logger;
use super::machine::{Call, MachineState};
use super::variables::{Real, DEFAULT_MOORING, INPUTS, MOORING_FILE, OUTPUTS};
use crate::moordyn::{Library, System};
use crate::planar::{body6, planar_force};
use std::ffi::{c_char, CString};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// `currentCommunicationPoint` must match the instance's time within this, relative to
/// max(1, |t|).
const TIME_TOLERANCE: f64 = 1e-9;

pub struct Instance {
    pub logger: Logger,
    state: MachineState,
    library: Arc<Library>,
    /// The unpacked FMU's `resources` folder.
    resources: PathBuf,
    mooring_file: String,
    time: f64,
    inputs: [f64; INPUTS.len()],
    outputs: [f64; OUTPUTS.len()],
    system: Option<System>,
    /// The inputs and file the system was initialised with, while in initialisation mode.
    made_for: Option<([f64; INPUTS.len()], String)>,
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
            time: 0.0,
            inputs: [0.0; INPUTS.len()],
            outputs: [0.0; OUTPUTS.len()],
            system: None,
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
        self.make_system()?;
        self.made_for = None;
        self.state = MachineState::StepComplete;
        Ok(())
    }

    pub fn terminate(&mut self) {
        self.state = MachineState::Terminated;
    }

    /// As freshly instantiated: start values, no system.
    pub fn reset(&mut self) {
        self.system = None;
        self.made_for = None;
        self.mooring_file.clear();
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
                    self.make_system()?;
                }
                Ok(self.outputs[i])
            }
            None => Err(format!("no Real variable has value reference {vr}")),
        }
    }

    pub fn set_string(&mut self, vr: u32, value: &str) -> Result<(), String> {
        if vr != MOORING_FILE {
            return Err(format!("no String variable has value reference {vr}"));
        }
        if !matches!(
            self.state,
            MachineState::Instantiated | MachineState::InitializationMode
        ) {
            return Err("mooringFile is a fixed parameter: set it before \
                        fmi2ExitInitializationMode"
                .into());
        }
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

    /// Makes the MoorDyn system at the inputs' position (unless it was made for the same
    /// inputs and file) and sets the outputs to its static force.
    fn make_system(&mut self) -> Result<(), String> {
        let key = (self.inputs, self.mooring_file.clone());
        if self.system.is_some() && self.made_for.as_ref() == Some(&key) {
            return Ok(());
        }
        self.system = None;
        let (x, xd) = self.kinematics();
        let input = self.input_file();
        let mut system = System::new(Arc::clone(&self.library), &input, x, xd)
            .map_err(|e| with_parameter(&self.mooring_file, &input, e))?;
        let force = system.step(x, xd, self.time, 0.0)?;
        self.set_outputs(&system, force)?;
        self.system = Some(system);
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
        let outputs = [fx, fy, mz, tension];
        if let Some(i) = outputs.iter().position(|v| !v.is_finite()) {
            return Err(format!(
                "MoorDyn returned {} = {} at t = {} s",
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
        let (x, xd) = self.kinematics();
        let mut system = self.system.take().ok_or("no MoorDyn system")?;
        let result = system
            .step(x, xd, t, h)
            .map_err(|e| format!("{e} in the step from t = {t} s"))
            .and_then(|force| self.set_outputs(&system, force));
        self.system = Some(system);
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
