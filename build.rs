//! Checks `modelDescription/modelDescription.xml` and generates
//! `$OUT_DIR/model_description.rs` from it (GUID, model identifier, value references,
//! start values and the variable table), so the Rust code and the XML cannot drift apart.
//!
//! The build fails with a message naming the offending variable on: duplicate names,
//! duplicate value references within a base type, illegal causality/variability/initial
//! combinations, missing or forbidden start values, start values outside min/max, missing
//! descriptions, LogCategories other than the FMI layer's (`slowdrift_fmi::log::Category`,
//! in its order), and a ModelStructure whose Outputs or InitialUnknowns do not match the
//! variables. The variables must be master-neutral (docs/fmu.md, "Master-neutral variables"):
//! no Enumeration (libcosim and ecos register only Real, Integer, Boolean and String: a mode
//! is an Integer with min, max and its codes in the description), and every Real carries
//! its own `unit`, one of the UnitDefinitions and its declaredType's (OMSimulator does not
//! inherit a unit from a declaredType). Each mode's FMU parameter (`src/model/modes.rs`, the
//! one definition of the modes, `include!`d here) must be an Integer whose min, max and
//! description list exactly the mode's codes, words and descriptions.
//!
//! From the same XML it generates the FMI 3.0 model description,
//! `$OUT_DIR/fmi3/modelDescription.xml` (`slowdrift-fmi-xml`: every value reference kept),
//! and its constants, `$OUT_DIR/fmi3/numbering.rs` (`crate::fmi2::fmi3_description`); a
//! description the generator cannot convert fails the build with its error.
//!
//! It also writes the embedded default platform's database (`src/hydro/default_platform.json`)
//! as MessagePack, `$OUT_DIR/default_platform.msgpack`: the same values (each number read
//! correctly rounded, then stored as its 8 bytes; the drift table's 5 364 nodes as arrays,
//! without their field names), which the library reads without parsing a decimal number
//! (`hydro::default_platform`; a test compares the two readings bit for bit).

use quick_xml::events::{BytesStart, Event};
use quick_xml::{Reader, XmlVersion};
use slowdrift_fmi::log::Category;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::PathBuf;

const XML_PATH: &str = "modelDescription/modelDescription.xml";
/// Linker version script of every FMU's cdylib (the FMI layer's): `fmi2*` global,
/// everything else local.
const VERSION_SCRIPT: &str = "fmi/src/fmi2/exports.map";
/// The modes' one definition, read here through the `modes!` below.
const MODES_PATH: &str = "src/model/modes.rs";
/// The embedded default platform's database (`hydro::default_platform`).
const DEFAULT_PLATFORM: &str = "src/hydro/default_platform.json";
/// What a mode parameter's description says before its codes.
const CODES_FOLLOW: &str = ", a code: ";

/// A mode of `src/model/modes.rs` as this script needs it.
struct ModeTable {
    /// The mode's type (`DragKind`).
    name: &'static str,
    /// Its FMU Integer parameter, if any.
    parameter: Option<&'static str>,
    /// The word of code 0 that keeps the configuration's choice, and its description.
    keep: Option<(&'static str, &'static str)>,
    /// Its words and their descriptions, in the order of their codes.
    words: &'static [(&'static str, &'static str)],
}

/// `src/model/modes.rs` as plain tables (the crate's `modes!` makes the enums from it).
macro_rules! modes {
    ($(
        $(#[$meta:meta])*
        $name:ident
        $(in $parameter:literal $(, keeping $keep:literal: $keep_description:literal)?)? {
            $($(#[$variant_meta:meta])* $variant:ident = $word:literal: $description:literal,)+
        }
    )*) => {
        /// Every mode, in the file's order.
        const MODES: &[ModeTable] = &[$(ModeTable {
            name: stringify!($name),
            parameter: modes!(@option $($parameter)?),
            keep: modes!(@option $($($keep, $keep_description)?)?),
            words: &[$(($word, $description)),+],
        }),*];
    };
    (@option) => { None };
    (@option $value:literal) => { Some($value) };
    (@option $word:literal, $description:literal) => { Some(($word, $description)) };
}

include!("src/model/modes.rs");

/// One `ScalarVariable` as read from the XML.
#[derive(Debug, Default)]
struct Var {
    name: String,
    vr: u32,
    causality: String,
    variability: String,
    initial: Option<String>,
    description: Option<String>,
    /// Real, Integer, Boolean, String (or Enumeration, which the checks refuse).
    ty: String,
    declared_type: Option<String>,
    start: Option<String>,
    /// `unit`, `min` and `max` of the type element.
    unit: Option<String>,
    min: Option<String>,
    max: Option<String>,
    line: usize,
}

/// One `Unknown` of `Outputs` or `InitialUnknowns`.
#[derive(Debug)]
struct Unknown {
    index: usize,
    dependencies: Option<Vec<usize>>,
}

#[derive(Debug, Default)]
struct Model {
    fmi_version: String,
    guid: String,
    model_identifier: Option<String>,
    vars: Vec<Var>,
    /// `UnitDefinitions/Unit` names.
    units: BTreeSet<String>,
    /// `SimpleType` name -> the `unit` of its Real element (None: a type without one).
    type_units: BTreeMap<String, Option<String>>,
    outputs: Vec<Unknown>,
    initial_unknowns: Vec<Unknown>,
    saw_model_structure: bool,
    /// `LogCategories/Category` names, in order.
    log_categories: Vec<String>,
}

fn main() {
    println!("cargo:rerun-if-changed={XML_PATH}");
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed={MODES_PATH}");
    println!("cargo:rerun-if-changed={DEFAULT_PLATFORM}");
    export_only_fmi2_symbols();

    let xml = std::fs::read_to_string(XML_PATH)
        .unwrap_or_else(|e| fail(&format!("cannot read {XML_PATH}: {e}")));
    let model = parse(&xml).unwrap_or_else(|e| fail(&e));
    let errors = check(&model);
    if !errors.is_empty() {
        fail(&errors.join("\n  "));
    }
    let code = generate(&model);
    let out_dir = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR"));
    write(&out_dir.join("model_description.rs"), &code);
    let fmi3 = slowdrift_fmi_xml::fmi3_model_description(&xml)
        .unwrap_or_else(|e| fail(&format!("no FMI 3.0 description: {e}")));
    let fmi3_dir = out_dir.join("fmi3");
    std::fs::create_dir_all(&fmi3_dir)
        .unwrap_or_else(|e| fail(&format!("cannot create {}: {e}", fmi3_dir.display())));
    write(&fmi3_dir.join("modelDescription.xml"), &fmi3);
    let numbering = slowdrift_fmi_xml::rust_constants(&slowdrift_fmi_xml::Numbering::SAME);
    write(&fmi3_dir.join("numbering.rs"), &numbering);
    default_platform_as_messagepack(&out_dir.join("default_platform.msgpack"));
}

/// The fields of a drift-table node (`hydro::io::database::DriftPoint`), in its order: serde
/// reads a struct from an array of its fields in order.
const DRIFT_POINT_FIELDS: [&str; 6] = ["omega", "heading", "surge", "sway", "yaw", "damping"];

/// The embedded default platform's database as MessagePack: maps with their field names, as
/// the JSON has them, but for the drift table's nodes, arrays of [`DRIFT_POINT_FIELDS`]
/// (a third less to read).
fn default_platform_as_messagepack(path: &std::path::Path) {
    let text = std::fs::read_to_string(DEFAULT_PLATFORM)
        .unwrap_or_else(|e| unreadable(&format!("cannot read {DEFAULT_PLATFORM}: {e}")));
    let mut value: serde_json::Value = serde_json::from_str(&text)
        .unwrap_or_else(|e| unreadable(&format!("{DEFAULT_PLATFORM}: {e}")));
    let Some(drift) = value.get_mut("drift").and_then(|d| d.as_array_mut()) else {
        unreadable(&format!("{DEFAULT_PLATFORM} has no drift table"));
    };
    for node in drift {
        let fields = node
            .as_object()
            .filter(|o| o.len() == DRIFT_POINT_FIELDS.len());
        let array = fields.and_then(|o| {
            DRIFT_POINT_FIELDS
                .iter()
                .map(|f| o.get(*f).cloned())
                .collect::<Option<Vec<_>>>()
        });
        let Some(array) = array else {
            unreadable(&format!(
                "{DEFAULT_PLATFORM}: a drift node without exactly the fields \
                 {DRIFT_POINT_FIELDS:?}: {node}"
            ));
        };
        *node = serde_json::Value::Array(array);
    }
    let bytes = rmp_serde::to_vec_named(&value)
        .unwrap_or_else(|e| unreadable(&format!("{DEFAULT_PLATFORM} as MessagePack: {e}")));
    std::fs::write(path, bytes)
        .unwrap_or_else(|e| unreadable(&format!("cannot write {}: {e}", path.display())));
}

fn write(path: &std::path::Path, text: &str) {
    std::fs::write(path, text)
        .unwrap_or_else(|e| fail(&format!("cannot write {}: {e}", path.display())));
}

/// The cdylib exports only `fmi2*` symbols (FMI 2.0: nothing else may clash with the
/// host's symbols): a linker version script, on Linux, where the FMU's binaries are built.
fn export_only_fmi2_symbols() {
    println!("cargo:rerun-if-changed={VERSION_SCRIPT}");
    if std::env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("linux") {
        let dir = std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR");
        let script = PathBuf::from(dir).join(VERSION_SCRIPT);
        println!(
            "cargo:rustc-cdylib-link-arg=-Wl,--version-script={}",
            script.display()
        );
    }
}

/// Fails the build on the embedded default platform's database.
fn unreadable(message: &str) -> ! {
    panic!("the embedded default platform's database: {message}");
}

fn fail(message: &str) -> ! {
    panic!("{XML_PATH} is invalid:\n  {message}");
}

/// The attributes of an element as a name -> unescaped value map.
fn attrs(e: &BytesStart, line: usize) -> Result<BTreeMap<String, String>, String> {
    let mut map = BTreeMap::new();
    for a in e.attributes() {
        let a = a.map_err(|err| format!("line {line}: bad attribute: {err}"))?;
        let key = a.key.as_ref().to_string();
        let value = a
            .normalized_value(XmlVersion::Implicit1_0)
            .map_err(|err| format!("line {line}: bad value of {key}: {err}"))?
            .into_owned();
        if map.insert(key.clone(), value).is_some() {
            return Err(format!("line {line}: attribute {key} given twice"));
        }
    }
    Ok(map)
}

fn parse(xml: &str) -> Result<Model, String> {
    let mut reader = Reader::from_str(xml);
    let mut model = Model::default();
    let mut stack: Vec<String> = Vec::new();
    let mut current_type: Option<String> = None;
    loop {
        let pos = reader.buffer_position() as usize;
        let line = 1 + xml[..pos.min(xml.len())].matches('\n').count();
        let event = reader
            .read_event()
            .map_err(|e| format!("line {line}: XML error: {e}"))?;
        let (e, is_empty) = match event {
            Event::Start(e) => (e, false),
            Event::Empty(e) => (e, true),
            Event::End(_) => {
                if stack.pop().as_deref() == Some("SimpleType") {
                    current_type = None;
                }
                continue;
            }
            Event::Eof => break,
            _ => continue,
        };
        let tag = e.name().as_ref().to_string();
        let a = attrs(&e, line)?;
        let parent = stack.last().map(String::as_str);
        match (parent, tag.as_str()) {
            (None, "fmiModelDescription") => {
                model.fmi_version = a.get("fmiVersion").cloned().unwrap_or_default();
                model.guid = a.get("guid").cloned().unwrap_or_default();
            }
            (Some("fmiModelDescription"), "CoSimulation") => {
                model.model_identifier = a.get("modelIdentifier").cloned();
            }
            (Some("UnitDefinitions"), "Unit") => {
                let name = a
                    .get("name")
                    .ok_or(format!("line {line}: Unit without name"))?;
                if !model.units.insert(name.clone()) {
                    return Err(format!("line {line}: unit {name} defined twice"));
                }
            }
            (Some("TypeDefinitions"), "SimpleType") => {
                current_type = a.get("name").cloned();
            }
            (Some("SimpleType"), ty) => {
                let name = current_type
                    .clone()
                    .ok_or(format!("line {line}: SimpleType without name"))?;
                let unit = a.get("unit").cloned().filter(|_| ty == "Real");
                if model.type_units.insert(name.clone(), unit).is_some() {
                    return Err(format!("line {line}: type {name} defined twice"));
                }
            }
            (Some("ModelVariables"), "ScalarVariable") => {
                let get = |k: &str| {
                    a.get(k)
                        .cloned()
                        .ok_or(format!("line {line}: ScalarVariable without {k}"))
                };
                let name = get("name")?;
                let vr = get("valueReference")?
                    .parse::<u32>()
                    .map_err(|err| format!("line {line}: {name}: valueReference: {err}"))?;
                model.vars.push(Var {
                    name,
                    vr,
                    // FMI 2 defaults: causality local, variability continuous.
                    causality: a.get("causality").cloned().unwrap_or("local".into()),
                    variability: a.get("variability").cloned().unwrap_or("continuous".into()),
                    initial: a.get("initial").cloned(),
                    description: a.get("description").cloned(),
                    line,
                    ..Var::default()
                });
            }
            (
                Some("ScalarVariable"),
                ty @ ("Real" | "Integer" | "Boolean" | "String" | "Enumeration"),
            ) => {
                let var = model.vars.last_mut().expect("inside a ScalarVariable");
                if !var.ty.is_empty() {
                    return Err(format!("line {line}: {} has two type elements", var.name));
                }
                var.ty = ty.to_string();
                var.declared_type = a.get("declaredType").cloned();
                var.start = a.get("start").cloned();
                var.unit = a.get("unit").cloned();
                var.min = a.get("min").cloned();
                var.max = a.get("max").cloned();
            }
            (Some("LogCategories"), "Category") => {
                let name = a
                    .get("name")
                    .ok_or(format!("line {line}: Category without name"))?;
                model.log_categories.push(name.clone());
            }
            (Some("fmiModelDescription"), "ModelStructure") => model.saw_model_structure = true,
            (Some(list @ ("Outputs" | "InitialUnknowns" | "Derivatives")), "Unknown") => {
                let index = a
                    .get("index")
                    .ok_or(format!("line {line}: Unknown without index"))?
                    .parse::<usize>()
                    .map_err(|err| format!("line {line}: Unknown index: {err}"))?;
                let dependencies = match a.get("dependencies") {
                    None => None,
                    Some(d) => Some(
                        d.split_whitespace()
                            .map(|s| s.parse::<usize>())
                            .collect::<Result<Vec<_>, _>>()
                            .map_err(|err| format!("line {line}: dependencies: {err}"))?,
                    ),
                };
                let unknown = Unknown {
                    index,
                    dependencies,
                };
                match list {
                    "Outputs" => model.outputs.push(unknown),
                    "InitialUnknowns" => model.initial_unknowns.push(unknown),
                    _ => return Err(format!("line {line}: this model declares no Derivatives")),
                }
            }
            _ => {}
        }
        if !is_empty {
            stack.push(tag);
        }
    }
    Ok(model)
}

/// Every problem found, one line each (empty = valid).
fn check(m: &Model) -> Vec<String> {
    let mut errors = Vec::new();
    if m.fmi_version != "2.0" {
        errors.push(format!(
            "fmiVersion is {:?}, expected \"2.0\"",
            m.fmi_version
        ));
    }
    if !(m.guid.starts_with('{') && m.guid.ends_with('}') && m.guid.len() > 2) {
        errors.push(format!("guid {:?} is not a UUID in braces", m.guid));
    }
    match &m.model_identifier {
        None => errors.push("no CoSimulation element with a modelIdentifier".into()),
        Some(id) if !is_c_identifier(id) => {
            errors.push(format!("modelIdentifier {id:?} is not a C identifier"))
        }
        Some(_) => {}
    }
    if m.vars.is_empty() {
        errors.push("no ScalarVariable".into());
    }
    // The FMI layer logs to exactly these categories, and fmi2SetDebugLogging accepts them.
    let layer = Category::ALL.map(Category::name);
    if m.log_categories != layer {
        errors.push(format!(
            "LogCategories are {:?}: they must be the FMI layer's, {layer:?}, in this order",
            m.log_categories
        ));
    }

    let mut names = BTreeMap::new();
    let mut idents = BTreeMap::new();
    let mut vrs = BTreeMap::new();
    for v in &m.vars {
        let at = format!("{} (line {})", v.name, v.line);
        if let Some(first) = names.insert(v.name.as_str(), v.line) {
            errors.push(format!("duplicate name {at}, first on line {first}"));
        }
        if !is_c_identifier(&v.name) {
            errors.push(format!(
                "{at}: name is not a flat C-like identifier (variableNamingConvention flat, \
                 and it must map to a Rust constant)"
            ));
        }
        if let Some(other) = idents.insert(const_name(&v.name), v.name.as_str()) {
            if other != v.name {
                errors.push(format!(
                    "{at}: Rust constant {} clashes with {other}",
                    const_name(&v.name)
                ));
            }
        }
        let space = v.ty.as_str();
        if let Some(other) = vrs.insert((space, v.vr), v.name.as_str()) {
            errors.push(format!(
                "{at}: valueReference {} of type {space} already used by {other}",
                v.vr
            ));
        }
        if v.description.as_deref().is_none_or(|d| d.trim().is_empty()) {
            errors.push(format!("{at}: no description"));
        }
        if v.ty.is_empty() {
            errors.push(format!("{at}: no type element (Real, Integer, ...)"));
            continue;
        }
        errors.extend(
            check_combination(v)
                .into_iter()
                .map(|e| format!("{at}: {e}")),
        );
        errors.extend(
            check_master_neutral(m, v)
                .into_iter()
                .map(|e| format!("{at}: {e}")),
        );
        if let Some(start) = &v.start {
            if let Err(e) = start_literal(&v.ty, start) {
                errors.push(format!("{at}: start {start:?}: {e}"));
            }
        }
        errors.extend(check_bounds(v).into_iter().map(|e| format!("{at}: {e}")));
    }
    errors.extend(check_modes(m));

    if !m.saw_model_structure {
        errors.push("no ModelStructure".into());
    }
    let n = m.vars.len();
    let index_of = |pred: &dyn Fn(&Var) -> bool| -> Vec<usize> {
        (1..=n).filter(|&i| pred(&m.vars[i - 1])).collect()
    };
    let outputs = index_of(&|v| v.causality == "output");
    let listed: Vec<usize> = m.outputs.iter().map(|u| u.index).collect();
    if listed != outputs {
        errors.push(format!(
            "ModelStructure/Outputs lists indices {listed:?}; the output variables \
             (1-based, in order) are {outputs:?}"
        ));
    }
    let initial = index_of(&|v| {
        (v.causality == "output"
            && matches!(
                effective_initial(v).as_deref(),
                Some("approx" | "calculated")
            ))
            || v.causality == "calculatedParameter"
    });
    let listed: Vec<usize> = m.initial_unknowns.iter().map(|u| u.index).collect();
    if listed != initial {
        errors.push(format!(
            "ModelStructure/InitialUnknowns lists indices {listed:?}; expected exactly the \
             outputs with initial approx/calculated and the calculated parameters, \
             sorted: {initial:?}"
        ));
    }
    for (list, unknowns) in [
        ("Outputs", &m.outputs),
        ("InitialUnknowns", &m.initial_unknowns),
    ] {
        for u in unknowns {
            for &d in u.dependencies.iter().flatten() {
                if d == 0 || d > n {
                    errors.push(format!(
                        "ModelStructure/{list}: index {}: dependency {d} out of 1..={n}",
                        u.index
                    ));
                } else if list == "Outputs" {
                    let dep = &m.vars[d - 1];
                    if !matches!(dep.causality.as_str(), "input" | "independent") {
                        errors.push(format!(
                            "ModelStructure/Outputs: index {}: dependency {d} ({}) is not an \
                             input (states are not declared in this model)",
                            u.index, dep.name
                        ));
                    }
                }
            }
        }
    }
    errors
}

/// What every master reads alike: no Enumeration (libcosim and ecos skip them), and a
/// Real's own `unit`, declared and equal to its declaredType's (OMSimulator reads only the
/// variable's own attribute).
fn check_master_neutral(m: &Model, v: &Var) -> Vec<String> {
    let mut errors = Vec::new();
    match v.ty.as_str() {
        "Enumeration" => errors.push(
            "is an Enumeration, which libcosim and ecos do not register: make it an Integer \
             with min, max and its codes in the description"
                .into(),
        ),
        "Real" => match &v.unit {
            None => errors.push(
                "a Real needs its own unit attribute (OMSimulator does not inherit it from \
                 a declaredType)"
                    .into(),
            ),
            Some(unit) => {
                if !m.units.contains(unit) {
                    errors.push(format!("unit {unit:?} is not in UnitDefinitions"));
                }
                if let Some(t) = &v.declared_type {
                    match m.type_units.get(t) {
                        None => errors.push(format!("declaredType {t:?} is not defined")),
                        Some(Some(declared)) if declared != unit => errors.push(format!(
                            "unit {unit:?} differs from its declaredType {t}'s {declared:?}"
                        )),
                        Some(_) => {}
                    }
                }
            }
        },
        _ => {}
    }
    errors
}

/// Each mode's FMU parameter (`MODES`, from src/model/modes.rs) is an Integer parameter
/// whose min and max are its first and last code and whose description lists, after
/// ", a code: ", exactly its codes in order, each with its word and description: "0 off (no
/// viscous drag), 1 separate (C_DS U|U| + C_DL u|u|, E&S 8; cdSlow, cdFast), ..." (what the
/// FMU adds follows the description after "; "). An Integer whose description lists codes
/// is a mode's.
fn check_modes(m: &Model) -> Vec<String> {
    let mut errors = Vec::new();
    for mode in MODES {
        let Some(parameter) = mode.parameter else {
            continue;
        };
        let Some(v) = m.vars.iter().find(|v| v.name == parameter) else {
            errors.push(format!(
                "mode {} ({MODES_PATH}) is written by FMU parameter {parameter}, which is not \
                 a variable",
                mode.name
            ));
            continue;
        };
        let at = format!("{} (line {})", v.name, v.line);
        if v.ty != "Integer" || v.causality != "parameter" {
            errors.push(format!(
                "{at}: the mode {} is an Integer parameter, not a {} {}",
                mode.name, v.causality, v.ty
            ));
            continue;
        }
        let codes: Vec<(&str, &str)> = mode
            .keep
            .into_iter()
            .chain(mode.words.iter().copied())
            .collect();
        let last = (codes.len() - 1).to_string();
        if v.min.as_deref() != Some("0") || v.max.as_deref() != Some(last.as_str()) {
            errors.push(format!(
                "{at}: min and max must be 0 and {last}, the codes of the mode {} \
                 ({MODES_PATH})",
                mode.name
            ));
        }
        let description = v.description.as_deref().unwrap_or_default();
        let listed = match description.split_once(CODES_FOLLOW) {
            Some((_, list)) => check_code_list(list, &codes),
            None => Err(format!("no {CODES_FOLLOW:?}")),
        };
        if let Err(e) = listed {
            errors.push(format!(
                "{at}: the description must list the codes of the mode {} ({MODES_PATH}), \
                 each with its word and description, after {CODES_FOLLOW:?}: {e}",
                mode.name
            ));
        }
    }
    for v in &m.vars {
        let lists_codes = v
            .description
            .as_deref()
            .is_some_and(|d| d.contains(CODES_FOLLOW));
        if lists_codes
            && !MODES
                .iter()
                .any(|mode| mode.parameter == Some(v.name.as_str()))
        {
            errors.push(format!(
                "{} (line {}): its description lists codes, but no mode of {MODES_PATH} is \
                 written by it",
                v.name, v.line
            ));
        }
    }
    errors
}

/// `list` is exactly `codes`, in order: "0 word (description[; more]), 1 ...".
fn check_code_list(list: &str, codes: &[(&str, &str)]) -> Result<(), String> {
    let mut rest = list;
    for (code, (word, description)) in codes.iter().enumerate() {
        let item = format!("{code} {word} ({description}");
        rest = rest
            .strip_prefix(&item)
            .ok_or_else(|| format!("expected {item:?}..., found {rest:?}"))?;
        let close = closing_parenthesis(rest)
            .ok_or_else(|| format!("no closing parenthesis after {item:?}"))?;
        let more = &rest[..close];
        if !(more.is_empty() || more.starts_with("; ")) {
            return Err(format!(
                "after {item:?}, expected \")\" or \"; \", found {more:?}"
            ));
        }
        rest = &rest[close + 1..];
        if code + 1 < codes.len() {
            rest = rest
                .strip_prefix(", ")
                .ok_or_else(|| format!("expected \", \" after code {code}, found {rest:?}"))?;
        }
    }
    if rest.is_empty() {
        Ok(())
    } else {
        Err(format!("more than the {} codes: {rest:?}", codes.len()))
    }
}

/// The byte offset of the parenthesis that closes one already open.
fn closing_parenthesis(text: &str) -> Option<usize> {
    let mut depth = 1;
    for (i, c) in text.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i);
                }
            }
            _ => {}
        }
    }
    None
}

/// `min <= start <= max` where given (Real and Integer).
fn check_bounds(v: &Var) -> Vec<String> {
    let number = |s: &Option<String>| s.as_ref().and_then(|s| s.trim().parse::<f64>().ok());
    let (min, max, start) = (number(&v.min), number(&v.max), number(&v.start));
    let mut errors = Vec::new();
    for (name, given, parsed) in [("min", &v.min, min), ("max", &v.max, max)] {
        if given.is_some() && parsed.is_none() {
            errors.push(format!("{name} {given:?} is not a number"));
        }
    }
    if let (Some(lo), Some(hi)) = (min, max) {
        if lo > hi {
            errors.push(format!("min {lo} is above max {hi}"));
        }
    }
    if let Some(x) = start {
        if min.is_some_and(|lo| x < lo) || max.is_some_and(|hi| x > hi) {
            errors.push(format!("start {x} is outside [min, max]"));
        }
    }
    errors
}

/// The legal causality/variability/initial/start combinations of FMI 2.0 (section 2.2.7),
/// with `initial` defaulted as the standard says.
fn check_combination(v: &Var) -> Vec<String> {
    let mut errors = Vec::new();
    let (c, var) = (v.causality.as_str(), v.variability.as_str());
    let initial = v.initial.as_deref();
    let has_start = v.start.is_some();
    let legal_variability: &[&str] = match c {
        "parameter" | "calculatedParameter" => &["fixed", "tunable"],
        "input" => &["discrete", "continuous"],
        "output" => &["constant", "discrete", "continuous"],
        "local" => &["constant", "fixed", "tunable", "discrete", "continuous"],
        "independent" => &["continuous"],
        _ => {
            errors.push(format!("unknown causality {c:?}"));
            return errors;
        }
    };
    if !legal_variability.contains(&var) {
        errors.push(format!(
            "causality {c} with variability {var} is illegal (allowed: {legal_variability:?})"
        ));
    }
    if var == "continuous" && v.ty != "Real" {
        errors.push(format!(
            "variability continuous needs type Real, not {}",
            v.ty
        ));
    }
    match c {
        "parameter" => {
            if !matches!(initial, None | Some("exact")) {
                errors.push(format!(
                    "a parameter needs initial=\"exact\", not {initial:?}"
                ));
            }
            if !has_start {
                errors.push("a parameter needs a start value".into());
            }
        }
        "calculatedParameter" => {
            if !matches!(initial, None | Some("calculated" | "approx")) {
                errors.push(format!(
                    "a calculatedParameter needs initial calculated or approx, not {initial:?}"
                ));
            }
        }
        "input" => {
            if initial.is_some() {
                errors.push("an input must not have an initial attribute".into());
            }
            if !has_start {
                errors.push("an input needs a start value".into());
            }
        }
        "independent" => {
            if initial.is_some() || has_start {
                errors.push("the independent variable has neither initial nor start".into());
            }
        }
        _ => {
            // output and local
            let allowed: &[&str] = if var == "constant" {
                &["exact"]
            } else if c == "local" && matches!(var, "fixed" | "tunable") {
                &["calculated", "approx"]
            } else {
                &["exact", "approx", "calculated"]
            };
            let eff = effective_initial(v);
            if let Some(i) = eff.as_deref() {
                if !allowed.contains(&i) {
                    errors.push(format!(
                        "causality {c}, variability {var}: initial {i} is illegal \
                         (allowed: {allowed:?})"
                    ));
                }
            }
        }
    }
    match (effective_initial(v).as_deref(), has_start) {
        (Some("exact" | "approx"), false) => errors.push(format!(
            "initial {} needs a start value",
            effective_initial(v).unwrap_or_default()
        )),
        (Some("calculated"), true) => {
            errors.push("initial calculated must not have a start value".into())
        }
        _ => {}
    }
    errors
}

/// `initial` as given, or its FMI 2.0 default for the causality and variability.
fn effective_initial(v: &Var) -> Option<String> {
    if let Some(i) = &v.initial {
        return Some(i.clone());
    }
    match (v.causality.as_str(), v.variability.as_str()) {
        ("input" | "independent", _) => None,
        (_, "constant") => Some("exact".into()),
        ("parameter", _) => Some("exact".into()),
        ("calculatedParameter", _) => Some("calculated".into()),
        ("local", "fixed" | "tunable") => Some("calculated".into()),
        _ => Some("calculated".into()),
    }
}

fn is_c_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// `waveDirection` -> `WAVE_DIRECTION`, `Fx_ext` -> `FX_EXT`, `Hs` -> `HS`.
fn const_name(name: &str) -> String {
    let mut out = String::new();
    let mut prev: Option<char> = None;
    for c in name.chars() {
        if c.is_ascii_uppercase()
            && prev.is_some_and(|p| p.is_ascii_lowercase() || p.is_ascii_digit())
        {
            out.push('_');
        }
        out.push(c.to_ascii_uppercase());
        prev = Some(c);
    }
    out
}

/// The Rust type and literal of a start value.
fn start_literal(ty: &str, start: &str) -> Result<(&'static str, String), String> {
    match ty {
        "Real" => {
            let x: f64 = start.trim().parse().map_err(|e| format!("{e}"))?;
            if !x.is_finite() {
                return Err("not finite".into());
            }
            Ok(("f64", format!("{x:?}")))
        }
        "Integer" => {
            let x: i32 = start.trim().parse().map_err(|e| format!("{e}"))?;
            Ok(("i32", x.to_string()))
        }
        "Boolean" => match start.trim() {
            "true" | "1" => Ok(("bool", "true".into())),
            "false" | "0" => Ok(("bool", "false".into())),
            other => Err(format!("{other:?} is not a boolean")),
        },
        "String" => Ok(("&str", format!("{start:?}"))),
        other => Err(format!("unknown type {other}")),
    }
}

fn rust_variant(s: &str) -> String {
    let mut c = s.chars();
    c.next()
        .map(|f| f.to_ascii_uppercase().to_string() + c.as_str())
        .unwrap_or_default()
}

fn generate(m: &Model) -> String {
    let mut s = String::new();
    let w = &mut s;
    let _ = writeln!(
        w,
        "// @generated by build.rs from {XML_PATH}. Do not edit.\n"
    );
    let _ = writeln!(
        w,
        "/// The GUID of the model description; fmi2Instantiate must receive it."
    );
    let _ = writeln!(w, "pub const GUID: &str = {:?};", m.guid);
    let _ = writeln!(
        w,
        "/// The co-simulation model identifier (the shared library's name)."
    );
    let _ = writeln!(
        w,
        "pub const MODEL_IDENTIFIER: &str = {:?};",
        m.model_identifier.as_deref().unwrap_or_default()
    );
    let _ = writeln!(w, "/// Number of model variables.");
    let _ = writeln!(
        w,
        "pub const NUMBER_OF_VARIABLES: usize = {};\n",
        m.vars.len()
    );

    let _ = writeln!(
        w,
        "/// Value references, one per variable (unique within a base type)."
    );
    let _ = writeln!(w, "pub mod vr {{");
    for v in &m.vars {
        let _ = writeln!(w, "    /// `{}` ({}, {}).", v.name, v.ty, v.causality);
        let _ = writeln!(w, "    pub const {}: u32 = {};", const_name(&v.name), v.vr);
    }
    let _ = writeln!(w, "}}\n");

    let _ = writeln!(w, "/// Start values of the variables that have one.");
    let _ = writeln!(w, "pub mod start {{");
    for v in &m.vars {
        if let Some(start) = &v.start {
            let (ty, lit) = start_literal(&v.ty, start).expect("checked");
            let _ = writeln!(w, "    /// `{}`.", v.name);
            let _ = writeln!(w, "    pub const {}: {ty} = {lit};", const_name(&v.name));
        }
    }
    let _ = writeln!(w, "}}\n");

    let _ = writeln!(
        w,
        "/// Every model variable in the XML's order (index = position + 1)."
    );
    let _ = writeln!(w, "pub const VARIABLES: &[VariableInfo] = &[");
    for v in &m.vars {
        let _ = writeln!(w, "    VariableInfo {{");
        let _ = writeln!(w, "        name: {:?},", v.name);
        let _ = writeln!(w, "        value_reference: {},", v.vr);
        let _ = writeln!(w, "        var_type: VariableType::{},", v.ty);
        let start = match (&v.start, v.ty.as_str()) {
            (None, _) => "Start::None".to_string(),
            (Some(s), "Real") => format!(
                "Start::Real({})",
                start_literal("Real", s).expect("checked").1
            ),
            (Some(s), "Integer") => {
                format!(
                    "Start::Integer({})",
                    start_literal("Integer", s).expect("checked").1
                )
            }
            (Some(s), _) => format!("Start::String({s:?})"),
        };
        let _ = writeln!(w, "        start: {start},");
        let _ = writeln!(
            w,
            "        causality: Causality::{},",
            rust_variant(&v.causality)
        );
        let _ = writeln!(
            w,
            "        variability: Variability::{},",
            rust_variant(&v.variability)
        );
        let _ = writeln!(w, "    }},");
    }
    let _ = writeln!(w, "];");
    s
}
