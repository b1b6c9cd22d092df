//! NEMOH v3 import on the OC3-Hywind spar of WEC-Sim's examples
//! (`../shared/data/nemoh/oc3-hywind`, see its SOURCE.md; `$SLOWDRIFT_DATA` overrides).
//! Every expected value is parsed here from the raw text (split_whitespace on the lines),
//! scaled and conjugated by hand, independently of the readers.

use crate::common::{base_problem, jonswap, long_crested, shared_data_dir, simpson};
use crate::quirks::temp_dir;
use rustfft::num_complex::Complex64;
use slowdrift::hydro::io::nemoh;
use slowdrift::model::{Dof, DriftDamping, Environment, SecondOrder};
use slowdrift::problem::Hydro;
use slowdrift::scenario::limits::DEFAULT_MEMORY_LIMIT as LIMIT;
use slowdrift::stats::summarize;
use slowdrift::{Problem, Simulation};
use std::f64::consts::PI;
use std::path::PathBuf;

/// The OC3 spar's NEMOH project directory, or `None` after printing a "skipped" line when
/// the data are absent. Under CI (env var `CI` set) absent data is a failure.
pub(crate) fn oc3_dir_or_skip() -> Option<PathBuf> {
    let dir = shared_data_dir().join("nemoh/oc3-hywind");
    if dir.join("Nemoh.cal").is_file() {
        return Some(dir);
    }
    if std::env::var_os("CI").is_some() {
        panic!(
            "the NEMOH OC3 data are absent at {} (CI is set: they must be there; set \
             SLOWDRIFT_DATA to the shared data directory)",
            dir.display()
        );
    }
    println!("skipped: data absent at {}", dir.display());
    None
}

/// The numbers of the lines of a file from line `skip` on.
pub(crate) fn raw_rows(path: &PathBuf, skip: usize) -> Vec<Vec<f64>> {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .skip(skip)
        .filter(|l| !l.trim().is_empty())
        .map(|l| l.split_whitespace().map(|f| f.parse().unwrap()).collect())
        .collect()
}

/// rho and g from Nemoh.cal's second and third lines, read here.
fn rho_g(dir: &std::path::Path) -> (f64, f64) {
    let text = std::fs::read_to_string(dir.join("Nemoh.cal")).unwrap();
    let first = |n: usize| -> f64 {
        text.lines()
            .nth(n)
            .unwrap()
            .split_whitespace()
            .next()
            .unwrap()
            .parse()
            .unwrap()
    };
    (first(1), first(2))
}

#[test]
fn oc3_qtf_against_the_raw_text_hermitian_and_its_diagonal_the_drift() {
    let Some(dir) = oc3_dir_or_skip() else {
        return;
    };
    let import = nemoh::import(&dir, LIMIT).unwrap();
    for line in &import.files {
        println!("{line}");
    }
    let db = &import.database;
    let (rho, g) = rho_g(&dir);
    assert_eq!((db.water_density, db.gravity), (rho, g));
    assert_eq!((rho, g), (1025.0, 9.81));

    let raw = raw_rows(&dir.join("results/QTF/OUT_QTFM_N_0.dat"), 1);
    assert_eq!(
        raw.len(),
        26 * 27 / 2 * 6,
        "the lower triangle incl. the diagonal"
    );
    assert!(raw.iter().all(|r| r[0] >= r[1]), "w1 >= w2");
    let qtf = db.qtf.as_ref().unwrap().to_qtf();
    let omegas = &qtf.omegas;
    assert_eq!(omegas.len(), 26);
    let index = |w: f64| {
        omegas
            .iter()
            .position(|&o| (o - w).abs() < 5e-4)
            .unwrap_or_else(|| panic!("{w} not on the grid"))
    };
    let n = omegas.len();
    let mut checked = 0;
    for row in &raw {
        let dof = match row[4] as usize {
            1 => Dof::Surge,
            2 => Dof::Sway,
            6 => Dof::Yaw,
            _ => continue,
        };
        let (i, j) = (index(row[0]), index(row[1]));
        // NEMOH's e^{-i w t}: the crate's T is rho g times the conjugate.
        let expected = Complex64::new(row[7], -row[8]) * rho * g;
        let block = qtf.block(dof, 0.0, 1e-9).unwrap();
        let got = block.values[i * n + j];
        assert!(
            (got - expected).norm() <= 1e-12 * expected.norm().max(1.0),
            "{dof:?} ({}, {}): {got} vs {expected}",
            row[0],
            row[1]
        );
        // Hermitian completion of the upper triangle, bit for bit.
        assert_eq!(block.values[j * n + i], got.conj());
        if i == j {
            // The diagonal is real in the file and is the mean drift.
            assert_eq!(row[8], 0.0);
            let point = db
                .drift
                .iter()
                .find(|p| (p.omega - omegas[i]).abs() < 1e-12)
                .unwrap();
            let drift = match dof {
                Dof::Surge => point.surge,
                Dof::Sway => point.sway,
                Dof::Yaw => point.yaw,
            };
            assert_eq!(drift, row[7] * (rho * g));
        }
        checked += 1;
    }
    assert_eq!(checked, 3 * 351);
    // The grid is Nemoh.cal's 26 frequencies 0.25 .. 1.5 rad/s, exactly.
    for (k, &w) in omegas.iter().enumerate() {
        assert!((w - (0.25 + 0.05 * k as f64)).abs() < 1e-12, "{k}: {w}");
    }
    let surge: Vec<f64> = db.drift.iter().map(|p| p.surge).collect();
    println!(
        "OC3 spar mean surge drift (N/m^2) at 0.25, 0.5, 1.0, 1.5 rad/s: {:.4e}, {:.4e}, {:.4e}, {:.4e}",
        surge[0], surge[5], surge[15], surge[25]
    );
}

#[test]
fn oc3_added_mass_mass_and_stiffness_from_the_raw_text() {
    let Some(dir) = oc3_dir_or_skip() else {
        return;
    };
    let db = nemoh::import(&dir, LIMIT).unwrap().database;
    // CM.dat: the first frequency's block, rows 1, 2, 6 and columns 1, 2, 6.
    let cm = raw_rows(&dir.join("results/CM.dat"), 1);
    assert_eq!(cm[0].len(), 1, "the frequency line");
    let slow = [0, 1, 5];
    let a = db.low_frequency_added_mass.unwrap();
    for (r, &i) in slow.iter().enumerate() {
        for (c, &j) in slow.iter().enumerate() {
            assert_eq!(a[r][c], cm[1 + i][j], "A[{i}][{j}]");
        }
    }
    assert!(a[0][0] > 3.0e7 && a[2][2] > 0.0, "{a:?}");
    let inertia = raw_rows(&dir.join("Mechanics/Inertia.dat"), 0);
    let mass = db.mass_properties.as_ref().unwrap();
    assert_eq!(mass.mass, inertia[0][0]);
    assert_eq!(mass.yaw_inertia, inertia[5][5]);
    assert_eq!(db.stiffness.unwrap(), [[0.0; 3]; 3]);
}

/// The yaw moments of Nemoh.cal are about (0, 0, -78): on the body's vertical axis, so kept.
/// Moved to a point off the axis (Nemoh.cal and the QTF rewritten here), the import must
/// give the same yaw QTF about the origin: M_o = M_r + x_r F_y - y_r F_x, and the yaw QTF
/// about r is made from the original with the opposite translation.
#[test]
fn an_off_axis_reference_point_is_moved_to_the_origin() {
    let Some(dir) = oc3_dir_or_skip() else {
        return;
    };
    let (xr, yr) = (4.0, -3.0);
    let copy = temp_dir("nemoh-offset");
    for sub in ["results/QTF", "Mechanics"] {
        std::fs::create_dir_all(copy.join(sub)).unwrap();
    }
    for file in [
        "results/CM.dat",
        "Mechanics/Inertia.dat",
        "Mechanics/Kh.dat",
    ] {
        std::fs::copy(dir.join(file), copy.join(file)).unwrap();
    }
    let cal = std::fs::read_to_string(dir.join("Nemoh.cal")).unwrap();
    let moved = cal.replace(
        "0.000000 0.000000 -78.000000",
        &format!("{xr:.6} {yr:.6} -78.000000"),
    );
    assert_ne!(moved, cal);
    std::fs::write(copy.join("Nemoh.cal"), moved).unwrap();
    // The file's yaw rows about r: M_r = M_o - x_r F_y + y_r F_x, per (w1, w2).
    let text = std::fs::read_to_string(dir.join("results/QTF/OUT_QTFM_N_0.dat")).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let key = |l: &str| -> String { l.split_whitespace().take(4).collect::<Vec<_>>().join(" ") };
    let value = |l: &str| -> Complex64 {
        let v: Vec<f64> = l.split_whitespace().map(|f| f.parse().unwrap()).collect();
        Complex64::new(v[7], v[8])
    };
    let dof_of = |l: &str| l.split_whitespace().nth(4).unwrap().to_string();
    for k in 1..lines.len() {
        if dof_of(&lines[k]) != "6" {
            continue;
        }
        let find = |d: &str| {
            lines[1..]
                .iter()
                .find(|l| key(l) == key(&lines[k]) && dof_of(l) == d)
                .map(|l| value(l))
                .unwrap()
        };
        let (fx, fy) = (find("1"), find("2"));
        let m = value(&lines[k]) - fy * xr + fx * yr;
        let head = lines[k]
            .split_whitespace()
            .take(5)
            .collect::<Vec<_>>()
            .join(" ");
        lines[k] = format!(
            "{head} {:.7e} {:.7e} {:.7e} {:.7e}",
            m.norm(),
            m.arg().to_degrees(),
            m.re,
            m.im
        );
    }
    std::fs::write(
        copy.join("results/QTF/OUT_QTFM_N.dat"),
        lines.join("\n") + "\n",
    )
    .unwrap();
    let original = nemoh::import(&dir, LIMIT).unwrap();
    let offset = nemoh::import(&copy, LIMIT).unwrap();
    assert!(
        offset
            .files
            .iter()
            .any(|l| l.contains("moved from the axis through (4, -3)")),
        "{:?}",
        offset.files
    );
    let (a, b) = (
        original.database.qtf.unwrap().to_qtf(),
        offset.database.qtf.unwrap().to_qtf(),
    );
    let (ya, yb) = (
        &a.block(Dof::Yaw, 0.0, 1e-9).unwrap().values,
        &b.block(Dof::Yaw, 0.0, 1e-9).unwrap().values,
    );
    // The file holds 8 significant digits of the moment about r, which is dominated by the
    // translation terms (the spar's yaw moment in head seas is noise): compare on their scale.
    let largest = |dof: Dof| {
        a.block(dof, 0.0, 1e-9)
            .unwrap()
            .values
            .iter()
            .fold(0.0f64, |m, z| m.max(z.norm()))
    };
    let scale = largest(Dof::Yaw) + xr.abs() * largest(Dof::Sway) + yr.abs() * largest(Dof::Surge);
    for (p, q) in ya.iter().zip(yb) {
        assert!((p - q).norm() <= 1e-6 * scale, "{p} vs {q}");
    }
}

/// The files and sections the import names are NEMOH's as it writes them: every file a
/// line of the import's report names exists under that name (case included) in NEMOH's
/// project, and a missing section is named by the header NEMOH writes in Nemoh.cal.
#[test]
fn files_and_sections_are_named_as_nemoh_writes_them() {
    let Some(dir) = oc3_dir_or_skip() else {
        return;
    };
    let import = nemoh::import(&dir, LIMIT).unwrap();
    let mut named = 0;
    for line in &import.files {
        let Some((path, _)) = line.split_once(": ") else {
            continue;
        };
        if path.starts_with(&dir.display().to_string()) {
            assert!(PathBuf::from(path).is_file(), "{line}");
            named += 1;
        }
    }
    assert!(named >= 5, "{:?}", import.files);
    let cal = std::fs::read_to_string(dir.join("Nemoh.cal")).unwrap();
    for header in ["Description of floating bodies", "Load cases to be solved"] {
        let line = cal
            .lines()
            .find(|l| l.starts_with(&format!("--- {header} ")))
            .unwrap_or_else(|| panic!("NEMOH's Nemoh.cal has a {header:?} header"));
        let copy = temp_dir("nemoh-header");
        std::fs::create_dir_all(&copy).unwrap();
        std::fs::write(copy.join("Nemoh.cal"), cal.replace(line, "--- ---")).unwrap();
        let message = nemoh::import(&copy, LIMIT).unwrap_err().to_string();
        assert!(
            message.ends_with(&format!("Nemoh.cal: no \"--- {header} ---\" section")),
            "{message}"
        );
    }
}

/// NEMOH's frequencies in another unit than Nemoh.cal says: refused naming the line.
#[test]
fn a_qtf_in_another_unit_than_nemoh_cal_names_is_refused() {
    let Some(dir) = oc3_dir_or_skip() else {
        return;
    };
    let copy = temp_dir("nemoh-unit");
    std::fs::create_dir_all(copy.join("results/QTF")).unwrap();
    let cal = std::fs::read_to_string(dir.join("Nemoh.cal")).unwrap();
    let hz: String = cal
        .lines()
        .map(|l| {
            if l.contains("For QTFposProc, output freq type") {
                format!("2{}\n", &l.trim_start()[1..])
            } else {
                format!("{l}\n")
            }
        })
        .collect();
    assert_ne!(hz, cal, "the output-unit line");
    std::fs::write(copy.join("Nemoh.cal"), hz).unwrap();
    std::fs::copy(
        dir.join("results/QTF/OUT_QTFM_N_0.dat"),
        copy.join("results/QTF/OUT_QTFM_N.dat"),
    )
    .unwrap();
    let message = nemoh::import(&copy, LIMIT).unwrap_err().to_string();
    assert!(
        message.contains("OUT_QTFM_N.dat:2:") && message.contains("w1 = 0.250 Hz"),
        "{message}"
    );
}

/// The spar in a JONSWAP sea (Hs 6 m, Tp 12 s, head seas, the QTF's band 0.25 .. 1.5 rad/s)
/// on soft moorings (surge 120 s):
/// full QTF and Newman from the same import, 4 seeds x 3 h each. Asserted: the records' mean
/// surge force against 2 integral S T(w, w) dw computed here from the raw diagonal, and
/// equal means for the two models (same diagonal); printed for the README.
#[test]
fn oc3_runs_in_full_qtf_and_newman_modes() {
    let Some(dir) = oc3_dir_or_skip() else {
        return;
    };
    let db = nemoh::import(&dir, LIMIT).unwrap().database;
    let config = |mode: SecondOrder, seed: u64| -> Problem {
        let mut c = base_problem(3.0 * 3600.0, 1.0, seed);
        c.environment = Environment {
            gravity: db.gravity,
            water_density: db.water_density,
        };
        c.hydro = Hydro {
            qtf: db.qtf.as_ref().map(|q| q.to_qtf()),
            bidirectional: None,
            ..Hydro::from_drift(db.to_drift_table().unwrap())
        };
        c.sea = long_crested(jonswap(6.0, 12.0), seed);
        c.sea.band = Some((0.25, 1.5));
        let mass = db.mass_properties.as_ref().unwrap();
        let added = db.low_frequency_added_mass.unwrap();
        c.platform.mass = Some(mass.mass);
        c.platform.yaw_inertia = Some(mass.yaw_inertia);
        c.platform.added_mass = Some(added);
        let periods = [120.0, 120.0, 8.0];
        let inertia = [
            mass.mass + added[0][0],
            mass.mass + added[1][1],
            mass.yaw_inertia + added[2][2],
        ];
        for i in 0..3 {
            let wn = 2.0 * PI / periods[i];
            c.platform.stiffness[i][i] = inertia[i] * wn * wn;
            c.platform.linear_damping[i][i] = 2.0 * 0.05 * inertia[i] * wn;
        }
        c.model.second_order = mode;
        c.model.drift_damping = DriftDamping::Off;
        c
    };
    // The expected mean surge force from the raw diagonal: 2 integral S T dw over the band
    // (linear between the file's nodes).
    let (rho, g) = rho_g(&dir);
    let mut diagonal: Vec<(f64, f64)> = raw_rows(&dir.join("results/QTF/OUT_QTFM_N_0.dat"), 1)
        .into_iter()
        .filter(|r| r[0] == r[1] && r[4] == 1.0)
        .map(|r| (r[0], r[7] * rho * g))
        .collect();
    diagonal.sort_by(|a, b| a.0.total_cmp(&b.0));
    let t = |w: f64| {
        let k = diagonal
            .partition_point(|p| p.0 <= w)
            .clamp(1, diagonal.len() - 1);
        let (a, b) = (diagonal[k - 1], diagonal[k]);
        a.1 + (b.1 - a.1) * (w - a.0) / (b.0 - a.0)
    };
    let reference = config(SecondOrder::Newman, 1);
    let band = reference.band();
    let spectrum = &reference.sea.spectrum;
    let expected_mean = 2.0 * simpson(|w| spectrum.density(w) * t(w), band.0, band.1, 4000);
    let seeds = 4;
    // The sampling error of a record's mean: the mean of a record over its grid is close
    // to sum_i |a_i|^2 T_ii, whose |a_i|^2 are exponential with mean 2 S_i d_omega, so its
    // standard deviation is sqrt(sum_i (2 S_i d_omega T_ii)^2), over sqrt(seeds) for the
    // mean of the seeds.
    let grid = Simulation::new(config(SecondOrder::Newman, 1))
        .unwrap()
        .grid()
        .clone();
    let sigma = (0..grid.count)
        .map(|i| {
            let w = grid.omega(i);
            (2.0 * spectrum.density(w) * grid.d_omega * t(w)).powi(2)
        })
        .sum::<f64>()
        .sqrt()
        / (seeds as f64).sqrt();
    let mut table = Vec::new();
    for mode in [SecondOrder::Newman, SecondOrder::FullQtf] {
        let (mut f_mean, mut f_std, mut x_mean, mut x_rms, mut x_max) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for seed in 1..=seeds {
            let mut sim = Simulation::new(config(mode, seed)).unwrap();
            let force = summarize(sim.records().wave_force[0].samples(), 0.5, 0.0).unwrap();
            let steps = 3 * 3600;
            let mut x = Vec::with_capacity(steps + 1);
            x.push(sim.position()[0]);
            for _ in 0..steps {
                sim.step([0.0; 3]).unwrap();
                x.push(sim.position()[0]);
            }
            let motion = summarize(&x, 1.0, 1200.0).unwrap();
            let n = seeds as f64;
            f_mean += force.mean / n;
            f_std += force.rms / n;
            x_mean += motion.mean / n;
            x_rms += motion.rms / n;
            x_max += motion.max / n;
        }
        println!(
            "OC3 spar, {mode:?}: surge force mean {f_mean:.4e} N (2 integral S T dw = {expected_mean:.4e}), std {f_std:.4e} N; surge mean {x_mean:.3} m, rms {x_rms:.3} m, max {x_max:.3} m"
        );
        table.push([f_mean, f_std, x_mean, x_rms, x_max]);
    }
    println!("sampling sigma of the 4-seed mean force: {sigma:.3e} N");
    for row in &table {
        assert!(
            (row[0] - expected_mean).abs() < 4.0 * sigma,
            "{} vs {expected_mean} (sigma {sigma})",
            row[0]
        );
    }
    let change = |k: usize| 100.0 * (table[1][k] / table[0][k] - 1.0);
    println!(
        "full QTF vs Newman: force std {:+.1} %, surge mean {:+.1} %, surge rms {:+.1} %, surge max {:+.1} %",
        change(1),
        change(2),
        change(3),
        change(4)
    );
    assert!(
        change(0).abs() < 2.0,
        "same diagonal, same mean: {:+.2} %",
        change(0)
    );
}

/// `slowdrift hydro nemoh --dir DIR --out FILE` writes the library's import, and says what
/// it took from each file.
#[test]
fn the_cli_writes_the_library_import() {
    let Some(dir) = oc3_dir_or_skip() else {
        return;
    };
    let out = temp_dir("nemoh-cli").join("oc3.json");
    let run = std::process::Command::new(env!("CARGO_BIN_EXE_slowdrift"))
        .args(["hydro", "nemoh", "--dir"])
        .arg(&dir)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(
        stdout.contains("conjugated from NEMOH's e^(-i w t)")
            && stdout.contains("low-frequency added mass from the lowest"),
        "{stdout}"
    );
    let written = slowdrift::hydro::io::database::HydroDatabase::load(&out, LIMIT).unwrap();
    assert_eq!(written, nemoh::import(&dir, LIMIT).unwrap().database);
    let missing = std::process::Command::new(env!("CARGO_BIN_EXE_slowdrift"))
        .args(["hydro", "nemoh", "--dir", "/nonexistent-nemoh", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(!missing.status.success());
    assert!(String::from_utf8_lossy(&missing.stderr).contains("no Nemoh.cal"));
}

/// Numbers cut short in NEMOH's matrix files: a mantissa whose exponent
/// was lost in `CM.dat` (a value 1e7 times too small that would parse), and `Inertia.dat`
/// ending inside its last number without a newline, are refused naming `file:line` and the
/// field; the intact files read.
#[test]
fn nemoh_matrices_with_a_number_cut_are_refused_at_file_and_line() {
    let Some(dir) = oc3_dir_or_skip() else {
        return;
    };
    let copy = temp_dir("nemoh-cut");
    let cm = std::fs::read_to_string(dir.join("results/CM.dat")).unwrap();
    assert!(
        nemoh::matrices::read_frequency_matrices(&dir.join("results/CM.dat"), 6, LIMIT).is_ok()
    );
    // Line 5 is the third row of the first matrix; its third field loses its exponent.
    let mut lines: Vec<String> = cm.lines().map(str::to_string).collect();
    let fields: Vec<&str> = lines[4].split_whitespace().collect();
    let (mantissa, exponent) = fields[2].split_once('E').expect("a Fortran E exponent");
    assert!(!exponent.is_empty());
    let cut = lines[4].replacen(fields[2], mantissa, 1);
    lines[4] = cut;
    let path = copy.join("CM.dat");
    std::fs::write(&path, lines.join("\n") + "\n").unwrap();
    let message = nemoh::matrices::read_frequency_matrices(&path, 6, LIMIT)
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("CM.dat:5:") && message.contains("field 3") && message.contains("cut"),
        "{message}"
    );

    let inertia = std::fs::read_to_string(dir.join("Mechanics/Inertia.dat")).unwrap();
    assert!(nemoh::matrices::read_matrix6(&dir.join("Mechanics/Inertia.dat"), LIMIT).is_ok());
    let whole = inertia.trim_end();
    let last_line = whole.lines().count();
    // Cut inside the last number: drop its exponent's last digit and everything after.
    let cut = &whole[..whole.len() - 1];
    let path = copy.join("Inertia.dat");
    std::fs::write(&path, cut).unwrap();
    let message = nemoh::matrices::read_matrix6(&path, LIMIT)
        .unwrap_err()
        .to_string();
    assert!(
        message.contains(&format!("Inertia.dat:{last_line}:"))
            && message.contains("field 6")
            && message.contains("without a newline"),
        "{message}"
    );
}
