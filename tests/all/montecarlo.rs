//! `slowdrift montecarlo`: resume after an interruption, independence of
//! the thread count, bad case tables, failed cases, the standard error against its formula,
//! and the statistics of a linear oscillator against the frequency-domain variance.
//!
//! The CLI runs use the cheap example configuration (inline drift table, four columns with
//! combined drag) for 2048 s at 1 s steps.

use crate::common::{base_problem, oscillator_surge_variance};
use slowdrift::montecarlo::{run_jobs, seed_statistics, Case, Job};
use slowdrift::scenario::limits::DEFAULT_MEMORY_LIMIT as LIMIT;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::atomic::AtomicBool;

const EXAMPLE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/example.toml");

/// A fresh, empty directory for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("slowdrift-mc-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs `slowdrift montecarlo` on the example for 2048 s with `extra` arguments.
fn montecarlo(out: &Path, extra: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_slowdrift"))
        .args(["montecarlo", "--config", EXAMPLE, "--duration", "2048"])
        .args(extra)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap()
}

fn succeeded(output: &Output) -> String {
    let stdout = String::from_utf8_lossy(&output.stdout).to_string();
    assert!(
        output.status.success(),
        "montecarlo failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    stdout
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn runs_file(out: &Path) -> PathBuf {
    out.with_file_name(format!(
        "{}.runs.csv",
        out.file_stem().unwrap().to_string_lossy()
    ))
}

/// One line of the per-run file: case, seed, and (column, field) pairs.
type RunLine = (String, u64, Vec<(String, String)>);

/// The per-run file, one entry per line.
fn per_run_lines(out: &Path) -> Vec<RunLine> {
    let text = read(&runs_file(out));
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    lines
        .map(|line| {
            let fields: Vec<String> = line.splitn(header.len(), ',').map(String::from).collect();
            (
                fields[0].clone(),
                fields[1].parse().unwrap(),
                header.iter().cloned().zip(fields).collect(),
            )
        })
        .collect()
}

fn field<'a>(fields: &'a [(String, String)], name: &str) -> &'a str {
    &fields.iter().find(|(k, _)| k == name).unwrap().1
}

#[test]
fn an_interrupted_campaign_resumes_and_equals_a_fresh_one() {
    let dir = scratch("resume");
    let (resumed, fresh) = (dir.join("resumed.csv"), dir.join("fresh.csv"));
    succeeded(&montecarlo(&resumed, &["--seeds", "4"]));
    // Killed while writing a line: a partial last line without its newline.
    let mut text = read(&runs_file(&resumed));
    text.push_str("base,5,0123456789abcdef,ok,1.2");
    std::fs::write(runs_file(&resumed), text).unwrap();

    let stdout = succeeded(&montecarlo(&resumed, &["--seeds", "8"]));
    assert!(
        stdout.contains("= 8 runs; 4 already in") && stdout.contains("4 to run"),
        "{stdout}"
    );
    let lines = per_run_lines(&resumed);
    let seeds: Vec<u64> = lines.iter().map(|(_, seed, _)| *seed).collect();
    assert_eq!(seeds.len(), 8, "each seed once: {seeds:?}");
    let mut sorted = seeds.clone();
    sorted.sort();
    assert_eq!(sorted, (1..=8).collect::<Vec<_>>());

    succeeded(&montecarlo(&fresh, &["--seeds", "8"]));
    assert_eq!(
        read(&resumed),
        read(&fresh),
        "resumed summary = fresh summary"
    );
    // A third call has nothing left to do and writes the same summary again.
    let stdout = succeeded(&montecarlo(&resumed, &["--seeds", "8"]));
    assert!(stdout.contains("0 to run"), "{stdout}");
    assert_eq!(read(&resumed), read(&fresh));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_resume_with_another_configuration_is_refused() {
    let dir = scratch("fingerprint");
    let out = dir.join("r.csv");
    succeeded(&montecarlo(&out, &["--seeds", "2"]));
    let other = montecarlo(&out, &["--seeds", "2", "--transient", "100"]);
    assert!(!other.status.success());
    let stderr = String::from_utf8_lossy(&other.stderr);
    assert!(
        stderr.contains("case 'base' was run with another configuration"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn results_do_not_depend_on_the_thread_count() {
    let dir = scratch("threads");
    let (one, two) = (dir.join("one.csv"), dir.join("two.csv"));
    succeeded(&montecarlo(&one, &["--seeds", "6", "--threads", "1"]));
    succeeded(&montecarlo(&two, &["--seeds", "6", "--threads", "2"]));
    assert_eq!(read(&one), read(&two));
    let mut a = per_run_lines(&one);
    let mut b = per_run_lines(&two);
    a.sort_by_key(|(_, seed, _)| *seed);
    b.sort_by_key(|(_, seed, _)| *seed);
    assert_eq!(a, b);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_malformed_case_table_names_the_row_and_column() {
    let dir = scratch("malformed");
    let cases = dir.join("cases.csv");
    std::fs::write(&cases, "name,hs,tp\ncalm,2,8\nrough,4,ten\n").unwrap();
    let out = dir.join("r.csv");
    let output = montecarlo(&out, &["--cases", cases.to_str().unwrap(), "--seeds", "2"]);
    assert!(!output.status.success());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("cases.csv:3: row 2, column 'tp': 'ten' is not a finite number"),
        "{stderr}"
    );
    assert!(!runs_file(&out).exists(), "nothing runs from a bad table");

    std::fs::write(&cases, "name,hs,swell\ncalm,2,1\n").unwrap();
    let output = montecarlo(&out, &["--cases", cases.to_str().unwrap(), "--seeds", "2"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        !output.status.success() && stderr.contains("cases.csv:1: unknown column 'swell'"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_failed_case_keeps_the_others_and_is_reported() {
    let dir = scratch("failed");
    let cases = dir.join("cases.csv");
    std::fs::write(&cases, "name,hs,tp\ncalm,2,8\nbroken,-1,9\nrough,4,10\n").unwrap();
    let out = dir.join("r.csv");
    let args = ["--cases", cases.to_str().unwrap(), "--seeds", "3"];
    let output = montecarlo(&out, &args);
    assert!(!output.status.success(), "failed runs fail the command");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("3 of 9 runs failed"), "{stderr}");

    let summary = read(&out);
    let rows: Vec<&str> = summary.lines().skip(1).collect();
    assert_eq!(rows.len(), 9, "3 cases x 3 DOFs:\n{summary}");
    for row in &rows {
        if row.starts_with("broken,") {
            assert!(row.contains(",3,0,3,failed,"), "{row}");
            assert!(
                row.contains("cases.csv:3: invalid row 2, column 'hs' = -1"),
                "{row}"
            );
        } else {
            assert!(row.contains(",3,3,0,complete,"), "{row}");
        }
    }
    let lines = per_run_lines(&out);
    let broken: Vec<_> = lines.iter().filter(|(c, _, _)| c == "broken").collect();
    assert_eq!(broken.len(), 3);
    for (_, _, fields) in &broken {
        assert_eq!(field(fields, "status"), "failed");
        assert!(field(fields, "error").contains("must be greater than zero"));
    }

    // Fixing the table reruns only the failed case; the others are kept.
    std::fs::write(&cases, "name,hs,tp\ncalm,2,8\nbroken,1,9\nrough,4,10\n").unwrap();
    let stdout = succeeded(&montecarlo(&out, &args));
    assert!(
        stdout.contains("6 already in") && stdout.contains("3 to run"),
        "{stdout}"
    );
    assert!(!read(&out).contains(",failed,"), "{}", read(&out));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_standard_error_is_the_sample_deviation_over_root_n() {
    let dir = scratch("stderr");
    let out = dir.join("r.csv");
    let seeds = 5;
    succeeded(&montecarlo(
        &out,
        &["--seeds", &seeds.to_string(), "--first-seed", "11"],
    ));
    let lines = per_run_lines(&out);
    let summary = read(&out);
    let mut rows = summary.lines();
    let header: Vec<&str> = rows.next().unwrap().split(',').collect();
    let mut checked = 0;
    for row in rows {
        let cells: Vec<&str> = row.split(',').collect();
        let cell = |name: &str| cells[header.iter().position(|h| *h == name).unwrap()];
        let (dof, unit) = (cell("dof"), cell("unit"));
        assert_eq!(cell("seeds_done"), seeds.to_string());
        for stat in ["mean", "rms", "max", "min"] {
            let values: Vec<f64> = lines
                .iter()
                .map(|(_, _, f)| field(f, &format!("{dof}_{stat}_{unit}")).parse().unwrap())
                .collect();
            let n = values.len() as f64;
            let mean = values.iter().sum::<f64>() / n;
            let sample_variance =
                values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
            let se = (sample_variance / n).sqrt();
            let reported_mean: f64 = cell(stat).parse().unwrap();
            let reported_se: f64 = cell(&format!("{stat}_se")).parse().unwrap();
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1e-300);
            assert!(
                close(reported_mean, mean),
                "{dof} {stat}: {reported_mean} vs {mean}"
            );
            assert!(
                close(reported_se, se),
                "{dof} {stat} se: {reported_se} vs {se}"
            );
            checked += 1;
        }
    }
    assert_eq!(checked, 12);
    std::fs::remove_dir_all(&dir).ok();
}

/// The known answer: the mean over seeds of the surge variance (rms^2) of a linear
/// oscillator equals the frequency-domain integral within 4 standard errors as the tool
/// computes them; so does the mean rms against the root of the integral.
#[test]
fn oscillator_variance_agrees_within_the_reported_standard_error() {
    let config = base_problem(16_384.0, 1.0, 0);
    let expected = oscillator_surge_variance(&config);
    let case = Case {
        name: "oscillator".into(),
        problem: config,
        transient: 1_000.0,
    };
    let seeds = 16;
    let jobs: Vec<Job> = (1..=seeds).map(|seed| Job { case: 0, seed }).collect();
    let mut rms = vec![0.0; jobs.len()];
    let never = AtomicBool::new(false);
    run_jobs(std::slice::from_ref(&case), &jobs, 2, &never, |event| {
        if let Some(finished) = event {
            rms[finished.job] = finished.result.unwrap()[0].rms;
        }
    });
    let variance: Vec<f64> = rms.iter().map(|r| r * r).collect();
    let v = seed_statistics(&variance).unwrap();
    let r = seed_statistics(&rms).unwrap();
    let (v_se, r_se) = (v.standard_error.unwrap(), r.standard_error.unwrap());
    eprintln!(
        "oscillator, {seeds} seeds x 16384 s: mean rms^2 {:.5e} +- {v_se:.2e} m^2 vs {expected:.5e} \
         m^2 ({:+.2} se); mean rms {:.5} +- {r_se:.5} m vs {:.5} m ({:+.2} se)",
        v.mean,
        (v.mean - expected) / v_se,
        r.mean,
        expected.sqrt(),
        (r.mean - expected.sqrt()) / r_se
    );
    assert!(
        v_se < 0.03 * expected,
        "the check must be tight: se {v_se:e}"
    );
    assert!((v.mean - expected).abs() < 4.0 * v_se);
    assert!((r.mean - expected.sqrt()).abs() < 4.0 * r_se);
}

/// `--case NAME` runs one case of a table (the Dask package's CLI backend runs each
/// (case, seed) this way): its per-run line equals that case's line of the whole table;
/// an unknown name lists the cases.
#[test]
fn one_case_of_a_table_equals_its_line_in_the_whole_campaign() {
    let dir = scratch("one-case");
    let table = dir.join("cases.csv");
    std::fs::write(&table, "name, hs, tp\nlow, 2, 8\nhigh, 4, 10\n").unwrap();
    let table = table.to_str().unwrap();
    let (all, one) = (dir.join("all.csv"), dir.join("one.csv"));
    succeeded(&montecarlo(&all, &["--cases", table, "--seeds", "2"]));
    let args = [
        "--cases",
        table,
        "--case",
        "high",
        "--seeds",
        "1",
        "--first-seed",
        "2",
    ];
    succeeded(&montecarlo(&one, &args));
    let high_2 = |out: &Path| {
        per_run_lines(out)
            .into_iter()
            .filter(|(case, seed, _)| case == "high" && *seed == 2)
            .collect::<Vec<_>>()
    };
    assert_eq!(per_run_lines(&one).len(), 1);
    assert_eq!(high_2(&one), high_2(&all));
    assert_eq!(high_2(&one).len(), 1);

    let unknown = montecarlo(&one, &["--cases", table, "--case", "mid", "--seeds", "1"]);
    assert!(!unknown.status.success());
    let stderr = String::from_utf8_lossy(&unknown.stderr);
    assert!(
        stderr.contains("--case mid: no such case; the cases are low, high"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// Jobs that share a plan (one per group of cases with the same plan key, made once in
/// `run_jobs`, dropped after the group's last job) give what a run with its own plan gives,
/// bit for bit: cases that differ in the wave height, the drag coefficient and the current
/// share the plan of the good case. A case whose plan cannot be made fails its jobs with its
/// own error, and a refused case of a group (run first) makes no plan for the others.
#[test]
fn shared_plans_give_the_runs_of_fresh_ones() {
    use slowdrift::montecarlo::run_seed;
    use slowdrift::sea_state::Spectrum;
    let mut good = base_problem(400.0, 1.0, 0);
    good.platform.columns = crate::common::four_columns();
    good.model.drag = slowdrift::model::DragModel::Combined { cd: 0.6 };
    let mut bad = good.clone();
    bad.run.time_step = -1.0;
    let with_hs = |hs: f64| {
        let mut c = good.clone();
        if let Spectrum::Jonswap { hs: h, .. } = &mut c.sea.spectrum {
            *h = hs;
        }
        c
    };
    let mut strong = with_hs(8.0);
    strong.model.drag = slowdrift::model::DragModel::Combined { cd: 1.2 };
    strong.current.speed = 0.5;
    let refused = with_hs(-1.0);
    let cases: Vec<Case> = [refused, good, bad, strong]
        .into_iter()
        .enumerate()
        .map(|(i, config)| Case {
            name: format!("c{i}"),
            problem: config,
            transient: 50.0,
        })
        .collect();
    let jobs: Vec<Job> = [
        (0, 1),
        (1, 4),
        (2, 4),
        (1, 9),
        (3, 4),
        (1, 2),
        (2, 5),
        (3, 2),
    ]
    .map(|(case, seed)| Job { case, seed })
    .to_vec();
    let mut results = vec![None; jobs.len()];
    let never = AtomicBool::new(false);
    run_jobs(&cases, &jobs, 2, &never, |event| {
        if let Some(f) = event {
            results[f.job] = Some(f.result);
        }
    });
    for (job, result) in jobs.iter().zip(results) {
        let expected = run_seed(&cases[job.case], job.seed).map_err(|e| e.to_string());
        assert_eq!(result.expect("every job reports"), expected, "{job:?}");
        assert_eq!(expected.is_err(), job.case == 0 || job.case == 2, "{job:?}");
    }
}

/// `slowdrift montecarlo` on the example with `extra` arguments, started and not waited
/// for; stdout discarded, stderr piped.
fn spawn_montecarlo(out: &Path, extra: &[&str]) -> std::process::Child {
    Command::new(env!("CARGO_BIN_EXE_slowdrift"))
        .args(["montecarlo", "--config", EXAMPLE])
        .args(extra)
        .arg("--out")
        .arg(out)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap()
}

/// Sends `signal` (`INT`, `TERM`, `KILL`) to `child` with kill(1).
fn send(signal: &str, child: &std::process::Child) {
    let sent = Command::new("kill")
        .args(["-s", signal, &child.id().to_string()])
        .status()
        .unwrap();
    assert!(sent.success(), "kill -s {signal}");
}

/// Waits (polling, at most 60 s) until `done` says yes.
fn wait_until(what: &str, mut done: impl FnMut() -> bool) {
    let start = std::time::Instant::now();
    while !done() {
        assert!(
            start.elapsed() < std::time::Duration::from_secs(60),
            "waited a minute for {what}"
        );
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
}

/// The lines of the per-run file after its header, sorted (the finishing order aside).
fn sorted_run_lines(out: &Path) -> Vec<String> {
    let mut lines: Vec<String> = read(&runs_file(out))
        .lines()
        .skip(1)
        .map(String::from)
        .collect();
    lines.sort();
    lines
}

/// Issue #15 item 4: a second campaign on the same --out is refused at once (while the
/// first still runs), naming the first's pid and the file; the runs file keeps only the
/// first's lines, each whole.
#[test]
fn a_second_campaign_on_the_same_out_is_refused_naming_the_first() {
    let dir = scratch("lock");
    let out = dir.join("r.csv");
    let args = ["--duration", "8192", "--seeds", "400", "--threads", "1"];
    let mut first = spawn_montecarlo(&out, &args);
    let lock = dir.join("r.runs.csv.lock");
    let pid = first.id().to_string();
    wait_until("the first campaign's lock and two runs", || {
        std::fs::read_to_string(&lock).is_ok_and(|text| text.trim() == pid)
            && std::fs::read_to_string(runs_file(&out)).is_ok_and(|t| t.lines().count() > 2)
    });
    let second = montecarlo_with(&out, &args);
    assert!(
        first.try_wait().unwrap().is_none(),
        "the second was refused while the first still ran"
    );
    assert!(!second.status.success());
    let stderr = String::from_utf8_lossy(&second.stderr);
    assert!(
        stderr.contains(&format!(
            "{}: in use by process {pid}, which holds its lock {}",
            runs_file(&out).display(),
            lock.display()
        )),
        "{stderr}"
    );
    send("TERM", &first);
    let status = first.wait().unwrap();
    assert_eq!(status.code(), Some(143));
    assert!(!lock.exists(), "the lock file goes with the campaign");
    let lines = per_run_lines(&out);
    assert!(!lines.is_empty());
    let mut seeds: Vec<u64> = lines.iter().map(|(_, seed, _)| *seed).collect();
    seeds.sort();
    seeds.dedup();
    assert_eq!(seeds.len(), lines.len(), "each seed once");
    for (case, _, fields) in &lines {
        assert_eq!(case, "base");
        assert_eq!(field(fields, "status"), "ok");
        assert_eq!(fields.len(), 17);
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `slowdrift montecarlo` on the example with exactly `extra` (no --duration added).
fn montecarlo_with(out: &Path, extra: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_slowdrift"))
        .args(["montecarlo", "--config", EXAMPLE])
        .args(extra)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap()
}

/// Issue #15 item 4: a campaign stopped by SIGINT, by SIGTERM, or killed (kill -9, its
/// last line then cut in the middle as a kill inside a write leaves it) and resumed writes
/// the summary of an uninterrupted campaign byte for byte, and the same runs. SIGINT and
/// SIGTERM end it with 128 + the signal's number, the summary of the runs done written
/// and the command to resume printed.
#[test]
fn a_stopped_or_killed_campaign_resumes_to_the_uninterrupted_one() {
    let dir = scratch("signals");
    let args = ["--duration", "8192", "--seeds", "24", "--threads", "2"];
    let reference = dir.join("reference.csv");
    succeeded(&montecarlo_with(&reference, &args));
    for (signal, status) in [("INT", Some(130)), ("TERM", Some(143)), ("KILL", None)] {
        let out = dir.join(format!("{signal}.csv"));
        let child = spawn_montecarlo(&out, &args);
        wait_until("three runs done", || {
            std::fs::read_to_string(runs_file(&out)).is_ok_and(|t| t.lines().count() > 3)
        });
        send(signal, &child);
        let stopped = child.wait_with_output().unwrap();
        let stderr = String::from_utf8_lossy(&stopped.stderr);
        assert_eq!(stopped.status.code(), status, "SIG{signal}: {stderr}");
        if signal == "KILL" {
            use std::os::unix::process::ExitStatusExt;
            assert_eq!(stopped.status.signal(), Some(9));
            // A kill inside the write of a line: the file ends in the middle of one.
            let text = read(&runs_file(&out));
            let last = text[..text.len() - 1].rfind('\n').unwrap() + 1;
            let cut = last + (text.len() - last) / 2;
            std::fs::write(runs_file(&out), &text[..cut]).unwrap();
        } else {
            assert!(
                stderr.contains(&format!("stopped by SIG{signal}: "))
                    && stderr.contains("To resume, run the same command again:")
                    && stderr.contains(&format!("--out {}", out.display())),
                "{stderr}"
            );
            let summary = read(&out);
            assert!(
                summary.contains(",24,") && summary.contains(",partial,"),
                "{summary}"
            );
        }
        let resumed = succeeded(&montecarlo_with(&out, &args));
        assert!(resumed.contains("to run on 2 thread(s)"), "{resumed}");
        assert_eq!(read(&out), read(&reference), "SIG{signal}: the summary");
        assert_eq!(
            sorted_run_lines(&out),
            sorted_run_lines(&reference),
            "SIG{signal}: the runs"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Issue #27: a case that a campaign stopped by SIGINT never reached reads `not started`
/// in the summary (with no seed done and none failed), not `failed`; the case it stopped in
/// reads `partial`. The seeds are announced in words (`seeds 1 to 24`).
#[test]
fn a_case_a_stopped_campaign_never_reached_is_not_started() {
    let dir = scratch("not-started");
    let cases = dir.join("cases.csv");
    std::fs::write(
        &cases,
        "name,hs
first,3
second,4
",
    )
    .unwrap();
    let out = dir.join("r.csv");
    let args = [
        "--cases",
        cases.to_str().unwrap(),
        "--duration",
        "8192",
        "--seeds",
        "24",
        "--threads",
        "1",
    ];
    let child = Command::new(env!("CARGO_BIN_EXE_slowdrift"))
        .args(["montecarlo", "--config", EXAMPLE])
        .args(args)
        .arg("--out")
        .arg(&out)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    wait_until("two runs of the first case", || {
        std::fs::read_to_string(runs_file(&out)).is_ok_and(|t| t.lines().count() > 2)
    });
    send("INT", &child);
    let stopped = child.wait_with_output().unwrap();
    let stdout = String::from_utf8_lossy(&stopped.stdout);
    assert_eq!(
        stopped.status.code(),
        Some(130),
        "{}",
        String::from_utf8_lossy(&stopped.stderr)
    );
    assert!(stdout.contains("seeds 1 to 24 of every case"), "{stdout}");
    assert!(stdout.contains("second           not started"), "{stdout}");
    let summary = read(&out);
    let rows: Vec<&str> = summary.lines().skip(1).collect();
    assert_eq!(rows.len(), 6, "2 cases x 3 DOFs:\n{summary}");
    for row in rows {
        if row.starts_with("second,") {
            assert!(row.contains(",24,0,0,not started,"), "{row}");
        } else {
            assert!(row.contains(",0,partial,"), "{row}");
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Issue #15 item 4: the summary is written anew atomically, so a kill at any moment of a
/// rewrite leaves it whole. A finished campaign of 150 cases (a summary of 450 lines) is
/// started again (nothing to run: it rewrites the summary) and killed at 20 moments spread
/// over such a run; the summary is the whole one after every kill.
#[test]
fn a_kill_never_leaves_the_summary_cut() {
    let dir = scratch("summary-kill");
    let table = dir.join("cases.csv");
    let mut text = String::from("name,hs\n");
    for k in 0..150 {
        text += &format!("c{k},{}\n", 1.0 + 0.01 * k as f64);
    }
    std::fs::write(&table, text).unwrap();
    let out = dir.join("r.csv");
    let args = [
        "--cases",
        table.to_str().unwrap(),
        "--duration",
        "256",
        "--seeds",
        "1",
        "--threads",
        "2",
    ];
    succeeded(&montecarlo_with(&out, &args));
    let whole = read(&out);
    assert_eq!(whole.lines().count(), 1 + 450);
    let start = std::time::Instant::now();
    succeeded(&montecarlo_with(&out, &args));
    let rerun = start.elapsed();
    for k in 0..20 {
        let child = spawn_montecarlo(&out, &args);
        std::thread::sleep(rerun * k / 19);
        send("KILL", &child);
        child.wait_with_output().unwrap();
        assert_eq!(read(&out), whole, "after a kill at {k}/19 of a rewrite");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `run_jobs` with its stop flag set while its runs are in flight returns without reporting
/// them (they are abandoned at their next step, not recorded as failed), and a run that
/// finished before is reported as a run that is never stopped reports it.
#[test]
fn a_stop_abandons_the_runs_in_flight_unreported() {
    use slowdrift::montecarlo::run_seed;
    use std::sync::atomic::Ordering;
    let short = Case {
        name: "short".into(),
        problem: base_problem(256.0, 1.0, 0),
        transient: 50.0,
    };
    // Each long run takes tens of seconds: the stop comes long before any ends.
    let long = Case {
        name: "long".into(),
        problem: base_problem(2.0e6, 1.0, 0),
        transient: 50.0,
    };
    let cases = [short, long];
    let jobs: Vec<Job> = [(0, 1), (1, 1), (1, 2), (1, 3)]
        .map(|(case, seed)| Job { case, seed })
        .to_vec();
    let stop = AtomicBool::new(false);
    let mut reported = Vec::new();
    run_jobs(&cases, &jobs, 1, &stop, |event| match event {
        Some(finished) => reported.push(finished),
        // The first tick after the short run: the long one is in flight.
        None if !reported.is_empty() => stop.store(true, Ordering::Relaxed),
        None => {}
    });
    assert_eq!(reported.len(), 1, "{reported:?}");
    assert_eq!(reported[0].job, 0);
    assert_eq!(reported[0].result, Ok(run_seed(&cases[0], 1).unwrap()));
}

/// The heap this thread held at most above what it held before, in bytes, while the cases
/// of a `rows`-row case table (file `table`) were written as `--print-cases` writes them
/// (the table read as a stream, each case made, written and dropped), and the bytes
/// written.
fn print_cases_peak(table: &Path, rows: usize) -> (isize, usize) {
    use crate::counting::{live_bytes, peak_bytes, reset_peak};
    use slowdrift::fmi2::campaign::write_cases_json;
    use slowdrift::montecarlo::cases::open_case_table;
    let mut text = String::from("name,hs,tp,direction_deg\n");
    for k in 0..rows {
        text += &format!("c{k},{},{},{}\n", 2 + k % 5, 8 + k % 7, k % 360);
    }
    std::fs::write(table, text).unwrap();
    let base = slowdrift::problem::load(Path::new(EXAMPLE)).unwrap();
    let source = table.display().to_string();
    let mut written = 0;
    let mut out = std::io::sink();
    let mut counted = CountingWriter(&mut out, &mut written);
    let before = live_bytes();
    reset_peak();
    let cases = open_case_table(table, LIMIT)
        .unwrap()
        .map(|row| row.and_then(|row| row.case(&base, None, &source)));
    write_cases_json(&mut counted, "sink", cases, &base, "").unwrap();
    (peak_bytes() - before, written)
}

/// A writer that counts the bytes written through it.
struct CountingWriter<'a, W>(&'a mut W, &'a mut usize);

impl<W: std::io::Write> std::io::Write for CountingWriter<'_, W> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        let n = self.0.write(buf)?;
        *self.1 += n;
        Ok(n)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.0.flush()
    }
}

/// Issue #15 item 8: `--print-cases` streams. Writing the cases of a 20 000-row table holds
/// at most what a 200-row one holds plus the names seen (under 200 bytes a row), against a
/// document of 100 times the size: the cases are not held (each holds its whole
/// configuration, tens of kB for the example).
#[test]
fn printing_cases_holds_memory_independent_of_the_rows() {
    let dir = scratch("print-cases");
    let (small, small_out) = print_cases_peak(&dir.join("small.csv"), 200);
    let (large, large_out) = print_cases_peak(&dir.join("large.csv"), 20_000);
    let base = slowdrift::problem::load(Path::new(EXAMPLE)).unwrap();
    let before = crate::counting::live_bytes();
    let copy = base.clone();
    let one_case = crate::counting::live_bytes() - before;
    drop(copy);
    eprintln!(
        "print-cases peak heap: 200 rows {small} B ({small_out} B written), 20 000 rows \
         {large} B ({large_out} B written); one configuration holds {one_case} B of heap"
    );
    assert!(large_out > 90 * small_out);
    assert!(
        large - small < 200 * 19_800,
        "{large} B for 20 000 rows vs {small} B for 200"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// `--print-cases` writes each case as it is made: a bad row stops the document unfinished
/// (after the cases before it; no JSON reader takes it for a whole one) with an error that
/// names the file and line, and the exit status 1; `--case` with an unknown name prints
/// nothing and lists the names.
#[test]
fn printed_cases_stop_unfinished_at_a_bad_row() {
    let dir = scratch("print-bad-row");
    let table = dir.join("cases.csv");
    std::fs::write(&table, "name,hs\na,2\nb,3\nc,x\n").unwrap();
    let print = |extra: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_slowdrift"))
            .args(["montecarlo", "--config", EXAMPLE, "--cases"])
            .arg(&table)
            .args(extra)
            .arg("--print-cases")
            .output()
            .unwrap()
    };
    let output = print(&[]);
    assert_eq!(output.status.code(), Some(1));
    let stdout = String::from_utf8_lossy(&output.stdout);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("cases.csv:4: row 3, column 'hs': 'x' is not a finite number"),
        "{stderr}"
    );
    assert!(
        stdout.starts_with("{\"format_version\":1,\"cases\":[{"),
        "{stdout}"
    );
    assert!(stdout.contains("\"name\":\"b\""), "{stdout}");
    assert!(serde_json::from_str::<serde_json::Value>(&stdout).is_err());

    std::fs::write(&table, "name,hs\na,2\nb,3\n").unwrap();
    let output = print(&["--case", "z"]);
    assert_eq!(output.status.code(), Some(1));
    assert!(output.stdout.is_empty());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("--case z: no such case; the cases are a, b"),
        "{stderr}"
    );
    let output = print(&["--case", "b"]);
    let document: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(document["cases"].as_array().unwrap().len(), 1);
    assert_eq!(document["cases"][0]["name"], "b");
    std::fs::remove_dir_all(&dir).ok();
}

/// A campaign does not make the wave-frequency motion (`Case::simulated`), and its
/// statistics are those of the case as given: on the default platform (RAOs, the motion on),
/// `run_seed` equals the statistics of X, Y and theta of the case's own simulation with the
/// motion on, stepped here and summarised by `stats::summarize`, bit for bit.
#[test]
fn a_campaign_without_the_wave_frequency_motion_gives_the_case_s_slow_drift() {
    use slowdrift::model::WaveFrequencyMotion;
    let mut problem = slowdrift::problem::default_problem().unwrap();
    problem.run.duration = 1200.0;
    assert_eq!(problem.model.wave_frequency_motion, WaveFrequencyMotion::On);
    assert!(
        problem.first_order_motions().unwrap().is_some(),
        "the default has RAOs"
    );
    let case = Case {
        name: "default".into(),
        problem: problem.clone(),
        transient: 300.0,
    };
    assert_eq!(
        case.simulated().model.wave_frequency_motion,
        WaveFrequencyMotion::Off
    );
    let seed = 5;
    let got = slowdrift::montecarlo::run_seed(&case, seed).unwrap();
    problem.sea.seed = seed;
    let mut sim = slowdrift::Simulation::new(problem).unwrap();
    let mut records: [Vec<f64>; 3] = Default::default();
    let mut push = |sim: &slowdrift::Simulation| {
        records
            .iter_mut()
            .zip(sim.position())
            .for_each(|(r, v)| r.push(v));
    };
    push(&sim);
    let h = sim.problem().run.time_step;
    for _ in 0..(1200.0 / h).round() as usize {
        sim.step([0.0; 3]).unwrap();
        push(&sim);
    }
    assert!(
        sim.outputs()
            .unwrap()
            .motion
            .wave_frequency
            .iter()
            .any(|&v| v != 0.0),
        "the case's own run moves at wave frequency"
    );
    for (dof, record) in records.iter().enumerate() {
        let s = slowdrift::stats::summarize(record, h, 300.0).unwrap();
        let scale = if dof == 2 {
            180.0 / std::f64::consts::PI
        } else {
            1.0
        };
        let want = [s.mean, s.rms, s.max, s.min].map(|v| (v * scale).to_bits());
        assert_eq!(got[dof].values().map(f64::to_bits), want, "dof {dof}");
    }
}
