//! Each FMU's shared library, SlowDrift's (`libslowdrift.so`) and the mooring's
//! (`libslowdrift_mooring.so`), exports exactly the FMI 2.0 common and co-simulation
//! functions and the FMI 3.0 functions (nothing of the FMI layer they share,
//! `slowdrift-fmi`, or of the model) and
//! depends on nothing beyond the C runtime (FMI 2.0.4 section 2.1.1; fmpy checks both).
//! Uses `nm` and `readelf` from GNU binutils.
#![cfg(target_os = "linux")]

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The functions of `fmi2FunctionTypes.h` for co-simulation, typed from the standard.
const FMI2_CO_SIMULATION: [&str; 34] = [
    "fmi2GetTypesPlatform",
    "fmi2GetVersion",
    "fmi2SetDebugLogging",
    "fmi2Instantiate",
    "fmi2FreeInstance",
    "fmi2SetupExperiment",
    "fmi2EnterInitializationMode",
    "fmi2ExitInitializationMode",
    "fmi2Terminate",
    "fmi2Reset",
    "fmi2GetReal",
    "fmi2GetInteger",
    "fmi2GetBoolean",
    "fmi2GetString",
    "fmi2SetReal",
    "fmi2SetInteger",
    "fmi2SetBoolean",
    "fmi2SetString",
    "fmi2GetFMUstate",
    "fmi2SetFMUstate",
    "fmi2FreeFMUstate",
    "fmi2SerializedFMUstateSize",
    "fmi2SerializeFMUstate",
    "fmi2DeSerializeFMUstate",
    "fmi2GetDirectionalDerivative",
    "fmi2SetRealInputDerivatives",
    "fmi2GetRealOutputDerivatives",
    "fmi2DoStep",
    "fmi2CancelStep",
    "fmi2GetStatus",
    "fmi2GetRealStatus",
    "fmi2GetIntegerStatus",
    "fmi2GetBooleanStatus",
    "fmi2GetStringStatus",
];

/// The FMI 3.0 functions, as `fmi3FunctionTypes.h` of the standard (v3.0.2) declares them, in
/// its order: an FMU exports all 75, whatever interface types it provides (FMI 3.0 section
/// 2.5).
const FMI3: [&str; 75] = [
    "fmi3GetVersion",
    "fmi3SetDebugLogging",
    "fmi3InstantiateModelExchange",
    "fmi3InstantiateCoSimulation",
    "fmi3InstantiateScheduledExecution",
    "fmi3FreeInstance",
    "fmi3EnterInitializationMode",
    "fmi3ExitInitializationMode",
    "fmi3EnterEventMode",
    "fmi3Terminate",
    "fmi3Reset",
    "fmi3GetFloat32",
    "fmi3GetFloat64",
    "fmi3GetInt8",
    "fmi3GetUInt8",
    "fmi3GetInt16",
    "fmi3GetUInt16",
    "fmi3GetInt32",
    "fmi3GetUInt32",
    "fmi3GetInt64",
    "fmi3GetUInt64",
    "fmi3GetBoolean",
    "fmi3GetString",
    "fmi3GetBinary",
    "fmi3GetClock",
    "fmi3SetFloat32",
    "fmi3SetFloat64",
    "fmi3SetInt8",
    "fmi3SetUInt8",
    "fmi3SetInt16",
    "fmi3SetUInt16",
    "fmi3SetInt32",
    "fmi3SetUInt32",
    "fmi3SetInt64",
    "fmi3SetUInt64",
    "fmi3SetBoolean",
    "fmi3SetString",
    "fmi3SetBinary",
    "fmi3SetClock",
    "fmi3GetNumberOfVariableDependencies",
    "fmi3GetVariableDependencies",
    "fmi3GetFMUState",
    "fmi3SetFMUState",
    "fmi3FreeFMUState",
    "fmi3SerializedFMUStateSize",
    "fmi3SerializeFMUState",
    "fmi3DeserializeFMUState",
    "fmi3GetDirectionalDerivative",
    "fmi3GetAdjointDerivative",
    "fmi3EnterConfigurationMode",
    "fmi3ExitConfigurationMode",
    "fmi3GetIntervalDecimal",
    "fmi3GetIntervalFraction",
    "fmi3GetShiftDecimal",
    "fmi3GetShiftFraction",
    "fmi3SetIntervalDecimal",
    "fmi3SetIntervalFraction",
    "fmi3SetShiftDecimal",
    "fmi3SetShiftFraction",
    "fmi3EvaluateDiscreteStates",
    "fmi3UpdateDiscreteStates",
    "fmi3EnterContinuousTimeMode",
    "fmi3CompletedIntegratorStep",
    "fmi3SetTime",
    "fmi3SetContinuousStates",
    "fmi3GetContinuousStateDerivatives",
    "fmi3GetEventIndicators",
    "fmi3GetContinuousStates",
    "fmi3GetNominalsOfContinuousStates",
    "fmi3GetNumberOfEventIndicators",
    "fmi3GetNumberOfContinuousStates",
    "fmi3EnterStepMode",
    "fmi3GetOutputDerivatives",
    "fmi3DoStep",
    "fmi3ActivateModelPartition",
];

/// Libraries of the C runtime a Rust cdylib may need.
const C_RUNTIME: [&str; 4] = ["libc.so", "libm.so", "libgcc_s.so", "ld-linux"];

/// The two FMUs' cdylibs: (package, file).
const CDYLIBS: [(&str, &str); 2] = [
    ("slowdrift", "libslowdrift.so"),
    ("slowdrift-mooring", "libslowdrift_mooring.so"),
];

/// The cdylib `file` of `package` in this build, in `<target>/<profile>/deps` or
/// `<target>/<profile>`, found from this test's own path (`<target>/<profile>/deps/all-*`),
/// so it follows CARGO_TARGET_DIR and the profile. Cargo builds both with this test, from
/// the current source: SlowDrift's with the rlib the test links, the mooring's as a
/// dev-dependency of this package; if one is missing anyway, it is built here.
fn cdylib(package: &str, file: &str) -> PathBuf {
    let exe = std::env::current_exe().expect("the test's own path");
    let deps = exe.parent().expect("deps directory");
    let profile_dir = deps.parent().expect("profile directory");
    // deps/ first: `cargo test` builds the cdylib there, and only `cargo build` copies it
    // up to the profile directory (which may be older).
    let candidates = [deps.join(file), profile_dir.join(file)];
    if let Some(found) = candidates.iter().find(|p| p.is_file()) {
        return found.clone();
    }
    let mut build = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()));
    build
        .args(["build", "--lib", "-p", package, "--manifest-path"])
        .arg(concat!(env!("CARGO_MANIFEST_DIR"), "/Cargo.toml"))
        .env(
            "CARGO_TARGET_DIR",
            profile_dir.parent().expect("target directory"),
        );
    if profile_dir.file_name().is_some_and(|n| n == "release") {
        build.arg("--release");
    }
    let status = build.status().expect("cargo runs");
    assert!(status.success(), "cargo build --lib -p {package} failed");
    candidates
        .into_iter()
        .find(|p| p.is_file())
        .unwrap_or_else(|| panic!("no {file} in {}", profile_dir.display()))
}

fn binutils(tool: &str, args: &[&str], library: &Path) -> String {
    let output = Command::new(tool)
        .args(args)
        .arg(library)
        .output()
        .unwrap_or_else(|e| {
            panic!("`{tool}` (GNU binutils) is needed for this test and could not run: {e}")
        });
    assert!(
        output.status.success(),
        "{tool} {args:?} {}: {}",
        library.display(),
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8(output.stdout).expect("UTF-8 output")
}

#[test]
fn each_fmu_exports_exactly_the_fmi2_and_fmi3_functions() {
    let expected: BTreeSet<&str> = FMI2_CO_SIMULATION.into_iter().chain(FMI3).collect();
    for (package, file) in CDYLIBS {
        let library = cdylib(package, file);
        let text = binutils("nm", &["-D", "--defined-only"], &library);
        let exported: BTreeSet<&str> = text
            .lines()
            .filter_map(|line| line.split_whitespace().nth(2))
            .map(|symbol| symbol.split('@').next().unwrap_or(symbol))
            .collect();
        assert_eq!(exported, expected, "{file}");
    }
}

#[test]
fn each_fmu_depends_only_on_the_c_runtime() {
    for (package, file) in CDYLIBS {
        let text = binutils("readelf", &["-d"], &cdylib(package, file));
        let needed: Vec<&str> = text
            .lines()
            .filter(|l| l.contains("(NEEDED)"))
            .filter_map(|l| l.split('[').nth(1)?.split(']').next())
            .collect();
        assert!(
            needed.iter().any(|n| n.starts_with("libc.so")),
            "{file}: {needed:?}"
        );
        for library in needed {
            assert!(
                C_RUNTIME.iter().any(|c| library.starts_with(c)),
                "{file}: {library} is not part of the C runtime"
            );
        }
    }
}
