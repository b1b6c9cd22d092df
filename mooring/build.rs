//! Exports only the `fmi2*` symbols of the cdylib (the FMU's rule), with the FMI layer's
//! linker version script (`fmi/src/fmi2/exports.map` of the workspace: one script for both
//! FMUs).

fn main() {
    let script =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../fmi/src/fmi2/exports.map");
    println!("cargo:rerun-if-changed={}", script.display());
    println!("cargo:rerun-if-changed=build.rs");
    if std::env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("linux") {
        println!(
            "cargo:rustc-cdylib-link-arg=-Wl,--version-script={}",
            script.display()
        );
    }
}
