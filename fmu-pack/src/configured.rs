//! An FMU of a user's configuration (`fmu-pack --config FILE`): the same library, with the
//! configuration as the FMU's embedded one (`resources/platform.toml`, the drift file it
//! names beside it: [`write_configuration`]) and a modelDescription.xml whose start values
//! are that configuration's values, as a master that sets nothing reads them
//! ([`Parameters::configuration_values`]). A master that shows the start values, or writes
//! them all back (fmpy's `apply_default_start_values`, a system tool), then shows and runs
//! the user's platform, not the embedded default. The GUID is the configuration's own
//! ([`slowdrift::fmi2::resources::configuration_guid`]), which the library accepts beside
//! its built-in one; the DefaultExperiment is the configuration's run.

use slowdrift::fmi2::model_description::VariableInfo;
use slowdrift::fmi2::parameters::{FmuValue, Parameters};
use slowdrift::fmi2::resources::write_configuration;
use slowdrift::scenario::Scenario;
use std::path::Path;

/// What [`prepare`] made: the model description and the resources folder's files.
pub struct Configured {
    pub model_description: String,
    /// The files of the resources folder, by name.
    pub resources: Vec<String>,
    /// The run of the configuration: start time, stop time (None: open-ended).
    pub experiment: (f64, Option<f64>),
}

/// Writes the resources of the configuration `config` into `resources` and makes the model
/// description from `xml` (the library's own) with `model_name`.
pub fn prepare(
    config: &Path,
    resources: &Path,
    xml: &str,
    model_name: &str,
) -> Result<Configured, String> {
    if resources.exists() {
        std::fs::remove_dir_all(resources).map_err(|e| format!("{}: {e}", resources.display()))?;
    }
    let packed = write_configuration(config, resources).map_err(|e| e.to_string())?;
    let values = Parameters::configuration_values(&packed.scenario);
    let model_description =
        with_configuration(xml, &values, &packed.scenario, &packed.guid, model_name)?;
    let mut names = Vec::new();
    for entry in std::fs::read_dir(resources).map_err(|e| e.to_string())? {
        let entry = entry.map_err(|e| e.to_string())?;
        names.push(entry.file_name().to_string_lossy().into_owned());
    }
    names.sort();
    let run = &packed.scenario.run;
    let stop = run
        .duration
        .is_finite()
        .then_some(run.start_time + run.duration);
    Ok(Configured {
        model_description,
        resources: names,
        experiment: (run.start_time, stop),
    })
}

/// `xml` with the start value of every parameter in `values`, the GUID, the model name and
/// the DefaultExperiment of `scenario`'s run written in; every other byte kept.
fn with_configuration(
    xml: &str,
    values: &[(&'static VariableInfo, FmuValue)],
    scenario: &Scenario,
    guid: &str,
    model_name: &str,
) -> Result<String, String> {
    let mut xml = replace_attribute(xml, 0, "guid", guid)?;
    xml = replace_attribute(&xml, 0, "modelName", &escape(model_name))?;
    for (info, value) in values {
        let text = match value {
            // Debug: the shortest text that reads back to the same double, with an
            // exponent where that is shorter (1e-7, not 0.0000001), as xs:double allows.
            FmuValue::Real(x) => format!("{x:?}"),
            FmuValue::Integer(i) => i.to_string(),
            FmuValue::String(s) => escape(s),
        };
        let at = xml
            .find(&format!("<ScalarVariable name=\"{}\"", info.name))
            .ok_or_else(|| format!("modelDescription.xml has no variable {}", info.name))?;
        let end = xml[at..]
            .find("</ScalarVariable>")
            .map(|e| at + e)
            .ok_or_else(|| format!("variable {} is not closed", info.name))?;
        let start = xml[at..end]
            .find(" start=\"")
            .ok_or_else(|| format!("variable {} has no start value", info.name))?;
        xml = replace_attribute(&xml, at + start, "start", &text)?;
    }
    let run = &scenario.run;
    let experiment = xml
        .find("<DefaultExperiment ")
        .ok_or("modelDescription.xml has no DefaultExperiment")?;
    xml = replace_attribute(
        &xml,
        experiment,
        "startTime",
        &format!("{:?}", run.start_time),
    )?;
    if run.duration.is_finite() {
        let stop = run.start_time + run.duration;
        xml = replace_attribute(&xml, experiment, "stopTime", &format!("{stop:?}"))?;
    }
    xml = replace_attribute(
        &xml,
        experiment,
        "stepSize",
        &format!("{:?}", run.time_step),
    )?;
    Ok(xml)
}

/// `xml` with the first attribute `name="..."` at or after byte `from` given `value`.
fn replace_attribute(xml: &str, from: usize, name: &str, value: &str) -> Result<String, String> {
    let key = format!(" {name}=\"");
    let start = xml[from..]
        .find(&key)
        .map(|i| from + i + key.len())
        .ok_or_else(|| format!("modelDescription.xml has no attribute {name}"))?;
    let end = xml[start..]
        .find('"')
        .map(|i| start + i)
        .ok_or_else(|| format!("attribute {name} is not closed"))?;
    Ok(format!("{}{value}{}", &xml[..start], &xml[end..]))
}

/// Text for an XML attribute value.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;
    use slowdrift::fmi2::model_description::VARIABLES;
    use slowdrift::scenario::file;

    const XML: &str = include_str!("../../modelDescription/modelDescription.xml");

    /// The start value of `name` as written in `xml`.
    fn start_of(xml: &str, name: &str) -> String {
        let at = xml
            .find(&format!("<ScalarVariable name=\"{name}\""))
            .unwrap();
        let element = &xml[at..at + xml[at..].find("</ScalarVariable>").unwrap()];
        let start = element.find(" start=\"").unwrap() + 8;
        element[start..start + element[start..].find('"').unwrap()].to_string()
    }

    /// The example configuration's values land in the start values, read back as numbers
    /// equal to the file's (degrees turned to radians), and nothing else of the XML changes
    /// but the GUID, the model name and the DefaultExperiment.
    #[test]
    fn the_start_values_are_the_configurations() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data/example.toml");
        let scenario =
            file::load(&path, slowdrift::scenario::limits::DEFAULT_MEMORY_LIMIT).unwrap();
        let values = Parameters::configuration_values(&scenario);
        let xml = with_configuration(XML, &values, &scenario, "{guid}", "example").unwrap();
        let number = |name: &str| start_of(&xml, name).parse::<f64>().unwrap();
        // The example's text: hs = 3.0, tp = 9.0, gamma = 3.3, direction_deg = 30.0,
        // current 0.5 m/s towards 30 deg, cd = 0.7 (combined), stiffness 8e4, 8e4, 7.7e7.
        assert_eq!(number("Hs"), 3.0);
        assert_eq!(number("Tp"), 9.0);
        assert_eq!(number("gamma"), 3.3);
        assert_eq!(number("waveDirection"), 30f64.to_radians());
        assert_eq!(number("currentSpeed"), 0.5);
        assert_eq!(number("currentDirection"), 30f64.to_radians());
        assert_eq!(number("cd"), 0.7);
        assert_eq!(number("stiffnessSurge"), 8.0e4);
        assert_eq!(number("stiffnessYaw"), 7.7e7);
        assert_eq!(number("dragModel"), 2.0, "combined");
        assert_eq!(number("driftDamping"), 2.0, "aranha");
        assert_eq!(start_of(&xml, "hydroDatabase"), "");
        assert!(xml.contains(" guid=\"{guid}\"") && xml.contains(" modelName=\"example\""));
        assert!(xml.contains(
            "<DefaultExperiment startTime=\"0.0\" stopTime=\"10800.0\" stepSize=\"1.0\"/>"
        ));
        // Outside the start values, the GUID, the name and the experiment: the same lines.
        let changed = XML.lines().zip(xml.lines()).filter(|(a, b)| a != b).count();
        let parameters = VARIABLES
            .iter()
            .filter(|v| v.causality == slowdrift::fmi2::model_description::Causality::Parameter)
            .count();
        assert_eq!(XML.lines().count(), xml.lines().count());
        assert!(changed <= parameters + 3, "{changed} lines changed");
    }
}
