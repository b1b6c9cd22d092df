//! [`crate::fmi2_exports`]: every FMI 2.0 common and co-simulation function as an
//! `extern "C"` symbol of a cdylib, for its model: thin shims that call the function of the
//! same name of [`crate::fmi2::functions`] (the layer checks the call against the state
//! machine, turns the pointers into references, runs the model behind its panic firewall and
//! reports the result). One macro call makes all 34, in both FMUs, so neither can miss one
//! or differ from the other; [`crate::fmi3_exports`] does the same for FMI 3.0.

/// The `#[no_mangle] extern "C" fn fmi2*` of FMI 2.0 co-simulation for the model `$model`:
/// a [`crate::fmi2::Model`] with [`crate::fmi2::SavedStates`], or, written
/// `fmi2_exports!(Model, without_saved_states)`, one without (the six state functions then
/// answer `fmi2Error` saying so: `canGetAndSetFMUstate="false"`). Call it in a module of its
/// own in the cdylib crate, whose documentation states the pointer contract (the functions
/// are `unsafe`: FMI 2.0 describes what the host passes): the expansion imports the FMI 2.0
/// types and `fmi2` (the layer's functions) there. The cdylib's linker version script
/// (`exports.map`) exports the `fmi2*` symbols and nothing else.
#[macro_export]
macro_rules! fmi2_exports {
    ($model:ty) => {
        $crate::fmi2_exports!(@common $model);
        $crate::fmi2_exports!(@states $model);
    };
    ($model:ty, without_saved_states) => {
        $crate::fmi2_exports!(@common $model);
        $crate::fmi2_exports!(@no_states $model);
    };
    (@common $model:ty) => {
        use $crate::fmi2::functions as fmi2;
        use $crate::fmi2::types::*;
        use std::ffi::c_char;

        // -----------------------------------------------------------------------------
        // Common functions

        #[no_mangle]
        pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
            fmi2::get_types_platform()
        }

        #[no_mangle]
        pub extern "C" fn fmi2GetVersion() -> *const c_char {
            fmi2::get_version()
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2SetDebugLogging(
            c: fmi2Component,
            loggingOn: fmi2Boolean,
            nCategories: usize,
            categories: *const fmi2String,
        ) -> fmi2Status {
            unsafe { fmi2::set_debug_logging::<$model>(c, loggingOn, nCategories, categories) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2Instantiate(
            instanceName: fmi2String,
            fmuType: fmi2Type,
            fmuGUID: fmi2String,
            fmuResourceLocation: fmi2String,
            functions: *const fmi2CallbackFunctions,
            _visible: fmi2Boolean,
            loggingOn: fmi2Boolean,
        ) -> fmi2Component {
            unsafe {
                fmi2::instantiate::<$model>(
                    instanceName,
                    fmuType,
                    fmuGUID,
                    fmuResourceLocation,
                    functions,
                    loggingOn,
                )
            }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2FreeInstance(c: fmi2Component) {
            unsafe { fmi2::free_instance::<$model>(c) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2SetupExperiment(
            c: fmi2Component,
            _toleranceDefined: fmi2Boolean,
            _tolerance: fmi2Real,
            startTime: fmi2Real,
            stopTimeDefined: fmi2Boolean,
            stopTime: fmi2Real,
        ) -> fmi2Status {
            unsafe { fmi2::setup_experiment::<$model>(c, startTime, stopTimeDefined, stopTime) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2EnterInitializationMode(c: fmi2Component) -> fmi2Status {
            unsafe { fmi2::enter_initialization_mode::<$model>(c) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2ExitInitializationMode(c: fmi2Component) -> fmi2Status {
            unsafe { fmi2::exit_initialization_mode::<$model>(c) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2Terminate(c: fmi2Component) -> fmi2Status {
            unsafe { fmi2::terminate::<$model>(c) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2Reset(c: fmi2Component) -> fmi2Status {
            unsafe { fmi2::reset::<$model>(c) }
        }

        // -----------------------------------------------------------------------------
        // Getting and setting variables

        #[no_mangle]
        pub unsafe extern "C" fn fmi2GetReal(
            c: fmi2Component,
            vr: *const fmi2ValueReference,
            nvr: usize,
            value: *mut fmi2Real,
        ) -> fmi2Status {
            unsafe { fmi2::get_real::<$model>(c, vr, nvr, value) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2GetInteger(
            c: fmi2Component,
            vr: *const fmi2ValueReference,
            nvr: usize,
            value: *mut fmi2Integer,
        ) -> fmi2Status {
            unsafe { fmi2::get_integer::<$model>(c, vr, nvr, value) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2GetBoolean(
            c: fmi2Component,
            vr: *const fmi2ValueReference,
            nvr: usize,
            value: *mut fmi2Boolean,
        ) -> fmi2Status {
            unsafe { fmi2::get_boolean::<$model>(c, vr, nvr, value) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2GetString(
            c: fmi2Component,
            vr: *const fmi2ValueReference,
            nvr: usize,
            value: *mut fmi2String,
        ) -> fmi2Status {
            unsafe { fmi2::get_string::<$model>(c, vr, nvr, value) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2SetReal(
            c: fmi2Component,
            vr: *const fmi2ValueReference,
            nvr: usize,
            value: *const fmi2Real,
        ) -> fmi2Status {
            unsafe { fmi2::set_real::<$model>(c, vr, nvr, value) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2SetInteger(
            c: fmi2Component,
            vr: *const fmi2ValueReference,
            nvr: usize,
            value: *const fmi2Integer,
        ) -> fmi2Status {
            unsafe { fmi2::set_integer::<$model>(c, vr, nvr, value) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2SetBoolean(
            c: fmi2Component,
            vr: *const fmi2ValueReference,
            nvr: usize,
            value: *const fmi2Boolean,
        ) -> fmi2Status {
            unsafe { fmi2::set_boolean::<$model>(c, vr, nvr, value) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2SetString(
            c: fmi2Component,
            vr: *const fmi2ValueReference,
            nvr: usize,
            value: *const fmi2String,
        ) -> fmi2Status {
            unsafe { fmi2::set_string::<$model>(c, vr, nvr, value) }
        }

        // -----------------------------------------------------------------------------
        // Not supported (declared false in modelDescription.xml)

        #[no_mangle]
        pub unsafe extern "C" fn fmi2GetDirectionalDerivative(
            c: fmi2Component,
            _vUnknown_ref: *const fmi2ValueReference,
            _nUnknown: usize,
            _vKnown_ref: *const fmi2ValueReference,
            _nKnown: usize,
            _dvKnown: *const fmi2Real,
            _dvUnknown: *mut fmi2Real,
        ) -> fmi2Status {
            unsafe { fmi2::get_directional_derivative::<$model>(c) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2SetRealInputDerivatives(
            c: fmi2Component,
            _vr: *const fmi2ValueReference,
            _nvr: usize,
            _order: *const fmi2Integer,
            _value: *const fmi2Real,
        ) -> fmi2Status {
            unsafe { fmi2::set_real_input_derivatives::<$model>(c) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
            c: fmi2Component,
            _vr: *const fmi2ValueReference,
            _nvr: usize,
            _order: *const fmi2Integer,
            _value: *mut fmi2Real,
        ) -> fmi2Status {
            unsafe { fmi2::get_real_output_derivatives::<$model>(c) }
        }

        // -----------------------------------------------------------------------------
        // Co-simulation

        #[no_mangle]
        pub unsafe extern "C" fn fmi2DoStep(
            c: fmi2Component,
            currentCommunicationPoint: fmi2Real,
            communicationStepSize: fmi2Real,
            _noSetFMUStatePriorToCurrentPoint: fmi2Boolean,
        ) -> fmi2Status {
            unsafe { fmi2::do_step::<$model>(c, currentCommunicationPoint, communicationStepSize) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2CancelStep(c: fmi2Component) -> fmi2Status {
            unsafe { fmi2::cancel_step::<$model>(c) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2GetStatus(
            c: fmi2Component,
            _s: fmi2StatusKind,
            _value: *mut fmi2Status,
        ) -> fmi2Status {
            unsafe { fmi2::get_status::<$model>(c) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2GetRealStatus(
            c: fmi2Component,
            s: fmi2StatusKind,
            value: *mut fmi2Real,
        ) -> fmi2Status {
            unsafe { fmi2::get_real_status::<$model>(c, s, value) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2GetIntegerStatus(
            c: fmi2Component,
            _s: fmi2StatusKind,
            _value: *mut fmi2Integer,
        ) -> fmi2Status {
            unsafe { fmi2::get_integer_status::<$model>(c) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2GetBooleanStatus(
            c: fmi2Component,
            s: fmi2StatusKind,
            value: *mut fmi2Boolean,
        ) -> fmi2Status {
            unsafe { fmi2::get_boolean_status::<$model>(c, s, value) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2GetStringStatus(
            c: fmi2Component,
            _s: fmi2StatusKind,
            _value: *mut fmi2String,
        ) -> fmi2Status {
            unsafe { fmi2::get_string_status::<$model>(c) }
        }
    };
    (@states $model:ty) => {
        // -----------------------------------------------------------------------------
        // FMU state

        #[no_mangle]
        pub unsafe extern "C" fn fmi2GetFMUstate(
            c: fmi2Component,
            FMUstate: *mut fmi2FMUstate,
        ) -> fmi2Status {
            unsafe { fmi2::get_fmu_state::<$model>(c, FMUstate) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2SetFMUstate(
            c: fmi2Component,
            FMUstate: fmi2FMUstate,
        ) -> fmi2Status {
            unsafe { fmi2::set_fmu_state::<$model>(c, FMUstate) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2FreeFMUstate(
            c: fmi2Component,
            FMUstate: *mut fmi2FMUstate,
        ) -> fmi2Status {
            unsafe { fmi2::free_fmu_state::<$model>(c, FMUstate) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
            c: fmi2Component,
            FMUstate: fmi2FMUstate,
            size: *mut usize,
        ) -> fmi2Status {
            unsafe { fmi2::serialized_fmu_state_size::<$model>(c, FMUstate, size) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2SerializeFMUstate(
            c: fmi2Component,
            FMUstate: fmi2FMUstate,
            serializedState: *mut fmi2Byte,
            size: usize,
        ) -> fmi2Status {
            unsafe { fmi2::serialize_fmu_state::<$model>(c, FMUstate, serializedState, size) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
            c: fmi2Component,
            serializedState: *const fmi2Byte,
            size: usize,
            FMUstate: *mut fmi2FMUstate,
        ) -> fmi2Status {
            unsafe { fmi2::deserialize_fmu_state::<$model>(c, serializedState, size, FMUstate) }
        }
    };
    (@no_states $model:ty) => {
        // -----------------------------------------------------------------------------
        // FMU state: not provided (canGetAndSetFMUstate="false")

        use $crate::fmi2::machine::Call;

        #[no_mangle]
        pub unsafe extern "C" fn fmi2GetFMUstate(
            c: fmi2Component,
            _s: *mut fmi2FMUstate,
        ) -> fmi2Status {
            unsafe { fmi2::without_saved_states::<$model>(c, Call::GetFMUstate) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2SetFMUstate(
            c: fmi2Component,
            _s: fmi2FMUstate,
        ) -> fmi2Status {
            unsafe { fmi2::without_saved_states::<$model>(c, Call::SetFMUstate) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2FreeFMUstate(
            c: fmi2Component,
            _s: *mut fmi2FMUstate,
        ) -> fmi2Status {
            unsafe { fmi2::without_saved_states::<$model>(c, Call::FreeFMUstate) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
            c: fmi2Component,
            _s: fmi2FMUstate,
            _size: *mut usize,
        ) -> fmi2Status {
            unsafe { fmi2::without_saved_states::<$model>(c, Call::SerializedFMUstateSize) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2SerializeFMUstate(
            c: fmi2Component,
            _s: fmi2FMUstate,
            _bytes: *mut fmi2Byte,
            _size: usize,
        ) -> fmi2Status {
            unsafe { fmi2::without_saved_states::<$model>(c, Call::SerializeFMUstate) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
            c: fmi2Component,
            _bytes: *const fmi2Byte,
            _size: usize,
            _s: *mut fmi2FMUstate,
        ) -> fmi2Status {
            unsafe { fmi2::without_saved_states::<$model>(c, Call::DeSerializeFMUstate) }
        }
    };
}
