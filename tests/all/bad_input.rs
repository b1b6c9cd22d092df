//! Every invalid input is refused with a typed `slowdrift::Error` that names the field and
//! the value, never a panic; a running simulation refuses bad inputs and keeps its state.

use crate::common::*;
use slowdrift::hydro::{DriftRow, DriftTable};
use slowdrift::sea_state::{Spectrum, Spreading};
use slowdrift::{Error, Problem, Simulation};

fn valid_problem() -> Problem {
    base_problem(200.0, 1.0, 1)
}

/// `Simulation::new` must fail with `InvalidValue` naming `field` and `value`, and the
/// message must show both.
fn refused(problem: Problem, field: &str, value: &str) -> Error {
    let err = Simulation::new(problem).expect_err("must be refused");
    match &err {
        Error::InvalidValue {
            field: f, value: v, ..
        } => {
            assert_eq!(f, field, "{err}");
            assert_eq!(v, value, "{err}");
        }
        other => panic!("expected InvalidValue for {field}, got {other:?}"),
    }
    let text = err.to_string();
    assert!(text.contains(field) && text.contains(value), "{text}");
    err
}

fn with(edit: impl FnOnce(&mut Problem)) -> Problem {
    let mut c = valid_problem();
    edit(&mut c);
    c
}

#[test]
fn the_base_configuration_is_accepted() {
    assert!(Simulation::new(valid_problem()).is_ok());
}

#[test]
fn non_positive_sea_state_parameters_are_refused() {
    refused(with(|c| c.sea.spectrum = jonswap(0.0, 10.0)), "sea.hs", "0");
    refused(
        with(|c| c.sea.spectrum = jonswap(-2.0, 10.0)),
        "sea.hs",
        "-2",
    );
    refused(with(|c| c.sea.spectrum = jonswap(6.0, 0.0)), "sea.tp", "0");
    refused(
        with(|c| c.sea.spectrum = Spectrum::PiersonMoskowitz { hs: 6.0, tp: -1.5 }),
        "sea.tp",
        "-1.5",
    );
    let gamma = |g| {
        with(|c| {
            c.sea.spectrum = Spectrum::Jonswap {
                hs: 6.0,
                tp: 10.0,
                gamma: Some(g),
            }
        })
    };
    refused(gamma(0.5), "sea.gamma", "0.5");
    // A_gamma = 1 - 0.287 ln(gamma) <= 0 above 32.6: the spectrum would turn negative.
    refused(gamma(40.0), "sea.gamma", "40");
    assert!(
        Simulation::new(gamma(1.0)).is_ok(),
        "gamma = 1 is PM-like, valid"
    );
}

/// A duration whose records could not be allocated is a clear error, not an abort.
#[test]
fn an_absurd_block_is_refused() {
    refused(
        with(|c| c.run.block_duration = 1.0e12),
        "run.block_duration",
        "1e12",
    );
    refused(
        with(|c| c.run.block_duration = 10.0),
        "run.block_duration",
        "10",
    );
}

#[test]
fn non_positive_platform_and_run_parameters_are_refused() {
    refused(with(|c| c.platform.mass = Some(0.0)), "platform.mass", "0");
    refused(
        with(|c| c.platform.mass = Some(-1.0e7)),
        "platform.mass",
        "-1e7",
    );
    refused(
        with(|c| c.platform.yaw_inertia = Some(0.0)),
        "platform.yaw_inertia",
        "0",
    );
    refused(with(|c| c.run.time_step = 0.0), "run.time_step", "0");
    refused(with(|c| c.run.time_step = -1.0), "run.time_step", "-1");
    refused(with(|c| c.run.duration = 0.0), "run.duration", "0");
    refused(with(|c| c.run.duration = -100.0), "run.duration", "-100");
    refused(
        with(|c| c.platform.added_mass = Some([[-1.0e7, 0.0, 0.0], [0.0; 3], [0.0; 3]])),
        "platform.added_mass",
        "[[-1e7, 0, 0], [0, 0, 0], [0, 0, 0]]",
    );
}

#[test]
fn non_finite_values_are_refused() {
    let nan = f64::NAN;
    let inf = f64::INFINITY;
    refused(
        with(|c| c.sea.spectrum = jonswap(nan, 10.0)),
        "sea.hs",
        "NaN",
    );
    refused(
        with(|c| c.sea.spectrum = jonswap(6.0, inf)),
        "sea.tp",
        "inf",
    );
    refused(
        with(|c| {
            c.sea.spectrum = Spectrum::Jonswap {
                hs: 6.0,
                tp: 10.0,
                gamma: Some(nan),
            }
        }),
        "sea.gamma",
        "NaN",
    );
    refused(
        with(|c| {
            c.sea.spectrum = Spectrum::Tabulated {
                omega: vec![0.3, 0.6, 0.9],
                density: vec![1.0, nan, 1.0],
            }
        }),
        "sea.density[1]",
        "NaN",
    );
    refused(
        with(|c| c.sea.mean_direction = inf),
        "sea.direction_deg",
        "inf",
    );
    refused(
        with(|c| c.platform.mass = Some(nan)),
        "platform.mass",
        "NaN",
    );
    refused(
        with(|c| c.platform.yaw_inertia = Some(inf)),
        "platform.yaw_inertia",
        "inf",
    );
    refused(
        with(|c| {
            let mut a = [[0.0; 3]; 3];
            a[2][1] = nan;
            c.platform.added_mass = Some(a)
        }),
        "platform.added_mass[2][1]",
        "NaN",
    );
    refused(
        with(|c| c.platform.stiffness[1][2] = -inf),
        "platform.stiffness[1][2]",
        "-inf",
    );
    refused(
        with(|c| c.platform.linear_damping[0][0] = nan),
        "platform.linear_damping[0][0]",
        "NaN",
    );
    refused(
        with(|c| c.platform.quadratic_damping[2][2] = inf),
        "platform.quadratic_damping[2][2]",
        "inf",
    );
    refused(with(|c| c.current.speed = nan), "current.speed", "NaN");
    refused(
        with(|c| c.current.direction = inf),
        "current.direction_deg",
        "inf",
    );
    refused(with(|c| c.run.start_time = nan), "run.start_time", "NaN");
    refused(with(|c| c.run.duration = f64::NAN), "run.duration", "NaN");
    // An infinite duration is an open-ended run (the records stream block by block).
    assert!(Simulation::new(with(|c| c.run.duration = inf)).is_ok());
    refused(
        with(|c| c.initial.position[2] = nan),
        "initial.heading_deg",
        "NaN",
    );
    refused(
        with(|c| c.initial.velocity[0] = -inf),
        "initial.velocity[0]",
        "-inf",
    );
}

/// Rows of a 3 x 3 table: headings 0, 10, 20 deg, omegas 0.5, 1.0, 1.5.
fn small_rows() -> Vec<DriftRow> {
    let mut rows = Vec::new();
    for ih in 0..3 {
        for iw in 1..=3 {
            rows.push(DriftRow {
                omega: 0.5 * iw as f64,
                heading: (10.0 * ih as f64).to_radians(),
                drift: [1.0, 2.0, 3.0],
                damping: None,
            });
        }
    }
    rows
}

fn table_refused(rows: &[DriftRow], field: &str, value: &str, reason: &str) {
    let err = DriftTable::from_rows(rows).expect_err("must be refused");
    let text = err.to_string();
    match &err {
        Error::InvalidValue {
            field: f, value: v, ..
        } => {
            assert_eq!((f.as_str(), v.as_str()), (field, value), "{text}");
        }
        other => panic!("expected InvalidValue, got {other:?}"),
    }
    assert!(
        text.contains(field) && text.contains(value) && text.contains(reason),
        "{text}"
    );
}

#[test]
fn malformed_drift_tables_are_refused() {
    assert!(DriftTable::from_rows(&small_rows()).is_ok());
    table_refused(&[], "drift.rows", "[]", "empty");

    let mut rows = small_rows();
    rows[4].drift[1] = f64::NAN;
    table_refused(&rows, "drift.rows[4].drift[1]", "NaN", "finite");
    let mut rows = small_rows();
    rows[7].omega = f64::INFINITY;
    table_refused(&rows, "drift.rows[7].omega", "inf", "finite");
    let mut rows = small_rows();
    rows[2].heading = f64::NAN;
    table_refused(&rows, "drift.rows[2].heading", "NaN", "finite");
    let mut rows = small_rows();
    rows[0].omega = 0.0;
    table_refused(&rows, "drift.rows[0].omega", "0", "greater than zero");

    // A hole at a later heading: (1.0 rad/s, 20 deg) missing.
    let mut rows = small_rows();
    rows.remove(7);
    table_refused(
        &rows,
        "drift.rows",
        "omega = 1, heading = 20.000 deg",
        "hole",
    );
    // A hole at the first heading: 1.0 rad/s exists only at the other headings.
    let mut rows = small_rows();
    rows.remove(1);
    table_refused(&rows, "drift.rows[3].omega", "1", "hole");

    // Unsorted frequencies within a heading (rows 3 and 4 swapped: 1.0 after 0.5 -> 0.5
    // after 1.0 is not increasing).
    let mut rows = small_rows();
    rows.swap(3, 4);
    table_refused(&rows, "drift.rows[4].omega", "0.5", "not increasing");
    // A duplicated frequency.
    let mut rows = small_rows();
    rows.insert(5, rows[4].clone());
    table_refused(&rows, "drift.rows[5].omega", "1", "duplicated");

    // Two frequencies of one heading closer than the matching tolerance (1e-9 relative):
    // each matches a frequency of the first heading, but they cannot pair up in order.
    let mut rows = small_rows();
    let near = DriftRow {
        omega: 1.0 + 1e-10,
        ..rows[7].clone()
    };
    rows.insert(8, near);
    table_refused(
        &rows,
        "drift.rows",
        "heading = 20.000 deg",
        "closer than the matching tolerance",
    );

    // Damping on some rows only.
    let mut rows = small_rows();
    rows[6].damping = Some([[0.0; 3]; 3]);
    table_refused(&rows, "drift.rows[6].damping", "present", "every row");
}

/// Rows given heading by heading in any order land on their own (frequency, heading) node.
#[test]
fn drift_rows_in_any_heading_order_land_on_their_nodes() {
    let value = |ih: usize, iw: usize| [ih as f64, iw as f64, (10 * ih + iw) as f64];
    let mut rows = Vec::new();
    for ih in [2, 0, 1] {
        for iw in 0..3 {
            rows.push(DriftRow {
                omega: 0.5 * (iw + 1) as f64,
                heading: (10.0 * ih as f64).to_radians(),
                drift: value(ih, iw),
                damping: None,
            });
        }
    }
    let table = DriftTable::from_rows(&rows).unwrap();
    assert_eq!(table.headings().len(), 3);
    for (ih, &h) in table.headings().iter().enumerate() {
        assert!((h - (10.0 * ih as f64).to_radians()).abs() < 1e-15);
        for iw in 0..3 {
            assert_eq!(table.drift_at_node(ih, iw), value(ih, iw));
        }
    }
}

#[test]
fn a_drift_table_that_misses_the_wave_band_or_heading_is_refused() {
    // Table 0.5 .. 1.5 rad/s; the default band for Tp = 10 s is 0.31 .. 2.51 rad/s.
    let mut full_circle = Vec::new();
    for ih in 0..36 {
        for iw in 1..=3 {
            full_circle.push(DriftRow {
                omega: 0.5 * iw as f64,
                heading: (10.0 * ih as f64).to_radians(),
                drift: [1.0, 0.0, 0.0],
                damping: None,
            });
        }
    }
    let err = refused(
        with(|c| c.hydro.drift = DriftTable::from_rows(&full_circle).unwrap()),
        "drift.omega",
        "[0.5, 1.5] rad/s",
    );
    assert!(err.to_string().contains("wave band"), "{err}");

    // Headings 0 .. 20 deg only (not periodic); waves towards 90 deg.
    // Frequencies 0.1 .. 3.0 rad/s cover the band.
    let mut rows = Vec::new();
    for ih in 0..3 {
        for k in 1..=30 {
            rows.push(DriftRow {
                omega: 0.1 * k as f64,
                heading: (10.0 * ih as f64).to_radians(),
                drift: [1.0, 0.0, 0.0],
                damping: None,
            });
        }
    }
    let narrow = DriftTable::from_rows(&rows).unwrap();
    assert_eq!(narrow.headings().len(), 3);
    let mut c = with(|c| c.hydro.drift = narrow.clone());
    c.sea.mean_direction = 90f64.to_radians();
    // Named as the sea's direction, which the user sets, with the data's headings.
    let err = refused(c, "sea.direction_deg", "90");
    assert!(
        err.to_string()
            .contains("(90 deg) are outside the drift data's headings 0 .. 20 deg"),
        "{err}"
    );
    // The same table serves waves inside its headings.
    let mut c = with(|c| c.hydro.drift = narrow);
    c.sea.mean_direction = 15f64.to_radians();
    assert!(Simulation::new(c).is_ok());
}

#[test]
fn zero_directions_with_spreading_are_refused() {
    let c = with(|c| {
        c.sea.spreading = Spreading::CosN { n: 2.0 };
        c.sea.n_directions = 0;
    });
    refused(c, "sea.n_directions", "0");
    let c = with(|c| c.sea.spreading = Spreading::CosN { n: 0.0 });
    refused(c, "sea.spreading_exponent", "0");
}

#[test]
fn a_time_step_too_large_for_the_wave_band_is_refused() {
    // Band top 4 wp = 2.51 rad/s; records at h/2 have Nyquist 2 pi / h: h = 3 s is too long.
    let err = refused(with(|c| c.run.time_step = 3.0), "run.time_step", "3");
    assert!(err.to_string().contains("Nyquist"), "{err}");
    assert!(Simulation::new(with(|c| c.run.time_step = 2.0)).is_ok());
}

/// A time before the run's start has no records: a restore there is refused, naming it.
#[test]
fn a_time_before_the_start_is_refused_and_keeps_the_state() {
    let mut c = base_problem(50.0, 1.0, 4);
    c.run.start_time = 100.0;
    let mut sim = Simulation::new(c).unwrap();
    sim.step([0.0; 3]).unwrap();
    let before = sim.snapshot();
    let mut early = sim.snapshot().to_bytes();
    early[..8].copy_from_slice(&50.0f64.to_le_bytes());
    let early = slowdrift::Snapshot::from_bytes(&early).unwrap();
    match sim.restore(&early) {
        Err(e @ Error::BeforeStart { .. }) => {
            assert!(
                e.to_string()
                    .contains("before the start of the run (100 s)"),
                "{e}"
            )
        }
        other => panic!("expected BeforeStart, got {other:?}"),
    }
    assert_eq!(sim.snapshot(), before);
}

#[test]
fn non_finite_external_forces_are_refused_and_keep_the_state() {
    let mut sim = Simulation::new(valid_problem()).unwrap();
    for _ in 0..5 {
        sim.step([1.0e5, 0.0, 0.0]).unwrap();
    }
    let before = sim.snapshot();
    for (i, bad) in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY]
        .into_iter()
        .enumerate()
    {
        let mut force = [1.0, 2.0, 3.0];
        force[i] = bad;
        let field = format!("external_force[{i}]");
        for result in [sim.step(force), sim.advance(2.5, force)] {
            let err = result.expect_err("non-finite force must be refused");
            match &err {
                Error::NonFiniteInput { field: f, value } => {
                    assert_eq!(f, &field);
                    assert!(value.is_nan() == bad.is_nan() && (bad.is_nan() || *value == bad));
                }
                other => panic!("expected NonFiniteInput, got {other:?}"),
            }
            let text = err.to_string();
            assert!(
                text.contains(&field) && text.contains(&bad.to_string()),
                "{text}"
            );
            assert_eq!(sim.snapshot(), before);
        }
    }
    // Still usable afterwards.
    sim.step([0.0; 3]).unwrap();
}

#[test]
fn non_positive_advance_intervals_are_refused() {
    let mut sim = Simulation::new(valid_problem()).unwrap();
    sim.step([0.0; 3]).unwrap();
    let before = sim.snapshot();
    for (interval, text) in [
        (0.0, "0"),
        (-1.0, "-1"),
        (f64::NAN, "NaN"),
        (f64::INFINITY, "inf"),
    ] {
        let err = sim
            .advance(interval, [0.0; 3])
            .expect_err("must be refused");
        match &err {
            Error::InvalidValue { field, value, .. } => {
                assert_eq!((field.as_str(), value.as_str()), ("interval", text));
            }
            other => panic!("expected InvalidValue, got {other:?}"),
        }
        assert!(err.to_string().contains("interval"), "{err}");
        assert_eq!(sim.snapshot(), before);
    }
}

/// Times a double cannot resolve to a millionth of a step are refused: doubles near t are
/// spaced |t| 2^-52 apart, so with h = 1 s times beyond 2^52 x 1e-6 s = 4.5e9 s (143
/// years) are too coarse. A start time of 1e16 s (where doubles are 2 s apart) and a run
/// that ends past the limit are refused naming the setting; a run just inside is accepted;
/// an open-ended run restored at 5e9 s cannot go on.
#[test]
fn times_a_double_cannot_resolve_are_refused() {
    let limit = 2f64.powi(52) * 1e-6;
    let err = refused(with(|c| c.run.start_time = 1e16), "run.start_time", "1e16");
    assert!(
        err.to_string().contains("resolves time only to 2.22"),
        "{err}"
    );
    refused(
        with(|c| {
            c.run.start_time = limit - 100.0;
            c.run.duration = 200.0;
        }),
        "run.duration",
        "200",
    );
    let mut sim = Simulation::new(with(|c| {
        c.run.start_time = limit - 300.0;
        c.run.duration = f64::INFINITY;
    }))
    .unwrap();
    sim.step([0.0; 3]).unwrap();
    // A state at 5e9 s (origin 5e9, no steps), restored: its segment is refused.
    let mut bytes = sim.snapshot().to_bytes();
    bytes[..8].copy_from_slice(&5e9f64.to_le_bytes());
    bytes[8..16].copy_from_slice(&0u64.to_le_bytes());
    let far = slowdrift::Snapshot::from_bytes(&bytes).unwrap();
    match sim.restore(&far) {
        Err(Error::TimeUnresolved { time, step }) => assert_eq!((time, step), (5e9, 1.0)),
        other => panic!("{other:?}"),
    }
}
