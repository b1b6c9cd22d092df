//! The platform: `[platform]` and its `[[platform.columns]]`.

use crate::error::{Error, Result};
use crate::model::Cylinder;
use crate::scenario::{BodyInertia, Motions, Origins, Platform};
use crate::wind::{CoefficientTable, WindArea, WindCoefficients, WindLoad};
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
    wind: Option<WindLoadFile>,
}

/// `[platform.wind]`: the wind coefficients, body frame (docs/configuration.md#platform-wind):
/// a table against the relative angle, or `[[platform.wind.areas]]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct WindLoadFile {
    /// m above still water.
    height: f64,
    angle_deg: Option<Vec<f64>>,
    cx: Option<Vec<f64>>,
    cy: Option<Vec<f64>>,
    cmz: Option<Vec<f64>>,
    /// m^2, m^2, m.
    area_x: Option<f64>,
    area_y: Option<f64>,
    length: Option<f64>,
    /// (x, y), m.
    centre: Option<[f64; 2]>,
    #[serde(default)]
    areas: Vec<WindAreaFile>,
}

/// `[[platform.wind.areas]]`, body frame, m and m^2.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct WindAreaFile {
    x: f64,
    y: f64,
    height: f64,
    area_x: f64,
    area_y: f64,
    shape_coefficient: f64,
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
        let wind = match self.wind {
            Some(w) => Some(w.into_core().map_err(|e| origins.locate(e))?),
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
            wind,
        })
    }
}

impl WindLoadFile {
    /// The coefficients, checked: the table's keys all given (the centre defaults to the
    /// reference point) or areas alone.
    fn into_core(self) -> Result<WindLoad> {
        let table_keys = [
            ("angle_deg", self.angle_deg.is_some()),
            ("cx", self.cx.is_some()),
            ("cy", self.cy.is_some()),
            ("cmz", self.cmz.is_some()),
            ("area_x", self.area_x.is_some()),
            ("area_y", self.area_y.is_some()),
            ("length", self.length.is_some()),
            ("centre", self.centre.is_some()),
        ];
        let coefficients = if self.areas.is_empty() {
            let missing = |key: &str| {
                Error::invalid(
                    format!("platform.wind.{key}"),
                    "missing",
                    "the coefficient table needs angle_deg, cx, cy, cmz, area_x, area_y and \
                     length (or give [[platform.wind.areas]] instead)",
                )
            };
            WindCoefficients::Table(CoefficientTable {
                angles: self
                    .angle_deg
                    .ok_or_else(|| missing("angle_deg"))?
                    .iter()
                    .map(|d| d.to_radians())
                    .collect(),
                cx: self.cx.ok_or_else(|| missing("cx"))?,
                cy: self.cy.ok_or_else(|| missing("cy"))?,
                cmz: self.cmz.ok_or_else(|| missing("cmz"))?,
                area_x: self.area_x.ok_or_else(|| missing("area_x"))?,
                area_y: self.area_y.ok_or_else(|| missing("area_y"))?,
                length: self.length.ok_or_else(|| missing("length"))?,
                centre: self.centre.unwrap_or([0.0, 0.0]),
            })
        } else {
            if let Some((key, _)) = table_keys.iter().find(|(_, given)| *given) {
                return Err(Error::invalid(
                    format!("platform.wind.{key}"),
                    "beside [[platform.wind.areas]]",
                    "give the coefficient table or the areas, not both",
                ));
            }
            WindCoefficients::Areas(
                self.areas
                    .into_iter()
                    .map(|a| WindArea {
                        centre: [a.x, a.y],
                        height: a.height,
                        area_x: a.area_x,
                        area_y: a.area_y,
                        shape_coefficient: a.shape_coefficient,
                    })
                    .collect(),
            )
        };
        let load = WindLoad {
            height: self.height,
            coefficients,
        };
        load.validate()?;
        Ok(load)
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
