//! `<ModelVariables>`: each FMI 2.0 `ScalarVariable` as the FMI 3.0 element of its base
//! type, with its value reference in the one space of FMI 3.0 ([`Numbering`]), and the
//! independent variable `time` that FMI 3.0 requires.

use crate::attributes::{carried, describe, fmi3_wording};
use crate::tree::Element;
use crate::writer::{Attributes, Writer};
use crate::{ArrayVariable, Error, Numbering, TIME_VALUE_REFERENCE};
use std::collections::BTreeMap;

/// The name of the independent variable the FMI 3.0 description adds.
pub(crate) const TIME: &str = "time";

/// An FMI 2.0 base type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum BaseType {
    Real,
    Integer,
    Boolean,
    String,
}

impl BaseType {
    /// The FMI 3.0 element of a variable of this type.
    fn fmi3_element(self) -> &'static str {
        match self {
            BaseType::Real => "Float64",
            BaseType::Integer => "Int32",
            BaseType::Boolean => "Boolean",
            BaseType::String => "String",
        }
    }

    /// The attributes of the FMI 2.0 type element that FMI 3.0 has on the variable.
    fn kept(self) -> &'static [&'static str] {
        match self {
            BaseType::Real => &[
                "declaredType",
                "quantity",
                "unit",
                "displayUnit",
                "relativeQuantity",
                "min",
                "max",
                "nominal",
                "unbounded",
                "start",
                "derivative",
                "reinit",
            ],
            BaseType::Integer => &["declaredType", "quantity", "min", "max", "start"],
            BaseType::Boolean | BaseType::String => &["declaredType", "start"],
        }
    }
}

/// The FMI 2.0 `ScalarVariable` attributes besides name, value reference, causality and
/// variability, the same in FMI 3.0.
const VARIABLE_KEPT: [&str; 3] = [
    "description",
    "initial",
    "canHandleMultipleSetPerTimeInstant",
];

/// One FMI 2.0 variable and its FMI 3.0 value reference.
pub(crate) struct Variable<'a> {
    /// The `ScalarVariable`.
    pub element: &'a Element,
    /// Its type element (`Real`, ...).
    pub base: &'a Element,
    pub ty: BaseType,
    pub name: &'a str,
    /// Its FMI 3.0 value reference.
    pub value_reference: u32,
    /// The FMI 3.0 array it is element `k` (1-based) of, if any.
    pub array: Option<(&'static ArrayVariable, u32)>,
}

impl Variable<'_> {
    /// Whether FMI 3.0 has no variable of its own for it: an array's element after the
    /// first (the first stands for the array).
    pub fn folded(&self) -> bool {
        matches!(self.array, Some((_, k)) if k > 1)
    }
}

/// The variables of `model_variables`, in order (the FMI 2.0 index `i` is element `i - 1`).
pub(crate) fn read<'a>(
    model_variables: &'a Element,
    numbering: &Numbering,
) -> Result<Vec<Variable<'a>>, Error> {
    let time = format!("{TIME} (the FMI 3.0 independent variable)");
    let mut taken: BTreeMap<u32, String> = BTreeMap::from([(TIME_VALUE_REFERENCE, time)]);
    let mut variables = Vec::new();
    for e in &model_variables.children {
        if e.name != "ScalarVariable" {
            return Err(Error::UnsupportedElement {
                parent: describe(model_variables),
                element: describe(e),
            });
        }
        let variable = variable(e, numbering)?;
        if let Some(first) = taken.insert(variable.value_reference, describe(e)) {
            return Err(Error::DuplicateValueReference {
                value_reference: variable.value_reference,
                first,
                second: describe(e),
            });
        }
        variables.push(variable);
    }
    for array in numbering.arrays {
        fold(array, numbering.real, &mut variables)?;
    }
    Ok(variables)
}

/// Marks the FMI 2.0 Reals `{name}1` .. `{name}{count}` as the elements of `array`: each
/// must exist with the value reference `first + k - 1` (before the Reals' offset `real`),
/// the first's causality and variability and no start; `{name}{count + 1}` must not exist.
fn fold(array: &'static ArrayVariable, real: u32, variables: &mut [Variable]) -> Result<(), Error> {
    let invalid = |element: String, attribute: &str, value: String, expected| Error::InvalidValue {
        element,
        attribute: attribute.into(),
        value,
        expected,
    };
    let of = format!("the array {}[{}]", array.name, array.count);
    let beyond = format!("{}{}", array.name, array.count + 1);
    if let Some(v) = variables.iter().find(|v| v.name == beyond) {
        return Err(invalid(
            describe(v.element),
            "name",
            beyond,
            "no element beyond the array's count",
        ));
    }
    let mut first_kind = None;
    for k in 1..=array.count {
        let name = format!("{}{k}", array.name);
        let v = variables
            .iter_mut()
            .find(|v| v.name == name)
            .ok_or_else(|| invalid(of.clone(), "element", name.clone(), "a Real of that name"))?;
        let expected = array.first + k - 1 + real;
        if v.ty != BaseType::Real || v.value_reference != expected {
            return Err(invalid(
                describe(v.element),
                "valueReference",
                v.value_reference.to_string(),
                "a Real at the array's first value reference plus its index minus one",
            ));
        }
        if v.base.attribute("start").is_some() {
            return Err(invalid(
                describe(v.element),
                "start",
                v.base.attribute("start").unwrap_or_default().into(),
                "no start value in an element of an array",
            ));
        }
        let kind = (
            causality(v.element).to_string(),
            variability(v.element).to_string(),
        );
        match &first_kind {
            None => first_kind = Some(kind),
            Some(first) if *first != kind => {
                return Err(invalid(
                    describe(v.element),
                    "causality",
                    format!("{} {}", kind.0, kind.1),
                    "the causality and variability of the array's first element",
                ))
            }
            Some(_) => {}
        }
        v.array = Some((array, k));
    }
    Ok(())
}

fn variable<'a>(e: &'a Element, numbering: &Numbering) -> Result<Variable<'a>, Error> {
    let required = |attribute| {
        e.attribute(attribute).ok_or(Error::MissingAttribute {
            element: describe(e),
            attribute,
        })
    };
    let name = required("name")?;
    let written = required("valueReference")?;
    let invalid = |attribute: &str, value: &str, expected| Error::InvalidValue {
        element: describe(e),
        attribute: attribute.into(),
        value: value.into(),
        expected,
    };
    if name == TIME {
        return Err(invalid(
            "name",
            name,
            "another name: the FMI 3.0 description adds the independent variable time",
        ));
    }
    if e.attribute("causality") == Some("independent") {
        return Err(invalid(
            "causality",
            "independent",
            "no independent variable: the FMI 3.0 description adds its own, time",
        ));
    }
    let [base] = &e.children[..] else {
        return Err(invalid(
            "its content",
            &format!("{} elements", e.children.len()),
            "one type element: Real, Integer, Boolean or String",
        ));
    };
    let ty = match base.name.as_str() {
        "Real" => BaseType::Real,
        "Integer" => BaseType::Integer,
        "Boolean" => BaseType::Boolean,
        "String" => BaseType::String,
        _ => {
            return Err(Error::UnsupportedElement {
                parent: describe(e),
                element: describe(base),
            })
        }
    };
    if ty != BaseType::Real && variability(e) == "continuous" {
        return Err(invalid(
            "variability",
            "continuous",
            "constant, fixed, tunable or discrete: FMI 3.0 allows continuous only for floats",
        ));
    }
    let value_reference = written
        .parse::<u32>()
        .ok()
        .and_then(|vr| vr.checked_add(crate::offset(numbering, ty)))
        .ok_or_else(|| {
            invalid(
                "valueReference",
                written,
                "an unsigned 32-bit integer, also after the numbering's offset",
            )
        })?;
    Ok(Variable {
        element: e,
        base,
        ty,
        name,
        value_reference,
        array: None,
    })
}

/// FMI 2.0's causality of `e` (default local).
fn causality(e: &Element) -> &str {
    e.attribute("causality").unwrap_or("local")
}

/// FMI 2.0's variability of `e` (default continuous).
fn variability(e: &Element) -> &str {
    e.attribute("variability").unwrap_or("continuous")
}

/// `<ModelVariables>`: `time` first (unit `time_unit`; none: implicitly s), then the
/// variables in their FMI 2.0 order.
pub(crate) fn write(
    variables: &[Variable],
    time_unit: Option<&str>,
    w: &mut Writer,
) -> Result<(), Error> {
    w.start("ModelVariables", &[]);
    let mut time = vec![
        ("name".to_string(), TIME.to_string()),
        (
            "valueReference".to_string(),
            TIME_VALUE_REFERENCE.to_string(),
        ),
        ("causality".to_string(), "independent".to_string()),
        ("variability".to_string(), "continuous".to_string()),
        ("description".to_string(), "Simulation time".to_string()),
    ];
    if let Some(unit) = time_unit {
        time.push(("unit".to_string(), unit.to_string()));
    }
    w.empty("Float64", &time);
    for v in variables.iter().filter(|v| !v.folded()) {
        let (mut attributes, string_start) = fmi3_attributes(v, variables)?;
        let element = v.ty.fmi3_element();
        if let Some((array, _)) = v.array {
            for (key, value) in attributes.iter_mut() {
                match key.as_str() {
                    "name" => *value = array.name.to_string(),
                    "description" => *value = array.description.to_string(),
                    _ => {}
                }
            }
            if !attributes.iter().any(|(key, _)| key == "description") {
                attributes.push(("description".to_string(), array.description.to_string()));
            }
            w.start(element, &attributes);
            w.empty(
                "Dimension",
                &[("start".to_string(), array.count.to_string())],
            );
            w.end(element);
            continue;
        }
        match string_start {
            None => w.empty(element, &attributes),
            Some(start) => {
                w.start(element, &attributes);
                w.empty("Start", &[("value".to_string(), start)]);
                w.end(element);
            }
        }
    }
    w.end("ModelVariables");
    Ok(())
}

/// The FMI 3.0 attributes of `v`, and its start value if it is a String's (a `<Start>`
/// child in FMI 3.0).
fn fmi3_attributes(
    v: &Variable,
    variables: &[Variable],
) -> Result<(Attributes, Option<String>), Error> {
    let e = v.element;
    let mut out = vec![
        ("name".to_string(), v.name.to_string()),
        ("valueReference".to_string(), v.value_reference.to_string()),
        ("causality".to_string(), causality(e).to_string()),
        ("variability".to_string(), variability(e).to_string()),
    ];
    let common = ["name", "valueReference", "causality", "variability"];
    for (key, value) in &e.attributes {
        if common.contains(&key.as_str()) {
            continue;
        }
        if !VARIABLE_KEPT.contains(&key.as_str()) {
            return Err(Error::UnsupportedAttribute {
                element: describe(e),
                attribute: key.clone(),
            });
        }
        let value = match key.as_str() {
            "description" => fmi3_wording(value),
            _ => value.clone(),
        };
        out.push((key.clone(), value));
    }
    if let Some(child) = v.base.children.first() {
        return Err(Error::UnsupportedElement {
            parent: describe(e),
            element: describe(child),
        });
    }
    let mut string_start = None;
    for (key, value) in carried(v.base, v.ty.kept(), &[])? {
        match (v.ty, key.as_str()) {
            (BaseType::String, "start") => string_start = Some(value),
            (BaseType::Boolean, "start") => out.push((key, boolean(e, &value)?)),
            (_, "derivative") => {
                let of = variable_at(&describe(e), "derivative", &value, variables)?;
                out.push((key, of.value_reference.to_string()));
            }
            _ => out.push((key, value)),
        }
    }
    Ok((out, string_start))
}

/// An xs:boolean as `true` or `false`.
fn boolean(e: &Element, value: &str) -> Result<String, Error> {
    match value {
        "true" | "1" => Ok("true".into()),
        "false" | "0" => Ok("false".into()),
        _ => Err(Error::InvalidValue {
            element: describe(e),
            attribute: "start".into(),
            value: value.into(),
            expected: "true, false, 1 or 0",
        }),
    }
}

/// The variable of FMI 2.0 index `index` (1-based, as `attribute` of `element` writes it).
pub(crate) fn variable_at<'v, 'a>(
    element: &str,
    attribute: &str,
    index: &str,
    variables: &'v [Variable<'a>],
) -> Result<&'v Variable<'a>, Error> {
    index
        .parse::<usize>()
        .ok()
        .and_then(|i| i.checked_sub(1))
        .and_then(|i| variables.get(i))
        .ok_or_else(|| Error::InvalidValue {
            element: element.into(),
            attribute: attribute.into(),
            value: index.into(),
            expected: "the index of a variable (1 to the number of ScalarVariables)",
        })
}
