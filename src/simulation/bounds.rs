//! The bounds of a physical state, and the cause of a state or an output that
//! leaves them: which force, input or step made it.
//!
//! A restored state (an FMU state, a snapshot) beyond these bounds is refused; a step that
//! ends beyond them, or with a value that is not finite, is refused with its cause. They are
//! far outside any slow-drift motion (the default platform's surge stays within tens of
//! metres and tenths of a metre per second) and well inside what double precision and the
//! records resolve.

use crate::dynamics::{ForceBreakdown, SlowDriftModel};
use crate::error::numbers::{readable, written};
use crate::error::{Cause, Error};

/// The bounds themselves are the problem's physical ranges (an initial state is checked
/// against them with the configuration).
pub use crate::problem::ranges::{MAX_OFFSET, MAX_SPEED, MAX_YAW, MAX_YAW_RATE};

/// Names, bounds and units of (X, Y, theta, X', Y', theta'), as the FMU names them.
const STATE: [(&str, f64, &str); 6] = [
    ("X", MAX_OFFSET, "m"),
    ("Y", MAX_OFFSET, "m"),
    ("theta", MAX_YAW, "rad"),
    ("Xdot", MAX_SPEED, "m/s"),
    ("Ydot", MAX_SPEED, "m/s"),
    ("thetadot", MAX_YAW_RATE, "rad/s"),
];

/// The first of (X, Y, theta, X', Y', theta') that is not finite or beyond its bound, as a
/// text ("Xdot = 2.5e3 m/s, beyond 1000 m/s"); `None` when the state is physical. No
/// allocation unless it finds one.
#[inline]
pub fn violation(position: &[f64; 3], velocity: &[f64; 3]) -> Option<String> {
    // Every step asks: inlined, one pass that stops at the first violation, over the
    // table by reference (by value, every step copied it).
    position
        .iter()
        .chain(velocity)
        .zip(&STATE)
        .find(|(v, (_, bound, _))| v.is_nan() || v.abs() > *bound)
        .map(|(v, (name, bound, unit))| {
            if v.is_finite() {
                format!(
                    "{name} = {} {unit}, beyond {} {unit}",
                    readable(*v),
                    written(*bound)
                )
            } else {
                format!("{name} = {v}")
            }
        })
}

/// A restored state beyond the bounds, refused naming the value.
pub fn check_restored(position: &[f64; 3], velocity: &[f64; 3]) -> crate::error::Result<()> {
    match violation(position, velocity) {
        None => Ok(()),
        Some(what) => Err(Error::invalid(
            "state",
            what,
            "not a physical state (the bounds: |X|, |Y| <= 1e6 m, |theta| <= 1e6 rad, \
             |Xdot|, |Ydot| <= 1000 m/s, |thetadot| <= 10 rad/s)",
        )),
    }
}

/// Why a step from state (q, q') over `h` left the bounds, or an output there is not
/// finite, from the forces at its start: the first force that is not finite; else the
/// first force (or the external input) that alone would change the velocity by more than
/// a bound within the step; else the step itself.
pub fn cause(
    model: &SlowDriftModel,
    forces: &ForceBreakdown,
    external: &[f64; 3],
    theta: f64,
    h: f64,
) -> Cause {
    let bounds = [MAX_SPEED, MAX_SPEED, MAX_YAW_RATE];
    let excessive = |force: &[f64; 3]| -> Option<usize> {
        let change = model.velocity_change(theta, force, h);
        (0..3).find(|&i| change[i].is_nan() || change[i].abs() > bounds[i])
    };
    let records: [(&'static str, &[f64; 3], &'static [&'static str]); 3] = [
        ("wave force", &forces.wave, &["sea.hs", "drift"]),
        (
            "wave-drift damping force",
            &forces.damping,
            &["sea.hs", "drift", "model.drift_damping"],
        ),
        (
            "drag force",
            &forces.drag,
            &["model.cd", "sea.hs", "current.speed"],
        ),
    ];
    // A force that is not finite first (it explains a non-finite output), then one that is
    // excessive.
    let non_finite = |force: &[f64; 3]| force.iter().position(|v| !v.is_finite());
    for find in [&non_finite as &dyn Fn(&[f64; 3]) -> Option<usize>, &|f| {
        excessive(f)
    }] {
        if let Some((force, values, settings)) =
            records.iter().find(|(_, values, _)| find(values).is_some())
        {
            let dof = find(values).expect("found above");
            return Cause::Force {
                force,
                dof,
                value: values[dof],
                settings,
            };
        }
    }
    match excessive(external) {
        Some(dof) => Cause::External {
            dof,
            value: external[dof],
        },
        None => Cause::Step,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_value_beyond_its_bound_is_named() {
        assert_eq!(violation(&[1.0, -2.0, 0.1], &[0.5, 0.0, 0.01]), None);
        assert_eq!(
            violation(&[1.0, -2.0, 0.1], &[0.5, -2.5e3, 0.01]).as_deref(),
            Some("Ydot = -2500 m/s, beyond 1000 m/s")
        );
        assert_eq!(
            violation(&[f64::NAN, 0.0, 0.0], &[0.0; 3]).as_deref(),
            Some("X = NaN")
        );
        assert!(check_restored(&[0.0; 3], &[1e200, 0.0, 0.0])
            .unwrap_err()
            .to_string()
            .contains("Xdot = 1e200 m/s, beyond 1000 m/s"));
    }
}
