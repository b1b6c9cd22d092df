//! The readers as fuzz targets: each takes one input (the file's text), reads it as the
//! program does, and goes on as far as the input allows: a configuration is checked
//! against its bounds, resolved (but for the column-array solver, whose work is bounded
//! and long), checked, its memory estimated and, when small, simulated for a few steps; a
//! case table's rows become cases on the default; a database is read alone and through a
//! configuration.

use super::{Outcome, Target};
use slowdrift::hydro::io::database::HydroDatabase;
use slowdrift::hydro::io::wamit::{
    read_added_mass_damping, read_difference_qtf, read_hydrostatics, read_mean_drift, WamitOptions,
};
use slowdrift::montecarlo::cases::parse_case_table;
use slowdrift::problem::{default_problem, resolve};
use slowdrift::scenario::default::DEFAULT_CONFIG_TOML;
use slowdrift::scenario::{file, limits, DriftSource};
use slowdrift::{MemoryEstimate, Problem, Simulation};
use std::path::Path;

/// Records of at most this size are made and stepped.
const SIMULATED_BYTES: f64 = 1.0e8;

fn done<T>(result: slowdrift::Result<T>) -> Outcome {
    Outcome::Done(result.map(|_| ()).map_err(|e| e.to_string()))
}

fn text(input: &[u8]) -> Result<&str, Outcome> {
    std::str::from_utf8(input).map_err(|e| Outcome::Done(Err(format!("not UTF-8: {e}"))))
}

/// A checked problem carried as far as it goes: its estimate, and a few steps when small.
/// An FMU-visible invariant is checked on the way: outputs given are finite.
fn exercise(problem: Problem) -> Outcome {
    if let Err(e) = problem.check() {
        return done::<()>(Err(e));
    }
    let estimate = match MemoryEstimate::of(&problem) {
        Ok(e) => e,
        Err(e) => return done::<()>(Err(e)),
    };
    if estimate.total() > SIMULATED_BYTES {
        return Outcome::Done(Ok(()));
    }
    let mut simulation = match Simulation::new(problem) {
        Ok(s) => s,
        Err(e) => return done::<()>(Err(e)),
    };
    for _ in 0..5 {
        if let Err(e) = simulation.step([0.0; 3]) {
            return done::<()>(Err(e));
        }
    }
    match simulation.outputs() {
        Ok(o) => {
            let values = o.position.iter().chain(&o.velocity).chain(&o.forces.wave);
            if values.clone().any(|v| !v.is_finite()) {
                return Outcome::Finding(format!("outputs given but not finite: {o:?}"));
            }
            Outcome::Done(Ok(()))
        }
        Err(e) => done::<()>(Err(e)),
    }
}

/// A small native database (3 frequencies x 4 headings with damping, a 2 x 2 QTF, a
/// bi-directional table), as JSON.
fn small_database() -> String {
    let mut drift = Vec::new();
    for h in [0.0, 0.5, 1.0, 1.5].map(|turns| turns * std::f64::consts::PI) {
        for w in [0.2, 0.8, 2.5] {
            drift.push(format!(
                "{{\"omega\": {w}, \"heading\": {h}, \"surge\": {}, \"sway\": 1.5e3, \"yaw\": -2.0e4, \
                 \"damping\": [[1.0e3, 0.0, 0.0], [0.0, 2.0e3, 0.0], [0.0, 0.0, 3.0e5]]}}",
                1.0e4 * w
            ));
        }
    }
    let pairs = "[[[1.0e3, 0.0, 0.0], [5.0e2, 1.0, 0.0]], [[5.0e2, -1.0, 0.0], [1.0e3, 0.0, 0.0]]]";
    format!(
        "{{\n\"format_version\": 1,\n\"name\": \"fuzz\",\n\"source\": \"seed\",\n\
         \"water_density\": 1025.0,\n\"gravity\": 9.80665,\n\
         \"mass_properties\": {{\"mass\": 1.0e7, \"yaw_inertia\": 1.0e10}},\n\
         \"low_frequency_added_mass\": [[1.0e6, 0.0, 0.0], [0.0, 1.0e6, 0.0], [0.0, 0.0, 1.0e9]],\n\
         \"stiffness\": null,\n\"drift\": [\n{}\n],\n\
         \"qtf\": {{\"omegas\": [0.2, 0.8], \"blocks\": [{{\"dof\": \"surge\", \"heading\": 0.0, \
         \"re\": [[2.0e3, 1.0e3], [1.0e3, 8.0e3]], \"im\": [[0.0, 5.0e2], [-5.0e2, 0.0]]}}]}},\n\
         \"bidirectional_drift\": {{\"omegas\": [0.2, 2.5], \"headings\": [0.0, 1.5], \
         \"re\": [{pairs}, {pairs}], \"im\": [{pairs}, {pairs}]}}\n}}\n",
        drift.join(",\n")
    )
}

pub fn configuration() -> Target {
    let spread = DEFAULT_CONFIG_TOML.replace(
        "\"long-crested\"",
        "\"cos-n\"\nspreading_exponent = 2.0\nn_directions = 5",
    );
    let seeds = vec![
        DEFAULT_CONFIG_TOML.to_string(),
        include_str!("../../data/example.toml").to_string(),
        spread.clone(),
        spread.replace("[model]\n", "[model]\nyaw_following = { headings = 8 }\n"),
        DEFAULT_CONFIG_TOML.replace(
            "source = \"default-platform\"",
            "source = \"columns\"\nomega_min = 0.2\nomega_max = 3.0\nn_omega = 20\nheading_step_deg = 30.0",
        ),
        DEFAULT_CONFIG_TOML.replace(
            "source = \"default-platform\"",
            "source = \"column-array\"\nn_omega = 10\nheading_step_deg = 45.0",
        ),
        DEFAULT_CONFIG_TOML.replace(
            "source = \"default-platform\"",
            "source = \"database\"\nfile = \"seed.json\"",
        ),
        DEFAULT_CONFIG_TOML.replace(
            "source = \"default-platform\"",
            "source = \"csv\"\nfile = \"seed.csv\"",
        ),
    ];
    Target {
        name: "configuration",
        seeds: seeds.into_iter().map(String::into_bytes).collect(),
        run: Box::new(|input, dir| {
            std::fs::write(dir.join("seed.json"), small_database()).unwrap();
            std::fs::write(
                dir.join("seed.csv"),
                "omega,beta_deg,surge,sway,yaw\n0.2,0,1e3,0,0\n3.0,0,9e3,0,0\n0.2,90,0,1e3,0\n3.0,90,0,9e3,0\n",
            )
            .unwrap();
            let text = match text(input) {
                Ok(t) => t,
                Err(o) => return o,
            };
            let scenario = match file::parse(text, "fuzz.toml", dir) {
                Ok(s) => s,
                Err(e) => return done::<()>(Err(e)),
            };
            if let Err(e) = limits::check_sizes(&scenario, Some(&scenario.hydro)) {
                return done::<()>(Err(e));
            }
            if let DriftSource::ColumnArray { .. } = scenario.hydro {
                return Outcome::Done(Ok(()));
            }
            match resolve(&scenario) {
                Ok(problem) => exercise(problem),
                Err(e) => done::<()>(Err(e)),
            }
        }),
    }
}

/// WAMIT files, tagged by their first line (`#1`, `#hst`, `#8`, `#12d`: the reader).
pub fn wamit() -> Target {
    let mut seeds = vec![
        "#1\n -0.100000E+01     1     1  8.526887E+03\n -0.100000E+01     6     6  6.273170E+09\n  0.126168E+01     1     1  8.526887E+03  1.621425E+04\n  0.126168E+01     6     6  4.626680E+06  1.621425E+04\n  0.628318E+01     1     1  8.000000E+03  2.000000E+04\n".to_string(),
        "#hst\n     1     1   0.000000E+00\n     3     3   1.000000E+03\n     6     6   0.000000E+00\n".to_string(),
        "#8\n  0.100000E+02  0.000000E+00  0.000000E+00  1  0.500000E+00  0.000000E+00  0.500000E+00  0.000000E+00\n  0.500000E+01  0.000000E+00  0.000000E+00  1  0.700000E+00  0.000000E+00  0.700000E+00  0.000000E+00\n  0.100000E+02  0.900000E+02  0.900000E+02  2  0.500000E+00  0.000000E+00  0.500000E+00  0.000000E+00\n".to_string(),
        "#12d\n    0.10000E+02    0.10000E+02    0.00000E+00    0.00000E+00    1    4.27149E-01    0.00000E+00    4.27149E-01    0.00000E+00\n    0.10000E+02    0.50000E+01    0.00000E+00    0.00000E+00    1    1.00000E-01    9.00000E+01    0.00000E+00    1.00000E-01\n    0.50000E+01    0.50000E+01    0.00000E+00    0.00000E+00    1    2.00000E-01    0.00000E+00    2.00000E-01    0.00000E+00\n".to_string(),
    ];
    // The start of the real OC4 files, when the shared data are here.
    let oc4 = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/data/wamit/oc4-semi");
    for (tag, ext) in [("1", "1"), ("hst", "hst"), ("12d", "12d")] {
        if let Ok(t) = std::fs::read_to_string(oc4.join(format!("marin_semi.{ext}"))) {
            let head: Vec<&str> = t.lines().take(120).collect();
            seeds.push(format!("#{tag}\n{}\n", head.join("\n")));
        }
    }
    Target {
        name: "wamit",
        seeds: seeds.into_iter().map(String::into_bytes).collect(),
        run: Box::new(|input, dir| {
            let (tag, body) = match input.iter().position(|&b| b == b'\n') {
                Some(k) => (&input[..k], &input[k + 1..]),
                None => (&b""[..], input),
            };
            let path = dir.join("fuzz.wamit");
            std::fs::write(&path, body).unwrap();
            let options = WamitOptions::default();
            match tag {
                b"#hst" => done(read_hydrostatics(&path, &options)),
                b"#8" => done(read_mean_drift(&path, &options).and_then(|d| {
                    let mut headings: Vec<f64> = d.blocks().iter().map(|b| b.heading).collect();
                    headings.sort_by(f64::total_cmp);
                    headings.dedup();
                    d.to_bidirectional_table([1, 2, 6])?;
                    d.to_drift_table(&headings, [1, 2, 6])
                })),
                b"#12d" => done(read_difference_qtf(&path, &options)),
                _ => done(read_added_mass_damping(&path, &options)),
            }
        }),
    }
}

pub fn case_table() -> Target {
    let base = default_problem().unwrap();
    let seeds = [
        include_str!("../../data/spread_fig16.csv"),
        include_str!("../../data/spread_table1.csv"),
        include_str!("../../data/study_cd.csv"),
        include_str!("../../data/study_cd_slow.csv"),
        include_str!("../../data/study_current.csv"),
        "name,yaw_headings,n_directions,spreading_exponent,interaction\nyaw,12,,,\nspread,,5,2,mean-direction\n",
    ];
    Target {
        name: "case_table",
        seeds: seeds.iter().map(|s| s.as_bytes().to_vec()).collect(),
        run: Box::new(move |input, _| {
            let text = match text(input) {
                Ok(t) => t,
                Err(o) => return o,
            };
            let rows = match parse_case_table(text, "fuzz.csv") {
                Ok(rows) => rows,
                Err(e) => return done::<()>(Err(e)),
            };
            let mut last = Outcome::Done(Ok(()));
            for row in rows.iter().take(20) {
                let case = match row.case(&base, None, "fuzz.csv") {
                    Ok(c) => c,
                    Err(e) => {
                        last = done::<()>(Err(e));
                        continue;
                    }
                };
                let outcome = match case.problem.check() {
                    Ok(()) => {
                        done(MemoryEstimate::of(&case.problem).and_then(|e| e.check(&case.problem)))
                    }
                    Err(e) => done::<()>(Err(e)),
                };
                if let Outcome::Finding(_) = outcome {
                    return outcome;
                }
                last = outcome;
            }
            last
        }),
    }
}

pub fn database() -> Target {
    Target {
        name: "database",
        seeds: vec![small_database().into_bytes()],
        run: Box::new(|input, dir| {
            let text = match text(input) {
                Ok(t) => t,
                Err(o) => return o,
            };
            if let Err(e) = HydroDatabase::parse(text, "fuzz.json") {
                return done::<()>(Err(e));
            }
            std::fs::write(dir.join("fuzz.json"), text).unwrap();
            let config = DEFAULT_CONFIG_TOML
                .replace(
                    "\"long-crested\"",
                    "\"cos-n\"\nspreading_exponent = 2.0\nn_directions = 3",
                )
                .replace(
                    "source = \"default-platform\"",
                    "source = \"database\"\nfile = \"fuzz.json\"",
                );
            let scenario = file::parse(&config, "fuzz.toml", dir).unwrap();
            match resolve(&scenario) {
                Ok(problem) => exercise(problem),
                Err(e) => done::<()>(Err(e)),
            }
        }),
    }
}
