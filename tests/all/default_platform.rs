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
/// bi-directional drift is the embedded table, read when a spread sea needs it, and the
/// first-order motions are the embedded RAOs, which the run's summary names.
#[test]
fn default_resolves_from_tables() {
    let problem = default_problem().unwrap();
    assert!(matches!(
        problem.hydro.bidirectional,
        Some(slowdrift::hydro::bidirectional::BidirectionalSource::Embedded { .. })
    ));
    let motions = problem.first_order_motions().unwrap().unwrap();
    assert_eq!(motions.rao, database().rao.unwrap().to_rao());
    let summary = problem.summary().unwrap().join("\n");
    assert!(
        summary.contains("first-order motions: RAOs held by the embedded default_platform.json"),
        "{summary}"
    );
}

/// The embedded RAOs (the database's `rao`, tests/bem/make_database.py) in waves long
/// against the platform (90 m wide; k L = 0.015 at 0.04 rad/s, 0.09 at 0.1 rad/s), against
/// the long-wave limits of the moored floating body the data describe, which do not come
/// from the radiation-diffraction solution. Conventions (SlowDrift's): elevation
/// Re{e^{i (omega t - k (x cos b + y sin b))}} (deep water, k = omega^2 / g), motions
/// Re{xi e^{i omega t}} about the body origin on the waterplane, the heading b the
/// direction the waves travel towards, from +x; roll, pitch, yaw positive about +x, +y, +z.
///
/// - Surge and sway: the hull is uniformly dense (mass rho V), so the long wave's force
///   (rho V + A11) i omega u (u = omega cos b, the water's velocity) drives the same mass
///   M + A11 against the mooring, whose stiffness is set for a 200 s period with A11 at
///   0.04 rad/s (docs/bem.md): xi = -i omega^2 / (omega^2 - omega_s^2) (cos b, sin b),
///   omega_s = 2 pi / 200 s (unmoored: -i, the water particles' excursion). Checked at 0.04
///   and 0.06 rad/s within 3 %: the Froude-Krylov force is the mesh's volume's, within
///   0.3 % of V, which the near resonance amplifies 2.6 times at 0.04 rad/s.
/// - Heave follows the surface, xi_3 -> 1 (the mooring has no heave stiffness), within
///   (omega / omega_n)^2 = 0.03 and the excitation's long-wave shortfall (5 % together),
///   and lags it as a damped oscillator with the viscous damping the model states (5 % of
///   critical, B33 and omega_n = 0.2318 rad/s in tests/bem/platform_model.json):
///   tan(lag) = omega B33 / (C33 (1 - (omega / omega_n)^2)), C33 = rho g 4 pi r^2 of the
///   four columns (r = 10 m), within 1 % (the radiation damping, the excitation's own phase
///   and A33's change from omega_n to 0.04 rad/s are all small there). Under e^{-i omega t}
///   the lag would be a lead.
/// - Pitch and roll tilt with the surface: i k cos b and -i k sin b, at 0.1 rad/s within
///   10 % of k ((omega / omega_n)^2 = 0.12 with omega_n = 0.284 rad/s, partly cancelled by
///   the wave's moment on the pontoons; at 0.04 rad/s the surge's resonance still pulls
///   pitch through the added-mass coupling).
/// - Yaw: none (the platform has two vertical planes of symmetry, x and y).
///
/// A conjugated table (the other time convention) fails every imaginary part; headings
/// taken the other way round (-b) flip sway and roll; headings the waves come from (b +
/// pi) flip surge and pitch; 90 degrees off swaps surge and sway.
#[test]
fn embedded_raos_meet_the_long_wave_limits() {
    use rustfft::num_complex::Complex64;
    use std::f64::consts::PI;
    let db = database();
    let table = db.rao.as_ref().expect("the default platform holds RAOs");
    table.validate().unwrap();
    let rao = table.to_rao();
    let headings: Vec<f64> = (0..36).map(|h| (10.0 * h as f64).to_radians()).collect();
    assert_eq!(rao.headings.len(), headings.len());
    for (a, b) in rao.headings.iter().zip(&headings) {
        assert!((a - b).abs() < 1e-12, "headings {:?}", rao.headings);
    }
    let at = |w: f64| {
        rao.omegas
            .iter()
            .position(|&v| (v - w).abs() < 1e-9)
            .unwrap_or_else(|| panic!("no {w} rad/s in {:?}", rao.omegas))
    };
    let (rho, g) = (db.water_density, db.gravity);
    let i = Complex64::new(0.0, 1.0);
    let model: serde_json::Value =
        serde_json::from_str(include_str!("../bem/platform_model.json")).unwrap();
    let b33 = model["viscous_damping"][2][2].as_f64().unwrap();
    let omega_n = model["natural_frequencies"]["heave"].as_f64().unwrap();
    let radius = default_scenario().unwrap().platform.columns[0].diameter / 2.0;
    let c33 = rho * g * 4.0 * PI * radius * radius;
    let omega_s = 2.0 * PI / 200.0;
    let mut worst = [0.0_f64; 4];
    for (h, &b) in headings.iter().enumerate() {
        let (c, s) = (b.cos(), b.sin());
        for w in [0.04, 0.06] {
            let xi = rao.values[at(w)][h];
            let limit = -i * w * w / (w * w - omega_s * omega_s);
            let miss = ((xi[0] - limit * c).norm_sqr() + (xi[1] - limit * s).norm_sqr()).sqrt()
                / limit.norm();
            worst[0] = worst[0].max(miss);
            assert!(
                miss < 0.03,
                "{w} rad/s, {:.0} deg: surge {} sway {} vs {} (cos, sin)",
                b.to_degrees(),
                xi[0],
                xi[1],
                limit
            );
        }
        let w = 0.04;
        let xi = rao.values[at(w)][h];
        let oscillator = w * b33 / (c33 * (1.0 - (w / omega_n).powi(2)));
        let lag = (-xi[2].arg()).tan() / oscillator;
        worst[1] = worst[1].max((xi[2] - 1.0).norm());
        worst[2] = worst[2].max((lag - 1.0).abs());
        assert!((xi[2] - 1.0).norm() < 0.05, "{w} rad/s: heave {}", xi[2]);
        assert!(
            (lag - 1.0).abs() < 0.01,
            "{w} rad/s: heave {} lags by {lag:.4} of the oscillator's {oscillator:.5}",
            xi[2]
        );
        assert!(xi[5].norm() < 1e-3 * w * w / g, "{w} rad/s: yaw {}", xi[5]);
        let w = 0.1;
        let k = w * w / g;
        let xi = rao.values[at(w)][h];
        let miss = ((xi[3] + i * k * s).norm_sqr() + (xi[4] - i * k * c).norm_sqr()).sqrt() / k;
        worst[3] = worst[3].max(miss);
        assert!(
            miss < 0.1,
            "{w} rad/s, {:.0} deg: roll {} pitch {} vs k = {k}",
            b.to_degrees(),
            xi[3],
            xi[4]
        );
    }
    eprintln!(
        "embedded RAOs against the long-wave limits, worst over 36 headings: surge and sway \
         {:.2} %, heave {:.2} %, heave's lag {:.2} %, roll and pitch {:.2} % of k",
        100.0 * worst[0],
        100.0 * worst[1],
        100.0 * worst[2],
        100.0 * worst[3]
    );
}

/// The default platform is symmetric about x: in head seas its table's sway and yaw drift
/// are round-off (read off the table here, at heading 0, against the surge drift), and the
/// run makes no record of them and says so; 20 deg off head seas they are records, made.
#[test]
fn records_of_round_off_size_are_not_made_and_named() {
    use slowdrift::Simulation;
    let problem = default_problem().unwrap();
    let table = &problem.hydro.drift;
    let head = table
        .headings()
        .iter()
        .position(|&b| b.abs() < 1e-12)
        .unwrap();
    let largest = |i: usize| {
        (0..table.omegas().len()).fold(0.0f64, |m, w| m.max(table.drift_at_node(head, w)[i].abs()))
    };
    let gyration = {
        let inertia = problem.inertia().unwrap();
        (inertia.yaw_inertia / inertia.mass).sqrt()
    };
    assert!(largest(1) < 1e-10 * largest(0), "sway {:e}", largest(1));
    assert!(
        largest(2) / gyration < 1e-10 * largest(0),
        "yaw {:e}",
        largest(2)
    );
    let mut short = problem.clone();
    short.run.duration = 100.0;
    let sim = Simulation::new(short.clone()).unwrap();
    let line = sim.records_line();
    assert!(
        line.contains("not made") && line.contains("sway drift, yaw drift"),
        "{line}"
    );
    let force = &sim.records().wave_force;
    assert!(force[1].samples().is_empty() && force[2].samples().is_empty());
    assert!(force[0].samples().iter().any(|&f| f != 0.0));
    let mut oblique = short;
    oblique.sea.mean_direction = 20f64.to_radians();
    let sim = Simulation::new(oblique).unwrap();
    assert!(
        !sim.records_line().contains("drift"),
        "{}",
        sim.records_line()
    );
    let force = &sim.records().wave_force;
    assert!(force.iter().all(|f| f.samples().iter().any(|&v| v != 0.0)));
}
