//! [`crate::fmi3_exports`]: every FMI 3.0 function as an `extern "C"` symbol of a cdylib,
//! for its model: thin shims that call [`crate::fmi3::functions`] (the layer checks the call,
//! turns the pointers into references, runs the model behind its firewall and reports the
//! result). One macro call makes all 75, so a new FMU of the layer cannot miss one (fmpy
//! refuses a library that lacks any).

/// The 75 `#[no_mangle] extern "C" fn fmi3*` of FMI 3.0 for the model `$model`, whose FMI
/// 3.0 value references are its FMI 2.0 ones numbered by `$numbering` (a
/// [`crate::fmi3::Numbering`]): a [`crate::fmi2::Model`] with [`crate::fmi2::SavedStates`],
/// or, written `fmi3_exports!(Model, NUMBERING, without_saved_states)`, one without (the six
/// state functions then answer `fmi3Error`: `canGetAndSetFMUState="false"`). Call it in a module of its own in
/// the cdylib crate: the expansion imports the FMI 3.0 types there. The cdylib's linker
/// version script exports `fmi3*` beside `fmi2*`.
#[macro_export]
macro_rules! fmi3_exports {
    ($model:ty, $numbering:expr) => {
        $crate::fmi3_exports!(@common $model, $numbering);
        $crate::fmi3_exports!(@states $model);
    };
    ($model:ty, $numbering:expr, without_saved_states) => {
        $crate::fmi3_exports!(@common $model, $numbering);
        $crate::fmi3_exports!(@no_states $model);
    };
    (@common $model:ty, $numbering:expr) => {
        use $crate::fmi3::functions as fmi3;
        use $crate::fmi3::functions::why;
        use $crate::fmi3::types::*;
        use std::ffi::c_char;

        // -----------------------------------------------------------------------------
        // Inquire version numbers, set debug logging

        #[no_mangle]
        pub extern "C" fn fmi3GetVersion() -> *const c_char {
            fmi3::get_version()
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetDebugLogging(
            instance: fmi3Instance,
            loggingOn: fmi3Boolean,
            nCategories: usize,
            categories: *const fmi3String,
        ) -> fmi3Status {
            unsafe { fmi3::set_debug_logging::<$model>(instance, loggingOn, nCategories, categories) }
        }

        // -----------------------------------------------------------------------------
        // Creation and destruction of instances

        #[no_mangle]
        pub extern "C" fn fmi3InstantiateModelExchange(
            _instanceName: fmi3String,
            _instantiationToken: fmi3String,
            _resourcePath: fmi3String,
            _visible: fmi3Boolean,
            _loggingOn: fmi3Boolean,
            instanceEnvironment: fmi3InstanceEnvironment,
            logMessage: Option<fmi3LogMessageCallback>,
        ) -> fmi3Instance {
            fmi3::refuse_instantiation::<$model>(
                "fmi3InstantiateModelExchange",
                why::MODEL_EXCHANGE,
                instanceEnvironment,
                logMessage,
            )
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3InstantiateCoSimulation(
            instanceName: fmi3String,
            instantiationToken: fmi3String,
            resourcePath: fmi3String,
            _visible: fmi3Boolean,
            loggingOn: fmi3Boolean,
            eventModeUsed: fmi3Boolean,
            earlyReturnAllowed: fmi3Boolean,
            _requiredIntermediateVariables: *const fmi3ValueReference,
            nRequiredIntermediateVariables: usize,
            instanceEnvironment: fmi3InstanceEnvironment,
            logMessage: Option<fmi3LogMessageCallback>,
            _intermediateUpdate: Option<fmi3IntermediateUpdateCallback>,
        ) -> fmi3Instance {
            unsafe {
                fmi3::instantiate_co_simulation::<$model>(
                    instanceName,
                    instantiationToken,
                    resourcePath,
                    loggingOn,
                    eventModeUsed,
                    earlyReturnAllowed,
                    nRequiredIntermediateVariables,
                    instanceEnvironment,
                    logMessage,
                )
            }
        }

        #[no_mangle]
        pub extern "C" fn fmi3InstantiateScheduledExecution(
            _instanceName: fmi3String,
            _instantiationToken: fmi3String,
            _resourcePath: fmi3String,
            _visible: fmi3Boolean,
            _loggingOn: fmi3Boolean,
            instanceEnvironment: fmi3InstanceEnvironment,
            logMessage: Option<fmi3LogMessageCallback>,
            _clockUpdate: Option<fmi3ClockUpdateCallback>,
            _lockPreemption: Option<fmi3LockPreemptionCallback>,
            _unlockPreemption: Option<fmi3UnlockPreemptionCallback>,
        ) -> fmi3Instance {
            fmi3::refuse_instantiation::<$model>(
                "fmi3InstantiateScheduledExecution",
                why::SCHEDULED_EXECUTION,
                instanceEnvironment,
                logMessage,
            )
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3FreeInstance(instance: fmi3Instance) {
            unsafe { fmi3::free_instance::<$model>(instance) }
        }

        // -----------------------------------------------------------------------------
        // Enter and exit initialization mode, enter event mode, terminate and reset

        #[no_mangle]
        pub unsafe extern "C" fn fmi3EnterInitializationMode(
            instance: fmi3Instance,
            _toleranceDefined: fmi3Boolean,
            _tolerance: fmi3Float64,
            startTime: fmi3Float64,
            stopTimeDefined: fmi3Boolean,
            stopTime: fmi3Float64,
        ) -> fmi3Status {
            unsafe {
                fmi3::enter_initialization_mode::<$model>(instance, startTime, stopTimeDefined, stopTime)
            }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3ExitInitializationMode(instance: fmi3Instance) -> fmi3Status {
            unsafe { fmi3::exit_initialization_mode::<$model>(instance) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3EnterEventMode(instance: fmi3Instance) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3EnterEventMode", why::EVENT_MODE) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3Terminate(instance: fmi3Instance) -> fmi3Status {
            unsafe { fmi3::terminate::<$model>(instance) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3Reset(instance: fmi3Instance) -> fmi3Status {
            unsafe { fmi3::reset::<$model>(instance) }
        }

        // -----------------------------------------------------------------------------
        // Getting and setting variable values

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetFloat32(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut fmi3Float32,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3GetFloat32", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetFloat64(
            instance: fmi3Instance,
            valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            values: *mut fmi3Float64,
            nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::get_float64::<$model>(instance, $numbering, valueReferences, nValueReferences, values, nValues) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetInt8(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut fmi3Int8,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3GetInt8", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetUInt8(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut fmi3UInt8,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3GetUInt8", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetInt16(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut fmi3Int16,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3GetInt16", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetUInt16(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut fmi3UInt16,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3GetUInt16", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetInt32(
            instance: fmi3Instance,
            valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            values: *mut fmi3Int32,
            nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::get_int32::<$model>(instance, $numbering, valueReferences, nValueReferences, values, nValues) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetUInt32(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut fmi3UInt32,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3GetUInt32", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetInt64(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut fmi3Int64,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3GetInt64", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetUInt64(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut fmi3UInt64,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3GetUInt64", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetBoolean(
            instance: fmi3Instance,
            valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            values: *mut fmi3Boolean,
            nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::get_boolean::<$model>(instance, $numbering, valueReferences, nValueReferences, values, nValues) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetString(
            instance: fmi3Instance,
            valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            values: *mut fmi3String,
            nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::get_string::<$model>(instance, $numbering, valueReferences, nValueReferences, values, nValues) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetBinary(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _valueSizes: *mut usize,
            _values: *mut fmi3Binary,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3GetBinary", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetClock(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut fmi3Clock,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3GetClock", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetFloat32(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *const fmi3Float32,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3SetFloat32", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetFloat64(
            instance: fmi3Instance,
            valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            values: *const fmi3Float64,
            nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::set_float64::<$model>(instance, $numbering, valueReferences, nValueReferences, values, nValues) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetInt8(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *const fmi3Int8,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3SetInt8", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetUInt8(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *const fmi3UInt8,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3SetUInt8", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetInt16(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *const fmi3Int16,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3SetInt16", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetUInt16(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *const fmi3UInt16,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3SetUInt16", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetInt32(
            instance: fmi3Instance,
            valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            values: *const fmi3Int32,
            nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::set_int32::<$model>(instance, $numbering, valueReferences, nValueReferences, values, nValues) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetUInt32(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *const fmi3UInt32,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3SetUInt32", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetInt64(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *const fmi3Int64,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3SetInt64", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetUInt64(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *const fmi3UInt64,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3SetUInt64", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetBoolean(
            instance: fmi3Instance,
            valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            values: *const fmi3Boolean,
            nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::set_boolean::<$model>(instance, $numbering, valueReferences, nValueReferences, values, nValues) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetString(
            instance: fmi3Instance,
            valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            values: *const fmi3String,
            nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::set_string::<$model>(instance, $numbering, valueReferences, nValueReferences, values, nValues) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetBinary(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _valueSizes: *const usize,
            _values: *const fmi3Binary,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3SetBinary", nValueReferences) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetClock(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            _values: *const fmi3Clock,
        ) -> fmi3Status {
            unsafe { fmi3::no_variable_of_type::<$model>(instance, "fmi3SetClock", nValueReferences) }
        }

        // -----------------------------------------------------------------------------
        // Variable dependencies

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetNumberOfVariableDependencies(
            instance: fmi3Instance,
            _valueReference: fmi3ValueReference,
            _nDependencies: *mut usize,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetNumberOfVariableDependencies", why::DEPENDENCIES) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetVariableDependencies(
            instance: fmi3Instance,
            _dependent: fmi3ValueReference,
            _elementIndicesOfDependent: *mut usize,
            _independents: *mut fmi3ValueReference,
            _elementIndicesOfIndependents: *mut usize,
            _dependencyKinds: *mut fmi3DependencyKind,
            _nDependencies: usize,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetVariableDependencies", why::DEPENDENCIES) }
        }

        // -----------------------------------------------------------------------------
        // Getting partial derivatives

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetDirectionalDerivative(
            instance: fmi3Instance,
            _unknowns: *const fmi3ValueReference,
            _nUnknowns: usize,
            _knowns: *const fmi3ValueReference,
            _nKnowns: usize,
            _seed: *const fmi3Float64,
            _nSeed: usize,
            _sensitivity: *mut fmi3Float64,
            _nSensitivity: usize,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetDirectionalDerivative", why::DERIVATIVES) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetAdjointDerivative(
            instance: fmi3Instance,
            _unknowns: *const fmi3ValueReference,
            _nUnknowns: usize,
            _knowns: *const fmi3ValueReference,
            _nKnowns: usize,
            _seed: *const fmi3Float64,
            _nSeed: usize,
            _sensitivity: *mut fmi3Float64,
            _nSensitivity: usize,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetAdjointDerivative", why::DERIVATIVES) }
        }

        // -----------------------------------------------------------------------------
        // Entering and exiting the Configuration or Reconfiguration Mode

        #[no_mangle]
        pub unsafe extern "C" fn fmi3EnterConfigurationMode(
            instance: fmi3Instance,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3EnterConfigurationMode", why::CONFIGURATION) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3ExitConfigurationMode(
            instance: fmi3Instance,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3ExitConfigurationMode", why::CONFIGURATION) }
        }

        // -----------------------------------------------------------------------------
        // Clock related functions

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetIntervalDecimal(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            _nValueReferences: usize,
            _intervals: *mut fmi3Float64,
            _qualifiers: *mut fmi3IntervalQualifier,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetIntervalDecimal", why::CLOCKS) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetIntervalFraction(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            _nValueReferences: usize,
            _counters: *mut fmi3UInt64,
            _resolutions: *mut fmi3UInt64,
            _qualifiers: *mut fmi3IntervalQualifier,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetIntervalFraction", why::CLOCKS) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetShiftDecimal(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            _nValueReferences: usize,
            _shifts: *mut fmi3Float64,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetShiftDecimal", why::CLOCKS) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetShiftFraction(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            _nValueReferences: usize,
            _counters: *mut fmi3UInt64,
            _resolutions: *mut fmi3UInt64,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetShiftFraction", why::CLOCKS) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetIntervalDecimal(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            _nValueReferences: usize,
            _intervals: *const fmi3Float64,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3SetIntervalDecimal", why::CLOCKS) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetIntervalFraction(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            _nValueReferences: usize,
            _counters: *const fmi3UInt64,
            _resolutions: *const fmi3UInt64,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3SetIntervalFraction", why::CLOCKS) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetShiftDecimal(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            _nValueReferences: usize,
            _shifts: *const fmi3Float64,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3SetShiftDecimal", why::CLOCKS) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetShiftFraction(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            _nValueReferences: usize,
            _counters: *const fmi3UInt64,
            _resolutions: *const fmi3UInt64,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3SetShiftFraction", why::CLOCKS) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3EvaluateDiscreteStates(
            instance: fmi3Instance,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3EvaluateDiscreteStates", why::EVENT_MODE) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3UpdateDiscreteStates(
            instance: fmi3Instance,
            _discreteStatesNeedUpdate: *mut fmi3Boolean,
            _terminateSimulation: *mut fmi3Boolean,
            _nominalsOfContinuousStatesChanged: *mut fmi3Boolean,
            _valuesOfContinuousStatesChanged: *mut fmi3Boolean,
            _nextEventTimeDefined: *mut fmi3Boolean,
            _nextEventTime: *mut fmi3Float64,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3UpdateDiscreteStates", why::EVENT_MODE) }
        }

        // -----------------------------------------------------------------------------
        // Functions for Model Exchange

        #[no_mangle]
        pub unsafe extern "C" fn fmi3EnterContinuousTimeMode(
            instance: fmi3Instance,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3EnterContinuousTimeMode", why::MODEL_EXCHANGE) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3CompletedIntegratorStep(
            instance: fmi3Instance,
            _noSetFMUStatePriorToCurrentPoint: fmi3Boolean,
            _enterEventMode: *mut fmi3Boolean,
            _terminateSimulation: *mut fmi3Boolean,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3CompletedIntegratorStep", why::MODEL_EXCHANGE) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetTime(
            instance: fmi3Instance,
            _time: fmi3Float64,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3SetTime", why::MODEL_EXCHANGE) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetContinuousStates(
            instance: fmi3Instance,
            _continuousStates: *const fmi3Float64,
            _nContinuousStates: usize,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3SetContinuousStates", why::MODEL_EXCHANGE) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetContinuousStateDerivatives(
            instance: fmi3Instance,
            _derivatives: *mut fmi3Float64,
            _nContinuousStates: usize,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetContinuousStateDerivatives", why::MODEL_EXCHANGE) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetEventIndicators(
            instance: fmi3Instance,
            _eventIndicators: *mut fmi3Float64,
            _nEventIndicators: usize,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetEventIndicators", why::MODEL_EXCHANGE) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetContinuousStates(
            instance: fmi3Instance,
            _continuousStates: *mut fmi3Float64,
            _nContinuousStates: usize,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetContinuousStates", why::MODEL_EXCHANGE) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetNominalsOfContinuousStates(
            instance: fmi3Instance,
            _nominals: *mut fmi3Float64,
            _nContinuousStates: usize,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetNominalsOfContinuousStates", why::MODEL_EXCHANGE) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetNumberOfEventIndicators(
            instance: fmi3Instance,
            _nEventIndicators: *mut usize,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetNumberOfEventIndicators", why::MODEL_EXCHANGE) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetNumberOfContinuousStates(
            instance: fmi3Instance,
            _nContinuousStates: *mut usize,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetNumberOfContinuousStates", why::MODEL_EXCHANGE) }
        }

        // -----------------------------------------------------------------------------
        // Functions for Co-Simulation

        #[no_mangle]
        pub unsafe extern "C" fn fmi3EnterStepMode(
            instance: fmi3Instance,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3EnterStepMode", why::EVENT_MODE) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetOutputDerivatives(
            instance: fmi3Instance,
            _valueReferences: *const fmi3ValueReference,
            _nValueReferences: usize,
            _orders: *const fmi3Int32,
            _values: *mut fmi3Float64,
            _nValues: usize,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetOutputDerivatives", why::OUTPUT_DERIVATIVES) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3DoStep(
            instance: fmi3Instance,
            currentCommunicationPoint: fmi3Float64,
            communicationStepSize: fmi3Float64,
            _noSetFMUStatePriorToCurrentPoint: fmi3Boolean,
            eventHandlingNeeded: *mut fmi3Boolean,
            terminateSimulation: *mut fmi3Boolean,
            earlyReturn: *mut fmi3Boolean,
            lastSuccessfulTime: *mut fmi3Float64,
        ) -> fmi3Status {
            unsafe {
                fmi3::do_step::<$model>(
                    instance,
                    currentCommunicationPoint,
                    communicationStepSize,
                    eventHandlingNeeded,
                    terminateSimulation,
                    earlyReturn,
                    lastSuccessfulTime,
                )
            }
        }

        // -----------------------------------------------------------------------------
        // Functions for Scheduled Execution

        #[no_mangle]
        pub unsafe extern "C" fn fmi3ActivateModelPartition(
            instance: fmi3Instance,
            _clockReference: fmi3ValueReference,
            _activationTime: fmi3Float64,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3ActivateModelPartition", why::SCHEDULED_EXECUTION) }
        }
    };
    (@states $model:ty) => {
        // -----------------------------------------------------------------------------
        // Getting and setting the internal FMU state

        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetFMUState(
            instance: fmi3Instance,
            FMUState: *mut fmi3FMUState,
        ) -> fmi3Status {
            unsafe { fmi3::get_fmu_state::<$model>(instance, FMUState) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetFMUState(
            instance: fmi3Instance,
            FMUState: fmi3FMUState,
        ) -> fmi3Status {
            unsafe { fmi3::set_fmu_state::<$model>(instance, FMUState) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3FreeFMUState(
            instance: fmi3Instance,
            FMUState: *mut fmi3FMUState,
        ) -> fmi3Status {
            unsafe { fmi3::free_fmu_state::<$model>(instance, FMUState) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SerializedFMUStateSize(
            instance: fmi3Instance,
            FMUState: fmi3FMUState,
            size: *mut usize,
        ) -> fmi3Status {
            unsafe { fmi3::serialized_fmu_state_size::<$model>(instance, FMUState, size) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SerializeFMUState(
            instance: fmi3Instance,
            FMUState: fmi3FMUState,
            serializedState: *mut fmi3Byte,
            size: usize,
        ) -> fmi3Status {
            unsafe { fmi3::serialize_fmu_state::<$model>(instance, FMUState, serializedState, size) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3DeserializeFMUState(
            instance: fmi3Instance,
            serializedState: *const fmi3Byte,
            size: usize,
            FMUState: *mut fmi3FMUState,
        ) -> fmi3Status {
            unsafe { fmi3::deserialize_fmu_state::<$model>(instance, serializedState, size, FMUState) }
        }

    };

    (@no_states $model:ty) => {
        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetFMUState(
            instance: fmi3Instance,
            _FMUState: *mut fmi3FMUState,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3GetFMUState", why::STATES) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SetFMUState(
            instance: fmi3Instance,
            _FMUState: fmi3FMUState,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3SetFMUState", why::STATES) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3FreeFMUState(
            instance: fmi3Instance,
            _FMUState: *mut fmi3FMUState,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3FreeFMUState", why::STATES) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SerializedFMUStateSize(
            instance: fmi3Instance,
            _FMUState: fmi3FMUState,
            _size: *mut usize,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3SerializedFMUStateSize", why::STATES) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3SerializeFMUState(
            instance: fmi3Instance,
            _FMUState: fmi3FMUState,
            _serializedState: *mut fmi3Byte,
            _size: usize,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3SerializeFMUState", why::STATES) }
        }

        #[no_mangle]
        pub unsafe extern "C" fn fmi3DeserializeFMUState(
            instance: fmi3Instance,
            _serializedState: *const fmi3Byte,
            _size: usize,
            _FMUState: *mut fmi3FMUState,
        ) -> fmi3Status {
            unsafe { fmi3::unsupported::<$model>(instance, "fmi3DeserializeFMUState", why::STATES) }
        }
    };
}
