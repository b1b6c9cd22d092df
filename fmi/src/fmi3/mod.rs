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
    /// FMI 2.0 Real scalars that FMI 3.0 gives as one array variable each.
    pub arrays: &'static [ArrayVariable],
}

/// One FMI 3.0 array variable (`<Dimension start="count"/>`) made of the FMI 2.0 Real
/// scalars `{name}1` .. `{name}{count}`, whose value references are `first` .. `first +
/// count - 1`; the array's FMI 3.0 value reference is `first` plus the Reals' offset, and
/// its values are the scalars' in that order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ArrayVariable {
    /// The array's name, and the scalars' without their number.
    pub name: &'static str,
    /// The FMI 2.0 value reference of `{name}1`.
    pub first: u32,
    /// Its length, the number of scalars.
    pub count: u32,
    /// Its description in the FMI 3.0 description.
    pub description: &'static str,
}

impl Numbering {
    /// Every value reference as in FMI 2.0 (for a description whose value references are
    /// unique across types already).
    pub const SAME: Numbering = Numbering {
        real: 0,
        integer: 0,
        boolean: 0,
        string: 0,
        arrays: &[],
    };

    /// The FMI 2.0 value references of the Float64 value reference `vr` (an FMI 3.0 one):
    /// an array's scalars, or the one Real; `None` when it names no Real of the FMI 3.0
    /// description (below the offset, or an array's scalar after its first).
    pub fn reals(&self, vr: u32) -> Option<std::ops::Range<u32>> {
        let fmi2 = vr.checked_sub(self.real)?;
        match self
            .arrays
            .iter()
            .find(|a| (a.first..a.first + a.count).contains(&fmi2))
        {
            Some(array) if array.first == fmi2 => Some(array.first..array.first + array.count),
            Some(_) => None,
            None => Some(fmi2..fmi2 + 1),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The mooring's numbering by hand: Reals unmoved, the tensions 101..108 one array.
    #[test]
    fn reals_expand_an_array_and_refuse_its_other_elements() {
        const N: Numbering = Numbering {
            integer: 1000,
            string: 2000,
            arrays: &[ArrayVariable {
                name: "t",
                first: 101,
                count: 8,
                description: "",
            }],
            ..Numbering::SAME
        };
        assert_eq!(N.reals(0), Some(0..1));
        assert_eq!(N.reals(100), Some(100..101));
        assert_eq!(N.reals(101), Some(101..109));
        assert_eq!(
            N.reals(102),
            None,
            "an element after the first is not a Float64"
        );
        assert_eq!(N.reals(109), Some(109..110));
        let moved = Numbering { real: 5, ..N };
        assert_eq!(moved.reals(4), None, "below the Reals' offset");
        assert_eq!(moved.reals(106), Some(101..109));
    }
}
