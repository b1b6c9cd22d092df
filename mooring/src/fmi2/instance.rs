//! One instance of the mooring FMU: its FMI state, parameters, inputs and outputs, and the
//! lines it drives: MoorDyn's dynamic lines or the quasi-static catenaries
//! (`mooringModel`).
//!
//! The inputs are the platform's 6-DOF position and velocity, the outputs the lines' force
//! and moment and their fairlead tensions (frames and angles: [`crate::motion`]).
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
//!
//! This is the model of the shared FMI layer ([`Model`]): the layer checks each call against
//! the state machine, turns C pointers into the arguments here and reports every failure,
//! an [`Error`], with one status and log policy. A bad argument (an unknown value reference,
//! a non-finite input, a fixed parameter set late) is [`Error::Argument`]; what the lines
//! refuse (the file, MoorDyn, a catenary without solution, a file whose number of lines is
//! not the outputs' [`LINE_COUNT`]) is [`Error::Model`].

use super::variables::{
    Real, DEFAULT_MOORING, DYNAMIC, GUID, INPUTS, LINE_COUNT, MODEL_IDENTIFIER, MOORING_FILE,
    MOORING_MODEL, OUTPUTS, POSITION, QUASI_STATIC, VELOCITY,
};
use crate::moordyn::{this_library_dir, Library, System, LIBRARY_FILE};
use crate::motion::{HEAVE, PITCH, ROLL, SURGE, SWAY, YAW};
use crate::quasi_static::QuasiStatic;
use slowdrift_fmi::fmi2::machine::MachineState;
use slowdrift_fmi::fmi2::{Context, Instantiation, Model};
use slowdrift_fmi::text::c_text;
use slowdrift_fmi::Error;
use std::ffi::CString;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// `currentCommunicationPoint` must match the instance's time within this, relative to
/// max(1, |t|).
const TIME_TOLERANCE: f64 = 1e-9;
/// The longest communication step, s. Over a call the fairleads move along the inputs'
/// velocity in a straight line (MoorDyn's coupled-body kinematics), which a master's step of
/// a second or so keeps true; an hour is 90 000 of the default mooring's MoorDyn steps (0.04
/// s, a few seconds of work) and bounds the time one call may take (a step of 1e308 s would
/// never return).
const MAX_STEP: f64 = 3600.0;

/// The lines of one instance, as `mooringModel` chose.
enum Lines {
    Dynamic(System),
    QuasiStatic(QuasiStatic),
}

pub struct Instance {
    library: Arc<Library>,
    /// The unpacked FMU's `resources` folder.
    resources: PathBuf,
    mooring_file: String,
    mooring_model: i32,
    time: f64,
    inputs: [f64; INPUTS.len()],
    outputs: [f64; OUTPUTS.len()],
    /// Each line's fairlead tension (the outputs fairleadTension1, 2, ...).
    tensions: [f64; LINE_COUNT],
    lines: Option<Lines>,
    /// The inputs, file and model the lines were made for, while in initialisation mode.
    made_for: Option<([f64; INPUTS.len()], String, i32)>,
    /// The strings last handed to the host by `fmi2GetString`; valid until the next call.
    strings: Vec<CString>,
}

impl Model for Instance {
    const MODEL_IDENTIFIER: &'static str = MODEL_IDENTIFIER;
    const WITHOUT_RESOURCES: &'static str =
        "the resources folder beside the library (binaries/linux64/../../resources) is used";

    /// An instance with MoorDyn's library loaded from beside this library, and the
    /// resources of `fmuResourceLocation` (else those beside this library, where every
    /// master unpacks them).
    fn instantiate(instantiation: Instantiation<'_>) -> Result<Instance, Error> {
        let Instantiation {
            guid, resources, ..
        } = instantiation;
        if guid != GUID {
            return Err(Error::Argument(format!(
                "fmuGUID {guid} is not this FMU's {GUID}"
            )));
        }
        let dir = this_library_dir().map_err(Error::Model)?;
        let library = Library::load(&dir.join(LIBRARY_FILE)).map_err(Error::Model)?;
        let resources = match resources.or_else(|| resources_beside(&dir)) {
            Some(resources) => resources,
            None => {
                return Err(Error::Model(format!(
                    "{} has no resources folder above it",
                    dir.display()
                )))
            }
        };
        Ok(Instance {
            library: Arc::new(library),
            resources,
            mooring_file: String::new(),
            mooring_model: DYNAMIC,
            time: 0.0,
            inputs: [0.0; INPUTS.len()],
            outputs: [0.0; OUTPUTS.len()],
            tensions: [0.0; LINE_COUNT],
            lines: None,
            made_for: None,
            strings: Vec::new(),
        })
    }

    fn setup_experiment(&mut self, start_time: f64, _stop: Option<f64>) -> Result<(), Error> {
        if !start_time.is_finite() {
            return Err(Error::Argument(format!(
                "startTime = {start_time} must be finite"
            )));
        }
        self.time = start_time;
        Ok(())
    }

    fn exit_initialization_mode(&mut self, cx: &Context) -> Result<(), Error> {
        self.make_lines()?;
        self.made_for = None;
        cx.event("initialized: the lines in static equilibrium at the inputs' position");
        Ok(())
    }

    /// As freshly instantiated: start values, no lines.
    fn reset(&mut self) {
        self.lines = None;
        self.made_for = None;
        self.mooring_file.clear();
        self.mooring_model = DYNAMIC;
        self.time = 0.0;
        self.inputs = [0.0; INPUTS.len()];
        self.outputs = [0.0; OUTPUTS.len()];
        self.tensions = [0.0; LINE_COUNT];
    }

    /// Inputs, and outputs (in initialisation mode, the lines are made at the inputs'
    /// position to give them).
    fn get_real(&mut self, cx: &Context, vrs: &[u32], values: &mut [f64]) -> Result<(), Error> {
        for (&vr, value) in vrs.iter().zip(values) {
            let real = Real::of(vr).ok_or_else(|| no_variable("Real", vr))?;
            let output = !matches!(real, Real::Input(_));
            if output && cx.state() == MachineState::InitializationMode {
                self.make_lines()?;
            }
            *value = match real {
                Real::Input(i) => self.inputs[i],
                Real::Output(i) => self.outputs[i],
                Real::LineTension(i) => self.tensions[i],
            };
        }
        Ok(())
    }

    fn get_integer(&mut self, _cx: &Context, vrs: &[u32], values: &mut [i32]) -> Result<(), Error> {
        for (&vr, value) in vrs.iter().zip(values) {
            if vr != MOORING_MODEL {
                return Err(no_variable("Integer", vr));
            }
            *value = self.mooring_model;
        }
        Ok(())
    }

    /// This FMU has no Boolean variable: any value reference is unknown.
    fn get_boolean(&mut self, _cx: &Context, vrs: &[u32], _: &mut [i32]) -> Result<(), Error> {
        no_boolean(vrs)
    }

    fn get_string(&mut self, _cx: &Context, vrs: &[u32]) -> Result<&[CString], Error> {
        let mut strings = Vec::with_capacity(vrs.len());
        for &vr in vrs {
            if vr != MOORING_FILE {
                return Err(no_variable("String", vr));
            }
            strings.push(c_text(&self.mooring_file));
        }
        self.strings = strings;
        Ok(&self.strings)
    }

    /// The inputs: all values are checked before any is set.
    fn set_real(&mut self, _cx: &Context, vrs: &[u32], values: &[f64]) -> Result<(), Error> {
        for (&vr, &value) in vrs.iter().zip(values) {
            match Real::of(vr) {
                Some(Real::Input(_)) if value.is_finite() => {}
                Some(Real::Input(i)) => {
                    return Err(Error::Argument(format!(
                        "{} = {value} must be finite",
                        INPUTS[i].0
                    )))
                }
                Some(output) => {
                    return Err(Error::Argument(format!(
                        "{} is an output: it cannot be set",
                        output.name()
                    )))
                }
                None => return Err(no_variable("Real", vr)),
            }
        }
        for (&vr, &value) in vrs.iter().zip(values) {
            if let Some(Real::Input(i)) = Real::of(vr) {
                self.inputs[i] = value;
            }
        }
        Ok(())
    }

    /// `mooringModel`: all values are checked before any is set.
    fn set_integer(&mut self, cx: &Context, vrs: &[u32], values: &[i32]) -> Result<(), Error> {
        for (&vr, &value) in vrs.iter().zip(values) {
            if vr != MOORING_MODEL {
                return Err(no_variable("Integer", vr));
            }
            check_parameter(cx, "mooringModel")?;
            if value != DYNAMIC && value != QUASI_STATIC {
                return Err(Error::Argument(format!(
                    "invalid FMU parameter mooringModel = {value}: must be {DYNAMIC} (dynamic, \
                     MoorDyn's lines) or {QUASI_STATIC} (quasi-static catenaries)"
                )));
            }
        }
        if let Some(&value) = values.last() {
            self.mooring_model = value;
        }
        Ok(())
    }

    /// This FMU has no Boolean variable: any value reference is unknown.
    fn set_boolean(&mut self, _cx: &Context, vrs: &[u32], _: &[i32]) -> Result<(), Error> {
        no_boolean(vrs)
    }

    /// `mooringFile`: all values are checked before any is set.
    fn set_string(&mut self, cx: &Context, vrs: &[u32], values: &[&str]) -> Result<(), Error> {
        for &vr in vrs {
            if vr != MOORING_FILE {
                return Err(no_variable("String", vr));
            }
            check_parameter(cx, "mooringFile")?;
        }
        if let Some(value) = values.last() {
            self.mooring_file = value.to_string();
        }
        Ok(())
    }

    fn do_step(&mut self, t: f64, h: f64) -> Result<(), Error> {
        if !(h.is_finite() && h > 0.0) {
            return Err(Error::Argument(format!(
                "communicationStepSize = {h} must be positive"
            )));
        }
        if h > MAX_STEP {
            return Err(Error::Discard(format!(
                "communicationStepSize = {h:e} s is longer than the longest step of {MAX_STEP} s \
                 (the fairleads move in a straight line over a step): take shorter steps"
            )));
        }
        if !t.is_finite() || (t - self.time).abs() > TIME_TOLERANCE * self.time.abs().max(1.0) {
            return Err(Error::Argument(format!(
                "currentCommunicationPoint = {t} is not the instance's time {}",
                self.time
            )));
        }
        let mut lines = self
            .lines
            .take()
            .ok_or_else(|| Error::Model("no mooring lines".into()))?;
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
                let (x, xd) = self.kinematics();
                let reached = std::array::from_fn(|k| x[k] + h * xd[k]);
                self.set_quasi_static_outputs(quasi_static, reached)
                    .map_err(|e| format!("{e} in the step from t = {t} s"))
            }
        };
        self.lines = Some(lines);
        result.map_err(Error::Model)?;
        self.time = t + h;
        Ok(())
    }

    fn last_successful_time(&self) -> f64 {
        self.time
    }
}

impl Instance {
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
    fn make_lines(&mut self) -> Result<(), Error> {
        let key = (self.inputs, self.mooring_file.clone(), self.mooring_model);
        if self.lines.is_some() && self.made_for.as_ref() == Some(&key) {
            return Ok(());
        }
        self.lines = None;
        let input = self.input_file();
        let named = |e: String| Error::Model(with_parameter(&self.mooring_file, &input, e));
        let (x, xd) = self.kinematics();
        let lines = if self.mooring_model == QUASI_STATIC {
            let lines = QuasiStatic::read(&input).map_err(named)?;
            check_line_count(lines.line_count(), &input).map_err(named)?;
            self.set_quasi_static_outputs(&lines, x)
                .map_err(Error::Model)?;
            Lines::QuasiStatic(lines)
        } else {
            let mut system =
                System::new(Arc::clone(&self.library), &input, x, xd).map_err(named)?;
            check_line_count(system.line_count(), &input).map_err(named)?;
            let force = system.step(x, xd, self.time, 0.0).map_err(Error::Model)?;
            self.set_outputs(&system, force).map_err(Error::Model)?;
            Lines::Dynamic(system)
        };
        self.lines = Some(lines);
        self.made_for = Some(key);
        Ok(())
    }

    /// MoorDyn's coupled position (x, y, z, roll, pitch, yaw) and its rate, from the inputs
    /// as they are ([`crate::motion`]: the identity to first order in roll and pitch).
    fn kinematics(&self) -> ([f64; 6], [f64; 6]) {
        (
            POSITION.map(|i| self.inputs[i]),
            VELOCITY.map(|i| self.inputs[i]),
        )
    }

    fn set_outputs(&mut self, system: &System, force: [f64; 6]) -> Result<(), String> {
        let tensions = system.fairlead_tensions()?;
        self.check_and_set(force, &tensions, "MoorDyn")
    }

    /// The outputs: the quasi-static lines' force with the platform at r6.
    fn set_quasi_static_outputs(
        &mut self,
        lines: &QuasiStatic,
        r6: [f64; 6],
    ) -> Result<(), String> {
        let f = lines.force(r6)?;
        self.check_and_set(f.force, &f.tensions, "the quasi-static lines")
    }

    /// Sets the outputs from the force (Fx, Fy, Fz, Mx, My, Mz) and the lines' fairlead
    /// tensions, all finite (else an error naming the output and the time).
    fn check_and_set(&mut self, f: [f64; 6], tensions: &[f64], from: &str) -> Result<(), String> {
        if tensions.len() != LINE_COUNT {
            return Err(format!(
                "{from} returned {} fairlead tensions for the FMU's {LINE_COUNT} outputs",
                tensions.len()
            ));
        }
        let max = tensions.iter().fold(0.0, |m: f64, &t| m.max(t));
        let outputs = [f[SURGE], f[SWAY], f[YAW], max, f[HEAVE], f[ROLL], f[PITCH]];
        let named = (0..OUTPUTS.len()).map(Real::Output).zip(outputs);
        let lines = (0..tensions.len())
            .map(Real::LineTension)
            .zip(tensions.iter().copied());
        if let Some((real, value)) = named.chain(lines).find(|(_, v)| !v.is_finite()) {
            return Err(format!(
                "{from} returned {} = {value} at t = {} s",
                real.name(),
                self.time
            ));
        }
        self.outputs = outputs;
        self.tensions.copy_from_slice(tensions);
        Ok(())
    }
}

/// A mooring of [`LINE_COUNT`] lines, as the modelDescription.xml's outputs say.
fn check_line_count(count: usize, input: &Path) -> Result<(), String> {
    if count == LINE_COUNT {
        return Ok(());
    }
    Err(format!(
        "{} has {count} mooring lines, and this FMU has {LINE_COUNT} fairlead tension outputs          (fairleadTension1 to fairleadTension{LINE_COUNT}, one per line of the mooring it was          packed with): its modelDescription.xml is fixed, so give a file of {LINE_COUNT} lines,          or use an FMU whose modelDescription.xml declares {count} (docs/coupling.md, the line          outputs)",
        input.display()
    ))
}

/// The FMU's `resources` folder beside this library: `<unpacked FMU>/resources`, two levels
/// above it (`binaries/linux64/Mooring.so`).
fn resources_beside(library_dir: &Path) -> Option<PathBuf> {
    Some(library_dir.parent()?.parent()?.join("resources"))
}

/// Parameters are fixed: settable until `fmi2ExitInitializationMode`.
fn check_parameter(cx: &Context, name: &str) -> Result<(), Error> {
    if cx.state().fixed_parameters_settable() {
        Ok(())
    } else {
        Err(Error::Argument(format!(
            "{name} is a fixed parameter: set it before fmi2ExitInitializationMode"
        )))
    }
}

fn no_variable(kind: &str, vr: u32) -> Error {
    Error::Argument(format!("no {kind} variable has value reference {vr}"))
}

fn no_boolean(vrs: &[u32]) -> Result<(), Error> {
    match vrs.first() {
        Some(&vr) => Err(no_variable("Boolean", vr)),
        None => Ok(()),
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
