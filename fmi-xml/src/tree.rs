//! The XML text as a tree of elements and their attributes (unescaped), comments and text
//! left out: the FMI 2.0 model description holds everything in elements and attributes.

use crate::Error;
use quick_xml::events::{BytesStart, Event};
use quick_xml::{Reader, XmlVersion};

/// One element: its name, its attributes in the order written and its child elements.
#[derive(Debug)]
pub(crate) struct Element {
    pub name: String,
    pub attributes: Vec<(String, String)>,
    pub children: Vec<Element>,
    /// Its line in the text (1-based), for messages.
    pub line: usize,
}

impl Element {
    /// The value of attribute `key`.
    pub fn attribute(&self, key: &str) -> Option<&str> {
        self.attributes
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }

    /// The children named `name`.
    pub fn children_named<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Element> {
        self.children.iter().filter(move |c| c.name == name)
    }
}

/// The root element of `xml`.
pub(crate) fn parse(xml: &str) -> Result<Element, Error> {
    let mut reader = Reader::from_str(xml);
    let mut stack: Vec<Element> = Vec::new();
    let mut root = None;
    loop {
        let line = line_at(xml, reader.buffer_position() as usize);
        let event = reader.read_event().map_err(|e| Error::Xml {
            line,
            message: e.to_string(),
        })?;
        let (element, is_empty) = match event {
            Event::Start(e) => (element(&e, line)?, false),
            Event::Empty(e) => (element(&e, line)?, true),
            Event::End(_) => {
                let done = stack.pop().expect("quick-xml matches end tags");
                close(done, &mut stack, &mut root, line)?;
                continue;
            }
            Event::Eof => break,
            _ => continue,
        };
        if is_empty {
            close(element, &mut stack, &mut root, line)?;
        } else {
            stack.push(element);
        }
    }
    match (root, stack.is_empty()) {
        (Some(root), true) => Ok(root),
        _ => Err(Error::Xml {
            line: line_at(xml, xml.len()),
            message: "no complete root element".into(),
        }),
    }
}

/// The 1-based line of byte `offset`.
fn line_at(xml: &str, offset: usize) -> usize {
    1 + xml.as_bytes()[..offset.min(xml.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
}

/// `done` as the last child of the open element, or as the root.
fn close(
    done: Element,
    stack: &mut [Element],
    root: &mut Option<Element>,
    line: usize,
) -> Result<(), Error> {
    match stack.last_mut() {
        Some(parent) => parent.children.push(done),
        None if root.is_none() => *root = Some(done),
        None => {
            return Err(Error::Xml {
                line,
                message: format!("a second root element, {}", done.name),
            })
        }
    }
    Ok(())
}

fn element(e: &BytesStart, line: usize) -> Result<Element, Error> {
    let name = e.name().as_ref().to_string();
    let mut attributes = Vec::new();
    for a in e.attributes() {
        let a = a.map_err(|err| Error::Xml {
            line,
            message: format!("{name}: {err}"),
        })?;
        let key = a.key.as_ref().to_string();
        let value = a
            .normalized_value(XmlVersion::Implicit1_0)
            .map_err(|err| Error::Xml {
                line,
                message: format!("{name}: attribute {key}: {err}"),
            })?
            .into_owned();
        attributes.push((key, value));
    }
    Ok(Element {
        name,
        attributes,
        children: Vec::new(),
        line,
    })
}
