//! What a model gives the FMI 2.0 layer: [`Model`] (instantiation, the experiment,
//! initialisation, variables, steps) and, for a model whose states can be saved,
//! [`SavedStates`]. Safe Rust: the layer has checked the call against the state machine and
//! turned the host's pointers into slices and text before a method runs, and it reports
//! what the method returns ([`crate::Error`]) in one place.
//!
//! The layer makes the state machine's transitions itself (initialisation mode entered and
//! left, terminated, reset, a failed or discarded call); a method reads the current state
//! from its [`Context`].

use super::logger::Logger;
use super::machine::MachineState;
use crate::Error;
use std::ffi::CString;
use std::path::PathBuf;

/// What `fmi2Instantiate` passes to [`Model::instantiate`], checked: a non-empty instance
/// name, a co-simulation instance, the GUID as text.
#[derive(Debug)]
pub struct Instantiation<'a> {
    /// `instanceName`.
    pub name: &'a str,
    /// `fmuGUID`: the model compares it with its own.
    pub guid: &'a str,
    /// The local folder of `fmuResourceLocation`; `None` when the host gave none or one
    /// that is not a local `file:` URI (then with a warning).
    pub resources: Option<PathBuf>,
}

/// What a method sees of its instance besides the model: the state of the state machine and
/// the logger's event lines.
pub struct Context<'a> {
    pub(crate) state: MachineState,
    pub(crate) logger: &'a Logger,
}

impl Context<'_> {
    /// The instance's current state.
    pub fn state(&self) -> MachineState {
        self.state
    }

    /// An event line (`logEvents`: initialisation, reset, states saved and restored).
    pub fn event(&self, message: &str) {
        self.logger.event(message);
    }
}

/// An FMI 2.0 co-simulation model. A model of this layer steps synchronously, never ends a
/// run itself (`fmi2Terminated` is false) and provides neither directional derivatives nor
/// input or output derivatives.
pub trait Model: Sized {
    /// The model identifier: the library's name, and the logger's instance name when the
    /// host gave none.
    const MODEL_IDENTIFIER: &'static str;
    /// What the model does without a resources folder: the end of the warning when
    /// `fmuResourceLocation` is not a local file URI.
    const WITHOUT_RESOURCES: &'static str;

    /// `fmi2Instantiate`: the model for this instance, or why not (a GUID that is not the
    /// model's, a library it cannot load...).
    fn instantiate(instantiation: Instantiation<'_>) -> Result<Self, Error>;

    /// `fmi2SetupExperiment` (`stop` when `stopTimeDefined`).
    fn setup_experiment(&mut self, start: f64, stop: Option<f64>) -> Result<(), Error>;

    /// `fmi2ExitInitializationMode`: the model ready to step.
    fn exit_initialization_mode(&mut self, cx: &Context) -> Result<(), Error>;

    /// `fmi2Reset`: back to a freshly instantiated model (the layer keeps the logger).
    fn reset(&mut self);

    /// `fmi2GetReal`: `values[i]` of `vrs[i]` (the slices have the same length).
    fn get_real(&mut self, cx: &Context, vrs: &[u32], values: &mut [f64]) -> Result<(), Error>;

    /// `fmi2GetInteger`.
    fn get_integer(&mut self, cx: &Context, vrs: &[u32], values: &mut [i32]) -> Result<(), Error>;

    /// `fmi2GetBoolean` (`fmi2True` 1, `fmi2False` 0).
    fn get_boolean(&mut self, cx: &Context, vrs: &[u32], values: &mut [i32]) -> Result<(), Error>;

    /// `fmi2GetString`: one string per value reference, valid until the instance's next
    /// call (the host gets pointers into them).
    fn get_string(&mut self, cx: &Context, vrs: &[u32]) -> Result<&[CString], Error>;

    /// `fmi2SetReal`.
    fn set_real(&mut self, cx: &Context, vrs: &[u32], values: &[f64]) -> Result<(), Error>;

    /// `fmi2SetInteger`.
    fn set_integer(&mut self, cx: &Context, vrs: &[u32], values: &[i32]) -> Result<(), Error>;

    /// `fmi2SetBoolean`.
    fn set_boolean(&mut self, cx: &Context, vrs: &[u32], values: &[i32]) -> Result<(), Error>;

    /// `fmi2SetString`.
    fn set_string(&mut self, cx: &Context, vrs: &[u32], values: &[&str]) -> Result<(), Error>;

    /// `fmi2DoStep` from `point` over `h`. [`Error::Discard`] leaves the model as it was
    /// and the instance in StepFailed.
    fn do_step(&mut self, point: f64, h: f64) -> Result<(), Error>;

    /// `fmi2GetRealStatus(fmi2LastSuccessfulTime)`.
    fn last_successful_time(&self) -> f64;
}

/// A model whose state can be saved, restored and serialized (`canGetAndSetFMUstate`,
/// `canSerializeFMUstate`). A model without it answers the six state functions with
/// `without_saved_states` of the C functions (functions/mod.rs).
pub trait SavedStates: Model {
    /// A saved state (boxed behind an `fmi2FMUstate`).
    type State;

    /// `fmi2GetFMUstate`: everything needed to continue from here.
    fn get_fmu_state(&mut self, cx: &Context) -> Result<Self::State, Error>;

    /// `fmi2SetFMUstate`: continue from `state`; the state machine's state it puts the
    /// instance in.
    fn set_fmu_state(&mut self, cx: &Context, state: &Self::State) -> Result<MachineState, Error>;

    /// `fmi2SerializedFMUstateSize`.
    fn serialized_size(state: &Self::State) -> usize;

    /// `fmi2SerializeFMUstate`: the state's bytes.
    fn serialize(state: &Self::State) -> Result<Vec<u8>, Error>;

    /// `fmi2DeSerializeFMUstate`: the state of `bytes`, checked.
    fn deserialize(bytes: &[u8]) -> Result<Self::State, Error>;
}
