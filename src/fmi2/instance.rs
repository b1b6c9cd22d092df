//! One FMU instance: its parameters, inputs and the [`Simulation`] once initialised, as the
//! model of the shared FMI layer ([`Model`], [`SavedStates`]). Safe Rust: the layer checks
//! each call against the state machine, turns C pointers into the arguments here, and
//! reports every failure, an [`FmuError`], as an `fmi2Status` and a log line in one place.

use super::fmu_error::discarded;
use super::parameters::{
    Experiment, FmuValue, Parameters, HYDRO_DATABASE, MAX_STRING_BYTES, TIME_TOLERANCE,
};
use super::resources::{holds_configuration_of, RESOURCE_CONFIG};
use super::state::{fingerprint, FmuState};
use crate::error::numbers::written;
use crate::error::Error;
use crate::fmi2::model_description::{
    find, vr, Causality, VariableType, GUID, MODEL_IDENTIFIER, VARIABLES,
};
use crate::problem::Problem;
use crate::scenario::Scenario;
use crate::simulation::{Held, Outputs, Simulation};
use slowdrift_fmi::fmi2::machine::MachineState;
use slowdrift_fmi::fmi2::{Context, Instantiation, Model, SavedStates};
use slowdrift_fmi::text::c_text;
use slowdrift_fmi::Error as FmuError;
use std::ffi::CString;
use std::path::PathBuf;

/// The simulation with the fingerprint of the configuration it was built from, computed
/// when a state first asks for it (hashing the problem's JSON, drift table included, takes
/// about a millisecond: not part of the initialisation).
#[derive(Debug)]
struct Built {
    simulation: Simulation,
    fingerprint: std::cell::OnceCell<u64>,
}

/// One FMU instance.
#[derive(Debug)]
pub struct Instance {
    /// The FMU's `resources` folder, from `fmuResourceLocation`.
    resources: Option<PathBuf>,
    parameters: Parameters,
    experiment: Experiment,
    /// Fx_ext, Fy_ext, Mz_ext (inertial frame) and windVelocity_ext, held over each step.
    inputs: Held,
    /// Built in initialisation mode when an output is first read, else at
    /// ExitInitializationMode; dropped when a parameter changes.
    built: Option<Built>,
    /// Outputs at the current time (no allocation when refreshed after a step).
    outputs: Option<Outputs>,
    last_successful_time: f64,
    /// The strings last returned by `fmi2GetString`; valid until the next call.
    strings: Vec<CString>,
    /// The base configuration the parameters name, read when a parameter the master did not
    /// set is read (its value is the configuration's); dropped when `hydroDatabase` changes.
    base: Option<Scenario>,
}

impl Instance {
    /// A freshly instantiated instance.
    fn new(resources: Option<PathBuf>) -> Instance {
        let experiment = Experiment::default();
        Instance {
            resources,
            parameters: Parameters::default(),
            experiment,
            inputs: start_inputs(),
            built: None,
            outputs: None,
            last_successful_time: experiment.start_time,
            strings: Vec::new(),
            base: None,
        }
    }

    /// The base configuration the parameters name, read once (and again after
    /// `hydroDatabase` changes): what the problem is built on and what a parameter the
    /// master did not set reads back, so that both are the same file's, read at one time.
    fn base_scenario(&mut self) -> Result<&Scenario, FmuError> {
        if self.base.is_none() {
            self.base = Some(self.parameters.base_scenario(self.resources.as_deref())?);
        }
        Ok(self.base.as_ref().expect("read above"))
    }

    /// The problem of the current parameters and experiment.
    fn problem(&mut self) -> Result<Problem, FmuError> {
        self.base_scenario()?;
        let base = self.base.as_ref().expect("read above");
        Ok(self.parameters.to_problem(base, &self.experiment)?)
    }

    /// The simulation, built now if needed (holding the input wind from its start).
    fn simulation(&mut self) -> Result<&mut Simulation, FmuError> {
        if self.built.is_none() {
            let mut built = Built::new(self.problem()?)?;
            built.simulation.hold_wind_input(self.inputs.wind_speed)?;
            self.built = Some(built);
        }
        Ok(&mut self.built.as_mut().expect("built above").simulation)
    }

    fn refresh_outputs(&mut self) -> Result<(), FmuError> {
        let outputs = self.simulation()?.outputs()?;
        self.outputs = Some(outputs);
        Ok(())
    }

    fn current_fingerprint(&mut self) -> Result<u64, FmuError> {
        match &self.built {
            Some(b) => Ok(b.fingerprint()),
            None => Ok(fingerprint(&self.problem()?)),
        }
    }

    /// The variable of `ty` with value reference `vr`, or an error that says what it is.
    fn variable(&self, ty: VariableType, vr: u32) -> Result<Causality, FmuError> {
        if let Some(v) = find(ty, vr) {
            return Ok(v.causality);
        }
        let other = VARIABLES
            .iter()
            .find(|v| v.value_reference == vr)
            .map(|v| format!(" ({} is {:?})", v.name, v.var_type))
            .unwrap_or_default();
        Err(FmuError::Argument(format!(
            "no {ty:?} variable has value reference {vr}{other}"
        )))
    }

    /// The value a master reads for the parameter of `ty` with value reference `vr`: its own
    /// where it set it, else the configuration's ([`Parameters::value_for`]).
    fn parameter_value(&mut self, ty: VariableType, vr: u32) -> Result<FmuValue, FmuError> {
        let info = find(ty, vr).expect("a parameter of modelDescription.xml");
        if self.parameters.is_set(ty, vr) || info.name == HYDRO_DATABASE {
            return Ok(self
                .parameters
                .iter()
                .find(|(v, _, _)| v.value_reference == vr && v.var_type == ty)
                .expect("a parameter")
                .1
                .clone());
        }
        self.base_scenario()?;
        let base = self.base.as_ref().expect("read above");
        // What runs: the configuration with the master's parameters over it (a set
        // `spreadingExponent` spreads a long-crested sea over 15 directions, and an unset
        // `nDirections` then reads 15). Parameters the run would refuse leave the
        // configuration's values to read.
        let running = self
            .parameters
            .apply(base.clone(), &self.experiment)
            .unwrap_or_else(|_| base.clone());
        Ok(self.parameters.value_for(info, &running))
    }

    /// May the parameter or input of `causality` with value reference `vr` take `value`
    /// now? A fixed parameter after initialisation only when `value` is the one it has (a
    /// master that writes its start values back after `fmi2SetFMUstate`, as fmusim does).
    fn may_set(
        &mut self,
        state: MachineState,
        causality: Causality,
        ty: VariableType,
        vr: u32,
        value: &FmuValue,
    ) -> Result<(), FmuError> {
        if causality == Causality::Parameter
            && settable(state, causality, vr).is_err()
            && self.parameter_value(ty, vr).ok().as_ref() == Some(value)
        {
            return Ok(());
        }
        settable(state, causality, vr)
    }

    /// An output, computed at the first request after a step (in initialisation mode the
    /// simulation is built to compute it).
    fn output(&mut self, state: MachineState, vr: u32) -> Result<f64, FmuError> {
        let computable = state == MachineState::InitializationMode || self.built.is_some();
        if self.outputs.is_none() && computable {
            self.refresh_outputs()?;
        }
        let o = self.outputs.as_ref().ok_or_else(|| {
            FmuError::Argument(
                "outputs are not available: the instance was never initialized".into(),
            )
        })?;
        Ok(output_value(o, vr))
    }

    /// `fmi2GetBoolean` / `fmi2SetBoolean`: this model has no Boolean variable.
    fn boolean(&self, vrs: &[u32]) -> Result<(), FmuError> {
        match vrs.first() {
            Some(&vr) => self.variable(VariableType::Boolean, vr).map(|_| ()),
            None => Ok(()),
        }
    }

    fn parameters_changed(&mut self) {
        self.built = None;
        self.outputs = None;
        // `hydroDatabase` may name another configuration.
        self.base = None;
    }
}

impl Model for Instance {
    const MODEL_IDENTIFIER: &'static str = MODEL_IDENTIFIER;
    const WITHOUT_RESOURCES: &'static str =
        "the embedded default platform is the default configuration";

    /// An instance of this binary's GUID, or of that of a user's configuration packed in the
    /// resources (`fmu-pack --config`: its modelDescription.xml carries that configuration's
    /// start values, and a GUID of its own).
    fn instantiate(instantiation: Instantiation<'_>) -> Result<Instance, FmuError> {
        let Instantiation {
            guid, resources, ..
        } = instantiation;
        if guid != GUID
            && !resources
                .as_deref()
                .is_some_and(|r| holds_configuration_of(r, guid))
        {
            return Err(FmuError::Argument(format!(
                "fmuGUID {guid:?} is neither this binary's {GUID:?} nor that of the \
                 configuration in the FMU's resources: the modelDescription.xml does not \
                 belong to this FMU (was resources/{RESOURCE_CONFIG} changed after \
                 fmu-pack packed it? pack it again)"
            )));
        }
        Ok(Instance::new(resources))
    }

    /// `fmi2SetupExperiment` (the tolerance is not used: RK4 has a fixed step).
    fn setup_experiment(&mut self, start: f64, stop: Option<f64>) -> Result<(), FmuError> {
        self.experiment = Experiment::new(start, stop)?;
        self.last_successful_time = start;
        self.built = None;
        Ok(())
    }

    /// Builds the simulation (precomputes the records) and its first outputs.
    fn exit_initialization_mode(&mut self, cx: &Context) -> Result<(), FmuError> {
        // What the run uses, as `slowdrift simulate` prints it (`Problem::summary`).
        let simulation = self.simulation()?;
        let mut lines = simulation.problem().summary()?;
        lines.push(simulation.records_line());
        for line in &lines {
            cx.event(line);
        }
        self.refresh_outputs()?;
        self.last_successful_time = self.experiment.start_time;
        cx.event("initialized: records precomputed");
        Ok(())
    }

    /// Back to a freshly instantiated instance; the resource location stays.
    fn reset(&mut self) {
        *self = Instance::new(self.resources.take());
    }

    fn get_real(&mut self, cx: &Context, vrs: &[u32], values: &mut [f64]) -> Result<(), FmuError> {
        for (&vr, value) in vrs.iter().zip(values) {
            *value = match self.variable(VariableType::Real, vr)? {
                Causality::Parameter => match self.parameter_value(VariableType::Real, vr)? {
                    FmuValue::Real(x) => x,
                    _ => unreachable!("a Real parameter"),
                },
                Causality::Input => *input_slot(&mut self.inputs, vr),
                _ => self.output(cx.state(), vr)?,
            };
        }
        Ok(())
    }

    fn get_integer(
        &mut self,
        _cx: &Context,
        vrs: &[u32],
        values: &mut [i32],
    ) -> Result<(), FmuError> {
        for (&vr, value) in vrs.iter().zip(values) {
            self.variable(VariableType::Integer, vr)?;
            *value = match self.parameter_value(VariableType::Integer, vr)? {
                FmuValue::Integer(i) => i,
                _ => unreachable!("an Integer parameter"),
            };
        }
        Ok(())
    }

    /// `fmi2GetBoolean`: this model has no Boolean variable.
    fn get_boolean(&mut self, _cx: &Context, vrs: &[u32], _: &mut [i32]) -> Result<(), FmuError> {
        self.boolean(vrs)
    }

    /// `fmi2GetString`: the returned strings live in the instance until its next call.
    fn get_string(&mut self, _cx: &Context, vrs: &[u32]) -> Result<&[CString], FmuError> {
        let mut strings = Vec::with_capacity(vrs.len());
        for &vr in vrs {
            self.variable(VariableType::String, vr)?;
            strings.push(c_text(
                self.parameters.string(vr).expect("a String parameter"),
            ));
        }
        self.strings = strings;
        Ok(&self.strings)
    }

    /// `fmi2SetReal`: all values are checked before any is set.
    fn set_real(&mut self, cx: &Context, vrs: &[u32], values: &[f64]) -> Result<(), FmuError> {
        for (&vr, &value) in vrs.iter().zip(values) {
            let causality = self.variable(VariableType::Real, vr)?;
            self.may_set(
                cx.state(),
                causality,
                VariableType::Real,
                vr,
                &FmuValue::Real(value),
            )?;
            if !value.is_finite() {
                let field = name_of(VariableType::Real, vr).to_string();
                return Err(match causality {
                    Causality::Input => Error::NonFiniteInput { field, value },
                    _ => Error::invalid(field, value, "must be a finite number"),
                }
                .into());
            }
            if vr == vr::WIND_VELOCITY_EXT && value < 0.0 {
                return Err(Error::invalid(
                    "windVelocity_ext",
                    value,
                    "must be at least 0 m/s (the wind speed at the force's height)",
                )
                .into());
            }
        }
        for (&vr, &value) in vrs.iter().zip(values) {
            if kept(cx.state(), VariableType::Real, vr) {
                continue;
            }
            match self.parameters.write(vr, FmuValue::Real(value)) {
                Some(true) => self.parameters_changed(),
                Some(false) => {}
                None => *input_slot(&mut self.inputs, vr) = value,
            }
        }
        Ok(())
    }

    fn set_integer(&mut self, cx: &Context, vrs: &[u32], values: &[i32]) -> Result<(), FmuError> {
        for (&vr, &value) in vrs.iter().zip(values) {
            let causality = self.variable(VariableType::Integer, vr)?;
            self.may_set(
                cx.state(),
                causality,
                VariableType::Integer,
                vr,
                &FmuValue::Integer(value),
            )?;
        }
        for (&vr, &value) in vrs.iter().zip(values) {
            if !kept(cx.state(), VariableType::Integer, vr)
                && self.parameters.write(vr, FmuValue::Integer(value)) == Some(true)
            {
                self.parameters_changed();
            }
        }
        Ok(())
    }

    /// `fmi2SetBoolean`: this model has no Boolean variable.
    fn set_boolean(&mut self, _cx: &Context, vrs: &[u32], _: &[i32]) -> Result<(), FmuError> {
        self.boolean(vrs)
    }

    /// `fmi2SetString`: a value longer than [`MAX_STRING_BYTES`] is refused (a saved state
    /// could not carry it).
    fn set_string(&mut self, cx: &Context, vrs: &[u32], values: &[&str]) -> Result<(), FmuError> {
        for (&vr, value) in vrs.iter().zip(values) {
            let causality = self.variable(VariableType::String, vr)?;
            self.may_set(
                cx.state(),
                causality,
                VariableType::String,
                vr,
                &FmuValue::String(value.to_string()),
            )?;
            if value.len() > MAX_STRING_BYTES {
                return Err(FmuError::Argument(format!(
                    "{} is {} bytes long: at most {MAX_STRING_BYTES} bytes are accepted",
                    name_of(VariableType::String, vr),
                    value.len()
                )));
            }
        }
        for (&vr, &value) in vrs.iter().zip(values) {
            if !kept(cx.state(), VariableType::String, vr)
                && self
                    .parameters
                    .write(vr, FmuValue::String(value.to_string()))
                    == Some(true)
            {
                self.parameters_changed();
            }
        }
        Ok(())
    }

    /// `fmi2DoStep`: one communication step with the current inputs. A step must advance
    /// the time (else fmi2Error) and may cover at most one block of the records
    /// ([`longest_step`]; a longer one is discarded, the state unchanged, so that a master
    /// can retry with shorter steps as FMI 2.0.4 section 4.2.2 advises).
    fn do_step(&mut self, point: f64, h: f64) -> Result<(), FmuError> {
        if !(h.is_finite() && h > 0.0) {
            return Err(FmuError::Argument(format!(
                "communicationStepSize = {} must be finite and positive",
                written(h)
            )));
        }
        let inputs = self.inputs;
        let experiment = self.experiment;
        let simulation = self.simulation()?;
        let t = simulation.time();
        if !point.is_finite() || (point - t).abs() > TIME_TOLERANCE * t.abs().max(1.0) {
            return Err(FmuError::Argument(format!(
                "currentCommunicationPoint = {point} s differs from the instance's time {t} s"
            )));
        }
        if t + h == t {
            return Err(FmuError::Argument(format!(
                "communicationStepSize = {} s does not advance the time: at t = {t} s, t + h \
                 == t in double precision (doubles there are {} s apart)",
                written(h),
                written(spacing(t))
            )));
        }
        if let (true, Some(stop)) = (experiment.passes_stop(t + h), experiment.stop_time) {
            return Err(FmuError::Argument(format!(
                "a step of {} s from {t} s passes stopTime = {stop} s",
                written(h)
            )));
        }
        let longest = longest_step(simulation.problem());
        if h > longest {
            return Err(discarded(Error::invalid(
                "communicationStepSize",
                format!("{} s", written(h)),
                format!(
                    "longer than one block of the records, {longest} s, the longest step this \
                     FMU takes (a step makes at most one block of records, as initialisation \
                     does, and {} RK4 steps of stepSize = {} s); the state is unchanged: \
                     step at most {longest} s at a time",
                    (longest / simulation.problem().run.time_step).ceil(),
                    simulation.problem().run.time_step
                ),
            )));
        }
        let advanced = simulation
            .hold_wind_input(inputs.wind_speed)
            .and_then(|()| simulation.advance(h, inputs.force))
            .map(|()| simulation.time());
        // Outputs are computed when a getter first asks for them after the step.
        self.outputs = None;
        match advanced {
            Ok(time) => {
                self.last_successful_time = time;
                Ok(())
            }
            // The state is unchanged and the instance usable: the master may change its
            // inputs (the yaw moment) and try again, or roll back.
            Err(e @ Error::YawOutsideRecords { .. }) => Err(discarded(e)),
            Err(e) => Err(e.into()),
        }
    }

    /// `fmi2GetRealStatus(fmi2LastSuccessfulTime)`.
    fn last_successful_time(&self) -> f64 {
        self.last_successful_time
    }
}

impl SavedStates for Instance {
    type State = FmuState;

    /// `fmi2GetFMUstate`: a copy of everything needed to continue from here.
    fn get_fmu_state(&mut self, cx: &Context) -> Result<FmuState, FmuError> {
        let initialized = matches!(
            cx.state(),
            MachineState::StepComplete | MachineState::StepFailed | MachineState::Terminated
        );
        let snapshot = match &self.built {
            Some(b) if initialized => Some(b.simulation.snapshot()),
            _ => None,
        };
        let state = FmuState {
            fingerprint: self.current_fingerprint()?,
            parameters: self.parameters.clone(),
            experiment: self.experiment,
            machine: cx.state(),
            last_successful_time: self.last_successful_time,
            inputs: self.inputs,
            snapshot,
        };
        cx.event("state saved");
        Ok(state)
    }

    /// `fmi2SetFMUstate`, in any instance (freshly instantiated, configured otherwise, in
    /// Error): the state's parameters and experiment become the instance's (FMI 2.0.4
    /// section 2.1.8: they are part of the FMU state). The records are this instance's when
    /// they were built from the state's problem (same fingerprint: a rollback), else they
    /// are rebuilt from the state's parameters, and the problem is refused, naming its base
    /// (`hydroDatabase`, resources or the embedded default), when it is not the saved one
    /// or cannot be built. Nothing changes before every check has passed.
    fn set_fmu_state(&mut self, cx: &Context, state: &FmuState) -> Result<MachineState, FmuError> {
        let reuse = self
            .built
            .as_ref()
            .is_some_and(|b| b.fingerprint() == state.fingerprint);
        let same_base = state.parameters.hydro_database() == self.parameters.hydro_database();
        let mut scenario = self.base.take().filter(|_| same_base);
        let (mut rebuilt, event) = if reuse {
            (None, "state restored".to_string())
        } else {
            let resources = self.resources.as_deref();
            let base = state.parameters.base(resources);
            let problem = match state.parameters.base_scenario(resources) {
                Ok(read) => {
                    let problem = state.parameters.to_problem(&read, &state.experiment);
                    scenario = Some(read);
                    problem
                }
                Err(e) => Err(e),
            };
            let problem = state.check_problem(&base, problem)?;
            let built = Built {
                simulation: Simulation::new(problem)?,
                fingerprint: state.fingerprint.into(),
            };
            let event =
                format!("state restored: records rebuilt from the state's parameters and {base}");
            (Some(built), event)
        };
        let simulation = match &mut rebuilt {
            Some(b) => &mut b.simulation,
            None => &mut self.built.as_mut().expect("reused above").simulation,
        };
        let outputs = match &state.snapshot {
            Some(snapshot) => {
                simulation.restore(snapshot)?;
                Some(simulation.outputs()?)
            }
            None => {
                simulation.reset()?;
                None
            }
        };
        if rebuilt.is_some() {
            self.built = rebuilt;
        }
        self.outputs = outputs;
        self.parameters = state.parameters.clone();
        self.base = scenario;
        self.experiment = state.experiment;
        self.last_successful_time = state.last_successful_time;
        self.inputs = state.inputs;
        cx.event(&event);
        Ok(state.machine)
    }

    fn serialized_size(state: &FmuState) -> usize {
        state.byte_len()
    }

    fn serialize(state: &FmuState) -> Result<Vec<u8>, FmuError> {
        Ok(state.to_bytes()?)
    }

    /// `fmi2DeSerializeFMUstate`: reads and checks the bytes; whether the state's problem
    /// can be rebuilt here is `fmi2SetFMUstate`'s check (see [`crate::fmi2::state`]).
    fn deserialize(bytes: &[u8]) -> Result<FmuState, FmuError> {
        Ok(FmuState::from_bytes(bytes)?)
    }
}

impl Built {
    /// The simulation of `problem` (its records precomputed).
    fn new(problem: Problem) -> Result<Built, FmuError> {
        Ok(Built {
            simulation: Simulation::new(problem)?,
            fingerprint: std::cell::OnceCell::new(),
        })
    }

    /// The fingerprint of the problem the simulation was built from.
    fn fingerprint(&self) -> u64 {
        *self
            .fingerprint
            .get_or_init(|| fingerprint(self.simulation.problem()))
    }
}

/// Whether the variable of `ty` with value reference `vr` is a parameter that is fixed
/// now, after `fmi2ExitInitializationMode` (a set of it was accepted because it keeps its
/// value: nothing to write).
fn kept(state: MachineState, ty: VariableType, vr: u32) -> bool {
    !state.fixed_parameters_settable()
        && find(ty, vr).is_some_and(|v| v.causality == Causality::Parameter)
}

/// May a variable of this causality be set now?
fn settable(state: MachineState, causality: Causality, vr: u32) -> Result<(), FmuError> {
    let name = VARIABLES
        .iter()
        .find(|v| v.value_reference == vr && v.causality == causality)
        .map_or("?", |v| v.name);
    match causality {
        Causality::Input => Ok(()),
        Causality::Parameter if state.fixed_parameters_settable() => Ok(()),
        Causality::Parameter => Err(FmuError::Argument(format!(
            "parameter {name} is fixed: set it before fmi2ExitInitializationMode (after \
             it, only to the value it has)"
        ))),
        other => Err(FmuError::Argument(format!(
            "{name} (value reference {vr}) is an {other:?} and cannot be set"
        ))),
    }
}

/// The longest communication step, s: one block of the records (`run.block_duration`, the
/// span of one segment of the record stream). Such a step crosses at most one join, so it
/// makes at most one new segment (the work of initialisation) and block_duration /
/// stepSize RK4 steps: its time is bounded whatever the master asks.
pub fn longest_step(problem: &Problem) -> f64 {
    problem.run.block_duration
}

/// The distance from `t` to the next double above |t|, s.
fn spacing(t: f64) -> f64 {
    let a = t.abs();
    f64::from_bits(a.to_bits() + 1) - a
}

fn start_inputs() -> Held {
    use crate::fmi2::model_description::start;
    Held {
        force: [start::FX_EXT, start::FY_EXT, start::MZ_EXT],
        wind_speed: start::WIND_VELOCITY_EXT,
    }
}

/// The slot of an input in [`Instance::inputs`].
fn input_slot(inputs: &mut Held, vr: u32) -> &mut f64 {
    match vr {
        vr::FX_EXT => &mut inputs.force[0],
        vr::FY_EXT => &mut inputs.force[1],
        vr::MZ_EXT => &mut inputs.force[2],
        vr::WIND_VELOCITY_EXT => &mut inputs.wind_speed,
        other => unreachable!("value reference {other} is not an input"),
    }
}

fn name_of(ty: VariableType, vr: u32) -> &'static str {
    find(ty, vr).map_or("?", |v| v.name)
}

/// The output with value reference `vr` (an output of the model description).
fn output_value(o: &Outputs, vr: u32) -> f64 {
    match vr {
        vr::X => o.position[0],
        vr::Y => o.position[1],
        vr::THETA => o.position[2],
        vr::XDOT => o.velocity[0],
        vr::YDOT => o.velocity[1],
        vr::THETADOT => o.velocity[2],
        vr::ETA => o.wave_elevation,
        vr::FX_WAVE => o.forces.wave[0],
        vr::FY_WAVE => o.forces.wave[1],
        vr::MZ_WAVE => o.forces.wave[2],
        vr::FX_DAMPING => o.forces.damping[0],
        vr::FY_DAMPING => o.forces.damping[1],
        vr::MZ_DAMPING => o.forces.damping[2],
        vr::FX_DRAG => o.forces.drag[0],
        vr::FY_DRAG => o.forces.drag[1],
        vr::MZ_DRAG => o.forces.drag[2],
        vr::X_WF => o.motion.wave_frequency[0],
        vr::Y_WF => o.motion.wave_frequency[1],
        vr::Z_WF => o.motion.wave_frequency[2],
        vr::ROLL_WF => o.motion.wave_frequency[3],
        vr::PITCH_WF => o.motion.wave_frequency[4],
        vr::YAW_WF => o.motion.wave_frequency[5],
        vr::X_TOTAL => o.motion.total[0],
        vr::Y_TOTAL => o.motion.total[1],
        vr::Z_TOTAL => o.motion.total[2],
        vr::ROLL_TOTAL => o.motion.total[3],
        vr::PITCH_TOTAL => o.motion.total[4],
        vr::YAW_TOTAL => o.motion.total[5],
        vr::XDOT_TOTAL => o.motion.total_rate[0],
        vr::YDOT_TOTAL => o.motion.total_rate[1],
        vr::ZDOT_TOTAL => o.motion.total_rate[2],
        vr::ROLLDOT_TOTAL => o.motion.total_rate[3],
        vr::PITCHDOT_TOTAL => o.motion.total_rate[4],
        vr::YAWDOT_TOTAL => o.motion.total_rate[5],
        vr::WIND_VELOCITY => o.wind_speed,
        vr::FX_WIND => o.forces.wind[0],
        vr::FY_WIND => o.forces.wind[1],
        vr::MZ_WIND => o.forces.wind[2],
        other => unreachable!("value reference {other} is not an output"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_output_and_input_has_a_slot() {
        let o = Outputs {
            time: 0.0,
            position: [0.0; 3],
            velocity: [0.0; 3],
            wave_elevation: 0.0,
            forces: Default::default(),
            external_force: [0.0; 3],
            motion: Default::default(),
            wind_speed: 0.0,
        };
        for v in VARIABLES {
            match v.causality {
                Causality::Output => {
                    output_value(&o, v.value_reference);
                }
                Causality::Input => {
                    input_slot(&mut start_inputs(), v.value_reference);
                }
                _ => {}
            }
        }
    }
}
