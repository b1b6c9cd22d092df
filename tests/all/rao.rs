//! First-order motions (RAOs): the WAMIT route against independent ones.
//!
//! Real data: the IEA-15 MW UMaine VolturnUS-S semi-submersible (`../shared/data/wamit/
//! iea15-semi`, see its SOURCE.md; `$SLOWDRIFT_DATA` overrides), skipped with a line when
//! absent. The expected values are made here from the raw text of its `.1`, `.3` and `.hst`
//! (split_whitespace, scaled by hand) and a complex Gaussian elimination written here; the
//! long-wave limits of a freely floating body come from linear wave theory. Synthetic files
//! cover the readers' scaling and refusals and the database's new fields.

use crate::wamit::{temp_dir, with_ext, write};
use rustfft::num_complex::Complex64;
use slowdrift::hydro::default_platform;
use slowdrift::hydro::io::database::HydroDatabase;
use slowdrift::hydro::io::wamit::{self, read_excitation, read_motions, WamitOptions};
use slowdrift::hydro::rao::{solve, BodyMatrices, FirstOrder, Rao, RaoTable};
use slowdrift::hydro::rigid_body::RigidBody;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

const RHO: f64 = 1025.0;
const G: f64 = 9.80665;
/// The platform alone (SOURCE.md, from OpenFAST's ElastoDyn input).
pub(crate) const MASS: f64 = 1.7838e7;
pub(crate) const ZG: f64 = -14.4;
pub(crate) const I_ROLL_PITCH: f64 = 1.2507e10;
pub(crate) const I_YAW: f64 = 2.3667e10;
const DEPTH: f64 = 200.0;

/// The IEA-15 semi's WAMIT files without extension, or `None` after saying so.
pub(crate) fn iea15_root_or_skip() -> Option<PathBuf> {
    let dir = crate::common::shared_data_dir().join("wamit/iea15-semi");
    let root = dir.join("IEA-15-240-RWT-UMaineSemi");
    if with_ext(&root, "3").is_file()
        && with_ext(&root, "1").is_file()
        && with_ext(&root, "hst").is_file()
    {
        return Some(root);
    }
    if std::env::var_os("CI").is_some() {
        panic!(
            "the IEA-15 semi's WAMIT data are absent at {}",
            dir.display()
        );
    }
    eprintln!("skipped: IEA-15 semi data absent at {}", dir.display());
    None
}

fn numbers(line: &str) -> Vec<f64> {
    line.split_whitespace()
        .map(|f| f.parse().unwrap())
        .collect()
}

/// The raw files, read here: omega -> (A, B) from `.1` (PER > 0; L = 1 so A = rho Abar,
/// B = rho omega Bbar), (omega, beta in degrees) -> X from `.3` (X = rho g (Re + i Im)),
/// C from `.hst` (rho g Cbar).
type Matrix = [[f64; 6]; 6];

struct Raw {
    radiation: Vec<(f64, Matrix, Matrix)>,
    excitation: Vec<(f64, f64, [Complex64; 6])>,
    c: [[f64; 6]; 6],
}

fn raw(root: &Path) -> Raw {
    let mut radiation: Vec<(f64, Matrix, Matrix)> = Vec::new();
    for line in std::fs::read_to_string(with_ext(root, "1"))
        .unwrap()
        .lines()
    {
        let v = numbers(line);
        if v[0] <= 0.0 {
            continue;
        }
        let w = 2.0 * PI / v[0];
        let (i, j) = (v[1] as usize - 1, v[2] as usize - 1);
        let k = match radiation.iter().position(|r| (r.0 - w).abs() < 1e-9 * w) {
            Some(k) => k,
            None => {
                radiation.push((w, [[0.0; 6]; 6], [[0.0; 6]; 6]));
                radiation.len() - 1
            }
        };
        radiation[k].1[i][j] = RHO * v[3];
        radiation[k].2[i][j] = RHO * w * v[4];
    }
    let mut excitation: Vec<(f64, f64, [Complex64; 6])> = Vec::new();
    for line in std::fs::read_to_string(with_ext(root, "3"))
        .unwrap()
        .lines()
    {
        let v = numbers(line);
        let w = 2.0 * PI / v[0];
        let k = match excitation
            .iter()
            .position(|e| (e.0 - w).abs() < 1e-9 * w && e.1 == v[1])
        {
            Some(k) => k,
            None => {
                excitation.push((w, v[1], [Complex64::default(); 6]));
                excitation.len() - 1
            }
        };
        excitation[k].2[v[2] as usize - 1] = RHO * G * Complex64::new(v[5], v[6]);
    }
    let mut c = [[0.0; 6]; 6];
    for line in std::fs::read_to_string(with_ext(root, "hst"))
        .unwrap()
        .lines()
    {
        let v = numbers(line);
        c[v[0] as usize - 1][v[1] as usize - 1] = RHO * G * v[2];
    }
    Raw {
        radiation,
        excitation,
        c,
    }
}

/// The platform's mass matrix written out by hand for a centre of gravity on the z axis:
/// M15 = m z_g, M24 = -m z_g, roll and pitch m z_g^2 above the inertia about the centre.
fn hand_mass(mass: f64) -> [[f64; 6]; 6] {
    let mut m = [[0.0; 6]; 6];
    m[0][0] = mass;
    m[1][1] = mass;
    m[2][2] = mass;
    m[3][3] = I_ROLL_PITCH + mass * ZG * ZG;
    m[4][4] = I_ROLL_PITCH + mass * ZG * ZG;
    m[5][5] = I_YAW;
    m[0][4] = mass * ZG;
    m[4][0] = mass * ZG;
    m[1][3] = -mass * ZG;
    m[3][1] = -mass * ZG;
    m
}

/// Gaussian elimination with partial pivoting on a complex 6x6 system.
pub(crate) fn gauss(mut a: [[Complex64; 6]; 6], mut b: [Complex64; 6]) -> [Complex64; 6] {
    for col in 0..6 {
        let p = (col..6)
            .max_by(|&i, &j| a[i][col].norm().total_cmp(&a[j][col].norm()))
            .unwrap();
        a.swap(col, p);
        b.swap(col, p);
        for row in col + 1..6 {
            let f = a[row][col] / a[col][col];
            let pivot = a[col];
            for (k, v) in a[row].iter_mut().enumerate().skip(col) {
                *v -= f * pivot[k];
            }
            let v = b[col];
            b[row] -= f * v;
        }
    }
    let mut x = [Complex64::default(); 6];
    for row in (0..6).rev() {
        let mut s = b[row];
        for k in row + 1..6 {
            s -= a[row][k] * x[k];
        }
        x[row] = s / a[row][row];
    }
    x
}

/// The crate's first-order coefficients of the IEA-15 semi, through `wamit::import`.
fn imported(root: &Path) -> FirstOrder {
    let import = wamit::import(root, &WamitOptions::default()).unwrap();
    assert!(
        import
            .files
            .iter()
            .any(|l| l.contains(".3: first-order excitation")),
        "{:#?}",
        import.files
    );
    import
        .database
        .first_order
        .expect("first_order from .1, .3, .hst")
}

fn body(mass: f64, stiffness: [[f64; 6]; 6], damping: [[f64; 6]; 6]) -> (BodyMatrices, RigidBody) {
    let rigid = RigidBody {
        mass,
        centre_of_gravity: [0.0, 0.0, ZG],
        inertia: [
            [I_ROLL_PITCH, 0.0, 0.0],
            [0.0, I_ROLL_PITCH, 0.0],
            [0.0, 0.0, I_YAW],
        ],
    };
    let weight = rigid.weight_stiffness(G);
    let mut c = stiffness;
    for i in 0..6 {
        for j in 0..6 {
            c[i][j] += weight[i][j];
        }
    }
    (
        BodyMatrices {
            mass: rigid.mass_matrix(),
            stiffness: c,
            damping,
        },
        rigid,
    )
}

/// `rao` against the equation built from the raw text with the platform's mass (`MASS`,
/// centre of gravity on the z axis at `ZG`), its weight's restoring and `c_ext`, `b_ext`,
/// solved here at 6 frequencies and 5 headings: each DOF within 1e-9 of the largest motion
/// (rotations times 100 m).
fn assert_is_the_raw_equation(rao: &Rao, raw: &Raw, c_ext: [[f64; 6]; 6], b_ext: [[f64; 6]; 6]) {
    assert_eq!(rao.omegas.len(), raw.radiation.len());
    let mass = hand_mass(MASS);
    let mut worst: f64 = 0.0;
    let mut checked = 0;
    for &n in &[0, 7, 30, 55, 80, raw.radiation.len() - 1] {
        let (w, a, b) = &raw.radiation[n];
        for beta_deg in [0.0, 30.0, 90.0, -150.0, 180.0] {
            let x = raw
                .excitation
                .iter()
                .find(|e| (e.0 - w).abs() < 1e-9 * w && e.1 == beta_deg)
                .unwrap()
                .2;
            let mut k = [[Complex64::default(); 6]; 6];
            for i in 0..6 {
                for j in 0..6 {
                    // The weight's restoring: -m g z_g in roll and pitch (the file holds
                    // buoyancy alone).
                    let weight = if i == j && (i == 3 || i == 4) {
                        -MASS * G * ZG
                    } else {
                        0.0
                    };
                    k[i][j] = Complex64::new(
                        -w * w * (mass[i][j] + a[i][j]) + raw.c[i][j] + c_ext[i][j] + weight,
                        w * (b[i][j] + b_ext[i][j]),
                    );
                }
            }
            let expected = gauss(k, x);
            let ih = rao
                .headings
                .iter()
                .position(|&h| (h - beta_deg.to_radians()).abs() < 1e-9)
                .unwrap();
            let iw = rao
                .omegas
                .iter()
                .position(|&v| (v - w).abs() < 1e-9 * w)
                .unwrap();
            let got = rao.values[iw][ih];
            for i in 0..6 {
                // Translations and rotations times a length (100 m) on one scale.
                let scale = |v: &[Complex64; 6]| {
                    (0..6)
                        .map(|d| v[d].norm() * if d >= 3 { 100.0 } else { 1.0 })
                        .fold(0.0, f64::max)
                };
                let unit = if i >= 3 { 100.0 } else { 1.0 };
                let err = (got[i] - expected[i]).norm() * unit / scale(&expected);
                worst = worst.max(err);
                assert!(
                    err < 1e-9,
                    "omega {w:.4}, beta {beta_deg}, DOF {}: {} vs {}",
                    i + 1,
                    got[i],
                    expected[i]
                );
            }
            checked += 1;
        }
    }
    eprintln!("RAOs: {checked} (omega, beta) pairs, worst relative difference {worst:.2e}");
}

/// (a) The crate's RAOs (import, then solve) against the equation solved here from the raw
/// text, with a mooring-like stiffness and viscous damping that couple the DOFs.
#[test]
fn iea15_raos_are_the_equation_solved_from_the_raw_files() {
    let Some(root) = iea15_root_or_skip() else {
        return;
    };
    let raw = raw(&root);
    let first_order = imported(&root);
    let mut c_ext = [[0.0; 6]; 6];
    c_ext[0][0] = 7.0e4;
    c_ext[1][1] = 7.0e4;
    c_ext[0][4] = -1.0e6;
    c_ext[4][0] = -1.0e6;
    c_ext[5][5] = 5.0e7;
    let mut b_ext = [[0.0; 6]; 6];
    b_ext[2][2] = 5.0e5;
    b_ext[3][3] = 2.0e9;
    b_ext[4][4] = 2.0e9;
    b_ext[0][0] = 1.0e5;
    let (matrices, _) = body(MASS, c_ext, b_ext);
    let rao = solve(&first_order, &matrices).unwrap();
    assert_eq!(rao.omegas.len(), raw.radiation.len());
    assert_is_the_raw_equation(&rao, &raw, c_ext, b_ext);
}

/// Wavenumber of omega in water of depth h: omega^2 = g k tanh(k h), by Newton.
fn wavenumber(w: f64, h: f64) -> f64 {
    let mut k = w * w / G / (w * w * h / G).sqrt().tanh().max(1e-3);
    for _ in 0..50 {
        let f = G * k * (k * h).tanh() - w * w;
        let df = G * (k * h).tanh() + G * k * h / (k * h).cosh().powi(2);
        k -= f / df;
    }
    k
}

/// (b) A freely floating body in long waves follows the water: heave -> 1, surge -> the
/// surface particle's horizontal displacement -i coth(k h) cos(beta) (Re{xi e^{i w t}} with
/// the elevation Re{e^{i (w t - k x)}}: u = w coth(kh) zeta, displacement u / (i w)), pitch
/// -> the wave slope's tilt i k cos(beta), roll -> -i k sin(beta) (the body's z axis along
/// the surface normal). "Free" means no mooring and, for the horizontal motions to be the
/// water's, a mass equal to the displaced water's: rho V with V = 20206.34889 m^3 (the
/// displaced volume WAMIT computed for these files, as the IEA-15-240-RWT repository's
/// HydroDyn input for this platform gives it, PtfmVol0), the given centre of
/// gravity and inertia. Tolerances at the file's lowest frequency, omega = 0.05 rad/s
/// (k = 1.14e-3 1/m at 200 m): the corrections to these limits are of the order of
/// (k L)^2 with L = 100 m the platform's width (0.013) and (omega / omega_n)^2 in heave
/// (0.025 at T_n ~ 20 s), hence 4% in heave, surge and sway; pitch and roll are the
/// difference of the hydrostatic moment and the surge (sway) inertia moment, each about 5
/// times the result, hence five times the surge's: 20%, and 20 deg of phase.
#[test]
fn iea15_free_body_long_wave_limits() {
    let Some(root) = iea15_root_or_skip() else {
        return;
    };
    let first_order = imported(&root);
    let (matrices, _) = body(RHO * 20206.34889, [[0.0; 6]; 6], [[0.0; 6]; 6]);
    let rao = solve(&first_order, &matrices).unwrap();
    let w = rao.omegas[0];
    assert!((w - 0.05).abs() < 1e-6, "lowest frequency {w}");
    let k = wavenumber(w, DEPTH);
    let coth = 1.0 / (k * DEPTH).tanh();
    let i = Complex64::new(0.0, 1.0);
    for beta_deg in [0.0_f64, 90.0, 180.0] {
        let ih = rao
            .headings
            .iter()
            .position(|&h| (h - beta_deg.to_radians()).abs() < 1e-9)
            .unwrap();
        let (c, s) = (beta_deg.to_radians().cos(), beta_deg.to_radians().sin());
        let xi = rao.values[0][ih];
        let heave = xi[2];
        eprintln!(
            "beta {beta_deg}: heave {heave:.5}, surge {:.4} (limit {:.4}), sway {:.4} (limit \
             {:.4}), roll {:.4e} (limit {:.4e}), pitch {:.4e} (limit {:.4e})",
            xi[0],
            -i * coth * c,
            xi[1],
            -i * coth * s,
            xi[3],
            -i * k * s,
            xi[4],
            i * k * c
        );
        assert!((heave - 1.0).norm() < 0.04, "heave {heave}");
        let horizontal = [(0, -i * coth * c), (1, -i * coth * s)];
        for (d, limit) in horizontal {
            if limit.norm() > 0.5 {
                assert!(
                    (xi[d] - limit).norm() < 0.04 * limit.norm(),
                    "DOF {} at {beta_deg} deg: {} vs {limit}",
                    d + 1,
                    xi[d]
                );
            }
        }
        for (d, limit) in [(3, -i * k * s), (4, i * k * c)] {
            if limit.norm() > 0.5 * k {
                let ratio = xi[d] / limit;
                assert!(
                    (ratio.norm() - 1.0).abs() < 0.2 && ratio.arg().abs() < 20f64.to_radians(),
                    "DOF {} at {beta_deg} deg: {} vs {limit} (ratio {ratio})",
                    d + 1,
                    xi[d]
                );
            }
        }
    }
}

/// (c) With a small heave damping (2% of critical), |xi_3| peaks at the heave natural
/// frequency omega_n = sqrt(C33 / (M33 + A33(omega_n))), found here by fixed-point iteration
/// on A33 read from the raw `.1` (interpolated linearly), within the grid's spacing there.
#[test]
fn iea15_heave_peaks_at_its_natural_frequency() {
    let Some(root) = iea15_root_or_skip() else {
        return;
    };
    let raw = raw(&root);
    let first_order = imported(&root);
    let c33 = raw.c[2][2];
    let mut grid: Vec<(f64, f64)> = raw.radiation.iter().map(|r| (r.0, r.1[2][2])).collect();
    grid.sort_by(|a, b| a.0.total_cmp(&b.0));
    let a33 = |w: f64| {
        let k = grid.partition_point(|g| g.0 < w).clamp(1, grid.len() - 1);
        let (l, r) = (grid[k - 1], grid[k]);
        l.1 + (r.1 - l.1) * (w - l.0) / (r.0 - l.0)
    };
    let mut wn = (c33 / (MASS + a33(0.3))).sqrt();
    for _ in 0..50 {
        wn = (c33 / (MASS + a33(wn))).sqrt();
    }
    let critical = 2.0 * (c33 * (MASS + a33(wn))).sqrt();
    let mut b_ext = [[0.0; 6]; 6];
    b_ext[2][2] = 0.02 * critical;
    let mut c_ext = [[0.0; 6]; 6];
    c_ext[0][0] = 7.0e4;
    c_ext[1][1] = 7.0e4;
    c_ext[5][5] = 5.0e7;
    let (matrices, _) = body(MASS, c_ext, b_ext);
    let rao = solve(&first_order, &matrices).unwrap();
    let ih = rao.headings.iter().position(|&h| h.abs() < 1e-9).unwrap();
    let peak = (0..rao.omegas.len())
        .max_by(|&a, &b| {
            rao.values[a][ih][2]
                .norm()
                .total_cmp(&rao.values[b][ih][2].norm())
        })
        .unwrap();
    let wp = rao.omegas[peak];
    let spacing = (rao.omegas[(peak + 1).min(rao.omegas.len() - 1)] - wp)
        .max(wp - rao.omegas[peak.saturating_sub(1)]);
    // The dynamic amplification at the peak: |xi_3| C33 / |X_3|.
    let x3 = first_order.excitation(peak, ih)[2].norm();
    let amplification = rao.values[peak][ih][2].norm() * c33 / x3;
    eprintln!(
        "heave: natural period {:.3} s (omega_n {wn:.4} rad/s), |xi3| peaks at {wp:.4} rad/s \
         ({:.3} s) with {:.3} m/m, amplification |xi3| C33 / |X3| = {amplification:.2}; grid \
         spacing there {spacing:.4} rad/s",
        2.0 * PI / wn,
        2.0 * PI / wp,
        rao.values[peak][ih][2].norm(),
    );
    assert!((wp - wn).abs() <= spacing, "peak {wp} vs omega_n {wn}");
    // A node within one spacing of omega_n (here |1 - omega / omega_n| <= 0.16 at most, in
    // fact 0.04) sees the one-DOF amplification 1 / |1 - r^2 + 2 i zeta r| of at least 3.
    assert!(
        amplification > 3.0,
        "amplification {amplification} at the peak"
    );
}

// --------------------------------------------------------------- readers, synthetic files

/// A `.3` with a header, ULEN = 2, both of two DOFs at two headings, and a `.4` alike:
/// X = rho g L^2 Xbar (forces), rho g L^3 Xbar (moments); xi = xibar (translations),
/// xibar / L (rotations).
#[test]
fn excitation_and_motion_files_read_back_scaled() {
    let dir = temp_dir("read");
    let text = "WAMIT .3 header\n\
        10.0 0.0 1 2.0 90.0 0.0 2.0\n\
        10.0 0.0 5 1.0 0.0 1.0 0.0\n\
        10.0 90.0 1 1.0 180.0 -1.0 0.0\n\
        10.0 90.0 5 3.0 -90.0 0.0 -3.0\n\
        5.0 0.0 1 1.0 0.0 1.0 0.0\n\
        5.0 0.0 5 1.0 0.0 1.0 0.0\n\
        5.0 90.0 5 1.0 0.0 1.0 0.0\n\
        5.0 90.0 1 1.0 0.0 1.0 0.0\n";
    let options = WamitOptions {
        ulen: 2.0,
        ..WamitOptions::default()
    };
    let x = read_excitation(&write(&dir, "b.3", text), &options).unwrap();
    assert_eq!(x.dofs, vec![1, 5]);
    assert!((x.omegas[0] - 2.0 * PI / 10.0).abs() < 1e-15);
    assert!((x.headings[1] - PI / 2.0).abs() < 1e-15);
    assert_eq!(x.values[0][0][0], Complex64::new(0.0, 2.0 * RHO * G * 4.0));
    assert_eq!(x.values[0][1][4], Complex64::new(0.0, -3.0 * RHO * G * 8.0));
    assert_eq!(x.values[0][0][2], Complex64::default());
    let m = read_motions(&write(&dir, "b.4", text), &options).unwrap();
    assert_eq!(m.values[0][0][0], Complex64::new(0.0, 2.0));
    assert_eq!(m.values[0][1][4], Complex64::new(0.0, -1.5));
}

#[test]
fn bad_excitation_lines_name_the_file_and_line() {
    let dir = temp_dir("bad");
    let options = WamitOptions::default();
    let good = "10.0 0.0 1 1.0 0.0 1.0 0.0\n";
    for (text, wants) in [
        (
            format!("{good}10.0 0.0 2 1.0 0.0 1.0\n"),
            ":2: expected 7 numbers",
        ),
        (format!("{good}10.0 0.0 7 1.0 0.0 1.0 0.0\n"), "I = 7"),
        (format!("{good}-3.0 0.0 2 1.0 0.0 1.0 0.0\n"), "PER = -3"),
        (
            format!("{good}10.0 0.0 1 1.0 0.0 1.0 0.0\n"),
            "given twice (first at line 1)",
        ),
        (
            format!("{good}10.0 0.0 2 1.0 0.0 1.0 0.0\n10.0 90.0 1 1.0 0.0 1.0 0.0\n"),
            "DOF 2 at 90.000 deg",
        ),
        (
            format!("{good}10.0 0.0 2 1.0 0.0 0.0 1.0\n"),
            "not the same complex number",
        ),
        (format!("{good}10.0 0.0 2 1.0 90.0 0.0 -1.0\n"), "conjugate"),
    ] {
        let path = write(&dir, "bad.3", &text);
        let err = read_excitation(&path, &options).unwrap_err().to_string();
        assert!(
            err.contains("bad.3") && err.contains(wants),
            "{wants}: {err}"
        );
        let path = write(&dir, "bad.4", &text);
        let err = read_motions(&path, &options).unwrap_err().to_string();
        assert!(
            err.contains("bad.4") && err.contains(wants),
            "{wants}: {err}"
        );
    }
}

/// A synthetic body (a `.1`, `.hst`, `.3`, `.4` at two periods, one heading): the import
/// fills `first_order` (with the `.3`, not the `.2` beside it) and `rao`, a line per file;
/// the database writes and reads them back bit for bit; `.1` and `.3` frequencies that
/// differ are refused naming both files.
#[test]
fn import_fills_first_order_and_rao_and_the_database_keeps_them() {
    let dir = temp_dir("import");
    let root = dir.join("body");
    write(&dir, "body.1", "-1 1 1 5.0\n0 1 1 4.0\n10.0 1 1 5.5 0.25\n10.0 3 3 7.0 0.5\n5.0 1 1 5.0 0.5\n5.0 3 3 6.0 1.0\n");
    write(&dir, "body.hst", "3 3 100.0\n4 4 20.0\n5 5 20.0\n");
    let three = "10.0 0.0 1 1.0 90.0 0.0 1.0\n10.0 0.0 3 2.0 0.0 2.0 0.0\n5.0 0.0 1 1.0 90.0 0.0 1.0\n5.0 0.0 3 2.0 0.0 2.0 0.0\n";
    write(&dir, "body.3", three);
    write(
        &dir,
        "body.2",
        "10.0 0.0 1 9.0 0.0 9.0 0.0\n5.0 0.0 1 9.0 0.0 9.0 0.0\n",
    );
    write(
        &dir,
        "body.4",
        "10.0 0.0 3 1.5 0.0 1.5 0.0\n5.0 0.0 3 1.25 0.0 1.25 0.0\n",
    );
    let import = wamit::import(&root, &WamitOptions::default()).unwrap();
    let db = &import.database;
    let fo = db.first_order.as_ref().expect("first_order");
    assert_eq!(fo.omegas.len(), 2);
    assert_eq!(fo.excitation(1, 0)[2], Complex64::new(2.0 * RHO * G, 0.0));
    // Frequencies increase: index 0 is PER = 10 s.
    assert_eq!(fo.added_mass[0][0][0], 5.5 * RHO);
    assert_eq!(fo.added_mass[1][0][0], 5.0 * RHO);
    assert_eq!(fo.damping[0][2][2], 0.5 * RHO * fo.omegas[0]);
    assert!((fo.hydrostatics[2][2] - 100.0 * RHO * G).abs() <= 1e-15 * 100.0 * RHO * G);
    let rao = db.rao.as_ref().expect("rao").to_rao();
    assert_eq!(rao.values[0][0][2], Complex64::new(1.5, 0.0));
    assert_eq!(rao.values[1][0][2], Complex64::new(1.25, 0.0));
    let text = import.files.join("\n");
    assert!(text.contains("body.3: first-order excitation"), "{text}");
    assert!(text.contains("body.2: not read"), "{text}");
    assert!(text.contains("body.4: RAOs"), "{text}");
    let json = dir.join("body.json");
    db.save(&json).unwrap();
    let back = HydroDatabase::load(&json, 1e9).unwrap();
    assert_eq!(&back, db);
    // The .3 at other periods than the .1's.
    write(&dir, "body.3", &three.replace("5.0 0.0", "4.0 0.0"));
    let err = wamit::import(&root, &WamitOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("body.3")
            && err.contains("body.1")
            && err.contains("excitation only: [1.570796]"),
        "{err}"
    );
}

/// Databases written before `first_order` and `rao` existed still read (a small
/// hand-written one), with neither, and the embedded default platform's has its RAOs and no
/// first-order coefficients; a `rao` of the wrong shape is refused naming its field and line.
#[test]
fn old_databases_read_and_bad_rao_is_refused() {
    let db = default_platform::database().unwrap();
    assert!(db.first_order.is_none() && db.rao.is_some());
    let old = r#"{"format_version": 1, "name": "old", "source": "hand", "water_density": 1025.0,
        "gravity": 9.80665, "mass_properties": null, "low_frequency_added_mass": null,
        "stiffness": null, "drift": [{"omega": 0.5, "heading": 0.0, "surge": 1.0, "sway": 0.0,
        "yaw": 0.0, "damping": null}], "qtf": null}"#;
    let db = HydroDatabase::parse(old, "old.json").unwrap();
    assert!(db.first_order.is_none() && db.rao.is_none());
    let bad = old.replace(
        r#""qtf": null"#,
        "\"qtf\": null,\n\"rao\": {\"omegas\": [0.5, 0.6], \"headings\": [0.0],\n\"re\": [[[1,0,0,0,0,0]]], \"im\": [[[0,0,0,0,0,0]]]}",
    );
    let err = HydroDatabase::parse(&bad, "bad.json")
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("bad.json") && err.contains("rao.re") && err.contains("2 x 1 x 6"),
        "{err}"
    );
    // A table made from RAOs in memory reads back as them.
    let rao = Rao {
        omegas: vec![0.5],
        headings: vec![0.0],
        values: vec![vec![[Complex64::new(1.0, -0.5); 6]]],
    };
    assert_eq!(RaoTable::from(&rao).to_rao(), rao);
}

/// A 6x6 or 3x3 matrix as TOML.
pub(crate) fn toml_matrix<const N: usize>(m: &[[f64; N]; N]) -> String {
    let rows: Vec<String> = m
        .iter()
        .map(|r| {
            let v: Vec<String> = r.iter().map(|x| format!("{x:e}")).collect();
            format!("[{}]", v.join(", "))
        })
        .collect();
    format!("[{}]", rows.join(", "))
}

/// A configuration of the IEA-15 semi (its WAMIT import saved in `dir`) with `motions`
/// as its `[platform.motions]` section's body (none when empty).
fn iea15_configuration(dir: &Path, root: &Path, motions: &str) -> PathBuf {
    let json = dir.join("iea15.json");
    if !json.exists() {
        wamit::import(root, &WamitOptions::default())
            .unwrap()
            .database
            .save(&json)
            .unwrap();
    }
    let motions = if motions.is_empty() {
        String::new()
    } else {
        format!("\n[platform.motions]\n{motions}\n")
    };
    write(
        dir,
        "iea15.toml",
        &format!(
            "[sea]\nspectrum = \"jonswap\"\nhs = 4.0\ntp = 10.0\nband = [0.3, 1.5]\n\n\
             [run]\nduration = 600.0\n\n\
             [platform]\nmass = {MASS:e}\nyaw_inertia = {I_YAW:e}\n\
             stiffness = [[7.0e4, 0, 0], [0, 7.0e4, 0], [0, 0, 5.0e7]]\n{motions}\n\
             [drift]\nsource = \"database\"\nfile = \"iea15.json\"\n"
        ),
    )
}

/// The configuration's `[platform.motions]` reaches the RAOs: a run of the IEA-15 semi's
/// WAMIT import with its centre of gravity, inertia tensor, a mooring's stiffness and a
/// viscous damping gives the RAOs of the equation solved here from the raw files; its
/// summary states the heave, roll and pitch natural periods computed here from the raw
/// `.1` and `.hst` (fixed-point on A_ii(omega), the weight's -m g z_g in roll and pitch).
#[test]
fn a_configuration_with_motions_runs_the_raw_equation() {
    let Some(root) = iea15_root_or_skip() else {
        return;
    };
    let raw = raw(&root);
    let mut c_ext = [[0.0; 6]; 6];
    c_ext[0][0] = 7.0e4;
    c_ext[1][1] = 7.0e4;
    c_ext[5][5] = 5.0e7;
    let mut b_ext = [[0.0; 6]; 6];
    b_ext[2][2] = 5.0e5;
    b_ext[3][3] = 2.0e9;
    b_ext[4][4] = 2.0e9;
    let tensor = [
        [I_ROLL_PITCH, 0.0, 0.0],
        [0.0, I_ROLL_PITCH, 0.0],
        [0.0, 0.0, I_YAW],
    ];
    let dir = temp_dir("motions-config");
    let config = iea15_configuration(
        &dir,
        &root,
        &format!(
            "centre_of_gravity = [0.0, 0.0, {ZG:e}]\ninertia = {}\nexternal_stiffness = {}\n\
             external_damping = {}",
            toml_matrix(&tensor),
            toml_matrix(&c_ext),
            toml_matrix(&b_ext)
        ),
    );
    let problem = slowdrift::problem::load(&config).unwrap();
    problem.check().unwrap();
    let motions = problem
        .first_order_motions()
        .unwrap()
        .expect("RAOs from [platform.motions]");
    assert_is_the_raw_equation(&motions.rao, &raw, c_ext, b_ext);

    // The natural periods by hand: M_ii + A_ii(omega) against C_ii, A interpolated
    // linearly in the raw .1's frequencies.
    let mass = hand_mass(MASS);
    let mut grid: Vec<(f64, Matrix)> = raw.radiation.iter().map(|r| (r.0, r.1)).collect();
    grid.sort_by(|a, b| a.0.total_cmp(&b.0));
    let summary = problem.summary().unwrap().join("\n");
    for (i, dof) in [(2, "heave"), (3, "roll"), (4, "pitch")] {
        let c = raw.c[i][i] + c_ext[i][i] + if i > 2 { -MASS * G * ZG } else { 0.0 };
        let a = |w: f64| {
            let k = grid.partition_point(|g| g.0 < w).clamp(1, grid.len() - 1);
            let (l, r) = (&grid[k - 1], &grid[k]);
            let t = ((w - l.0) / (r.0 - l.0)).clamp(0.0, 1.0);
            l.1[i][i] + (r.1[i][i] - l.1[i][i]) * t
        };
        let mut w = (c / (mass[i][i] + a(grid[0].0))).sqrt();
        for _ in 0..200 {
            w = (c / (mass[i][i] + a(w))).sqrt();
        }
        let period = format!("{dof} {:.1} s", 2.0 * PI / w);
        eprintln!("{dof}: natural period {:.3} s", 2.0 * PI / w);
        assert!(summary.contains(&period), "{period} not in\n{summary}");
    }
    assert!(
        summary.contains("first-order motions: RAOs solved from the first-order coefficients of")
            && summary.contains("iea15.json with [platform.motions]; natural periods heave"),
        "{summary}"
    );
}

/// Without `[platform.motions]` a database with first-order coefficients runs no RAOs and
/// the summary says what would give them; with it, a drift source without coefficients and
/// a section that gives two inertias, none, or a radius that is not positive are refused
/// at their line, naming the key.
#[test]
fn motions_are_what_the_configuration_asks_or_refused() {
    let Some(root) = iea15_root_or_skip() else {
        return;
    };
    let dir = temp_dir("motions-refused");
    let problem = slowdrift::problem::load(&iea15_configuration(&dir, &root, "")).unwrap();
    problem.check().unwrap();
    assert!(problem.first_order_motions().unwrap().is_none());
    let summary = problem.summary().unwrap().join("\n");
    assert!(
        summary.contains("first-order motions: none (")
            && summary.contains(
                "iea15.json has first-order coefficients: give [platform.motions] for its RAOs)"
            ),
        "{summary}"
    );

    let refused = |motions: &str| {
        let config = iea15_configuration(&dir, &root, motions);
        let checked = slowdrift::problem::load(&config).and_then(|p| p.check());
        let message = checked.unwrap_err().to_string();
        eprintln!("{message}");
        message
    };
    let both = refused(
        "centre_of_gravity = [0, 0, -14.4]\nradii_of_gyration = [26, 26, 36]\n\
         inertia = [[1e10, 0, 0], [0, 1e10, 0], [0, 0, 2e10]]",
    );
    assert!(
        both.contains("iea15.toml:") && both.contains("not both"),
        "{both}"
    );
    let none = refused("centre_of_gravity = [0, 0, -14.4]");
    assert!(
        none.contains("iea15.toml:") && none.contains("radii_of_gyration"),
        "{none}"
    );
    let negative = refused("centre_of_gravity = [0, 0, -14.4]\nradii_of_gyration = [26, -1, 36]");
    assert!(
        negative.contains("radii_of_gyration[1]") && negative.contains("iea15.toml:"),
        "{negative}"
    );
    let impossible = refused(
        "centre_of_gravity = [0, 0, -14.4]\ninertia = [[1e10, 0, 0], [0, 1e10, 0], [0, 0, 3e10]]",
    );
    assert!(impossible.contains("no body has them"), "{impossible}");

    // A drift table has no first-order coefficients.
    let table = write(
        &dir,
        "table.toml",
        &std::fs::read_to_string(
            Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/minimal.toml"),
        )
        .unwrap()
        .replace(
            "[drift]",
            "[platform.motions]\ncentre_of_gravity = [0, 0, -10]\nradii_of_gyration = [20, 20, 25]\n\n[drift]",
        ),
    );
    let problem = slowdrift::problem::load(&table).unwrap();
    let message = problem.check().unwrap_err().to_string();
    assert!(
        message.contains("table.toml:15: invalid [platform] motions")
            && message.contains("first-order coefficients"),
        "{message}"
    );
}
