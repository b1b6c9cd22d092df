//! The XML text of the FMI 3.0 model description: two spaces a level, attribute values
//! escaped, an element's attributes one a line when they do not fit on its line.

/// Attributes as written: name and (unescaped) value, in order.
pub(crate) type Attributes = Vec<(String, String)>;

/// Lines longer than this put each attribute on a line of its own.
const WIDTH: usize = 100;

pub(crate) struct Writer {
    out: String,
    depth: usize,
}

impl Writer {
    /// A document with its XML declaration.
    pub fn new() -> Self {
        Writer {
            out: "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n".into(),
            depth: 0,
        }
    }

    /// `<!-- text -->`, each line of `text` indented.
    pub fn comment(&mut self, text: &str) {
        self.line("<!--");
        for l in text.lines() {
            self.line(&format!("  {l}"));
        }
        self.line("-->");
    }

    /// `<name attributes>`, its content to follow.
    pub fn start(&mut self, name: &str, attributes: &[(String, String)]) {
        self.tag(name, attributes, ">");
        self.depth += 1;
    }

    /// `<name attributes/>`.
    pub fn empty(&mut self, name: &str, attributes: &[(String, String)]) {
        self.tag(name, attributes, "/>");
    }

    /// `</name>`.
    pub fn end(&mut self, name: &str) {
        self.depth -= 1;
        self.line(&format!("</{name}>"));
    }

    pub fn finish(self) -> String {
        self.out
    }

    fn tag(&mut self, name: &str, attributes: &[(String, String)], close: &str) {
        let written: Vec<String> = attributes
            .iter()
            .map(|(k, v)| format!("{k}=\"{}\"", escape(v)))
            .collect();
        let one_line = format!("<{name}{}{close}", prefixed(&written, " "));
        if 2 * self.depth + one_line.len() <= WIDTH || written.len() < 2 {
            self.line(&one_line);
        } else {
            let indent = "  ".repeat(self.depth + 1);
            let separator = format!("\n{indent}");
            self.line(&format!("<{name}{}{close}", prefixed(&written, &separator)));
        }
    }

    fn line(&mut self, text: &str) {
        self.out.push_str(&"  ".repeat(self.depth));
        self.out.push_str(text);
        self.out.push('\n');
    }
}

/// `value` as an attribute value in double quotes: `&`, `<`, `>` and `"` as entities.
fn escape(value: &str) -> String {
    let mut out = String::with_capacity(value.len());
    for c in value.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(c),
        }
    }
    out
}

/// Each item with `separator` before it.
fn prefixed(items: &[String], separator: &str) -> String {
    items.iter().map(|i| format!("{separator}{i}")).collect()
}
