//! What the user gives is what runs: the model takes its mass and added
//! mass from the user's data where the configuration does not give its own, and says so;
//! a stiffness that stores negative energy and values beyond their physical ranges are
//! refused naming the setting where it was written (configuration file, case table, FMU).
//!
//! Expected values come from the raw files (the WAMIT `.1` line at PER = -1, read here as
//! text) and closed forms (the free oscillation period 2 pi sqrt((M + A) / K)), never from
//! SlowDrift's own output.

use crate::common::shared_data_dir;
use crate::fmu::Fmu;
use slowdrift::fmi2::model_description::vr;
use slowdrift::fmi2::types::fmi2Status;
use slowdrift::hydro::io::wamit::{self, WamitOptions};
use slowdrift::problem::{self, Origin, Problem};
use slowdrift::scenario::file;
use slowdrift::scenario::limits::DEFAULT_MEMORY_LIMIT as LIMIT;
use slowdrift::Simulation;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The IEA-15 semi's WAMIT files without extension, or `None` after printing a "skipped"
/// line when the data are absent. Under CI (env var `CI` set) absent data is a failure.
fn iea15_root_or_skip() -> Option<PathBuf> {
    let dir = shared_data_dir().join("wamit/iea15-semi");
    let root = dir.join("IEA-15-240-RWT-UMaineSemi");
    if dir.join("IEA-15-240-RWT-UMaineSemi.1").is_file() {
        return Some(root);
    }
    if std::env::var_os("CI").is_some() {
        panic!(
            "the IEA-15 WAMIT data are absent at {} (CI is set: they must be there; set \
             SLOWDRIFT_DATA to the shared data directory)",
            dir.display()
        );
    }
    println!("skipped: data absent at {}", dir.display());
    None
}

/// A scratch directory removed on drop.
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Scratch {
        let dir = std::env::temp_dir().join(format!("slowdrift-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        Scratch(dir)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        std::fs::remove_dir_all(&self.0).ok();
    }
}

/// The surge added mass at omega = 0 from the raw `.1` text: the line `-1 1 1 Abar`
/// (PER = -1, I = J = 1), A = rho ULEN^3 Abar with ULEN = 1 m, rho = 1025 kg/m^3.
fn raw_surge_added_mass(root: &Path) -> f64 {
    let text = std::fs::read_to_string(root.with_extension("1")).unwrap();
    let abar = text
        .lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>())
        .find(|f| f.len() >= 4 && f[1] == "1" && f[2] == "1" && f[0].parse() == Ok(-1.0))
        .map(|f| f[3].parse::<f64>().unwrap())
        .expect("the .1 file has its PER = -1 surge line");
    1025.0 * abar
}

/// The platform of the report: mass 2e7 kg and surge stiffness 8.95e4 N/m, the
/// IEA-15 semi's yaw inertia (SOURCE.md), its database `iea.json` beside the configuration,
/// a sea too small to move it (Hs 1 mm), no damping: the platform oscillates freely from
/// X = 5 m. `platform_extra` is written into `[platform]`.
fn iea_config(platform_extra: &str) -> String {
    format!(
        "[sea]\nspectrum = \"jonswap\"\nhs = 0.001\ntp = 10.0\n\n\
         [run]\nduration = 1500.0\ntime_step = 1.0\n\n\
         [platform]\nmass = 2.0e7\nyaw_inertia = 2.3667e10\n{platform_extra}\
         stiffness = [[8.95e4, 0.0, 0.0], [0.0, 8.95e4, 0.0], [0.0, 0.0, 1.0e9]]\n\n\
         [model]\ndrift_damping = \"off\"\n\n\
         [initial]\nposition = [5.0, 0.0]\n\n\
         [drift]\nsource = \"database\"\nfile = \"iea.json\"\n"
    )
}

/// The IEA-15 database in `dir/iea.json` and the configuration `text` in `dir/iea.toml`.
fn write_iea(dir: &Path, root: &Path, text: &str) -> PathBuf {
    wamit::import(root, &WamitOptions::default())
        .unwrap()
        .database
        .save(&dir.join("iea.json"))
        .unwrap();
    let config = dir.join("iea.toml");
    std::fs::write(&config, text).unwrap();
    config
}

/// The free oscillation's period: the mean spacing of the upward zero crossings of X
/// (linearly interpolated between steps), s.
fn free_period(problem: Problem) -> f64 {
    let h = problem.run.time_step;
    let steps = (problem.run.duration / h) as usize;
    let mut sim = Simulation::new(problem).unwrap();
    let mut crossings = Vec::new();
    let mut previous = sim.position()[0];
    for n in 1..=steps {
        sim.step([0.0; 3]).unwrap();
        let x = sim.position()[0];
        if previous < 0.0 && x >= 0.0 {
            crossings.push((n as f64 - 1.0 + previous / (previous - x)) * h);
        }
        previous = x;
    }
    assert!(crossings.len() >= 5, "{crossings:?}");
    (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64
}

fn slowdrift(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_slowdrift"))
        .args(args)
        .output()
        .expect("the CLI runs")
}

/// The report: the IEA-15 semi's WAMIT import with mass 2e7 kg and K 8.95e4 N/m
/// oscillated at 94 s (no added mass, 2 pi sqrt(M / K)); with the database's A11(0) the
/// free surge period is 2 pi sqrt((M + A11) / K) = 120 s, A11 read from the raw `.1` text.
#[test]
fn a_wamit_import_added_mass_reaches_the_equations_of_motion() {
    let Some(root) = iea15_root_or_skip() else {
        return;
    };
    let scratch = Scratch::new("iea-added-mass");
    let config = write_iea(&scratch.0, &root, &iea_config(""));
    let problem = problem::load(&config).unwrap();
    let a11 = raw_surge_added_mass(&root);
    assert!((a11 - 1.264e7).abs() < 1e4, "{a11}");
    let inertia = problem.inertia().unwrap();
    assert!((inertia.added_mass[0][0] / a11 - 1.0).abs() < 1e-12);
    let expected = 2.0 * PI * ((2.0e7 + a11) / 8.95e4).sqrt();
    let without = 2.0 * PI * (2.0e7_f64 / 8.95e4).sqrt();
    assert!((expected - 120.0).abs() < 0.5 && (without - 94.0).abs() < 0.5);
    let period = free_period(problem);
    assert!(
        (period / expected - 1.0).abs() < 2e-3,
        "free period {period} s, expected {expected} s (without added mass {without} s)"
    );
}

/// `simulate` says what it used and where from: the added mass with the database and the
/// WAMIT file it came from, the mass from [platform], the natural period it gives.
#[test]
fn the_summary_names_the_added_mass_and_its_source() {
    let Some(root) = iea15_root_or_skip() else {
        return;
    };
    let scratch = Scratch::new("iea-summary");
    let config = write_iea(&scratch.0, &root, &iea_config(""));
    let run = slowdrift(&["simulate", "--config", config.to_str().unwrap()]);
    let out = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "{out}{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let a11 = raw_surge_added_mass(&root);
    let database = scratch.0.join("iea.json").display().to_string();
    let added = format!(
        "added mass surge {a11:.3e} kg, sway {a11:.3e} kg, yaw {:.3e} kg m^2 ({database}, WAMIT \
         .1 at omega = 0 (PER = -1))",
        1025.0 * 2.531095e7
    );
    assert!(out.contains(&added), "{added}\nnot in\n{out}");
    assert!(
        out.contains("mass 2.000e7 kg, yaw inertia 2.367e10 kg m^2 ([platform])"),
        "{out}"
    );
    let period = 2.0 * PI * ((2.0e7 + a11) / 8.95e4).sqrt();
    assert!(
        out.contains(&format!("natural periods surge {period:.1} s")),
        "{out}"
    );
    assert!(!out.contains("note:"), "{out}");
}

/// A configuration that gives its own added mass runs it (the free period follows it), and
/// the run says that the database's is not used.
#[test]
fn the_configuration_added_mass_wins_with_a_note() {
    let Some(root) = iea15_root_or_skip() else {
        return;
    };
    let scratch = Scratch::new("iea-own-added-mass");
    let own = "added_mass = [[5.0e6, 0.0, 0.0], [0.0, 5.0e6, 0.0], [0.0, 0.0, 1.0e10]]\n";
    let config = write_iea(&scratch.0, &root, &iea_config(own));
    let problem = problem::load(&config).unwrap();
    let inertia = problem.inertia().unwrap();
    assert_eq!(inertia.added_mass_origin, Origin::Configuration);
    let expected = 2.0 * PI * ((2.0e7 + 5.0e6) / 8.95e4_f64).sqrt();
    let period = free_period(problem);
    assert!(
        (period / expected - 1.0).abs() < 2e-3,
        "{period} vs {expected}"
    );
    let run = slowdrift(&["simulate", "--config", config.to_str().unwrap()]);
    let out = String::from_utf8_lossy(&run.stdout);
    assert!(run.status.success(), "{out}");
    assert!(
        out.contains("note: platform.added_mass from [platform] is used (A11 = 5e6 kg"),
        "{out}"
    );
    assert!(out.contains("added mass surge 5.000e6 kg"), "{out}");
}

/// Without a mass anywhere (a drift table has no body data) the run is refused naming the
/// key and its file; with a NEMOH database (OC3 spar, Mechanics/Inertia.dat) the absent mass
/// and yaw inertia are the database's.
#[test]
fn a_mass_comes_from_the_data_or_is_required() {
    let example = include_str!("../data/example.toml");
    let without: String = example
        .lines()
        .filter(|l| !l.starts_with("mass =") && !l.starts_with("yaw_inertia ="))
        .map(|l| format!("{l}\n"))
        .collect();
    assert_ne!(without, example);
    let message = file::parse(&without, "nomass.toml", Path::new("."))
        .and_then(|s| problem::resolve(&s))
        .and_then(|p| p.check().map(|()| p))
        .unwrap_err()
        .to_string();
    assert!(
        message.starts_with("nomass.toml")
            && message.contains(
                "[platform] mass = (not given): is required: the configuration's \
                                 [drift] table holds no mass properties; give it in [platform]"
            ),
        "{message}"
    );
    let dir = shared_data_dir().join("nemoh/oc3-hywind");
    if !dir.join("Nemoh.cal").is_file() {
        assert!(
            std::env::var_os("CI").is_none(),
            "NEMOH data absent under CI"
        );
        println!("skipped: data absent at {}", dir.display());
        return;
    }
    let scratch = Scratch::new("oc3-mass");
    let db = slowdrift::hydro::io::nemoh::import(&dir, LIMIT)
        .unwrap()
        .database;
    db.save(&scratch.0.join("oc3.json")).unwrap();
    let text = "[environment]\ngravity = 9.81\n\n\
         [sea]\nspectrum = \"jonswap\"\nhs = 6.0\ntp = 12.0\nband = [0.25, 1.5]\n\n\
         [run]\nduration = 600.0\n\n\
         [platform]\nstiffness = [[4.0e4, 0.0, 0.0], [0.0, 4.0e4, 0.0], [0.0, 0.0, 1.0e8]]\n\n\
         [model]\ndrift_damping = \"off\"\n\n\
         [drift]\nsource = \"database\"\nfile = \"oc3.json\"\n";
    let scenario = file::parse(text, "oc3.toml", &scratch.0).unwrap();
    let p = problem::resolve(&scenario).unwrap();
    p.check().unwrap();
    let inertia = p.inertia().unwrap();
    let props = db.mass_properties.unwrap();
    assert_eq!(
        (inertia.mass, inertia.yaw_inertia),
        (props.mass, props.yaw_inertia)
    );
    assert!(
        inertia
            .mass_origin
            .to_string()
            .ends_with("NEMOH Mechanics/Inertia.dat"),
        "{}",
        inertia.mass_origin
    );
}

/// The configuration `example.toml` with `old` replaced by `new`, its first error as text.
fn example_error(old: &str, new: &str) -> String {
    let example = include_str!("../data/example.toml");
    assert!(example.contains(old), "{old}");
    let text = example.replacen(old, new, 1);
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    file::parse(&text, "user.toml", &dir)
        .and_then(|s| problem::resolve(&s))
        .and_then(|p| p.check())
        .unwrap_err()
        .to_string()
}

/// The line of `needle` in example.toml, 1-based.
fn example_line(needle: &str) -> usize {
    include_str!("../data/example.toml")
        .lines()
        .position(|l| l.contains(needle))
        .unwrap()
        + 1
}

/// A negative or indefinite stiffness is refused in the configuration file at its line;
/// gravity, water density, mass, Tp, band and draft beyond their physical ranges likewise.
#[test]
fn configuration_values_beyond_physics_are_refused_at_their_line() {
    let rows = "  [8.0e4, 0.0,   0.0],\n  [0.0,   8.0e4, 0.0],\n  [0.0,   0.0,   7.7e7],";
    // A matrix entry is located at its row's line, the matrix at its key's.
    let at = example_line("stiffness = [") + 1;
    let message = example_error(
        rows,
        "  [-8.0e4, 0, 0],\n  [0, 8.0e4, 0],\n  [0, 0, 7.7e7],",
    );
    assert!(
        message.starts_with(&format!(
            "user.toml:{at}: invalid [platform] stiffness[0][0] = -80000: must not be negative"
        )),
        "{message}"
    );
    // Surge-yaw coupling beyond sqrt(C11 C33) = sqrt(8e4 x 7.7e7) = 2.5e6.
    let message = example_error(
        rows,
        "  [8.0e4, 0, 3.0e6],\n  [0, 8.0e4, 0],\n  [3.0e6, 0, 7.7e7],",
    );
    assert!(
        message.starts_with(&format!(
            "user.toml:{}: invalid [platform] stiffness = ",
            at - 1
        )) && message.contains("not positive semi-definite"),
        "{message}"
    );
    for (old, new, key) in [
        (
            "gravity = 9.80665",
            "gravity = 1e300",
            "[environment] gravity = 1e300",
        ),
        (
            "water_density = 1025.0",
            "water_density = 1.0",
            "[environment] water_density = 1",
        ),
        ("mass = 1.2e7", "mass = 1e-300", "[platform] mass = 1e-300"),
        // Named as written, not as the steep sea or the Nyquist limit it would make.
        ("tp = 9.0", "tp = 1e-6", "[sea] tp = 1e-6"),
        (
            "band = [0.3, 2.0]",
            "band = [0.3, 1e300]",
            "[sea] band[1] = 1e300",
        ),
        (
            "draft = 20.0",
            "draft = 1e300",
            "[platform] columns[0].draft = 1e300",
        ),
    ] {
        let at = example_line(old);
        let message = example_error(old, new);
        assert!(
            message.starts_with(&format!("user.toml:{at}: invalid {key}: must be within")),
            "{old}: {message}"
        );
    }
}

/// The FMU refuses a negative stiffness parameter at initialisation naming it; zero (an
/// external mooring) runs, and its log says that nothing inside restores the platform.
#[test]
fn the_fmu_refuses_a_negative_stiffness() {
    let fmu = Fmu::new("negative-stiffness");
    assert_eq!(fmu.setup(0.0, Some(3600.0)), fmi2Status::fmi2OK);
    assert_eq!(fmu.set_real(vr::STIFFNESS_SURGE, -1.0), fmi2Status::fmi2OK);
    assert_eq!(fmu.init(), fmi2Status::fmi2Error);
    let message = fmu.last_message().message;
    assert!(
        message.contains("invalid FMU parameter stiffnessSurge = -1: must not be negative"),
        "{message}"
    );
    let fmu = Fmu::new("zero-stiffness");
    assert_eq!(fmu.setup(0.0, Some(3600.0)), fmi2Status::fmi2OK);
    for k in [vr::STIFFNESS_SURGE, vr::STIFFNESS_SWAY, vr::STIFFNESS_YAW] {
        assert_eq!(fmu.set_real(k, 0.0), fmi2Status::fmi2OK);
    }
    assert_eq!(fmu.init(), fmi2Status::fmi2OK, "{}", fmu.messages());
}

/// A case table's stiffness column below zero: that case's runs are refused naming the
/// file, row and column (the other cases run, as for any case the model refuses), and the
/// campaign fails.
#[test]
fn a_case_table_negative_stiffness_is_refused_at_its_row() {
    let scratch = Scratch::new("negative-stiffness-cases");
    let cases = scratch.0.join("cases.csv");
    std::fs::write(&cases, "name,surge_stiffness\nsoft,1.0e5\nbad,-2.0e5\n").unwrap();
    let run = slowdrift(&[
        "montecarlo",
        "--cases",
        cases.to_str().unwrap(),
        "--seeds",
        "1",
        "--duration",
        "600",
        "--out",
        scratch.0.join("runs.csv").to_str().unwrap(),
    ]);
    let out = String::from_utf8_lossy(&run.stdout);
    assert!(!run.status.success(), "{out}");
    assert!(
        out.contains(&format!(
            "1 run(s) failed; first: seed 1: {}:3: invalid row 2, column 'surge_stiffness' = \
             -200000: must not be negative",
            cases.display()
        )),
        "{out}"
    );
    let soft = out
        .lines()
        .find(|l| l.starts_with("soft") && l.contains("surge"));
    assert!(soft.is_some_and(|l| l.contains(" 1/1 ")), "{out}");
}
