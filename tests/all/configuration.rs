//! A configuration file through `problem::resolve` and `Problem::check`: what the files its
//! `[drift]` names give (CSV tables and databases read relative to it, their errors at their
//! own lines), and the checks of its values named where the file wrote them. Reading the
//! file itself is tested beside the reader (`scenario::file`).

use slowdrift::error::Result;
use slowdrift::hydro::bidirectional::{BidirectionalSource, BidirectionalTable};
use slowdrift::hydro::io::database::{
    DriftPoint, HydroDatabase, QtfData, QtfMatrix, FORMAT_VERSION,
};
use slowdrift::model::{Dof, SecondOrder};
use slowdrift::problem::{resolve, Origin, Problem};
use slowdrift::scenario::file::parse;
use slowdrift::Error;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// A file with only the required keys (the file's lines are the tests' line numbers).
const MINIMAL: &str = include_str!("../data/minimal.toml");

/// The text parsed, resolved and checked, as a simulation would take it.
fn problem(text: &str, base_dir: &Path) -> Result<Problem> {
    let problem = resolve(&parse(text, "test.toml", base_dir)?)?;
    problem.check()?;
    Ok(problem)
}

fn parse_text(text: &str) -> Result<Problem> {
    problem(text, Path::new("."))
}

/// The 1-based line of the first line of `text` that starts with `key`.
fn key_line(text: &str, key: &str) -> usize {
    text.lines()
        .position(|l| l.starts_with(key))
        .expect("key present")
        + 1
}

fn error_text(text: &str) -> String {
    parse_text(text).expect_err("must be refused").to_string()
}

/// A file under the temporary directory whose name no other test uses.
fn temp_file(stem: &str, contents: &str) -> PathBuf {
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let unique = COUNTER.fetch_add(1, Ordering::Relaxed);
    let path = std::env::temp_dir().join(format!(
        "slowdrift-config-{}-{unique}-{stem}",
        std::process::id()
    ));
    std::fs::write(&path, contents).expect("temporary file is writable");
    path
}

/// MINIMAL with its drift section replaced by a CSV source.
fn minimal_with_csv(csv: &Path) -> String {
    let head = MINIMAL
        .split("[drift]")
        .next()
        .expect("MINIMAL has a drift section");
    format!(
        "{head}[drift]\nsource = \"csv\"\nfile = {:?}\n",
        csv.display().to_string()
    )
}

#[test]
fn negative_hs_is_refused_by_validation() {
    let text = MINIMAL.replace("hs = 2.0", "hs = -1");
    assert!(
        error_text(&text).starts_with("test.toml:4: invalid [sea] hs = -1: "),
        "{}",
        error_text(&text)
    );
}

#[test]
fn gamma_below_one_is_refused() {
    let text = MINIMAL.replace(
        "spectrum = \"pierson-moskowitz\"",
        "spectrum = \"jonswap\"\ngamma = 0.5",
    );
    let expected = format!(
        "test.toml:{}: invalid [sea] gamma = 0.5: ",
        key_line(&text, "gamma")
    );
    assert!(
        error_text(&text).starts_with(&expected),
        "{}",
        error_text(&text)
    );
}

#[test]
fn nan_is_refused() {
    let text = MINIMAL.replace("tp = 8.0", "tp = nan");
    let expected = format!(
        "test.toml:{}: invalid [sea] tp = NaN: ",
        key_line(&text, "tp")
    );
    assert!(
        error_text(&text).starts_with(&expected),
        "{}",
        error_text(&text)
    );
    let text = MINIMAL.replace("mass = 1.0e7", "mass = nan");
    let expected = format!(
        "test.toml:{}: invalid [platform] mass = NaN: ",
        key_line(&text, "mass")
    );
    assert!(
        error_text(&text).starts_with(&expected),
        "{}",
        error_text(&text)
    );
}

/// Without an added mass in the file or the data, a problem's is zero, and says so.
#[test]
fn an_added_mass_given_nowhere_is_zero() {
    let inertia = parse_text(MINIMAL).expect("valid file").inertia().unwrap();
    assert_eq!(inertia.added_mass, [[0.0; 3]; 3]);
    assert_eq!(inertia.added_mass_origin, Origin::Zero);
}

#[test]
fn csv_drift_table_is_read_relative_to_the_base_directory() {
    let csv = temp_file(
        "good.csv",
        "# invented numbers\nomega, beta_deg, surge, sway, yaw\n\n0.3, 0, 100, 0, 0\n2.0, 0, 900, 0, 0\n",
    );
    let dir = csv.parent().expect("temp dir");
    let name = csv
        .file_name()
        .expect("file name")
        .to_string_lossy()
        .to_string();
    let head = MINIMAL.split("[drift]").next().expect("drift section");
    let text = format!("{head}[drift]\nsource = \"csv\"\nfile = \"{name}\"\n");
    let mut from_csv = problem(&text, dir).expect("valid file");
    std::fs::remove_file(&csv).expect("remove temporary file");
    let inline = parse_text(MINIMAL).expect("valid file");
    // The same table; only the summary's description of where it came from differs.
    assert_eq!(
        from_csv.hydro.source,
        format!("the CSV drift table {}", csv.display())
    );
    from_csv.hydro.source = inline.hydro.source.clone();
    assert_eq!(from_csv, inline);
}

#[test]
fn malformed_csv_line_names_file_and_line() {
    let csv = temp_file(
        "bad.csv",
        "omega,beta_deg,surge,sway,yaw\n# comment\n0.3,0,100,0,0\n2.0,0,9oo,0,0\n",
    );
    let err = parse_text(&minimal_with_csv(&csv)).expect_err("malformed line");
    std::fs::remove_file(&csv).expect("remove temporary file");
    match &err {
        Error::Parse {
            path,
            line,
            message,
        } => {
            assert_eq!(path, &csv.display().to_string());
            assert_eq!(*line, Some(4));
            assert!(
                message.contains("surge") && message.contains("9oo"),
                "{message}"
            );
        }
        other => panic!("expected a parse error, got {other:?}"),
    }
}

/// A CSV table cut inside its last number (no newline after it, fewer digits than the
/// line above: "9.0e2" cut to "9.0") is refused at that line; the same line ended by
/// a newline, or with as many digits, is whole.
#[test]
fn a_csv_cut_inside_its_last_number_is_refused() {
    let head = "omega,beta_deg,sway,yaw,surge\n0.3,0,0,0,1.0e2\n";
    for (tail, cut) in [
        ("2.0,0,0,0,9.0", true),
        ("2.0,0,0,0,9.0\n", false),
        ("2.0,0,0,0,9.0e2", false),
    ] {
        let csv = temp_file("cut.csv", &format!("{head}{tail}"));
        let result = parse_text(&minimal_with_csv(&csv));
        std::fs::remove_file(&csv).expect("remove temporary file");
        match (result, cut) {
            (Err(Error::Parse { line, message, .. }), true) => {
                assert_eq!(line, Some(3));
                assert!(message.contains("\"9.0\" has fewer digits"), "{message}");
            }
            (Ok(_), false) => {}
            (other, _) => panic!("{tail:?}: {other:?}"),
        }
    }
}

#[test]
fn csv_missing_a_column_names_it() {
    let csv = temp_file(
        "nosway.csv",
        "omega,beta_deg,surge,yaw\n0.3,0,100,0\n2.0,0,900,0\n",
    );
    let err = parse_text(&minimal_with_csv(&csv)).expect_err("missing column");
    std::fs::remove_file(&csv).expect("remove temporary file");
    assert!(
        matches!(&err, Error::Parse { line: Some(1), message, .. } if message.contains("\"sway\"")),
        "{err:?}"
    );
}

/// A database holding MINIMAL's drift table, made with `rho` and g = 9.80665.
fn database_with_minimal_drift(rho: f64) -> HydroDatabase {
    let point = |omega: f64, surge: f64| DriftPoint {
        omega,
        heading: 0.0,
        surge,
        sway: 0.0,
        yaw: 0.0,
        damping: None,
    };
    HydroDatabase {
        format_version: FORMAT_VERSION,
        name: "minimal".into(),
        source: "test".into(),
        water_density: rho,
        gravity: 9.80665,
        mass_properties: None,
        low_frequency_added_mass: None,
        stiffness: None,
        drift: vec![point(0.3, 100.0), point(2.0, 900.0)],
        qtf: None,
        bidirectional_drift: None,
        first_order: None,
        rao: None,
        provenance: Default::default(),
    }
}

/// A database's bi-directional table reaches the configuration; `bidirectional =
/// "column-array"` takes the solver instead, and refuses to shadow a table.
#[test]
fn database_bidirectional_drift_sources() {
    let json = temp_file("db-bidirectional.json", "");
    let dir = json.parent().expect("temp dir");
    let name = json.file_name().expect("file name").to_string_lossy();
    let head = MINIMAL.split("[drift]").next().expect("drift section");
    let text = format!("{head}[drift]\nsource = \"database\"\nfile = \"{name}\"\n");
    let with_columns = format!(
        "{head}[[platform.columns]]\nx = 20.0\ny = 0.0\ndiameter = 8.0\ndraft = 10.0\n\
         [drift]\nsource = \"database\"\nfile = \"{name}\"\nbidirectional = \"column-array\"\n"
    );
    let mut database = database_with_minimal_drift(1025.0);
    database.save(&json).expect("writable");
    let solver = problem(&with_columns, dir).expect("valid");
    let table = BidirectionalTable {
        omegas: vec![0.3, 2.0],
        headings: vec![0.0],
        re: vec![vec![vec![[1.0, 0.0, 0.0]]]; 2],
        im: vec![vec![vec![[0.0; 3]]]; 2],
    };
    database.bidirectional_drift = Some(table.clone());
    database.save(&json).expect("writable");
    let own = problem(&text, dir).expect("valid");
    let clash = problem(&with_columns, dir).expect_err("two sources");
    std::fs::remove_file(&json).expect("remove temporary file");
    assert!(matches!(
        solver.hydro.bidirectional,
        Some(BidirectionalSource::ColumnArray { ref omegas, .. }) if omegas == &[0.3, 2.0]
    ));
    assert_eq!(
        own.hydro.bidirectional,
        Some(BidirectionalSource::Table(table))
    );
    let message = clash.to_string();
    assert!(
        message.contains("bidirectional = \"column-array\"")
            && message.contains("own bidirectional_drift"),
        "{message}"
    );
}

#[test]
fn database_drift_is_read_relative_to_the_base_directory() {
    let json = temp_file("db.json", "");
    database_with_minimal_drift(1025.0)
        .save(&json)
        .expect("writable");
    let dir = json.parent().expect("temp dir");
    let name = json.file_name().expect("file name").to_string_lossy();
    let head = MINIMAL.split("[drift]").next().expect("drift section");
    let text = format!("{head}[drift]\nsource = \"database\"\nfile = \"{name}\"\n");
    let from_database = problem(&text, dir);

    database_with_minimal_drift(1000.0)
        .save(&json)
        .expect("writable");
    let mismatch = problem(&text, dir).expect_err("rho differs");
    std::fs::remove_file(&json).expect("remove temporary file");
    let mut from_database = from_database.expect("valid file");
    // The database has no body data, but it is named as their source.
    assert_eq!(from_database.hydro.body.name, json.display().to_string());
    from_database.hydro.body = Default::default();
    let inline = parse_text(MINIMAL).expect("valid file");
    assert!(from_database.hydro.source.starts_with("the database "));
    from_database.hydro.source = inline.hydro.source.clone();
    assert_eq!(from_database, inline);
    let message = mismatch.to_string();
    assert!(
        message.starts_with("test.toml:") && message.contains("water_density = 1000"),
        "{message}"
    );
}

/// MINIMAL with its drift from a database whose QTF spans `omegas` at `heading_deg`,
/// and `model` as the [model] section.
fn with_qtf_database(stem: &str, omegas: &[f64], heading_deg: f64, model: &str) -> Result<Problem> {
    let n = omegas.len();
    let mut database = database_with_minimal_drift(1025.0);
    database.qtf = Some(QtfData {
        omegas: omegas.to_vec(),
        blocks: Dof::ALL
            .into_iter()
            .map(|dof| QtfMatrix {
                dof,
                heading: heading_deg.to_radians(),
                second_heading: None,
                re: (0..n)
                    .map(|i| (0..n).map(|j| 1.0e3 * (1 + i + j) as f64).collect())
                    .collect(),
                im: (0..n)
                    .map(|i| (0..n).map(|j| 10.0 * (i as f64 - j as f64)).collect())
                    .collect(),
            })
            .collect(),
    });
    let json = temp_file(stem, "");
    database.save(&json).expect("writable");
    let dir = json.parent().expect("temp dir");
    let name = json.file_name().expect("file name").to_string_lossy();
    let head = MINIMAL.split("[drift]").next().expect("drift section");
    let text = format!("{head}{model}\n[drift]\nsource = \"database\"\nfile = \"{name}\"\n");
    let resolved = problem(&text, dir);
    std::fs::remove_file(&json).expect("remove temporary file");
    resolved
}

#[test]
fn full_qtf_mode_takes_the_database_qtf_and_names_what_is_missing() {
    // PM, Tp = 8 s: the default band is 0.39 .. 3.14 rad/s.
    let covering = [0.3, 1.0, 2.0, 3.5];
    let full = "[model]\nsecond_order = \"full-qtf\"\nqtf_tolerance = 1e-4";
    let full_qtf = with_qtf_database("qtf-ok.json", &covering, 0.0, full).expect("valid");
    assert_eq!(full_qtf.model.second_order, SecondOrder::FullQtf);
    assert_eq!(full_qtf.model.qtf_tolerance, 1e-4);
    assert_eq!(full_qtf.hydro.qtf.as_ref().map(|q| q.omegas.len()), Some(4));
    let defaults = with_qtf_database("qtf-default.json", &covering, 0.0, "").expect("valid");
    assert_eq!(defaults.model.second_order, SecondOrder::Newman);
    assert!(
        defaults.hydro.qtf.is_some(),
        "the QTF is carried even when unused"
    );

    let short = with_qtf_database("qtf-short.json", &[0.3, 1.0, 2.0], 0.0, full)
        .expect_err("band not covered")
        .to_string();
    assert!(short.contains("2.0000 .. 3.1416 rad/s"), "{short}");
    let heading = with_qtf_database("qtf-heading.json", &covering, 30.0, full)
        .expect_err("no QTF at 0 deg")
        .to_string();
    assert!(
        heading.contains("0.000 deg") && heading.contains("30.000 deg"),
        "{heading}"
    );
    let tolerance = "[model]\nsecond_order = \"full-qtf\"\nqtf_tolerance = 0.0";
    assert!(with_qtf_database("qtf-tol.json", &covering, 0.0, tolerance)
        .expect_err("zero tolerance")
        .to_string()
        .contains("[model] qtf_tolerance"));
    let newman = "[model]\nqtf_tolerance = 1e-4";
    assert!(with_qtf_database("qtf-newman.json", &covering, 0.0, newman)
        .expect_err("tolerance without full-qtf")
        .to_string()
        .contains("qtf_tolerance"));
    let no_qtf = MINIMAL.replace("[drift]", "[model]\nsecond_order = \"full-qtf\"\n\n[drift]");
    assert!(error_text(&no_qtf).contains("needs a QTF"));
}

#[test]
fn unreadable_csv_is_an_io_error() {
    let missing = std::env::temp_dir().join("slowdrift-config-no-such-file.csv");
    let err = parse_text(&minimal_with_csv(&missing)).expect_err("no file");
    assert!(matches!(err, Error::Io { .. }), "{err:?}");
}

/// The case table's wind columns set the wind of the base in the file's units (degrees for
/// `wind_direction_deg`), and a value the wind cannot take fails that case's check naming
/// the row and column.
#[test]
fn case_table_wind_columns_set_the_wind() {
    use slowdrift::model::WindSpectrumKind;
    use slowdrift::montecarlo::cases::parse_case_table;
    let wind = "[wind]\nspeed = 10.0\n\n[platform.wind]\nheight = 20.0\n\
                [[platform.wind.areas]]\nx = 0.0\ny = 0.0\nheight = 20.0\narea_x = 100.0\n\
                area_y = 100.0\nshape_coefficient = 1.0\n\n[drift]";
    let base = parse_text(&MINIMAL.replace("[drift]", wind)).expect("valid base");
    let table = "name, wind_speed, wind_direction_deg, wind_spectrum, wind_reference_height\n\
                 storm, 25, 90, kaimal, 20\n\
                 keep, , , , \n\
                 gale, -3, , , \n";
    let rows = parse_case_table(table, "cases.csv").expect("a valid table");
    let cases: Vec<_> = rows
        .iter()
        .map(|row| row.case(&base, None, "cases.csv").expect("a case"))
        .collect();
    let storm = &cases[0].problem.wind;
    assert_eq!(storm.speed, 25.0);
    assert_eq!(storm.direction, 90f64.to_radians());
    assert_eq!(storm.spectrum, WindSpectrumKind::Kaimal);
    assert_eq!(storm.reference_height, 20.0);
    cases[0].problem.check().expect("the storm case is valid");
    assert_eq!(cases[1].problem, base);
    let err = cases[2]
        .problem
        .check()
        .expect_err("a negative speed")
        .to_string();
    assert!(
        err.starts_with("cases.csv:4: invalid row 3, column 'wind_speed' = -3: must be at least 0"),
        "{err}"
    );
    let err = parse_case_table("wind_spectrum\nfroya\n", "cases.csv")
        .expect_err("not a spectrum")
        .to_string();
    assert_eq!(
        err,
        "cases.csv:2: row 1, column 'wind_spectrum': 'froya' is not one of configuration, npd, api, \
         harris, davenport, kaimal, ochi-shin, constant"
    );
}

/// `[platform.wind]` as a table (angles in degrees read as radians, the centre defaulting
/// to the origin) and as areas; a table key beside the areas, a missing table key and a
/// short coefficient row refused naming the key and its line; `[wind]` without
/// `[platform.wind]` refused naming the speed.
#[test]
fn platform_wind_coefficients_are_read_and_checked() {
    use slowdrift::wind::WindCoefficients;
    let table = "[platform.wind]\nheight = 30.0\nangle_deg = [-180.0, -90.0, 0.0, 90.0]\n\
                 cx = [-0.8, 0.0, 0.8, 0.0]\ncy = [0.0, -0.9, 0.0, 0.9]\n\
                 cmz = [0.0, 0.05, 0.0, -0.05]\narea_x = 2500.0\narea_y = 3000.0\n\
                 length = 90.0\n\n";
    let with = |block: &str| MINIMAL.replace("[drift]", &format!("{block}[drift]"));
    let problem = parse_text(&with(table)).unwrap();
    let load = problem.platform.wind.as_ref().unwrap();
    assert_eq!(load.height, 30.0);
    match &load.coefficients {
        WindCoefficients::Table(t) => {
            assert!((t.angles[1] + std::f64::consts::FRAC_PI_2).abs() < 1e-15);
            assert_eq!(t.centre, [0.0, 0.0]);
            assert_eq!(t.cmz[3], -0.05);
        }
        other => panic!("{other:?}"),
    }
    let areas = "[platform.wind]\nheight = 20.0\n[[platform.wind.areas]]\nx = 1.0\ny = 2.0\n\
                 height = 20.0\narea_x = 10.0\narea_y = 20.0\nshape_coefficient = 1.5\n\n";
    match &parse_text(&with(areas))
        .unwrap()
        .platform
        .wind
        .unwrap()
        .coefficients
    {
        WindCoefficients::Areas(a) => assert_eq!((a.len(), a[0].centre), (1, [1.0, 2.0])),
        other => panic!("{other:?}"),
    }
    let mixed = with(&areas.replace("height = 20.0\n[[", "height = 20.0\nlength = 5.0\n[["));
    let err = error_text(&mixed);
    assert!(
        err.contains("[platform] wind.length") && err.contains("not both"),
        "{err}"
    );
    let missing = with(&table.replace("length = 90.0\n", ""));
    assert!(error_text(&missing).contains("[platform] wind.length"));
    let short = with(&table.replace("cy = [0.0, -0.9, 0.0, 0.9]", "cy = [0.0, -0.9, 0.0]"));
    let err = error_text(&short);
    assert!(
        err.contains("[platform] wind.cy")
            && err.contains(&format!(":{}:", key_line(&short, "cy"))),
        "{err}"
    );
    let windy = MINIMAL.replace("[drift]", "[wind]\nspeed = 15.0\n\n[drift]");
    let err = error_text(&windy);
    assert!(
        err.contains("[wind] speed") && err.contains("[platform.wind]"),
        "{err}"
    );
}
