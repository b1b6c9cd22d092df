//! The `min` and `max` of modelDescription.xml are the FMU's own bounds. FMI 2.0's bounds
//! are inclusive, so a parameter that must be greater than zero has no `min`: for every Real
//! and Integer parameter with a `min` or `max` (its own or its declared type's, read from
//! the XML here with quick-xml), the bound is accepted and a value just beyond it refused,
//! naming the parameter. The values go through the FMU's parameter code as
//! `fmi2ExitInitializationMode` takes them (`Parameters::to_problem`, then
//! `Problem::check`), without making records (720 yaw-following headings would take GBs).

use crate::fmu::packed_resources;
use quick_xml::events::Event;
use quick_xml::Reader;
use slowdrift::fmi2::parameters::{Experiment, FmuValue, Parameters};
use std::collections::HashMap;
use std::path::PathBuf;

const XML: &str = include_str!("../../modelDescription/modelDescription.xml");

/// A parameter's bounds as the XML gives them.
#[derive(Debug)]
struct Bounds {
    name: String,
    integer: bool,
    min: Option<f64>,
    max: Option<f64>,
}

/// Every Real and Integer parameter with its `min` and `max`, a variable's own attribute
/// before its declared type's (FMI 2.0 section 2.2.7).
fn parameter_bounds() -> Vec<Bounds> {
    let mut reader = Reader::from_str(XML);
    let mut types: HashMap<String, (Option<f64>, Option<f64>)> = HashMap::new();
    let mut out = Vec::new();
    let mut simple_type: Option<String> = None;
    let mut parameter: Option<String> = None;
    loop {
        let event = reader.read_event().unwrap();
        let element = match &event {
            Event::Start(e) | Event::Empty(e) => e.clone(),
            Event::Eof => break,
            _ => continue,
        };
        let attribute = |key: &str| {
            element
                .attributes()
                .map(|a| a.unwrap())
                .find(|a| a.key.as_ref() == key)
                .map(|a| a.value.to_string())
        };
        let number = |key: &str| attribute(key).map(|v| v.parse::<f64>().unwrap());
        match element.name().as_ref() {
            "SimpleType" => simple_type = attribute("name"),
            "ScalarVariable" => {
                simple_type = None;
                parameter = (attribute("causality").as_deref() == Some("parameter"))
                    .then(|| attribute("name").unwrap());
            }
            kind @ ("Real" | "Integer") => {
                if let Some(name) = &simple_type {
                    types.insert(name.clone(), (number("min"), number("max")));
                } else if let Some(name) = parameter.take() {
                    let declared = attribute("declaredType")
                        .map(|t| types[&t])
                        .unwrap_or_default();
                    out.push(Bounds {
                        name,
                        integer: kind == "Integer",
                        min: number("min").or(declared.0),
                        max: number("max").or(declared.1),
                    });
                }
            }
            _ => {}
        }
    }
    out
}

/// Other parameters that put `name` in force (a setting applies only under the choice it
/// belongs to) or keep its bound from failing another check (Tp = 0.3 s with the default Hs
/// of 7 m is steeper than waves can be: L_p = g Tp^2 / (2 pi) = 0.14 m).
fn context(name: &str) -> Vec<(&'static str, FmuValue)> {
    match name {
        "nDirections" => vec![("spreadingExponent", FmuValue::Real(2.0))],
        "cdSlow" | "cdFast" => vec![("dragModel", FmuValue::Integer(1))],
        "yawFollowingRange" => vec![("yawFollowingHeadings", FmuValue::Integer(2))],
        "Tp" => vec![("Hs", FmuValue::Real(0.01))],
        _ => vec![],
    }
}

/// The packed default's resources folder.
fn resources() -> PathBuf {
    PathBuf::from(packed_resources().strip_prefix("file://").unwrap())
}

/// What the FMU says of parameter `name` = `value` (with its [`context`]): `Ok` when it
/// accepts it, else the message.
fn verdict(name: &str, value: FmuValue) -> Result<(), String> {
    let mut parameters = Parameters::default();
    for (other, v) in context(name) {
        assert!(parameters.set(other, v));
    }
    assert!(parameters.set(name, value));
    let base = parameters
        .base_scenario(Some(&resources()))
        .map_err(|e| e.to_string())?;
    let experiment = Experiment::new(0.0, Some(100.0)).unwrap();
    let problem = parameters
        .to_problem(&base, &experiment)
        .map_err(|e| e.to_string())?;
    problem.check().map_err(|e| e.to_string())
}

#[test]
fn every_bound_of_the_xml_is_the_fmus() {
    let bounds = parameter_bounds();
    let mut checked = 0;
    for b in &bounds {
        let value = |x: f64| {
            if b.integer {
                FmuValue::Integer(x as i32)
            } else {
                FmuValue::Real(x)
            }
        };
        // Just beyond: the next whole number, or a relative 1e-9 (absolute at zero).
        let beyond = |x: f64, direction: f64| {
            if b.integer {
                x + direction
            } else {
                x + direction * 1e-9 * x.abs().max(1.0)
            }
        };
        for (bound, direction) in [(b.min, -1.0), (b.max, 1.0)] {
            let Some(x) = bound else { continue };
            if let Err(message) = verdict(&b.name, value(x)) {
                panic!("{} = {x} (an XML bound) is refused: {message}", b.name);
            }
            let outside = beyond(x, direction);
            let message = verdict(&b.name, value(outside))
                .err()
                .unwrap_or_else(|| panic!("{} = {outside} (beyond the XML) accepted", b.name));
            assert!(
                message.contains(&format!("invalid FMU parameter {} = ", b.name)),
                "{} = {outside}: {message}",
                b.name
            );
            println!("{} = {x} accepted, {outside} refused: {message}", b.name);
            checked += 1;
        }
    }
    // 21 mins (the declared stiffness types' included) and 11 maxes; among them the bounds
    // the code has and the XML did not say.
    assert_eq!(checked, 32, "{bounds:#?}");
    assert!(bounds
        .iter()
        .any(|b| b.name == "memoryLimit" && b.max == Some(1e6)));
    for name in ["Tp", "currentSpeed", "nDirections", "yawFollowingHeadings"] {
        let b = bounds.iter().find(|b| b.name == name).unwrap();
        assert!(b.min.is_some() && b.max.is_some(), "{b:?}");
    }
}
