//! A campaign's cases as JSON for other masters (`slowdrift montecarlo --print-cases`): the
//! Dask package `fmu-pack/python/slowdrift_dask` reads its cases from here instead of
//! parsing the case table and the configuration a second time, so both paths share one
//! reader, its error messages and the per-case fingerprint.
//!
//! Per case: `name`, `fingerprint` ([`Case::fingerprint`]), `transient` (s from the start
//! of the run), `time_step` (s), `steps` (the RK4 steps of `montecarlo::run_seed`:
//! round(duration / time_step); the statistics use the samples at k time_step >= transient,
//! k = 0 ..= steps), and `fmu`: either `{"start_time", "stop_time", "parameters": {FMU
//! parameter name: value}}` (every parameter of modelDescription.xml except `seed`, which
//! the master sets per run; modes as their Integer codes) that makes `SlowDrift.fmu` run this
//! case exactly, or `{"unavailable": reason}`; and, for a case whose values the model
//! refuses, `refused`: the message every run of the case fails with (as the native tool
//! records it, naming the case-table cell or configuration key). Numbers are written in
//! their shortest round-trip form.
//!
//! The parameters are read off the case with the override table's getters; a case they do
//! not rebuild (applied to the base, as the FMU applies them) is unavailable.

use super::parameters::{Experiment, FmuValue, Parameters, HYDRO_DATABASE};
use crate::error::Error;
use crate::fmi2::model_description::VariableType;
use crate::montecarlo::Case;
use crate::scenario::overrides::{by_fmu, Value};
use crate::{Problem, Scenario};
use serde_json::{json, Map, Value as Json};
use std::io::Write;

/// The FMU parameter the master sets per run.
const SEED: &str = "seed";

/// Writes the JSON document of the cases `cases` yields, run on top of `base`, to `out`
/// one case at a time, so that its memory does not grow with the number of cases:
/// `{"format_version":1,"cases":[...]}` and a newline; `hydro_database` is the FMU's
/// `hydroDatabase` parameter that loads `base` (empty for the packed default platform).
/// The first case that is an error stops the document there, unfinished (a reader cannot
/// take it for a whole one), and is returned; nothing is written before the first case.
/// Write errors name `out_name`.
pub fn write_cases_json(
    out: &mut impl Write,
    out_name: &str,
    cases: impl IntoIterator<Item = crate::Result<Case>>,
    base: &Problem,
    hydro_database: &str,
) -> crate::Result<()> {
    let io = |e: std::io::Error| Error::Io {
        path: out_name.to_string(),
        message: e.to_string(),
    };
    let mut separator = "{\"format_version\":1,\"cases\":[";
    for case in cases {
        let document = case_json(&case?, base, hydro_database);
        out.write_all(separator.as_bytes()).map_err(io)?;
        serde_json::to_writer(&mut *out, &document).map_err(|e| io(e.into()))?;
        separator = ",";
    }
    if separator == "," {
        out.write_all(b"]}\n").map_err(io)?;
    } else {
        out.write_all(b"{\"format_version\":1,\"cases\":[]}\n")
            .map_err(io)?;
    }
    out.flush().map_err(io)
}

fn case_json(case: &Case, base: &Problem, hydro_database: &str) -> Json {
    let run = &case.problem.run;
    let steps = (run.duration / run.time_step).round();
    let fmu = match parameters_for(&case.problem, base, hydro_database) {
        Ok((parameters, experiment)) => fmu_json(&parameters, &experiment, steps, run.time_step),
        Err(reason) => json!({ "unavailable": reason }),
    };
    let mut document = json!({
        "name": case.name,
        "fingerprint": case.fingerprint(),
        "transient": case.transient,
        "time_step": run.time_step,
        "steps": steps as u64,
        "fmu": fmu,
    });
    // A case runs if its problem is valid and its run has an end (every step is recorded).
    let runs = case
        .problem
        .check()
        .and_then(|_| crate::reserve_recorded(&case.problem, &mut Vec::<()>::new()));
    if let Err(e) = runs {
        document["refused"] = json!(e.to_string());
    }
    document
}

/// The parameters and experiment that make an instance whose base is `base` (what
/// `hydro_database` loads) run `case` exactly, seed aside (left at 0: a master sets it per
/// run). `Err` says why the FMU cannot run it.
pub fn parameters_for<H: Clone + PartialEq>(
    case: &Scenario<H>,
    base: &Scenario<H>,
    hydro_database: &str,
) -> Result<(Parameters, Experiment), String> {
    let mut parameters = Parameters::default();
    let variables: Vec<_> = parameters.iter().map(|(v, _, _)| v).collect();
    for variable in variables {
        let (name, ty) = (variable.name, variable.var_type);
        let value = if name == HYDRO_DATABASE {
            FmuValue::String(hydro_database.to_string())
        } else if name == SEED {
            FmuValue::Integer(0)
        } else {
            let setting = by_fmu(name).expect("every FMU parameter but hydroDatabase is a setting");
            match (setting.get(case), ty) {
                // Not in force (cd under separate drag): any value; the start value stays.
                (Value::Number(x), _) if x.is_nan() => continue,
                (Value::Number(x), VariableType::Real) => FmuValue::Real(x),
                (Value::Number(x), _) => {
                    if x.fract() != 0.0 || x.abs() > f64::from(i32::MAX) {
                        return Err(format!("{} = {x} is not an FMU Integer", setting.key));
                    }
                    FmuValue::Integer(x as i32)
                }
                (Value::Word(word), _) => FmuValue::Integer(
                    setting
                        .code_of(word)
                        .ok_or_else(|| format!("{name} has no code for '{word}'"))?,
                ),
            }
        };
        parameters.set(name, value);
    }
    let start = case.run.start_time;
    let experiment =
        Experiment::new(start, Some(start + case.run.duration)).map_err(|e| e.to_string())?;
    let mut expected = case.clone();
    expected.sea.seed = 0;
    let applied = parameters
        .apply(base.clone(), &experiment)
        .map_err(|e| e.to_string())?;
    if applied != expected {
        return Err(
            "the configuration differs from the FMU's base in a field the FMU's parameters \
             do not set (or its start time and duration do not survive stopTime - startTime)"
                .into(),
        );
    }
    Ok((parameters, experiment))
}

fn fmu_json(parameters: &Parameters, experiment: &Experiment, steps: f64, h: f64) -> Json {
    let start = experiment.start_time;
    let stop = experiment.stop_time.unwrap_or(f64::INFINITY);
    let end = start + steps * h;
    // `fmi2DoStep` refuses a step that ends past the stop time.
    if experiment.passes_stop(end) {
        return json!({
            "unavailable": format!(
                "the run's {steps} steps of {h} s end at {end} s, after the FMU's stopTime \
                 {stop} s (the duration is not a whole number of steps)"
            )
        });
    }
    let mut values = Map::new();
    // The parameters a master sets; the others keep the configuration's value.
    for (v, value, _) in parameters
        .iter()
        .filter(|(v, _, set)| *set && v.name != SEED)
    {
        let value = match value {
            FmuValue::Real(x) => json!(*x),
            FmuValue::Integer(i) => json!(*i),
            FmuValue::String(s) => json!(s),
        };
        values.insert(v.name.to_string(), value);
    }
    json!({ "start_time": start, "stop_time": stop, "parameters": values })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fmi2::model_description::{Causality, VARIABLES};
    use crate::montecarlo::cases::parse_case_table;
    use crate::sea_state::Spectrum;
    use std::path::Path;

    fn base() -> Problem {
        crate::problem::load(Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/data/example.toml"
        )))
        .unwrap()
    }

    /// The document of `cases`, as written and read back.
    fn cases_json(cases: &[Case], base: &Problem, hydro_database: &str) -> Json {
        let mut out = Vec::new();
        let cases = cases.iter().cloned().map(Ok);
        write_cases_json(&mut out, "out", cases, base, hydro_database).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(text.ends_with("]}\n"), "{text}");
        serde_json::from_str(&text).unwrap()
    }

    fn plan(table: &str, base: &Problem) -> Json {
        let cases: Vec<Case> = parse_case_table(table, "cases.csv")
            .unwrap()
            .iter()
            .map(|row| row.case(base, Some(100.0), "cases.csv").unwrap())
            .collect();
        cases_json(&cases, base, "/abs/example.toml")
    }

    const TABLE: &str = "name, hs, tp, direction_deg, spreading_exponent, drag, cd_slow, \
                         cd_fast, duration, interaction, yaw_headings\n\
                         a, 4, 11, 90, 2, separate, 0.5, 0.9, 600, none, 12\n\
                         b, , , , , , , , , , \n\
                         c, -1, , , , , , , 300, mean-direction, \n";

    /// The FMU parameters, set on a fresh `Parameters` by name as a master would and
    /// applied to the base, rebuild each case's configuration (seed aside).
    #[test]
    fn fmu_parameters_rebuild_every_case() {
        let base = base();
        let doc = plan(TABLE, &base);
        let cases = doc["cases"].as_array().unwrap();
        assert_eq!(cases.len(), 3);
        let parsed: Vec<Case> = parse_case_table(TABLE, "cases.csv")
            .unwrap()
            .iter()
            .map(|row| row.case(&base, Some(100.0), "cases.csv").unwrap())
            .collect();
        for (json, case) in cases.iter().zip(&parsed) {
            assert_eq!(json["name"], case.name.as_str());
            assert_eq!(json["fingerprint"], case.fingerprint().as_str());
            assert_eq!(json["transient"], 100.0);
            let fmu = &json["fmu"];
            let mut p = Parameters::default();
            assert!(p.set("seed", FmuValue::Integer(0)));
            for v in VARIABLES
                .iter()
                .filter(|v| v.causality == Causality::Parameter)
            {
                let value = &fmu["parameters"][v.name];
                let set = match v.var_type {
                    VariableType::Integer if v.name == "seed" => {
                        assert!(value.is_null());
                        true
                    }
                    // Left to the configuration (a setting out of force: cd under separate drag).
                    _ if value.is_null() => true,
                    VariableType::Real => p.set(v.name, FmuValue::Real(value.as_f64().unwrap())),
                    VariableType::Integer => {
                        p.set(v.name, FmuValue::Integer(value.as_i64().unwrap() as i32))
                    }
                    VariableType::String => {
                        p.set(v.name, FmuValue::String(value.as_str().unwrap().into()))
                    }
                    _ => unreachable!("no such parameter type"),
                };
                assert!(set, "{}", v.name);
            }
            assert_eq!(p.hydro_database(), "/abs/example.toml");
            let experiment = Experiment::new(
                fmu["start_time"].as_f64().unwrap(),
                Some(fmu["stop_time"].as_f64().unwrap()),
            )
            .unwrap();
            let mut expected = case.problem.clone();
            expected.sea.seed = 0;
            assert_eq!(p.apply(base.clone(), &experiment).unwrap(), expected);
            assert_eq!(
                json["steps"].as_f64().unwrap(),
                case.problem.run.duration / case.problem.run.time_step
            );
        }
        // Row c's negative Hs is the model's to refuse at run time, not the plan's; the
        // message its runs fail with names the cell.
        assert_eq!(cases[2]["fmu"]["parameters"]["Hs"], -1.0);
        assert_eq!(
            cases[2]["refused"],
            "cases.csv:4: invalid row 3, column 'hs' = -1: must be greater than zero"
        );
        assert!(cases[0].get("refused").is_none());
    }

    #[test]
    fn cases_the_fmu_cannot_run_say_why() {
        let mut base = base();
        let doc = plan("duration\n600.6\n", &base);
        let reason = doc["cases"][0]["fmu"]["unavailable"].as_str().unwrap();
        assert!(reason.contains("not a whole number of steps"), "{reason}");
        // A base without end (the case table refuses an infinite duration itself): every
        // run of its cases records every step, so they are refused.
        let mut open = base.clone();
        open.run.duration = f64::INFINITY;
        let doc = plan("hs\n5\n", &open);
        let refused = doc["cases"][0]["refused"].as_str().unwrap();
        assert!(
            refused.contains("example.toml:")
                && refused.contains(": invalid [run] duration = inf: is not finite"),
            "{refused}"
        );
        // A Pierson-Moskowitz base: Hs and Tp write its own spectrum (it stays PM).
        base.sea.spectrum = Spectrum::PiersonMoskowitz { hs: 3.0, tp: 9.0 };
        let doc = plan("hs\n5\n", &base);
        assert_eq!(doc["cases"][0]["fmu"]["parameters"]["Hs"], 5.0);
        assert_eq!(doc["cases"][0]["fmu"]["parameters"]["gamma"], 0.0);
        // A tabulated spectrum has no Hs for the FMU to write, so it keeps the base's.
        let mut table = base.clone();
        table.sea.spectrum = Spectrum::Tabulated {
            omega: vec![0.2, 1.0, 3.0],
            density: vec![0.0, 1.0, 0.0],
        };
        let doc = plan("duration\n600\n", &table);
        assert!(doc["cases"][0]["fmu"]["parameters"].is_object(), "{doc}");
        // A base that differs from what hydroDatabase loads in an unset field.
        let mut other = base.clone();
        other.sea.spectrum = Spectrum::Jonswap {
            hs: 3.0,
            tp: 9.0,
            gamma: None,
        };
        let case = Case {
            name: "x".into(),
            problem: {
                let mut c = other.clone();
                c.platform.mass = Some(2.0 * c.inertia().unwrap().mass);
                c
            },
            transient: 0.0,
        };
        let doc = cases_json(&[case], &other, "");
        let reason = doc["cases"][0]["fmu"]["unavailable"].as_str().unwrap();
        assert!(reason.contains("do not set"), "{reason}");
    }
}
