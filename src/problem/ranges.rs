//! The physical ranges of a problem's values: a value outside its range describes no
//! platform or sea that SlowDrift models (`gravity = 1e300`, `mass = 1e-300`), and is refused
//! naming the setting, its value and the range, instead of run. The ranges are wide: from a
//! laboratory model at Froude scale to ten times the largest floating structures; a value
//! near a bound is a warning sign, not an error. docs/configuration.md#limits lists them.
//!
//! The stiffness is checked for what makes it physical, not for a range
//! ([`check_stiffness`]): the energy it stores, x^T C x, must not be negative.

use crate::error::numbers::{readable, written, written_matrix};
use crate::error::{Error, Result};
use nalgebra::Matrix3;

/// A closed interval of physical values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    pub min: f64,
    pub max: f64,
    /// The unit of the bounds, as the configuration file writes the value.
    pub unit: &'static str,
    /// What the bounds cover.
    pub covers: &'static str,
}

/// `environment.gravity`, m/s^2.
pub const GRAVITY: Range = Range {
    min: 9.0,
    max: 10.5,
    unit: "m/s^2",
    covers: "the Earth's gravity (9.78 at the equator to 9.83 at the poles) and rounded values \
             such as 10",
};

/// `environment.water_density`, kg/m^3.
pub const WATER_DENSITY: Range = Range {
    min: 900.0,
    max: 1300.0,
    unit: "kg/m^3",
    covers: "fresh water (1000), sea water (1020-1030) and brines",
};

/// `platform.mass`, kg.
pub const MASS: Range = Range {
    min: 1.0,
    max: 1.0e10,
    unit: "kg",
    covers: "a laboratory model to ten times the largest floating structure (6e8 kg)",
};

/// `platform.yaw_inertia`, kg m^2 (about the body origin).
pub const YAW_INERTIA: Range = Range {
    min: 1.0e-3,
    max: 1.0e16,
    unit: "kg m^2",
    covers: "a laboratory model to ten times the largest floating structure's",
};

/// `sea.tp`, s.
pub const PEAK_PERIOD: Range = Range {
    min: 0.3,
    max: 50.0,
    unit: "s",
    covers: "laboratory waves to the longest swell (about 25 s)",
};

/// Either end of `sea.band`, rad/s.
pub const BAND: Range = Range {
    min: 1.0e-3,
    max: 100.0,
    unit: "rad/s",
    covers: "wave periods from 0.06 s to 6000 s",
};

/// `current.speed`, m/s.
pub const CURRENT_SPEED: Range = Range {
    min: 0.0,
    max: 10.0,
    unit: "m/s",
    covers: "still water to twice the fastest tidal streams (about 5 m/s)",
};

/// `platform.columns[k].diameter`, m.
pub const COLUMN_DIAMETER: Range = Range {
    min: 1.0e-3,
    max: 200.0,
    unit: "m",
    covers: "a laboratory model's column to twice the widest floating columns",
};

/// `platform.columns[k].draft`, m.
pub const COLUMN_DRAFT: Range = Range {
    min: 1.0e-3,
    max: 1000.0,
    unit: "m",
    covers: "a laboratory model's column to five times the deepest spar",
};

/// `platform.columns[k].x` and `.y`, m: each within this distance of the body origin.
pub const COLUMN_OFFSET: Range = Range {
    min: -1000.0,
    max: 1000.0,
    unit: "m",
    covers: "columns within a kilometre of the body origin",
};

/// `sea.direction_deg` and `current.direction_deg`, deg.
pub const DIRECTION: Range = Range {
    min: -360.0,
    max: 360.0,
    unit: "deg",
    covers: "a turn either way",
};

/// Largest offset |X|, |Y| of a physical state, m (1000 km).
pub const MAX_OFFSET: f64 = 1.0e6;
/// Largest yaw |theta| of a physical state, rad (about 160 000 turns: sin and cos of theta
/// keep 10 significant digits).
pub const MAX_YAW: f64 = 1.0e6;
/// Largest speed |X'|, |Y'| of a physical state, m/s (1 km/s).
pub const MAX_SPEED: f64 = 1.0e3;
/// Largest yaw rate |theta'| of a physical state, rad/s (a turn in 0.6 s).
pub const MAX_YAW_RATE: f64 = 10.0;

/// The initial state (X, Y, theta) and (X', Y', theta') within the bounds of a physical
/// state (`simulation::bounds`), each named by its key and shown in the file's unit
/// (degrees for the angles).
pub fn check_initial_state(position: &[f64; 3], velocity: &[f64; 3]) -> Result<()> {
    let (x, y, yaw) = (position[0], position[1], position[2]);
    let checks = [
        ("initial.position[0]", x, MAX_OFFSET, 1.0, "m"),
        ("initial.position[1]", y, MAX_OFFSET, 1.0, "m"),
        (
            "initial.heading_deg",
            yaw,
            MAX_YAW,
            1f64.to_degrees(),
            "deg",
        ),
        ("initial.velocity[0]", velocity[0], MAX_SPEED, 1.0, "m/s"),
        ("initial.velocity[1]", velocity[1], MAX_SPEED, 1.0, "m/s"),
        (
            "initial.yaw_rate_deg",
            velocity[2],
            MAX_YAW_RATE,
            1f64.to_degrees(),
            "deg/s",
        ),
    ];
    for (key, value, bound, scale, unit) in checks {
        if value.is_nan() || value.abs() > bound {
            let shown = if scale == 1.0 {
                written(value)
            } else {
                readable(value * scale)
            };
            return Err(Error::invalid(
                key,
                shown,
                format!(
                    "must be within -{} .. {} {unit}: beyond it the state is no physical \
                     state of a moored platform",
                    readable(bound * scale),
                    readable(bound * scale)
                ),
            ));
        }
    }
    Ok(())
}

impl Range {
    /// Refuses `value` (finite, within the bounds) naming `field`.
    pub fn check(&self, field: impl Into<String>, value: f64) -> Result<()> {
        if value.is_finite() && (self.min..=self.max).contains(&value) {
            return Ok(());
        }
        Err(self.refusal(field, written(value)))
    }

    /// Refuses an angle held in radians whose file value (degrees) is outside the bounds,
    /// shown in degrees to six digits (the conversion's last bits are not the user's).
    pub fn check_degrees(&self, field: impl Into<String>, radians: f64) -> Result<()> {
        let shown = readable(radians.to_degrees());
        let degrees: f64 = shown.parse().unwrap_or(f64::NAN);
        if degrees.is_finite() && (self.min..=self.max).contains(&degrees) {
            return Ok(());
        }
        Err(self.refusal(field, shown))
    }

    fn refusal(&self, field: impl Into<String>, shown: String) -> Error {
        Error::invalid(
            field,
            shown,
            format!(
                "must be within {} .. {} {} ({})",
                written(self.min),
                written(self.max),
                self.unit,
                self.covers
            ),
        )
    }
}

/// The stiffness C on (X, Y, theta) (N/m, N, N m/rad): each diagonal entry not negative,
/// and the symmetric part positive semi-definite (x^T C x >= 0 for every displacement: a
/// spring that gives energy back is not a mooring). Zero is allowed (an external mooring
/// restores the platform). The check is made on D Cs D with D = diag(1/sqrt(C_ii)) (the
/// entries with C_ii = 0 unscaled), which has the definiteness of Cs (Sylvester's law of
/// inertia) and unit diagonal, so that N/m and N m/rad weigh alike; an eigenvalue below
/// -1e-9 is refused. The errors name `platform.stiffness[i][i]` or `platform.stiffness`.
pub fn check_stiffness(c: &[[f64; 3]; 3]) -> Result<()> {
    const KEYS: [&str; 3] = [
        "platform.stiffness[0][0]",
        "platform.stiffness[1][1]",
        "platform.stiffness[2][2]",
    ];
    for (i, key) in KEYS.iter().enumerate() {
        if c[i][i] < 0.0 {
            return Err(Error::invalid(
                *key,
                written(c[i][i]),
                "must not be negative: a negative stiffness pushes the platform away from its \
                 mean position (0 = no internal stiffness: an external mooring restores it)",
            ));
        }
    }
    let scale: [f64; 3] = std::array::from_fn(|i| {
        if c[i][i] > 0.0 {
            1.0 / c[i][i].sqrt()
        } else {
            1.0
        }
    });
    let scaled = Matrix3::from_fn(|i, j| 0.5 * (c[i][j] + c[j][i]) * scale[i] * scale[j]);
    let lowest = scaled.symmetric_eigenvalues().min();
    if lowest < -1e-9 {
        return Err(Error::invalid(
            "platform.stiffness",
            written_matrix(c),
            format!(
                "is not positive semi-definite: a displacement along the eigenvector of its \
                 symmetric part with the eigenvalue {} (scaled by the diagonal) stores negative \
                 energy; its off-diagonal terms are larger than the diagonal allows",
                readable(lowest)
            ),
        ));
    }
    Ok(())
}

/// The mass matrix M + A (body frame) must be positive definite: its symmetric part's
/// eigenvalues, scaled by the diagonal as in [`check_stiffness`], above 1e-9 (a kinetic
/// energy that vanishes or changes sign describes no body).
pub fn mass_matrix_is_positive(total: &[[f64; 3]; 3]) -> bool {
    if (0..3).any(|i| total[i][i].is_nan() || total[i][i] <= 0.0) {
        return false;
    }
    let scale: [f64; 3] = std::array::from_fn(|i| 1.0 / total[i][i].sqrt());
    let scaled = Matrix3::from_fn(|i, j| 0.5 * (total[i][j] + total[j][i]) * scale[i] * scale[j]);
    scaled.symmetric_eigenvalues().min() > 1e-9
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_outside_a_range_are_refused_as_written() {
        assert!(GRAVITY.check("environment.gravity", 9.80665).is_ok());
        let e = GRAVITY.check("environment.gravity", 1e300).unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid environment.gravity = 1e300: must be within 9 .. 10.5 m/s^2 (the Earth's \
             gravity (9.78 at the equator to 9.83 at the poles) and rounded values such as 10)"
        );
        let e = MASS.check("platform.mass", 1e-300).unwrap_err().to_string();
        assert!(
            e.contains("platform.mass = 1e-300") && e.contains("1 .. 1e10 kg"),
            "{e}"
        );
        assert!(MASS.check("platform.mass", f64::NAN).is_err());
        assert!(CURRENT_SPEED.check("current.speed", 0.0).is_ok());
    }

    #[test]
    fn stiffness_must_store_no_negative_energy() {
        let diagonal = |a, b, c| [[a, 0.0, 0.0], [0.0, b, 0.0], [0.0, 0.0, c]];
        assert!(check_stiffness(&diagonal(1e5, 1e5, 1e9)).is_ok());
        assert!(check_stiffness(&diagonal(0.0, 0.0, 0.0)).is_ok());
        let e = check_stiffness(&diagonal(1e5, -1.0, 1e9))
            .unwrap_err()
            .to_string();
        assert!(e.contains("platform.stiffness[1][1] = -1"), "{e}");
        // Coupled surge-yaw: PSD iff C13^2 <= C11 C33 (here 1e5 x 1e9 = 1e14).
        let coupled = |c13: f64| [[1e5, 0.0, c13], [0.0, 1e5, 0.0], [c13, 0.0, 1e9]];
        assert!(check_stiffness(&coupled(0.99e7)).is_ok());
        let e = check_stiffness(&coupled(1.01e7)).unwrap_err().to_string();
        assert!(
            e.contains("invalid platform.stiffness = [[100000, 0, 1.01e7]"),
            "{e}"
        );
        assert!(e.contains("not positive semi-definite"), "{e}");
        // An off-diagonal term on a DOF without stiffness makes it indefinite.
        assert!(check_stiffness(&[[1e5, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]]).is_err());
        // Only the symmetric part stores energy: an antisymmetric coupling is no refusal.
        assert!(check_stiffness(&[[1e5, 5e5, 0.0], [-5e5, 1e5, 0.0], [0.0, 0.0, 1e9]]).is_ok());
    }

    #[test]
    fn mass_matrix_positive_definite() {
        let m = [[2e7, 0.0, 0.0], [0.0, 2e7, 0.0], [0.0, 0.0, 1e10]];
        assert!(mass_matrix_is_positive(&m));
        let mut negative = m;
        negative[1][1] = -1.0;
        assert!(!mass_matrix_is_positive(&negative));
        let mut coupled = m;
        coupled[0][2] = 1e9;
        coupled[2][0] = 1e9;
        // 1e9^2 = 1e18 > 2e7 x 1e10 = 2e17.
        assert!(!mass_matrix_is_positive(&coupled));
    }
}
