//! The fuzzing harness: the readers (TOML configuration, WAMIT files,
//! case tables, the native database) and FMI call sequences, fed mutated inputs for a time
//! budget. A finding is a panic (caught), an input that takes longer than [`SLOW`], an
//! FMU output returned as fmi2OK but not finite, or a process that dies (an abort: an
//! allocation that the memory budget did not bound, a stack overflow).
//!
//! Each target runs in a child process of this test binary under a limit of its address
//! space (`ulimit -v`, [`CHILD_ADDRESS_SPACE_KB`]): an allocation beyond it that the budget
//! did not refuse aborts the child, not the test run, and the parent reports the input the
//! child was on (written to `target/tmp/fuzz/<target>/current` before each input). Inputs
//! that found something are saved beside it; once fixed they are kept as regression cases
//! in `tests/data/fuzz/<target>/`, replayed before any mutation on every run.
//!
//! Guidance: no coverage instrumentation is available on the stable toolchain, so the
//! corpus grows by outcome: a mutated input joins it when its outcome (accepted, or the
//! error's text with its numbers removed) is one the target has not given before, so that
//! later mutations start from inputs that reach new checks.
//!
//! Budget and seed: `SLOWDRIFT_FUZZ_SECONDS` per target (default [`DEFAULT_SECONDS`], what
//! the test command runs) and `SLOWDRIFT_FUZZ_SEED` (default 1). For a longer run:
//!
//! ```sh
//! SLOWDRIFT_FUZZ_SECONDS=600 SLOWDRIFT_FUZZ_SEED=$RANDOM \
//!     cargo test --release --workspace --test all fuzz:: -- --nocapture --test-threads=1
//! ```

mod fmi;
mod mutate;
mod targets;

use mutate::Rng;
use std::collections::HashSet;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// Seconds per target in the test command.
const DEFAULT_SECONDS: f64 = 5.0;
/// An input slower than this is a finding (a hang, or work no bound limits).
const SLOW: Duration = Duration::from_secs(10);
/// Address space of a target's child process, kB: the default memory budget (4 GB) does
/// not fit, so anything near it must be refused by the allocator probe, not aborted on.
const CHILD_ADDRESS_SPACE_KB: u64 = 3_000_000;
/// Inputs kept in a target's corpus at most.
const MAX_CORPUS: usize = 400;
/// The environment variable that makes a fuzz test its own child.
const CHILD: &str = "SLOWDRIFT_FUZZ_CHILD";

/// What one input did.
pub enum Outcome {
    /// Accepted, or refused with this message (numbers are removed to classify it).
    Done(Result<(), String>),
    /// Something that must never happen, said in words.
    Finding(String),
}

/// What a target does with one input (and its working directory).
pub type Run = Box<dyn Fn(&[u8], &Path) -> Outcome>;

/// A fuzz target: its seeds and what it does with one input.
pub struct Target {
    pub name: &'static str,
    pub seeds: Vec<Vec<u8>>,
    pub run: Run,
}

fn seconds() -> f64 {
    std::env::var("SLOWDRIFT_FUZZ_SECONDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(DEFAULT_SECONDS)
}

fn seed() -> u64 {
    std::env::var("SLOWDRIFT_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1)
}

/// `target/tmp/fuzz/<name>`, made empty.
fn work_dir(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("fuzz")
        .join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The regression cases of a target: every file of `tests/data/fuzz/<name>/`.
fn regressions(name: &str) -> Vec<(PathBuf, Vec<u8>)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/fuzz")
        .join(name);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map(|entries| entries.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    files.sort();
    files
        .into_iter()
        .map(|p| {
            let bytes = std::fs::read(&p).unwrap();
            (p, bytes)
        })
        .collect()
}

/// An error's kind: its text with digits removed and cut short.
fn kind(outcome: &Result<(), String>) -> String {
    match outcome {
        Ok(()) => "ok".into(),
        Err(e) => e.chars().filter(|c| !c.is_ascii_digit()).take(80).collect(),
    }
}

/// One input, timed, its panic caught.
fn attempt(target: &Target, input: &[u8], dir: &Path) -> Outcome {
    std::fs::write(dir.join("current"), input).unwrap();
    let start = Instant::now();
    let outcome =
        catch_unwind(AssertUnwindSafe(|| (target.run)(input, dir))).unwrap_or_else(|panic| {
            let message = panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default();
            Outcome::Finding(format!("panic: {message}"))
        });
    let took = start.elapsed();
    match outcome {
        Outcome::Done(_) if took > SLOW => Outcome::Finding(format!("took {took:.1?}")),
        other => other,
    }
}

/// The child's loop: the regression cases, then mutations for the budget. Returns the
/// findings (each saved beside `current`).
fn fuzz(target: &Target) -> Vec<String> {
    let dir = work_dir(target.name);
    let mut findings = Vec::new();
    let report = |input: &[u8], what: String, findings: &mut Vec<String>| {
        let path = dir.join(format!("finding-{}", findings.len()));
        std::fs::write(&path, input).unwrap();
        findings.push(format!("{what} (input: {})", path.display()));
    };
    for (path, input) in regressions(target.name) {
        if let Outcome::Finding(what) = attempt(target, &input, &dir) {
            report(
                &input,
                format!("regression {}: {what}", path.display()),
                &mut findings,
            );
        }
    }
    let mut corpus = target.seeds.clone();
    let mut seen = HashSet::new();
    for input in &target.seeds {
        match attempt(target, input, &dir) {
            Outcome::Done(outcome) => {
                seen.insert(kind(&outcome));
            }
            Outcome::Finding(what) => report(input, format!("seed: {what}"), &mut findings),
        }
    }
    let mut rng = Rng::new(seed() ^ target.name.len() as u64);
    let budget = Duration::from_secs_f64(seconds());
    let start = Instant::now();
    let mut runs = 0usize;
    while start.elapsed() < budget && findings.len() < 20 {
        let base = rng.below(corpus.len());
        let other = rng.below(corpus.len());
        let input = mutate::mutate(&mut rng, &corpus[base], &corpus[other]);
        runs += 1;
        match attempt(target, &input, &dir) {
            Outcome::Done(outcome) => {
                if seen.insert(kind(&outcome)) && corpus.len() < MAX_CORPUS {
                    corpus.push(input);
                }
            }
            Outcome::Finding(what) => report(&input, what, &mut findings),
        }
    }
    println!(
        "fuzz {}: {runs} inputs in {:.1?}, {} outcomes, corpus {}, {} findings",
        target.name,
        start.elapsed(),
        seen.len(),
        corpus.len(),
        findings.len()
    );
    findings
}

/// Runs `target` (by its test's name) in a child process under the address-space limit and
/// fails with the findings, or with the input a dead child was on.
fn run_target(test: &str, make: fn() -> Target) {
    if std::env::var(CHILD).as_deref() == Ok(test) {
        let findings = fuzz(&make());
        assert!(findings.is_empty(), "findings:\n{}", findings.join("\n"));
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
            &format!("fuzz::{test}"),
            "--nocapture",
            "--test-threads=1",
        ])
        .env(CHILD, test)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    let stderr = String::from_utf8_lossy(&output.stderr);
    println!("{stdout}");
    if !output.status.success() {
        let name = make().name;
        let current = work_dir(name).join("current");
        let kept = work_dir(name).join("crash");
        std::fs::copy(&current, &kept).ok();
        panic!(
            "fuzz target {name}: the child {:?} (its last input: {})\n{stdout}\n{}",
            output.status,
            kept.display(),
            stderr
                .chars()
                .rev()
                .take(4000)
                .collect::<String>()
                .chars()
                .rev()
                .collect::<String>()
        );
    }
}

#[test]
fn configuration() {
    run_target("configuration", targets::configuration);
}

#[test]
fn wamit() {
    run_target("wamit", targets::wamit);
}

#[test]
fn case_table() {
    run_target("case_table", targets::case_table);
}

#[test]
fn database() {
    run_target("database", targets::database);
}

#[test]
fn fmi_calls() {
    run_target("fmi_calls", fmi::target);
}
