//! The embedded default: the paper's four-column platform in a three-hour JONSWAP sea,
//! described by `default.toml` (compiled in; its comments document how every number was
//! derived). What a new user simulates without giving any data.

use super::{file, Config};
use crate::error::{Error, Result};
use crate::hydro::database::HydroDatabase;
use std::path::Path;

/// The configuration file an FMU carries in its `resources/` folder.
pub const RESOURCE_CONFIG: &str = "platform.toml";
/// The hydro database next to it, holding the default platform's precomputed drift.
pub const RESOURCE_DRIFT: &str = "platform_drift.json";

/// The default configuration file, as compiled into the library.
pub const DEFAULT_CONFIG_TOML: &str = include_str!("default.toml");

/// One line that says where the default platform's drift comes from.
pub const DEFAULT_DRIFT_LABEL: &str = "the four columns as an interacting array (Linton & Evans \
     1990; deep water, no pontoons), Aranha damping from the solver";

/// The default configuration.
pub fn default_config() -> Result<Config> {
    file::parse(DEFAULT_CONFIG_TOML, "embedded default.toml", Path::new("."))
}

/// Writes the default platform for an FMU's `resources/` folder: its drift table (the
/// column solver's, computed here once) as the hydro database [`RESOURCE_DRIFT`], and the
/// default configuration as [`RESOURCE_CONFIG`] with its `[drift]` section pointing at that
/// database, so that an instance loads the hydrodynamics instead of recomputing them. The
/// bi-directional drift of spread seas still comes from the column solver (`bidirectional =
/// "column-array"`), at the sea's exact directions when the instance initialises, as in
/// the native default.
pub fn write_resources(dir: &Path) -> Result<()> {
    let config = default_config()?;
    let database = HydroDatabase::from_drift_table(
        "SlowDrift default platform",
        DEFAULT_DRIFT_LABEL,
        &config.environment,
        &config.drift,
    );
    std::fs::create_dir_all(dir).map_err(|e| Error::Io {
        path: dir.display().to_string(),
        message: e.to_string(),
    })?;
    database.save(&dir.join(RESOURCE_DRIFT))?;
    let drift_section = DEFAULT_CONFIG_TOML
        .find("\n[drift]")
        .expect("default.toml ends with its [drift] section");
    let text = format!(
        "{}\n[drift]\n# precomputed by fmu-pack from the default's column-array source\n\
         source = \"database\"\nfile = \"{RESOURCE_DRIFT}\"\n\
         # spread seas: bi-directional drift from the column solver at the sea's directions\n\
         bidirectional = \"column-array\"\n",
        &DEFAULT_CONFIG_TOML[..drift_section]
    );
    let path = dir.join(RESOURCE_CONFIG);
    std::fs::write(&path, text).map_err(|e| Error::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn default_parses_and_validates() {
        let config = default_config().unwrap();
        config.validate().unwrap();
        assert_eq!(config.platform.columns.len(), 4);
        // The column-array source brings the bi-directional drift, so `auto` uses it.
        assert_eq!(
            config.interaction(),
            crate::model::Interaction::Bidirectional
        );
    }

    /// The documented natural periods follow from the numbers in the file.
    #[test]
    fn natural_periods_are_200_s_surge_and_100_s_yaw() {
        let p = default_config().unwrap().platform;
        let surge = 2.0 * PI * ((p.mass + p.added_mass[0][0]) / p.stiffness[0][0]).sqrt();
        let yaw = 2.0 * PI * ((p.yaw_inertia + p.added_mass[2][2]) / p.stiffness[2][2]).sqrt();
        assert!((surge - 200.0).abs() < 0.5, "surge period {surge}");
        assert!((yaw - 100.0).abs() < 0.5, "yaw period {yaw}");
    }

    /// The FMU's start values (modelDescription.xml) describe the same default as this file.
    #[test]
    fn model_description_start_values_match_the_default() {
        use crate::model::{DragModel, DriftDamping};
        use crate::model_description::start;
        use crate::sea_state::{Spectrum, Spreading};
        let c = default_config().unwrap();
        let Spectrum::Jonswap { hs, tp, gamma } = c.sea.spectrum else {
            panic!("the default sea is JONSWAP");
        };
        assert_eq!((hs, tp), (start::HS, start::TP));
        assert_eq!(gamma.is_none(), start::GAMMA == 0.0);
        assert_eq!(c.sea.mean_direction, start::WAVE_DIRECTION);
        assert_eq!(
            c.sea.spreading == Spreading::LongCrested,
            start::SPREADING_EXPONENT == 0.0
        );
        assert_eq!(c.sea.seed, start::SEED as u64);
        assert_eq!(c.current.speed, start::CURRENT_SPEED);
        assert_eq!(c.run.time_step, start::STEP_SIZE);
        let stiffness = [
            start::STIFFNESS_SURGE,
            start::STIFFNESS_SWAY,
            start::STIFFNESS_YAW,
        ];
        for (i, k) in stiffness.iter().enumerate() {
            assert_eq!(c.platform.stiffness[i][i], *k);
        }
        assert_eq!(c.model.drag, DragModel::Combined { cd: start::CD });
        assert_eq!(start::DRAG_MODEL, 2, "2 = combined");
        assert_eq!(c.model.drift_damping, DriftDamping::Table);
        assert_eq!(start::DRIFT_DAMPING, 1, "1 = table");
    }

    /// The resources an FMU carries describe exactly the default (the database keeps every
    /// bit of the drift and damping).
    #[test]
    fn resources_reproduce_the_default() {
        let dir = std::env::temp_dir().join(format!("slowdrift-resources-{}", std::process::id()));
        write_resources(&dir).unwrap();
        let loaded = file::load(&dir.join(RESOURCE_CONFIG)).unwrap();
        std::fs::remove_dir_all(&dir).ok();
        assert_eq!(loaded, default_config().unwrap());
    }

    /// Mass equals rho times the displaced volume of the documented geometry.
    #[test]
    fn mass_is_the_displaced_water() {
        let p = default_config().unwrap().platform;
        let columns = 4.0 * PI * 10.0f64.powi(2) * 30.0;
        let pontoons = 4.0 * (20.0 * 70.0 - PI * 100.0) * 14.0;
        let mass = 1025.0 * (columns + pontoons);
        assert!((p.mass / mass - 1.0).abs() < 1e-3, "{} vs {mass}", p.mass);
    }
}
