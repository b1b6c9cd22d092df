//! NEMOH v3 results into the native database (`slowdrift hydro nemoh --dir DIR`).
//!
//! | file | what is taken | conventions |
//! |---|---|---|
//! | `Nemoh.cal` | rho, g, depth; the body's DOFs and generalised forces (which are surge, sway, yaw; the point the yaw moment is taken about); the QTF grid and its output unit | [`cal`] |
//! | `results/CM.dat` | the added mass at the lowest frequency as the low-frequency added mass | dimensional; NEMOH has no omega = 0 |
//! | `Mechanics/Inertia.dat`, `Mechanics/Kh.dat` | mass and yaw inertia; hydrostatic stiffness | dimensional, about the DOFs' points |
//! | `results/RadiationCoefficients.tec`, `results/ExcitationForce.tec` | A, B per frequency, the excitation per frequency and heading: the database's `first_order` | [`tec`], [`first_order`]: A[i][j] the force i of zone (motion) j; excitation conjugated from e^{-i omega t}; the 6 DOFs moved from Nemoh.cal's point to the origin |
//! | `Mechanics/Km.dat`, `Mechanics/Badd.dat` (and `Inertia.dat`, `Kh.dat` 6 x 6) | with the above, the database's `rao` solved ([`crate::hydro::rao::solve`]): M = Inertia, C_hs = Kh (the weight's restoring in), C_ext = Km (mooring), B_ext = Badd | absent Km, Badd are zero |
//! | `results/QTF/OUT_QTFM_N.dat` (or the one `OUT_QTFM_N*.dat`) | the difference-frequency QTF: the database's `qtf`, its diagonal as the mean drift, its bi-directional diagonal as `bidirectional_drift` | [`qtf`]: divided by rho g, e^{-i omega t}, lower triangle |
//!
//! Reference point: NEMOH takes moments about the point each generalised force names (the
//! OC3 spar's about (0, 0, -78) m). A yaw moment about a point on the vertical axis through
//! the origin is the yaw moment about the origin; a point off that axis is moved to the
//! origin ([`crate::hydro::reference_point`]), the yaw motion's axis too (the two must be
//! the same vertical axis). Units in the database are SI, frequencies rad/s, headings rad.

pub mod cal;
pub mod matrices;
pub mod qtf;
pub mod tec;

pub mod first_order;
mod import;

pub use import::import;
