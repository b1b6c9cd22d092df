//! The command-line tool as a user runs it.

use slowdrift::config::file;
use slowdrift::hydro::database::HydroDatabase;
use std::path::Path;
use std::process::Command;

fn slowdrift(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_slowdrift"))
        .args(args)
        .output()
        .expect("the CLI runs")
}

/// `hydro columns` writes a configuration's drift table as a database that reads back as
/// exactly the same table.
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
    let database = HydroDatabase::load(&out).unwrap();
    std::fs::remove_file(&out).ok();
    assert_eq!(
        database.to_drift_table().unwrap(),
        file::load(&config).unwrap().drift
    );
}

/// `simulate` with a configuration prints the three DOFs and writes the CSV it announces.
#[test]
fn simulate_prints_the_summary_and_writes_the_series() {
    let config = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/example.toml");
    let out =
        std::env::temp_dir().join(format!("slowdrift-cli-simulate-{}.csv", std::process::id()));
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
    let text = String::from_utf8_lossy(&run.stdout);
    for dof in ["surge [m]", "sway [m]", "yaw [deg]"] {
        assert!(text.contains(dof), "{text}");
    }
    let csv = std::fs::read_to_string(&out).unwrap();
    std::fs::remove_file(&out).ok();
    let duration = file::load(&config).unwrap().run;
    let rows = (duration.duration / duration.time_step).round() as usize + 1;
    assert_eq!(
        csv.lines().count(),
        rows + 1,
        "header plus one row per step"
    );
}

#[test]
fn bad_arguments_fail_with_the_usage() {
    let run = slowdrift(&["simulate", "--bogus"]);
    assert!(!run.status.success());
    assert!(String::from_utf8_lossy(&run.stderr).contains("unknown option '--bogus'"));
    let run = slowdrift(&["hydro", "columns"]);
    assert!(!run.status.success());
    assert!(String::from_utf8_lossy(&run.stderr).contains("--out is required"));
}
