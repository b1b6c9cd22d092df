//! The command line's messages in the user's words: a setting named as
//! the user wrote it with its file and line, its value as written (1e308, not 309 digits or
//! `inf`), the modes in the file's words, advice a user can type, and the settings a
//! running simulation blames (a database whose values make the state diverge) with the
//! files they are in. Every expected text is built here from the configuration's own lines
//! and the documented rules, not copied from the tool's output.

use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const EXAMPLE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/example.toml");
const DEFAULT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/src/scenario/default.toml");

fn slowdrift(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_slowdrift"))
        .args(args)
        .output()
        .expect("the CLI runs")
}

/// A fresh directory for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("slowdrift-words-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `text` with the first line that starts with `key` replaced by `line`, written to
/// `dir/name`; the path and the 1-based number of that line.
fn with_line(dir: &Path, name: &str, text: &str, key: &str, line: &str) -> (String, usize) {
    let mut lines: Vec<&str> = text.lines().collect();
    let at = lines
        .iter()
        .position(|l| l.starts_with(key))
        .unwrap_or_else(|| panic!("no line starting with {key:?}"));
    lines[at] = line;
    let path = dir.join(name);
    std::fs::write(&path, lines.join("\n") + "\n").unwrap();
    (path.display().to_string(), at + 1)
}

/// The 1-based line of the first line of the file at `path` that starts with `key`.
fn line_of(path: &str, key: &str) -> usize {
    1 + std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .position(|l| l.starts_with(key))
        .unwrap_or_else(|| panic!("no {key:?} in {path}"))
}

/// `simulate --config path` expected to fail: its stderr, with no run done (nothing after
/// the summary on stdout).
fn refused(path: &str) -> String {
    let run = slowdrift(&["simulate", "--config", path]);
    let stderr = String::from_utf8_lossy(&run.stderr).into_owned();
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    stderr
}

/// Whether `text` holds a run of at least 20 digits (a number no one writes).
fn has_long_digits(text: &str) -> bool {
    text.split(|c: char| !c.is_ascii_digit())
        .any(|run| run.len() >= 20)
}

/// `time_step = 500` over the default block of 16384 s (at least 64 steps a block, so
/// steps of at most 16384 / 64 = 256 s): named as the user wrote it, with the largest step
/// the block takes; the block, which the file never writes, is not blamed.
#[test]
fn a_step_too_long_for_the_block_names_the_step() {
    let dir = scratch("step");
    let example = std::fs::read_to_string(EXAMPLE).unwrap();
    let (path, line) = with_line(&dir, "c.toml", &example, "time_step", "time_step = 500");
    let stderr = refused(&path);
    let largest = 16384.0 / 64.0;
    assert!(
        stderr.starts_with(&format!(
            "slowdrift: {path}:{line}: invalid [run] time_step = 500: must be at most {largest} s"
        )) && stderr.contains("a block of the records (16384 s) holds at least 64 steps"),
        "{stderr}"
    );
    assert!(!stderr.contains("invalid [run] block_duration"), "{stderr}");
    std::fs::remove_dir_all(&dir).ok();
}

/// Values far beyond any platform are shown as the file writes them: `hs = 1e308` (its
/// steepness a number with an exponent, not 300 digits), a duration of 1e-300 s shorter than
/// the step, `memory_limit_gb = 1e308` (refused as written, not as `inf`), and `seed =
/// 1e308` where a whole number belongs (not 309 digits and Rust's `u64`).
#[test]
fn huge_and_tiny_values_read_as_written() {
    let dir = scratch("values");
    let example = std::fs::read_to_string(EXAMPLE).unwrap();
    // (the line replaced, its new text, the line the error names, the message)
    let cases = [
        (
            "hs",
            "hs = 1e308",
            "hs",
            "invalid [sea] hs = 1e308: a sea steeper than waves can be",
        ),
        (
            "duration",
            "duration = 1e-300",
            "time_step",
            "invalid [run] time_step = 1: is longer than the run (duration 1e-300 s)",
        ),
        (
            "start_time",
            "start_time = 0.0\nmemory_limit_gb = 1e308",
            "memory_limit_gb",
            "invalid [run] memory_limit_gb = 1e308: must be a number of GB greater than zero \
             and at most 1e6",
        ),
        (
            "seed",
            "seed = 1e308",
            "seed",
            "invalid type: floating point `1e308`, expected a whole number, 0 or more",
        ),
    ];
    for (key, line, named, expected) in cases {
        let (path, _) = with_line(&dir, &format!("{key}.toml"), &example, key, line);
        let at = line_of(&path, named);
        let stderr = refused(&path);
        assert!(
            stderr.starts_with(&format!("slowdrift: {path}:{at}: {expected}")),
            "{key}: {stderr}"
        );
        assert!(!has_long_digits(&stderr), "{key}: {stderr}");
        assert!(!stderr.contains("= inf"), "{key}: {stderr}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Records are sampled at half a step, so their Nyquist frequency is 2 pi / time_step and
/// must exceed the band's top (2 rad/s in the example): `time_step = 3.5` is refused with a
/// step the user can type, strictly under pi s, and that step runs.
#[test]
fn advice_is_a_step_the_user_can_type() {
    let dir = scratch("advice");
    let example = std::fs::read_to_string(EXAMPLE).unwrap();
    let (path, line) = with_line(&dir, "c.toml", &example, "time_step", "time_step = 3.5");
    let stderr = refused(&path);
    assert!(
        stderr.starts_with(&format!(
            "slowdrift: {path}:{line}: invalid [run] time_step = 3.5:"
        )),
        "{stderr}"
    );
    let advised = stderr
        .split("use time_step = ")
        .nth(1)
        .and_then(|rest| rest.split(" s or less").next())
        .unwrap_or_else(|| panic!("no advice in {stderr}"));
    let step: f64 = advised.parse().unwrap();
    assert!(advised.len() <= 4 && step < PI && step > 3.0, "{advised}");
    let text = std::fs::read_to_string(&path).unwrap();
    let (accepted, _) = with_line(
        &dir,
        "advised.toml",
        &text,
        "time_step",
        &format!("time_step = {advised}"),
    );
    let run = slowdrift(&["simulate", "--config", &accepted]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// A spread sea on the default platform runs with the bi-directional drift: the summary
/// names the mode by the file's word.
#[test]
fn modes_are_named_by_the_files_words() {
    let dir = scratch("modes");
    let default = std::fs::read_to_string(DEFAULT).unwrap();
    let (path, _) = with_line(
        &dir,
        "spread.toml",
        &default,
        "spreading",
        "spreading = \"cos-n\"\nspreading_exponent = 2.0\nn_directions = 3",
    );
    let (path, _) = with_line(
        &dir,
        "spread.toml",
        &std::fs::read_to_string(&path).unwrap(),
        "duration",
        "duration = 2000.0",
    );
    let run = slowdrift(&["simulate", "--config", &path]);
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(
        stdout.contains("short-crested: 3 directions, interaction between them: bidirectional"),
        "{stdout}"
    );
    assert!(!stdout.contains("Bidirectional"), "{stdout}");
    std::fs::remove_dir_all(&dir).ok();
}

/// Settings outside what a platform or its data can take are named at their line: a sea
/// turned past the data's headings (the example's table has 0 and 90 deg), a direction and
/// an initial heading of 1e308 deg (the heading used to end in "reduce run.time_step").
#[test]
fn settings_beyond_the_data_or_a_physical_state_are_named_at_their_line() {
    let dir = scratch("beyond");
    let example = std::fs::read_to_string(EXAMPLE).unwrap();
    let cases = [
        (
            "direction_deg = 30.0",
            "direction_deg = 120.0",
            "invalid [sea] direction_deg = 120: 1 of the sea's 1 wave direction(s) (120 deg) \
             are outside the drift data's headings 0 .. 90 deg",
        ),
        (
            "direction_deg = 30.0",
            "direction_deg = 1e308",
            "invalid [sea] direction_deg = 1e308: must be within -360 .. 360 deg",
        ),
        (
            "heading_deg",
            "heading_deg = 1e308",
            "invalid [initial] heading_deg = 1e308: must be within",
        ),
    ];
    for (key, line, expected) in cases {
        let (path, at) = with_line(&dir, "c.toml", &example, key, line);
        let stderr = refused(&path);
        assert!(
            stderr.starts_with(&format!("slowdrift: {path}:{at}: {expected}")),
            "{line}: {stderr}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `--transient` longer than the run is refused before the run, naming the option.
#[test]
fn a_transient_past_the_end_is_refused_before_the_run() {
    let run = slowdrift(&["simulate", "--config", EXAMPLE, "--transient", "20000"]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.starts_with(
            "slowdrift: --transient 20000: longer than the run (10800 s): no sample would be \
             left for the statistics"
        ),
        "{stderr}"
    );
    assert!(!String::from_utf8_lossy(&run.stdout).contains("steps in"));
}

/// A database whose drift (the example's, times 1e20) throws the platform out at the first
/// step: the error names what the force grows with where the user wrote it, the wave height
/// at its line and the drift data with the database's file and the `[drift]` that names it,
/// in `simulate` and in a campaign's runs file alike (before: `sea.hs, drift`, no file).
#[test]
fn a_diverging_database_is_named_with_its_file() {
    let dir = scratch("diverging");
    let database = dir.join("huge.json");
    let made = slowdrift(&[
        "hydro",
        "columns",
        "--config",
        EXAMPLE,
        "--out",
        database.to_str().unwrap(),
    ]);
    assert!(
        made.status.success(),
        "{}",
        String::from_utf8_lossy(&made.stderr)
    );
    let mut json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&database).unwrap()).unwrap();
    for point in json["drift"].as_array_mut().unwrap() {
        let surge = point["surge"].as_f64().unwrap();
        point["surge"] = serde_json::json!(surge * 1e20);
    }
    std::fs::write(&database, json.to_string()).unwrap();
    let example = std::fs::read_to_string(EXAMPLE).unwrap();
    let head = &example[..example.find("\n[drift]").unwrap()];
    let config = dir.join("c.toml");
    std::fs::write(
        &config,
        format!("{head}\n[drift]\nsource = \"database\"\nfile = \"huge.json\"\n"),
    )
    .unwrap();
    let path = config.to_str().unwrap();
    let named = format!(
        "it grows with [sea] hs ({path}:{}), the drift data of [drift] ({path}:{}; the database \
         {}",
        line_of(path, "hs ="),
        line_of(path, "[drift]"),
        database.display()
    );
    let stderr = refused(path);
    assert!(
        stderr.contains("the wave force there is") && stderr.contains(&named),
        "{stderr}"
    );
    let out = dir.join("r.csv");
    let campaign = slowdrift(&[
        "montecarlo",
        "--config",
        path,
        "--seeds",
        "1",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(campaign.status.code(), Some(1));
    let runs = std::fs::read_to_string(dir.join("r.runs.csv")).unwrap();
    assert!(runs.contains(&named.replace('"', "\"\"")), "{runs}");
    std::fs::remove_dir_all(&dir).ok();
}

/// `hydro columns` and `study drift` solve or use a configuration's columns without running
/// it: a column 1e308 m deep is refused at its line, not solved (before, both wrote their
/// files). The studies that run the configuration check all of it first.
#[test]
fn the_commands_that_use_the_columns_check_them_first() {
    let dir = scratch("columns");
    let example = std::fs::read_to_string(EXAMPLE).unwrap();
    let (path, line) = with_line(&dir, "c.toml", &example, "draft", "draft = 1e308");
    let expected = format!(
        "slowdrift: {path}:{line}: invalid [platform] columns[0].draft = 1e308: must be within"
    );
    let out = dir.join("out");
    let out = out.to_str().unwrap();
    for args in [
        vec!["hydro", "columns", "--config", &path, "--out", "db.json"],
        vec!["study", "drift", "--config", &path, "--out", out],
        vec!["study", "waves", "--config", &path, "--out", out],
    ] {
        let run = Command::new(env!("CARGO_BIN_EXE_slowdrift"))
            .args(&args)
            .current_dir(&dir)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(stderr.starts_with(&expected), "{args:?}: {stderr}");
    }
    assert!(!dir.join("db.json").exists());
    assert_eq!(
        std::fs::read_dir(out).unwrap().count(),
        0,
        "nothing written"
    );
    std::fs::remove_dir_all(&dir).ok();
}
