//! References that resolve: every `NAME.md#anchor` that the code, the tests, the scripts and
//! the docs cite names a page of docs/ (or the README) and a heading of it, and nothing cites
//! a page the repository does not have (such as the former `physics.md`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// The files that may cite a page: sources, tests, scripts, docs, build scripts.
fn citing_files() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            let name = entry.file_name().to_string_lossy().into_owned();
            if path.is_dir() {
                if !matches!(name.as_str(), "target" | "data" | "figures" | "schema") {
                    walk(&path, out);
                }
            } else if ["rs", "py", "md", "toml", "sh", "xml", "ssd"]
                .iter()
                .any(|ext| name.ends_with(&format!(".{ext}")))
            {
                out.push(path);
            }
        }
    }
    let root = Path::new(ROOT);
    let mut files = vec![root.join("README.md"), root.join("build.rs")];
    for dir in [
        "src",
        "tests",
        "benches",
        "docs",
        "fmu-pack",
        "mooring",
        "modelDescription",
    ] {
        walk(&root.join(dir), &mut files);
    }
    files
}

/// The anchor mdBook and GitHub give a heading: lower case, letters, digits, `_` and `-`
/// kept, spaces turned to `-`, everything else dropped.
fn slug(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '_' || c == '-' => Some(c),
            _ => None,
        })
        .collect()
}

/// The anchors of every page: docs/*.md by file name, and README.md.
fn anchors() -> BTreeMap<String, Vec<String>> {
    let root = Path::new(ROOT);
    let mut pages: Vec<PathBuf> = std::fs::read_dir(root.join("docs"))
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    pages.push(root.join("README.md"));
    pages
        .iter()
        .map(|page| {
            let text = std::fs::read_to_string(page).unwrap();
            let mut in_code = false;
            let headings = text
                .lines()
                .filter(|line| {
                    if line.starts_with("```") {
                        in_code = !in_code;
                    }
                    !in_code
                })
                .filter_map(|line| line.strip_prefix('#'))
                .map(|rest| slug(rest.trim_start_matches('#')))
                .collect();
            let name = page.file_name().unwrap().to_string_lossy().into_owned();
            (name, headings)
        })
        .collect()
}

/// Every `NAME.md#anchor` in `text`, with its line.
fn citations(text: &str) -> Vec<(usize, String, String)> {
    let mut found = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let mut rest = line;
        while let Some(at) = rest.find(".md#") {
            let name_start = rest[..at]
                .rfind(|c: char| !(c.is_alphanumeric() || c == '-' || c == '_'))
                .map_or(0, |i| i + 1);
            let name = format!("{}.md", &rest[name_start..at]);
            let anchor: String = rest[at + 4..]
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '-' || *c == '_')
                .collect();
            found.push((n + 1, name, anchor));
            rest = &rest[at + 4..];
        }
    }
    found
}

#[test]
fn every_cited_page_and_heading_exists() {
    let anchors = anchors();
    let mut problems = Vec::new();
    let mut cited = 0;
    for file in citing_files() {
        let Ok(text) = std::fs::read_to_string(&file) else {
            continue;
        };
        let shown = file
            .strip_prefix(ROOT)
            .unwrap_or(&file)
            .display()
            .to_string();
        if shown.ends_with("references.rs") {
            continue;
        }
        if let Some(line) = text.lines().position(|l| l.contains("physics.md")) {
            problems.push(format!("{shown}:{}: cites physics.md", line + 1));
        }
        for (line, page, anchor) in citations(&text) {
            cited += 1;
            match anchors.get(&page) {
                None => problems.push(format!("{shown}:{line}: no page {page}")),
                Some(headings) if !headings.contains(&anchor) => {
                    problems.push(format!("{shown}:{line}: {page} has no heading #{anchor}"))
                }
                Some(_) => {}
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    assert!(cited > 60, "the code and docs cite pages: found {cited}");
}

/// The checks above can fail: a heading renamed, a page missing, the old page cited.
#[test]
fn the_reference_check_catches_what_does_not_resolve() {
    assert_eq!(
        slug(" Full QTF (second_order = \"full-qtf\")"),
        "full-qtf-second_order--full-qtf"
    );
    assert_eq!(
        slug(" Columns (Linton and Evans)"),
        "columns-linton-and-evans"
    );
    let anchors = anchors();
    let text = "see docs/theory.md#sea-state and (theory.md#no-such-heading), also nope.md#x";
    let found = citations(text);
    assert_eq!(found.len(), 3);
    assert!(anchors["theory.md"].contains(&found[0].2));
    assert!(!anchors["theory.md"].contains(&found[1].2));
    assert!(!anchors.contains_key(&found[2].1));
}
