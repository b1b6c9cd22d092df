//! The command-line tool as a user runs it.

use slowdrift::hydro::aranha::aranha_damping;
use slowdrift::hydro::io::database::HydroDatabase;
use slowdrift::model::DriftDamping;
use slowdrift::problem;
use slowdrift::scenario::limits::DEFAULT_MEMORY_LIMIT as LIMIT;
use std::path::Path;
use std::process::Command;

fn slowdrift(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_slowdrift"))
        .args(args)
        .output()
        .expect("the CLI runs")
}

/// `hydro columns` writes a configuration's drift table as a database that reads back as
/// exactly the same table, with the damping a run of it uses (here Aranha's, which the
/// configuration asks for and its table does not hold).
#[test]
fn hydro_columns_writes_the_configuration_drift_table() {
    let config = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/example.toml");
    let out =
        std::env::temp_dir().join(format!("slowdrift-cli-columns-{}.json", std::process::id()));
    let run = slowdrift(&[
        "hydro",
        "columns",
        "--config",
        config.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let database = HydroDatabase::load(&out, LIMIT).unwrap();
    std::fs::remove_file(&out).ok();
    let problem = problem::load(&config).unwrap();
    assert_eq!(problem.model.drift_damping, DriftDamping::Aranha);
    assert!(!problem.hydro.drift.has_damping());
    assert_eq!(
        database.to_drift_table().unwrap(),
        aranha_damping(
            &problem.hydro.drift,
            problem.environment.gravity,
            &problem.platform.columns
        )
        .unwrap()
    );
}

/// `simulate --config config --out out`, which must succeed.
fn simulate_to(config: &Path, out: &Path) -> std::process::Output {
    let run = slowdrift(&[
        "simulate",
        "--config",
        config.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    run
}

/// tests/data/example.toml with `duration = value` written to a temporary file, and the
/// line of that key.
fn example_with_duration(value: &str) -> (std::path::PathBuf, usize) {
    let example = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/example.toml");
    let text = std::fs::read_to_string(example).unwrap();
    let key = "duration = 10800.0";
    let line = 1 + text
        .lines()
        .position(|l| l.starts_with(key))
        .expect("example.toml's duration");
    let path = std::env::temp_dir().join(format!(
        "slowdrift-cli-duration-{value}-{}.toml",
        std::process::id()
    ));
    std::fs::write(&path, text.replacen(key, &format!("duration = {value}"), 1)).unwrap();
    (path, line)
}

/// The CLI's run does not depend on its duration: 20 000 s (past the first join of the
/// records, at 16 384 s) and 40 000 s write the same samples over the common span, bit for
/// bit (17 significant digits).
#[test]
fn simulate_gives_the_same_series_for_any_duration() {
    let series = |duration: &str| -> Vec<String> {
        let (config, _) = example_with_duration(duration);
        let out = config.with_extension("csv");
        simulate_to(&config, &out);
        let csv = std::fs::read_to_string(&out).unwrap();
        std::fs::remove_file(&config).ok();
        std::fs::remove_file(&out).ok();
        csv.lines().map(str::to_string).collect()
    };
    let (short, long) = (series("20000.0"), series("40000.0"));
    // The header and the samples at 0, 1, ..., 20 000 s.
    assert_eq!(short.len(), 1 + 20_001);
    assert_eq!(short[..], long[..short.len()]);
}

/// `simulate` runs to an end: an infinite duration (which the FMU's open-ended run has) and
/// one that ends where a double no longer resolves the step are refused with the file, line,
/// key and value, not by an abort.
#[test]
fn simulate_refuses_a_run_without_end() {
    for (value, reason) in [
        ("inf", "is not finite"),
        ("1e15", "where a double resolves time only to"),
    ] {
        let (path, line) = example_with_duration(value);
        let run = slowdrift(&["simulate", "--config", path.to_str().unwrap()]);
        std::fs::remove_file(&path).ok();
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(1), "{stderr}");
        let expected = format!("{}:{line}: invalid [run] duration = ", path.display());
        assert!(
            stderr.contains(&expected) && stderr.contains(reason),
            "{value}: {stderr}"
        );
    }
}

/// A transient past the run's last sample but within its duration (1000.4 s at 1 s: 1000
/// steps, the last sample at t = 1000 s) is refused before the run is made, in the words of
/// the summary that would have no sample, and leaves no CSV (not even a temporary one); a
/// transient on that last sample keeps just it.
#[test]
fn simulate_refuses_a_transient_past_the_last_sample_before_the_run() {
    let (config, _) = example_with_duration("1000.4");
    let dir = std::env::temp_dir().join(format!("slowdrift-cli-last-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("series.csv");
    let run = |transient: &str| {
        slowdrift(&[
            "simulate",
            "--config",
            config.to_str().unwrap(),
            "--transient",
            transient,
            "--out",
            out.to_str().unwrap(),
        ])
    };
    let refused = run("1000.3");
    let (stdout, stderr) = (
        String::from_utf8_lossy(&refused.stdout),
        String::from_utf8_lossy(&refused.stderr),
    );
    assert_eq!(refused.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains(
            "leaves no sample: the record has 1001 samples at dt = 1 s, the last at t = 1000 s"
        ),
        "{stderr}"
    );
    // Refused before the records are made.
    assert!(!stdout.contains("slowly varying records"), "{stdout}");
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert!(left.is_empty(), "{left:?}");

    let kept = run("1000");
    let stdout = String::from_utf8_lossy(&kept.stdout);
    assert_eq!(
        kept.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&kept.stderr)
    );
    assert!(stdout.contains("(1 samples at 1 s)"), "{stdout}");
    assert_eq!(
        std::fs::read_to_string(&out).unwrap().lines().count(),
        1 + 1001
    );
    std::fs::remove_file(&config).ok();
    std::fs::remove_dir_all(&dir).ok();
}

/// The printed summary is the two-pass `summarize` of the series `--out` writes: surge and
/// sway in m, yaw in degrees, the samples at t >= 2000 s of 10 800 s at 1 s (8801), each
/// printed value within half a unit of its 4th decimal of the CSV's.
#[test]
fn simulate_summarises_the_series_it_writes() {
    let config = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/example.toml");
    let out =
        std::env::temp_dir().join(format!("slowdrift-cli-summary-{}.csv", std::process::id()));
    let run = slowdrift(&[
        "simulate",
        "--config",
        config.to_str().unwrap(),
        "--transient",
        "2000",
        "--out",
        out.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(
        stdout.contains("statistics after a transient of 2000 s (8801 samples at 1 s):"),
        "{stdout}"
    );
    let csv = std::fs::read_to_string(&out).unwrap();
    std::fs::remove_file(&out).ok();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    let column = |name: &str, scale: f64| -> Vec<f64> {
        let at = header.iter().position(|h| *h == name).unwrap();
        rows.iter().map(|r| r[at] * scale).collect()
    };
    for (row, name, scale) in [
        ("surge [m]", "X_m", 1.0),
        ("sway [m]", "Y_m", 1.0),
        ("yaw [deg]", "theta_rad", 180.0 / std::f64::consts::PI),
    ] {
        let s = slowdrift::stats::summarize(&column(name, scale), 1.0, 2000.0).unwrap();
        assert_eq!(s.samples, 8801);
        let printed: Vec<f64> = stdout
            .lines()
            .find_map(|l| l.strip_prefix(row))
            .unwrap_or_else(|| panic!("no {row} in {stdout}"))
            .split_whitespace()
            .map(|v| v.parse().unwrap())
            .collect();
        for (p, x) in printed.iter().zip([s.mean, s.rms, s.max, s.min]) {
            assert!(
                (p - x).abs() <= 0.5e-4 * (1.0 + 1e-9),
                "{row}: {printed:?} {s:?}"
            );
        }
        assert_eq!(printed.len(), 4);
    }
}

/// `simulate` keeps none of its steps: a run of 300 000 steps, whose outputs alone (384 bytes
/// a sample) would take 115 MB, runs in an address space of 100 MB (its records, about
/// 30 MB, and the program), with and without `--out`, and summarises every kept sample.
#[test]
fn simulate_runs_longer_than_its_outputs_would_fit() {
    use std::os::unix::process::CommandExt;
    const ADDRESS_SPACE: u64 = 100_000_000;
    let (config, _) = example_with_duration("300000.0");
    let out = config.with_extension("csv");
    for with_out in [false, true] {
        let mut command = Command::new(env!("CARGO_BIN_EXE_slowdrift"));
        command.args(["simulate", "--config", config.to_str().unwrap()]);
        if with_out {
            command.args(["--out", out.to_str().unwrap()]);
        }
        // SAFETY: setrlimit is async-signal-safe; nothing else runs between fork and exec.
        #[allow(unsafe_code)]
        unsafe {
            command.pre_exec(|| {
                let limit = libc::rlimit {
                    rlim_cur: ADDRESS_SPACE,
                    rlim_max: ADDRESS_SPACE,
                };
                if libc::setrlimit(libc::RLIMIT_AS, &limit) == 0 {
                    Ok(())
                } else {
                    Err(std::io::Error::last_os_error())
                }
            });
        }
        let run = command.output().expect("the CLI runs");
        let (stdout, stderr) = (
            String::from_utf8_lossy(&run.stdout),
            String::from_utf8_lossy(&run.stderr),
        );
        assert_eq!(run.status.code(), Some(0), "--out {with_out}: {stderr}");
        // The default transient of example.toml's platform, then every sample to 300 000 s.
        let kept = stdout
            .lines()
            .find_map(|l| l.strip_prefix("statistics after a transient of "))
            .expect("the summary");
        let transient: f64 = kept.split(' ').next().unwrap().parse().unwrap();
        let samples = 300_000 - transient.ceil() as usize + 1;
        assert!(
            kept.contains(&format!("({samples} samples at 1 s)")),
            "{kept}"
        );
        if with_out {
            let lines = std::io::BufRead::lines(std::io::BufReader::new(
                std::fs::File::open(&out).unwrap(),
            ));
            assert_eq!(lines.count(), 1 + 300_001);
        }
    }
    std::fs::remove_file(&config).ok();
    std::fs::remove_file(&out).ok();
}

/// `simulate` with a configuration prints the three DOFs and writes the CSV it announces.
#[test]
fn simulate_prints_the_summary_and_writes_the_series() {
    let config = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/example.toml");
    let out =
        std::env::temp_dir().join(format!("slowdrift-cli-simulate-{}.csv", std::process::id()));
    let run = simulate_to(&config, &out);
    let text = String::from_utf8_lossy(&run.stdout);
    for dof in ["surge [m]", "sway [m]", "yaw [deg]"] {
        assert!(text.contains(dof), "{text}");
    }
    let csv = std::fs::read_to_string(&out).unwrap();
    std::fs::remove_file(&out).ok();
    let duration = problem::load(&config).unwrap().run;
    let rows = (duration.duration / duration.time_step).round() as usize + 1;
    assert_eq!(
        csv.lines().count(),
        rows + 1,
        "header plus one row per step"
    );
}

/// Runs the CLI expecting a refusal: a non-zero status and every one of `expected` in the
/// message on stderr.
fn refused(args: &[&str], expected: &[&str]) {
    let run = slowdrift(args);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(!run.status.success(), "{args:?} succeeded: {stderr}");
    for text in expected {
        assert!(stderr.contains(text), "{args:?}: no {text:?} in {stderr}");
    }
}

#[test]
fn bad_arguments_fail_with_the_usage() {
    refused(
        &["simulate", "--bogus"],
        &["unexpected argument '--bogus'", "Usage: slowdrift simulate"],
    );
    refused(
        &["hydro", "columns"],
        &[
            "required",
            "--out <FILE.json>",
            "Usage: slowdrift hydro columns",
        ],
    );
    refused(&["frobnicate"], &["unrecognized subcommand 'frobnicate'"]);
    // No command is a usage error too: the usage and the commands on stderr, status 2
    // (as `slowdrift hydro` and `slowdrift study` without theirs).
    let bare = slowdrift(&[]);
    let stderr = String::from_utf8_lossy(&bare.stderr);
    assert_eq!(bare.status.code(), Some(2), "{stderr}");
    assert!(
        bare.stdout.is_empty(),
        "{}",
        String::from_utf8_lossy(&bare.stdout)
    );
    for text in ["Usage: slowdrift <COMMAND>", "simulate", "montecarlo"] {
        assert!(stderr.contains(text), "no {text:?} in {stderr}");
    }
    refused(
        &["simulate", "--transient", "-5"],
        &["--transient -5: must be a non-negative number of seconds"],
    );
    refused(
        &["simulate", "--transient", "ten"],
        &["--transient ten: not a number"],
    );
    refused(
        &[
            "hydro", "wamit", "--root", "x", "--rho", "0", "--out", "y.json",
        ],
        &["--rho 0: must be a positive number"],
    );
    refused(
        &["hydro", "wamit", "--out", "y.json"],
        &["required", "--root <PATH/NAME>"],
    );
}

/// The help text of `args`, which must exit 0, with every run of whitespace made one space
/// (the help is wrapped to the terminal's width).
fn help(args: &[&str]) -> String {
    let run = slowdrift(args);
    assert!(
        run.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&run.stderr)
    );
    let text = String::from_utf8_lossy(&run.stdout);
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

fn assert_lists(args: &[&str], expected: &[&str]) {
    let text = help(args);
    for item in expected {
        assert!(text.contains(item), "{args:?}: no {item:?} in {text}");
    }
}

/// `--help` of the tool and of every command exits 0 and lists the options with their
/// values, units and defaults.
#[test]
fn help_lists_the_options_with_units_and_defaults() {
    let commands = [
        "simulate",
        "hydro",
        "montecarlo",
        "study",
        "slowdrift COMMAND --help",
    ];
    assert_lists(&["--help"], &commands);
    assert_lists(
        &["hydro", "--help"],
        &["imports WAMIT or NEMOH output", "wamit", "nemoh", "columns"],
    );
    assert_lists(
        &["simulate", "--help"],
        &[
            "--config <FILE.toml>",
            "--out <FILE.csv>",
            "--transient <SECONDS> Start-up transient dropped before the statistics, s \
             [default: ten surge natural periods, at most half the run]",
        ],
    );
    assert_lists(
        &["hydro", "wamit", "--help"],
        &[
            "--root <PATH/NAME>",
            "m [default: 1]",
            "--rho <RHO> Water density, kg/m^3",
            "[default: 1025]",
            "m/s^2",
            "[default: 9.80665]",
            "--out <FILE.json>",
        ],
    );
    assert_lists(
        &["hydro", "columns", "--help"],
        &["--config <FILE.toml>", "--out <FILE.json>"],
    );
    assert_lists(
        &["montecarlo", "--help"],
        &[
            "--print-cases",
            "--seeds <N>",
            "(required unless --print-cases)",
            "--first-seed <S>",
            "[default: 1]",
            "--duration <SECONDS> Replaces run.duration of the base, s",
            "--transient <SECONDS>",
            "at most half the run]",
            "--threads <T>",
            "[default: all cores]",
            "--cases <CASES.csv>",
            "--case <NAME>",
            "--out <RESULTS.csv>",
        ],
    );
    assert_lists(
        &["study", "--help"],
        &[
            "Usage: slowdrift study <drift|waves|boxplots|transient|sensitivity|motion>",
            "waves",
            "boxplots",
            "transient",
            "sensitivity",
        ],
    );
    assert_lists(
        &["study", "waves", "--help"],
        &[
            "--exponents <A..B> Record lengths 2^A .. 2^B s",
            "[default: 11..17]",
            "--out <DIR>",
        ],
    );
    assert_lists(
        &["study", "boxplots", "--help"],
        &[
            "--exponents <A..B>",
            "--samples <N,N,...>",
            "[default: 1000,1000,1000,400,200,200,200 for 11..17, else 200]",
            "--transient <SECONDS>",
            "s [default: ten undamped surge natural periods]",
            "--threads <T>",
            "--out <DIR>",
        ],
    );
    assert_lists(
        &["study", "transient", "--help"],
        &[
            "--runs <N>",
            "[default: 200]",
            "--blocks <N>",
            "[default: 8]",
            "--block-cycles <CYCLES>",
            "undamped surge natural periods",
            "[default: 10]",
            "--offsets <M,M,...>",
            "m (released at rest) [default: 0,15]",
            "--threads <T>",
        ],
    );
    assert_lists(
        &["study", "sensitivity", "--help"],
        &[
            "--cases <CASES.csv>",
            "--x <COLUMN>",
            "--seeds <N>",
            "[default: 100]",
            "--threads <T>",
            "--out <DIR>",
        ],
    );
}

/// `montecarlo` checks its options before anything runs, naming the option and the value.
#[test]
fn montecarlo_refuses_bad_options() {
    let config = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/example.toml");
    let config = config.to_str().unwrap();
    let out = std::env::temp_dir().join(format!("slowdrift-cli-mc-{}.csv", std::process::id()));
    let out = out.to_str().unwrap();
    let base = ["montecarlo", "--config", config];
    let with =
        |extra: &[&'static str]| -> Vec<&str> { base.iter().chain(extra).copied().collect() };
    refused(
        &[with(&["--seeds", "0"]), vec!["--out", out]].concat(),
        &["--seeds 0: must be a whole number of at least 1"],
    );
    refused(
        &[
            with(&["--seeds", "2", "--threads", "0"]),
            vec!["--out", out],
        ]
        .concat(),
        &["--threads 0: must be a whole number of at least 1"],
    );
    refused(
        &[
            with(&["--seeds", "2", "--first-seed", "-1"]),
            vec!["--out", out],
        ]
        .concat(),
        &["--first-seed -1: must be a whole number of at least 0"],
    );
    refused(
        &[
            with(&["--seeds", "2", "--duration", "0"]),
            vec!["--out", out],
        ]
        .concat(),
        &["--duration 0: must be a positive number of seconds"],
    );
    refused(
        &[
            with(&["--seeds", "2", "--transient", "-1"]),
            vec!["--out", out],
        ]
        .concat(),
        &["--transient -1: must be a non-negative number of seconds"],
    );
    refused(
        &[with(&[]), vec!["--out", out]].concat(),
        &["required", "--seeds <N>"],
    );
    refused(
        &with(&["--seeds", "2"]),
        &["required", "--out <RESULTS.csv>"],
    );
    // An unknown option is named, with the option it resembles.
    refused(
        &[with(&["--seed", "2"]), vec!["--out", out]].concat(),
        &["unexpected argument '--seed'", "'--seeds'"],
    );
    refused(
        &[
            with(&["--seeds", "2", "--first-seed", "18446744073709551615"]),
            vec!["--out", out],
        ]
        .concat(),
        &["--first-seed 18446744073709551615 + --seeds 2 overflows"],
    );
    assert!(!Path::new(out).exists(), "nothing ran, nothing was written");
}

/// `montecarlo --print-cases` needs neither --seeds nor --out, and other options given
/// once more replace the earlier value (as they always did).
#[test]
fn montecarlo_prints_cases_without_seeds_or_out() {
    let config = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/example.toml");
    let run = slowdrift(&[
        "montecarlo",
        "--config",
        config.to_str().unwrap(),
        "--transient",
        "100",
        "--transient",
        "123",
        "--print-cases",
    ]);
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let document: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(document["format_version"], 1, "{stdout}");
    let cases = document["cases"].as_array().unwrap();
    assert_eq!(cases.len(), 1, "{stdout}");
    assert_eq!(cases[0]["name"], "base", "{stdout}");
    assert_eq!(cases[0]["transient"], 123.0, "{stdout}");
}

fn temp_dir(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("slowdrift-cli-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    dir
}

fn assert_figure(dir: &Path, stem: &str) {
    let png = std::fs::read(dir.join(format!("{stem}.png"))).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n", "{stem}.png");
    let svg = std::fs::read_to_string(dir.join(format!("{stem}.svg"))).unwrap();
    assert!(
        svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"),
        "{stem}.svg"
    );
}

/// `study drift` on the default platform: the CSV every 0.01 rad/s and the figure; where
/// the default's table is the column solver's (above 2 rad/s) the two curves agree but for
/// their grids, and near the sea's peak (0.5 rad/s) the pontoons and the motions make the
/// radiation-diffraction drift several times the columns'.
#[test]
fn study_drift_compares_the_default_with_the_column_solver() {
    let dir = temp_dir("drift");
    let run = slowdrift(&["study", "drift", "--out", dir.to_str().unwrap()]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let csv = std::fs::read_to_string(dir.join("drift_comparison.csv")).unwrap();
    let rows: Vec<Vec<f64>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 296, "0.05 .. 3.0 every 0.01");
    let at = |omega: f64| {
        rows.iter()
            .find(|r| (r[0] - omega).abs() < 1e-9)
            .unwrap()
            .clone()
    };
    for omega in [2.2, 2.5, 2.8] {
        let r = at(omega);
        assert!((r[1] / r[2] - 1.0).abs() < 0.05, "{omega}: {r:?}");
    }
    let r = at(0.5);
    assert!(r[1] > 5.0 * r[2], "{r:?}");
    assert_figure(&dir, "drift_comparison");
    std::fs::remove_dir_all(&dir).ok();
}

/// `study waves` on a configuration file: one CSV row per record length and both figures.
#[test]
fn study_waves_writes_data_and_figures() {
    let config = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/example.toml");
    let dir = temp_dir("waves");
    let run = slowdrift(&[
        "study",
        "waves",
        "--config",
        config.to_str().unwrap(),
        "--exponents",
        "11..12",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let csv = std::fs::read_to_string(dir.join("fig7_fig8_waves.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().skip(1).collect();
    assert_eq!(rows.len(), 2, "{csv}");
    assert!(
        rows[0].starts_with("2048,4096,") && rows[1].starts_with("4096,8192,"),
        "{csv}"
    );
    assert_figure(&dir, "fig7_elevation_pdf");
    assert_figure(&dir, "fig8_elevation_spectrum");
    std::fs::remove_dir_all(&dir).ok();
}

/// `study sensitivity`: a case table's column on the x axis, the summary per case, the
/// figure; run again, it finds every run in its per-run file and runs none.
#[test]
fn study_sensitivity_runs_plots_and_resumes() {
    let config = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/example.toml");
    let dir = temp_dir("sensitivity");
    std::fs::create_dir_all(&dir).unwrap();
    let table = dir.join("drag.csv");
    std::fs::write(&table, "name,cd,duration\nlow,0.3,1200\nhigh,1.2,1200\n").unwrap();
    let args = [
        "study",
        "sensitivity",
        "--config",
        config.to_str().unwrap(),
        "--cases",
        table.to_str().unwrap(),
        "--x",
        "cd",
        "--seeds",
        "3",
        "--out",
        dir.to_str().unwrap(),
    ];
    let first = slowdrift(&args);
    assert!(
        first.status.success(),
        "{}",
        String::from_utf8_lossy(&first.stderr)
    );
    let summary = std::fs::read_to_string(dir.join("drag.summary.csv")).unwrap();
    assert!(
        summary.contains("low,0.3,3,") && summary.contains("high,1.2,3,"),
        "{summary}"
    );
    assert_figure(&dir, "drag");
    let again = slowdrift(&args);
    let stdout = String::from_utf8_lossy(&again.stdout);
    assert!(
        again.status.success() && stdout.contains("6 already in") && stdout.contains("0 to run"),
        "{stdout}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn study_refuses_bad_arguments() {
    let dir = temp_dir("bad");
    let out = dir.to_str().unwrap();
    let kinds = "<drift|waves|boxplots|transient|sensitivity|motion>";
    for (args, expected) in [
        (vec!["study"], vec![kinds]),
        (
            vec!["study", "plots", "--out", out],
            vec!["unrecognized subcommand 'plots'", kinds],
        ),
        (
            vec!["study", "waves", "--seeds", "3", "--out", out],
            vec!["unexpected argument '--seeds'"],
        ),
        (
            vec!["study", "waves", "--exponents", "12..11", "--out", out],
            vec!["--exponents 12..11: must be A..B with 4 <= A <= B <= 20"],
        ),
        (vec!["study", "waves"], vec!["required", "--out <DIR>"]),
        (
            vec!["study", "waves", "--out", out, "--out", out],
            vec!["'--out <DIR>' cannot be used multiple times"],
        ),
        (
            vec![
                "study",
                "boxplots",
                "--exponents",
                "11..13",
                "--samples",
                "3,4",
                "--out",
                out,
            ],
            vec!["--samples: 2 counts for 3 record lengths"],
        ),
        (
            vec!["study", "boxplots", "--samples", "3,1", "--out", out],
            vec!["--samples 1: must be a whole number of at least 2"],
        ),
        (
            vec!["study", "transient", "--offsets", "0,x", "--out", out],
            vec!["--offsets 0,x: 'x' is not a finite number"],
        ),
        (
            vec!["study", "transient", "--block-cycles", "0", "--out", out],
            vec!["--block-cycles 0: must be a positive number"],
        ),
        (
            vec!["study", "transient", "--runs", "1", "--out", out],
            vec!["--runs 1: must be a whole number of at least 2"],
        ),
        (
            vec!["study", "sensitivity", "--x", "cd", "--out", out],
            vec!["required", "--cases <CASES.csv>"],
        ),
        (
            vec!["study", "sensitivity", "--cases", "c.csv", "--out", out],
            vec!["required", "--x <COLUMN>"],
        ),
    ] {
        refused(&args, &expected);
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `--memory-limit-gb` (of `simulate`, as of `montecarlo`) is the budget of the records: the
/// default's (tens of MB) are refused at 0.001 GB naming the limit as set, and run at 1 GB;
/// a limit that is not a positive number is a usage error naming the option.
#[test]
fn the_memory_limit_is_a_cli_option() {
    let refused = slowdrift(&["simulate", "--memory-limit-gb", "0.001"]);
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert_eq!(refused.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("needs ")
            && stderr.contains("the limit is 1.000 MB (run.memory_limit_gb = 0.001)"),
        "{stderr}"
    );
    let accepted = slowdrift(&["simulate", "--memory-limit-gb", "1"]);
    assert_eq!(
        accepted.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&accepted.stderr)
    );
    let bad = slowdrift(&["simulate", "--memory-limit-gb", "-1"]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr)
        .contains("--memory-limit-gb -1: must be a positive number of GB"));
}

/// `--out` is checked before any work: a directory where a file is written, a
/// file where a study's directory is, a directory that does not exist and a place nobody
/// can write (sysfs takes no new file, even from root) are refused at once, naming `--out`
/// and the path; nothing runs and nothing is written (`montecarlo --out DIR` used to run
/// every run, write `DIR.runs.csv` beside the directory and fail on the summary).
#[test]
fn out_is_checked_before_any_work() {
    let dir = temp_dir("out");
    std::fs::create_dir_all(&dir).unwrap();
    let d = dir.to_str().unwrap().to_string();
    let file = dir.join("plain.csv");
    std::fs::write(&file, "").unwrap();
    let f = file.to_str().unwrap().to_string();
    let missing = dir.join("no/series.csv");
    let m = missing.to_str().unwrap().to_string();
    assert!(Path::new("/sys").is_dir(), "the test needs sysfs at /sys");
    let is_dir = format!("--out {d}: is a directory: give a file's path (such as {d}/results.csv)");
    let cases: [(Vec<&str>, String); 7] = [
        (vec!["simulate", "--out", &d], is_dir.clone()),
        (
            vec!["montecarlo", "--seeds", "2", "--out", &d],
            is_dir.clone(),
        ),
        (vec!["hydro", "columns", "--out", &d], is_dir.clone()),
        (
            vec!["simulate", "--out", &m],
            format!("--out {m}: its directory {d}/no does not exist"),
        ),
        (
            vec![
                "montecarlo",
                "--seeds",
                "2",
                "--out",
                "/sys/slowdrift-results.csv",
            ],
            "--out /sys/slowdrift-results.csv: cannot write in /sys: ".to_string(),
        ),
        (
            vec!["study", "drift", "--out", &f],
            format!(
                "--out {f}: is a file, not a directory: the study writes several files into \
                 a directory"
            ),
        ),
        (
            vec!["study", "waves", "--out", "/sys/slowdrift-study"],
            "--out /sys/slowdrift-study: cannot make the directory: ".to_string(),
        ),
    ];
    for (args, expected) in cases {
        let run = slowdrift(&args);
        let (stdout, stderr) = (
            String::from_utf8_lossy(&run.stdout),
            String::from_utf8_lossy(&run.stderr),
        );
        assert_eq!(run.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(
            stderr.starts_with(&format!("slowdrift: {expected}")),
            "{args:?}: {stderr}"
        );
        assert!(stdout.is_empty(), "{args:?}: nothing runs, but: {stdout}");
    }
    // Nothing was written beside the directory or in it.
    assert!(!dir
        .with_file_name(format!(
            "{}.runs.csv",
            dir.file_name().unwrap().to_string_lossy()
        ))
        .exists());
    let mut left: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    left.sort();
    assert_eq!(left, ["plain.csv"]);
    std::fs::remove_dir_all(&dir).ok();
}

/// `study motion` on the default over 2^13 s: the spectra (simulated and predicted rows of
/// every drawn part), the variances per DOF with the damping parts, and the figure; the
/// DOFs a head sea does not excite are named as not drawn.
#[test]
fn study_motion_writes_spectra_variances_and_figure() {
    let dir = temp_dir("motion");
    let run = slowdrift(&[
        "study",
        "motion",
        "--duration",
        "8192",
        "--out",
        dir.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(
        stdout.contains("slow drift, sway Y: not excited"),
        "{stdout}"
    );
    let csv = std::fs::read_to_string(dir.join("motion_spectra.csv")).unwrap();
    for part in [
        "slow-drift,surge X,simulated,",
        "slow-drift,surge X,predicted,",
        "wave-frequency,heave,simulated,",
        "wave-frequency,pitch,predicted,",
    ] {
        assert!(csv.contains(part), "no {part}");
    }
    let variances = std::fs::read_to_string(dir.join("motion_variances.csv")).unwrap();
    assert_eq!(variances.lines().count(), 1 + 3 + 6, "{variances}");
    let surge: Vec<&str> = variances.lines().nth(1).unwrap().split(',').collect();
    assert_eq!(surge[..2], ["slow-drift", "surge X"]);
    let drag: f64 = surge[6].parse().unwrap();
    assert!(drag > 0.0, "the default's drag damps: {surge:?}");
    assert_figure(&dir, "motion_spectra");
    // With wind: the slow drift's prediction in its two parts, and the wind speed's spectrum.
    let windy = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/default_wind.toml");
    let run = slowdrift(&[
        "study",
        "motion",
        "--config",
        windy.to_str().unwrap(),
        "--duration",
        "8192",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let csv = std::fs::read_to_string(dir.join("motion_spectra.csv")).unwrap();
    for part in [
        "slow-drift,surge X,predicted wave drift,",
        "slow-drift,surge X,predicted wind gusts,",
        "wind,speed,simulated,",
        "wind,speed,predicted,",
    ] {
        assert!(csv.contains(part), "no {part}");
    }
    let variances = std::fs::read_to_string(dir.join("motion_variances.csv")).unwrap();
    let surge: Vec<&str> = variances.lines().nth(1).unwrap().split(',').collect();
    let wind_damping: f64 = surge[8].parse().unwrap();
    assert!(wind_damping > 0.0, "{surge:?}");
    assert!(
        slowdrift(&["study", "motion", "--duration", "0", "--out", "x"])
            .status
            .code()
            .is_some_and(|c| c != 0)
    );
    std::fs::remove_dir_all(&dir).ok();
}
