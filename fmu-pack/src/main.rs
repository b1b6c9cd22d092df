//! `fmu-pack`: will package the SlowDrift cdylib as `target/fmu/SlowDrift.fmu` and run it
//! through its C ABI. The FMI 2.0 exports exist (`src/fmi2/`, built into `libslowdrift.so`);
//! packing them is the rest of issue #4. Until then this tool says so and fails, rather than
//! writing an archive that has not been checked.

use std::process::ExitCode;

fn main() -> ExitCode {
    eprintln!(
        "fmu-pack: packing the FMU is not implemented yet (issue #4); the FMI 2.0 \
         co-simulation library is built by `cargo build --release` (libslowdrift.so). \
         Run the simulation with `cargo run --release -- simulate`."
    );
    ExitCode::from(2)
}
