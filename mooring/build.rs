//! Exports only the `fmi2*` symbols of the cdylib (the FMU's rule), with the FMI layer's
//! linker version script (`fmi/src/fmi2/exports.map` of the workspace: one script for both
//! FMUs), and generates the FMU's FMI 3.0 model description from its FMI 2.0 one
//! (`modelDescription.xml`, the single source) with `slowdrift-fmi-xml`:
//! `$OUT_DIR/fmi3/modelDescription.xml` and its constants, `$OUT_DIR/fmi3/numbering.rs`
//! (`crate::fmi3_description`). A description the generator cannot convert fails the build
//! with its error.

use slowdrift_fmi_xml::{ArrayVariable, Numbering};
use std::path::{Path, PathBuf};

/// The FMI 2.0 description's value references are unique per type only (String 0,
/// Integer 0 and Real 0..25, 101..108): FMI 3.0's, unique across all variables, move the
/// Integers by 1000 and the Strings by 2000 (mooringModel 1000, mooringFile 2000); the
/// Reals keep theirs. The per-line fairlead tensions, FMI 2.0's fairleadTension1 ..
/// fairleadTension8 (value references 101 .. 108), are one FMI 3.0 array, fairleadTension
/// (value reference 101).
const NUMBERING: Numbering = Numbering {
    integer: 1000,
    string: 2000,
    arrays: &[ArrayVariable {
        name: "fairleadTension",
        first: 101,
        count: 8,
        description: "Fairlead tension of each mooring line (element k: line ID k of the \
                      mooring file) at the end of the last step",
    }],
    ..Numbering::SAME
};

const XML_PATH: &str = "modelDescription.xml";

fn main() {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fmi/src/fmi2/exports.map");
    println!("cargo:rerun-if-changed={}", script.display());
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed={XML_PATH}");
    if std::env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("linux") {
        println!(
            "cargo:rustc-cdylib-link-arg=-Wl,--version-script={}",
            script.display()
        );
    }
    let xml = std::fs::read_to_string(XML_PATH)
        .unwrap_or_else(|e| panic!("cannot read mooring/{XML_PATH}: {e}"));
    let fmi3 = slowdrift_fmi_xml::fmi3_model_description_numbered(&xml, &NUMBERING)
        .unwrap_or_else(|e| panic!("mooring/{XML_PATH}: no FMI 3.0 description: {e}"));
    let dir = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("fmi3");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
    for (file, text) in [
        ("modelDescription.xml", fmi3),
        (
            "numbering.rs",
            slowdrift_fmi_xml::rust_constants(&NUMBERING),
        ),
    ] {
        let path = dir.join(file);
        std::fs::write(&path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    }
}
