//! WAMIT files with several headings: `.8`/`.9` bi-directional rows into
//! the database's `bidirectional_drift`, and what is refused. The files are written here from
//! a closed form T(omega; beta1, beta2), Hermitian in the heading pair; the expected values are
//! that form, scaled by rho g by hand.

use crate::common::{base_problem, jonswap};
use crate::quirks::temp_dir;
use rustfft::num_complex::Complex64;
use slowdrift::forces::direction_pairs;
use slowdrift::hydro::io::database::HydroDatabase;
use slowdrift::hydro::io::wamit::{self, read_mean_drift, WamitOptions};
use slowdrift::model::Interaction;
use slowdrift::problem::Hydro;
use slowdrift::scenario::limits::DEFAULT_MEMORY_LIMIT as LIMIT;
use slowdrift::sea_state::{FrequencyGrid, Spreading};
use slowdrift::Simulation;
use std::f64::consts::PI;
use std::fmt::Write;
use std::path::Path;

const RHO: f64 = 1025.0;
const G: f64 = 9.80665;

/// A Hermitian closed form, nondimensional: real and symmetric magnitude in the heading
/// pair times e^{i (h(beta1) - h(beta2))}, so T(beta2, beta1) = conj T(beta1, beta2); the
/// diagonal is real (a uni-directional mean drift).
fn closed_form(dof: usize, omega: f64, b1: f64, b2: f64) -> Complex64 {
    let magnitude = match dof {
        1 => (1.0 + omega) * (b1.cos() + b2.cos()),
        2 => (1.0 + omega) * (b1.sin() + b2.sin()),
        _ => 3.0 * omega * (b1 - b2).cos() + (b1 + b2).sin(),
    };
    let h = |b: f64| 0.8 * omega * omega * b.sin();
    magnitude * Complex64::from_polar(1.0, h(b1) - h(b2))
}

/// A `.8` file on 3 periods and `headings` (deg): every uni-directional row and the
/// bi-directional rows with beta1 < beta2 only (the other order is Hermitian), unless
/// `both_orders`; the pairs in `skip` left out.
fn write_mean_drift(path: &Path, headings: &[f64], both_orders: bool, skip: &[(f64, f64)]) {
    let mut text = String::from(" header line of the test\n");
    for period in [20.0, 10.0, 5.0] {
        let omega = 2.0 * PI / period;
        for &h1 in headings {
            for &h2 in headings {
                if (!both_orders && h2 < h1) || skip.contains(&(h1, h2)) {
                    continue;
                }
                for dof in [1, 2, 6] {
                    let t = closed_form(dof, omega, h1.to_radians(), h2.to_radians());
                    writeln!(
                        text,
                        "{period} {h1} {h2} {dof} {:.9e} {:.7} {:.9e} {:.9e}",
                        t.norm(),
                        t.arg().to_degrees(),
                        t.re,
                        t.im
                    )
                    .unwrap();
                }
            }
        }
    }
    std::fs::write(path, text).unwrap();
}

#[test]
fn bidirectional_rows_fill_the_database_table_and_reach_a_spread_sea() {
    let dir = temp_dir("bidir");
    let headings = [-72.0, -36.0, 0.0, 36.0, 72.0];
    write_mean_drift(&dir.join("semi.8"), &headings, false, &[]);
    let options = WamitOptions::default();
    let mean = read_mean_drift(&dir.join("semi.8"), &options).unwrap();
    assert_eq!(mean.pairs().len(), 3 * 10);
    let table = mean.to_bidirectional_table([1, 2, 6]).unwrap().unwrap();
    let radians: Vec<f64> = headings.iter().map(|h: &f64| h.to_radians()).collect();
    assert_eq!(table.headings.len(), 5);
    for (p, &hp) in radians.iter().enumerate() {
        assert!((table.headings[p] - hp).abs() < 1e-12);
    }
    for (n, &omega) in table.omegas.iter().enumerate() {
        for (p, &bp) in radians.iter().enumerate() {
            for (q, &bq) in radians.iter().enumerate() {
                for (i, dof) in [1, 2, 6].into_iter().enumerate() {
                    let expected = closed_form(dof, omega, bp, bq) * RHO * G;
                    let got = Complex64::new(table.re[n][p][q][i], table.im[n][p][q][i]);
                    assert!(
                        (got - expected).norm() <= 1e-8 * (1.0 + expected.norm()),
                        "omega {omega}, ({p}, {q}), DOF {dof}: {got} vs {expected}"
                    );
                }
            }
        }
    }

    // The import puts it into the database; a spread sea on the table's headings takes its
    // cross terms from it, exactly at the nodes.
    let import = wamit::import(&dir.join("semi"), &options).unwrap();
    assert!(
        import
            .files
            .iter()
            .any(|l| l.contains("bi-directional drift on every pair")),
        "{:?}",
        import.files
    );
    let database = import.database;
    assert_eq!(database.bidirectional_drift.as_ref(), Some(&table));
    let json = dir.join("semi.json");
    database.save(&json).unwrap();
    assert_eq!(HydroDatabase::load(&json, LIMIT).unwrap(), database);

    let mut problem = base_problem(1200.0, 1.0, 3);
    problem.hydro = Hydro {
        qtf: None,
        bidirectional: database
            .bidirectional_drift
            .clone()
            .map(slowdrift::hydro::bidirectional::BidirectionalSource::Table),
        ..Hydro::from_drift(database.to_drift_table().unwrap())
    };
    problem.sea.spectrum = jonswap(3.0, 8.0);
    problem.sea.band = Some((0.4, 1.2));
    problem.sea.spreading = Spreading::CosN { n: 2.0 };
    problem.sea.n_directions = 5;
    problem.model.interaction = Interaction::Bidirectional;
    let directions = problem.sea.directions();
    let grid = FrequencyGrid::new(0.0, 1200.0, 0.5, (0.4, 1.2)).unwrap();
    let pairs = direction_pairs(&problem, &grid, &directions)
        .unwrap()
        .expect("cross terms");
    for (k, dk) in directions.iter().enumerate() {
        for (l, dl) in directions.iter().enumerate() {
            for (n, &omega) in pairs.omegas.iter().enumerate() {
                let on_node = radians.iter().any(|h| (h - dk.heading).abs() < 1e-9)
                    && radians.iter().any(|h| (h - dl.heading).abs() < 1e-9);
                if !on_node {
                    continue;
                }
                for (i, dof) in [1, 2, 6].into_iter().enumerate() {
                    let expected = closed_form(dof, omega, dk.heading, dl.heading) * RHO * G;
                    let got = pairs.get(n, k, l)[i];
                    assert!((got - expected).norm() <= 1e-8 * (1.0 + expected.norm()));
                }
            }
        }
    }
    let mut sim = Simulation::new(problem).expect("a spread sea on the imported table");
    sim.step([0.0; 3]).unwrap();
}

#[test]
fn missing_heading_pairs_are_listed_and_both_orders_must_agree() {
    let dir = temp_dir("bidir-missing");
    let headings = [0.0, 45.0, 90.0];
    write_mean_drift(&dir.join("a.8"), &headings, false, &[(0.0, 90.0)]);
    let mean = read_mean_drift(&dir.join("a.8"), &WamitOptions::default()).unwrap();
    let message = mean
        .to_bidirectional_table([1, 2, 6])
        .unwrap_err()
        .to_string();
    for dof in [1, 2, 6] {
        assert!(
            message.contains(&format!("DOF {dof} at (0.000, 90.000) deg"))
                && message.contains(&format!("DOF {dof} at (90.000, 0.000) deg")),
            "{message}"
        );
    }
    assert!(message.contains("6 of the 27"), "{message}");

    // Both orders given: the file's own values are kept and must be conjugates.
    write_mean_drift(&dir.join("b.8"), &headings, true, &[]);
    let mean = read_mean_drift(&dir.join("b.8"), &WamitOptions::default()).unwrap();
    assert_eq!(mean.pairs().len(), 3 * 6);
    assert!(mean.to_bidirectional_table([1, 2, 6]).unwrap().is_some());
    let text = std::fs::read_to_string(dir.join("b.8")).unwrap();
    // Flip the sign of the imaginary part of one (90, 0) surge row: no longer Hermitian.
    let row = text
        .lines()
        .find(|l| l.split_whitespace().take(4).collect::<Vec<_>>() == ["10", "90", "0", "1"])
        .unwrap()
        .to_string();
    let v: Vec<f64> = row.split_whitespace().map(|f| f.parse().unwrap()).collect();
    let flipped = format!(
        "10 90 0 1 {:.9e} {:.7} {:.9e} {:.9e}",
        v[4], -v[5], v[6], -v[7]
    );
    std::fs::write(dir.join("c.8"), text.replace(&row, &flipped)).unwrap();
    let mean = read_mean_drift(&dir.join("c.8"), &WamitOptions::default()).unwrap();
    let message = mean
        .to_bidirectional_table([1, 2, 6])
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("c.8") && message.contains("conj T(beta_p, beta_q)"),
        "{message}"
    );
}

/// A bi-directional QTF, Hermitian in the combined (frequency, heading) pair:
/// T(w2, w1; b2, b1) = conj T(w1, w2; b1, b2); nondimensional.
pub fn closed_form_qtf(dof: usize, w1: f64, w2: f64, b1: f64, b2: f64) -> Complex64 {
    let magnitude = match dof {
        1 => (0.5 + w1 * w2) * (b1.cos() + b2.cos()),
        2 => (0.5 + w1 * w2) * (b1.sin() + b2.sin()),
        _ => 2.0 * (w1 + w2) * (b1 - b2).cos() + 0.3 * (b1 + b2).sin(),
    };
    let phase = |w: f64, b: f64| 0.7 * w + 0.3 * w * w * b.sin();
    magnitude * Complex64::from_polar(1.0, phase(w1, b1) - phase(w2, b2))
}

/// A `.12d` file of `closed_form_qtf` on `periods` (s) and `headings` (deg): for beta1 =
/// beta2 one frequency triangle, for beta1 < beta2 every frequency pair, nothing for
/// beta1 > beta2 (Hermitian symmetry), the pairs `skip` left out.
pub fn write_bidirectional_qtf(
    path: &Path,
    periods: &[f64],
    headings: &[f64],
    skip: &[(f64, f64)],
) {
    let mut text = String::from(" a header\n");
    for (a, &h1) in headings.iter().enumerate() {
        for &h2 in &headings[a..] {
            if skip.contains(&(h1, h2)) {
                continue;
            }
            for (i, &p1) in periods.iter().enumerate() {
                for (j, &p2) in periods.iter().enumerate() {
                    if h1 == h2 && j > i {
                        continue;
                    }
                    for dof in [1, 2, 6] {
                        let t = closed_form_qtf(
                            dof,
                            2.0 * PI / p1,
                            2.0 * PI / p2,
                            h1.to_radians(),
                            h2.to_radians(),
                        );
                        writeln!(
                            text,
                            "{p1} {p2} {h1} {h2} {dof} {:.12e} {:.10} {:.12e} {:.12e}",
                            t.norm(),
                            t.arg().to_degrees(),
                            t.re,
                            t.im
                        )
                        .unwrap();
                    }
                }
            }
        }
    }
    std::fs::write(path, text).unwrap();
}

#[test]
fn a_qtf_with_several_heading_pairs_becomes_per_pair_blocks() {
    let dir = temp_dir("qtf-pairs");
    let periods = [20.0, 12.0, 9.0, 7.0];
    let headings = [-30.0, 0.0, 30.0];
    write_bidirectional_qtf(&dir.join("semi.12d"), &periods, &headings, &[]);
    let import = wamit::import(&dir.join("semi"), &WamitOptions::default()).unwrap();
    assert!(
        import
            .files
            .iter()
            .any(|l| l.contains("bi-directional blocks on every pair of the headings")),
        "{:?}",
        import.files
    );
    // Without a .8 or .9 the bi-directional drift is the QTF's diagonal of every pair.
    let table = import
        .database
        .bidirectional_drift
        .as_ref()
        .expect("from the QTF");
    assert_eq!(table.headings.len(), 3);
    for (n, &w) in table.omegas.iter().enumerate() {
        for (p, &bp) in table.headings.iter().enumerate() {
            for (q, &bq) in table.headings.iter().enumerate() {
                for (i, dof) in [1, 2, 6].into_iter().enumerate() {
                    let expected = closed_form_qtf(dof, w, w, bp, bq) * RHO * G;
                    let got = Complex64::new(table.re[n][p][q][i], table.im[n][p][q][i]);
                    assert!((got - expected).norm() <= 1e-9 * (1.0 + expected.norm()));
                }
            }
        }
    }
    let stored = import.database.qtf.as_ref().unwrap();
    // 3 uni-directional headings and 6 ordered pairs, 3 DOFs each.
    assert_eq!(stored.blocks.len(), 3 * 9);
    let json = dir.join("semi.json");
    import.database.save(&json).unwrap();
    let qtf = HydroDatabase::load(&json, LIMIT)
        .unwrap()
        .qtf
        .unwrap()
        .to_qtf();
    assert!(qtf.is_bidirectional());
    let omegas: Vec<f64> = qtf.omegas.clone();
    for &h1 in &headings {
        for &h2 in &headings {
            let (b1, b2) = (f64::to_radians(h1), f64::to_radians(h2));
            for (dof, wamit) in slowdrift::model::Dof::ALL.into_iter().zip([1, 2, 6]) {
                let block = qtf.pair_block(dof, (b1, b2), 1e-9).expect("every pair");
                assert_eq!(block.is_unidirectional(), h1 == h2);
                let n = omegas.len();
                for i in 0..n {
                    for j in 0..n {
                        let expected =
                            closed_form_qtf(wamit, omegas[i], omegas[j], b1, b2) * RHO * G;
                        let got = block.values[i * n + j];
                        assert!(
                            (got - expected).norm() <= 1e-9 * (1.0 + expected.norm()),
                            "({h1}, {h2}) DOF {wamit} ({i}, {j}): {got} vs {expected}"
                        );
                    }
                }
            }
        }
    }
    // One pair missing in both orders: every missing block is listed.
    write_bidirectional_qtf(&dir.join("gap.12d"), &periods, &headings, &[(-30.0, 30.0)]);
    let message = slowdrift::hydro::io::wamit::read_difference_qtf(
        &dir.join("gap.12d"),
        &WamitOptions::default(),
    )
    .unwrap_err()
    .to_string();
    for dof in [1, 2, 6] {
        assert!(
            message.contains(&format!("DOF {dof} at (-30.000, 30.000) deg"))
                && message.contains(&format!("DOF {dof} at (30.000, -30.000) deg")),
            "{message}"
        );
    }
    assert!(message.contains("6 of the 27"), "{message}");
}
