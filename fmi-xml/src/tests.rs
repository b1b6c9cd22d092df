//! The conversion of a small hand-written FMI 2.0 description, checked element by element
//! against what FMI 3.0 (§2.4) says it must be. The output is read by plain text scanning,
//! not by the generator's reader.

use super::*;
use std::collections::BTreeMap;

/// Seven variables (index: name, type, value reference): 1 k Real 0, 2 n Integer 1, 3 on
/// Boolean 2, 4 file String 3, 5 u Real 10, 6 x Real 20, 7 y Real 21.
const TOY: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<!-- a toy -->
<fmiModelDescription fmiVersion="2.0" modelName="Toy" guid="{0a1b}"
  description="A toy &amp; its fmi2Error, not fmi2 itself" numberOfEventIndicators="0"
  variableNamingConvention="flat">
  <CoSimulation modelIdentifier="Toy" canHandleVariableCommunicationStepSize="true"
    canInterpolateInputs="false" canRunAsynchronuously="false" maxOutputDerivativeOrder="0"
    canGetAndSetFMUstate="true" canSerializeFMUstate="false"
    canNotUseMemoryManagementFunctions="true"/>
  <UnitDefinitions>
    <Unit name="m"><BaseUnit m="1"/></Unit>
    <Unit name="rad"><BaseUnit rad="1"/><DisplayUnit name="deg" factor="57.29577951308232"/></Unit>
  </UnitDefinitions>
  <TypeDefinitions>
    <SimpleType name="Length"><Real quantity="Length" unit="m" min="-5"/></SimpleType>
    <SimpleType name="Count"><Integer min="0"/></SimpleType>
  </TypeDefinitions>
  <LogCategories>
    <Category name="logStatusError" description="Calls that return fmi2Error"/>
  </LogCategories>
  <DefaultExperiment startTime="0" stopTime="10" stepSize="0.5"/>
  <ModelVariables>
    <ScalarVariable name="k" valueReference="0" causality="parameter" variability="fixed"
      initial="exact" description="stiffness"><Real unit="m" min="0" start="2.5"/></ScalarVariable>
    <ScalarVariable name="n" valueReference="1" causality="parameter" variability="fixed"
      initial="exact"><Integer declaredType="Count" min="1" max="9" start="3"/></ScalarVariable>
    <ScalarVariable name="on" valueReference="2" causality="parameter" variability="tunable"
      ><Boolean start="1"/></ScalarVariable>
    <ScalarVariable name="file" valueReference="3" causality="parameter" variability="fixed"
      initial="exact"><String start="a &lt;b&gt;.txt"/></ScalarVariable>
    <ScalarVariable name="u" valueReference="10" causality="input"
      ><Real declaredType="Length" unit="m" start="0"/></ScalarVariable>
    <ScalarVariable name="x" valueReference="20" causality="output" initial="calculated"
      ><Real declaredType="Length" unit="m"/></ScalarVariable>
    <ScalarVariable name="y" valueReference="21" causality="output" variability="continuous"
      initial="calculated"><Real unit="m"/></ScalarVariable>
  </ModelVariables>
  <ModelStructure>
    <Outputs>
      <Unknown index="6" dependencies="5"/>
      <Unknown index="7" dependencies=""/>
    </Outputs>
    <InitialUnknowns>
      <Unknown index="6" dependencies="1 2 5" dependenciesKind="dependent fixed dependent"/>
      <Unknown index="7"/>
    </InitialUnknowns>
  </ModelStructure>
</fmiModelDescription>
"#;

type Attributes = BTreeMap<String, String>;

/// The attributes of every `<tag ...>` in `xml`, in order, entities left as written.
fn tags(xml: &str, tag: &str) -> Vec<Attributes> {
    let open = format!("<{tag}");
    let mut out = Vec::new();
    let mut rest = xml;
    while let Some(i) = rest.find(&open) {
        let tail = &rest[i + open.len()..];
        let end = tail.find('>').expect("the tag closes");
        if tail.starts_with(|c: char| c.is_whitespace() || c == '/' || c == '>') {
            out.push(pairs(&tail[..end]));
        }
        rest = &tail[end..];
    }
    out
}

/// `key="value"` pairs of a tag's text.
fn pairs(text: &str) -> Attributes {
    let mut map = Attributes::new();
    let mut rest = text;
    while let Some(eq) = rest.find("=\"") {
        let key = rest[..eq]
            .split_whitespace()
            .last()
            .expect("a key")
            .to_string();
        let after = &rest[eq + 2..];
        let close = after.find('"').expect("the value closes");
        assert!(map.insert(key, after[..close].to_string()).is_none());
        rest = &after[close + 1..];
    }
    map
}

/// The attributes of the one `<tag>` whose name is `name`.
fn named(xml: &str, tag: &str, name: &str) -> Attributes {
    let found: Vec<Attributes> = tags(xml, tag)
        .into_iter()
        .filter(|a| a.get("name").map(String::as_str) == Some(name))
        .collect();
    assert_eq!(found.len(), 1, "<{tag} name={name:?}> in\n{xml}");
    found.into_iter().next().unwrap()
}

fn map(pairs: &[(&str, &str)]) -> Attributes {
    pairs
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect()
}

fn convert(xml: &str) -> String {
    fmi3_model_description(xml).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn root_and_co_simulation() {
    let out = convert(TOY);
    assert!(out.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"));
    assert_eq!(
        tags(&out, "fmiModelDescription"),
        [map(&[
            ("fmiVersion", "3.0"),
            ("modelName", "Toy"),
            ("instantiationToken", "{0a1b}"),
            ("description", "A toy &amp; its fmi3Error, not fmi2 itself"),
            ("variableNamingConvention", "flat"),
        ])]
    );
    assert_eq!(
        tags(&out, "CoSimulation"),
        [map(&[
            ("modelIdentifier", "Toy"),
            ("canHandleVariableCommunicationStepSize", "true"),
            ("maxOutputDerivativeOrder", "0"),
            ("canGetAndSetFMUState", "true"),
            ("canSerializeFMUState", "false"),
            ("hasEventMode", "false"),
            ("providesIntermediateUpdate", "false"),
            ("mightReturnEarlyFromDoStep", "false"),
            ("canReturnEarlyAfterIntermediateUpdate", "false"),
        ])]
    );
}

#[test]
fn units_types_categories_and_experiment() {
    let out = convert(TOY);
    assert_eq!(
        tags(&out, "Unit"),
        [map(&[("name", "m")]), map(&[("name", "rad")])]
    );
    assert_eq!(
        tags(&out, "BaseUnit"),
        [map(&[("m", "1")]), map(&[("rad", "1")])]
    );
    assert_eq!(
        tags(&out, "DisplayUnit"),
        [map(&[("name", "deg"), ("factor", "57.29577951308232")])]
    );
    assert_eq!(
        tags(&out, "Float64Type"),
        [map(&[
            ("name", "Length"),
            ("quantity", "Length"),
            ("unit", "m"),
            ("min", "-5")
        ])]
    );
    assert_eq!(
        tags(&out, "Int32Type"),
        [map(&[("name", "Count"), ("min", "0")])]
    );
    assert!(!out.contains("SimpleType"));
    assert_eq!(
        tags(&out, "Category"),
        [map(&[
            ("name", "logStatusError"),
            ("description", "Calls that return fmi3Error")
        ])]
    );
    assert_eq!(
        tags(&out, "DefaultExperiment"),
        [map(&[
            ("startTime", "0"),
            ("stopTime", "10"),
            ("stepSize", "0.5")
        ])]
    );
}

#[test]
fn variables_by_type() {
    let out = convert(TOY);
    assert_eq!(
        named(&out, "Float64", "k"),
        map(&[
            ("name", "k"),
            ("valueReference", "0"),
            ("causality", "parameter"),
            ("variability", "fixed"),
            ("initial", "exact"),
            ("description", "stiffness"),
            ("unit", "m"),
            ("min", "0"),
            ("start", "2.5"),
        ])
    );
    assert_eq!(
        named(&out, "Int32", "n"),
        map(&[
            ("name", "n"),
            ("valueReference", "1"),
            ("causality", "parameter"),
            ("variability", "fixed"),
            ("initial", "exact"),
            ("declaredType", "Count"),
            ("min", "1"),
            ("max", "9"),
            ("start", "3"),
        ])
    );
    // xs:boolean 1 as true; no initial where FMI 2.0 wrote none.
    assert_eq!(
        named(&out, "Boolean", "on"),
        map(&[
            ("name", "on"),
            ("valueReference", "2"),
            ("causality", "parameter"),
            ("variability", "tunable"),
            ("start", "true"),
        ])
    );
    // FMI 2.0's defaults written out: causality input, variability continuous.
    assert_eq!(
        named(&out, "Float64", "u"),
        map(&[
            ("name", "u"),
            ("valueReference", "10"),
            ("causality", "input"),
            ("variability", "continuous"),
            ("declaredType", "Length"),
            ("unit", "m"),
            ("start", "0"),
        ])
    );
    assert_eq!(named(&out, "Float64", "x")["valueReference"], "20");
    assert_eq!(named(&out, "Float64", "x")["variability"], "continuous");
    assert_eq!(named(&out, "Float64", "y")["unit"], "m");
}

#[test]
fn a_string_start_is_a_child_element() {
    let out = convert(TOY);
    let file = named(&out, "String", "file");
    assert_eq!(file.get("start"), None);
    assert_eq!(file["valueReference"], "3");
    let open = out.find("<String").unwrap();
    let close = open + out[open..].find("</String>").expect("String has content");
    assert_eq!(
        tags(&out[open..close], "Start"),
        [map(&[("value", "a &lt;b&gt;.txt")])]
    );
}

#[test]
fn exactly_one_independent_variable_time_first() {
    let out = convert(TOY);
    let independent: Vec<Attributes> = ["Float64", "Int32", "Boolean", "String"]
        .iter()
        .flat_map(|t| tags(&out, t))
        .filter(|a| a.get("causality").map(String::as_str) == Some("independent"))
        .collect();
    // No unit "s" among the units: none written (implicitly s).
    let time = map(&[
        ("name", "time"),
        ("valueReference", "999999"),
        ("causality", "independent"),
        ("variability", "continuous"),
        ("description", "Simulation time"),
    ]);
    assert_eq!(independent, std::slice::from_ref(&time));
    assert_eq!(tags(&out, "Float64")[0], time);
    assert_eq!(TIME_VALUE_REFERENCE, 999_999);
    // With a unit "s" declared, time has it.
    let with_seconds = TOY.replace(
        "<Unit name=\"m\">",
        "<Unit name=\"s\"><BaseUnit s=\"1\"/></Unit><Unit name=\"m\">",
    );
    assert_eq!(
        named(&convert(&with_seconds), "Float64", "time").get("unit"),
        Some(&"s".to_string())
    );
}

#[test]
fn model_structure_by_value_reference() {
    let out = convert(TOY);
    assert_eq!(
        tags(&out, "Output"),
        [
            map(&[("valueReference", "20"), ("dependencies", "10")]),
            map(&[("valueReference", "21"), ("dependencies", "")]),
        ]
    );
    assert_eq!(
        tags(&out, "InitialUnknown"),
        [
            map(&[
                ("valueReference", "20"),
                ("dependencies", "0 1 10"),
                ("dependenciesKind", "dependent fixed dependent"),
            ]),
            map(&[("valueReference", "21")]),
        ]
    );
    assert!(!out.contains("Unknown index") && !out.contains("<Outputs"));
    // FMI 3.0's order: every Output before the first InitialUnknown.
    assert!(out.rfind("<Output ").unwrap() < out.find("<InitialUnknown").unwrap());
}

#[test]
fn a_numbering_moves_value_references_by_type() {
    let numbering = Numbering {
        integer: 1000,
        string: 2000,
        ..Numbering::SAME
    };
    let out = fmi3_model_description_numbered(TOY, &numbering).unwrap();
    assert_eq!(named(&out, "Int32", "n")["valueReference"], "1001");
    assert_eq!(named(&out, "String", "file")["valueReference"], "2003");
    assert_eq!(named(&out, "Boolean", "on")["valueReference"], "2");
    assert_eq!(named(&out, "Float64", "k")["valueReference"], "0");
    assert_eq!(tags(&out, "InitialUnknown")[0]["dependencies"], "0 1001 10");
    let constants = crate::rust_constants(&numbering);
    for line in [
        "pub const NUMBERING: ::slowdrift_fmi::fmi3::Numbering",
        "pub const FLOAT64_OFFSET: u32 = 0;",
        "pub const INT32_OFFSET: u32 = 1000;",
        "pub const BOOLEAN_OFFSET: u32 = 0;",
        "pub const STRING_OFFSET: u32 = 2000;",
    ] {
        assert!(constants.contains(line), "{line} in\n{constants}");
    }
}

#[test]
fn a_value_reference_used_twice_names_both_variables() {
    // FMI 2.0 allows Integer 0 beside Real 0; FMI 3.0 does not.
    let shared = TOY.replace(
        r#"name="n" valueReference="1""#,
        r#"name="n" valueReference="0""#,
    );
    let error = fmi3_model_description(&shared).unwrap_err();
    let Error::DuplicateValueReference {
        value_reference,
        first,
        second,
    } = &error
    else {
        panic!("{error:?}");
    };
    assert_eq!(*value_reference, 0);
    assert!(first.starts_with("ScalarVariable \"k\""), "{first}");
    assert!(second.starts_with("ScalarVariable \"n\""), "{second}");
    let message = error.to_string();
    assert!(
        message.contains("\"k\"") && message.contains("\"n\""),
        "{message}"
    );
    // A numbering that separates the types converts it.
    let numbering = Numbering {
        integer: 100,
        ..Numbering::SAME
    };
    let out = fmi3_model_description_numbered(&shared, &numbering).unwrap();
    assert_eq!(named(&out, "Int32", "n")["valueReference"], "100");
}

#[test]
fn time_cannot_be_taken() {
    let vr = TOY.replace(r#"valueReference="21""#, r#"valueReference="999999""#);
    match fmi3_model_description(&vr) {
        Err(Error::DuplicateValueReference { first, second, .. }) => {
            assert!(first.starts_with("time"), "{first}");
            assert!(second.starts_with("ScalarVariable \"y\""), "{second}");
        }
        other => panic!("{other:?}"),
    }
    let name = TOY.replace(r#"name="y""#, r#"name="time""#);
    assert!(matches!(
        fmi3_model_description(&name),
        Err(Error::InvalidValue { attribute, .. }) if attribute == "name"
    ));
    let independent = TOY.replace(r#"causality="input""#, r#"causality="independent""#);
    match fmi3_model_description(&independent) {
        Err(Error::InvalidValue {
            element, attribute, ..
        }) => {
            assert!(element.starts_with("ScalarVariable \"u\""), "{element}");
            assert_eq!(attribute, "causality");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn what_is_not_converted_is_named() {
    let enumeration = TOY.replace(r#"<Boolean start="1"/>"#, r#"<Enumeration start="1"/>"#);
    match fmi3_model_description(&enumeration) {
        Err(Error::UnsupportedElement { parent, element }) => {
            assert!(parent.starts_with("ScalarVariable \"on\""), "{parent}");
            assert!(element.starts_with("Enumeration"), "{element}");
        }
        other => panic!("{other:?}"),
    }
    let attribute = TOY.replace(r#"canInterpolateInputs="false""#, r#"bogus="1""#);
    assert!(matches!(
        fmi3_model_description(&attribute),
        Err(Error::UnsupportedAttribute { element, attribute })
            if element.starts_with("CoSimulation") && attribute == "bogus"
    ));
    let index = TOY.replace(
        r#"<Unknown index="7" dependencies=""/>"#,
        r#"<Unknown index="8"/>"#,
    );
    match fmi3_model_description(&index) {
        Err(Error::InvalidValue {
            element,
            attribute,
            value,
            ..
        }) => {
            assert!(
                element.starts_with("Outputs/Unknown index=\"8\""),
                "{element}"
            );
            assert_eq!((attribute.as_str(), value.as_str()), ("index", "8"));
        }
        other => panic!("{other:?}"),
    }
    let continuous = TOY.replace(
        r#"name="n" valueReference="1" causality="parameter" variability="fixed""#,
        r#"name="n" valueReference="1" causality="output" variability="continuous""#,
    );
    assert!(matches!(
        fmi3_model_description(&continuous),
        Err(Error::InvalidValue { element, attribute, .. })
            if element.starts_with("ScalarVariable \"n\"") && attribute == "variability"
    ));
    let version = TOY.replace(r#"fmiVersion="2.0""#, r#"fmiVersion="3.0""#);
    assert_eq!(
        fmi3_model_description(&version),
        Err(Error::NotFmi2 {
            fmi_version: "3.0".into()
        })
    );
    let unclosed = &TOY[..TOY.len() - 30];
    assert!(matches!(
        fmi3_model_description(unclosed),
        Err(Error::Xml { .. })
    ));
}

/// The toy's outputs x (Real 20) and y (Real 21) named as the elements of an array `p`:
/// p1, p2 at 20, 21 become one Float64 `p` of dimension 2 at 20 (no p1 or p2 left), its
/// Output and InitialUnknown once, and a dependency on an element one on the array; an
/// element missing, one beyond the count, or a value reference out of order is refused.
#[test]
fn an_array_is_one_variable_of_its_elements() {
    const P: ArrayVariable = ArrayVariable {
        name: "p",
        first: 20,
        count: 2,
        description: "the two outputs",
    };
    let toy = TOY
        .replace(
            r#"name="x" valueReference="20""#,
            r#"name="p1" valueReference="20""#,
        )
        .replace(
            r#"name="y" valueReference="21""#,
            r#"name="p2" valueReference="21""#,
        )
        .replace(
            r#"<Unknown index="7"/>"#,
            r#"<Unknown index="7" dependencies="6 7"/>"#,
        );
    let numbering = Numbering {
        arrays: &[P],
        ..Numbering::SAME
    };
    let out = fmi3_model_description_numbered(&toy, &numbering).unwrap();
    let p = named(&out, "Float64", "p");
    assert_eq!(
        (p["valueReference"].as_str(), p["description"].as_str()),
        ("20", "the two outputs")
    );
    assert_eq!(tags(&out, "Dimension"), vec![map(&[("start", "2")])]);
    assert!(!out.contains("\"p1\"") && !out.contains("\"p2\"") && !out.contains("\"21\""));
    let outputs: Vec<String> = tags(&out, "Output")
        .iter()
        .map(|o| o["valueReference"].clone())
        .collect();
    assert_eq!(outputs, ["20"]);
    assert_eq!(tags(&out, "InitialUnknown").len(), 1);
    // Elements missing, beyond the count, out of order.
    for (from, to) in [
        (r#"name="p2""#, r#"name="q2""#),
        (r#"name="u""#, r#"name="p3""#),
        (
            r#"name="p2" valueReference="21""#,
            r#"name="p2" valueReference="22""#,
        ),
    ] {
        let wrong = toy.replace(from, to);
        let err = fmi3_model_description_numbered(&wrong, &numbering).unwrap_err();
        assert!(err.to_string().contains('p'), "{err}");
    }
}
