//! The slow-drift equations of motion (E&S 1, 2) and their time integration.

mod eom;
mod rk4;

pub use eom::{BodyFrame, ForceBreakdown, Held, Read, SlowDriftModel};
pub use rk4::rk4_step;
