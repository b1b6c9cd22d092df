//! A campaign's cases as JSON for other masters (`slowdrift montecarlo --print-cases`): the
//! Dask package `fmu-pack/python/slowdrift_dask` reads its cases from here instead of
//! parsing the case table and the configuration a second time, so both paths share one
//! reader, its error messages and the per-case fingerprint.
//!
//! Per case: `name`, `fingerprint` ([`Case::fingerprint`]), `transient` (s from the start
//! of the run), `time_step` (s), `steps` (the RK4 steps of [`super::run_seed`]:
//! round(duration / time_step); the statistics use the samples at k time_step >= transient,
//! k = 0 ..= steps), and `fmu`: either `{"start_time", "stop_time", "parameters": {FMU
//! parameter name: value}}` (every parameter of modelDescription.xml except `seed`, which
//! the master sets per run) that makes `SlowDrift.fmu` run this case exactly, or
//! `{"unavailable": reason}`. Numbers are written in their shortest round-trip form.

use super::Case;
use crate::fmi2::parameters::{Experiment, Parameters};
use crate::model_description::{Causality, VariableType, VARIABLES};
use crate::Problem;
use serde_json::{json, Map, Value};

/// Relative tolerance of the FMU's end-of-run check (`fmi2DoStep` refuses a step that ends
/// past stopTime by more than this times max(1, |stopTime|)).
const FMU_TIME_TOLERANCE: f64 = 1e-9;

/// The JSON document of `cases` run on top of `base`; `hydro_database` is the FMU's
/// `hydroDatabase` parameter that loads `base` (empty for the packed default platform).
pub fn cases_json(cases: &[Case], base: &Problem, hydro_database: &str) -> Value {
    let cases: Vec<Value> = cases
        .iter()
        .map(|case| case_json(case, base, hydro_database))
        .collect();
    json!({ "format_version": 1, "cases": cases })
}

fn case_json(case: &Case, base: &Problem, hydro_database: &str) -> Value {
    let run = &case.config.run;
    let steps = (run.duration / run.time_step).round();
    let fmu = match Parameters::for_config(&case.config, base, hydro_database) {
        Ok((parameters, experiment)) => fmu_json(&parameters, &experiment, steps, run.time_step),
        Err(reason) => json!({ "unavailable": reason }),
    };
    json!({
        "name": case.name,
        "fingerprint": case.fingerprint(),
        "transient": case.transient,
        "time_step": run.time_step,
        "steps": steps as u64,
        "fmu": fmu,
    })
}

fn fmu_json(parameters: &Parameters, experiment: &Experiment, steps: f64, h: f64) -> Value {
    let start = experiment.start_time;
    let stop = experiment.stop_time.unwrap_or(f64::INFINITY);
    let end = start + steps * h;
    if end > stop + FMU_TIME_TOLERANCE * stop.abs().max(1.0) {
        return json!({
            "unavailable": format!(
                "the run's {steps} steps of {h} s end at {end} s, after the FMU's stopTime \
                 {stop} s (the duration is not a whole number of steps)"
            )
        });
    }
    let mut p = parameters.clone();
    let mut values = Map::new();
    for v in VARIABLES
        .iter()
        .filter(|v| v.causality == Causality::Parameter && v.name != "seed")
    {
        let vr = v.value_reference;
        let value = match v.var_type.access_type() {
            VariableType::Real => p.real_mut(vr).map(|x| json!(*x)),
            VariableType::Integer => p.integer_mut(vr).map(|x| json!(*x)),
            VariableType::String => p.string_mut(vr).map(|x| json!(x.clone())),
            VariableType::Boolean | VariableType::Enumeration => None,
        };
        values.insert(v.name.to_string(), value.unwrap_or(Value::Null));
    }
    json!({ "start_time": start, "stop_time": stop, "parameters": values })
}

#[cfg(test)]
mod tests {
    use super::*;
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

    fn plan(table: &str, base: &Problem) -> Value {
        let cases: Vec<Case> = parse_case_table(table, "cases.csv")
            .unwrap()
            .iter()
            .map(|row| row.case(base, Some(100.0), "cases.csv").unwrap())
            .collect();
        cases_json(&cases, base, "/abs/example.toml")
    }

    const TABLE: &str = "name, hs, tp, direction_deg, spreading_exponent, cd_slow, cd_fast, \
                         duration, interaction, yaw_headings\n\
                         a, 4, 11, 90, 2, 0.5, 0.9, 600, none, 12\n\
                         b, , , , , , , , , \n\
                         c, -1, , , , , , 300, mean-direction, \n";

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
            let mut p = Parameters {
                seed: 0,
                ..Parameters::default()
            };
            for v in VARIABLES
                .iter()
                .filter(|v| v.causality == Causality::Parameter)
            {
                let value = &fmu["parameters"][v.name];
                let vr = v.value_reference;
                match v.var_type.access_type() {
                    VariableType::Real => *p.real_mut(vr).unwrap() = value.as_f64().unwrap(),
                    VariableType::Integer if v.name == "seed" => assert!(value.is_null()),
                    VariableType::Integer => {
                        *p.integer_mut(vr).unwrap() = value.as_i64().unwrap() as i32
                    }
                    VariableType::String => {
                        *p.string_mut(vr).unwrap() = value.as_str().unwrap().into()
                    }
                    _ => unreachable!("no such parameter type"),
                }
            }
            assert_eq!(p.hydro_database, "/abs/example.toml");
            let experiment = Experiment::new(
                fmu["start_time"].as_f64().unwrap(),
                Some(fmu["stop_time"].as_f64().unwrap()),
            )
            .unwrap();
            let mut expected = case.config.clone();
            expected.sea.seed = 0;
            assert_eq!(p.apply(base.clone(), &experiment).unwrap(), expected);
            assert_eq!(
                json["steps"].as_f64().unwrap(),
                case.config.run.duration / case.config.run.time_step
            );
        }
        // Row c's negative Hs is the model's to refuse at run time, not the plan's.
        assert_eq!(cases[2]["fmu"]["parameters"]["Hs"], -1.0);
    }

    #[test]
    fn cases_the_fmu_cannot_run_say_why() {
        let mut base = base();
        let doc = plan("duration\n600.6\n", &base);
        let reason = doc["cases"][0]["fmu"]["unavailable"].as_str().unwrap();
        assert!(reason.contains("not a whole number of steps"), "{reason}");
        base.sea.spectrum = Spectrum::PiersonMoskowitz { hs: 3.0, tp: 9.0 };
        let doc = plan("duration\n600\n", &base);
        let reason = doc["cases"][0]["fmu"]["unavailable"].as_str().unwrap();
        assert!(reason.contains("JONSWAP"), "{reason}");
        // A base that differs from what hydroDatabase loads in an unset field.
        let mut other = base.clone();
        other.sea.spectrum = Spectrum::Jonswap {
            hs: 3.0,
            tp: 9.0,
            gamma: None,
        };
        let case = Case {
            name: "x".into(),
            config: {
                let mut c = other.clone();
                c.platform.mass *= 2.0;
                c
            },
            transient: 0.0,
        };
        let doc = cases_json(&[case], &other, "");
        let reason = doc["cases"][0]["fmu"]["unavailable"].as_str().unwrap();
        assert!(reason.contains("do not set"), "{reason}");
    }
}
