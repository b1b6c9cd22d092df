//! The command-line tool as a user runs it.

use slowdrift::hydro::io::database::HydroDatabase;
use slowdrift::problem;
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
        problem::load(&config).unwrap().hydro.drift
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
    let duration = problem::load(&config).unwrap().run;
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
    for (args, expected) in [
        (vec!["study"], "waves, boxplots, transient, sensitivity"),
        (
            vec!["study", "plots", "--out", out],
            "waves, boxplots, transient, sensitivity",
        ),
        (
            vec!["study", "waves", "--seeds", "3", "--out", out],
            "unknown option '--seeds'",
        ),
        (
            vec!["study", "waves", "--exponents", "12..11", "--out", out],
            "--exponents 12..11",
        ),
        (vec!["study", "waves"], "--out is required"),
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
            "--samples: 2 counts for 3 record lengths",
        ),
        (
            vec!["study", "transient", "--offsets", "0,x", "--out", out],
            "'x' is not a finite number",
        ),
        (
            vec!["study", "sensitivity", "--x", "cd", "--out", out],
            "--cases is required",
        ),
    ] {
        let run = slowdrift(&args);
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert!(
            !run.status.success() && stderr.contains(expected),
            "{args:?}: {stderr}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
