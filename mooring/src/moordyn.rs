//! MoorDyn's C library behind a safe type.
//!
//! The library is MoorDyn 2.7.2's `libmoordyn`, as the `moordyn` wheel on PyPI ships it
//! (`moordyn.libs/`); fmu-pack copies it into the FMU beside `Mooring.so` as
//! [`LIBRARY_FILE`], and the FMU loads it from there ([`this_library_dir`]) at run time, so
//! this crate builds with plain cargo (no MoorDyn, no headers, no C compiler). It needs the
//! C++ runtime (libstdc++), as every MoorDyn build does. The functions and their signatures are
//! those of MoorDyn's C API (`MoorDyn2.h`, `Line.h`); see <https://moordyn.readthedocs.io>.
//!
//! MoorDyn writes its output files (`<name>.out`, `<name>_Body1.out`) beside its input file
//! and opens the main one in `MoorDyn_Init`, so [`System::new`] runs it on a copy of the
//! input file in a directory of its own, removed when the system is dropped.

#![allow(unsafe_code)]

use std::ffi::{c_char, c_int, c_uint, c_void, CString};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// The file name of MoorDyn's library in the FMU's `binaries/linux64` folder.
pub const LIBRARY_FILE: &str = "libmoordyn.so.2.7";
/// MoorDyn's `MOORDYN_NO_OUTPUT`: no console messages.
const NO_OUTPUT: c_int = 4096;
/// The coupled degrees of freedom this FMU drives: one 6-DOF body.
pub const COUPLED_DOF: usize = 6;
/// The largest input file read (a MoorDyn file of thousands of lines is a few hundred kB).
const MAX_INPUT_BYTES: u64 = 16 << 20;

type Handle = *mut c_void;

/// The C functions used, resolved once per loaded library.
struct Api {
    create: unsafe extern "C" fn(*const c_char) -> Handle,
    n_coupled_dof: unsafe extern "C" fn(Handle, *mut c_uint) -> c_int,
    set_verbosity: unsafe extern "C" fn(Handle, c_int) -> c_int,
    init: unsafe extern "C" fn(Handle, *const f64, *const f64) -> c_int,
    step:
        unsafe extern "C" fn(Handle, *const f64, *const f64, *mut f64, *mut f64, *mut f64) -> c_int,
    close: unsafe extern "C" fn(Handle) -> c_int,
    number_lines: unsafe extern "C" fn(Handle, *mut c_uint) -> c_int,
    get_line: unsafe extern "C" fn(Handle, c_uint) -> Handle,
    line_fairlead_tension: unsafe extern "C" fn(Handle, *mut f64) -> c_int,
}

/// MoorDyn's C library, loaded.
pub struct Library {
    api: Api,
    /// Keeps the functions of `api` mapped.
    _library: libloading::Library,
}

impl Library {
    /// Loads the library at `path`.
    pub fn load(path: &Path) -> Result<Library, String> {
        let at = |e: libloading::Error| format!("MoorDyn's library {}: {e}", path.display());
        // SAFETY: loading runs the library's initialisers; MoorDyn's are the C++ runtime's.
        let library = unsafe { libloading::Library::new(path) }.map_err(at)?;
        macro_rules! function {
            ($name:literal) => {
                // SAFETY: the symbol is MoorDyn's C function of that name, whose signature is
                // the field's type (MoorDyn2.h, Line.h).
                *unsafe { library.get(concat!($name, "\0").as_bytes()) }.map_err(at)?
            };
        }
        let api = Api {
            create: function!("MoorDyn_Create"),
            n_coupled_dof: function!("MoorDyn_NCoupledDOF"),
            set_verbosity: function!("MoorDyn_SetVerbosity"),
            init: function!("MoorDyn_Init"),
            step: function!("MoorDyn_Step"),
            close: function!("MoorDyn_Close"),
            number_lines: function!("MoorDyn_GetNumberLines"),
            get_line: function!("MoorDyn_GetLine"),
            line_fairlead_tension: function!("MoorDyn_GetLineFairTen"),
        };
        Ok(Library {
            api,
            _library: library,
        })
    }
}

/// The folder of the shared object that holds this function (dladdr): in the FMU, the
/// `binaries/linux64` folder of `Mooring.so`, where [`LIBRARY_FILE`] is.
#[cfg(all(target_os = "linux", target_env = "gnu"))]
pub fn this_library_dir() -> Result<PathBuf, String> {
    use std::ffi::CStr;
    let mut info = std::mem::MaybeUninit::<libc::Dl_info>::zeroed();
    let address = this_library_dir as *const c_void;
    // SAFETY: dladdr fills `info` for an address inside a loaded object; a function of
    // this library is one.
    let found = unsafe { libc::dladdr(address, info.as_mut_ptr()) };
    // SAFETY: zero-initialised, and filled by dladdr when it returns non-zero.
    let info = unsafe { info.assume_init() };
    if found == 0 || info.dli_fname.is_null() {
        return Err("cannot tell where Mooring.so was loaded from (dladdr)".into());
    }
    // SAFETY: dli_fname is a NUL-terminated path owned by the dynamic loader.
    let file = unsafe { CStr::from_ptr(info.dli_fname) };
    let file = PathBuf::from(file.to_string_lossy().into_owned());
    file.parent()
        .map(Path::to_path_buf)
        .ok_or_else(|| format!("{} has no folder", file.display()))
}

#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
pub fn this_library_dir() -> Result<PathBuf, String> {
    Err("the mooring FMU runs on linux64 only".into())
}

/// One MoorDyn mooring system with one coupled 6-DOF body, initialised.
pub struct System {
    library: Arc<Library>,
    handle: Handle,
    /// The folder of the input file's copy (MoorDyn writes its output files there).
    workdir: PathBuf,
    lines: Vec<Handle>,
}

/// A directory name no other system of this process uses.
fn fresh_dir() -> PathBuf {
    static COUNT: AtomicU64 = AtomicU64::new(0);
    let n = COUNT.fetch_add(1, Ordering::Relaxed);
    std::env::temp_dir().join(format!("slowdrift-mooring-{}-{n}", std::process::id()))
}

impl System {
    /// Reads the input file `input` (a copy of it, in a fresh directory), checks that it
    /// couples one 6-DOF body, silences MoorDyn's console and solves the lines' static
    /// equilibrium with the body at `x` moving at `xd` (MoorDyn_Init). MoorDyn prints its
    /// banner and the input file's summary on standard output while it reads the file,
    /// before its console can be silenced.
    pub fn new(
        library: Arc<Library>,
        input: &Path,
        x: [f64; COUPLED_DOF],
        xd: [f64; COUPLED_DOF],
    ) -> Result<System, String> {
        let text = read_input(input)?;
        let workdir = fresh_dir();
        let name = input
            .file_name()
            .ok_or_else(|| format!("{} is not a file name", input.display()))?;
        let copy = workdir.join(name);
        std::fs::create_dir_all(&workdir)
            .and_then(|()| std::fs::write(&copy, text))
            .map_err(|e| format!("{}: {e}", copy.display()))?;
        let mut system = System {
            library,
            handle: std::ptr::null_mut(),
            workdir,
            lines: Vec::new(),
        };
        let path = CString::new(copy.to_string_lossy().as_bytes())
            .map_err(|_| format!("{} contains a NUL byte", copy.display()))?;
        let library = Arc::clone(&system.library);
        let api = &library.api;
        // SAFETY: a NUL-terminated path; NULL is returned on any error.
        system.handle = unsafe { (api.create)(path.as_ptr()) };
        if system.handle.is_null() {
            return Err(format!(
                "MoorDyn cannot read {} (MoorDyn_Create failed; its console output says why)",
                input.display()
            ));
        }
        let mut n: c_uint = 0;
        // SAFETY: a live system and a valid out-pointer.
        system.check("MoorDyn_NCoupledDOF", unsafe {
            (api.n_coupled_dof)(system.handle, &mut n)
        })?;
        if n as usize != COUPLED_DOF {
            return Err(format!(
                "{} couples {n} degrees of freedom: the mooring FMU needs exactly one coupled \
                 6-DOF body (the platform) and nothing else coupled",
                input.display()
            ));
        }
        // SAFETY: a live system.
        system.check("MoorDyn_SetVerbosity", unsafe {
            (api.set_verbosity)(system.handle, NO_OUTPUT)
        })?;
        // SAFETY: a live system and arrays of the coupled DOF count.
        system.check("MoorDyn_Init", unsafe {
            (api.init)(system.handle, x.as_ptr(), xd.as_ptr())
        })?;
        let mut count: c_uint = 0;
        // SAFETY: a live system and a valid out-pointer.
        system.check("MoorDyn_GetNumberLines", unsafe {
            (api.number_lines)(system.handle, &mut count)
        })?;
        for l in 1..=count {
            // SAFETY: a live system; lines are numbered from 1.
            let line = unsafe { (api.get_line)(system.handle, l) };
            if line.is_null() {
                return Err(format!("MoorDyn_GetLine({l}) returned NULL"));
            }
            system.lines.push(line);
        }
        Ok(system)
    }

    fn check(&self, function: &str, code: c_int) -> Result<(), String> {
        match code {
            0 => Ok(()),
            code => Err(format!(
                "{function} failed with MoorDyn error {code} ({})",
                error_name(code)
            )),
        }
    }

    /// Advances the lines from `t` by `dt` while the body moves from `x` along `xd`
    /// (MoorDyn's coupled-body kinematics are linear over a call), and returns the force of
    /// the lines on the body at `t + dt`; `dt = 0` returns the force now, moving nothing.
    pub fn step(
        &mut self,
        x: [f64; COUPLED_DOF],
        xd: [f64; COUPLED_DOF],
        t: f64,
        dt: f64,
    ) -> Result<[f64; COUPLED_DOF], String> {
        let mut f = [0.0; COUPLED_DOF];
        let (mut t, mut dt) = (t, dt);
        // SAFETY: a live system, arrays of the coupled DOF count, valid in-out pointers.
        let code = unsafe {
            (self.library.api.step)(
                self.handle,
                x.as_ptr(),
                xd.as_ptr(),
                f.as_mut_ptr(),
                &mut t,
                &mut dt,
            )
        };
        self.check("MoorDyn_Step", code)?;
        Ok(f)
    }

    /// The number of lines (MoorDyn's lines 1, 2, ..., in the input file's order).
    pub fn line_count(&self) -> usize {
        self.lines.len()
    }

    /// The fairlead tension of each line (N; MoorDyn's `GetLineFairTen`, the tension at the
    /// line's end B), in MoorDyn's order of lines.
    pub fn fairlead_tensions(&self) -> Result<Vec<f64>, String> {
        self.lines
            .iter()
            .map(|&line| {
                let mut t = 0.0;
                // SAFETY: a line of this live system and a valid out-pointer.
                self.check("MoorDyn_GetLineFairTen", unsafe {
                    (self.library.api.line_fairlead_tension)(line, &mut t)
                })?;
                Ok(t)
            })
            .collect()
    }
}

impl Drop for System {
    fn drop(&mut self) {
        if !self.handle.is_null() {
            // SAFETY: a live system, closed once.
            unsafe { (self.library.api.close)(self.handle) };
        }
        let _ = std::fs::remove_dir_all(&self.workdir);
    }
}

/// The input file's bytes: a regular file of at most [`MAX_INPUT_BYTES`].
fn read_input(path: &Path) -> Result<Vec<u8>, String> {
    use std::io::Read;
    let at = |e: std::io::Error| format!("mooring input file {}: {e}", path.display());
    let file = std::fs::File::open(path).map_err(at)?;
    let meta = file.metadata().map_err(at)?;
    if !meta.is_file() {
        return Err(format!(
            "mooring input file {} is not a regular file",
            path.display()
        ));
    }
    if meta.len() > MAX_INPUT_BYTES {
        return Err(format!(
            "mooring input file {} has {} bytes, more than the {MAX_INPUT_BYTES} a MoorDyn file \
             can sensibly have",
            path.display(),
            meta.len()
        ));
    }
    let mut bytes = Vec::new();
    file.take(MAX_INPUT_BYTES)
        .read_to_end(&mut bytes)
        .map_err(at)?;
    Ok(bytes)
}

/// MoorDyn's error codes (MoorDynAPI.h).
fn error_name(code: c_int) -> &'static str {
    match code {
        -1 => "invalid input file",
        -2 => "invalid output file",
        -3 => "invalid input",
        -4 => "NaN",
        -5 => "memory",
        -6 => "invalid value",
        -7 => "not implemented",
        _ => "unhandled",
    }
}
