//! A minimal FMI 3.0 co-simulation master, as [`crate::master`] is for FMI 2.0: loads the
//! packed library with `dlopen` and drives it through the `fmi3*` C ABI only, knowing the
//! model from the archive's FMI 3.0 modelDescription.xml (its instantiation token and value
//! references by name).

use crate::master::{c_text, check, function, open, sample, ModelDescription, Variables};
use libloading::Library;
use std::ffi::{c_char, c_void, CString};
use std::path::Path;

type Instance = *mut c_void;
/// `fmi3Status` (a C enum).
type Status = i32;

/// `fmi3LogMessageCallback`.
unsafe extern "C" fn print_log(
    _env: *mut c_void,
    status: Status,
    category: *const c_char,
    message: *const c_char,
) {
    // SAFETY: the FMU passes NUL-terminated strings valid for the call.
    let text = |p| unsafe { c_text(p) };
    eprintln!("{} ({status}): {}", text(category), text(message));
}

type Logger = unsafe extern "C" fn(*mut c_void, Status, *const c_char, *const c_char);

/// The functions this master calls, resolved once (with the FMI 3.0 signatures of
/// `fmi3FunctionTypes.h`; `fmi3Boolean` is C `bool`).
pub struct Fmu {
    _library: Library,
    #[allow(clippy::type_complexity)]
    instantiate: unsafe extern "C" fn(
        *const c_char,
        *const c_char,
        *const c_char,
        bool,
        bool,
        bool,
        bool,
        *const u32,
        usize,
        *mut c_void,
        Option<Logger>,
        *const c_void,
    ) -> Instance,
    enter_initialization: unsafe extern "C" fn(Instance, bool, f64, f64, bool, f64) -> Status,
    exit_initialization: unsafe extern "C" fn(Instance) -> Status,
    #[allow(clippy::type_complexity)]
    do_step: unsafe extern "C" fn(
        Instance,
        f64,
        f64,
        bool,
        *mut bool,
        *mut bool,
        *mut bool,
        *mut f64,
    ) -> Status,
    get_float64: unsafe extern "C" fn(Instance, *const u32, usize, *mut f64, usize) -> Status,
    set_float64: unsafe extern "C" fn(Instance, *const u32, usize, *const f64, usize) -> Status,
    terminate: unsafe extern "C" fn(Instance) -> Status,
    free_instance: unsafe extern "C" fn(Instance),
}

impl Fmu {
    /// Loads the library and resolves the functions (any missing one is an error).
    pub fn load(path: &Path) -> Result<Self, String> {
        let library = open(path)?;
        // SAFETY: each field's type is the FMI 3.0 signature of the function it is read from.
        Ok(unsafe {
            Fmu {
                instantiate: function(&library, "fmi3InstantiateCoSimulation")?,
                enter_initialization: function(&library, "fmi3EnterInitializationMode")?,
                exit_initialization: function(&library, "fmi3ExitInitializationMode")?,
                do_step: function(&library, "fmi3DoStep")?,
                get_float64: function(&library, "fmi3GetFloat64")?,
                set_float64: function(&library, "fmi3SetFloat64")?,
                terminate: function(&library, "fmi3Terminate")?,
                free_instance: function(&library, "fmi3FreeInstance")?,
                _library: library,
            }
        })
    }
}

/// [`crate::master::run`] through FMI 3.0: the same samples (outputs `k` at every
/// communication point from the start), with the resources as a native path
/// (`resource_path`, ending in a separator).
pub fn run(
    fmu: &Fmu,
    description: &ModelDescription,
    resource_path: &str,
    (inputs, outputs): (&[(&str, f64)], &[&str]),
    (start, stop, step): (f64, f64, f64),
) -> Result<Vec<Vec<f64>>, String> {
    let variables = Variables::of(description, inputs, outputs)?;
    let name = CString::new("fmu-pack").expect("no NUL");
    let token = CString::new(description.guid.clone()).map_err(|e| e.to_string())?;
    let path = CString::new(resource_path).map_err(|e| e.to_string())?;
    // SAFETY: FMI 3.0 calling sequence on a valid instance; pointers outlive the calls.
    unsafe {
        let c = (fmu.instantiate)(
            name.as_ptr(),
            token.as_ptr(),
            path.as_ptr(),
            false,
            false,
            false,
            false,
            std::ptr::null(),
            0,
            std::ptr::null_mut(),
            Some(print_log),
            std::ptr::null(),
        );
        if c.is_null() {
            return Err("fmi3InstantiateCoSimulation returned NULL".into());
        }
        let result = (|| {
            check(
                "fmi3EnterInitializationMode",
                (fmu.enter_initialization)(c, false, 0.0, start, true, stop),
            )?;
            let Variables {
                outputs: references,
                inputs,
                values,
            } = &variables;
            check(
                "fmi3SetFloat64",
                (fmu.set_float64)(
                    c,
                    inputs.as_ptr(),
                    inputs.len(),
                    values.as_ptr(),
                    values.len(),
                ),
            )?;
            check("fmi3ExitInitializationMode", (fmu.exit_initialization)(c))?;
            let (mut event, mut terminate, mut early, mut last) = (false, false, false, 0.0);
            let samples = sample(
                (start, stop, step),
                references.len(),
                |t| {
                    check(
                        "fmi3DoStep",
                        (fmu.do_step)(
                            c,
                            t,
                            step,
                            true,
                            &mut event,
                            &mut terminate,
                            &mut early,
                            &mut last,
                        ),
                    )?;
                    if event || terminate || early || last != t + step {
                        return Err(format!(
                            "fmi3DoStep at {t} s: eventHandlingNeeded {event}, \
                             terminateSimulation {terminate}, earlyReturn {early}, \
                             lastSuccessfulTime {last} s"
                        ));
                    }
                    Ok(())
                },
                |values| {
                    let (r, n) = (references.as_ptr(), references.len());
                    let read = (fmu.get_float64)(c, r, n, values.as_mut_ptr(), values.len());
                    check("fmi3GetFloat64", read)
                },
            )?;
            check("fmi3Terminate", (fmu.terminate)(c))?;
            Ok(samples)
        })();
        (fmu.free_instance)(c);
        result
    }
}
