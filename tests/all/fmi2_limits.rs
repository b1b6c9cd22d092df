//! Sizes the user controls never abort the host: each size that
//! aborted or hung a master before (an allocation of terabytes, a count of 2^31) is refused
//! at initialisation with fmi2Error and a log line that names the parameter, its value and
//! the limit; the instance is then in the Error state and the process lives on. Under a
//! process memory limit (`ulimit -v`, RLIMIT_AS, in a child process) sizes within the memory
//! budget but beyond what the process may allocate are refused the same way.

use crate::fmu::*;
use slowdrift::fmi2::exports::*;
use slowdrift::fmi2::machine::MachineState;
use slowdrift::fmi2::model_description::vr;
use slowdrift::fmi2::types::*;
use std::process::Command;

const DEFAULT_TOML: &str = include_str!("../../src/scenario/default.toml");

/// One hostile set of parameters.
struct Case {
    name: &'static str,
    set: fn(&Fmu, &std::path::Path),
    /// What the fmi2Error's log line must say.
    expected: &'static [&'static str],
}

fn spread(fmu: &Fmu, directions: i32) {
    assert_eq!(
        fmu.set_real(vr::SPREADING_EXPONENT, 2.0),
        fmi2Status::fmi2OK
    );
    assert_eq!(
        fmu.set_int(vr::N_DIRECTIONS, directions),
        fmi2Status::fmi2OK
    );
}

/// A configuration file (the FMU's `hydroDatabase`) with one line replaced.
fn database_with(dir: &std::path::Path, from: &str, to: &str) -> String {
    assert!(DEFAULT_TOML.contains(from), "{from}");
    let path = dir.join("hostile.toml");
    std::fs::write(&path, DEFAULT_TOML.replacen(from, to, 1)).unwrap();
    path.display().to_string()
}

/// The embedded default configuration with its `[drift]` section (the last) made of
/// `drift`, written to `dir` as `name`; its path.
fn configuration_with_drift(dir: &std::path::Path, name: &str, drift: &str) -> String {
    let start = DEFAULT_TOML.find("\n[drift]\n").unwrap();
    assert!(
        !DEFAULT_TOML[start + 1..].contains("\n["),
        "[drift] is the last section"
    );
    let path = dir.join(name);
    std::fs::write(
        &path,
        format!("{}\n[drift]\n{drift}", &DEFAULT_TOML[..start]),
    )
    .unwrap();
    path.display().to_string()
}

/// `unit` repeated to `bytes`.
fn repeated(unit: &str, bytes: usize) -> String {
    unit.repeat(bytes / unit.len())
}

/// Sizes that would abort or hang a master, at the default memory budget.
const HOSTILE: [Case; 6] = [
    Case {
        name: "nDirections = 100000",
        set: |f, _| spread(f, 100_000),
        expected: &["nDirections = 100000: must be at most 360"],
    },
    Case {
        name: "nDirections = 360 with memoryLimit = 0.3 (300 MB)",
        set: |f, _| {
            spread(f, 360);
            assert_eq!(f.set_real(vr::MEMORY_LIMIT, 0.3), fmi2Status::fmi2OK);
        },
        // The largest part, 360^2 pairs x 75 frequencies (the default's bi-directional
        // table) x 3 DOFs x 16 bytes (complex f64) = 4.67e8 bytes.
        expected: &[
            "nDirections = 360: needs ",
            "of which 467 MB: the drift of 360 x 360 direction pairs at 75 frequencies",
            "the limit is 300 MB (the parameter memoryLimit = 0.3)",
        ],
    },
    Case {
        name: "yawFollowingHeadings = 2147483647",
        set: |f, _| {
            assert_eq!(
                f.set_int(vr::YAW_FOLLOWING_HEADINGS, i32::MAX),
                fmi2Status::fmi2OK
            )
        },
        expected: &["yawFollowingHeadings = 2147483647: must be at most 720"],
    },
    Case {
        name: "a hydroDatabase with strips_per_column = 10000000",
        set: |f, dir| {
            let path = database_with(
                dir,
                "strips_per_column = 20",
                "strips_per_column = 10000000",
            );
            assert_eq!(f.set_string(vr::HYDRO_DATABASE, &path), fmi2Status::fmi2OK)
        },
        expected: &[
            "hostile.toml:",
            "[model] strips_per_column = 10000000: must be at most 1000",
        ],
    },
    // (10 MB, not less: reading the packed 3 kB configuration may take 2.9 MB.)
    Case {
        name: "memoryLimit = 0.01 (10 MB) with the default's 32 MB",
        set: |f, _| assert_eq!(f.set_real(vr::MEMORY_LIMIT, 0.01), fmi2Status::fmi2OK),
        expected: &[
            "invalid FMU parameter memoryLimit = 0.01 (10.000 MB): the records need ",
            "from [model] strips_per_column = 20 in the FMU's embedded configuration",
            "raise memoryLimit to at least ",
        ],
    },
    Case {
        name: "a valid 100 kB hydroDatabase with memoryLimit = 0.05 (50 MB)",
        set: |f, dir| {
            // The default configuration, padded with comments to 100 000 bytes: reading it
            // may take 900 bytes per byte (the TOML reader's stated cost), 90 MB.
            let path = dir.join("padded.toml");
            let padding = repeated("# a comment\n", 100_000 - DEFAULT_TOML.len());
            let text = format!("{DEFAULT_TOML}{padding}");
            let text = format!("{text}{}", "#".repeat(100_000 - text.len()));
            std::fs::write(&path, text).unwrap();
            assert_eq!(
                f.set_string(vr::HYDRO_DATABASE, path.to_str().unwrap()),
                fmi2Status::fmi2OK
            );
            assert_eq!(f.set_real(vr::MEMORY_LIMIT, 0.05), fmi2Status::fmi2OK);
        },
        expected: &[
            "padded.toml: reading it needs 90.000 MB of memory (a TOML configuration of \
             100000 bytes (100 kB), up to 900 bytes of memory per byte); the limit is \
             50.000 MB (the parameter memoryLimit = 0.05)",
        ],
    },
];

/// Initialises an instance set up by `case` and checks the refusal: fmi2Error, a log line
/// with every expected text, the Error state, and a step refused after it.
fn refused(case: &Case, dir: &std::path::Path, raise_budget: bool) {
    let fmu = Fmu::new(case.name);
    assert_eq!(fmu.setup(0.0, Some(3600.0)), fmi2Status::fmi2OK);
    if raise_budget {
        assert_eq!(fmu.set_real(vr::MEMORY_LIMIT, 1000.0), fmi2Status::fmi2OK);
    }
    (case.set)(&fmu, dir);
    let start = std::time::Instant::now();
    let status = fmu.init();
    let messages = fmu.messages();
    println!(
        "{}: {status:?} in {:.2?}\n  {}",
        case.name,
        start.elapsed(),
        fmu.last_message().message
    );
    assert_eq!(status, fmi2Status::fmi2Error, "{}: {messages}", case.name);
    let last = fmu.last_message();
    assert_eq!(last.status, fmi2Status::fmi2Error);
    for needle in case.expected {
        assert!(
            last.message.contains(needle),
            "{}: {needle:?} in {messages}",
            case.name
        );
    }
    assert_eq!(unsafe { instance_state(fmu.c) }, Some(MachineState::Error));
    assert_eq!(fmu.step(0.0, 1.0), fmi2Status::fmi2Error);
}

fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("slowdrift-limits-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn hostile_sizes_are_refused_with_fmi2_error_and_the_process_lives_on() {
    let dir = scratch("budget");
    for case in &HOSTILE {
        refused(case, &dir, false);
    }
    // The same process then runs the default.
    let fmu = Fmu::running("after", 1, 0.0, 0.0, Some(100.0));
    fmu.step_with(0.0, 1.0, [0.0; 3]);
    std::fs::remove_dir_all(dir).ok();
}

/// The memory the FMU's refusal states is the estimate of the configuration it runs
/// (`MemoryEstimate` of the embedded default, computed here), and the limit it advises is
/// the next 0.001 GB above it.
#[test]
fn a_memory_refusal_states_the_estimate_of_what_runs() {
    let fmu = Fmu::new("estimate");
    assert_eq!(fmu.setup(0.0, Some(3600.0)), fmi2Status::fmi2OK);
    assert_eq!(fmu.set_real(vr::MEMORY_LIMIT, 0.01), fmi2Status::fmi2OK);
    assert_eq!(fmu.init(), fmi2Status::fmi2Error, "{}", fmu.messages());
    let message = fmu.last_message().message;
    let number_after = |prefix: &str| -> f64 {
        let rest = &message[message.find(prefix).expect(prefix) + prefix.len()..];
        let end = rest.find(' ').unwrap_or(rest.len());
        rest[..end]
            .parse()
            .unwrap_or_else(|e| panic!("{prefix}: {e} in {message}"))
    };
    let estimate = slowdrift::MemoryEstimate::of(&native_problem(1, 0.0, 0.0, 3600.0)).unwrap();
    let bytes = estimate.plan + estimate.per_run;
    let stated = number_after("the records need ") * 1e6;
    assert!(
        (stated - bytes).abs() <= 1e3,
        "{stated} B vs {bytes} B: {message}"
    );
    let advised = number_after("raise memoryLimit to at least ");
    assert!(
        advised >= bytes / 1e9 && advised <= bytes / 1e9 + 0.001,
        "{advised}: {message}"
    );
}

/// The environment variable that makes the test below its own child.
const CHILD: &str = "SLOWDRIFT_LIMITS_CHILD";

/// Address space of the child, kB: room for the test binary and the default's records
/// (tens of MB), far below what the cases need.
const CHILD_ADDRESS_SPACE_KB: u64 = 1_500_000;

/// Sizes within a raised budget (memoryLimit = 1000 GB) but beyond the process's own limit:
/// the probe of the allocator finds it, fmi2Error instead of an abort.
const BEYOND_THE_PROCESS: [Case; 4] = [
    Case {
        name: "yawFollowingHeadings = 720 under a 1.5 GB process limit",
        set: |f, _| {
            assert_eq!(
                f.set_int(vr::YAW_FOLLOWING_HEADINGS, 720),
                fmi2Status::fmi2OK
            )
        },
        expected: &["this process cannot allocate them"],
    },
    Case {
        // The depth kernel's matrices over a 2^20-s block's 330 000 components (2.7 GB);
        // a 65536-s block fits since the kinematics' rows are a window.
        name: "strips_per_column = 1000 and a 2^20-s block under a 1.5 GB process limit",
        set: |f, dir| {
            let path = database_with(dir, "strips_per_column = 20", "strips_per_column = 1000");
            let path = {
                let text = std::fs::read_to_string(&path).unwrap();
                let text = text.replacen(
                    "time_step = 1.0",
                    "time_step = 1.0\nblock_duration = 1048576.0",
                    1,
                );
                std::fs::write(&path, text).unwrap();
                path
            };
            assert_eq!(f.set_string(vr::HYDRO_DATABASE, &path), fmi2Status::fmi2OK)
        },
        expected: &["this process cannot allocate them"],
    },
    // Files within the budget whose reading this process cannot hold:
    // before, the readers aborted the process (the TOML reader took 2.2 GB for this file,
    // the CSV reader 1.7 GB for this table).
    Case {
        name: "a 4 MB hydroDatabase of dotted keys (2.2 GB to read) under a 1.5 GB process \
               limit",
        set: |f, dir| {
            let path = dir.join("dotted.toml");
            let chain = vec!["a"; 40].join(".");
            let tables = repeated(&format!("{{{chain}=0}},"), 4_000_000);
            std::fs::write(&path, format!("[sea]\nx = [{tables}0]\n")).unwrap();
            assert_eq!(
                f.set_string(vr::HYDRO_DATABASE, path.to_str().unwrap()),
                fmi2Status::fmi2OK
            );
        },
        expected: &[
            "dotted.toml: reading it needs 3.600 GB of memory (a TOML configuration of ",
            " bytes (4.000 MB), up to 900 bytes of memory per byte) and this process cannot \
             allocate them",
        ],
    },
    Case {
        name: "a 100 MB CSV drift table (1.7 GB to read) under a 1.5 GB process limit",
        set: |f, dir| {
            let csv = dir.join("drift.csv");
            let rows = repeated("1,0,0,0,0\n", 100_000_000);
            std::fs::write(&csv, format!("omega,beta_deg,surge,sway,yaw\n{rows}")).unwrap();
            let path = configuration_with_drift(
                dir,
                "csv.toml",
                &format!("source = \"csv\"\nfile = \"{}\"\n", csv.display()),
            );
            assert_eq!(f.set_string(vr::HYDRO_DATABASE, &path), fmi2Status::fmi2OK);
        },
        expected: &[
            "drift.csv: reading it needs 3.400 GB of memory (a CSV drift table of 100000030 \
             bytes (100 MB), up to 34 bytes of memory per byte) and this process cannot \
             allocate them",
        ],
    },
];

#[test]
fn under_a_process_memory_limit_sizes_beyond_it_are_refused() {
    if std::env::var_os(CHILD).is_some() {
        let dir = scratch("rlimit");
        for case in &BEYOND_THE_PROCESS {
            refused(case, &dir, true);
        }
        let fmu = Fmu::running("within the limit", 1, 0.0, 0.0, Some(100.0));
        fmu.step_with(0.0, 1.0, [0.0; 3]);
        std::fs::remove_dir_all(dir).ok();
        println!("child done");
        return;
    }
    let exe = std::env::current_exe().unwrap();
    let output = Command::new("bash")
        .arg("-c")
        .arg(format!(
            "ulimit -v {CHILD_ADDRESS_SPACE_KB} && exec \"$0\" \"$@\""
        ))
        .arg(exe)
        .args([
            "--exact",
            "fmi2_limits::under_a_process_memory_limit_sizes_beyond_it_are_refused",
            "--nocapture",
            "--test-threads=1",
        ])
        .env(CHILD, "1")
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    let stderr = String::from_utf8_lossy(&output.stderr);
    println!("{stdout}");
    assert!(
        output.status.success() && stdout.contains("child done"),
        "child {:?}\n{stdout}\n{stderr}",
        output.status
    );
}
