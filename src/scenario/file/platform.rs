//! The platform: `[platform]` and its `[[platform.columns]]`.

use crate::model::Cylinder;
use crate::scenario::Platform;
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
    pub(super) fn into_core(self) -> Platform {
        Platform {
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
        }
    }
}
