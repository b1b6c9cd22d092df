//! First-order motions (RAOs) from NEMOH v3: the OC3-Hywind spar of WEC-Sim's examples
//! (`../shared/data/nemoh/oc3-hywind`, see its SOURCE.md; `$SLOWDRIFT_DATA` overrides),
//! skipped with a line when absent.
//!
//! The expected values are made here from the raw text (split_whitespace on the lines of
//! `RadiationCoefficients.tec`, `ExcitationForce.tec`, `CM.dat`, `CA.dat` and
//! `Mechanics/`), by NEMOH's own equation in its own convention (e^{-i w t}, about its
//! point (0, 0, -78) m) solved by the hand-written elimination of tests/all/rao.rs, then
//! conjugated and moved to the origin by hand; the long-wave limits and the heave natural
//! frequency come from linear wave theory and the raw coefficients.

use crate::nemoh::{oc3_dir_or_skip, raw_rows};
use crate::rao::gauss;
use rustfft::num_complex::Complex64;
use slowdrift::hydro::io::nemoh;
use slowdrift::hydro::rao::{FirstOrder, Rao};
use slowdrift::scenario::limits::DEFAULT_MEMORY_LIMIT as LIMIT;
use std::path::Path;

/// The zones of a NEMOH Tecplot file: `zones[z][row]` = the numbers of the row (the
/// frequency first), read with split_whitespace.
fn tec_zones(path: &Path) -> Vec<Vec<Vec<f64>>> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut zones: Vec<Vec<Vec<f64>>> = Vec::new();
    for line in text.lines() {
        let t = line.trim();
        if t.is_empty() || t.starts_with("VARIABLES") || t.starts_with('"') {
            continue;
        }
        if t.starts_with("Zone") {
            zones.push(Vec::new());
            continue;
        }
        zones
            .last_mut()
            .unwrap()
            .push(t.split_whitespace().map(|f| f.parse().unwrap()).collect());
    }
    zones
}

/// The CM.dat / CA.dat blocks: (frequency, 6x6 as written).
fn frequency_blocks(path: &Path) -> Vec<(f64, Vec<Vec<f64>>)> {
    let rows = raw_rows(&path.to_path_buf(), 1);
    rows.chunks(7).map(|c| (c[0][0], c[1..].to_vec())).collect()
}

fn matrix(path: &Path) -> [[f64; 6]; 6] {
    let rows = raw_rows(&path.to_path_buf(), 0);
    std::array::from_fn(|i| std::array::from_fn(|j| rows[i][j]))
}

/// The z of the point Nemoh.cal's roll is about (its line "2 1. 0. 0. x y z ! Roll ...").
fn roll_point(dir: &Path) -> [f64; 3] {
    let text = std::fs::read_to_string(dir.join("Nemoh.cal")).unwrap();
    let line = text
        .lines()
        .find(|l| l.contains("Roll about a point"))
        .unwrap();
    let v: Vec<f64> = line
        .split_whitespace()
        .take(7)
        .map(|f| f.parse().unwrap())
        .collect();
    [v[4], v[5], v[6]]
}

struct Imported {
    first_order: FirstOrder,
    rao: Rao,
    files: Vec<String>,
}

fn imported(dir: &Path) -> Imported {
    let import = nemoh::import(dir, LIMIT).unwrap();
    let db = import.database;
    Imported {
        first_order: db.first_order.expect("first_order from the .tec files"),
        rao: db
            .rao
            .expect("rao from first_order and Mechanics/")
            .to_rao(),
        files: import.files,
    }
}

/// (a) The import's first_order and RAOs against NEMOH's equation solved here from the raw
/// text: -w^2 (M + A) - i w (B + Badd) + Kh + Km (e^{-i w t}, about the point r), A and B
/// with the force's row first (zone j = motion j, pair i = force i), F = |F| e^{i arg};
/// then conjugated to e^{+i w t} and the translations moved to the origin,
/// u_o = u_r + r x theta. The coefficients themselves: the translational block and the
/// yaw term unchanged by a point on the z axis, the excitation moments M_o = M_r + r x F.
#[test]
fn oc3_first_order_and_raos_are_nemohs_equation_from_the_raw_text() {
    let Some(dir) = oc3_dir_or_skip() else {
        return;
    };
    let got = imported(&dir);
    for line in &got.files {
        println!("{line}");
    }
    let rad = tec_zones(&dir.join("results/RadiationCoefficients.tec"));
    let exc = tec_zones(&dir.join("results/ExcitationForce.tec"));
    let mech = |name: &str| matrix(&dir.join("Mechanics").join(name));
    let (m, kh, km, badd) = (
        mech("Inertia.dat"),
        mech("Kh.dat"),
        mech("Km.dat"),
        mech("Badd.dat"),
    );
    let r = roll_point(&dir);
    assert_eq!(r, [0.0, 0.0, -78.0]);
    assert_eq!(
        (rad.len(), exc.len()),
        (6, 1),
        "6 radiating DOFs, 1 heading"
    );
    let nw = rad[0].len();
    assert_eq!(got.first_order.omegas.len(), nw);
    assert_eq!(got.first_order.headings, vec![0.0]);
    let i1 = Complex64::new(0.0, 1.0);
    let mut worst: f64 = 0.0;
    let mut worst_coefficient: f64 = 0.0;
    for n in [0, 1, 4, 9, 20, 40, 70, 100, nw - 1] {
        let w = rad[0][n][0];
        assert_eq!(got.first_order.omegas[n], w);
        let a = |i: usize, j: usize| rad[j][n][1 + 2 * i];
        let b = |i: usize, j: usize| rad[j][n][2 + 2 * i];
        let f: [Complex64; 6] = std::array::from_fn(|i| {
            Complex64::from_polar(exc[0][n][1 + 2 * i], exc[0][n][2 + 2 * i])
        });
        // The coefficients: translations and yaw as written, moments moved.
        let scale = (0..6).map(|i| a(i, i).abs()).fold(0.0, f64::max);
        for (i, j) in [
            (0, 0),
            (0, 1),
            (1, 0),
            (2, 2),
            (0, 2),
            (2, 0),
            (5, 5),
            (1, 2),
        ] {
            let d = (got.first_order.added_mass[n][i][j] - a(i, j)).abs() / scale;
            worst_coefficient = worst_coefficient.max(d);
            assert!(d < 1e-12, "A[{i}][{j}] at {w}");
            assert_eq!(
                got.first_order.damping[n][i][j],
                b(i, j),
                "B[{i}][{j}] at {w}"
            );
        }
        let x = got.first_order.excitation(n, 0);
        let hand = [
            f[0].conj(),
            f[1].conj(),
            f[2].conj(),
            (f[3] - f[1] * r[2]).conj(),
            (f[4] + f[0] * r[2]).conj(),
            f[5].conj(),
        ];
        for i in 0..6 {
            let d = (x[i] - hand[i]).norm() / hand.iter().map(|v| v.norm()).fold(0.0, f64::max);
            worst_coefficient = worst_coefficient.max(d);
            assert!(d < 1e-12, "X[{i}] at {w}: {} vs {}", x[i], hand[i]);
        }
        // NEMOH's equation, its convention and point.
        let k: [[Complex64; 6]; 6] = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                Complex64::new(
                    -w * w * (m[i][j] + a(i, j)) + kh[i][j] + km[i][j],
                    -w * (b(i, j) + badd[i][j]),
                )
            })
        });
        let xi_r = gauss(k, f);
        let theta = [xi_r[3].conj(), xi_r[4].conj(), xi_r[5].conj()];
        // u_o = u_r + r x theta.
        let cross = [
            theta[2] * r[1] - theta[1] * r[2],
            theta[0] * r[2] - theta[2] * r[0],
            theta[1] * r[0] - theta[0] * r[1],
        ];
        let expected = [
            xi_r[0].conj() + cross[0],
            xi_r[1].conj() + cross[1],
            xi_r[2].conj() + cross[2],
            theta[0],
            theta[1],
            theta[2],
        ];
        let xi = got.rao.values[n][0];
        // Translations and rotations times a length (100 m) on one scale.
        let unit = |d: usize| if d >= 3 { 100.0 } else { 1.0 };
        let size = (0..6)
            .map(|d| expected[d].norm() * unit(d))
            .fold(0.0, f64::max);
        for d in 0..6 {
            let err = (xi[d] - expected[d]).norm() * unit(d) / size;
            worst = worst.max(err);
            assert!(
                err < 1e-9,
                "omega {w}, DOF {}: {} vs {} (e^(i w t) {})",
                d + 1,
                xi[d],
                expected[d],
                i1
            );
        }
    }
    eprintln!(
        "NEMOH first_order: coefficients worst {worst_coefficient:.2e}; RAOs at 9 frequencies, \
         heading 0 (the data's only one), worst relative difference {worst:.2e}"
    );
}

/// (b) Two NEMOH files agree: CM.dat is the added mass and CA.dat the damping of
/// RadiationCoefficients.tec (NEMOH's Results.f90 writes CM.dat from AddedMass and CA.dat
/// from RadiationDamping, both a row per radiating DOF; the data's SOURCE.md says the
/// reverse), at every frequency, to the files' digits: CM.dat writes E13.6 (0.dddddd E+xx:
/// a rounding up to 0.5e-6 of a mantissa >= 0.1, 5e-6 of the value), the tec E14.7 (5e-7),
/// so 5.5e-6 of the block's largest value. The existing import's low-frequency added mass (CM.dat at
/// its lowest frequency) is the first_order's at that frequency in surge, sway and yaw.
#[test]
fn oc3_cm_dat_is_the_added_mass_and_ca_dat_the_damping_of_the_tec() {
    let Some(dir) = oc3_dir_or_skip() else {
        return;
    };
    let rad = tec_zones(&dir.join("results/RadiationCoefficients.tec"));
    let cm = frequency_blocks(&dir.join("results/CM.dat"));
    let ca = frequency_blocks(&dir.join("results/CA.dat"));
    assert_eq!((cm.len(), ca.len()), (rad[0].len(), rad[0].len()));
    let mut worst = [0.0_f64; 2];
    let mut swapped: f64 = 0.0;
    for (n, ((w_cm, a), (w_ca, b))) in cm.iter().zip(&ca).enumerate() {
        let w = rad[0][n][0];
        // CM.dat prints the frequency with four decimals (F7.4).
        assert!(
            (w_cm - w).abs() <= 5.001e-5 && (w_ca - w).abs() <= 5.001e-5,
            "{w_cm} vs {w}"
        );
        for (p, block) in [a, b].into_iter().enumerate() {
            let largest = (0..6)
                .flat_map(|i| (0..6).map(move |j| (i, j)))
                .map(|(i, j)| rad[i][n][1 + p + 2 * j].abs())
                .fold(0.0, f64::max);
            for i in 0..6 {
                for j in 0..6 {
                    let tec = rad[i][n][1 + p + 2 * j];
                    let d = (block[i][j] - tec).abs() / largest;
                    worst[p] = worst[p].max(d);
                    assert!(
                        d < 5.5e-6,
                        "{} [{i}][{j}] at {w}: {} vs the tec's {tec}",
                        ["CM.dat", "CA.dat"][p],
                        block[i][j]
                    );
                }
            }
            // The other file's values are not these (CM and CA are not the same numbers).
            let other = [b, a][p];
            swapped = swapped.max((other[2][2] - rad[2][n][1 + p + 4]).abs() / largest);
        }
    }
    eprintln!(
        "CM.dat vs the tec's A: worst {:.2e} of the block's largest; CA.dat vs B: {:.2e}; \
         the files swapped would differ by {swapped:.2e}",
        worst[0], worst[1]
    );
    assert!(swapped > 1e-3);
    let import = nemoh::import(&dir, LIMIT).unwrap();
    let low = import.database.low_frequency_added_mass.unwrap();
    let fo = import.database.first_order.unwrap();
    let slow = [0, 1, 5];
    for (r, &i) in slow.iter().enumerate() {
        for (c, &j) in slow.iter().enumerate() {
            let d = (low[r][c] - fo.added_mass[0][i][j]).abs() / fo.added_mass[0][0][0];
            assert!(
                d < 5.5e-6,
                "A[{i}][{j}]: {} vs {}",
                low[r][c],
                fo.added_mass[0][i][j]
            );
        }
    }
}

/// (c) The freely floating spar (no mooring: Km = 0, NEMOH's mass rho V) in long waves
/// follows the water. Deep water (Nemoh.cal's depth 0), elevation Re{e^{i (w t - k x)}},
/// k = w^2 / g: heave -> 1; surge at the origin (the still waterline) -> the surface
/// particle's horizontal excursion -i (|xi_1| = 1, 90 deg behind the elevation); pitch ->
/// the slope's tilt i k. At the lowest frequency, 0.025 rad/s (k = 6.4e-5 1/m, wave
/// length 98.6 km), the corrections are of the order of k D with D = 120 m the draft
/// (0.008), and in heave (w / w_n)^2 with w_n ~ 0.2 rad/s (0.016): hence 3% on heave and
/// surge. Pitch is a tilt of order k itself, the balance of the hydrostatic moment and the
/// moment of the surge inertia forces, so its relative corrections are larger: 30% and
/// 20 deg of phase, as for the WAMIT route (tests/all/rao.rs).
#[test]
fn oc3_free_spar_long_wave_limits() {
    let Some(dir) = oc3_dir_or_skip() else {
        return;
    };
    let got = imported(&dir);
    let g = 9.81;
    let w = got.rao.omegas[0];
    assert!((w - 0.025).abs() < 1e-7, "lowest frequency {w}");
    let k = w * w / g;
    let i = Complex64::new(0.0, 1.0);
    let xi = got.rao.values[0][0];
    let (heave, surge, pitch) = (xi[2], xi[0], xi[4]);
    let ratio = pitch / (i * k);
    eprintln!(
        "omega {w}: heave {heave:.5} (limit 1), surge {surge:.5} (limit -i; |{:.5}| at \
         {:.2} deg), pitch {pitch:.4e} (limit i k = {:.4e}; ratio {ratio:.4}); sway {:.2e}, \
         roll {:.2e}, yaw {:.2e}",
        surge.norm(),
        surge.arg().to_degrees(),
        i * k,
        xi[1].norm(),
        xi[3].norm(),
        xi[5].norm()
    );
    assert!((heave - 1.0).norm() < 0.03, "heave {heave}");
    assert!((surge + i).norm() < 0.03, "surge {surge}");
    assert!(
        (ratio.norm() - 1.0).abs() < 0.3 && ratio.arg().abs() < 20f64.to_radians(),
        "pitch {pitch} vs i k {}",
        i * k
    );
    // Head seas: sway, roll and yaw are not excited (NEMOH's values there are noise, 1e-5
    // of the surge force or less).
    assert!(xi[1].norm() < 1e-3 && xi[3].norm() * 100.0 < 1e-3 && xi[5].norm() * 100.0 < 1e-3);
}

/// (d) Undamped but for the radiation damping (Badd = 0), |xi_3| peaks at the heave
/// natural frequency omega_n = sqrt(C33 / (M33 + A33(omega_n))), with M33, C33 from
/// Mechanics/ and A33 from the tec (linear between its nodes), found by fixed-point
/// iteration: within the grid's spacing there (0.047 rad/s). The spar's heave excitation
/// falls quickly with frequency (its 120 m draft: 5.2e5 N/m at 0.166, 1.4e5 at 0.213
/// rad/s), so the peak node is the one below omega_n, not the nearest: the grid is too
/// coarse to say more than "within a spacing".
#[test]
fn oc3_heave_peaks_at_its_natural_frequency() {
    let Some(dir) = oc3_dir_or_skip() else {
        return;
    };
    let got = imported(&dir);
    let rad = tec_zones(&dir.join("results/RadiationCoefficients.tec"));
    let m33 = matrix(&dir.join("Mechanics/Inertia.dat"))[2][2];
    let c33 = matrix(&dir.join("Mechanics/Kh.dat"))[2][2];
    // A33: zone 3 (heave motion), pair 3 (heave force).
    let grid: Vec<(f64, f64)> = rad[2].iter().map(|row| (row[0], row[5])).collect();
    let a33 = |w: f64| {
        let k = grid.partition_point(|g| g.0 < w).clamp(1, grid.len() - 1);
        let (l, r) = (grid[k - 1], grid[k]);
        l.1 + (r.1 - l.1) * (w - l.0) / (r.0 - l.0)
    };
    let mut wn = (c33 / (m33 + a33(0.2))).sqrt();
    for _ in 0..50 {
        wn = (c33 / (m33 + a33(wn))).sqrt();
    }
    let rao = &got.rao;
    let peak = (0..rao.omegas.len())
        .max_by(|&a, &b| {
            rao.values[a][0][2]
                .norm()
                .total_cmp(&rao.values[b][0][2].norm())
        })
        .unwrap();
    let wp = rao.omegas[peak];
    let spacing = (rao.omegas[(peak + 1).min(rao.omegas.len() - 1)] - wp)
        .max(wp - rao.omegas[peak.saturating_sub(1)]);
    eprintln!(
        "heave: natural period {:.2} s (omega_n {wn:.4} rad/s, A33 {:.4e} kg, M33 {m33:.4e} \
         kg, C33 {c33:.4e} N/m); |xi3| peaks at {wp:.4} rad/s ({:.2} s) with {:.2} m/m; grid \
         spacing {spacing:.4} rad/s",
        2.0 * std::f64::consts::PI / wn,
        a33(wn),
        2.0 * std::f64::consts::PI / wp,
        rao.values[peak][0][2].norm()
    );
    assert!((wp - wn).abs() <= spacing, "peak {wp} vs omega_n {wn}");
}

/// The numbers of a line `NAME = value` of NEMOH's Mesh/Hydrostatics.dat (the first `=`'s
/// value after `name`).
fn hydrostatics_value(text: &str, name: &str) -> f64 {
    let line = text.lines().find(|l| l.contains(name)).unwrap();
    let after = &line[line.find(name).unwrap() + name.len()..];
    let value = after
        .trim_start()
        .trim_start_matches('=')
        .split_whitespace()
        .next();
    value.unwrap().parse().unwrap()
}

/// The database's hydrostatics are the buoyancy's alone, about the origin: roll and pitch
/// rho g (I_wp + V z_B) with the displaced volume, the centre of buoyancy and the
/// waterplane area of NEMOH's own Mesh/Hydrostatics.dat (a file the import does not read),
/// the waterplane a circle (I_wp = A^2 / (4 pi)); heave rho g A_wp. Within 2e-5: the file's
/// z_B is written to 5 digits (-62.066 m).
#[test]
fn oc3_hydrostatics_are_the_buoyancys_alone() {
    let Some(dir) = oc3_dir_or_skip() else {
        return;
    };
    let text = std::fs::read_to_string(dir.join("Mesh/Hydrostatics.dat")).unwrap();
    let (v, zb, area) = (
        hydrostatics_value(&text, "Displacement"),
        hydrostatics_value(&text, "ZF"),
        hydrostatics_value(&text, "Waterplane area"),
    );
    let (rho, g) = (1025.0, 9.81);
    let i_wp = area * area / (4.0 * std::f64::consts::PI);
    let roll = rho * g * (i_wp + v * zb);
    let c = imported(&dir).first_order.hydrostatics;
    eprintln!(
        "OC3 hydrostatics about the origin: C44 {:.6e}, C55 {:.6e} vs rho g (I_wp + V z_B) \
         {roll:.6e}; C33 {:.6e} vs rho g A_wp {:.6e}",
        c[3][3],
        c[4][4],
        c[2][2],
        rho * g * area
    );
    for k in [3, 4] {
        assert!(
            ((c[k][k] - roll) / roll).abs() < 2e-5,
            "C{0}{0} {1} vs {roll}",
            k + 1,
            c[k][k]
        );
    }
    assert!(((c[2][2] - rho * g * area) / (rho * g * area)).abs() < 1e-5);
}

/// Two routes to the spar's RAOs agree: the import's (NEMOH's own equation with Kh.dat,
/// Inertia.dat and Badd.dat, moved to the origin) and a configuration's `[platform.motions]`
/// giving the same body as Inertia.dat (centre of gravity at the rotations' point, the
/// inertia about it), which adds the weight's restoring to the database's buoyancy.
#[test]
fn oc3_motions_from_a_configuration_are_the_imports() {
    let Some(dir) = oc3_dir_or_skip() else {
        return;
    };
    let data = imported(&dir);
    let import = nemoh::import(&dir, LIMIT).unwrap();
    let work = crate::wamit::temp_dir("oc3-motions");
    let json = work.join("oc3.json");
    import.database.save(&json).unwrap();
    let inertia = matrix(&dir.join("Mechanics/Inertia.dat"));
    let point = roll_point(&dir);
    let tensor: Vec<String> = (3..6)
        .map(|i| {
            let row: Vec<String> = (3..6).map(|j| format!("{:e}", inertia[i][j])).collect();
            format!("[{}]", row.join(", "))
        })
        .collect();
    let config = work.join("oc3.toml");
    std::fs::write(
        &config,
        format!(
            "[environment]\ngravity = 9.81\n\n\
             [sea]\nspectrum = \"jonswap\"\nhs = 4.0\ntp = 10.0\nband = [0.3, 1.5]\n\n\
             [run]\nduration = 600.0\n\n\
             [platform]\nstiffness = [[4.1e4, 0, 0], [0, 4.1e4, 0], [0, 0, 1.2e8]]\n\n\
             [platform.motions]\ncentre_of_gravity = [{:e}, {:e}, {:e}]\ninertia = [{}]\n\n\
             [drift]\nsource = \"database\"\nfile = \"oc3.json\"\n",
            point[0],
            point[1],
            point[2],
            tensor.join(", ")
        ),
    )
    .unwrap();
    let problem = slowdrift::problem::load(&config).unwrap();
    problem.check().unwrap();
    let motions = problem.first_order_motions().unwrap().unwrap();
    let mut worst: f64 = 0.0;
    for (n, row) in data.rao.values.iter().enumerate() {
        for (h, expected) in row.iter().enumerate() {
            let got = motions.rao.values[n][h];
            let scale = (0..6)
                .map(|d| expected[d].norm() * if d >= 3 { 100.0 } else { 1.0 })
                .fold(0.0, f64::max);
            for d in 0..6 {
                let unit = if d >= 3 { 100.0 } else { 1.0 };
                worst = worst.max((got[d] - expected[d]).norm() * unit / scale);
            }
        }
    }
    eprintln!("OC3: RAOs of [platform.motions] vs the import's, worst {worst:.2e}");
    assert!(worst < 1e-9, "{worst}");
}
