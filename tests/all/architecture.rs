//! The architecture as docs/architecture.md states it, checked against the code: the
//! library's modules, their layers and imports (every import points to a lower layer), no
//! import cycle between files, `fmi2` imported by no library module, and `unsafe` code only
//! where the page says. The imports are read from the source text (`crate::a::b` paths and
//! `use crate::{a, b}` lists; comments and the trailing `#[cfg(test)] mod tests` are left
//! out), so a new edge fails here until the page says it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// Names the crate root re-exports, and the module they come from.
const REEXPORTS: [(&str, &str); 10] = [
    ("Problem", "problem"),
    ("Scenario", "scenario"),
    ("Simulation", "simulation"),
    ("Outputs", "simulation"),
    ("Snapshot", "simulation"),
    ("RecordPlan", "record_plan"),
    ("QtfRank", "record_plan"),
    ("PlanKey", "record_plan"),
    ("Error", "error"),
    ("Result", "error"),
];

/// The files of the library (not the binary's main.rs, cli/ and plot/).
fn library_files() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    let src = Path::new(ROOT).join("src");
    let mut files = Vec::new();
    walk(&src, &mut files);
    files.retain(|f| {
        let rel = f.strip_prefix(&src).unwrap();
        !(rel == Path::new("main.rs") || rel.starts_with("cli") || rel.starts_with("plot"))
    });
    files.sort();
    files
}

/// The source without line comments and without the trailing unit-test module.
fn code(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    let text = match text.find("#[cfg(test)]\nmod tests") {
        Some(i) => &text[..i],
        None => &text[..],
    };
    text.lines()
        .map(|line| match line.find("//") {
            Some(i) => &line[..i],
            None => line,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// Module path of a file: `src/hydro/io/mod.rs` -> [hydro, io].
fn module_path(path: &Path) -> Vec<String> {
    let rel = path.strip_prefix(Path::new(ROOT).join("src")).unwrap();
    let mut parts: Vec<String> = rel
        .with_extension("")
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if parts.last().is_some_and(|p| p == "mod" || p == "lib") {
        parts.pop();
    }
    parts
}

/// The crate paths a file names: each as its segments after `crate::`.
fn crate_paths(code: &str) -> Vec<Vec<String>> {
    let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    let mut paths = Vec::new();
    let mut rest = code;
    while let Some(i) = rest.find("crate::") {
        let before = rest[..i].chars().next_back();
        rest = &rest[i + "crate::".len()..];
        if before.is_some_and(ident) {
            continue;
        }
        if let Some(list) = rest.strip_prefix('{') {
            let end = list.find('}').unwrap_or(list.len());
            for item in list[..end].split(',') {
                let segments: Vec<String> = item
                    .split("::")
                    .map(|s| s.trim().trim_start_matches('{').to_string())
                    .filter(|s| !s.is_empty() && s != "self")
                    .collect();
                if !segments.is_empty() {
                    paths.push(segments);
                }
            }
            continue;
        }
        let end = rest
            .find(|c: char| !(ident(c) || c == ':'))
            .unwrap_or(rest.len());
        let segments: Vec<String> = rest[..end]
            .split("::")
            .filter(|s| !s.is_empty())
            .map(String::from)
            .collect();
        if !segments.is_empty() {
            paths.push(segments);
        }
    }
    paths
}

/// The library file a crate path lands in: the longest prefix that names a module file.
fn resolve(files: &BTreeSet<Vec<String>>, segments: &[String]) -> Option<Vec<String>> {
    let mut segments = segments.to_vec();
    if let Some(&(_, module)) = REEXPORTS.iter().find(|(name, _)| *name == segments[0]) {
        segments[0] = module.to_string();
    }
    (1..=segments.len())
        .rev()
        .map(|n| segments[..n].to_vec())
        .find(|prefix| files.contains(prefix))
}

/// The table of docs/architecture.md: module -> (layer, imports).
fn documented() -> BTreeMap<String, (u32, BTreeSet<String>)> {
    let page = std::fs::read_to_string(Path::new(ROOT).join("docs/architecture.md")).unwrap();
    let start = page
        .find("<!-- architecture table")
        .expect("docs/architecture.md has the architecture table");
    let mut table = BTreeMap::new();
    for line in page[start..].lines().skip(3) {
        if !line.starts_with('|') {
            break;
        }
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        let layer: u32 = cells[1]
            .parse()
            .unwrap_or_else(|_| panic!("layer of {line}"));
        let module = cells[2].trim_matches('`').to_string();
        let imports: BTreeSet<String> = cells[3]
            .split(',')
            .map(str::trim)
            .filter(|s| !s.is_empty() && *s != "-")
            .map(String::from)
            .collect();
        assert!(
            table.insert(module.clone(), (layer, imports)).is_none(),
            "{module} twice"
        );
    }
    table
}

#[test]
fn the_architecture_page_is_the_code() {
    let files = library_files();
    let paths: BTreeSet<Vec<String>> = files.iter().map(|f| module_path(f)).collect();
    let lib = code(&Path::new(ROOT).join("src/lib.rs"));
    let modules: BTreeSet<String> = lib
        .lines()
        .filter_map(|l| {
            let l = l.trim();
            l.strip_prefix("pub mod ")
                .or_else(|| l.strip_prefix("mod "))
                .map(|m| m.trim_end_matches(';').to_string())
        })
        .collect();
    let table = documented();
    assert_eq!(
        table.keys().cloned().collect::<BTreeSet<_>>(),
        modules,
        "the page lists exactly the modules of src/lib.rs"
    );
    // File-level edges, and the module-level imports they make.
    let mut edges: BTreeMap<Vec<String>, BTreeSet<Vec<String>>> = BTreeMap::new();
    let mut imports: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for file in &files {
        let me = module_path(file);
        if me.is_empty() {
            continue;
        }
        let mine = edges.entry(me.clone()).or_default();
        let top = imports.entry(me[0].clone()).or_default();
        for segments in crate_paths(&code(file)) {
            let Some(target) = resolve(&paths, &segments) else {
                continue;
            };
            if target.is_empty() || target == me {
                continue;
            }
            if target[0] != me[0] {
                top.insert(target[0].clone());
            }
            mine.insert(target);
        }
    }
    for (module, (layer, listed)) in &table {
        let actual = imports.get(module).cloned().unwrap_or_default();
        assert_eq!(
            &actual, listed,
            "imports of {module} (docs/architecture.md)"
        );
        for import in &actual {
            let (their_layer, _) = &table[import];
            assert!(
                their_layer < layer,
                "{module} (layer {layer}) imports {import} (layer {their_layer}): \
                 dependencies must point to a lower layer"
            );
        }
    }
    assert!(
        imports.values().all(|i| !i.contains("fmi2")),
        "nothing in the library imports fmi2"
    );
    assert!(
        imports["model"].is_empty(),
        "model imports nothing of the crate"
    );
    // No cycle between files (depth-first search for a back edge).
    fn visit(
        node: &Vec<String>,
        edges: &BTreeMap<Vec<String>, BTreeSet<Vec<String>>>,
        state: &mut BTreeMap<Vec<String>, bool>,
        stack: &mut Vec<Vec<String>>,
    ) {
        match state.get(node) {
            Some(true) => return,
            Some(false) => {
                let at = stack.iter().position(|n| n == node).unwrap();
                panic!("files import each other: {:?}", &stack[at..]);
            }
            None => {}
        }
        state.insert(node.clone(), false);
        stack.push(node.clone());
        for next in edges.get(node).into_iter().flatten() {
            visit(next, edges, state, stack);
        }
        stack.pop();
        state.insert(node.clone(), true);
    }
    let mut state = BTreeMap::new();
    for node in edges.keys() {
        visit(node, &edges, &mut state, &mut Vec::new());
    }
}

/// `unsafe` appears only in the three files the page names (function-pointer types of the
/// FMI headers in fmi2/types.rs aside).
#[test]
fn unsafe_code_only_where_the_page_says() {
    let allowed = ["fmi2/exports.rs", "fmi2/logger.rs", "allocator.rs"];
    let src = Path::new(ROOT).join("src");
    for file in library_files() {
        let rel = file
            .strip_prefix(&src)
            .unwrap()
            .to_string_lossy()
            .into_owned();
        let code = code(&file);
        let uses = code
            .lines()
            .filter(|l| l.contains("unsafe") && !l.contains("unsafe extern \"C\" fn("))
            .filter(|l| !l.contains("deny(unsafe_code)"))
            .count();
        if !allowed.contains(&rel.as_str()) {
            assert_eq!(uses, 0, "{rel} has unsafe code");
        }
    }
    let lib = std::fs::read_to_string(src.join("lib.rs")).unwrap();
    assert!(lib.contains("#![deny(unsafe_code)]"));
}
