//! The FMU runs the configuration it is given (#27 section 2): a parameter the master does
//! not set takes the value of the configuration in `hydroDatabase` (or the FMU's embedded
//! one), a parameter it sets wins, every value of the file is checked even where a set
//! parameter replaces it, and a fixed parameter set to the value it has after a restored
//! state is accepted. The independent route is the configuration file read and run natively,
//! as `slowdrift simulate --config` does.

use crate::fmu::*;
use slowdrift::fmi2::model_description::vr;
use slowdrift::fmi2::types::*;
use slowdrift::problem::resolve;
use slowdrift::scenario::file;
use slowdrift::scenario::limits::DEFAULT_MEMORY_LIMIT as LIMIT;
use slowdrift::sea_state::{Spectrum, Spreading};
use slowdrift::Simulation;
use std::path::PathBuf;

const STOP: f64 = 600.0;

/// The example configuration with `edits` (old, new) made, written to a file of its own.
fn configuration(name: &str, edits: &[(&str, &str)]) -> PathBuf {
    let mut text = include_str!("../data/example.toml").to_string();
    for (old, new) in edits {
        assert!(text.contains(old), "{old}");
        text = text.replacen(old, new, 1);
    }
    let path = std::env::temp_dir().join(format!(
        "slowdrift-fmu-configuration-{name}-{}.toml",
        std::process::id()
    ));
    std::fs::write(&path, text).unwrap();
    path
}

/// A user's sea: Hs 5 m, 30 degrees (the example's), cos^2 spreading over 9 directions, and
/// drag other than the FMU's start values (combined, C_D 0.7 in the example); the example's
/// drift table given at every heading the spread sea reaches (its rows at 0 and 90 degrees
/// mirrored to 180 and -90).
fn users_sea(name: &str) -> PathBuf {
    configuration(
        name,
        &[
            ("hs = 3.0 ", "hs = 5.0 "),
            ("spreading = \"long-crested\"", "spreading = \"cos-n\""),
            ("# spreading_exponent = 2.0", "spreading_exponent = 2.0"),
            ("# n_directions = 15 ", "n_directions = 9 "),
            ("duration = 10800.0", "duration = 600.0"),
            (
                "  [0.30,   90.0, ",
                "  [0.30, -90.0, 0.0, -1.6e3, 0.0], [0.50, -90.0, 0.0, -6.3e3, 0.0],\n\
                 [0.75, -90.0, 0.0, -2.3e4, 0.0], [1.00, -90.0, 0.0, -4.3e4, 0.0],\n\
                 [1.50, -90.0, 0.0, -6.0e4, 0.0], [2.00, -90.0, 0.0, -6.8e4, 0.0],\n\
                 [0.30, 180.0, -1.5e3, 0.0, 0.0], [0.50, 180.0, -6.0e3, 0.0, 0.0],\n\
                 [0.75, 180.0, -2.2e4, 0.0, 0.0], [1.00, 180.0, -4.1e4, 0.0, 0.0],\n\
                 [1.50, 180.0, -5.8e4, 0.0, 0.0], [2.00, 180.0, -6.6e4, 0.0, 0.0],\n\
                 [0.30,   90.0, ",
            ),
        ],
    )
}

/// An instance with `hydroDatabase` = `path` and nothing else set, initialised for
/// [0, STOP].
fn fmu_of(name: &str, path: &std::path::Path) -> Fmu {
    let fmu = Fmu::new(name);
    assert_eq!(fmu.setup(0.0, Some(STOP)), fmi2Status::fmi2OK);
    assert_eq!(
        fmu.set_string(vr::HYDRO_DATABASE, path.to_str().unwrap()),
        fmi2Status::fmi2OK,
        "{}",
        fmu.messages()
    );
    fmu
}

fn enter_initialization(fmu: &Fmu) -> fmi2Status {
    unsafe { slowdrift::fmi2::exports::fmi2EnterInitializationMode(fmu.c) }
}

fn exit_initialization(fmu: &Fmu) -> fmi2Status {
    unsafe { slowdrift::fmi2::exports::fmi2ExitInitializationMode(fmu.c) }
}

/// With only `hydroDatabase` set, the FMU runs the file's sea and drag: its outputs equal
/// the file run natively bit for bit, and a master reads the file's values back.
#[test]
fn a_configuration_file_runs_as_written() {
    let path = users_sea("runs-as-written");
    let fmu = fmu_of("users-sea", &path);
    // In initialisation mode a master already reads the file's values, not the start values.
    assert_eq!(enter_initialization(&fmu), fmi2Status::fmi2OK);
    let (status, read) = fmu.get_reals(&[
        vr::HS,
        vr::WAVE_DIRECTION,
        vr::SPREADING_EXPONENT,
        vr::CURRENT_SPEED,
        vr::CD,
        vr::STIFFNESS_SURGE,
    ]);
    assert_eq!(status, fmi2Status::fmi2OK, "{}", fmu.messages());
    assert_eq!(read, [5.0, 30f64.to_radians(), 2.0, 0.5, 0.7, 8.0e4]);
    assert_eq!(
        exit_initialization(&fmu),
        fmi2Status::fmi2OK,
        "{}",
        fmu.messages()
    );

    let mut problem = resolve(&file::load(&path, LIMIT).unwrap()).unwrap();
    assert_eq!(problem.sea.spreading, Spreading::CosN { n: 2.0 });
    assert_eq!(problem.sea.n_directions, 9);
    problem.run.start_time = 0.0;
    problem.run.duration = STOP;
    let mut native = Simulation::new(problem).unwrap();
    for n in 0..300 {
        let t = n as f64;
        assert_eq!(
            bits(&fmu.outputs()),
            bits(&native_outputs(&native.outputs().unwrap())),
            "t = {t} s"
        );
        fmu.step_with(t, 1.0, [0.0; 3]);
        native.advance(1.0, [0.0; 3]).unwrap();
    }
    // Short-crested at 30 degrees: sway and yaw move.
    let last = fmu.outputs();
    assert!(last[1] != 0.0 && last[2] != 0.0, "{last:?}");
    std::fs::remove_file(&path).ok();
}

/// A parameter the master sets wins over the file; the others keep the file's values.
#[test]
fn a_parameter_the_master_sets_wins() {
    let path = users_sea("set-hs");
    let fmu = fmu_of("set-hs", &path);
    assert_eq!(fmu.set_real(vr::HS, 4.0), fmi2Status::fmi2OK);
    assert_eq!(fmu.init(), fmi2Status::fmi2OK, "{}", fmu.messages());
    let (status, read) = fmu.get_reals(&[vr::HS, vr::SPREADING_EXPONENT]);
    assert_eq!(status, fmi2Status::fmi2OK, "{}", fmu.messages());
    assert_eq!(read, [4.0, 2.0]);

    let mut problem = resolve(&file::load(&path, LIMIT).unwrap()).unwrap();
    match &mut problem.sea.spectrum {
        Spectrum::Jonswap { hs, .. } => *hs = 4.0,
        other => panic!("{other:?}"),
    }
    problem.run.duration = STOP;
    let mut native = Simulation::new(problem).unwrap();
    for n in 0..50 {
        fmu.step_with(n as f64, 1.0, [0.0; 3]);
        native.advance(1.0, [0.0; 3]).unwrap();
    }
    assert_eq!(
        bits(&fmu.outputs()),
        bits(&native_outputs(&native.outputs().unwrap()))
    );
    std::fs::remove_file(&path).ok();
}

/// A master that switches the drag model without its coefficients gets the coefficients'
/// start values (what it reads back), not an error about the file's empty setting.
#[test]
fn a_mode_the_master_chooses_takes_the_start_values_it_shows() {
    let path = users_sea("separate");
    let fmu = fmu_of("separate", &path);
    assert_eq!(fmu.set_int(vr::DRAG_MODEL, 1), fmi2Status::fmi2OK);
    assert_eq!(enter_initialization(&fmu), fmi2Status::fmi2OK);
    let (status, shown) = fmu.get_reals(&[vr::CD_SLOW, vr::CD_FAST]);
    assert_eq!(status, fmi2Status::fmi2OK, "{}", fmu.messages());
    assert_eq!(
        exit_initialization(&fmu),
        fmi2Status::fmi2OK,
        "{}",
        fmu.messages()
    );
    assert_eq!(
        shown,
        [0.6, 0.6],
        "the start values of modelDescription.xml"
    );
    std::fs::remove_file(&path).ok();
}

/// Every value of the file is checked, even one a set parameter replaces: `hs = nan` is an
/// error naming the file's line, as `simulate --config` gives it.
#[test]
fn the_file_is_checked_where_a_parameter_replaces_it() {
    let path = configuration("nan-hs", &[("hs = 3.0 ", "hs = nan ")]);
    let fmu = fmu_of("nan-hs", &path);
    assert_eq!(fmu.set_real(vr::HS, 4.0), fmi2Status::fmi2OK);
    assert_eq!(fmu.init(), fmi2Status::fmi2Error);
    let message = fmu.last_message().message;
    let line = format!("{}:14", path.display());
    assert!(
        message.contains("[sea] hs") && message.contains(&line),
        "{message}"
    );
    std::fs::remove_file(&path).ok();
}

/// After `fmi2SetFMUstate` a fixed parameter set to the value it has is accepted (fmusim
/// writes start values back after restoring); another value is refused.
#[test]
fn a_fixed_parameter_takes_only_its_own_value_after_a_restore() {
    let fmu = Fmu::running("restore", 3, 0.0, 0.0, Some(STOP));
    let state = get_state(&fmu);
    fmu.step_with(0.0, 1.0, [0.0; 3]);
    assert_eq!(
        unsafe { slowdrift::fmi2::exports::fmi2SetFMUstate(fmu.c, state) },
        fmi2Status::fmi2OK
    );
    assert_eq!(
        fmu.set_int(vr::SEED, 3),
        fmi2Status::fmi2OK,
        "{}",
        fmu.messages()
    );
    assert_eq!(
        fmu.set_real(vr::HS, 7.0),
        fmi2Status::fmi2OK,
        "{}",
        fmu.messages()
    );
    assert_eq!(fmu.set_real(vr::HS, 6.0), fmi2Status::fmi2Error);
    assert!(
        fmu.last_message().message.contains("parameter Hs is fixed"),
        "{}",
        fmu.messages()
    );
    free_state(&fmu, state);
}

/// `spreadingExponent` alone spreads the embedded default's long-crested sea as the case
/// table's `spreading_exponent` does: cos^N over 15 directions (the override table's rule),
/// which `nDirections` then reads; the run equals the native one with that sea.
#[test]
fn a_spreading_exponent_alone_spreads_the_sea_over_15_directions() {
    let fmu = Fmu::new("spread");
    assert_eq!(fmu.setup(0.0, Some(STOP)), fmi2Status::fmi2OK);
    assert_eq!(
        fmu.set_real(vr::SPREADING_EXPONENT, 2.0),
        fmi2Status::fmi2OK
    );
    assert_eq!(enter_initialization(&fmu), fmi2Status::fmi2OK);
    let mut n = -1;
    let status =
        unsafe { slowdrift::fmi2::exports::fmi2GetInteger(fmu.c, &vr::N_DIRECTIONS, 1, &mut n) };
    assert_eq!((status, n), (fmi2Status::fmi2OK, 15), "{}", fmu.messages());
    assert_eq!(
        exit_initialization(&fmu),
        fmi2Status::fmi2OK,
        "{}",
        fmu.messages()
    );

    let mut problem = native_problem(1, 0.0, 0.0, STOP);
    assert_eq!(problem.sea.spreading, Spreading::LongCrested);
    problem.sea.spreading = Spreading::CosN { n: 2.0 };
    problem.sea.n_directions = 15;
    let mut native = Simulation::new(problem).unwrap();
    for n in 0..20 {
        fmu.step_with(n as f64, 1.0, [0.0; 3]);
        native.advance(1.0, [0.0; 3]).unwrap();
    }
    assert_eq!(
        bits(&fmu.outputs()),
        bits(&native_outputs(&native.outputs().unwrap()))
    );
}

/// `driftDamping = 1` (table) on the embedded default, whose data has no damping table,
/// fails by design: the message names the parameter as the master set it and the codes
/// that work with this data, and the variable's description says so.
#[test]
fn table_damping_on_the_default_names_the_choices_that_work() {
    let fmu = Fmu::new("table-damping");
    assert_eq!(fmu.setup(0.0, Some(STOP)), fmi2Status::fmi2OK);
    assert_eq!(fmu.set_int(vr::DRIFT_DAMPING, 1), fmi2Status::fmi2OK);
    assert_eq!(fmu.init(), fmi2Status::fmi2Error);
    let message = fmu.last_message().message;
    assert!(
        message.contains("FMU parameter driftDamping = 1 (table)")
            && message.contains("the damping choices that work with it are aranha and off"),
        "{message}"
    );
    let xml = include_str!("../../modelDescription/modelDescription.xml");
    let variable = &xml[xml.find("name=\"driftDamping\"").unwrap()..];
    let description = &variable[..variable.find('>').unwrap()];
    assert!(
        description.contains("not on the embedded default"),
        "{description}"
    );
}

/// Messages name what the FMU's user set, never a setting of the embedded configuration
/// they cannot see (`[run] block_duration`) or the master's temporary folder.
#[test]
fn messages_name_the_parameters_the_user_set() {
    // 10 MB: the embedded configuration reads (3 MB), its records (31 MB) do not fit.
    assert_refusal_names(
        vr::MEMORY_LIMIT,
        0.01,
        "FMU parameter memoryLimit = 0.01 (10.000 MB)",
    );
    // A step longer than a 64th of a record block (16384 s): named as the step, not as the
    // block, which an FMU's user cannot set.
    assert_refusal_names(vr::STEP_SIZE, 500.0, "FMU parameter stepSize = 500");
    assert_refusal_names(vr::STEP_SIZE, 20000.0, "FMU parameter stepSize = 20000");
    // 1 kB: not even the embedded configuration reads; named as the FMU's, not by the
    // master's folder.
    assert_refusal_names(
        vr::MEMORY_LIMIT,
        1e-6,
        "the FMU's embedded configuration (resources/platform.toml): reading it needs",
    );
}

/// Initialising with the Real parameter `vr` set to `value` is refused, naming `named` and
/// nothing the FMU's user cannot set or see.
fn assert_refusal_names(vr: u32, value: f64, named: &str) {
    let resources = packed_resources().trim_start_matches("file://").to_string();
    let fmu = Fmu::new("named");
    assert_eq!(fmu.setup(0.0, Some(3600.0)), fmi2Status::fmi2OK);
    assert_eq!(fmu.set_real(vr, value), fmi2Status::fmi2OK);
    assert_eq!(fmu.init(), fmi2Status::fmi2Error, "{value}");
    let message = fmu.last_message().message;
    assert!(message.contains(named), "{message}");
    assert!(
        !message.contains("block_duration")
            && !message.contains("[run]")
            && !message.contains(&resources),
        "{message}"
    );
}

/// With `loggingOn` (as libcosim and FMI Library instantiate) a run logs its events, not a
/// line per call; the trace of every call comes when `fmi2SetDebugLogging` names `logAll`.
/// Errors are reported with logging off.
/// The FMU logs at initialisation what the run uses, the lines `slowdrift simulate` prints
/// for the same configuration (its data, masses, stiffness, damping, drag, wind, motions and
/// how its slowly varying records are sampled), in that order, then that it is initialised.
#[test]
fn initialisation_logs_what_the_run_uses() {
    let fmu = Fmu::running("summary", 3, 0.2, 0.0, Some(STOP));
    let native = native(3, 0.2, 0.0, STOP);
    let mut expected = native.problem().summary().unwrap();
    expected.push(native.records_line());
    assert!(expected.iter().any(|l| l.starts_with("mass ")));
    assert!(expected
        .last()
        .unwrap()
        .contains("refined to its midpoints"));
    expected.push("initialized: records precomputed".to_string());
    let events: Vec<String> = fmu
        .entries()
        .into_iter()
        .filter(|e| e.category == "logEvents")
        .map(|e| e.message)
        .skip_while(|m| !m.starts_with("data: "))
        .collect();
    assert_eq!(events, expected, "{}", fmu.messages());
}

#[test]
fn logging_on_alone_logs_events_not_every_step() {
    let fmu = Fmu::running("quiet-steps", 1, 0.0, 0.0, Some(STOP));
    fmu.clear_log();
    for n in 0..200 {
        fmu.step_with(n as f64, 1.0, [0.0; 3]);
    }
    assert!(fmu.entries().is_empty(), "{}", fmu.messages());
    let category = std::ffi::CString::new("logAll").unwrap();
    let categories = [category.as_ptr()];
    assert_eq!(
        unsafe {
            slowdrift::fmi2::exports::fmi2SetDebugLogging(fmu.c, fmi2True, 1, categories.as_ptr())
        },
        fmi2Status::fmi2OK
    );
    fmu.step_with(200.0, 1.0, [0.0; 3]);
    assert!(
        fmu.entries()
            .iter()
            .any(|e| e.category == "logAll" && e.message == "fmi2DoStep: ok"),
        "{}",
        fmu.messages()
    );

    let silent = Fmu::instantiate("silent", Some(packed_resources()), false);
    assert_eq!(silent.set_real(vr::HS, -1.0), fmi2Status::fmi2OK);
    assert_eq!(silent.setup(0.0, Some(STOP)), fmi2Status::fmi2OK);
    assert_eq!(silent.init(), fmi2Status::fmi2Error);
    let entries = silent.entries();
    assert_eq!(entries.len(), 1, "{entries:?}");
    assert_eq!(entries[0].category, "logStatusError");
}

/// A JSON database (as `slowdrift hydro` writes it) given as `hydroDatabase` is refused with
/// the remedy, naming the file: it has no sea, mooring or run to make a configuration.
#[test]
fn a_json_database_as_hydro_database_is_refused_with_the_remedy() {
    let path = std::env::temp_dir().join(format!("slowdrift-db-{}.json", std::process::id()));
    std::fs::write(&path, "{\"format_version\": 1}\n").unwrap();
    let fmu = fmu_of("json", &path);
    assert_eq!(fmu.init(), fmi2Status::fmi2Error);
    let message = fmu.last_message().message;
    std::fs::remove_file(&path).ok();
    assert!(
        message.contains(&format!(
            "{}:1: this is a hydrodynamic database",
            path.display()
        )) && message.contains("name it in a configuration's [drift] section"),
        "{message}"
    );
}

/// An FMU packed from a user's configuration (`fmu-pack --config`) has the configuration's
/// GUID: the library accepts it with those resources (and runs the configuration, whose
/// values a master reads), and refuses it once the packed configuration has been changed.
#[test]
fn a_packed_configuration_has_its_own_guid() {
    use slowdrift::fmi2::resources::{write_configuration, RESOURCE_CONFIG};
    let dir = std::env::temp_dir().join(format!("slowdrift-packed-{}", std::process::id()));
    let config = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/example.toml");
    let packed = write_configuration(&config, &dir).unwrap();
    let uri = format!("file://{}", dir.display());
    let instantiate = |guid: &str| {
        let log: Box<Log> = Box::default();
        let functions = callbacks(&log);
        let name = std::ffi::CString::new("packed").unwrap();
        let guid = std::ffi::CString::new(guid).unwrap();
        let location = std::ffi::CString::new(uri.as_str()).unwrap();
        let c = unsafe {
            slowdrift::fmi2::exports::fmi2Instantiate(
                name.as_ptr(),
                fmi2Type::fmi2CoSimulation,
                guid.as_ptr(),
                location.as_ptr(),
                &functions,
                fmi2False,
                fmi2False,
            )
        };
        (c, log)
    };
    let (c, log) = instantiate(&packed.guid);
    assert!(!c.is_null(), "{:?}", log.lock().unwrap());
    let fmu = Fmu { c, log };
    assert_eq!(fmu.setup(0.0, Some(STOP)), fmi2Status::fmi2OK);
    assert_eq!(enter_initialization(&fmu), fmi2Status::fmi2OK);
    assert_eq!(fmu.get_reals(&[vr::HS]).1, [3.0], "the example's hs");
    drop(fmu);
    // The default's GUID is accepted with any resources.
    let (c, _log) = instantiate(slowdrift::fmi2::model_description::GUID);
    assert!(!c.is_null());
    unsafe { slowdrift::fmi2::exports::fmi2FreeInstance(c) };
    // Changed after packing: refused.
    let path = dir.join(RESOURCE_CONFIG);
    let text = std::fs::read_to_string(&path).unwrap();
    std::fs::write(&path, text.replace("hs = 3.0 ", "hs = 4.0 ")).unwrap();
    let (c, log) = instantiate(&packed.guid);
    assert!(c.is_null());
    let message = log.lock().unwrap()[0].message.clone();
    assert!(
        message.contains("is neither this binary's") && message.contains("pack it again"),
        "{message}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
