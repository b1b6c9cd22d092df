//! The FMI 3.0 co-simulation `modelDescription.xml` of an FMU, generated from its FMI 2.0
//! one, so that a variable or a unit is written once (in the hand-written FMI 2.0 XML) and
//! both descriptions follow. [`fmi3_model_description`] is a pure function of the text: the
//! FMUs' build scripts call it, and so can `fmu-pack` on a description it rewrote.
//!
//! The rules (FMI 3.0.2, §2.4; docs/fmu.md, "FMI 3.0 model description"):
//!
//! - the root: `fmiVersion="3.0"`, `instantiationToken` = the FMI 2.0 `guid` (the same
//!   string), the other attributes carried over (`numberOfEventIndicators` dropped);
//! - `CoSimulation`: the flags FMI 3.0 has with the same meaning carried over
//!   (`canGetAndSetFMUstate` -> `canGetAndSetFMUState`, `canSerializeFMUstate` ->
//!   `canSerializeFMUState`, `providesDirectionalDerivative` ->
//!   `providesDirectionalDerivatives`), FMI 2.0's own (`canInterpolateInputs`,
//!   `canRunAsynchronuously`, `canNotUseMemoryManagementFunctions`) dropped, and no event
//!   mode, intermediate update or early return;
//! - `UnitDefinitions`, `LogCategories`, `DefaultExperiment`: the same;
//!   `TypeDefinitions`: `SimpleType` + `Real` -> `Float64Type` (`Integer` -> `Int32Type`,
//!   `Boolean` -> `BooleanType`, `String` -> `StringType`);
//! - each `ScalarVariable` as `Float64` (Real), `Int32` (Integer), `Boolean` or `String`,
//!   with its attributes (causality and variability always written: their defaults differ);
//!   a String's start as a `<Start value=".."/>` child; value references by [`Numbering`],
//!   unique across all variables or an error that names both variables;
//! - the independent variable `time` (Float64, continuous, no start, value reference
//!   [`TIME_VALUE_REFERENCE`], unit `s` when the units declare `s`, else implicitly s),
//!   first;
//! - `ModelStructure`: `Outputs`, `Derivatives`, `InitialUnknowns` -> `Output`,
//!   `ContinuousStateDerivative`, `InitialUnknown`, the 1-based indices of `index` and
//!   `dependencies` as value references, `dependenciesKind` kept;
//! - descriptions name FMI 3.0's functions and statuses (`fmi2Error` -> `fmi3Error`);
//!   comments are dropped.
//!
//! Anything else of FMI 2.0 (ModelExchange, Enumeration, VendorAnnotations, an
//! independent variable of its own...) is an [`Error`] naming it.

mod attributes;
mod error;
mod header;
mod structure;
mod tree;
mod variables;
mod writer;

pub use error::Error;

use attributes::only_child;
use variables::BaseType;

/// The value reference of the independent variable `time`: the FMI layer's
/// (`slowdrift_fmi::fmi3`, whose functions answer it), one constant for the descriptions and
/// the functions.
pub use slowdrift_fmi::fmi3::TIME_VALUE_REFERENCE;

/// How FMI 2.0 value references become FMI 3.0's: the FMI layer's numbering (its functions
/// undo it), one type for the descriptions and the functions.
pub use slowdrift_fmi::fmi3::{ArrayVariable, Numbering};

/// The offset `numbering` adds to a value reference of the FMI 2.0 base type `ty`.
fn offset(numbering: &Numbering, ty: BaseType) -> u32 {
    match ty {
        BaseType::Real => numbering.real,
        BaseType::Integer => numbering.integer,
        BaseType::Boolean => numbering.boolean,
        BaseType::String => numbering.string,
    }
}

/// Rust constants of `numbering`, for a build script to write beside the XML (an FMU's
/// FMI 3.0 code reads them): the four offsets and `NUMBERING`, the layer's
/// [`Numbering`] that the FMU's `fmi3*` functions take (with its arrays).
pub fn rust_constants(numbering: &Numbering) -> String {
    let Numbering {
        real,
        integer,
        boolean,
        string,
        arrays,
    } = *numbering;
    let arrays: String = arrays
        .iter()
        .map(|a| {
            format!(
                "\x20       ::slowdrift_fmi::fmi3::ArrayVariable {{ name: {:?}, first: {}, count: {}, \
                 description: {:?} }},\n",
                a.name, a.first, a.count, a.description
            )
        })
        .collect();
    format!(
        "/// FMI 3.0 value reference = FMI 2.0 value reference + the offset of its FMI 2.0 \
         type.\n\
         pub const FLOAT64_OFFSET: u32 = {real};\n\
         /// See [`FLOAT64_OFFSET`].\n\
         pub const INT32_OFFSET: u32 = {integer};\n\
         /// See [`FLOAT64_OFFSET`].\n\
         pub const BOOLEAN_OFFSET: u32 = {boolean};\n\
         /// See [`FLOAT64_OFFSET`].\n\
         pub const STRING_OFFSET: u32 = {string};\n\
         /// The offsets as the FMI layer's numbering, for the `fmi3*` functions.\n\
         pub const NUMBERING: ::slowdrift_fmi::fmi3::Numbering = ::slowdrift_fmi::fmi3::Numbering {{\n\
         \x20   real: FLOAT64_OFFSET,\n\
         \x20   integer: INT32_OFFSET,\n\
         \x20   boolean: BOOLEAN_OFFSET,\n\
         \x20   string: STRING_OFFSET,\n\
         \x20   arrays: &[\n{arrays}\x20   ],\n\
         }};\n"
    )
}

/// The FMI 3.0 description of the FMI 2.0 co-simulation description `fmi2_xml`, every
/// value reference kept ([`Numbering::SAME`]).
pub fn fmi3_model_description(fmi2_xml: &str) -> Result<String, Error> {
    fmi3_model_description_numbered(fmi2_xml, &Numbering::SAME)
}

/// The FMI 3.0 description of `fmi2_xml`, its value references by `numbering`.
pub fn fmi3_model_description_numbered(
    fmi2_xml: &str,
    numbering: &Numbering,
) -> Result<String, Error> {
    let root = tree::parse(fmi2_xml)?;
    if root.name != "fmiModelDescription" {
        return Err(Error::UnsupportedElement {
            parent: "the document".into(),
            element: attributes::describe(&root),
        });
    }
    let root_attributes = header::root_attributes(&root)?;
    let known = [
        "CoSimulation",
        "UnitDefinitions",
        "TypeDefinitions",
        "LogCategories",
        "DefaultExperiment",
        "ModelVariables",
        "ModelStructure",
    ];
    if let Some(other) = root
        .children
        .iter()
        .find(|c| !known.contains(&c.name.as_str()))
    {
        return Err(Error::UnsupportedElement {
            parent: attributes::describe(&root),
            element: attributes::describe(other),
        });
    }
    let optional = |name| -> Result<Option<&tree::Element>, Error> {
        match root.children_named(name).next() {
            None => Ok(None),
            Some(_) => only_child(&root, name).map(Some),
        }
    };
    let co_simulation = only_child(&root, "CoSimulation")?;
    let model_variables = only_child(&root, "ModelVariables")?;
    let model_structure = only_child(&root, "ModelStructure")?;
    let variables = variables::read(model_variables, numbering)?;
    let units = optional("UnitDefinitions")?;
    let time_unit = units
        .is_some_and(|u| {
            u.children_named("Unit")
                .any(|u| u.attribute("name") == Some("s"))
        })
        .then_some("s");

    let mut w = writer::Writer::new();
    w.comment(&format!(
        "FMI 3.0 model description, generated by slowdrift-fmi-xml from the FMI 2.0 one\n\
         (the single source: edit that file, not this one). Value references: FMI 2.0's plus\n\
         Real {}, Integer {}, Boolean {}, String {}; the independent variable time: {}.",
        numbering.real,
        numbering.integer,
        numbering.boolean,
        numbering.string,
        TIME_VALUE_REFERENCE
    ));
    w.start("fmiModelDescription", &root_attributes);
    header::co_simulation(co_simulation, &mut w)?;
    if let Some(e) = units {
        header::unit_definitions(e, &mut w)?;
    }
    if let Some(e) = optional("TypeDefinitions")? {
        header::type_definitions(e, &mut w)?;
    }
    if let Some(e) = optional("LogCategories")? {
        header::log_categories(e, &mut w)?;
    }
    if let Some(e) = optional("DefaultExperiment")? {
        header::default_experiment(e, &mut w)?;
    }
    variables::write(&variables, time_unit, &mut w)?;
    structure::write(model_structure, &variables, &mut w)?;
    w.end("fmiModelDescription");
    Ok(w.finish())
}

#[cfg(test)]
mod tests;
