//! What stops a conversion: each error names the element (a variable by its name) and the
//! attribute or value at fault.

use std::fmt;

/// Why an FMI 2.0 model description has no FMI 3.0 counterpart here. `element` is the
/// element as a reader finds it: `ScalarVariable "Hs"`, `CoSimulation`,
/// `Outputs/Unknown index="23"`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Error {
    /// The text is not well-formed XML.
    Xml { line: usize, message: String },
    /// The root is not an FMI 2.0 model description.
    NotFmi2 { fmi_version: String },
    /// A required element is absent.
    MissingElement {
        parent: String,
        element: &'static str,
    },
    /// A required attribute is absent.
    MissingAttribute {
        element: String,
        attribute: &'static str,
    },
    /// An element this generator does not convert (FMI 2.0 allows it, but the FMUs here do
    /// not use it, or FMI 3.0 has no element of the same meaning).
    UnsupportedElement { parent: String, element: String },
    /// An attribute this generator does not convert.
    UnsupportedAttribute { element: String, attribute: String },
    /// An attribute's value FMI 3.0 cannot take, or that is not a number where one is due.
    InvalidValue {
        element: String,
        attribute: String,
        value: String,
        expected: &'static str,
    },
    /// Two variables with one value reference (FMI 2.0 allows it across base types and for
    /// aliases; FMI 3.0 value references are unique across all variables).
    DuplicateValueReference {
        value_reference: u32,
        first: String,
        second: String,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Xml { line, message } => write!(f, "line {line}: XML error: {message}"),
            Error::NotFmi2 { fmi_version } => write!(
                f,
                "fmiModelDescription fmiVersion = {fmi_version:?}: expected \"2.0\""
            ),
            Error::MissingElement { parent, element } => {
                write!(f, "{parent} has no {element}")
            }
            Error::MissingAttribute { element, attribute } => {
                write!(f, "{element} has no attribute {attribute}")
            }
            Error::UnsupportedElement { parent, element } => write!(
                f,
                "{parent}: element {element} is not converted to FMI 3.0 (slowdrift-fmi-xml)"
            ),
            Error::UnsupportedAttribute { element, attribute } => write!(
                f,
                "{element}: attribute {attribute} is not converted to FMI 3.0 (slowdrift-fmi-xml)"
            ),
            Error::InvalidValue {
                element,
                attribute,
                value,
                expected,
            } => write!(f, "{element}: {attribute} = {value:?}: expected {expected}"),
            Error::DuplicateValueReference {
                value_reference,
                first,
                second,
            } => write!(
                f,
                "value reference {value_reference} of {second} is already {first}'s: FMI 3.0 \
                 value references are unique across all variables"
            ),
        }
    }
}

impl std::error::Error for Error {}
