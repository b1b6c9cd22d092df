//! WAMIT readers and the native database.
//!
//! Real data: the OC4 DeepCwind semisubmersible (`../shared/data/wamit/oc4-semi`, or
//! `$SLOWDRIFT_DATA/wamit/oc4-semi`). Every expected value is parsed from the raw text here,
//! independently of the readers (split_whitespace on chosen lines), and scaled by hand.
//! Synthetic files cover what the real data do not: header lines, both triangles, DOFs and
//! headings in any order, bi-directional pairs, malformed lines, missing DOFs and headings.

use rustfft::num_complex::Complex64;
use slowdrift::hydro::io::database::{HydroDatabase, MassProperties, FORMAT_VERSION};
use slowdrift::hydro::io::wamit::{
    self, read_added_mass_damping, read_difference_qtf, read_hydrostatics, read_mean_drift,
    WamitOptions,
};
use slowdrift::model::Dof;
use slowdrift::scenario::limits::DEFAULT_MEMORY_LIMIT as LIMIT;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

const RHO: f64 = 1025.0;
const G: f64 = 9.80665;

/// A fresh, empty directory under the system's temporary directory.
pub fn temp_dir(name: &str) -> PathBuf {
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let dir = std::env::temp_dir().join(format!(
        "slowdrift-wamit-{}-{}-{name}",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temporary directory");
    dir
}

pub fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).expect("temporary file");
    path
}

pub fn with_ext(root: &Path, ext: &str) -> PathBuf {
    PathBuf::from(format!("{}.{ext}", root.display()))
}

/// Line `n` (1-based) of a file as numbers.
fn raw_line(path: &Path, n: usize) -> Vec<f64> {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines()
        .nth(n - 1)
        .unwrap()
        .split_whitespace()
        .map(|f| f.parse().unwrap())
        .collect()
}

/// rho g L^k per unit amplitude squared, L = 1: forces (DOF 1-3) and moments alike.
fn force_scale(ulen: f64, dof: usize) -> f64 {
    RHO * G * if dof <= 3 { ulen } else { ulen * ulen }
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs())
}

// ------------------------------------------------------------------------ OC4 .12d

#[test]
fn oc4_qtf_grid_layout_and_triangle_from_the_raw_text() {
    let Some(root) = crate::common::oc4_root_or_skip() else {
        return;
    };
    let path = with_ext(&root, "12d");
    let text = std::fs::read_to_string(&path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    assert!(header.contains("WAMIT"), "first line is the text header");
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split_whitespace().map(|f| f.parse().unwrap()).collect())
        .collect();
    // Independent grid: the distinct period texts of both columns.
    let mut periods: Vec<f64> = rows.iter().flat_map(|r| [r[0], r[1]]).collect();
    periods.sort_by(f64::total_cmp);
    periods.dedup();
    assert_eq!(periods.len(), 56);
    let dof_order: Vec<usize> = rows[..6].iter().map(|r| r[4] as usize).collect();
    assert_eq!(dof_order, [1, 3, 5, 2, 4, 6]);
    assert!(
        rows.iter().all(|r| r[2] == 0.0 && r[3] == 0.0),
        "heading 0 only"
    );
    assert!(
        rows.iter().all(|r| r[0] <= r[1]),
        "one triangle: PER1 <= PER2"
    );
    assert_eq!(
        rows.len(),
        56 * 57 / 2 * 6,
        "the triangle incl. the diagonal"
    );

    let qtf = read_difference_qtf(&path, &WamitOptions::default()).unwrap();
    let omegas = qtf.omegas();
    assert_eq!(omegas.len(), 56);
    assert!((omegas[0] - 0.25).abs() < 1e-4 && (omegas[55] - 3.0).abs() < 1e-4);
    assert!(omegas.windows(2).all(|w| (w[1] - w[0] - 0.05).abs() < 1e-4));
    assert_eq!(qtf.dofs(), [1, 2, 3, 4, 5, 6]);
    assert_eq!(qtf.headings(), [0.0]);
    assert_eq!(qtf.blocks().len(), 6);
    assert_eq!(qtf.filled_by_symmetry(), 55 * 56 / 2 * 6);
    println!(
        "OC4 .12d: {} frequencies {:.5} .. {:.5} rad/s, DOFs {:?}",
        omegas.len(),
        omegas[0],
        omegas[55],
        qtf.dofs()
    );
}

#[test]
fn oc4_qtf_values_are_the_scaled_raw_lines_and_hermitian_exactly() {
    let Some(root) = crate::common::oc4_root_or_skip() else {
        return;
    };
    let path = with_ext(&root, "12d");
    let qtf = read_difference_qtf(&path, &WamitOptions::default()).unwrap();
    for n in [2, 8, 17, 500, 4321, 9000, 9577] {
        let v = raw_line(&path, n);
        let (i, j) = (
            qtf.omega_index(2.0 * PI / v[0]).unwrap(),
            qtf.omega_index(2.0 * PI / v[1]).unwrap(),
        );
        let dof = v[4] as usize;
        let expected = Complex64::new(v[7], v[8]) * force_scale(1.0, dof);
        let got = qtf.value(dof, (0.0, 0.0), i, j).unwrap();
        assert!(
            close(got.re, expected.re, 1e-14) && close(got.im, expected.im, 1e-14),
            "line {n}: {got} vs {expected}"
        );
        // The other triangle is the conjugate, bit for bit (the diagonal is kept as given).
        if i != j {
            assert_eq!(qtf.value(dof, (0.0, 0.0), j, i).unwrap(), got.conj());
        }
        // The modulus and phase columns (degrees) describe the same number: the file's
        // complex value is |F| e^{i phase}, no sign flip between the columns.
        let (modulus, phase) = (v[5], v[6].to_radians());
        let polar = Complex64::from_polar(modulus, phase);
        assert!(
            (polar - Complex64::new(v[7], v[8])).norm() <= 2e-5 * modulus.max(1e-12),
            "line {n}: |F| e^(i phase) = {polar} vs Re, Im = {}, {}",
            v[7],
            v[8]
        );
    }
    let n = qtf.omegas().len();
    for block in qtf.blocks() {
        for i in 0..n {
            for j in 0..i {
                assert_eq!(block.values[j * n + i], block.values[i * n + j].conj());
            }
        }
    }
}

#[test]
fn oc4_qtf_diagonal_is_real_and_is_the_mean_drift() {
    let Some(root) = crate::common::oc4_root_or_skip() else {
        return;
    };
    let path = with_ext(&root, "12d");
    let qtf = read_difference_qtf(&path, &WamitOptions::default()).unwrap();
    let n = qtf.omegas().len();
    let largest = |dof: usize| {
        let m = qtf.matrix(dof, 0.0).unwrap();
        (0..n).map(|i| m[i * n + i].norm()).fold(0.0, f64::max)
    };
    // Surge, heave, pitch: real to single-precision noise, entry by entry where the drift
    // is not negligible.
    for dof in [1, 3, 5] {
        let m = qtf.matrix(dof, 0.0).unwrap();
        for i in 0..n {
            let t = m[i * n + i];
            assert!(t.im.abs() <= 1e-6 * largest(dof), "DOF {dof} at {i}: {t}");
            if t.norm() > 1e-3 * largest(dof) {
                assert!(t.im.abs() <= 1e-5 * t.norm(), "DOF {dof} at {i}: {t}");
            }
        }
    }
    // Sway, roll, yaw vanish in head seas on this symmetric platform: the whole complex
    // diagonal is noise, three orders of magnitude below surge (forces) or pitch (moments).
    assert!(
        largest(2) <= 1e-3 * largest(1),
        "{} vs {}",
        largest(2),
        largest(1)
    );
    assert!(
        largest(4) <= 1e-3 * largest(5),
        "{} vs {}",
        largest(4),
        largest(5)
    );
    assert!(
        largest(6) <= 1e-3 * largest(5),
        "{} vs {}",
        largest(6),
        largest(5)
    );
    let table = qtf.to_drift_table(&[0.0], [1, 2, 6]).unwrap();
    assert_eq!(table.omegas(), qtf.omegas());
    let surge = qtf.diagonal(1, 0.0).unwrap();
    let yaw = qtf.diagonal(6, 0.0).unwrap();
    for (iw, (&(w, t1), &(_, t6))) in surge.iter().zip(&yaw).enumerate() {
        assert_eq!(table.drift_at_node(0, iw)[0], t1);
        assert_eq!(table.drift_at_node(0, iw)[2], t6);
        assert_eq!(table.omegas()[iw], w);
    }
    // The diagonal from the raw text: lines with PER1 = PER2 and DOF 1.
    let text = std::fs::read_to_string(&path).unwrap();
    let mut raw: Vec<(f64, f64)> = text
        .lines()
        .skip(1)
        .map(|l| l.split_whitespace().map(|f| f.parse().unwrap()).collect())
        .filter(|v: &Vec<f64>| v[0] == v[1] && v[4] == 1.0)
        .map(|v| (2.0 * PI / v[0], v[7] * RHO * G))
        .collect();
    raw.sort_by(|a, b| a.0.total_cmp(&b.0));
    assert_eq!(raw.len(), n);
    for (&(w, t), &(rw, rt)) in surge.iter().zip(&raw) {
        assert!(close(w, rw, 1e-12) && close(t, rt, 1e-14));
    }
    println!("OC4 mean surge drift in head seas, N/m^2 (QTF diagonal):");
    for &k in &[0, 5, 15, 25, 35, 45, 55] {
        println!("  omega = {:.3} rad/s: {:.4e}", surge[k].0, surge[k].1);
    }
}

// ------------------------------------------------------------------------ OC4 .1, .hst

#[test]
fn oc4_added_mass_and_damping_from_the_raw_text() {
    let Some(root) = crate::common::oc4_root_or_skip() else {
        return;
    };
    let path = with_ext(&root, "1");
    let text = std::fs::read_to_string(&path).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .map(|l| l.split_whitespace().map(|f| f.parse().unwrap()).collect())
        .collect();
    assert!(rows.iter().any(|r| r[0] == -1.0) && rows.iter().any(|r| r[0] == 0.0));
    let mut finite: Vec<f64> = rows.iter().map(|r| r[0]).filter(|&p| p > 0.0).collect();
    finite.sort_by(f64::total_cmp);
    finite.dedup();

    let amd = read_added_mass_damping(&path, &WamitOptions::default()).unwrap();
    assert_eq!(amd.omegas.len(), finite.len());
    assert!(amd.omegas.windows(2).all(|w| w[1] > w[0]));
    let zero = amd.zero_frequency_added_mass.expect("PER = -1 rows");
    let infinite = amd.infinite_frequency_added_mass.expect("PER = 0 rows");
    for r in &rows {
        let (i, j) = (r[1] as usize, r[2] as usize);
        let k = 3 + i32::from(i >= 4) + i32::from(j >= 4);
        let a = RHO * r[3] * 1f64.powi(k);
        if r[0] == -1.0 {
            assert_eq!(zero[i - 1][j - 1], a);
        } else if r[0] == 0.0 {
            assert_eq!(infinite[i - 1][j - 1], a);
        } else {
            let omega = 2.0 * PI / r[0];
            let m = amd
                .omegas
                .iter()
                .position(|&w| close(w, omega, 1e-12))
                .unwrap();
            assert_eq!(amd.added_mass[m][i - 1][j - 1], a);
            assert!(close(
                amd.damping[m][i - 1][j - 1],
                RHO * omega * r[4],
                1e-14
            ));
        }
    }
    // Unlisted pairs (zero by the xz symmetry) are zero.
    assert_eq!(zero[0][1], 0.0);
    println!(
        "OC4 .1: {} frequencies {:.4} .. {:.4} rad/s; A11(0) = {:.5e} kg, A66(0) = {:.5e} kg m^2",
        amd.omegas.len(),
        amd.omegas[0],
        amd.omegas[amd.omegas.len() - 1],
        zero[0][0],
        zero[5][5]
    );
}

#[test]
fn oc4_hydrostatics_heave_positive_and_symmetric() {
    let Some(root) = crate::common::oc4_root_or_skip() else {
        return;
    };
    let path = with_ext(&root, "hst");
    let c = read_hydrostatics(&path, &WamitOptions::default())
        .unwrap()
        .c;
    let heave = raw_line(&path, 15);
    assert_eq!((heave[0], heave[1]), (3.0, 3.0));
    assert_eq!(c[2][2], RHO * G * heave[2]);
    assert!(c[2][2] > 0.0);
    for (i, row) in c.iter().enumerate() {
        for (j, v) in row.iter().enumerate() {
            assert_eq!(*v, c[j][i], "C{}{} vs C{}{}", i + 1, j + 1, j + 1, i + 1);
        }
    }
    assert_eq!(
        [c[0][0], c[1][1], c[5][5]],
        [0.0; 3],
        "no surge/sway/yaw hydrostatics"
    );
}

// ------------------------------------------------------------------------ OC4 database

#[test]
fn oc4_database_from_wamit_saves_loads_and_gives_the_qtf_diagonal() {
    let Some(root) = crate::common::oc4_root_or_skip() else {
        return;
    };
    let options = WamitOptions::default();
    let import = wamit::import(&root, &options).unwrap();
    for line in &import.files {
        println!("{line}");
    }
    let found = |ext: &str| {
        import.files.iter().any(|l| {
            l.starts_with(&with_ext(&root, ext).display().to_string()) && !l.ends_with("absent")
        })
    };
    assert!(found("1") && found("hst") && found("12d"));
    assert!(!found("8") && !found("9"));
    let db = &import.database;
    assert_eq!(db.name, "marin_semi");
    assert!(db.source.contains("QTF diagonal"), "{}", db.source);

    let amd = read_added_mass_damping(&with_ext(&root, "1"), &options).unwrap();
    let a0 = amd.zero_frequency_added_mass.unwrap();
    let slow = [0, 1, 5];
    assert_eq!(
        db.low_frequency_added_mass.unwrap(),
        slow.map(|i| slow.map(|j| a0[i][j]))
    );
    assert_eq!(db.stiffness.unwrap(), [[0.0; 3]; 3]);

    let qtf = read_difference_qtf(&with_ext(&root, "12d"), &options).unwrap();
    assert_eq!(
        db.to_drift_table().unwrap(),
        qtf.to_drift_table(&[0.0], [1, 2, 6]).unwrap()
    );
    let stored = db.qtf.as_ref().unwrap();
    assert_eq!(stored.omegas, qtf.omegas());
    let n = stored.omegas.len();
    for (block, wamit_dof) in stored.blocks.iter().zip([1, 2, 6]) {
        let m = qtf.matrix(wamit_dof, 0.0).unwrap();
        for i in 0..n {
            for j in 0..n {
                assert_eq!(Complex64::new(block.re[i][j], block.im[i][j]), m[i * n + j]);
            }
        }
    }
    assert_eq!(
        stored.blocks.iter().map(|b| b.dof).collect::<Vec<_>>(),
        [Dof::Surge, Dof::Sway, Dof::Yaw]
    );

    let dir = temp_dir("oc4-db");
    let file = dir.join("oc4.json");
    db.save(&file).unwrap();
    assert_eq!(
        &HydroDatabase::load(&file, LIMIT).unwrap(),
        db,
        "bit-for-bit round trip"
    );
}

// ------------------------------------------------------------------------ synthetic files

/// Two periods (10 s, 5 s), headings 0 and 90 deg, DOFs in the order 6, 1, 2, both
/// triangles, after a header line; the lower triangle deliberately not the conjugate of
/// the upper one (a file with both triangles is stored as given).
const BOTH_TRIANGLES: &str = "  some header text 12-Jan-2024
  10.0  10.0  90.0  90.0  6  0 0  3.0  0.5
  10.0  10.0  90.0  90.0  1  0 0  1.0  0.0
  10.0  10.0  90.0  90.0  2  0 0  2.0  0.0
  5.0   10.0  90.0  90.0  6  0 0  3.5  0.25
  10.0  5.0   90.0  90.0  6  0 0  3.6  0.75
  5.0   10.0  90.0  90.0  1  0 0  1.5  0.1
  10.0  5.0   90.0  90.0  1  0 0  1.5 -0.1
  5.0   10.0  90.0  90.0  2  0 0  2.5  0.2
  10.0  5.0   90.0  90.0  2  0 0  2.5 -0.2
  5.0   5.0   90.0  90.0  2  0 0  2.9  0.0
  5.0   5.0   90.0  90.0  1  0 0  1.9  0.0
  5.0   5.0   90.0  90.0  6  0 0  3.9  0.0

  5.0   5.0   0.0   0.0   1  0 0  11.9  0.0
  10.0  5.0   0.0   0.0   1  0 0  11.5 -0.3
  10.0  10.0  0.0   0.0   1  0 0  11.0  0.0
  5.0   10.0  0.0   0.0   1  0 0  11.5  0.3
";

#[test]
fn header_both_triangles_any_dof_order_several_headings() {
    let dir = temp_dir("both");
    let path = write(&dir, "body.12d", BOTH_TRIANGLES);
    let ulen = 2.0;
    let options = WamitOptions {
        ulen,
        ..WamitOptions::default()
    };
    let qtf = read_difference_qtf(&path, &options).unwrap();
    let (w_lo, w_hi) = (2.0 * PI / 10.0, 2.0 * PI / 5.0);
    assert_eq!(qtf.omegas(), [w_lo, w_hi]);
    assert_eq!(qtf.dofs(), [1, 2, 6]);
    assert_eq!(qtf.headings(), [0.0, 90f64.to_radians()]);
    assert_eq!(qtf.filled_by_symmetry(), 0);
    let beam = (90f64.to_radians(), 90f64.to_radians());
    // PER1 = 10 s, PER2 = 5 s -> T(w_lo, w_hi); the moment scales with L^2.
    let t = qtf.value(6, beam, 0, 1).unwrap();
    assert_eq!(t, Complex64::new(3.6, 0.75) * (RHO * G * ulen * ulen));
    let t = qtf.value(6, beam, 1, 0).unwrap();
    assert_eq!(t, Complex64::new(3.5, 0.25) * (RHO * G * ulen * ulen));
    let t = qtf.value(2, beam, 1, 1).unwrap();
    assert_eq!(t, Complex64::new(2.9, 0.0) * (RHO * G * ulen));
    assert_eq!(
        qtf.diagonal(1, 0.0).unwrap(),
        [
            (w_lo, 11.0 * (RHO * G * ulen)),
            (w_hi, 11.9 * (RHO * G * ulen))
        ]
    );
    // DOF 2 and 6 exist at 90 deg only.
    let err = qtf
        .to_drift_table(&[0.0, PI / 2.0], [1, 2, 6])
        .unwrap_err()
        .to_string();
    assert!(err.contains("body.12d"), "{err}");
    assert!(
        err.contains("DOF 2 at 0.000 deg") && err.contains("DOF 6 at 0.000 deg"),
        "{err}"
    );
    let table = qtf.to_drift_table(&[PI / 2.0], [1, 2, 6]).unwrap();
    assert_eq!(
        table.drift_at_node(0, 1),
        [
            1.9 * (RHO * G * ulen),
            2.9 * (RHO * G * ulen),
            3.9 * (RHO * G * ulen * ulen)
        ]
    );
}

#[test]
fn one_triangle_of_a_bidirectional_pair_fills_the_mirror_pair() {
    let dir = temp_dir("bidir");
    // Headings (0, 30): the mirror block (30, 0) is not in the file.
    let pair = "\
  10.0  10.0  0.0  30.0  1  0 0  1.0  0.5
  5.0   10.0  0.0  30.0  1  0 0  2.0  0.25
  10.0  5.0   0.0  30.0  1  0 0  3.0  -0.75
  5.0   5.0   0.0  30.0  1  0 0  4.0  1.5
";
    // Without the uni-directional blocks of 0 and 30 deg the pairs are incomplete: listed.
    let path = write(&dir, "pair.11d", pair);
    let err = read_difference_qtf(&path, &WamitOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("pair.11d")
            && err.contains("2 of the 4 (DOF, heading pair) blocks are missing")
            && err.contains("DOF 1 at (0.000, 0.000) deg; DOF 1 at (30.000, 30.000) deg"),
        "{err}"
    );
    let uni = "\
  10.0  10.0  0.0  0.0  1  0 0  1.0  0.0
  5.0   10.0  0.0  0.0  1  0 0  2.0  0.1
  5.0   5.0   0.0  0.0  1  0 0  4.0  0.0
  10.0  10.0  30.0  30.0  1  0 0  1.5  0.0
  5.0   10.0  30.0  30.0  1  0 0  2.5  0.1
  5.0   5.0   30.0  30.0  1  0 0  4.5  0.0
";
    let path = write(&dir, "bi.11d", &format!("{pair}{uni}"));
    let qtf = read_difference_qtf(&path, &WamitOptions::default()).unwrap();
    let (a, b) = (0.0, 30f64.to_radians());
    assert_eq!(qtf.blocks().len(), 4);
    assert_eq!(qtf.filled_by_symmetry(), 4 + 2);
    for i in 0..2 {
        for j in 0..2 {
            assert_eq!(
                qtf.value(1, (b, a), j, i).unwrap(),
                qtf.value(1, (a, b), i, j).unwrap().conj()
            );
        }
    }
    assert_eq!(qtf.headings(), [a, b]);
}

#[test]
fn malformed_lines_name_the_file_and_line() {
    let dir = temp_dir("malformed");
    let good = "  10.0  10.0  0.0  0.0  1  1.0 0.0  1.0  0.0\n";
    let cases = [
        // (text, line, words the message must hold)
        (
            format!("{good}  10.0  10.0  0.0  0.0  1  1.0 0.0  x  0.0\n"),
            2,
            "field 8",
        ),
        (
            format!("header\n{good}  10.0  10.0  0.0  0.0  1  1.0 0.0  1.0\n"),
            3,
            "found 8",
        ),
        (
            format!("{good}\n  10.0  10.0  0.0  0.0  7  1.0 0.0  1.0  0.0\n"),
            3,
            "DOF",
        ),
        (
            format!("{good}  -3.0  10.0  0.0  0.0  2  1.0 0.0  1.0  0.0\n"),
            2,
            "PER1",
        ),
        (
            format!("{good}  10.0  10.0  0.0  0.0  1  2.0 0.0  2.0  0.0\n"),
            2,
            "line 1",
        ),
        (format!("{good}more text\n"), 2, "found 2 fields"),
        (
            format!("{good}1 2 3 4 5 6 7 eight 9\n"),
            2,
            "field 8 (\"eight\")",
        ),
        (
            format!("{good}  10.0  10.0  0.0  0.0  1  1.0 0.0  NaN  0.0\n"),
            2,
            "finite",
        ),
    ];
    for (k, (text, line, words)) in cases.iter().enumerate() {
        let path = write(&dir, &format!("case{k}.12d"), text);
        let err = read_difference_qtf(&path, &WamitOptions::default())
            .unwrap_err()
            .to_string();
        let at = format!("{}:{line}:", path.display());
        assert!(
            err.starts_with(&at) && err.contains(words),
            "case {k}: {err}"
        );
    }
    let path = write(
        &dir,
        "holes.12d",
        &format!("{good}  5.0  5.0  0.0  0.0  1  1 0  1  0\n"),
    );
    let err = read_difference_qtf(&path, &WamitOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("holes.12d") && err.contains("2 of 4 frequency pairs missing"),
        "{err}"
    );
    let path = write(&dir, "bad.1", "  -2.0  1  1  5.0\n");
    let err = read_added_mass_damping(&path, &WamitOptions::default())
        .unwrap_err()
        .to_string();
    assert!(err.starts_with(&format!("{}:1:", path.display())), "{err}");
    let path = write(&dir, "bad.hst", "  1  1  0.0\n  1  1  0.0\n");
    let err = read_hydrostatics(&path, &WamitOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        err.starts_with(&format!("{}:2:", path.display())) && err.contains("line 1"),
        "{err}"
    );
}

/// Strict numbers: a `.1` file cut inside its last number (the exponent lost:
/// it would read A66 = 6.27 kg m^2 instead of 6.27e9), an exponent cut short at its end,
/// a number cut on an unterminated last line of a column without exponents, and a `.1`
/// file with no frequency at all are refused naming the file and line.
#[test]
fn cut_numbers_and_files_without_frequencies_are_refused() {
    let dir = temp_dir("cut");
    let lines = [
        " -0.100000E+01     1     1  8.526887E+03\n",
        "  0.126168E+01     1     1  8.526887E+03  1.621425E+04\n",
        " -0.100000E+01     6     6  6.273170E+09\n",
    ];
    let good = lines.concat();
    read_added_mass_damping(&write(&dir, "good.1", &good), &WamitOptions::default()).unwrap();
    let cut_exponent = good.replace("6.273170E+09\n", "6.273170");
    let wrong_digits = good.replace("E+09\n", "E+0");
    for (name, text, field) in [
        ("lost.1", cut_exponent, "field 4 (\"6.273170\")"),
        ("short.1", wrong_digits, "field 4 (\"6.273170E+0\")"),
    ] {
        let path = write(&dir, name, &text);
        let err = read_added_mass_damping(&path, &WamitOptions::default())
            .unwrap_err()
            .to_string();
        assert!(
            err.starts_with(&format!(
                "{}:3: {field} has fewer digits than",
                path.display()
            )) && err.contains("on line 1 (\"8.526887E+03\")")
                && err.contains("looks cut"),
            "{err}"
        );
    }
    // A column without exponents: decimals count on an unterminated last line only.
    let f_format =
        "  10.000   0.0   0.0  1  0.500  0.0  0.500  0.000\n  10.000   0.0   0.0  2  0.500  0.0  0.500  0.0";
    let path = write(&dir, "cut.8", f_format);
    let err = read_mean_drift(&path, &WamitOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        err.starts_with(&format!(
            "{}:2: field 8 (\"0.0\") has fewer digits",
            path.display()
        )) && err.contains("ends in this line without a newline"),
        "{err}"
    );
    let limits_only = write(&dir, "limits.1", lines[0]);
    let err = read_added_mass_damping(&limits_only, &WamitOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        err.starts_with(&format!("{}: no frequency", limits_only.display())),
        "{err}"
    );
}

#[test]
fn added_mass_damping_and_hydrostatics_scale_with_ulen() {
    let dir = temp_dir("scale");
    let ulen: f64 = 3.0;
    let options = WamitOptions {
        ulen,
        rho: 1000.0,
        gravity: 9.81,
        ..WamitOptions::default()
    };
    let one = write(
        &dir,
        "b.1",
        " -1.0  1  1  2.0\n  0.0  1  1  1.5\n  8.0  6  6  4.0  0.5\n  8.0  1  5  1.0  0.25\n  4.0  1  1  3.0  2.0\n",
    );
    let amd = read_added_mass_damping(&one, &options).unwrap();
    let (w1, w2) = (2.0 * PI / 8.0, 2.0 * PI / 4.0);
    assert_eq!(amd.omegas, [w1, w2]);
    assert_eq!(
        amd.zero_frequency_added_mass.unwrap()[0][0],
        1000.0 * ulen.powi(3) * 2.0
    );
    assert_eq!(
        amd.infinite_frequency_added_mass.unwrap()[0][0],
        1000.0 * ulen.powi(3) * 1.5
    );
    assert_eq!(amd.added_mass[0][5][5], 1000.0 * ulen.powi(5) * 4.0);
    assert_eq!(amd.damping[0][5][5], 1000.0 * w1 * ulen.powi(5) * 0.5);
    assert_eq!(amd.added_mass[0][0][4], 1000.0 * ulen.powi(4) * 1.0);
    assert_eq!(amd.damping[1][0][0], 1000.0 * w2 * ulen.powi(3) * 2.0);
    assert_eq!(amd.added_mass[1][5][5], 0.0, "unlisted entries are zero");

    let hst = write(
        &dir,
        "b.hst",
        "  3 3  2.0\n  3 5  -1.0\n  5 3 -1.0\n  4 4  5.0\n",
    );
    let c = read_hydrostatics(&hst, &options).unwrap().c;
    let rg = 1000.0 * 9.81;
    assert_eq!(c[2][2], rg * ulen.powi(2) * 2.0);
    assert_eq!(c[2][4], -(rg * ulen.powi(3)));
    assert_eq!(c[3][3], rg * ulen.powi(4) * 5.0);
}

#[test]
fn mean_drift_file_gives_a_drift_table_and_lists_what_is_missing() {
    let dir = temp_dir("mean");
    // Momentum file: DOFs 1, 2, 6 at 0 and 90 deg, order shuffled, one bi-directional
    // block (kept apart from the drift table), a header line.
    let text = "WAMIT .8 test
  5.0  90.0  90.0  6  0 0  0.6  0.0
 10.0   0.0   0.0  1  0 0  1.0  0.0
  5.0   0.0   0.0  1  0 0  1.5  0.0
 10.0   0.0   0.0  2  0 0  0.0  0.0
  5.0   0.0   0.0  2  0 0  0.0  0.0
 10.0   0.0   0.0  6  0 0  0.0  0.0
  5.0   0.0   0.0  6  0 0  0.0  0.0
 10.0  90.0  90.0  1  0 0  0.1  0.0
  5.0  90.0  90.0  1  0 0  0.2  0.0
 10.0  90.0  90.0  2  0 0  1.1  0.0
  5.0  90.0  90.0  2  0 0  1.6  0.0
 10.0  90.0  90.0  6  0 0  0.5  0.0
 10.0   0.0  90.0  1  0 0  9.0  0.0
  5.0   0.0  90.0  1  0 0  9.5  0.0
";
    let path = write(&dir, "m.8", text);
    let ulen = 2.0;
    let mean = read_mean_drift(
        &path,
        &WamitOptions {
            ulen,
            ..WamitOptions::default()
        },
    )
    .unwrap();
    let beam = 90f64.to_radians();
    assert_eq!(mean.headings(), [0.0, beam]);
    assert_eq!(mean.pairs().len(), 1);
    assert_eq!(mean.pairs()[0].headings, (0.0, beam));
    assert_eq!(
        mean.values(1, 0.0).unwrap(),
        [force_scale(ulen, 1), 1.5 * force_scale(ulen, 1)]
    );
    let table = mean.to_drift_table(&[0.0, beam], [1, 2, 6]).unwrap();
    assert_eq!(
        table.drift_at_node(1, 1),
        [
            0.2 * force_scale(ulen, 1),
            1.6 * force_scale(ulen, 2),
            0.6 * force_scale(ulen, 6)
        ]
    );
    let err = mean
        .to_drift_table(&[0.0, PI], [1, 3, 5])
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("m.8")
            && err.contains("missing DOF 3, 5")
            && err.contains("heading 180.000 deg"),
        "{err}"
    );
    // A hole inside a (DOF, heading): DOF 6 at 90 deg lacks 10 s.
    let path = write(
        &dir,
        "hole.9",
        &text.replace(" 10.0  90.0  90.0  6  0 0  0.5  0.0\n", ""),
    );
    let err = read_mean_drift(&path, &WamitOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("hole.9") && err.contains("DOF 6 at heading 90.000 deg lacks 1"),
        "{err}"
    );
}

// ------------------------------------------------------------------------ database

fn small_database() -> HydroDatabase {
    use slowdrift::hydro::io::database::{DriftPoint, QtfData, QtfMatrix};
    let b = [[1.0e3, 0.1, 0.0], [0.0, 2.0e3, 0.0], [0.0, 0.0, 3.0e5]];
    HydroDatabase {
        format_version: FORMAT_VERSION,
        name: "test body".into(),
        source: "hand-written; \"quoted\" text".into(),
        water_density: 1025.0,
        gravity: 9.80665,
        mass_properties: Some(MassProperties {
            mass: 1.0e7,
            yaw_inertia: 1.0 / 3.0 * 1e10,
        }),
        low_frequency_added_mass: Some([[1.0e6, 0.0, 0.1], [0.0, 1.1e6, 0.0], [0.1, 0.0, 1e9]]),
        stiffness: Some([[0.0; 3]; 3]),
        drift: [0.3, 0.7, 1.1]
            .iter()
            .map(|&omega| DriftPoint {
                omega,
                heading: 0.1,
                surge: 1.0e3 * omega / 3.0,
                sway: -0.0,
                yaw: 5e-324,
                damping: Some(b),
            })
            .collect(),
        qtf: Some(QtfData {
            omegas: vec![0.3, 0.7],
            blocks: vec![QtfMatrix {
                dof: Dof::Yaw,
                heading: 0.1,
                second_heading: None,
                re: vec![vec![1.0, PI], vec![PI, 2.0]],
                im: vec![vec![0.0, -1.0 / 7.0], vec![1.0 / 7.0, 0.0]],
            }],
        }),
        bidirectional_drift: None,
        first_order: None,
        rao: None,
        provenance: slowdrift::hydro::io::database::Provenance {
            mass_properties: Some("hand-written".into()),
            low_frequency_added_mass: None,
            stiffness: Some("zero \"by construction\"".into()),
        },
    }
}

#[test]
fn database_round_trip_is_bit_for_bit_and_gives_its_drift_table() {
    let dir = temp_dir("db");
    let db = small_database();
    let path = dir.join("db.json");
    db.save(&path).unwrap();
    let back = HydroDatabase::load(&path, LIMIT).unwrap();
    assert_eq!(back, db);
    assert_eq!(back.drift[0].sway.to_bits(), (-0.0f64).to_bits());
    let table = back.to_drift_table().unwrap();
    assert_eq!(table.omegas(), [0.3, 0.7, 1.1]);
    assert_eq!(table.damping(0.7, 0.1).unwrap().unwrap()[2][2], 3.0e5);
}

#[test]
fn database_errors_name_the_file() {
    let dir = temp_dir("db-errors");
    let text = serde_json::to_string_pretty(&small_database()).unwrap();
    let wrong_version = write(
        &dir,
        "v2.json",
        &text.replace("\"format_version\": 1", "\"format_version\": 2"),
    );
    let err = HydroDatabase::load(&wrong_version, LIMIT)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("v2.json") && err.contains("format_version = 2"),
        "{err}"
    );
    // Another version whose content does not fit this version's types is still refused
    // for its version, and so is a file without one.
    let other_layout = write(
        &dir,
        "v2-other.json",
        &text.replace(
            "\"format_version\": 1",
            "\"format_version\": 2, \"panels\": []",
        ),
    );
    let err = HydroDatabase::load(&other_layout, LIMIT)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("format_version = 2: this program reads version 1"),
        "{err}"
    );
    let absent = write(
        &dir,
        "unversioned.json",
        &text.replace("\"format_version\": 1,", ""),
    );
    let err = HydroDatabase::load(&absent, LIMIT).unwrap_err().to_string();
    assert!(err.contains("format_version = (absent)"), "{err}");
    let broken = write(
        &dir,
        "broken.json",
        &text.replacen("\"name\"", "\"name\" :: ", 1),
    );
    let err = HydroDatabase::load(&broken, LIMIT).unwrap_err().to_string();
    assert!(
        err.starts_with(&format!("{}:3:", broken.display())),
        "{err}"
    );
    let unknown = write(
        &dir,
        "unknown.json",
        &text.replacen("\"name\"", "\"nmae\"", 1),
    );
    let err = HydroDatabase::load(&unknown, LIMIT)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("unknown.json") && err.contains("nmae"),
        "{err}"
    );
    let mut bad = small_database();
    bad.qtf.as_mut().unwrap().blocks[0].re.pop();
    let err = bad.save(&dir.join("bad.json")).unwrap_err().to_string();
    assert!(err.contains("bad.json") && err.contains("2 x 2"), "{err}");
    let err = HydroDatabase::load(&dir.join("absent.json"), LIMIT)
        .unwrap_err()
        .to_string();
    assert!(err.contains("absent.json"), "{err}");
}

/// A database whose content is wrong (a negative frequency, found when its drift table is
/// made; a negative gravity, found by its own check) is refused naming the database file,
/// the line of the value (found here by scanning the written text) and the field as the
/// file spells it, whether loaded alone or through a configuration that names it.
#[test]
fn database_content_errors_name_the_file_and_line() {
    let dir = temp_dir("db-content");
    let text = serde_json::to_string_pretty(&small_database()).unwrap();
    // The third "omega" key of the text is drift[2]'s (the QTF's frequencies are under
    // "omegas").
    let line = text
        .lines()
        .enumerate()
        .filter(|(_, l)| l.trim_start().starts_with("\"omega\":"))
        .nth(2)
        .map(|(k, _)| k + 1)
        .unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    assert_eq!(lines[line - 1].trim(), "\"omega\": 1.1,");
    lines[line - 1] = lines[line - 1].replace("1.1", "-1.1");
    let negative = write(&dir, "negative.json", &lines.join("\n"));
    let config = write(
        &dir,
        "negative.toml",
        &slowdrift::scenario::default::DEFAULT_CONFIG_TOML.replace(
            "source = \"default-platform\"",
            "source = \"database\"\nfile = \"negative.json\"",
        ),
    );
    let expected = format!(
        "{}:{line}: invalid drift[2].omega = -1.1: must be greater than zero",
        negative.display()
    );
    let err = slowdrift::problem::load(&config).unwrap_err().to_string();
    assert!(err.starts_with(&expected), "{err}");

    let gravity_line = text
        .lines()
        .position(|l| l.contains("\"gravity\""))
        .unwrap()
        + 1;
    let negative_gravity = write(
        &dir,
        "gravity.json",
        &text.replace("\"gravity\": 9.80665", "\"gravity\": -9.8"),
    );
    let err = HydroDatabase::load(&negative_gravity, LIMIT)
        .unwrap_err()
        .to_string();
    assert_eq!(
        err,
        format!(
            "{}:{gravity_line}: invalid gravity = -9.8: must be greater than zero",
            negative_gravity.display()
        )
    );
}

#[test]
fn database_from_synthetic_wamit_files_prefers_the_momentum_drift() {
    let dir = temp_dir("import");
    let root = dir.join("body");
    // The beam-sea part of BOTH_TRIANGLES: DOFs 1, 2, 6 at 90 deg.
    let beam: String = BOTH_TRIANGLES
        .lines()
        .take(13)
        .map(|l| format!("{l}\n"))
        .collect();
    write(&dir, "body.12d", &beam);
    let mut eight = String::new();
    for (per, v) in [(10.0, 0.5), (5.0, 0.7)] {
        for h in [0.0, 90.0] {
            for dof in [1, 2, 6] {
                eight += &format!("{per} {h} {h} {dof} 0 0 {v} 0\n");
            }
        }
    }
    write(&dir, "body.8", &eight);
    let import = wamit::import(&root, &WamitOptions::default()).unwrap();
    let db = &import.database;
    assert!(db.source.contains("drift from .8"), "{}", db.source);
    assert_eq!(db.low_frequency_added_mass, None);
    assert_eq!(db.stiffness, None);
    assert_eq!(db.drift.len(), 4);
    assert_eq!(db.drift[3].yaw, 0.7 * (RHO * G));
    // The QTF lacks DOFs 2 and 6 at 0 deg: the import says so.
    std::fs::remove_file(dir.join("body.8")).unwrap();
    let only_surge_at_0: String = BOTH_TRIANGLES
        .lines()
        .skip(14)
        .map(|l| format!("{l}\n"))
        .collect();
    std::fs::write(dir.join("body.12d"), only_surge_at_0).unwrap();
    let err = wamit::import(&root, &WamitOptions::default()).unwrap_err();
    assert!(err.to_string().contains("DOF 2"), "{err}");
    let err = wamit::import(&dir.join("nothing"), &WamitOptions::default()).unwrap_err();
    assert!(err.to_string().contains("no WAMIT file found"), "{err}");
}

// ------------------------------------------------------------------------ CLI

#[test]
fn cli_hydro_wamit_writes_the_database_and_summarises() {
    let Some(root) = crate::common::oc4_root_or_skip() else {
        return;
    };
    let out = temp_dir("cli").join("oc4.json");
    let run = std::process::Command::new(env!("CARGO_BIN_EXE_slowdrift"))
        .args(["hydro", "wamit", "--root"])
        .arg(&root)
        .args(["--rho", "1025", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(
        stdout.contains("56 frequencies 0.2500 .. 3.0000 rad/s x 1 headings"),
        "{stdout}"
    );
    assert!(stdout.contains("marin_semi.8: absent"), "{stdout}");
    let expected = wamit::import(&root, &WamitOptions::default()).unwrap();
    assert_eq!(HydroDatabase::load(&out, LIMIT).unwrap(), expected.database);

    let refused = std::process::Command::new(env!("CARGO_BIN_EXE_slowdrift"))
        .args([
            "hydro", "wamit", "--root", "x", "--ulen", "-1", "--out", "y.json",
        ])
        .output()
        .unwrap();
    assert!(!refused.status.success());
    assert!(
        String::from_utf8_lossy(&refused.stderr).contains("--ulen -1: must be a positive number")
    );
}
