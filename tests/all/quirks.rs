//! The quirks of real hydrodynamic files: frequencies computed from
//! printed periods, mixed time conventions. The files are written here from closed forms;
//! the expected numbers come from those forms and from integrals computed in the test.

use crate::common::{base_problem, jonswap, long_crested, simpson};
use rustfft::num_complex::Complex64;
use slowdrift::hydro::io::wamit::{self, read_difference_qtf, WamitOptions};
use slowdrift::model::{SecondOrder, FREQUENCY_MATCH_TOLERANCE};
use slowdrift::problem::{Hydro, DEFAULT_BAND_TRIM_LIMIT};
use slowdrift::{Problem, Simulation};
use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

const RHO: f64 = 1025.0;
const G: f64 = 9.80665;

/// A fresh, empty directory under the system's temporary directory.
pub fn temp_dir(name: &str) -> PathBuf {
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let dir = std::env::temp_dir().join(format!(
        "slowdrift-quirks-{}-{}-{name}",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temporary directory");
    dir
}

/// A smooth Hermitian QTF, nondimensional (divided by rho g): T(w1, w2) = conj T(w2, w1).
fn closed_form_qtf(dof: usize, w1: f64, w2: f64) -> Complex64 {
    let size = match dof {
        1 => 1.0,
        2 => 0.2,
        _ => 5.0,
    };
    size * (0.5 + w1 * w2) * Complex64::from_polar(1.0, 0.7 * (w1 - w2))
}

/// A `.12d` file (lower triangle, heading 0, DOFs 1, 2, 6) on `omegas`, with the periods
/// printed as `period_format` does and every column consistent (polar and Cartesian).
fn write_qtf(path: &Path, omegas: &[f64], period: impl Fn(f64) -> String) {
    let mut text = String::from(" WAMIT-style header written by the test\n");
    for (i, &w1) in omegas.iter().enumerate() {
        for &w2 in &omegas[..=i] {
            for dof in [1, 2, 6] {
                // The value at the printed periods' frequencies, so that the file is
                // exactly the closed form at its own nodes.
                let (p1, p2) = (period(w1), period(w2));
                let (f1, f2) = (
                    2.0 * PI / p1.parse::<f64>().unwrap(),
                    2.0 * PI / p2.parse::<f64>().unwrap(),
                );
                let t = closed_form_qtf(dof, f1, f2);
                text += &format!(
                    "{p1} {p2} 0.0 0.0 {dof} {:.7e} {:.5} {:.7e} {:.7e}\n",
                    t.norm(),
                    t.arg().to_degrees(),
                    t.re,
                    t.im
                );
            }
        }
    }
    std::fs::write(path, text).unwrap();
}

/// The problem of a `.12d` written with periods printed to five significant digits: a
/// 0.1-rad/s grid from 0.2 to `top` rad/s, full QTF, JONSWAP Hs 6 m Tp 10 s.
fn printed_period_problem(name: &str, top: f64) -> (Problem, Vec<f64>) {
    let dir = temp_dir(name);
    let n = ((top - 0.2) / 0.1).round() as usize + 1;
    let omegas: Vec<f64> = (0..n).map(|k| 0.2 + 0.1 * k as f64).collect();
    let root = dir.join("body");
    write_qtf(
        &PathBuf::from(format!("{}.12d", root.display())),
        &omegas,
        |w| format!("{:.4}", 2.0 * PI / w),
    );
    let database = wamit::import(&root, &WamitOptions::default())
        .unwrap()
        .database;
    let mut problem = base_problem(600.0, 1.0, 1);
    problem.hydro = Hydro {
        qtf: database.qtf.as_ref().map(|q| q.to_qtf()),
        bidirectional: None,
        ..Hydro::from_drift(database.to_drift_table().unwrap())
    };
    problem.sea = long_crested(jonswap(6.0, 10.0), 1);
    problem.model.second_order = SecondOrder::FullQtf;
    let data = problem.hydro.drift.omegas().to_vec();
    (problem, data)
}

/// The IEA-15 MW case: the file's top frequency, from a printed period, is 2.4999...
/// rad/s. A band to 2.5 rad/s is covered within the documented tolerance, and the default
/// band of Tp = 10 s (to 4 wp = 2.5133 rad/s) is limited to the data, with the share of the
/// variance left out computed here by an independent integral.
#[test]
fn printed_periods_cover_the_band_they_stand_for() {
    let (problem, data) = printed_period_problem("iea15", 2.5);
    let top = data[data.len() - 1];
    assert!(
        top < 2.5 && top > 2.5 * (1.0 - FREQUENCY_MATCH_TOLERANCE),
        "{top}"
    );
    println!("top frequency from the printed period 2.5133 s: {top:.7} rad/s");

    let mut explicit = problem.clone();
    explicit.sea.band = Some((0.3, 2.5));
    assert_eq!(explicit.band(), (0.3, 2.5));
    assert!(explicit.band_trim().is_none());
    let sim = Simulation::new(explicit).expect("a band to 2.5 rad/s is covered");
    assert!(sim.grid().omega(sim.grid().count - 1) <= 2.5);

    let wp = 2.0 * PI / 10.0;
    let trim = problem
        .band_trim()
        .expect("the default band is limited to the data");
    assert_eq!(trim.default, (0.5 * wp, 4.0 * wp));
    assert_eq!(trim.band, (0.5 * wp, top));
    let spectrum = &problem.sea.spectrum;
    let variance = |a: f64, b: f64| simpson(|w| spectrum.density(w), a, b, 2000);
    let expected = variance(top, 4.0 * wp) / variance(0.5 * wp, 4.0 * wp);
    assert!(
        (trim.variance_left_out / expected - 1.0).abs() < 1e-4,
        "{} vs {expected}",
        trim.variance_left_out
    );
    println!(
        "default band {:.4} .. {:.4} rad/s limited to {:.4} .. {:.7}: {:.3e} of the variance left out",
        trim.default.0, trim.default.1, trim.band.0, trim.band.1, trim.variance_left_out
    );
    let sim = Simulation::new(problem).expect("the default band runs on the data");
    let grid = sim.grid();
    assert!(grid.omega(grid.count - 1) <= top);
    assert!(grid.omega(grid.count - 1) > top - grid.d_omega);
}

/// Data that stop well inside the default band are not stretched to it: limiting the band
/// to 0.2 .. 2.0 rad/s would leave out more than the documented share of the variance, so
/// the default band is kept and the run is refused naming the gap.
#[test]
fn data_far_short_of_the_default_band_are_refused_naming_the_gap() {
    let (problem, _) = printed_period_problem("short", 1.2);
    let wp = 2.0 * PI / 10.0;
    let spectrum = &problem.sea.spectrum;
    let variance = |a: f64, b: f64| simpson(|w| spectrum.density(w), a, b, 2000);
    let left_out = variance(2.0 * PI / 5.2360, 4.0 * wp) / variance(0.5 * wp, 4.0 * wp);
    assert!(left_out > DEFAULT_BAND_TRIM_LIMIT, "{left_out}");
    assert!(problem.band_trim().is_none());
    let Err(error) = Simulation::new(problem) else {
        panic!("data short of the band must be refused")
    };
    let message = error.to_string();
    assert!(message.contains("1.2000 .. 2.5133 rad/s"), "{message}");
}

/// A line whose abs(F) and phase are the conjugate of its Re and Im mixes the time
/// conventions: refused naming the file, the line and the fields.
#[test]
fn a_line_mixing_time_conventions_is_refused() {
    let dir = temp_dir("mixed");
    let good = "header\n10.0 10.0 0 0 1 2.0 0.0 2.0 0.0\n10.0 5.0 0 0 1 2.0 30.0 1.7320508 1.0\n";
    let path = dir.join("good.12d");
    std::fs::write(&path, good).unwrap();
    let qtf = read_difference_qtf(&path, &WamitOptions::default());
    assert!(qtf.is_err(), "the other triangle's (5, 5) is missing");
    let mixed = good.replace("1.7320508 1.0", "1.7320508 -1.0");
    let path = dir.join("mixed.12d");
    std::fs::write(&path, &mixed).unwrap();
    let message = read_difference_qtf(&path, &WamitOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        message.starts_with(&format!("{}:3:", path.display()))
            && message.contains("mixes the time conventions"),
        "{message}"
    );
    let wrong = good.replace("1.7320508 1.0", "1.0 1.0");
    let path = dir.join("wrong.12d");
    std::fs::write(&path, &wrong).unwrap();
    let message = read_difference_qtf(&path, &WamitOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        message.contains(":3:") && message.contains("not the same complex number"),
        "{message}"
    );
    // The value read is the Cartesian form, scaled; the polar form agrees.
    let full = format!("{good}5.0 5.0 0 0 1 1.0 0.0 1.0 0.0\n");
    let path = dir.join("full.12d");
    std::fs::write(&path, &full).unwrap();
    let qtf = read_difference_qtf(&path, &WamitOptions::default()).unwrap();
    let (i, j) = (
        qtf.omega_index(2.0 * PI / 10.0).unwrap(),
        qtf.omega_index(2.0 * PI / 5.0).unwrap(),
    );
    let t = qtf.value(1, (0.0, 0.0), i, j).unwrap();
    assert!((t - Complex64::new(1.7320508, 1.0) * RHO * G).norm() < 1e-9 * t.norm());
}

/// A sparse QTF (pairs missing off the diagonal, as converted from other codes): interior
/// holes of a difference-frequency line are filled linearly between the line's nearest
/// given pairs (here compared with the interpolation of the closed form, computed in the
/// test) and counted; holes beyond the largest given difference frequency are refused,
/// every one listed.
#[test]
fn sparse_qtfs_are_filled_along_difference_lines_or_refused_listing_the_holes() {
    let dir = temp_dir("sparse");
    let omegas: Vec<f64> = (0..6).map(|k| 0.4 + 0.2 * k as f64).collect();
    let period = |w: f64| format!("{:.12}", 2.0 * PI / w);
    let path = dir.join("full.12d");
    write_qtf(&path, &omegas, period);
    let text = std::fs::read_to_string(&path).unwrap();
    let index = |w: f64| omegas.iter().position(|&o| (o - w).abs() < 1e-9).unwrap();
    let pair_of = |line: &str| -> (usize, usize) {
        let v: Vec<f64> = line
            .split_whitespace()
            .map(|f| f.parse().unwrap())
            .collect();
        (index(2.0 * PI / v[0]), index(2.0 * PI / v[1]))
    };
    // Drop (3, 1) and (4, 2) (interior of the line i - j = 2) and (4, 1) (interior of
    // i - j = 3): three pairs per DOF.
    let dropped = [(3, 1), (4, 2), (4, 1)];
    let sparse: String = text
        .lines()
        .enumerate()
        .filter(|(k, l)| *k == 0 || !dropped.contains(&pair_of(l)))
        .map(|(_, l)| format!("{l}\n"))
        .collect();
    let path = dir.join("sparse.12d");
    std::fs::write(&path, &sparse).unwrap();
    let qtf = read_difference_qtf(&path, &WamitOptions::default()).unwrap();
    // Each dropped pair and its Hermitian mirror, three DOFs.
    assert_eq!(qtf.filled_by_interpolation(), 2 * 3 * dropped.len());
    let exact =
        |dof: usize, i: usize, j: usize| closed_form_qtf(dof, omegas[i], omegas[j]) * RHO * G;
    for dof in [1, 2, 6] {
        for &(i, j) in &dropped {
            // Neighbours on the line: the nearest given pairs (i -+ m, j -+ m).
            let (below, above) = match (i, j) {
                (3, 1) => ((2, 0), (5, 3)),
                (4, 2) => ((2, 0), (5, 3)),
                _ => ((3, 0), (5, 2)),
            };
            let mean = |(a, b): (usize, usize)| omegas[a] + omegas[b];
            let s = (mean((i, j)) - mean(below)) / (mean(above) - mean(below));
            let expected =
                exact(dof, below.0, below.1) * (1.0 - s) + exact(dof, above.0, above.1) * s;
            let got = qtf.value(dof, (0.0, 0.0), i, j).unwrap();
            assert!(
                (got - expected).norm() < 1e-6 * expected.norm(),
                "{dof} ({i}, {j})"
            );
            assert_eq!(qtf.value(dof, (0.0, 0.0), j, i).unwrap(), got.conj());
        }
    }
    let import_dir = temp_dir("sparse-import");
    std::fs::copy(&path, import_dir.join("body.12d")).unwrap();
    let import = wamit::import(&import_dir.join("body"), &WamitOptions::default()).unwrap();
    assert!(
        import
            .files
            .iter()
            .any(|l| l.contains("warning: a sparse QTF, 18 values")),
        "{:?}",
        import.files
    );

    // The corner (5, 0) alone on its line: nothing on either side to interpolate from.
    let corner: String = text
        .lines()
        .enumerate()
        .filter(|(k, l)| *k == 0 || pair_of(l) != (5, 0))
        .map(|(_, l)| format!("{l}\n"))
        .collect();
    let path = dir.join("corner.12d");
    std::fs::write(&path, &corner).unwrap();
    let message = read_difference_qtf(&path, &WamitOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("2 of 36 frequency pairs missing")
            && message.contains("w1 = 0.400000: w2 = 1.400000; w1 = 1.400000: w2 = 0.400000"),
        "{message}"
    );
}
