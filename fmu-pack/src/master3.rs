//! A minimal FMI 3.0 co-simulation master, as [`crate::master`] is for FMI 2.0: loads the
//! packed library with `dlopen` and drives it through the `fmi3*` C ABI only, knowing the
//! model from the archive's FMI 3.0 modelDescription.xml (its instantiation token and value
//! references by name).

use crate::master::ModelDescription;
use libloading::{Library, Symbol};
use std::ffi::{c_char, c_void, CStr, CString};
use std::path::Path;

type Instance = *mut c_void;
/// `fmi3Status` (a C enum).
type Status = i32;
const OK: Status = 0;
const WARNING: Status = 1;

/// `fmi3LogMessageCallback`.
unsafe extern "C" fn print_log(
    _env: *mut c_void,
    status: Status,
    category: *const c_char,
    message: *const c_char,
) {
    let text = |p: *const c_char| {
        if p.is_null() {
            "(null)".to_string()
        } else {
            // SAFETY: the FMU passes NUL-terminated strings valid for the call.
            unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned()
        }
    };
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
        // SAFETY: loading the FMU's library runs no initialisers beyond Rust's runtime.
        let library =
            unsafe { Library::new(path) }.map_err(|e| format!("dlopen {}: {e}", path.display()))?;
        fn get<T: Copy>(library: &Library, name: &str) -> Result<T, String> {
            // SAFETY: the symbol has the FMI 3.0 signature T.
            let symbol: Symbol<T> =
                unsafe { library.get(name.as_bytes()) }.map_err(|e| format!("{name}: {e}"))?;
            Ok(*symbol)
        }
        Ok(Fmu {
            instantiate: get(&library, "fmi3InstantiateCoSimulation")?,
            enter_initialization: get(&library, "fmi3EnterInitializationMode")?,
            exit_initialization: get(&library, "fmi3ExitInitializationMode")?,
            do_step: get(&library, "fmi3DoStep")?,
            get_float64: get(&library, "fmi3GetFloat64")?,
            set_float64: get(&library, "fmi3SetFloat64")?,
            terminate: get(&library, "fmi3Terminate")?,
            free_instance: get(&library, "fmi3FreeInstance")?,
            _library: library,
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
    let references = outputs
        .iter()
        .map(|n| description.value_reference(n))
        .collect::<Result<Vec<_>, _>>()?;
    let input_references = inputs
        .iter()
        .map(|(n, _)| description.value_reference(n))
        .collect::<Result<Vec<_>, _>>()?;
    let input_values: Vec<f64> = inputs.iter().map(|(_, v)| *v).collect();
    let name = CString::new("fmu-pack").expect("no NUL");
    let token = CString::new(description.guid.clone()).map_err(|e| e.to_string())?;
    let path = CString::new(resource_path).map_err(|e| e.to_string())?;
    let check = |what: &str, status: Status| {
        if status == OK || status == WARNING {
            Ok(())
        } else {
            Err(format!("{what} returned status {status}"))
        }
    };
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
            check(
                "fmi3SetFloat64",
                (fmu.set_float64)(
                    c,
                    input_references.as_ptr(),
                    input_references.len(),
                    input_values.as_ptr(),
                    input_values.len(),
                ),
            )?;
            check("fmi3ExitInitializationMode", (fmu.exit_initialization)(c))?;
            let steps = ((stop - start) / step).round() as usize;
            let mut samples = vec![Vec::with_capacity(steps + 1); outputs.len()];
            let mut values = vec![0.0; outputs.len()];
            let (mut event, mut terminate, mut early, mut last) = (false, false, false, 0.0);
            for n in 0..=steps {
                if n > 0 {
                    let t = start + (n - 1) as f64 * step;
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
                }
                check(
                    "fmi3GetFloat64",
                    (fmu.get_float64)(
                        c,
                        references.as_ptr(),
                        references.len(),
                        values.as_mut_ptr(),
                        values.len(),
                    ),
                )?;
                for (s, v) in samples.iter_mut().zip(&values) {
                    s.push(*v);
                }
            }
            check("fmi3Terminate", (fmu.terminate)(c))?;
            Ok(samples)
        })();
        (fmu.free_instance)(c);
        result
    }
}
