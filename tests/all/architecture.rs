//! The architecture as docs/architecture.md states it, checked against the code: the
//! library's modules, their layers and imports (every import points to a lower layer), no
//! import cycle between files, `fmi2` imported by no library module and the FMI layer
//! (`slowdrift_fmi`, a row of the table) only by `fmi2`; in the three crates of
//! the FMUs (`slowdrift`, the FMI layer `slowdrift-fmi` in fmi/, `slowdrift-mooring`),
//! `unsafe` code only where the page says, no pointer cast in the FMI code outside the FMI
//! layer's handle module, and `#[no_mangle]` only in the cdylibs' shims. The code is read
//! as source text (comments and the trailing `#[cfg(test)] mod tests` are left out; the
//! imports are `crate::a::b` paths and `use crate::{a, b}` lists), so a new edge, cast or
//! `unsafe` fails here until the page says it. Every mode is defined once
//! (`src/model/modes.rs`). A last test runs the checks on synthetic
//! code, so each is seen to catch what it forbids.

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

/// The crates of the workspace the library imports, each a row of the page's table as the
/// modules are: `slowdrift_fmi`, the FMI layer (fmi/), which imports nothing of the library.
const WORKSPACE_CRATES: [&str; 1] = ["slowdrift_fmi"];

/// The Rust files under `dir` (relative to the workspace root), sorted; there must be some.
fn rust_files(dir: &str) -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    let mut files = Vec::new();
    walk(&Path::new(ROOT).join(dir), &mut files);
    assert!(!files.is_empty(), "no Rust file under {dir}");
    files.sort();
    files
}

/// The Rust files of `src/`, sorted.
fn source_files() -> Vec<PathBuf> {
    rust_files("src")
}

/// The files of the library (not the binary's main.rs, cli/ and plot/).
fn library_files() -> Vec<PathBuf> {
    let src = Path::new(ROOT).join("src");
    let mut files = rust_files("src");
    files.retain(|f| {
        let rel = f.strip_prefix(&src).unwrap();
        !(rel == Path::new("main.rs") || rel.starts_with("cli") || rel.starts_with("plot"))
    });
    files
}

/// `file` relative to the workspace root, with `/` separators.
fn relative(file: &Path) -> String {
    file.strip_prefix(ROOT)
        .unwrap()
        .to_string_lossy()
        .replace('\\', "/")
}

/// The source of the file at `path` as [`strip`] leaves it.
fn code(path: &Path) -> String {
    strip(&std::fs::read_to_string(path).unwrap())
}

/// The source without line comments and without the trailing unit-test module.
fn strip(text: &str) -> String {
    let text = match text.find("#[cfg(test)]\nmod tests") {
        Some(i) => &text[..i],
        None => text,
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
        modules
            .iter()
            .map(String::as_str)
            .chain(WORKSPACE_CRATES)
            .map(String::from)
            .collect(),
        "the page lists exactly the modules of src/lib.rs and the workspace's crates the \
         library imports"
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
        let code = code(file);
        for krate in WORKSPACE_CRATES {
            if code.contains(&format!("{krate}::")) {
                top.insert(krate.to_string());
            }
        }
        for segments in crate_paths(&code) {
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
    let fmi_layer_users: Vec<&String> = imports
        .iter()
        .filter(|(_, i)| i.contains("slowdrift_fmi"))
        .map(|(m, _)| m)
        .collect();
    assert_eq!(fmi_layer_users, ["fmi2"], "only fmi2 imports the FMI layer");
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

/// The Rust files of the three crates of the FMUs: the library (as [`library_files`]), the
/// FMI layer and the mooring FMU.
fn fmu_crate_files() -> Vec<PathBuf> {
    let mut files = library_files();
    files.extend(rust_files("fmi/src"));
    files.extend(rust_files("mooring/src"));
    files
}

/// The files the page lists as the only ones that may hold `unsafe` code: the list after
/// its `<!-- unsafe files` marker, one `- `path`: why` line each.
fn documented_unsafe_files() -> Vec<String> {
    let page = std::fs::read_to_string(Path::new(ROOT).join("docs/architecture.md")).unwrap();
    let start = page
        .find("<!-- unsafe files")
        .expect("docs/architecture.md lists the files with unsafe code");
    let files: Vec<String> = page[start..]
        .lines()
        .skip(1)
        .map_while(|line| line.strip_prefix("- `"))
        .map(|item| item.split('`').next().unwrap().to_string())
        .collect();
    assert!(
        !files.is_empty(),
        "the page's list of unsafe files is empty"
    );
    files
}

/// The lines (1-based) of `code` (as [`strip`] leaves it) that hold `unsafe` code or allow
/// it; the function-pointer types of the FMI headers (`unsafe extern "C" fn(`) and a crate
/// root's `deny(unsafe_code)` are not unsafe code.
fn unsafe_lines(code: &str) -> Vec<usize> {
    code.lines()
        .enumerate()
        .filter(|(_, l)| l.contains("unsafe") && !l.contains("unsafe extern \"C\" fn("))
        .filter(|(_, l)| !l.contains("deny(unsafe_code)"))
        .map(|(n, _)| n + 1)
        .collect()
}

/// What the unsafe rule finds wrong: a file holding `unsafe` code that `allowed` does not
/// name, and a name of `allowed` whose file holds none (a stale list). `holding` is each
/// file (relative to the workspace root) with its `unsafe` lines.
fn unsafe_misplaced(holding: &[(String, Vec<usize>)], allowed: &[String]) -> Vec<String> {
    let mut wrong = Vec::new();
    for (rel, lines) in holding {
        if !lines.is_empty() && !allowed.contains(rel) {
            wrong.push(format!(
                "{rel}:{}: unsafe code in a file the page does not list",
                lines[0]
            ));
        }
    }
    for rel in allowed {
        if !holding
            .iter()
            .any(|(h, lines)| h == rel && !lines.is_empty())
        {
            wrong.push(format!("{rel} is listed but holds no unsafe code"));
        }
    }
    wrong
}

/// `unsafe` appears only in the files the page lists, and each of them holds some; every
/// crate root denies it.
#[test]
fn unsafe_code_only_where_the_page_says() {
    let holding: Vec<(String, Vec<usize>)> = fmu_crate_files()
        .iter()
        .map(|f| (relative(f), unsafe_lines(&code(f))))
        .collect();
    let wrong = unsafe_misplaced(&holding, &documented_unsafe_files());
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    for root in ["src/lib.rs", "fmi/src/lib.rs", "mooring/src/lib.rs"] {
        let text = std::fs::read_to_string(Path::new(ROOT).join(root)).unwrap();
        assert!(
            text.contains("#![deny(unsafe_code)]"),
            "{root} denies unsafe code"
        );
    }
}

/// The FMI code of the two cdylibs and of the layer they share.
const FMI_CODE: [&str; 3] = ["src/fmi2", "mooring/src/fmi2", "fmi/src"];

/// The one module of the FMI code that converts pointers (docs/architecture.md).
const HANDLE_MODULE: &str = "fmi/src/fmi2/handle.rs";

/// What converts a pointer: casts between pointer types, from pointers to references,
/// boxes and slices and back.
const POINTER_CASTS: [&str; 10] = [
    "as *const",
    "as *mut",
    ".cast::<",
    ".cast()",
    ".cast_mut()",
    ".cast_const()",
    "from_raw",
    "into_raw",
    "from_ptr",
    "transmute",
];

/// The pointer casts of `code` (as [`strip`] leaves it): (line, cast), 1-based.
fn pointer_casts(code: &str) -> Vec<(usize, &'static str)> {
    let mut casts = Vec::new();
    for (n, line) in code.lines().enumerate() {
        for cast in POINTER_CASTS.into_iter().filter(|c| line.contains(c)) {
            casts.push((n + 1, cast));
        }
    }
    casts
}

/// The pointer casts of the file `rel` that the rule forbids: any, unless it is the handle
/// module.
fn casts_misplaced(rel: &str, code: &str) -> Vec<String> {
    if rel == HANDLE_MODULE {
        return Vec::new();
    }
    pointer_casts(code)
        .into_iter()
        .map(|(n, cast)| format!("{rel}:{n}: `{cast}` outside the handle module ({HANDLE_MODULE})"))
        .collect()
}

/// No pointer cast in the FMI code of either cdylib or of the FMI layer outside the layer's
/// handle module, which holds them all (each in an `unsafe` block with its SAFETY note:
/// clippy's `undocumented_unsafe_blocks` is denied there).
#[test]
fn pointer_casts_only_in_the_handle_module() {
    let mut wrong = Vec::new();
    for dir in FMI_CODE {
        for file in rust_files(dir) {
            wrong.extend(casts_misplaced(&relative(&file), &code(&file)));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    // The handle module is where the casts are, so the scan above can find one.
    let handles = code(&Path::new(ROOT).join(HANDLE_MODULE));
    let found: Vec<&str> = pointer_casts(&handles)
        .into_iter()
        .map(|(_, c)| c)
        .collect();
    for cast in [".cast::<", "from_raw", "into_raw", "from_ptr"] {
        assert!(found.contains(&cast), "{HANDLE_MODULE} has no `{cast}`");
    }
    assert!(handles.contains("#![deny(clippy::undocumented_unsafe_blocks)]"));
    let page = std::fs::read_to_string(Path::new(ROOT).join("docs/architecture.md")).unwrap();
    assert!(
        page.contains(&format!("`{HANDLE_MODULE}`")),
        "docs/architecture.md names the handle module"
    );
}

/// The cdylibs' shims: the only files with `#[no_mangle]` items, the layer's two macros
/// (`fmi2_exports!`, `fmi3_exports!`), each expanded in each cdylib.
const SHIMS: [&str; 2] = ["fmi/src/fmi2/exports.rs", "fmi/src/fmi3/exports.rs"];

/// What the file `rel` exports that the rule forbids: any `export_name`, a `#[no_mangle]`
/// outside the shims, and in them an item that is not an `extern "C" fn fmi2*` or `fmi3*`.
fn exports_misplaced(rel: &str, code: &str) -> Vec<String> {
    let lines: Vec<&str> = code.lines().collect();
    let mut wrong = Vec::new();
    for (n, line) in lines.iter().enumerate() {
        if line.contains("export_name") {
            wrong.push(format!("{rel}:{}: names an exported symbol", n + 1));
        }
        if !line.contains("no_mangle") {
            continue;
        }
        if !SHIMS.contains(&rel) {
            wrong.push(format!(
                "{rel}:{}: #[no_mangle] outside the cdylibs' shims",
                n + 1
            ));
            continue;
        }
        let item = lines.get(n + 1).copied().unwrap_or_default();
        if !item.contains("extern \"C\" fn fmi2") && !item.contains("extern \"C\" fn fmi3") {
            wrong.push(format!(
                "{rel}:{}: exports {item:?}, not an fmi2 or fmi3 function",
                n + 2
            ));
        }
    }
    wrong
}

/// No `#[no_mangle]` or `#[export_name]` outside the layer's two macros of the shims, which
/// each cdylib expands (`fmi2_exports!`, `fmi3_exports!`): every exported symbol is named
/// `fmi2*` or `fmi3*`.
#[test]
fn only_the_shims_export_symbols() {
    let mut wrong = Vec::new();
    let mut exported = 0;
    for file in fmu_crate_files() {
        let rel = relative(&file);
        let code = code(&file);
        if SHIMS.contains(&rel.as_str()) {
            exported += code.matches("#[no_mangle]").count();
        }
        wrong.extend(exports_misplaced(&rel, &code));
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    // The macros write the 34 FMI 2.0 functions and the 75 FMI 3.0 ones, each with its six
    // state functions twice (with saved states and without), so the scan above sees the
    // attribute.
    assert_eq!(exported, 34 + 6 + 75 + 6);
}

/// The checks above catch what they forbid, on synthetic code.
#[test]
fn the_checks_catch_what_they_forbid() {
    let source = "//! unsafe in a comment is no code\n\
                  #![deny(unsafe_code)]\n\
                  pub type F = unsafe extern \"C\" fn(i32);\n\
                  fn f(p: *mut u8) -> *const i8 {\n    \
                      let q = unsafe { p.cast::<i8>() }; // from_raw in a comment\n    \
                      q as *const i8\n\
                  }\n\
                  #[no_mangle]\n\
                  pub extern \"C\" fn helper() {}\n\
                  #[cfg(test)]\nmod tests {\n    fn g() { unsafe { h() } }\n}\n";
    let code = strip(source);
    assert_eq!(unsafe_lines(&code), [5]);
    assert_eq!(pointer_casts(&code), [(5, ".cast::<"), (6, "as *const")]);

    // unsafe in a file the page does not list, and a listed file without any.
    let holding = [
        ("src/hydro/qtf.rs".to_string(), unsafe_lines(&code)),
        ("src/allocator.rs".to_string(), Vec::new()),
    ];
    assert_eq!(
        unsafe_misplaced(&holding, &["src/allocator.rs".to_string()]),
        [
            "src/hydro/qtf.rs:5: unsafe code in a file the page does not list",
            "src/allocator.rs is listed but holds no unsafe code",
        ]
    );
    assert!(unsafe_misplaced(&holding[..1], &["src/hydro/qtf.rs".to_string()]).is_empty());

    // A cast outside the handle module, none inside it.
    assert_eq!(
        casts_misplaced("src/fmi2/exports.rs", &code),
        [
            "src/fmi2/exports.rs:5: `.cast::<` outside the handle module (fmi/src/fmi2/handle.rs)",
            "src/fmi2/exports.rs:6: `as *const` outside the handle module (fmi/src/fmi2/handle.rs)",
        ]
    );
    assert!(casts_misplaced(HANDLE_MODULE, &code).is_empty());

    // #[no_mangle] outside the shims, or on something other than an fmi2 function.
    assert_eq!(
        exports_misplaced("fmi/src/fmi2/functions/mod.rs", &code),
        ["fmi/src/fmi2/functions/mod.rs:8: #[no_mangle] outside the cdylibs' shims"]
    );
    assert_eq!(
        exports_misplaced("fmi/src/fmi2/exports.rs", &code),
        ["fmi/src/fmi2/exports.rs:9: exports \"pub extern \\\"C\\\" fn helper() {}\", not an fmi2 or fmi3 function"]
    );
    let shim = "#[no_mangle]\npub extern \"C\" fn fmi2GetVersion() -> *const c_char {\n";
    assert!(exports_misplaced("fmi/src/fmi2/exports.rs", shim).is_empty());
    // A cdylib's own module that makes its shims by the macro writes no `#[no_mangle]`.
    assert_eq!(
        exports_misplaced("src/fmi2/exports.rs", shim),
        ["src/fmi2/exports.rs:1: #[no_mangle] outside the cdylibs' shims"]
    );
    assert_eq!(
        exports_misplaced("fmi/src/lib.rs", "#[export_name = \"fmi2Reset\"]\n"),
        ["fmi/src/lib.rs:1: names an exported symbol"]
    );
}

/// A mode of src/model/modes.rs as this test needs it: its type and each variant's word.
struct ModeWords {
    name: &'static str,
    words: &'static [(&'static str, &'static str)],
}

/// src/model/modes.rs, the one definition of the modes, as tables (the crate's `modes!` makes
/// the enums from it, build.rs's its check of the model description).
macro_rules! modes {
    ($(
        $(#[$meta:meta])*
        $name:ident
        $(in $parameter:literal $(, keeping $keep:literal: $keep_description:literal)?)? {
            $($(#[$variant_meta:meta])* $variant:ident = $word:literal: $description:literal,)+
        }
    )*) => {
        /// Every mode, in the file's order.
        const MODES: &[ModeWords] = &[$(ModeWords {
            name: stringify!($name),
            words: &[$((stringify!($variant), $word)),+],
        }),*];
    };
}

include!("../../src/model/modes.rs");

/// The one definition of the modes.
const MODES_FILE: &str = "model/modes.rs";

/// The string literals of each array of two or more string literals in `code` (`&["a",
/// "b"]`), with the line where it starts.
fn string_arrays(code: &str) -> Vec<(usize, Vec<String>)> {
    let bytes = code.as_bytes();
    let mut arrays = Vec::new();
    for (open, _) in code.match_indices('[') {
        let mut i = open + 1;
        let mut items = Vec::new();
        loop {
            while i < bytes.len() && bytes[i].is_ascii_whitespace() {
                i += 1;
            }
            if bytes.get(i) != Some(&b'"') {
                break;
            }
            let start = i + 1;
            i = start;
            while i < bytes.len() && bytes[i] != b'"' {
                i += if bytes[i] == b'\\' { 2 } else { 1 };
            }
            items.push(code[start..i.min(code.len())].to_string());
            i += 1;
            while i < bytes.len() && bytes[i].is_ascii_whitespace() {
                i += 1;
            }
            match bytes.get(i) {
                Some(b',') => i += 1,
                _ => break,
            }
        }
        while i < bytes.len() && bytes[i].is_ascii_whitespace() {
            i += 1;
        }
        if items.len() >= 2 && bytes.get(i) == Some(&b']') {
            arrays.push((1 + code[..open].matches('\n').count(), items));
        }
    }
    arrays
}

/// The enums of `code` that derive `Deserialize` and have only unit variants (words that
/// serde reads), by name.
fn word_enums(code: &str) -> Vec<String> {
    let mut found = Vec::new();
    for (at, _) in code.match_indices("enum ") {
        let attributes = &code[code[..at].rfind(['}', ';']).map_or(0, |i| i + 1)..at];
        if !(attributes.contains("derive(") && attributes.contains("Deserialize")) {
            continue;
        }
        let rest = &code[at + "enum ".len()..];
        let Some(open) = rest.find('{') else { continue };
        let name = rest[..open].trim().to_string();
        let mut depth = 0;
        let mut body = String::new();
        for c in rest[open + 1..].chars() {
            match c {
                '[' => depth += 1,
                ']' => depth -= 1,
                '}' if depth == 0 => break,
                _ if depth == 0 => body.push(c),
                _ => {}
            }
        }
        // The body without its attributes (`#[serde(rename = "...")]` dropped above).
        if !body.contains(['{', '(']) {
            found.push(name);
        }
    }
    found
}

/// Where `code` writes a mode's words a second time: a string array with two words of one
/// mode, a line that pairs a mode's variant with its word (`Interaction::Auto => "auto"`),
/// or an enum of words that serde reads (a mirror of a mode).
fn words_written_twice(code: &str) -> Vec<String> {
    let mut found = Vec::new();
    for (line, items) in string_arrays(code) {
        for mode in MODES {
            let words: Vec<&String> = items
                .iter()
                .filter(|item| mode.words.iter().any(|(_, word)| word == item))
                .collect();
            if words.len() >= 2 {
                found.push(format!(
                    "line {line}: the words of {} as a list {words:?}",
                    mode.name
                ));
            }
        }
    }
    for (n, text) in code.lines().enumerate() {
        for mode in MODES {
            for (variant, word) in mode.words {
                let names_variant = text.match_indices(&format!("::{variant}")).any(|(i, m)| {
                    !text[i + m.len()..].starts_with(|c: char| c.is_alphanumeric() || c == '_')
                });
                let quotes_word = text.contains(&format!("\"{word}\""))
                    || text.contains(&format!("\\\"{word}\\\""));
                if names_variant && quotes_word {
                    found.push(format!(
                        "line {}: {variant} paired with its word \"{word}\" ({}::word gives it)",
                        n + 1,
                        mode.name
                    ));
                }
            }
        }
    }
    for name in word_enums(code) {
        // `Dof`'s words are the JSON database's (its `Serialize` writes them too): not a mode.
        if name != "Dof" {
            found.push(format!(
                "enum {name}: words that serde reads, a mirror of a mode"
            ));
        }
    }
    found
}

/// The check catches each way of writing a mode's words twice.
#[test]
fn words_written_twice_are_found() {
    let drag_list = "const WORDS: &[&str] = &[\n    \"off\",\n    \"separate\", \"combined\"];";
    assert_eq!(words_written_twice(drag_list).len(), 1, "{drag_list}");
    assert!(words_written_twice("&[\"off\", \"jonswap\"]").is_empty());
    for pair in [
        "Interaction::Auto => \"auto\",",
        "\"mean-direction\" => Interaction::MeanDirection,",
        "Spectrum::Jonswap { .. } => \"spectrum = \\\"jonswap\\\"\",",
    ] {
        assert_eq!(words_written_twice(pair).len(), 1, "{pair}");
    }
    assert!(words_written_twice("DragKind::Offset => \"off\"").is_empty());
    let mirror = "#[derive(Deserialize, Clone, Copy)]\n#[serde(rename_all = \"kebab-case\")]\n\
                  enum NewmanFile {\n    Geometric,\n    #[serde(rename = \"x\")]\n    \
                  Arithmetic,\n}";
    assert_eq!(words_written_twice(mirror).len(), 1, "{mirror}");
    let tagged = "#[derive(Deserialize)]\nenum DriftFile {\n    Csv { file: PathBuf },\n}";
    assert!(words_written_twice(tagged).is_empty());
}

/// Every mode is defined once, in src/model/modes.rs (its words, codes and descriptions): no
/// other file of src/ lists a mode's words, pairs a variant with its word, or mirrors a
/// mode in an enum of its own (tests aside).
#[test]
fn every_mode_is_defined_once() {
    let src = Path::new(ROOT).join("src");
    let mut found = Vec::new();
    for file in source_files() {
        let rel = file
            .strip_prefix(&src)
            .unwrap()
            .to_string_lossy()
            .into_owned();
        if rel != MODES_FILE {
            found.extend(
                words_written_twice(&code(&file))
                    .into_iter()
                    .map(|f| format!("{rel}: {f}")),
            );
        }
    }
    assert!(
        found.is_empty(),
        "a mode's words outside {MODES_FILE}:\n{}",
        found.join("\n")
    );
}
