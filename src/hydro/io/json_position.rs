//! Where a value is in a JSON text, for errors about a file's content: the 1-based line of
//! the value a key path names (`drift[3].omega`), found by walking the text's raw values
//! (serde_json's `RawValue` borrows the text, so its offset is its position). Used only
//! when an error is reported: a file is read in one pass into its types, and its content
//! checked after, without positions.

use serde_json::value::RawValue;
use std::collections::BTreeMap;

/// One step of a key path: an object's key or an array's index.
#[derive(Debug, Clone, PartialEq)]
enum Step {
    Key(String),
    Index(usize),
}

/// The steps of a key path such as `drift[3].damping[0][1]`; `None` when it is not one.
fn steps(path: &str) -> Option<Vec<Step>> {
    let mut out = Vec::new();
    for part in path.split('.') {
        let (key, mut rest) = part.split_at(part.find('[').unwrap_or(part.len()));
        if key.is_empty() {
            return None;
        }
        out.push(Step::Key(key.to_string()));
        while let Some(inner) = rest.strip_prefix('[') {
            let close = inner.find(']')?;
            out.push(Step::Index(inner[..close].parse().ok()?));
            rest = &inner[close + 1..];
        }
        if !rest.is_empty() {
            return None;
        }
    }
    Some(out)
}

/// The 1-based line of the deepest value of `path` (a key path from the document's root)
/// that `text` holds: the value itself, or the nearest enclosing one that exists (a path
/// may end in a name the file does not spell, such as a derived quantity). `None` when the
/// text is not JSON or holds no part of the path.
pub fn line_of(text: &str, path: &str) -> Option<usize> {
    let steps = steps(path)?;
    let mut current: &RawValue = serde_json::from_str(text).ok()?;
    let mut found = false;
    for step in &steps {
        let next = match step {
            Step::Key(key) => serde_json::from_str::<BTreeMap<String, &RawValue>>(current.get())
                .ok()
                .and_then(|object| object.get(key).copied()),
            Step::Index(i) => serde_json::from_str::<Vec<&RawValue>>(current.get())
                .ok()
                .and_then(|array| array.get(*i).copied()),
        };
        match next {
            Some(value) => {
                current = value;
                found = true;
            }
            None => break,
        }
    }
    if !found {
        return None;
    }
    let offset = current.get().as_ptr() as usize - text.as_ptr() as usize;
    Some(text[..offset].matches('\n').count() + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "{\n  \"name\": \"x\",\n  \"drift\": [\n    {\"omega\": 0.1},\n    {\n      \"omega\": -1,\n      \"damping\": [[1, 2],\n                  [3, 4]]\n    }\n  ]\n}\n";

    #[test]
    fn a_path_finds_the_line_of_its_value() {
        assert_eq!(line_of(TEXT, "name"), Some(2));
        assert_eq!(line_of(TEXT, "drift[0].omega"), Some(4));
        assert_eq!(line_of(TEXT, "drift[1].omega"), Some(6));
        assert_eq!(line_of(TEXT, "drift[1].damping[1][0]"), Some(8));
    }

    #[test]
    fn a_path_the_file_does_not_spell_ends_at_its_deepest_value() {
        assert_eq!(line_of(TEXT, "drift[1].b12"), Some(5));
        assert_eq!(line_of(TEXT, "drift[7].omega"), Some(3));
        assert_eq!(line_of(TEXT, "qtf.omegas"), None);
        assert_eq!(line_of("not json", "name"), None);
        assert_eq!(line_of(TEXT, "drift[x]"), None);
    }
}
