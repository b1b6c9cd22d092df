//! WAMIT files with several headings (issue #13 part 1): `.8`/`.9` bi-directional rows into
//! the database's `bidirectional_drift`, and what is refused. The files are written here from
//! a closed form T(omega; beta1, beta2), Hermitian in the heading pair; the expected values are
//! that form, scaled by rho g by hand.

use crate::common::{base_config, jonswap};
use crate::quirks::temp_dir;
use rustfft::num_complex::Complex64;
use slowdrift::forces::direction_pairs;
use slowdrift::hydro::io::database::HydroDatabase;
use slowdrift::hydro::io::wamit::{read_mean_drift, WamitOptions};
use slowdrift::model::Interaction;
use slowdrift::problem::Hydro;
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
    let import = HydroDatabase::from_wamit(&dir.join("semi"), &options).unwrap();
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
    assert_eq!(HydroDatabase::load(&json).unwrap(), database);

    let mut problem = base_config(1200.0, 1.0, 3);
    problem.hydro = Hydro {
        drift: database.to_drift_table().unwrap(),
        qtf: None,
        bidirectional: database
            .bidirectional_drift
            .clone()
            .map(slowdrift::hydro::bidirectional::BidirectionalSource::Table),
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
