//! The embedded default platform's radiation-diffraction database (`tests/bem`)
//! against independent routes: the column solver where the pontoons and the draft no longer
//! matter, the platform's mass properties and the documented configuration.

use slowdrift::hydro::bidirectional::BidirectionalTable;
use slowdrift::hydro::columns::ColumnArray;
use slowdrift::hydro::default_platform;
use slowdrift::hydro::io::database::HydroDatabase;
use slowdrift::problem::default_problem;
use slowdrift::scenario::default::default_scenario;

fn database() -> HydroDatabase {
    default_platform::database().unwrap()
}

/// At 1.56 and 1.6 rad/s, the top of the frequencies taken from the radiation-diffraction
/// solution alone, the waves reach neither the pontoons (e^{-2 k 16 m} = 3e-6) nor the columns'
/// bottom, and the platform hardly moves: the bi-directional drift of every pair of headings
/// must be the column solver's (infinitely deep, fixed columns), phases included, within the
/// panels' discretisation error. This also checks the conjugation that takes Capytaine's
/// time convention to SlowDrift's: the wrong one flips every imaginary part.
#[test]
fn high_frequency_drift_is_the_column_solvers() {
    let db = database();
    let table = db.bidirectional_drift.as_ref().unwrap();
    let n = table
        .omegas
        .iter()
        .position(|&w| (w - 1.56).abs() < 1e-9)
        .expect("the table has 1.56 rad/s");
    assert!((table.omegas[n + 1] - 1.6).abs() < 1e-9);
    let scenario = default_scenario().unwrap();
    let array = ColumnArray::new(scenario.platform.columns.clone(), None).unwrap();
    let columns = BidirectionalTable::from_column_array(
        &array,
        &scenario.environment,
        &table.omegas[n..n + 2],
        &table.headings,
    )
    .unwrap();
    let nh = table.headings.len();
    for (m, dof) in (0..2).flat_map(|m| (0..3).map(move |dof| (m, dof))) {
        let mut largest: f64 = 0.0;
        let mut worst: f64 = 0.0;
        let mut worst_conjugated: f64 = 0.0;
        for p in 0..nh {
            for q in 0..nh {
                let (re, im) = (table.re[n + m][p][q][dof], table.im[n + m][p][q][dof]);
                let (cre, cim) = (columns.re[m][p][q][dof], columns.im[m][p][q][dof]);
                largest = largest.max(cre.hypot(cim));
                worst = worst.max((re - cre).hypot(im - cim));
                worst_conjugated = worst_conjugated.max((re - cre).hypot(im + cim));
            }
        }
        assert!(
            worst < 0.05 * largest,
            "omega {}, dof {dof}: BEM - columns {worst:.4e} against largest {largest:.4e}",
            table.omegas[n + m]
        );
        assert!(
            worst_conjugated > 0.3 * largest,
            "omega {}, dof {dof}: the check cannot tell the conjugate ({worst_conjugated:.4e})",
            table.omegas[n + m]
        );
    }
}

/// One platform, not two that drift apart: the configuration leaves the mass, yaw inertia
/// and added mass out, so the default run takes them from the database its drift comes
/// from, and says so. The numbers themselves are checked independently elsewhere: the mass
/// against the closed-form volume (`scenario::default`), the section integrals behind the
/// inertia against a grid integration and the added mass against a fresh Capytaine
/// solution (`tests/bem/test_bem.py`).
#[test]
fn the_default_runs_the_database_platform() {
    use slowdrift::problem::Origin;
    let db = database();
    let scenario = default_scenario().unwrap();
    let p = &scenario.platform;
    assert_eq!((p.mass, p.yaw_inertia, p.added_mass), (None, None, None));
    let inertia = slowdrift::problem::resolve(&scenario)
        .unwrap()
        .inertia()
        .unwrap();
    let mass = db.mass_properties.as_ref().unwrap();
    assert_eq!(
        (inertia.mass, inertia.yaw_inertia),
        (mass.mass, mass.yaw_inertia)
    );
    assert_eq!(inertia.added_mass, db.low_frequency_added_mass.unwrap());
    for origin in [&inertia.mass_origin, &inertia.added_mass_origin] {
        assert!(
            matches!(origin, Origin::Data { name, .. } if name.contains("default_platform.json")),
            "{origin}"
        );
    }
    assert!(inertia.notes.is_empty(), "{:?}", inertia.notes);
}

/// The default is resolved from precomputed data (no solver runs at start-up): the
/// bi-directional drift is the embedded table, read when a spread sea needs it.
#[test]
fn default_resolves_from_tables() {
    let problem = default_problem().unwrap();
    assert!(matches!(
        problem.hydro.bidirectional,
        Some(slowdrift::hydro::bidirectional::BidirectionalSource::Embedded { .. })
    ));
}
