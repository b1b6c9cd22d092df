//! The embedded default: the paper's four-column platform in a three-hour JONSWAP sea,
//! described by `default.toml` (compiled in; its comments document how every number was
//! derived). What a new user simulates without giving any data.
//!
//! Reading it takes microseconds; resolving it reads the embedded radiation-diffraction
//! database (`hydro::default_platform`; no solver runs, and the packed FMU carries a copy,
//! `fmi2::resources`).

use super::{file, Scenario};
use crate::error::Result;
use std::path::Path;

/// The default configuration file, as compiled into the library.
pub const DEFAULT_CONFIG_TOML: &str = include_str!("default.toml");

/// One line that says where the default platform's drift comes from.
pub const DEFAULT_DRIFT_LABEL: &str = "radiation-diffraction database of the columns on their \
     pontoons, freely floating (Capytaine; the column solver above 1.6-2.0 rad/s)";

/// The default scenario (parsed from [`DEFAULT_CONFIG_TOML`]; its database is read when it
/// is resolved).
pub fn default_scenario() -> Result<Scenario> {
    file::parse(DEFAULT_CONFIG_TOML, "embedded default.toml", Path::new("."))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn default_parses_resolves_and_validates() {
        let config = crate::problem::resolve(&default_scenario().unwrap()).unwrap();
        config.check().unwrap();
        assert_eq!(config.platform.columns.len(), 4);
        // The database brings the bi-directional drift, so `auto` uses it.
        assert_eq!(
            config.interaction(),
            crate::model::Interaction::Bidirectional
        );
    }

    /// The documented natural periods follow from the file's stiffness and the database's
    /// mass and added mass.
    #[test]
    fn natural_periods_are_200_s_surge_and_100_s_yaw() {
        let problem = crate::problem::resolve(&default_scenario().unwrap()).unwrap();
        let (p, i) = (&problem.platform, problem.inertia().unwrap());
        let surge = 2.0 * PI * ((i.mass + i.added_mass[0][0]) / p.stiffness[0][0]).sqrt();
        let yaw = 2.0 * PI * ((i.yaw_inertia + i.added_mass[2][2]) / p.stiffness[2][2]).sqrt();
        assert!((surge - 200.0).abs() < 0.5, "surge period {surge}");
        assert!((yaw - 100.0).abs() < 0.5, "yaw period {yaw}");
    }

    /// Mass equals rho times the displaced volume of the documented geometry: the columns,
    /// and the pontoons between column centres less the half columns inside them and less
    /// the cusp that two pontoons share at each inner corner (r^2 - pi r^2 / 4).
    #[test]
    fn mass_is_the_displaced_water() {
        let problem = crate::problem::resolve(&default_scenario().unwrap()).unwrap();
        let p = problem.inertia().unwrap();
        let columns = 4.0 * PI * 10.0f64.powi(2) * 30.0;
        let pontoons = 4.0 * (20.0 * 70.0 - PI * 100.0 - (100.0 - PI * 25.0)) * 14.0;
        let mass = 1025.0 * (columns + pontoons);
        assert!((p.mass / mass - 1.0).abs() < 1e-3, "{} vs {mass}", p.mass);
    }
}
