//! The FMI 2.0 model description as Rust constants.
//!
//! `build.rs` checks `modelDescription/modelDescription.xml` (unique names, unique value
//! references per type, legal causality/variability/initial combinations, ModelStructure)
//! and generates from it [`GUID`], [`MODEL_IDENTIFIER`], the value references in [`vr`],
//! the start values in [`start`] and the table [`VARIABLES`]. The FMU layer uses these,
//! so the XML is the single source of truth.

/// Base type of a model variable (the FMI 2.0 element inside `ScalarVariable`). No
/// Enumeration: build.rs refuses one, as libcosim and ecos do not register them (a mode is
/// an Integer with its codes in the description).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum VariableType {
    Real,
    Integer,
    Boolean,
    String,
}

/// FMI 2.0 causality.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Causality {
    Parameter,
    CalculatedParameter,
    Input,
    Output,
    Local,
    Independent,
}

/// FMI 2.0 variability.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Variability {
    Constant,
    Fixed,
    Tunable,
    Discrete,
    Continuous,
}

/// The start value of a variable, as its type has it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Start {
    None,
    Real(f64),
    Integer(i32),
    String(&'static str),
}

/// One model variable of the model description.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VariableInfo {
    /// The variable's name in the XML.
    pub name: &'static str,
    /// Its value reference (unique within its type).
    pub value_reference: u32,
    /// Its base type.
    pub var_type: VariableType,
    /// Its start value.
    pub start: Start,
    pub causality: Causality,
    pub variability: Variability,
}

/// Looks a variable up by its access type and value reference.
pub fn find(var_type: VariableType, value_reference: u32) -> Option<&'static VariableInfo> {
    VARIABLES
        .iter()
        .find(|v| v.var_type == var_type && v.value_reference == value_reference)
}

include!(concat!(env!("OUT_DIR"), "/model_description.rs"));

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;

    /// The XML, read independently of build.rs (which uses quick-xml).
    const XML: &str = include_str!("../../modelDescription/modelDescription.xml");

    /// The value of `key="..."` inside one tag's text, by plain string scanning.
    fn attr<'a>(tag: &'a str, key: &str) -> Option<&'a str> {
        let pat = format!(" {key}=\"");
        let start = tag.find(&pat)? + pat.len();
        let len = tag[start..].find('"')?;
        Some(&tag[start..start + len])
    }

    /// The text of every `<name ...>` or `<name .../>` tag in `section`.
    fn tags<'a>(section: &'a str, name: &str) -> Vec<&'a str> {
        let open = format!("<{name}");
        let mut out = Vec::new();
        let mut rest = section;
        while let Some(i) = rest.find(&open) {
            let tail = &rest[i..];
            let end = tail.find('>').expect("tag closes");
            let next = tail.as_bytes()[open.len()];
            if next.is_ascii_whitespace() || next == b'>' || next == b'/' {
                out.push(&tail[..end]);
            }
            rest = &tail[end..];
        }
        out
    }

    /// The text between `<name>` and `</name>`, comments removed.
    fn section(name: &str) -> String {
        let start = XML.find(&format!("<{name}>")).expect("section opens");
        let end = XML.find(&format!("</{name}>")).expect("section closes");
        let mut s = &XML[start..end];
        let mut out = String::new();
        while let Some(i) = s.find("<!--") {
            out.push_str(&s[..i]);
            s = &s[i + s[i..].find("-->").expect("comment closes") + 3..];
        }
        out.push_str(s);
        out
    }

    #[test]
    fn table_matches_the_xml_scanned_as_text() {
        let vars = section("ModelVariables");
        let names: Vec<&str> = tags(&vars, "ScalarVariable")
            .iter()
            .map(|t| attr(t, "name").expect("name"))
            .collect();
        let table: Vec<&str> = VARIABLES.iter().map(|v| v.name).collect();
        assert_eq!(names, table);
        assert_eq!(NUMBER_OF_VARIABLES, VARIABLES.len());
        assert_eq!(attr(XML, "guid"), Some(GUID));
        assert_eq!(MODEL_IDENTIFIER, "SlowDrift");
    }

    /// What every master reads alike (checked here on the text, independently of build.rs,
    /// which refuses the same): no Enumeration, which libcosim and ecos skip; every Real with
    /// its own unit (OMSimulator does not inherit one from a declaredType), declared in
    /// UnitDefinitions and equal to its declaredType's.
    #[test]
    fn variables_are_master_neutral() {
        let unit_definitions = section("UnitDefinitions");
        let units: HashSet<&str> = tags(&unit_definitions, "Unit")
            .iter()
            .map(|t| attr(t, "name").expect("name"))
            .collect();
        let types = section("TypeDefinitions");
        let type_unit = |name: &str| -> Option<String> {
            let open = format!("<SimpleType name=\"{name}\">");
            let body = &types[types.find(&open)?..];
            let body = &body[..body.find("</SimpleType>").expect("closes")];
            tags(body, "Real")
                .first()
                .and_then(|t| attr(t, "unit"))
                .map(str::to_string)
        };
        let vars = section("ModelVariables");
        let mut reals = 0;
        for block in vars.split("<ScalarVariable").skip(1) {
            let name = attr(block, "name").expect("name");
            assert!(!block.contains("<Enumeration"), "{name} is an Enumeration");
            let Some(real) = tags(block, "Real").first().copied() else {
                continue;
            };
            reals += 1;
            let unit = attr(real, "unit").unwrap_or_else(|| panic!("{name} has no unit"));
            assert!(units.contains(unit), "{name}: unit {unit} is not declared");
            if let Some(t) = attr(real, "declaredType") {
                let declared = type_unit(t).unwrap_or_else(|| panic!("{name}: type {t}"));
                assert_eq!(declared, unit, "{name}: declaredType {t}");
            }
        }
        let expected = VARIABLES
            .iter()
            .filter(|v| v.var_type == VariableType::Real)
            .count();
        assert_eq!(reals, expected);
    }

    #[test]
    fn names_are_unique() {
        let names: HashSet<&str> = VARIABLES.iter().map(|v| v.name).collect();
        assert_eq!(names.len(), VARIABLES.len());
    }

    #[test]
    fn value_references_are_unique_per_type() {
        let keys: HashSet<(VariableType, u32)> = VARIABLES
            .iter()
            .map(|v| (v.var_type, v.value_reference))
            .collect();
        assert_eq!(keys.len(), VARIABLES.len());
        for v in VARIABLES {
            assert_eq!(find(v.var_type, v.value_reference), Some(v));
        }
    }

    #[test]
    fn every_output_is_in_model_structure() {
        let outputs: Vec<usize> = VARIABLES
            .iter()
            .enumerate()
            .filter(|(_, v)| v.causality == Causality::Output)
            .map(|(i, _)| i + 1)
            .collect();
        assert_eq!(outputs.len(), 38);
        let indices = |name: &str| -> Vec<usize> {
            tags(&section(name), "Unknown")
                .iter()
                .map(|t| attr(t, "index").expect("index").parse().expect("number"))
                .collect()
        };
        // Every output here is initial="calculated", and there are no calculated parameters.
        assert_eq!(indices("Outputs"), outputs);
        assert_eq!(indices("InitialUnknowns"), outputs);
        // No output depends directly on an input.
        for t in tags(&section("Outputs"), "Unknown") {
            assert_eq!(attr(t, "dependencies"), Some(""), "{t}");
        }
    }

    #[test]
    fn causalities_and_value_references() {
        use Causality::*;
        let inputs = [vr::FX_EXT, vr::FY_EXT, vr::MZ_EXT, vr::WIND_VELOCITY_EXT];
        let names = ["Fx_ext", "Fy_ext", "Mz_ext", "windVelocity_ext"];
        for (v, expected) in inputs.iter().zip(names) {
            let info = find(VariableType::Real, *v).expect("input");
            assert_eq!((info.name, info.causality), (expected, Input));
        }
        assert_eq!(
            find(VariableType::Real, vr::X).map(|v| v.causality),
            Some(Output)
        );
        assert_eq!(
            find(VariableType::Integer, vr::DRAG_MODEL).map(|v| v.causality),
            Some(Parameter)
        );
        assert_eq!(
            find(VariableType::String, vr::HYDRO_DATABASE).map(|v| v.causality),
            Some(Parameter)
        );
    }

    #[test]
    fn start_values_are_physical() {
        // (name, start, lowest, highest), checked in a loop over the generated constants.
        let reals = [
            ("Hs", start::HS, 1e-3, 30.0),
            ("Tp", start::TP, 1.0, 30.0),
            ("spreadingExponent", start::SPREADING_EXPONENT, 0.0, 100.0),
            ("currentSpeed", start::CURRENT_SPEED, 0.0, 5.0),
            ("windSpeed", start::WIND_SPEED, 0.0, 0.0),
            (
                "windReferenceHeight",
                start::WIND_REFERENCE_HEIGHT,
                1.0,
                100.0,
            ),
            ("cdSlow", start::CD_SLOW, 0.0, 3.0),
            ("cdFast", start::CD_FAST, 0.0, 3.0),
            ("cd", start::CD, 0.0, 3.0),
            ("stiffnessSurge", start::STIFFNESS_SURGE, 1.0, 1e9),
            ("stiffnessSway", start::STIFFNESS_SWAY, 1.0, 1e9),
            ("stiffnessYaw", start::STIFFNESS_YAW, 1.0, 1e13),
            ("stepSize", start::STEP_SIZE, 1e-3, 10.0),
        ];
        for (name, x, lo, hi) in reals {
            assert!((lo..=hi).contains(&x), "{name} = {x} outside [{lo}, {hi}]");
        }
        // 0 selects the DNV default; otherwise gamma >= 1.
        let gamma = [start::GAMMA];
        assert!(gamma.iter().all(|&g| g == 0.0 || g >= 1.0));
        let integers = [
            ("nDirections", start::N_DIRECTIONS, 1, 360),
            ("dragModel", start::DRAG_MODEL, 0, 2),
            ("driftDamping", start::DRIFT_DAMPING, 0, 2),
            ("windSpectrum", start::WIND_SPECTRUM, 0, 7),
        ];
        for (name, x, lo, hi) in integers {
            assert!((lo..=hi).contains(&x), "{name} = {x} outside [{lo}, {hi}]");
        }
        assert_eq!(start::HYDRO_DATABASE, "");
        assert_eq!(
            [
                start::FX_EXT,
                start::FY_EXT,
                start::MZ_EXT,
                start::WIND_VELOCITY_EXT
            ],
            [0.0; 4],
            "inputs start at zero"
        );
    }
}
