//! The mass matrix the equations of motion use (E&S 1: M + A), and where each part came
//! from.
//!
//! One rule, for each of `platform.mass`, `platform.yaw_inertia` and `platform.added_mass`
//! (docs/configuration.md, "Mass and added mass"): the configuration's value where
//! `[platform]` gives it; else the value of the hydrodynamic data the drift source reads (a
//! database's `mass_properties` and `low_frequency_added_mass`: a WAMIT import's `.1` at
//! omega = 0, a NEMOH import's `CM.dat` and `Mechanics/Inertia.dat`, the embedded default
//! platform's radiation-diffraction solution); else, for the added mass only, zero. A mass or
//! yaw inertia given nowhere is an error. Where the configuration gives a value that the data
//! also have, the configuration's is used and [`Inertia::notes`] says so.
//!
//! Units: kg (mass), kg m^2 (yaw inertia about the body origin); the added mass is indexed
//! (surge, sway, yaw) in kg, kg m and kg m^2 and acts in the body frame, as `Platform`'s.

use crate::error::numbers::written;
use crate::hydro::io::database::{MassProperties, Provenance};
use crate::hydro::rao::{FirstOrder, RaoTable};
use crate::scenario::Platform;
use serde::Serialize;

/// The body data that a drift source's hydrodynamic data hold (none for a drift table, a
/// CSV file or the column solvers).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct BodyData {
    /// What names the data in a summary: the database file as the configuration named it,
    /// or the embedded data's name; empty when the source has no body data.
    pub name: String,
    /// Mass and yaw inertia about the body origin.
    pub mass_properties: Option<MassProperties>,
    /// Added mass as omega -> 0 (kg, kg m, kg m^2), about the body origin.
    pub added_mass: Option<[[f64; 3]; 3]>,
    /// Where the database's importer took them from.
    pub provenance: Provenance,
    /// The first-order radiation-diffraction coefficients (6 DOF), for the RAOs
    /// (`problem::motions`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub first_order: Option<FirstOrder>,
    /// RAOs the data give directly (a WAMIT `.4`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rao: Option<RaoTable>,
}

/// Where a value of [`Inertia`] came from.
#[derive(Debug, Clone, PartialEq)]
pub enum Origin {
    /// The configuration's `[platform]` key (or what overrides it).
    Configuration,
    /// The hydrodynamic data: their name ([`BodyData::name`]) and, when the importer said,
    /// where in them (`WAMIT .1 at omega = 0 (PER = -1)`).
    Data {
        name: String,
        detail: Option<String>,
    },
    /// Given nowhere: zero (the added mass only).
    Zero,
}

impl std::fmt::Display for Origin {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Origin::Configuration => f.write_str("[platform]"),
            Origin::Data { name, detail: None } => f.write_str(name),
            Origin::Data {
                name,
                detail: Some(detail),
            } => write!(f, "{name}, {detail}"),
            Origin::Zero => f.write_str(
                "none given: zero (no [platform] added_mass, and the drift source has no \
                 low-frequency added mass)",
            ),
        }
    }
}

/// The rigid-body mass, yaw inertia and low-frequency added mass of a problem (module doc),
/// each with its [`Origin`].
#[derive(Debug, Clone, PartialEq)]
pub struct Inertia {
    /// kg.
    pub mass: f64,
    /// kg m^2, about the body origin.
    pub yaw_inertia: f64,
    /// (surge, sway, yaw), kg, kg m, kg m^2.
    pub added_mass: [[f64; 3]; 3],
    pub mass_origin: Origin,
    pub yaw_inertia_origin: Origin,
    pub added_mass_origin: Origin,
    /// One line per value of the data that the configuration's own replaces.
    pub notes: Vec<String>,
}

/// Why a mass or yaw inertia is missing: neither the configuration nor the data give it.
#[derive(Debug, Clone, PartialEq)]
pub struct Missing {
    /// The configuration key (`platform.mass`).
    pub key: &'static str,
    /// The drift source's data, as [`BodyData::name`] (empty: no body data).
    pub data: String,
}

impl Inertia {
    /// The inertia of `platform` with the drift source's `data` (the module doc's rule).
    pub fn resolve(platform: &Platform, data: &BodyData) -> Result<Inertia, Missing> {
        let from_data = |detail: &Option<String>| Origin::Data {
            name: data.name.clone(),
            detail: detail.clone(),
        };
        let mut notes = Vec::new();
        let mut pick =
            |key: &'static str, given: Option<f64>, theirs: Option<f64>| match (given, theirs) {
                (Some(value), theirs) => {
                    if let Some(theirs) = theirs.filter(|t| *t != value) {
                        notes.push(format!(
                            "note: {key} = {} from [platform] is used, not {}'s {}",
                            written(value),
                            data.name,
                            written(theirs)
                        ));
                    }
                    Ok((value, Origin::Configuration))
                }
                (None, Some(theirs)) => Ok((theirs, from_data(&data.provenance.mass_properties))),
                (None, None) => Err(Missing {
                    key,
                    data: data.name.clone(),
                }),
            };
        let props = data.mass_properties.as_ref();
        let (mass, mass_origin) = pick("platform.mass", platform.mass, props.map(|p| p.mass))?;
        let (yaw_inertia, yaw_inertia_origin) = pick(
            "platform.yaw_inertia",
            platform.yaw_inertia,
            props.map(|p| p.yaw_inertia),
        )?;
        let (added_mass, added_mass_origin) = match (platform.added_mass, data.added_mass) {
            (Some(given), theirs) => {
                if let Some(theirs) = theirs.filter(|t| *t != given) {
                    notes.push(format!(
                        "note: platform.added_mass from [platform] is used (A11 = {} kg, A66 = \
                         {} kg m^2), not {}'s low-frequency added mass (A11 = {} kg, A66 = {} \
                         kg m^2)",
                        written(given[0][0]),
                        written(given[2][2]),
                        data.name,
                        written(theirs[0][0]),
                        written(theirs[2][2])
                    ));
                }
                (given, Origin::Configuration)
            }
            (None, Some(theirs)) => (theirs, from_data(&data.provenance.low_frequency_added_mass)),
            (None, None) => ([[0.0; 3]; 3], Origin::Zero),
        };
        Ok(Inertia {
            mass,
            yaw_inertia,
            added_mass,
            mass_origin,
            yaw_inertia_origin,
            added_mass_origin,
            notes,
        })
    }

    /// The diagonal of M + A: (surge, sway, yaw) in kg, kg, kg m^2.
    pub fn total_diagonal(&self) -> [f64; 3] {
        let rigid = [self.mass, self.mass, self.yaw_inertia];
        std::array::from_fn(|i| rigid[i] + self.added_mass[i][i])
    }

    /// The undamped natural periods of each DOF alone, 2 pi sqrt((M + A)_ii / C_ii), s, for
    /// the stiffness diagonal `stiffness`; `None` where C_ii is not positive (nothing
    /// restores that DOF). The uncoupled periods: the off-diagonal terms are left out.
    pub fn uncoupled_periods(&self, stiffness: &[[f64; 3]; 3]) -> [Option<f64>; 3] {
        let total = self.total_diagonal();
        std::array::from_fn(|i| {
            (stiffness[i][i] > 0.0)
                .then(|| 2.0 * std::f64::consts::PI * (total[i] / stiffness[i][i]).sqrt())
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn platform(mass: Option<f64>, yaw: Option<f64>, added: Option<[[f64; 3]; 3]>) -> Platform {
        Platform {
            mass,
            yaw_inertia: yaw,
            added_mass: added,
            stiffness: [[0.0; 3]; 3],
            linear_damping: [[0.0; 3]; 3],
            quadratic_damping: [[0.0; 3]; 3],
            columns: Vec::new(),
            motions: None,
            wind: None,
        }
    }

    fn data() -> BodyData {
        BodyData {
            name: "iea.json".into(),
            mass_properties: Some(MassProperties {
                mass: 2.0e7,
                yaw_inertia: 3.0e10,
            }),
            added_mass: Some([[1.0e7, 0.0, 0.0], [0.0, 1.1e7, 0.0], [0.0, 0.0, 2.0e10]]),
            provenance: Provenance {
                mass_properties: Some("NEMOH Mechanics/Inertia.dat".into()),
                low_frequency_added_mass: Some("WAMIT .1 at omega = 0 (PER = -1)".into()),
                stiffness: None,
            },
            first_order: None,
            rao: None,
        }
    }

    #[test]
    fn the_data_fill_what_the_configuration_leaves_out() {
        let i = Inertia::resolve(&platform(None, None, None), &data()).unwrap();
        assert_eq!(
            (i.mass, i.yaw_inertia, i.added_mass[1][1]),
            (2.0e7, 3.0e10, 1.1e7)
        );
        assert_eq!(
            i.added_mass_origin.to_string(),
            "iea.json, WAMIT .1 at omega = 0 (PER = -1)"
        );
        assert_eq!(
            i.mass_origin.to_string(),
            "iea.json, NEMOH Mechanics/Inertia.dat"
        );
        assert!(i.notes.is_empty());
    }

    #[test]
    fn the_configuration_wins_with_a_note() {
        let given = [[5.0e6, 0.0, 0.0], [0.0, 5.0e6, 0.0], [0.0, 0.0, 1.0e10]];
        let i = Inertia::resolve(&platform(Some(1.5e7), None, Some(given)), &data()).unwrap();
        assert_eq!(
            (i.mass, i.yaw_inertia, i.added_mass),
            (1.5e7, 3.0e10, given)
        );
        assert_eq!(i.mass_origin, Origin::Configuration);
        assert_eq!(i.added_mass_origin, Origin::Configuration);
        assert_eq!(i.notes.len(), 2, "{:?}", i.notes);
        assert!(i.notes[0].contains("platform.mass") && i.notes[0].contains("iea.json"));
        assert!(i.notes[1].contains("A11 = 5e6 kg") && i.notes[1].contains("A11 = 1e7 kg"));
        // The same value in both places is no news.
        let same = platform(Some(2.0e7), Some(3.0e10), data().added_mass);
        assert!(Inertia::resolve(&same, &data()).unwrap().notes.is_empty());
    }

    #[test]
    fn without_data_the_added_mass_is_zero_and_the_mass_is_required() {
        let none = BodyData::default();
        let i = Inertia::resolve(&platform(Some(1.0e7), Some(1.0e9), None), &none).unwrap();
        assert_eq!(
            (i.added_mass, i.added_mass_origin),
            ([[0.0; 3]; 3], Origin::Zero)
        );
        let missing = Inertia::resolve(&platform(Some(1.0e7), None, None), &none).unwrap_err();
        assert_eq!(missing.key, "platform.yaw_inertia");
    }

    /// 2 pi sqrt((M + A) / C) for each DOF with stiffness; none without.
    #[test]
    fn uncoupled_periods() {
        let i = Inertia::resolve(&platform(Some(2.0e7), Some(1.0e10), None), &data()).unwrap();
        let c = [[8.95e4, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0e9]];
        let [surge, sway, yaw] = i.uncoupled_periods(&c);
        let expect = 2.0 * std::f64::consts::PI * (3.0e7_f64 / 8.95e4).sqrt();
        assert!((surge.unwrap() - expect).abs() < 1e-12 * expect);
        assert_eq!(sway, None);
        let expect = 2.0 * std::f64::consts::PI * 30.0_f64.sqrt();
        assert!((yaw.unwrap() - expect).abs() < 1e-12 * expect);
    }
}
