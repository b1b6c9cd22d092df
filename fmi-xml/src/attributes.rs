//! The rules every part of the conversion shares: how an element is named in messages,
//! attributes carried over by an allowed list, and descriptions in FMI 3.0's words.

use crate::tree::Element;
use crate::writer::Attributes;
use crate::Error;

/// The element as messages name it: `ScalarVariable "Hs" (line 120)`.
pub(crate) fn describe(e: &Element) -> String {
    match e.attribute("name") {
        Some(name) => format!("{} {name:?} (line {})", e.name, e.line),
        None => format!("{} (line {})", e.name, e.line),
    }
}

/// The attributes of `e` in the order written, each renamed by `renames` (FMI 2.0 name,
/// FMI 3.0 name) or kept if listed in `kept`; any other attribute is an error.
pub(crate) fn carried(
    e: &Element,
    kept: &[&str],
    renames: &[(&str, &str)],
) -> Result<Attributes, Error> {
    e.attributes
        .iter()
        .map(|(key, value)| {
            let name = match renames.iter().find(|(from, _)| from == key) {
                Some((_, to)) => *to,
                None if kept.contains(&key.as_str()) => key.as_str(),
                None => {
                    return Err(Error::UnsupportedAttribute {
                        element: describe(e),
                        attribute: key.clone(),
                    })
                }
            };
            let value = if key == "description" {
                fmi3_wording(value)
            } else {
                value.clone()
            };
            Ok((name.to_string(), value))
        })
        .collect()
}

/// `text` with the FMI 2.0 functions and statuses it names (`fmi2Error`,
/// `fmi2SetDebugLogging`: `fmi2` and a capital letter) as FMI 3.0's (`fmi3Error`,
/// `fmi3SetDebugLogging`).
pub(crate) fn fmi3_wording(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(i) = rest.find("fmi2") {
        let after = &rest[i + 4..];
        out.push_str(&rest[..i]);
        if after.starts_with(|c: char| c.is_ascii_uppercase()) {
            out.push_str("fmi3");
        } else {
            out.push_str("fmi2");
        }
        rest = after;
    }
    out.push_str(rest);
    out
}

/// The one child `name` of `parent`, required.
pub(crate) fn only_child<'a>(
    parent: &'a Element,
    name: &'static str,
) -> Result<&'a Element, Error> {
    let mut found = parent.children_named(name);
    let first = found.next().ok_or_else(|| Error::MissingElement {
        parent: describe(parent),
        element: name,
    })?;
    match found.next() {
        None => Ok(first),
        Some(second) => Err(Error::UnsupportedElement {
            parent: describe(parent),
            element: format!("a second {} ({})", name, describe(second)),
        }),
    }
}
