//! Everything of the model description before its variables: the root's attributes,
//! `CoSimulation`, `UnitDefinitions`, `TypeDefinitions`, `LogCategories` and
//! `DefaultExperiment`.

use crate::attributes::{carried, describe};
use crate::tree::Element;
use crate::writer::{Attributes, Writer};
use crate::Error;

/// The FMI 2.0 root attributes FMI 3.0 has with the same meaning (`guid` is renamed
/// `instantiationToken`; `numberOfEventIndicators` has no counterpart and is dropped).
const ROOT_KEPT: [&str; 9] = [
    "modelName",
    "description",
    "author",
    "version",
    "copyright",
    "license",
    "generationTool",
    "generationDateAndTime",
    "variableNamingConvention",
];

/// The FMI 2.0 `CoSimulation` attributes FMI 3.0 has with the same meaning.
const CO_SIMULATION_KEPT: [&str; 5] = [
    "modelIdentifier",
    "needsExecutionTool",
    "canHandleVariableCommunicationStepSize",
    "maxOutputDerivativeOrder",
    "canBeInstantiatedOnlyOncePerProcess",
];

/// FMI 2.0 `CoSimulation` attributes renamed in FMI 3.0.
const CO_SIMULATION_RENAMED: [(&str, &str); 3] = [
    ("canGetAndSetFMUstate", "canGetAndSetFMUState"),
    ("canSerializeFMUstate", "canSerializeFMUState"),
    (
        "providesDirectionalDerivative",
        "providesDirectionalDerivatives",
    ),
];

/// FMI 2.0-only `CoSimulation` attributes, dropped: FMI 3.0 has none of the same meaning.
const CO_SIMULATION_DROPPED: [&str; 3] = [
    "canInterpolateInputs",
    "canRunAsynchronuously",
    "canNotUseMemoryManagementFunctions",
];

/// The FMI 3.0 co-simulation capabilities FMI 2.0 did not have, all off: no event mode,
/// no intermediate update, no early return.
const CO_SIMULATION_ADDED: [(&str, &str); 4] = [
    ("hasEventMode", "false"),
    ("providesIntermediateUpdate", "false"),
    ("mightReturnEarlyFromDoStep", "false"),
    ("canReturnEarlyAfterIntermediateUpdate", "false"),
];

/// The root's FMI 3.0 attributes.
pub(crate) fn root_attributes(root: &Element) -> Result<Attributes, Error> {
    let version = root.attribute("fmiVersion").unwrap_or("");
    if version != "2.0" {
        return Err(Error::NotFmi2 {
            fmi_version: version.into(),
        });
    }
    for required in ["modelName", "guid"] {
        if root.attribute(required).is_none() {
            return Err(Error::MissingAttribute {
                element: describe(root),
                attribute: required,
            });
        }
    }
    let rest = strip(root, &["fmiVersion", "numberOfEventIndicators"]);
    let carried = carried(&rest, &ROOT_KEPT, &[("guid", "instantiationToken")])?;
    // modelName and instantiationToken first, then the rest in their order.
    let first = ["modelName", "instantiationToken"];
    let mut out = vec![("fmiVersion".to_string(), "3.0".to_string())];
    for key in first {
        out.extend(carried.iter().filter(|(k, _)| k == key).cloned());
    }
    out.extend(
        carried
            .into_iter()
            .filter(|(k, _)| !first.contains(&k.as_str())),
    );
    Ok(out)
}

/// `<CoSimulation>` from FMI 2.0's.
pub(crate) fn co_simulation(e: &Element, w: &mut Writer) -> Result<(), Error> {
    if let Some(child) = e.children.first() {
        return Err(Error::UnsupportedElement {
            parent: describe(e),
            element: describe(child),
        });
    }
    let rest = strip(e, &CO_SIMULATION_DROPPED);
    let mut attributes = carried(&rest, &CO_SIMULATION_KEPT, &CO_SIMULATION_RENAMED)?;
    if e.attribute("modelIdentifier").is_none() {
        return Err(Error::MissingAttribute {
            element: describe(e),
            attribute: "modelIdentifier",
        });
    }
    attributes.extend(
        CO_SIMULATION_ADDED
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string())),
    );
    w.empty("CoSimulation", &attributes);
    Ok(())
}

/// `<UnitDefinitions>`: the same elements and attributes in FMI 3.0.
pub(crate) fn unit_definitions(e: &Element, w: &mut Writer) -> Result<(), Error> {
    const BASE: [&str; 10] = [
        "kg", "m", "s", "A", "K", "mol", "cd", "rad", "factor", "offset",
    ];
    w.start("UnitDefinitions", &[]);
    for unit in &e.children {
        expect_name(e, unit, "Unit")?;
        let attributes = carried(unit, &["name"], &[])?;
        if unit.children.is_empty() {
            w.empty("Unit", &attributes);
            continue;
        }
        w.start("Unit", &attributes);
        for part in &unit.children {
            match part.name.as_str() {
                "BaseUnit" => w.empty("BaseUnit", &carried(part, &BASE, &[])?),
                "DisplayUnit" => w.empty(
                    "DisplayUnit",
                    &carried(part, &["name", "factor", "offset"], &[])?,
                ),
                _ => return Err(unsupported(unit, part)),
            }
        }
        w.end("Unit");
    }
    w.end("UnitDefinitions");
    Ok(())
}

/// `<TypeDefinitions>`: each `SimpleType` as the FMI 3.0 type element of its base type.
pub(crate) fn type_definitions(e: &Element, w: &mut Writer) -> Result<(), Error> {
    w.start("TypeDefinitions", &[]);
    for simple in &e.children {
        expect_name(e, simple, "SimpleType")?;
        let [base] = &simple.children[..] else {
            return Err(Error::InvalidValue {
                element: describe(simple),
                attribute: "its content".into(),
                value: format!("{} elements", simple.children.len()),
                expected: "one element: Real, Integer, Boolean or String",
            });
        };
        let (name, kept): (&str, &[&str]) = match base.name.as_str() {
            "Real" => (
                "Float64Type",
                &[
                    "quantity",
                    "unit",
                    "displayUnit",
                    "relativeQuantity",
                    "min",
                    "max",
                    "nominal",
                    "unbounded",
                ],
            ),
            "Integer" => ("Int32Type", &["quantity", "min", "max"]),
            "Boolean" => ("BooleanType", &[]),
            "String" => ("StringType", &[]),
            _ => return Err(unsupported(simple, base)),
        };
        let mut attributes = carried(simple, &["name", "description"], &[])?;
        attributes.extend(carried(base, kept, &[])?);
        w.empty(name, &attributes);
    }
    w.end("TypeDefinitions");
    Ok(())
}

/// `<LogCategories>`: the same in FMI 3.0 (their descriptions in FMI 3.0's words).
pub(crate) fn log_categories(e: &Element, w: &mut Writer) -> Result<(), Error> {
    w.start("LogCategories", &[]);
    for category in &e.children {
        expect_name(e, category, "Category")?;
        w.empty(
            "Category",
            &carried(category, &["name", "description"], &[])?,
        );
    }
    w.end("LogCategories");
    Ok(())
}

/// `<DefaultExperiment>`: the same attributes in FMI 3.0.
pub(crate) fn default_experiment(e: &Element, w: &mut Writer) -> Result<(), Error> {
    let kept = ["startTime", "stopTime", "tolerance", "stepSize"];
    w.empty("DefaultExperiment", &carried(e, &kept, &[])?);
    Ok(())
}

/// An error unless `child` of `parent` is named `name`.
fn expect_name(parent: &Element, child: &Element, name: &str) -> Result<(), Error> {
    if child.name == name {
        Ok(())
    } else {
        Err(unsupported(parent, child))
    }
}

fn unsupported(parent: &Element, child: &Element) -> Error {
    Error::UnsupportedElement {
        parent: describe(parent),
        element: describe(child),
    }
}

/// `e`'s attributes without `dropped` (its children left out).
fn strip(e: &Element, dropped: &[&str]) -> Element {
    Element {
        name: e.name.clone(),
        attributes: e
            .attributes
            .iter()
            .filter(|(k, _)| !dropped.contains(&k.as_str()))
            .cloned()
            .collect(),
        children: Vec::new(),
        line: e.line,
    }
}
