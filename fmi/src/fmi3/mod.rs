//! The FMI 3.0 co-simulation layer: a thin adapter beside [`crate::fmi2`], with no model
//! and no physics.
//!
//! - [`types`]: the C types of the FMI 3.0 headers, written by hand;
//! - [`machine`]: the FMI 3.0 calls and the states that allow each, on the layer's one
//!   state machine;
//! - [`functions`]: every FMI 3.0 function for any [`crate::fmi2::Model`]: an FMI 3.0
//!   instance is the FMI 2.0 layer's (its model, state, logger and report), so one model
//!   serves both standards; the functions the FMU does not provide answer `fmi3Error`;
//! - [`crate::fmi3_exports`]: the `#[no_mangle] extern "C" fn fmi3*` shims of a cdylib, all
//!   of them, made for its model by one macro call.
//!
//! The variables are the FMI 2.0 model description's, with one more: the independent
//! variable `time` ([`TIME_VALUE_REFERENCE`]), which FMI 3.0 requires of every model
//! description and which these functions answer themselves.

pub mod functions;
pub mod machine;
pub mod types;
#[macro_use]
mod exports;

/// The value reference of the independent variable `time` in every FMI 3.0 model
/// description of the layer (no FMI 2.0 variable may take it).
pub const TIME_VALUE_REFERENCE: u32 = 999_999;

/// How a model's FMI 2.0 value references, unique per base type, become FMI 3.0's, unique
/// across all variables: FMI 3.0 value reference = FMI 2.0 value reference + the offset of
/// its FMI 2.0 base type. The model descriptions are generated with it
/// (`slowdrift-fmi-xml`), and the functions subtract it before they ask the model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Numbering {
    /// Added to a Real's value reference (its Float64's).
    pub real: u32,
    /// Added to an Integer's (its Int32's).
    pub integer: u32,
    /// Added to a Boolean's.
    pub boolean: u32,
    /// Added to a String's.
    pub string: u32,
}

impl Numbering {
    /// Every value reference as in FMI 2.0 (for a description whose value references are
    /// unique across types already).
    pub const SAME: Numbering = Numbering {
        real: 0,
        integer: 0,
        boolean: 0,
        string: 0,
    };
}
