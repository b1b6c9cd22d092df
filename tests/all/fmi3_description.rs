//! The FMI 3.0 model descriptions against the FMI 2.0 ones they are generated from, both
//! read here with quick-xml's reader: every FMI 2.0 variable is in the FMI 3.0 description
//! with the same name, causality, variability, unit and start, and its value reference
//! moved by the documented offset of its type (SlowDrift: none; the mooring: Integer +1000,
//! String +2000); the independent variable `time` is the one addition, at 999999; every
//! output and initial unknown depends on the same variables, by name.
//!
//! SlowDrift's is the library's constant (build.rs's output). The mooring's crate cannot be
//! linked beside SlowDrift's (both export the `fmi2*` symbols), so its description is made
//! here the way mooring/build.rs makes it; tests/clients/test_fmi3_description.py checks the
//! files fmu-pack takes from both build scripts.

use quick_xml::events::Event;
use quick_xml::{Reader, XmlVersion};
use slowdrift_fmi_xml::Numbering;
use std::collections::BTreeMap;

/// The value reference of `time`, as docs/fmu.md states it.
const TIME_VALUE_REFERENCE: u32 = 999_999;

/// One variable as either version writes it.
#[derive(Debug, Clone, PartialEq)]
struct Variable {
    name: String,
    value_reference: u32,
    /// FMI 2.0: Real, Integer, Boolean, String; FMI 3.0: the element.
    ty: String,
    causality: String,
    variability: String,
    unit: Option<String>,
    start: Option<String>,
}

/// One output or initial unknown: the variable and what it depends on (None: everything).
type Unknown = (String, Option<Vec<String>>);

#[derive(Debug, Default)]
struct Description {
    variables: Vec<Variable>,
    outputs: Vec<Unknown>,
    initial_unknowns: Vec<Unknown>,
}

/// Every element of `xml` as (its path of ancestors' names, its name, its attributes).
fn elements(xml: &str) -> Vec<(Vec<String>, String, BTreeMap<String, String>)> {
    let mut reader = Reader::from_str(xml);
    let mut stack = Vec::new();
    let mut out = Vec::new();
    loop {
        let (e, empty) = match reader.read_event().expect("well-formed XML") {
            Event::Start(e) => (e, false),
            Event::Empty(e) => (e, true),
            Event::End(_) => {
                stack.pop();
                continue;
            }
            Event::Eof => break,
            _ => continue,
        };
        let name = e.name().as_ref().to_string();
        let attributes = e
            .attributes()
            .map(|a| {
                let a = a.unwrap();
                let value = a.normalized_value(XmlVersion::Implicit1_0).unwrap();
                (a.key.as_ref().to_string(), value.into_owned())
            })
            .collect();
        out.push((stack.clone(), name.clone(), attributes));
        if !empty {
            stack.push(name);
        }
    }
    out
}

fn fmi2(xml: &str) -> Description {
    let mut d = Description::default();
    let mut indices = Vec::new();
    let mut unknowns = Vec::new();
    for (path, name, a) in elements(xml) {
        match (path.last().map(String::as_str), name.as_str()) {
            (Some("ModelVariables"), "ScalarVariable") => {
                indices.push(a["name"].clone());
                d.variables.push(Variable {
                    name: a["name"].clone(),
                    value_reference: a["valueReference"].parse().unwrap(),
                    ty: String::new(),
                    causality: a.get("causality").cloned().unwrap_or("local".into()),
                    variability: a.get("variability").cloned().unwrap_or("continuous".into()),
                    unit: None,
                    start: None,
                });
            }
            (Some("ScalarVariable"), ty) => {
                let v = d.variables.last_mut().unwrap();
                v.ty = ty.to_string();
                v.unit = a.get("unit").cloned();
                v.start = a.get("start").cloned();
            }
            (Some(list @ ("Outputs" | "InitialUnknowns")), "Unknown") => {
                unknowns.push((list.to_string(), a));
            }
            _ => {}
        }
    }
    let by_index = |i: &str| indices[i.parse::<usize>().unwrap() - 1].clone();
    for (list, a) in unknowns {
        let unknown = (
            by_index(&a["index"]),
            a.get("dependencies")
                .map(|d| d.split_whitespace().map(by_index).collect()),
        );
        match list.as_str() {
            "Outputs" => d.outputs.push(unknown),
            _ => d.initial_unknowns.push(unknown),
        }
    }
    d
}

fn fmi3(xml: &str) -> Description {
    let mut d = Description::default();
    let mut unknowns = Vec::new();
    for (path, name, a) in elements(xml) {
        match (path.last().map(String::as_str), name.as_str()) {
            (Some("ModelVariables"), ty) => d.variables.push(Variable {
                name: a["name"].clone(),
                value_reference: a["valueReference"].parse().unwrap(),
                ty: ty.to_string(),
                causality: a["causality"].clone(),
                variability: a["variability"].clone(),
                unit: a.get("unit").cloned(),
                start: a.get("start").cloned(),
            }),
            (Some("String"), "Start") => {
                d.variables.last_mut().unwrap().start = Some(a["value"].clone());
            }
            (Some("ModelStructure"), list @ ("Output" | "InitialUnknown")) => {
                unknowns.push((list.to_string(), a));
            }
            _ => {}
        }
    }
    let names: BTreeMap<String, String> = d
        .variables
        .iter()
        .map(|v| (v.value_reference.to_string(), v.name.clone()))
        .collect();
    assert_eq!(
        names.len(),
        d.variables.len(),
        "value references are unique"
    );
    for (list, a) in unknowns {
        let unknown = (
            names[&a["valueReference"]].clone(),
            a.get("dependencies")
                .map(|d| d.split_whitespace().map(|vr| names[vr].clone()).collect()),
        );
        match list.as_str() {
            "Output" => d.outputs.push(unknown),
            _ => d.initial_unknowns.push(unknown),
        }
    }
    d
}

/// `fmi3_xml` is `fmi2_xml` with value references moved by (Integer, String) offsets.
/// The array and the index k of an FMI 2.0 name `{array}k` (k = 1 .. its count).
fn element_of(name: &str, arrays: &[(&str, u32)]) -> Option<(String, u32)> {
    arrays.iter().find_map(|(array, count)| {
        name.strip_prefix(array)
            .and_then(|k| k.parse::<u32>().ok())
            .filter(|k| (1..=*count).contains(k))
            .map(|k| (array.to_string(), k))
    })
}

/// The FMI 2.0 name `name` as FMI 3.0 has it: an array's element k is the array for k = 1
/// and no variable of its own for k > 1 (`None`).
fn fmi3_name(name: &str, arrays: &[(&str, u32)]) -> Option<String> {
    match element_of(name, arrays) {
        Some((array, 1)) => Some(array),
        Some(_) => None,
        None => Some(name.to_string()),
    }
}

/// The FMI 2.0 unknowns as FMI 3.0 has them: an array's elements one unknown, a dependency
/// on any of them one on the array.
fn fmi3_unknowns(unknowns: &[Unknown], arrays: &[(&str, u32)]) -> Vec<Unknown> {
    unknowns
        .iter()
        .filter_map(|(name, dependencies)| {
            let name = fmi3_name(name, arrays)?;
            let dependencies = dependencies.as_ref().map(|d| {
                let mut out: Vec<String> = Vec::new();
                for n in d {
                    let n = element_of(n, arrays).map_or_else(|| n.clone(), |(array, _)| array);
                    if !out.contains(&n) {
                        out.push(n);
                    }
                }
                out
            });
            Some((name, dependencies))
        })
        .collect()
}

/// `arrays`: (name, count) of the FMI 3.0 arrays made of FMI 2.0 Reals `{name}1` ..
fn check(fmi2_xml: &str, fmi3_xml: &str, (integer, string): (u32, u32), arrays: &[(&str, u32)]) {
    let before = fmi2(fmi2_xml);
    let after = fmi3(fmi3_xml);
    assert!(fmi3_xml.contains("fmiVersion=\"3.0\""));
    let time = Variable {
        name: "time".into(),
        value_reference: TIME_VALUE_REFERENCE,
        ty: "Float64".into(),
        causality: "independent".into(),
        variability: "continuous".into(),
        unit: after.variables[0].unit.clone(),
        start: None,
    };
    assert!(matches!(time.unit.as_deref(), None | Some("s")));
    let mut expected = vec![time];
    for v in &before.variables {
        let Some(name) = fmi3_name(&v.name, arrays) else {
            continue;
        };
        let (ty, offset) = match v.ty.as_str() {
            "Real" => ("Float64", 0),
            "Integer" => ("Int32", integer),
            "Boolean" => ("Boolean", 0),
            "String" => ("String", string),
            other => panic!("{}: {other}", v.name),
        };
        expected.push(Variable {
            name,
            ty: ty.into(),
            value_reference: v.value_reference + offset,
            ..v.clone()
        });
    }
    assert_eq!(after.variables.len(), expected.len());
    for (a, e) in after.variables.iter().zip(&expected) {
        assert_eq!(a, e);
    }
    let independent = after
        .variables
        .iter()
        .filter(|v| v.causality == "independent");
    assert_eq!(independent.count(), 1);
    assert!(!before.outputs.is_empty());
    assert_eq!(after.outputs, fmi3_unknowns(&before.outputs, arrays));
    assert_eq!(
        after.initial_unknowns,
        fmi3_unknowns(&before.initial_unknowns, arrays)
    );
}

#[test]
fn slowdrift_fmi3_is_its_fmi2_description() {
    let fmi2_xml = include_str!("../../modelDescription/modelDescription.xml");
    check(
        fmi2_xml,
        slowdrift::fmi2::fmi3_description::MODEL_DESCRIPTION_FMI3,
        (0, 0),
        &[],
    );
    use slowdrift::fmi2::fmi3_description as d;
    assert_eq!(d::TIME_VALUE_REFERENCE, TIME_VALUE_REFERENCE);
    let offsets = [
        d::FLOAT64_OFFSET,
        d::INT32_OFFSET,
        d::BOOLEAN_OFFSET,
        d::STRING_OFFSET,
    ];
    assert_eq!(offsets, [0; 4]);
    // Its guid is the instantiation token, and time has the unit s it declares.
    assert!(
        slowdrift::fmi2::fmi3_description::MODEL_DESCRIPTION_FMI3.contains(&format!(
            "instantiationToken=\"{}\"",
            slowdrift::fmi2::model_description::GUID
        ))
    );
    let after = fmi3(slowdrift::fmi2::fmi3_description::MODEL_DESCRIPTION_FMI3);
    assert_eq!(after.variables[0].unit.as_deref(), Some("s"));
}

#[test]
fn mooring_fmi3_is_its_fmi2_description() {
    let fmi2_xml = include_str!("../../mooring/modelDescription.xml");
    let numbering = Numbering {
        integer: 1000,
        string: 2000,
        arrays: &[slowdrift_fmi_xml::ArrayVariable {
            name: "fairleadTension",
            first: 101,
            count: 8,
            description: "each line's",
        }],
        ..Numbering::SAME
    };
    let fmi3_xml =
        slowdrift_fmi_xml::fmi3_model_description_numbered(fmi2_xml, &numbering).unwrap();
    check(fmi2_xml, &fmi3_xml, (1000, 2000), &[("fairleadTension", 8)]);
    assert!(fmi3_xml.contains("<Dimension start=\"8\"/>"));
    // Without the offsets, String 0, Integer 0 and Real 0 collide.
    let error = slowdrift_fmi_xml::fmi3_model_description(fmi2_xml).unwrap_err();
    assert!(error.to_string().contains("value reference 0"), "{error}");
}
