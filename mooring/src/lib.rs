//! The mooring FMU of SlowDrift's co-simulation (docs/coupling.md): MoorDyn's mooring lines
//! on a platform that moves in six degrees of freedom, as an FMI 2.0 co-simulation FMU
//! (`target/fmu/Mooring.fmu`, packed by `fmu-pack`).
//!
//! - [`motion`]: the platform's motion and force (X, Y, Z, roll, pitch, theta; Fx, Fy, Fz,
//!   Mx, My, Mz) against MoorDyn's six coupled degrees of freedom: the frame, angle and sign
//!   conventions, in one place.
//! - [`moordyn`]: MoorDyn's C library, loaded at run time from beside this library, behind
//!   a safe type (one mooring system, closed when dropped).
//! - [`catenary`], [`lines_file`], [`quasi_static`]: the quasi-static alternative to
//!   MoorDyn's dynamic lines (`mooringModel` = 1): each line an elastic catenary on a
//!   frictionless seabed, read from the same MoorDyn input file.
//! - [`fmi2`]: the C ABI (the 34 FMI 2.0 functions, shims into the FMI layer that SlowDrift's
//!   FMU shares, the workspace's `slowdrift-fmi`), its variables and the model it runs.

// Unsafe code: only MoorDyn's C library (`moordyn`) and the C shims (`fmi2::exports`) allow
// it (checked by the workspace's tests/all/architecture.rs).
#![deny(unsafe_code)]

pub mod catenary;
pub mod fmi2;
pub mod lines_file;
pub mod moordyn;
pub mod motion;
pub mod quasi_static;
