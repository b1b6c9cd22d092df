//! What reading a file costs: every reader states the most memory it
//! holds per byte of the file (`files::Cost`), and a file whose size times that exceeds the
//! memory limit is refused before it is read. Here each reader reads its format's costliest
//! contents (the shortest lines that each make an entry, names or keys that each make a
//! table, empty rows, a header of a million fields) and the peak the counting allocator
//! measures on this thread while it reads must stay within its stated cost, which must not
//! be looser than 2.5 times the worst peak (it would refuse files that fit). A QTF's
//! matrices, which grow with the square of its frequencies, not its size, are budgeted
//! where they are made: a file whose every line has its own frequencies is refused before
//! they are allocated.

use crate::counting::{live_bytes, peak_bytes, reset_peak};
use crate::quirks::temp_dir;
use slowdrift::files::Cost;
use slowdrift::hydro::io::nemoh::{cal, matrices, qtf as nemoh_qtf, tec};
use slowdrift::hydro::io::wamit::{self, WamitOptions};
use slowdrift::hydro::io::{database, drift_csv};
use slowdrift::montecarlo::{cases, runs_file};
use slowdrift::scenario::limits::DEFAULT_MEMORY_LIMIT as LIMIT;
use std::path::{Path, PathBuf};

/// `head`, then `unit` repeated to about `bytes`, then `tail`.
fn repeated(head: &str, unit: &str, tail: &str, bytes: usize) -> String {
    let mut s = String::with_capacity(bytes + head.len() + tail.len());
    s.push_str(head);
    while s.len() + unit.len() <= bytes {
        s.push_str(unit);
    }
    s.push_str(tail);
    s
}

/// `head`, then `line(k)` for k = 0, 1, ... to about `bytes`.
fn numbered(head: &str, line: impl Fn(usize) -> String, bytes: usize) -> String {
    let mut s = String::from(head);
    let mut k = 0;
    while s.len() < bytes {
        s.push_str(&line(k));
        k += 1;
    }
    s
}

/// One content of a format and how its reader reads it (the outcome does not matter: a
/// refused file has been read, and its memory held, before the refusal).
struct Content {
    name: &'static str,
    file: &'static str,
    text: String,
}

/// Reads each content with `read` (the path of its file) and checks the peak per byte
/// against `cost`; returns the worst ratio.
fn check(cost: &Cost, contents: Vec<Content>, read: &dyn Fn(&Path)) -> f64 {
    let dir = temp_dir("reading-cost");
    let mut worst: f64 = 0.0;
    for content in contents {
        let path = dir.join(content.file);
        std::fs::write(&path, &content.text).unwrap();
        let size = content.text.len() as f64;
        drop(content.text);
        let before = live_bytes();
        reset_peak();
        read(&path);
        let ratio = (peak_bytes() - before) as f64 / size;
        println!(
            "{}: {}: {:.2} MB, peak {ratio:.1} bytes per byte",
            cost.format,
            content.name,
            size / 1e6
        );
        assert!(
            ratio <= cost.per_byte,
            "{}: {}: {ratio:.1} bytes per byte, more than the stated {}",
            cost.format,
            content.name,
            cost.per_byte
        );
        worst = worst.max(ratio);
    }
    assert!(
        cost.per_byte <= 2.5 * worst,
        "{}: the stated {} bytes per byte is more than 2.5 times the worst peak {worst:.1}",
        cost.format,
        cost.per_byte
    );
    std::fs::remove_dir_all(dir).ok();
    worst
}

fn content(name: &'static str, file: &'static str, text: String) -> Content {
    Content { name, file, text }
}

#[test]
fn the_toml_reader_stays_within_its_cost() {
    const SIZE: usize = 500_000;
    let chain = vec!["a"; 40].join(".");
    let contents = vec![
        content(
            "inline tables of 40 dotted keys",
            "c.toml",
            repeated("[sea]\nx = [", &format!("{{{chain}=0}},"), "0]\n", SIZE),
        ),
        content(
            "lines of 40 dotted keys",
            "c.toml",
            numbered("", |k| format!("t{k}.{chain}=0\n"), SIZE),
        ),
        content(
            "inline tables {a=0}",
            "c.toml",
            repeated("[sea]\nx = [", "{a=0},", "0]\n", SIZE),
        ),
        content(
            "an inline drift table of one-digit numbers",
            "c.toml",
            repeated(
                &with_drift(
                    "source = \"table\"\nfields = [\"omega\", \"beta_deg\", \"surge\", \
                     \"sway\", \"yaw\"]\nrows = [",
                ),
                "[0,0,0,0,0],",
                "]\n",
                SIZE,
            ),
        ),
        content("comments", "c.toml", repeated("", "# comment\n", "", SIZE)),
        content(
            "a long string",
            "c.toml",
            repeated("[sea]\nx = \"", "a", "\"\n", SIZE),
        ),
    ];
    check(&slowdrift::scenario::file::READING, contents, &|path| {
        let _ = slowdrift::scenario::file::load(path, LIMIT);
    });
}

#[test]
fn the_csv_drift_reader_stays_within_its_cost() {
    const SIZE: usize = 2_000_000;
    let header = "omega,beta_deg,surge,sway,yaw\n";
    let contents = vec![
        content(
            "rows of five zeros",
            "d.csv",
            repeated(header, "0,0,0,0,0\n", "", SIZE),
        ),
        content(
            "distinct rows",
            "d.csv",
            numbered(header, |k| format!("{},0,0,0,0\n", k + 1), SIZE),
        ),
        content(
            "rows with damping",
            "d.csv",
            repeated(
                "omega,beta_deg,surge,sway,yaw,b11,b12,b13,b21,b22,b23,b31,b32,b33\n",
                "0,0,0,0,0,0,0,0,0,0,0,0,0,0\n",
                "",
                SIZE,
            ),
        ),
        content(
            "a header of a million fields",
            "d.csv",
            repeated("", "a,", "a\n", SIZE),
        ),
        content(
            "a row of a million fields",
            "d.csv",
            repeated(header, "0,", "0\n", SIZE),
        ),
    ];
    check(&drift_csv::READING, contents, &|path| {
        let _ = drift_csv::read(path, LIMIT);
    });
}

/// The embedded default configuration with its `[drift]` section (the last) made of
/// `drift`.
fn with_drift(drift: &str) -> String {
    let text = slowdrift::scenario::default::DEFAULT_CONFIG_TOML;
    let start = text.find("\n[drift]\n").unwrap();
    assert!(
        !text[start + 1..].contains("\n["),
        "[drift] is the last section"
    );
    format!("{}\n[drift]\n{drift}", &text[..start])
}

/// A configuration that names `database` as its drift source (the default's otherwise).
fn naming(database: &Path) -> PathBuf {
    let config = with_drift(&format!(
        "source = \"database\"\nfile = \"{}\"\n",
        database.display()
    ));
    let path = database.with_extension("toml");
    std::fs::write(&path, config).unwrap();
    path
}

/// The database's fields before its drift table.
const HEAD: &str = r#"{"format_version": 1, "name": "x", "source": "x", "water_density": 1025.0, "gravity": 9.80665, "mass_properties": null, "low_frequency_added_mass": null, "stiffness": null, "#;

#[test]
fn the_database_reader_stays_within_its_cost() {
    const SIZE: usize = 2_000_000;
    let qtf = |unit: &str, tail: &str| {
        repeated(
            &format!(
                "{HEAD}\"drift\": [], \"qtf\": {{\"omegas\": [1], \"blocks\": [{{\"dof\":\
                 \"surge\",\"heading\":0,\"re\":["
            ),
            unit,
            &format!("{tail}], \"im\": [[0]]}}]}}}}"),
            SIZE,
        )
    };
    // A valid database: n x n zeros in each of re and im, the drift its diagonal.
    let n = 300;
    let row = format!("[{}]", vec!["0"; n].join(","));
    let matrix = format!("[{}]", vec![row.as_str(); n].join(","));
    let omegas: Vec<String> = (1..=n).map(|k| format!("{}", k as f64 * 0.01)).collect();
    let drift: Vec<String> = omegas
        .iter()
        .map(|w| {
            format!(r#"{{"omega":{w},"heading":0,"surge":0,"sway":0,"yaw":0,"damping":null}}"#)
        })
        .collect();
    let valid = format!(
        "{HEAD}\"drift\": [{}], \"qtf\": {{\"omegas\": [{}], \"blocks\": [{}]}}}}",
        drift.join(","),
        omegas.join(","),
        ["surge", "sway", "yaw"]
            .map(|dof| format!(r#"{{"dof":"{dof}","heading":0,"re":{matrix},"im":{matrix}}}"#))
            .join(",")
    );
    let contents = vec![
        content(
            "drift points",
            "db.json",
            repeated(
                &format!("{HEAD}\"drift\": ["),
                r#"{"omega":0,"heading":0,"surge":0,"sway":0,"yaw":0,"damping":null},"#,
                r#"{"omega":0,"heading":0,"surge":0,"sway":0,"yaw":0,"damping":null}]}"#,
                SIZE,
            ),
        ),
        content("rows of one zero", "db.json", qtf("[0],", "[0]")),
        content("empty rows", "db.json", qtf("[],", "[]")),
        content("one row of zeros", "db.json", qtf("[0,", "0]")),
        content(
            "a QTF of 300 x 300 zeros, drift and QTF read",
            "db.json",
            valid,
        ),
    ];
    check(&database::READING, contents, &|path| {
        let _ = slowdrift::problem::load(&naming(path));
    });
}

#[test]
fn the_numeric_file_reader_stays_within_its_cost() {
    const SIZE: usize = 2_000_000;
    let options = WamitOptions::default();
    let contents = vec![
        content(
            ".1, four fields",
            "b.1",
            repeated("", "1 1 1 1\n", "", SIZE),
        ),
        content(
            ".1, five fields",
            "b.1",
            repeated("", "1 1 1 1 1\n", "", SIZE),
        ),
        content(
            ".1, distinct periods",
            "b.1",
            numbered("", |k| format!("{} 1 1 1 1\n", k + 1), SIZE),
        ),
        content(
            ".1, a line of a million fields",
            "b.1",
            repeated("", "1 ", "1\n", SIZE),
        ),
        content(".hst", "b.hst", repeated("", "1 1 1\n", "", SIZE)),
        content(".8", "b.8", repeated("", "1 0 0 1 0 0 0 0\n", "", SIZE)),
        content(
            ".12d",
            "b.12d",
            repeated("", "1 1 0 0 1 0 0 0 0\n", "", SIZE),
        ),
    ];
    check(&wamit::READING, contents, &|path| {
        let _ = match path.extension().and_then(|e| e.to_str()) {
            Some("1") => wamit::read_added_mass_damping(path, &options).map(|_| ()),
            Some("hst") => wamit::read_hydrostatics(path, &options).map(|_| ()),
            Some("8") => wamit::read_mean_drift(path, &options).map(|_| ()),
            _ => wamit::read_difference_qtf(path, &options).map(|_| ()),
        };
    });
}

/// The OC3 spar's Nemoh.cal (`../shared/data`), or `None` after printing a "skipped" line.
fn nemoh_cal() -> Option<String> {
    let path = crate::common::shared_data_dir().join("nemoh/oc3-hywind/Nemoh.cal");
    let text = std::fs::read_to_string(&path).ok();
    if text.is_none() {
        println!("skipped the NEMOH QTF: data absent at {}", path.display());
    }
    text
}

#[test]
fn the_nemoh_readers_stay_within_their_cost() {
    const SIZE: usize = 2_000_000;
    check(
        &cal::READING,
        vec![content(
            "blank lines",
            "Nemoh.cal",
            repeated("", "\n", "", SIZE),
        )],
        &|path| {
            let _ = cal::NemohCal::read(path, LIMIT);
        },
    );
    check(
        &matrices::READING,
        vec![
            content(
                "one number a line",
                "CM.dat",
                repeated("a 1\n", "1\n", "", SIZE),
            ),
            content(
                "a million frequencies of one DOF",
                "CM.dat",
                repeated("a 1000000\n", "1\n1\n", "", SIZE),
            ),
            content(
                "a row of a million numbers",
                "CM.dat",
                repeated("a 1\n1\n", "1 ", "1\n", SIZE),
            ),
        ],
        &|path| {
            let _ = matrices::read_frequency_matrices(path, 1, LIMIT);
            let _ = matrices::read_matrix6(path, LIMIT);
        },
    );
    let head = "VARIABLES=\"w (rad/s)\"\n\"A 1 1\" \"B 1 1\"\n";
    check(
        &tec::READING,
        vec![
            content(
                "one number a line",
                "RadiationCoefficients.tec",
                repeated(head, "1\n", "", SIZE),
            ),
            content(
                "a zone of one-DOF rows",
                "RadiationCoefficients.tec",
                repeated(
                    &format!("{head}Zone t=\"DoF 1\",I=1000000,F=POINT\n"),
                    "1 1 1\n",
                    "",
                    SIZE,
                ),
            ),
            content(
                "zone lines",
                "ExcitationForce.tec",
                repeated(
                    head,
                    "Zone t=\"beta = 1 deg\",I=1,F=POINT\n1 1 1\n",
                    "",
                    SIZE,
                ),
            ),
        ],
        &|path| {
            let _ = tec::read_radiation(path, 1, 1, LIMIT);
            let _ = tec::read_excitation(path, 1, LIMIT);
        },
    );
    if let Some(text) = nemoh_cal() {
        let dir = temp_dir("nemoh-cal");
        let path = dir.join("Nemoh.cal");
        std::fs::write(&path, text).unwrap();
        let nemoh = cal::NemohCal::read(&path, LIMIT).unwrap();
        let settings = nemoh.qtf.clone().unwrap();
        check(
            &wamit::READING,
            vec![content(
                "QTF lines of one-digit numbers",
                "OUT_QTFM_N.dat",
                repeated("header\n", "1 1 0 0 1 0 0 0 0\n", "", SIZE),
            )],
            &|path| {
                let _ = nemoh_qtf::read_difference_qtf(path, &nemoh, &settings, LIMIT);
            },
        );
    }
}

#[test]
fn the_montecarlo_readers_stay_within_their_cost() {
    check(
        &cases::READING,
        vec![
            content(
                "a column of one-digit numbers",
                "cases.csv",
                repeated("hs\n", "1\n", "", 500_000),
            ),
            content(
                "two columns",
                "cases.csv",
                repeated("hs,tp\n", "1,1\n", "", 500_000),
            ),
            content(
                "words",
                "cases.csv",
                repeated("drag\n", "off\n", "", 500_000),
            ),
            content(
                "names",
                "cases.csv",
                numbered("name\n", |k| format!("{k:x}\n"), 500_000),
            ),
        ],
        &|path| {
            let _ = cases::read_case_table(path, LIMIT);
        },
    );
    let header = format!("{}\n", runs_file::header());
    check(
        &runs_file::READING,
        vec![
            content(
                "failed runs",
                "runs.csv",
                numbered(
                    &header,
                    |k| format!("a,{k},f,failed,,,,,,,,,,,,,e\n"),
                    250_000,
                ),
            ),
            content(
                "runs",
                "runs.csv",
                numbered(
                    &header,
                    |k| format!("a,{k},f,ok,0,0,0,0,0,0,0,0,0,0,0,0,\n"),
                    250_000,
                ),
            ),
        ],
        &|path| {
            let _ = runs_file::RunsFile::open(path, LIMIT);
        },
    );
}

/// A `.12d` file of 2000 lines (40 kB), each on the diagonal at its own period: 2000
/// frequencies, whose 2000 x 2000 matrices (one block, its own mirror) need 40 bytes per
/// pair, 160 MB. It is refused before they are made under a 0.1 GB limit, and read within
/// the estimate under the default.
#[test]
fn a_qtf_grid_is_budgeted_before_its_matrices_are_made() {
    let dir = temp_dir("qtf-grid");
    let path = dir.join("diagonal.12d");
    let lines = 2000;
    let text: String = (1..=lines)
        .map(|k| format!("{k} {k} 0 0 1 1 0 1 0\n"))
        .collect();
    std::fs::write(&path, text).unwrap();
    let n = lines as f64;
    let needs = 40.0 * n * n;
    let options = WamitOptions {
        memory_limit: 0.1e9,
        ..WamitOptions::default()
    };
    let start = std::time::Instant::now();
    let message = wamit::read_difference_qtf(&path, &options)
        .unwrap_err()
        .to_string();
    assert!(start.elapsed().as_secs_f64() < 1.0);
    assert!(
        message.contains(&format!(
            "diagonal.12d: reading it needs {:.0} MB of memory (a QTF of {lines} x {lines} \
             frequency pairs in 1 blocks",
            needs / 1e6
        )) && message.contains("the limit is 100 MB (run.memory_limit_gb = 0.1)"),
        "{message}"
    );
    let before = live_bytes();
    reset_peak();
    let read = wamit::read_difference_qtf(&path, &WamitOptions::default());
    let peak = (peak_bytes() - before) as f64;
    println!(
        "{lines} frequencies: estimate {:.0} MB, peak {:.0} MB ({})",
        needs / 1e6,
        peak / 1e6,
        read.err().map_or("read".into(), |e| e.to_string())
    );
    assert!(
        peak <= needs && needs <= 2.5 * peak,
        "{peak} against {needs}"
    );
    std::fs::remove_dir_all(dir).ok();
}

/// `slowdrift hydro wamit` on a 100 MB `.1` file (1.2 GB to read) under a 1 GB process
/// limit: refused at once with exit status 1 and a message naming the file, its size, the
/// estimate and why (before, the process aborted: "memory allocation of ... bytes failed").
#[test]
fn the_cli_refuses_a_wamit_file_this_process_cannot_read() {
    let dir = temp_dir("wamit-under-a-process-limit");
    let root = dir.join("big");
    let text = repeated("", "1 1 1 1 1\n", "", 100_000_000);
    std::fs::write(root.with_extension("1"), text).unwrap();
    let out = dir.join("out.json");
    let start = std::time::Instant::now();
    let output = std::process::Command::new("bash")
        .arg("-c")
        .arg("ulimit -v 1000000 && exec \"$0\" \"$@\"")
        .arg(env!("CARGO_BIN_EXE_slowdrift"))
        .args(["hydro", "wamit", "--root"])
        .arg(&root)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    println!("{:?} in {:.2?}: {stderr}", output.status, start.elapsed());
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains(
            "big.1: reading it needs 3.200 GB of memory (a numeric file (WAMIT's layout) of \
             100000000 bytes (100 MB), up to 32 bytes of memory per byte) and this process \
             cannot allocate them: its own memory limit (ulimit, a container) or the \
             machine's is lower than run.memory_limit_gb = 4 GB"
        ),
        "{stderr}"
    );
    assert!(!out.exists());
    std::fs::remove_dir_all(dir).ok();
}
