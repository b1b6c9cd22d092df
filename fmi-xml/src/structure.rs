//! `<ModelStructure>`: FMI 2.0's lists of `Unknown`s, by 1-based variable index, as FMI
//! 3.0's elements by value reference: `Outputs` -> `Output`, `Derivatives` ->
//! `ContinuousStateDerivative`, `InitialUnknowns` -> `InitialUnknown` (the same variables:
//! FMI 3.0 asks the same set of initial unknowns as FMI 2.0), in FMI 3.0's order.
//! `dependencies` keep their meaning (absent: every known; empty: none) and
//! `dependenciesKind` is carried over, its words being the same. An array's elements are one
//! FMI 3.0 variable: its first element's `Unknown` stands for the array (the others are
//! left out), and a dependency on any of its elements is one on the array.

use crate::attributes::describe;
use crate::tree::Element;
use crate::variables::{variable_at, Variable};
use crate::writer::Writer;
use crate::Error;

/// FMI 2.0 list -> FMI 3.0 element, in the order FMI 3.0's schema requires.
const LISTS: [(&str, &str); 3] = [
    ("Outputs", "Output"),
    ("Derivatives", "ContinuousStateDerivative"),
    ("InitialUnknowns", "InitialUnknown"),
];

pub(crate) fn write(e: &Element, variables: &[Variable], w: &mut Writer) -> Result<(), Error> {
    if let Some(other) = e
        .children
        .iter()
        .find(|c| !LISTS.iter().any(|(list, _)| *list == c.name))
    {
        return Err(Error::UnsupportedElement {
            parent: describe(e),
            element: describe(other),
        });
    }
    w.start("ModelStructure", &[]);
    for (list, element) in LISTS {
        for unknown in e.children_named(list).flat_map(|l| &l.children) {
            if let Some(attributes) = unknown_attributes(list, unknown, variables)? {
                w.empty(element, &attributes);
            }
        }
    }
    w.end("ModelStructure");
    Ok(())
}

/// The FMI 3.0 attributes of one `Unknown` of `list`; `None` for an array's element after
/// the first (the first stands for the array).
fn unknown_attributes(
    list: &str,
    unknown: &Element,
    variables: &[Variable],
) -> Result<Option<Vec<(String, String)>>, Error> {
    if unknown.name != "Unknown" {
        return Err(Error::UnsupportedElement {
            parent: list.into(),
            element: describe(unknown),
        });
    }
    let at = match unknown.attribute("index") {
        Some(index) => format!("{list}/Unknown index={index:?} (line {})", unknown.line),
        None => format!("{list}/Unknown (line {})", unknown.line),
    };
    let mut out = Vec::new();
    let index = unknown.attribute("index").ok_or(Error::MissingAttribute {
        element: at.clone(),
        attribute: "index",
    })?;
    let of = variable_at(&at, "index", index, variables)?;
    if of.folded() {
        return Ok(None);
    }
    out.push(("valueReference".to_string(), of.value_reference.to_string()));
    let mut count = None;
    for (key, value) in &unknown.attributes {
        match key.as_str() {
            "index" => {}
            "dependencies" => {
                let mut references: Vec<String> = Vec::new();
                for i in value.split_whitespace() {
                    let v = variable_at(&at, "dependencies", i, variables)?;
                    // An array's elements: the array's first element's value reference.
                    let vr = match v.array {
                        Some((_, k)) => v.value_reference - (k - 1),
                        None => v.value_reference,
                    }
                    .to_string();
                    if v.array.is_some() && references.contains(&vr) {
                        if unknown.attribute("dependenciesKind").is_some() {
                            return Err(Error::InvalidValue {
                                element: at.clone(),
                                attribute: "dependencies".into(),
                                value: value.clone(),
                                expected: "one dependency per array with dependenciesKind",
                            });
                        }
                        continue;
                    }
                    references.push(vr);
                }
                count = Some(references.len());
                out.push((key.clone(), references.join(" ")));
            }
            "dependenciesKind" => out.push((key.clone(), value.clone())),
            _ => {
                return Err(Error::UnsupportedAttribute {
                    element: at.clone(),
                    attribute: key.clone(),
                })
            }
        }
    }
    if let Some(kinds) = unknown.attribute("dependenciesKind") {
        if Some(kinds.split_whitespace().count()) != count {
            return Err(Error::InvalidValue {
                element: at.clone(),
                attribute: "dependenciesKind".into(),
                value: kinds.into(),
                expected: "one kind per dependency",
            });
        }
    }
    Ok(Some(out))
}
