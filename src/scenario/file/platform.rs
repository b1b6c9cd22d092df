//! The platform: `[platform]` and its `[[platform.columns]]`.

use crate::error::{Error, Result};
use crate::model::Cylinder;
use crate::scenario::{BodyInertia, Motions, Origins, Platform};
use serde::Deserialize;

/// `[platform]`; every matrix is indexed (surge, sway, yaw) like [`Platform`].
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct PlatformFile {
    mass: Option<f64>,
    yaw_inertia: Option<f64>,
    added_mass: Option<[[f64; 3]; 3]>,
    stiffness: [[f64; 3]; 3],
    #[serde(default)]
    linear_damping: [[f64; 3]; 3],
    #[serde(default)]
    quadratic_damping: [[f64; 3]; 3],
    #[serde(default)]
    columns: Vec<ColumnFile>,
    motions: Option<MotionsFile>,
}

/// `[platform.motions]`: body frame about the reference point (docs/configuration.md).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MotionsFile {
    /// m.
    centre_of_gravity: [f64; 3],
    /// m, about the centre of gravity; or `inertia`.
    radii_of_gyration: Option<[f64; 3]>,
    /// kg m^2, about the centre of gravity; or `radii_of_gyration`.
    inertia: Option<[[f64; 3]; 3]>,
    #[serde(default)]
    external_stiffness: [[f64; 6]; 6],
    #[serde(default)]
    external_damping: [[f64; 6]; 6],
}

/// `[[platform.columns]]`, body frame, m.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ColumnFile {
    x: f64,
    y: f64,
    diameter: f64,
    draft: f64,
}

impl PlatformFile {
    /// The platform; a `[platform.motions]` that gives both or neither of its inertias is
    /// refused at its line.
    pub(super) fn into_core(self, origins: &Origins) -> Result<Platform> {
        let motions = match self.motions {
            Some(m) => Some(m.into_core().map_err(|e| origins.locate(e))?),
            None => None,
        };
        Ok(Platform {
            mass: self.mass,
            yaw_inertia: self.yaw_inertia,
            added_mass: self.added_mass,
            stiffness: self.stiffness,
            linear_damping: self.linear_damping,
            quadratic_damping: self.quadratic_damping,
            columns: self
                .columns
                .into_iter()
                .map(|c| Cylinder {
                    x: c.x,
                    y: c.y,
                    diameter: c.diameter,
                    draft: c.draft,
                })
                .collect(),
            motions,
            wind: None,
        })
    }
}

impl MotionsFile {
    fn into_core(self) -> Result<Motions> {
        const TENSOR: &str = "platform.motions.inertia";
        let inertia =
            match (self.radii_of_gyration, self.inertia) {
                (Some(radii), None) => BodyInertia::RadiiOfGyration(radii),
                (None, Some(tensor)) => BodyInertia::Tensor(tensor),
                (Some(_), Some(_)) => {
                    return Err(Error::invalid(
                        TENSOR,
                        "beside radii_of_gyration",
                        "give radii_of_gyration (m) or inertia (kg m^2), not both",
                    ))
                }
                (None, None) => return Err(Error::invalid(
                    "platform.motions",
                    "without an inertia",
                    "give radii_of_gyration (m) or inertia (kg m^2), about the centre of gravity",
                )),
            };
        Ok(Motions {
            centre_of_gravity: self.centre_of_gravity,
            inertia,
            external_stiffness: self.external_stiffness,
            external_damping: self.external_damping,
        })
    }
}
