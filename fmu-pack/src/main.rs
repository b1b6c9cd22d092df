//! `fmu-pack`: will package the SlowDrift cdylib as `target/fmu/SlowDrift.fmu` and run it
//! through its C ABI. The FMI 2.0 exports it packs are issue #4's work; until they exist
//! this tool says so and fails, rather than writing an FMU that cannot be loaded.

use std::process::ExitCode;

fn main() -> ExitCode {
    eprintln!(
        "fmu-pack: the FMI 2.0 co-simulation exports are not built yet (issue #4); \
         nothing to pack. Run the simulation with `cargo run --release -- simulate`."
    );
    ExitCode::from(2)
}
