//! A minimal FMI 2.0 co-simulation master: loads the packed library with `dlopen`, as fmpy
//! or any other master would, and drives it through its C ABI only. It knows the model only
//! from the archive's modelDescription.xml (GUID and value references by variable name),
//! not from the SlowDrift crate, so it checks the FMU from the outside.

use libloading::{Library, Symbol};
use std::ffi::{c_char, c_int, c_uint, c_void, CStr, CString};
use std::path::Path;

type Component = *mut c_void;
type Status = c_int;
const OK: Status = 0;
const WARNING: Status = 1;
const CO_SIMULATION: c_int = 1;
const FALSE: c_int = 0;
const TRUE: c_int = 1;

/// The logger as masters declare it; SlowDrift passes the text with '%' escaped and no
/// variable arguments, so the fixed parameters are all this master reads.
type Logger =
    unsafe extern "C" fn(*mut c_void, *const c_char, Status, *const c_char, *const c_char);

#[repr(C)]
struct CallbackFunctions {
    logger: Option<Logger>,
    allocate_memory: Option<unsafe extern "C" fn(usize, usize) -> *mut c_void>,
    free_memory: Option<unsafe extern "C" fn(*mut c_void)>,
    step_finished: Option<unsafe extern "C" fn(*mut c_void, Status)>,
    component_environment: *mut c_void,
}

unsafe extern "C" fn print_log(
    _env: *mut c_void,
    instance: *const c_char,
    status: Status,
    category: *const c_char,
    message: *const c_char,
) {
    // SAFETY: the FMU passes NUL-terminated strings valid for the call.
    let text = |p| unsafe { c_text(p) };
    eprintln!(
        "[{}] {} ({status}): {}",
        text(instance),
        text(category),
        text(message)
    );
}

/// A C string the FMU passed, as text ("(null)" for NULL).
///
/// # Safety
/// `p` is NULL or a NUL-terminated string valid for the call.
pub(crate) unsafe fn c_text(p: *const c_char) -> String {
    if p.is_null() {
        "(null)".to_string()
    } else {
        // SAFETY: the caller's contract.
        unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned()
    }
}

/// The GUID (FMI 3.0: the instantiation token) and the value reference of each named
/// variable, read from the XML text.
pub struct ModelDescription {
    pub guid: String,
    xml: String,
}

impl ModelDescription {
    pub fn parse(xml: String) -> Result<Self, String> {
        let guid = attribute(&xml, "guid").ok_or("modelDescription.xml has no guid")?;
        Ok(ModelDescription { guid, xml })
    }

    /// An FMI 3.0 description: its `instantiationToken` in place of the GUID.
    pub fn parse_fmi3(xml: String) -> Result<Self, String> {
        let guid = attribute(&xml, "instantiationToken")
            .ok_or("modelDescription.xml has no instantiationToken")?;
        Ok(ModelDescription { guid, xml })
    }

    /// Value reference of the ScalarVariable called `name`.
    pub fn value_reference(&self, name: &str) -> Result<c_uint, String> {
        let key = format!("name=\"{name}\"");
        let at = self
            .xml
            .find(&key)
            .ok_or_else(|| format!("no variable {name}"))?;
        let element_end = self.xml[at..]
            .find('>')
            .map(|e| at + e)
            .unwrap_or(self.xml.len());
        attribute(&self.xml[at..element_end], "valueReference")
            .and_then(|v| v.parse().ok())
            .ok_or_else(|| format!("variable {name} has no valueReference"))
    }
}

fn attribute(text: &str, name: &str) -> Option<String> {
    let key = format!(" {name}=\"");
    let start = text.find(&key)? + key.len();
    let end = text[start..].find('"')? + start;
    Some(text[start..end].to_string())
}

/// The functions this master calls, resolved once.
pub struct Fmu {
    _library: Library,
    instantiate: unsafe extern "C" fn(
        *const c_char,
        c_int,
        *const c_char,
        *const c_char,
        *const CallbackFunctions,
        c_int,
        c_int,
    ) -> Component,
    setup_experiment: unsafe extern "C" fn(Component, c_int, f64, f64, c_int, f64) -> Status,
    enter_initialization: unsafe extern "C" fn(Component) -> Status,
    exit_initialization: unsafe extern "C" fn(Component) -> Status,
    do_step: unsafe extern "C" fn(Component, f64, f64, c_int) -> Status,
    get_real: unsafe extern "C" fn(Component, *const c_uint, usize, *mut f64) -> Status,
    set_real: unsafe extern "C" fn(Component, *const c_uint, usize, *const f64) -> Status,
    terminate: unsafe extern "C" fn(Component) -> Status,
    free_instance: unsafe extern "C" fn(Component),
}

impl Fmu {
    /// Loads the library and resolves the functions (any missing one is an error).
    pub fn load(path: &Path) -> Result<Self, String> {
        let library = open(path)?;
        // SAFETY: each field's type is the FMI 2.0 signature of the function it is read from.
        Ok(unsafe {
            Fmu {
                instantiate: function(&library, "fmi2Instantiate")?,
                setup_experiment: function(&library, "fmi2SetupExperiment")?,
                enter_initialization: function(&library, "fmi2EnterInitializationMode")?,
                exit_initialization: function(&library, "fmi2ExitInitializationMode")?,
                do_step: function(&library, "fmi2DoStep")?,
                get_real: function(&library, "fmi2GetReal")?,
                set_real: function(&library, "fmi2SetReal")?,
                terminate: function(&library, "fmi2Terminate")?,
                free_instance: function(&library, "fmi2FreeInstance")?,
                _library: library,
            }
        })
    }
}

/// The FMU's library, loaded as a master loads it.
pub(crate) fn open(path: &Path) -> Result<Library, String> {
    // SAFETY: loading the FMU's library runs no initialisers beyond Rust's runtime.
    unsafe { Library::new(path) }.map_err(|e| format!("dlopen {}: {e}", path.display()))
}

/// The function `name` of `library` (a missing one is an error naming it).
///
/// # Safety
/// `T` is the function's C signature.
pub(crate) unsafe fn function<T: Copy>(library: &Library, name: &str) -> Result<T, String> {
    // SAFETY: the caller's contract.
    let symbol: Symbol<T> =
        unsafe { library.get(name.as_bytes()) }.map_err(|e| format!("{name}: {e}"))?;
    Ok(*symbol)
}

/// A run's variables: the outputs' value references, the inputs' and the inputs' values.
pub(crate) struct Variables {
    pub outputs: Vec<c_uint>,
    pub inputs: Vec<c_uint>,
    pub values: Vec<f64>,
}

impl Variables {
    /// The named inputs (with their values) and outputs of `description`.
    pub(crate) fn of(
        description: &ModelDescription,
        inputs: &[(&str, f64)],
        outputs: &[&str],
    ) -> Result<Self, String> {
        let reference = |n: &str| description.value_reference(n);
        Ok(Variables {
            outputs: outputs
                .iter()
                .map(|n| reference(n))
                .collect::<Result<_, _>>()?,
            inputs: inputs
                .iter()
                .map(|(n, _)| reference(n))
                .collect::<Result<_, _>>()?,
            values: inputs.iter().map(|(_, v)| *v).collect(),
        })
    }
}

/// A call's status as a result: OK and Warning (0 and 1 in FMI 2.0 and 3.0) pass.
pub(crate) fn check(what: &str, status: c_int) -> Result<(), String> {
    if status == OK || status == WARNING {
        Ok(())
    } else {
        Err(format!("{what} returned status {status}"))
    }
}

/// The samples of `outputs` outputs at every communication point from `start` to `stop`
/// by `step`: `read` at the start, then after each `advance(t)` (the step from t). Output
/// `k` is `samples[k]`.
pub(crate) fn sample(
    (start, stop, step): (f64, f64, f64),
    outputs: usize,
    mut advance: impl FnMut(f64) -> Result<(), String>,
    mut read: impl FnMut(&mut [f64]) -> Result<(), String>,
) -> Result<Vec<Vec<f64>>, String> {
    let steps = ((stop - start) / step).round() as usize;
    let mut samples = vec![Vec::with_capacity(steps + 1); outputs];
    let mut values = vec![0.0; outputs];
    for n in 0..=steps {
        if n > 0 {
            advance(start + (n - 1) as f64 * step)?;
        }
        read(&mut values)?;
        for (s, v) in samples.iter_mut().zip(&values) {
            s.push(*v);
        }
    }
    Ok(samples)
}

/// Runs one instance from `start` to `stop` at communication step `step` with the named
/// Real inputs held at the given values (set in initialisation mode; the others at their
/// start values) and returns the samples of the named real outputs at every communication
/// point from the start: `samples[k][m]` is output `k` at t = start + m step, m = 0 ..= the
/// number of steps (the first read after initialisation, as a record of the native tool
/// starts with the state at the start of the run).
pub fn run(
    fmu: &Fmu,
    description: &ModelDescription,
    resource_uri: &str,
    (inputs, outputs): (&[(&str, f64)], &[&str]),
    (start, stop, step): (f64, f64, f64),
) -> Result<Vec<Vec<f64>>, String> {
    let variables = Variables::of(description, inputs, outputs)?;
    let name = CString::new("fmu-pack").expect("no NUL");
    let guid = CString::new(description.guid.clone()).map_err(|e| e.to_string())?;
    let uri = CString::new(resource_uri).map_err(|e| e.to_string())?;
    let callbacks = CallbackFunctions {
        logger: Some(print_log),
        allocate_memory: None,
        free_memory: None,
        step_finished: None,
        component_environment: std::ptr::null_mut(),
    };
    // SAFETY: FMI 2.0 calling sequence on a valid instance; pointers outlive the calls.
    unsafe {
        let c = (fmu.instantiate)(
            name.as_ptr(),
            CO_SIMULATION,
            guid.as_ptr(),
            uri.as_ptr(),
            &callbacks,
            FALSE,
            FALSE,
        );
        if c.is_null() {
            return Err("fmi2Instantiate returned NULL".into());
        }
        let result = (|| {
            check(
                "fmi2SetupExperiment",
                (fmu.setup_experiment)(c, FALSE, 0.0, start, TRUE, stop),
            )?;
            check("fmi2EnterInitializationMode", (fmu.enter_initialization)(c))?;
            let Variables {
                outputs: references,
                inputs,
                values,
            } = &variables;
            check(
                "fmi2SetReal",
                (fmu.set_real)(c, inputs.as_ptr(), inputs.len(), values.as_ptr()),
            )?;
            check("fmi2ExitInitializationMode", (fmu.exit_initialization)(c))?;
            let samples = sample(
                (start, stop, step),
                references.len(),
                |t| check("fmi2DoStep", (fmu.do_step)(c, t, step, TRUE)),
                |values| {
                    let (r, n) = (references.as_ptr(), references.len());
                    check("fmi2GetReal", (fmu.get_real)(c, r, n, values.as_mut_ptr()))
                },
            )?;
            check("fmi2Terminate", (fmu.terminate)(c))?;
            Ok(samples)
        })();
        (fmu.free_instance)(c);
        result
    }
}
