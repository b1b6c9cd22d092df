//! The wind's force on the platform from the relative velocity (docs/theory.md#wind-force):
//! the platform's wind coefficients as users have them, and the force at an instant.
//!
//! Frames and signs: body frame (x forward, y to port, z up) at the reference point, the
//! force on the body. The wind at the force's height blows towards beta_w (inertial, from +X
//! counter-clockwise) at the speed U(t) = mean + gust; the relative velocity at a point
//! (x, y) of the body is V_r = U(t) (cos(beta_w - theta), sin(beta_w - theta)) - (u - r y,
//! v + r x), (u, v, r) the body's slow velocity in the body frame. So the wind damps the slow
//! drift: a body moving with the wind feels less of it (the viscous wind effect of E&S
//! section 1).
//!
//! - Coefficients per unit dynamic pressure (the OCIMF and SIMO style): F_x = q A_x C_x(alpha),
//!   F_y = q A_y C_y(alpha), M_z = q A_y L C_mz(alpha), q = 1/2 rho_air |V_r|^2, alpha = atan2(V_r,y,
//!   V_r,x) the relative angle: the direction the relative wind blows towards, from the body's
//!   x axis counter-clockwise (0: from astern), V_r taken at the table's centre. The
//!   coefficients are interpolated linearly in alpha over a table that covers the circle.
//! - Projected areas (API RP 2SK's method, sec. 5.3): each area i (its centre (x_i, y_i),
//!   height z_i, areas A_x,i facing the x axis and A_y,i facing the y axis, shape coefficient
//!   C_s,i) takes F_x,i = 1/2 rho_air C_s,i A_x,i V_x |V|, F_y,i = 1/2 rho_air C_s,i A_y,i V_y
//!   |V| with V its relative velocity, the wind speed there being U(t) U(z_i)/U(z_f) (the
//!   mean profile's ratio to the force's height z_f, the gust scaled with it); M_z = sum
//!   (x_i F_y,i - y_i F_x,i). Linearised about a steady wind U along x, the areas damp surge
//!   by rho_air C_s A_x U (per area, at its speed).

use crate::error::{require_finite, require_positive, Error, Result};
use serde::Serialize;
use std::cmp::Ordering;
use std::f64::consts::PI;

/// The platform's wind coefficients (`[platform.wind]`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WindLoad {
    /// The height of the wind force, m above still water: where the mean and the gust
    /// records are taken (for the areas: their scale).
    pub height: f64,
    pub coefficients: WindCoefficients,
}

/// The two forms users have their wind loads in.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum WindCoefficients {
    /// Coefficients per unit dynamic pressure against the relative angle.
    Table(CoefficientTable),
    /// Projected areas with shape coefficients and heights (API RP 2SK).
    Areas(Vec<WindArea>),
}

/// C_x, C_y, C_mz against the relative angle, with their reference areas and length.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CoefficientTable {
    /// Relative angles alpha, rad, strictly increasing, spanning less than a full turn; the
    /// interpolation wraps from the last to the first + 2 pi.
    pub angles: Vec<f64>,
    pub cx: Vec<f64>,
    pub cy: Vec<f64>,
    pub cmz: Vec<f64>,
    /// A_x (the frontal area) and A_y (the lateral area), m^2; L the reference length, m.
    pub area_x: f64,
    pub area_y: f64,
    pub length: f64,
    /// Where the relative velocity is taken, (x, y) in the body frame, m.
    pub centre: [f64; 2],
}

/// One projected area of the areas form.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WindArea {
    /// (x, y) of its centre in the body frame, m.
    pub centre: [f64; 2],
    /// Height of its centre above still water, m.
    pub height: f64,
    /// Projected areas facing the x and the y axis, m^2.
    pub area_x: f64,
    pub area_y: f64,
    /// API RP 2SK's shape coefficient C_s.
    pub shape_coefficient: f64,
}

impl WindLoad {
    /// Checks the coefficients; the error names the setting of `[platform.wind]`.
    pub fn validate(&self) -> Result<()> {
        require_positive("platform.wind.height", self.height)?;
        match &self.coefficients {
            WindCoefficients::Table(t) => t.validate(),
            WindCoefficients::Areas(areas) => {
                if areas.is_empty() {
                    return Err(Error::invalid(
                        "platform.wind.areas",
                        "none",
                        "must list at least one area",
                    ));
                }
                for (i, a) in areas.iter().enumerate() {
                    let name = |key: &str| format!("platform.wind.areas[{}].{key}", i + 1);
                    require_finite(name("x"), a.centre[0])?;
                    require_finite(name("y"), a.centre[1])?;
                    require_positive(&name("height"), a.height)?;
                    for (key, value) in [("area_x", a.area_x), ("area_y", a.area_y)] {
                        require_finite(name(key), value)?;
                        if value < 0.0 {
                            return Err(Error::invalid(name(key), value, "must be at least 0 m^2"));
                        }
                    }
                    require_positive(&name("shape_coefficient"), a.shape_coefficient)?;
                }
                Ok(())
            }
        }
    }
}

impl CoefficientTable {
    fn validate(&self) -> Result<()> {
        let n = self.angles.len();
        for (key, values) in [("cx", &self.cx), ("cy", &self.cy), ("cmz", &self.cmz)] {
            if values.len() != n {
                return Err(Error::invalid(
                    format!("platform.wind.{key}"),
                    format!("{} values", values.len()),
                    format!("must have one value per angle of platform.wind.angle_deg ({n})"),
                ));
            }
            for v in values {
                require_finite(format!("platform.wind.{key}"), *v)?;
            }
        }
        if n < 2 {
            return Err(Error::invalid(
                "platform.wind.angle_deg",
                format!("{n} angles"),
                "must give at least two angles around the circle",
            ));
        }
        for w in self.angles.windows(2) {
            if w[1].partial_cmp(&w[0]) != Some(Ordering::Greater) {
                return Err(Error::invalid(
                    "platform.wind.angle_deg",
                    w[1].to_degrees(),
                    "must increase strictly",
                ));
            }
        }
        let span = self.angles[n - 1] - self.angles[0];
        if span.partial_cmp(&(2.0 * PI)) != Some(Ordering::Less) {
            return Err(Error::invalid(
                "platform.wind.angle_deg",
                format!("a span of {} deg", span.to_degrees()),
                "must span less than 360 deg (the table wraps from its last angle to its first)",
            ));
        }
        for (key, value) in [
            ("area_x", self.area_x),
            ("area_y", self.area_y),
            ("length", self.length),
        ] {
            require_positive(&format!("platform.wind.{key}"), value)?;
        }
        require_finite("platform.wind.centre", self.centre[0])?;
        require_finite("platform.wind.centre", self.centre[1])
    }

    /// (C_x, C_y, C_mz) at the relative angle `alpha` (rad, any number of turns), linear
    /// between the table's angles and across the gap from the last to the first + 2 pi.
    pub fn at(&self, alpha: f64) -> [f64; 3] {
        let first = self.angles[0];
        let a = first + (alpha - first).rem_euclid(2.0 * PI);
        let n = self.angles.len();
        let upper = self.angles.partition_point(|&v| v <= a);
        let (lo, hi, s) = if upper == 0 || upper == n {
            // In the closing gap: from the last angle to the first + 2 pi.
            let (last, next) = (self.angles[n - 1], first + 2.0 * PI);
            (n - 1, 0, (a - last) / (next - last))
        } else {
            let (l, h) = (self.angles[upper - 1], self.angles[upper]);
            (upper - 1, upper, (a - l) / (h - l))
        };
        let lerp = |v: &[f64]| v[lo] * (1.0 - s) + v[hi] * s;
        [lerp(&self.cx), lerp(&self.cy), lerp(&self.cmz)]
    }
}

/// A run's wind force: the platform's coefficients with the wind's direction, air density
/// and the mean profile's ratios.
#[derive(Debug, Clone, PartialEq)]
pub struct WindForce {
    coefficients: WindCoefficients,
    air_density: f64,
    /// beta_w, rad.
    direction: f64,
    /// U(z_i) / U(z_f) per area (empty for the table).
    ratios: Vec<f64>,
}

impl WindForce {
    /// The force of `load` in a wind towards `direction` (rad) of air density `air_density`
    /// (kg/m^3); `mean_at(z)` the mean speed at height z (its ratio to the force's height
    /// scales each area's wind).
    pub fn new(
        load: &WindLoad,
        direction: f64,
        air_density: f64,
        mean_at: impl Fn(f64) -> Result<f64>,
    ) -> Result<Self> {
        load.validate()?;
        let ratios = match &load.coefficients {
            WindCoefficients::Table(_) => Vec::new(),
            WindCoefficients::Areas(areas) => {
                let at_force = mean_at(load.height)?;
                areas
                    .iter()
                    .map(|a| Ok(mean_at(a.height)? / at_force))
                    .collect::<Result<_>>()?
            }
        };
        Ok(WindForce {
            coefficients: load.coefficients.clone(),
            air_density,
            direction,
            ratios,
        })
    }

    /// The force on the body, body frame (N, N, N m), in the wind of speed `speed` (m/s, at
    /// the force's height) at body yaw `theta` (rad) and slow body velocity `velocity` (u, v,
    /// r) in the body frame.
    pub fn force(&self, speed: f64, theta: f64, velocity: [f64; 3]) -> [f64; 3] {
        let (s, c) = (self.direction - theta).sin_cos();
        let [u, v, r] = velocity;
        let relative = |wind: f64, x: f64, y: f64| [wind * c - (u - r * y), wind * s - (v + r * x)];
        let half_rho = 0.5 * self.air_density;
        match &self.coefficients {
            WindCoefficients::Table(t) => {
                let [vx, vy] = relative(speed, t.centre[0], t.centre[1]);
                let q = half_rho * (vx * vx + vy * vy);
                let [cx, cy, cmz] = t.at(vy.atan2(vx));
                [
                    q * t.area_x * cx,
                    q * t.area_y * cy,
                    q * t.area_y * t.length * cmz,
                ]
            }
            WindCoefficients::Areas(areas) => {
                let mut total = [0.0; 3];
                for (a, ratio) in areas.iter().zip(&self.ratios) {
                    let [vx, vy] = relative(speed * ratio, a.centre[0], a.centre[1]);
                    let norm = vx.hypot(vy);
                    let fx = half_rho * a.shape_coefficient * a.area_x * vx * norm;
                    let fy = half_rho * a.shape_coefficient * a.area_y * vy * norm;
                    total[0] += fx;
                    total[1] += fy;
                    total[2] += a.centre[0] * fy - a.centre[1] * fx;
                }
                total
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table() -> CoefficientTable {
        // Every 90 degrees: C_x = cos, C_y = sin (a drag-like body), C_mz 0.1 sin(2 alpha).
        let angles: Vec<f64> = [-180.0f64, -90.0, 0.0, 90.0]
            .iter()
            .map(|d| d.to_radians())
            .collect();
        CoefficientTable {
            cx: angles.iter().map(|a| a.cos().round()).collect(),
            cy: angles.iter().map(|a| a.sin().round()).collect(),
            cmz: vec![0.0, 0.1, 0.0, -0.1],
            angles,
            area_x: 1000.0,
            area_y: 2000.0,
            length: 80.0,
            centre: [0.0, 0.0],
        }
    }

    /// Interpolation: at the nodes, halfway, and across the closing gap (from 90 deg to
    /// 180 deg, i.e. -180 + 360).
    #[test]
    fn the_table_is_read_around_the_circle() {
        let t = table();
        assert_eq!(t.at(0.0), [1.0, 0.0, 0.0]);
        assert_eq!(t.at(45f64.to_radians()), [0.5, 0.5, -0.05]);
        let gap = t.at(135f64.to_radians());
        assert!((gap[0] + 0.5).abs() < 1e-12 && (gap[1] - 0.5).abs() < 1e-12);
        let turned = t.at(45f64.to_radians() + 4.0 * PI);
        assert!((turned[0] - 0.5).abs() < 1e-12);
    }

    /// A wind of 20 m/s towards +X on a body at rest heading 0: q = 1/2 1.225 400 = 245 Pa,
    /// F_x = q A_x C_x(0) = 245 000 N; the body turned by 90 deg sees the wind towards its
    /// -y (alpha = -90 deg): F_y = q A_y C_y(-90) = -490 000 N, M_z = q A_y L 0.1 =
    /// 3 920 000 N m; a body moving with the wind at 5 m/s feels (15/20)^2 of it.
    #[test]
    fn table_forces_by_hand() {
        let load = WindLoad {
            height: 30.0,
            coefficients: WindCoefficients::Table(table()),
        };
        let wind = WindForce::new(&load, 0.0, 1.225, |_| Ok(20.0)).unwrap();
        let f = wind.force(20.0, 0.0, [0.0; 3]);
        assert!(
            (f[0] - 245_000.0).abs() < 1e-6 && f[1].abs() < 1e-9,
            "{f:?}"
        );
        let turned = wind.force(20.0, PI / 2.0, [0.0; 3]);
        assert!((turned[1] + 490_000.0).abs() < 1e-6, "{turned:?}");
        assert!((turned[2] - 3_920_000.0).abs() < 1e-6, "{turned:?}");
        let moving = wind.force(20.0, 0.0, [5.0, 0.0, 0.0]);
        assert!((moving[0] / f[0] - 0.5625).abs() < 1e-12);
    }

    /// Areas: two areas at heights whose mean speeds are 1 and 1.2 times the force's, a
    /// wind towards +Y: F_y = 1/2 rho C_s A_y (U r)^2 per area, the moment sum x F_y; the
    /// linearised surge damping of a steady wind along x is rho C_s A_x U r (numerical
    /// derivative of F_x in u).
    #[test]
    fn area_forces_and_their_damping() {
        let areas = vec![
            WindArea {
                centre: [10.0, 0.0],
                height: 20.0,
                area_x: 300.0,
                area_y: 500.0,
                shape_coefficient: 1.0,
            },
            WindArea {
                centre: [-20.0, 5.0],
                height: 40.0,
                area_x: 200.0,
                area_y: 100.0,
                shape_coefficient: 1.5,
            },
        ];
        let load = WindLoad {
            height: 20.0,
            coefficients: WindCoefficients::Areas(areas),
        };
        let mean = |z: f64| Ok(if z > 30.0 { 24.0 } else { 20.0 });
        let towards_y = WindForce::new(&load, PI / 2.0, 1.225, mean).unwrap();
        let f = towards_y.force(20.0, 0.0, [0.0; 3]);
        let (f1, f2) = (
            0.5 * 1.225 * 500.0 * 400.0,
            0.5 * 1.225 * 1.5 * 100.0 * 576.0,
        );
        assert!((f[1] - (f1 + f2)).abs() < 1e-6, "{f:?}");
        assert!(f[0].abs() < 1e-9);
        assert!((f[2] - (10.0 * f1 - 20.0 * f2)).abs() < 1e-6, "{f:?}");
        let along_x = WindForce::new(&load, 0.0, 1.225, mean).unwrap();
        let du = 1e-4;
        let damping = -(along_x.force(20.0, 0.0, [du, 0.0, 0.0])[0]
            - along_x.force(20.0, 0.0, [-du, 0.0, 0.0])[0])
            / (2.0 * du);
        let expected = 1.225 * (300.0 * 20.0 + 1.5 * 200.0 * 24.0);
        assert!(
            (damping / expected - 1.0).abs() < 1e-6,
            "{damping} vs {expected}"
        );
    }

    #[test]
    fn bad_tables_and_areas_are_named() {
        let mut t = table();
        t.cy.pop();
        let load = WindLoad {
            height: 30.0,
            coefficients: WindCoefficients::Table(t),
        };
        let err = load.validate().unwrap_err().to_string();
        assert!(err.contains("platform.wind.cy"), "{err}");
        let mut wide = table();
        wide.angles[3] = 200f64.to_radians();
        let err = WindLoad {
            height: 30.0,
            coefficients: WindCoefficients::Table(wide),
        }
        .validate()
        .unwrap_err()
        .to_string();
        assert!(err.contains("360"), "{err}");
        let none = WindLoad {
            height: 30.0,
            coefficients: WindCoefficients::Areas(Vec::new()),
        };
        assert!(none
            .validate()
            .unwrap_err()
            .to_string()
            .contains("platform.wind.areas"));
    }
}
