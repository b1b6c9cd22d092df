//! The native hydrodynamic database: what a simulation needs from a diffraction code, in
//! SI units and radians, as versioned JSON.
//!
//! Layout (format version [`FORMAT_VERSION`]; matrices are rows of numbers, indexed
//! (surge, sway, yaw)):
//!
//! ```text
//! {
//!   "format_version": 1,
//!   "name": "marin_semi",
//!   "source": "free text: where the numbers come from",
//!   "water_density": 1025.0,                 kg/m^3 the data were made with
//!   "gravity": 9.80665,                      m/s^2
//!   "mass_properties": null | {"mass": kg, "yaw_inertia": kg m^2},
//!   "low_frequency_added_mass": null | 3x3   kg, kg m, kg m^2 (omega -> 0)
//!   "stiffness": null | 3x3                  N/m, N, N m/rad (hydrostatic only; the mooring adds its own)
//!   "drift": [{"omega": rad/s, "heading": rad, "surge": N/m^2, "sway": N/m^2, "yaw": N m/m^2,
//!              "damping": null | 3x3 b_ij}, ...],
//!   "qtf": null | {"omegas": [rad/s, increasing],
//!                  "blocks": [{"dof": "surge" | "sway" | "yaw", "heading": rad,
//!                              "re": n x n, "im": n x n}, ...]},
//!   "bidirectional_drift": (optional) {"omegas": [rad/s], "headings": [rad],
//!                  "re": n_omega x n_heading x n_heading x [surge, sway, yaw], "im": same},
//!   "first_order": (optional) {"omegas": [rad/s], "headings": [rad],
//!                  "added_mass": n_omega x 6x6, "damping": n_omega x 6x6,
//!                  "excitation_re": n_omega x n_heading x 6 (N/m, N m/m), "excitation_im": same,
//!                  "hydrostatics": 6x6},
//!   "rao": (optional) {"omegas": [rad/s], "headings": [rad],
//!                  "re": n_omega x n_heading x 6 (m/m, rad/m), "im": same},
//!   "provenance": (optional) {"mass_properties": "...", "low_frequency_added_mass": "...",
//!                  "stiffness": "..."}   where each came from, one phrase each
//! }
//! ```
//!
//! `first_order` and `rao` are 6 DOF (surge, sway, heave, roll, pitch, yaw) about the body
//! origin, per unit wave amplitude, Re{X e^{i omega t}} with the phase relative to the
//! incident elevation at the origin ([`crate::hydro::rao`]; docs/theory.md#first-order-motions-raos).
//!
//! A simulation that names the database takes its `mass_properties` and
//! `low_frequency_added_mass` for the model's mass, yaw inertia and added mass where the
//! configuration's `[platform]` does not give its own (`problem::inertia`); `provenance`
//! then says where they came from in the run's summary.
//!
//! `re[i][j] + i im[i][j]` = T(w_i, w_j), the full difference-frequency QTF per unit
//! amplitude squared with F(t) = Re sum a_i a_j* T_ij e^{i (w_i - w_j) t}
//! (docs/theory.md#the-slowly-varying-force). Numbers are written so that they read back bit for
//! bit.

use crate::error::{
    require_finite, require_finite_matrix, require_positive, Error, Location, Result,
};
use crate::files::Cost;
use crate::hydro::bidirectional::BidirectionalTable;
use crate::hydro::qtf::{Qtf, QtfBlock};
use crate::hydro::rao::{FirstOrder, RaoTable};
use crate::hydro::{DriftRow, DriftTable};
use crate::model::{Dof, Environment};
use rustfft::num_complex::Complex64;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// The database format this code writes and reads.
pub const FORMAT_VERSION: u32 = 1;

/// What reading a database costs, to the problem made of it (its drift table, QTF and
/// bi-directional table): up to 16 bytes of memory per byte of the file (measured on its
/// costliest content: matrices of one-digit numbers, and of empty rows), with a margin for
/// the allocator's own overhead.
pub const READING: Cost = Cost {
    format: "hydrodynamic database (JSON)",
    per_byte: 24.0,
};

/// An error about the content of a database read from `text` (`name`: where the text came
/// from), from [`HydroDatabase::validate`] or the drift table made from it: located at the
/// line of the value it names, the field named as the file spells it (`drift[3].omega`).
/// Other errors are returned unchanged.
pub fn locate(error: Error, text: &str, name: &str) -> Error {
    match error {
        Error::InvalidValue {
            field,
            value,
            reason,
            at: None,
        } => {
            let field = field.strip_prefix("database.").unwrap_or(&field);
            // The drift table's rows are the database's `drift` entries, in order.
            let field = match field.strip_prefix("drift.rows[") {
                Some(rest) => format!("drift[{rest}"),
                None => field.to_string(),
            };
            let line = super::json_position::line_of(text, &field);
            Error::InvalidValue {
                field,
                value,
                reason,
                at: Some(Location {
                    path: name.to_string(),
                    line,
                }),
            }
        }
        other => other,
    }
}

/// A platform's hydrodynamic data for the slow-drift DOFs (surge, sway, yaw).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HydroDatabase {
    /// Always [`FORMAT_VERSION`] for data this code wrote.
    pub format_version: u32,
    /// Short name of the platform.
    pub name: String,
    /// Where the numbers come from (files, scales, choices).
    pub source: String,
    /// Water density the data were made dimensional with, kg/m^3.
    pub water_density: f64,
    /// Acceleration of gravity the data were made dimensional with, m/s^2.
    pub gravity: f64,
    /// Rigid-body mass properties, if known.
    pub mass_properties: Option<MassProperties>,
    /// Added mass as omega -> 0 (kg, kg m, kg m^2).
    pub low_frequency_added_mass: Option<[[f64; 3]; 3]>,
    /// Hydrostatic stiffness on (X, Y, theta) (N/m, N, N m/rad); zero for a floater in
    /// these DOFs: the mooring supplies the stiffness.
    pub stiffness: Option<[[f64; 3]; 3]>,
    /// Mean drift (and optional wave-drift damping) per unit amplitude squared.
    pub drift: Vec<DriftPoint>,
    /// The full difference-frequency QTF, uni-directional headings.
    pub qtf: Option<QtfData>,
    /// The bi-directional mean drift T(omega; beta_p, beta_q) for short-crested seas
    /// (optional; absent from older files and not written when `None`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bidirectional_drift: Option<BidirectionalTable>,
    /// The first-order radiation-diffraction coefficients, 6 DOF about the body origin
    /// ([`FirstOrder`]; optional; absent from older files and not written when `None`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_order: Option<FirstOrder>,
    /// First-order motions (RAOs), 6 DOF about the body origin ([`RaoTable`]; optional;
    /// absent from older files and not written when `None`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rao: Option<RaoTable>,
    /// Where the mass properties, the added mass and the stiffness came from (optional;
    /// absent from older files and not written when empty).
    #[serde(default, skip_serializing_if = "Provenance::is_empty")]
    pub provenance: Provenance,
}

/// Where a database's body data came from, one phrase each (`WAMIT .1 at omega = 0 (PER =
/// -1)`), as its importer wrote it; `None` where the importer said nothing.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Provenance {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass_properties: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub low_frequency_added_mass: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stiffness: Option<String>,
}

impl Provenance {
    /// Whether it says nothing (then it is not written).
    pub fn is_empty(&self) -> bool {
        self == &Provenance::default()
    }
}

/// Rigid-body mass properties.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MassProperties {
    /// Mass, kg.
    pub mass: f64,
    /// Yaw moment of inertia about the body origin, kg m^2.
    pub yaw_inertia: f64,
}

/// One node of the drift table. (The embedded default's MessagePack twin holds each node as
/// an array of these fields in this order: `DRIFT_POINT_FIELDS` in build.rs.)
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DriftPoint {
    /// Wave frequency, rad/s.
    pub omega: f64,
    /// Wave heading relative to the body x axis, rad.
    pub heading: f64,
    /// Mean surge drift, N/m^2.
    pub surge: f64,
    /// Mean sway drift, N/m^2.
    pub sway: f64,
    /// Mean yaw drift moment, N m/m^2.
    pub yaw: f64,
    /// Wave-drift damping b_ij (row: force, column: velocity), per unit amplitude squared.
    pub damping: Option<[[f64; 3]; 3]>,
}

/// The difference-frequency QTF on its frequency grid.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct QtfData {
    /// Frequencies, rad/s, increasing.
    pub omegas: Vec<f64>,
    /// One n x n matrix per (DOF, heading).
    pub blocks: Vec<QtfMatrix>,
}

/// T(w_i, w_j; beta1, beta2) = `re[i][j] + i im[i][j]` of one DOF for one heading pair.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct QtfMatrix {
    pub dof: Dof,
    /// Heading beta1 of the waves at w_i, rad.
    pub heading: f64,
    /// Heading beta2 of the waves at w_j, rad, for a bi-directional block; absent (`None`)
    /// for a uni-directional one (beta2 = beta1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub second_heading: Option<f64>,
    pub re: Vec<Vec<f64>>,
    pub im: Vec<Vec<f64>>,
}

impl HydroDatabase {
    /// Writes the database as JSON; the error names the file.
    pub fn save(&self, path: &Path) -> Result<()> {
        let name = path.display().to_string();
        self.validate().map_err(|e| Error::Io {
            path: name.clone(),
            message: format!("not written: {e}"),
        })?;
        let text = serde_json::to_string_pretty(self).map_err(|e| Error::Io {
            path: name.clone(),
            message: e.to_string(),
        })?;
        std::fs::write(path, text + "\n").map_err(|e| Error::Io {
            path: name,
            message: e.to_string(),
        })
    }

    /// Reads and validates a database within `memory_limit` bytes; refuses other format
    /// versions. Errors name the file (and the line, for JSON syntax).
    pub fn load(path: &Path, memory_limit: f64) -> Result<Self> {
        let text = crate::files::read_text(path, &READING, memory_limit)?;
        Self::parse(&text, &path.display().to_string())
    }

    /// A database from its JSON text; `name` says where the text came from in errors.
    pub fn parse(text: &str, name: &str) -> Result<Self> {
        let at = |e: serde_json::Error| Error::Parse {
            path: name.to_string(),
            line: (e.line() > 0).then(|| e.line()),
            message: e.to_string(),
        };
        // One pass straight into the types (errors with their line). A file of another
        // version is refused as such: by the version read in that pass, or, when the pass
        // fails, by a second one that reads the version alone (every other field skipped).
        let version_refused = |format_version: Option<serde_json::Value>| Error::Parse {
            path: name.to_string(),
            line: None,
            message: format!(
                "format_version = {}: this program reads version {FORMAT_VERSION}",
                format_version.map_or("(absent)".to_string(), |v| v.to_string())
            ),
        };
        let database: HydroDatabase = match serde_json::from_str(text) {
            Ok(database) => database,
            Err(error) => {
                #[derive(Deserialize)]
                struct Version {
                    format_version: Option<serde_json::Value>,
                }
                let version: Version = serde_json::from_str(text).map_err(at)?;
                if version
                    .format_version
                    .as_ref()
                    .and_then(serde_json::Value::as_u64)
                    != Some(u64::from(FORMAT_VERSION))
                {
                    return Err(version_refused(version.format_version));
                }
                return Err(at(error));
            }
        };
        if database.format_version != FORMAT_VERSION {
            return Err(version_refused(Some(database.format_version.into())));
        }
        database.validate().map_err(|e| locate(e, text, name))?;
        Ok(database)
    }

    /// Checks the version, the constants, finiteness and the QTF's shape.
    pub fn validate(&self) -> Result<()> {
        if self.format_version != FORMAT_VERSION {
            return Err(Error::invalid(
                "database.format_version",
                self.format_version,
                format!("this program handles version {FORMAT_VERSION}"),
            ));
        }
        require_positive("database.water_density", self.water_density)?;
        require_positive("database.gravity", self.gravity)?;
        if let Some(m) = &self.mass_properties {
            require_positive("database.mass_properties.mass", m.mass)?;
            require_positive("database.mass_properties.yaw_inertia", m.yaw_inertia)?;
        }
        if let Some(a) = &self.low_frequency_added_mass {
            require_finite_matrix("database.low_frequency_added_mass", a)?;
        }
        if let Some(c) = &self.stiffness {
            require_finite_matrix("database.stiffness", c)?;
        }
        for (k, p) in self.drift.iter().enumerate() {
            for (name, v) in [
                ("omega", p.omega),
                ("heading", p.heading),
                ("surge", p.surge),
                ("sway", p.sway),
                ("yaw", p.yaw),
            ] {
                require_finite(format_args!("database.drift[{k}].{name}"), v)?;
            }
            if let Some(b) = &p.damping {
                require_finite_matrix(format_args!("database.drift[{k}].damping"), b)?;
            }
        }
        if let Some(q) = &self.qtf {
            q.validate()?;
        }
        if let Some(t) = &self.bidirectional_drift {
            t.validate()?;
        }
        if let Some(f) = &self.first_order {
            f.validate()?;
        }
        if let Some(r) = &self.rao {
            r.validate()?;
        }
        Ok(())
    }

    /// A database holding just a drift table (and its damping, if any), e.g. the column
    /// solver's, made dimensional with `environment`'s density and gravity.
    pub fn from_drift_table(
        name: &str,
        source: &str,
        environment: &Environment,
        table: &DriftTable,
    ) -> Self {
        let mut drift = Vec::with_capacity(table.headings().len() * table.omegas().len());
        for (ih, &heading) in table.headings().iter().enumerate() {
            for (iw, &omega) in table.omegas().iter().enumerate() {
                let [surge, sway, yaw] = table.drift_at_node(ih, iw);
                drift.push(DriftPoint {
                    omega,
                    heading,
                    surge,
                    sway,
                    yaw,
                    damping: table.damping_at_node(ih, iw),
                });
            }
        }
        HydroDatabase {
            format_version: FORMAT_VERSION,
            name: name.to_string(),
            source: source.to_string(),
            water_density: environment.water_density,
            gravity: environment.gravity,
            mass_properties: None,
            low_frequency_added_mass: None,
            stiffness: None,
            drift,
            qtf: None,
            bidirectional_drift: None,
            first_order: None,
            rao: None,
            provenance: Provenance::default(),
        }
    }

    /// The drift table of the database (with damping if every node has it).
    pub fn to_drift_table(&self) -> Result<DriftTable> {
        if self.drift.is_empty() {
            return Err(Error::invalid(
                "database.drift",
                "[]",
                format!("the database \"{}\" holds no drift table", self.name),
            ));
        }
        let rows: Vec<DriftRow> = self
            .drift
            .iter()
            .map(|p| DriftRow {
                omega: p.omega,
                heading: p.heading,
                drift: [p.surge, p.sway, p.yaw],
                damping: p.damping,
            })
            .collect();
        DriftTable::from_rows(&rows)
    }
}

impl QtfData {
    /// Checks the frequencies (positive, strictly increasing) and every block's shape and
    /// finiteness.
    pub fn validate(&self) -> Result<()> {
        let n = self.omegas.len();
        for (k, w) in self.omegas.iter().enumerate() {
            require_positive(&format!("database.qtf.omegas[{k}]"), *w)?;
            if k > 0 && *w <= self.omegas[k - 1] {
                return Err(Error::invalid(
                    format!("database.qtf.omegas[{k}]"),
                    w,
                    "frequencies must be strictly increasing",
                ));
            }
        }
        for (k, b) in self.blocks.iter().enumerate() {
            require_finite(format_args!("database.qtf.blocks[{k}].heading"), b.heading)?;
            if let Some(h) = b.second_heading {
                require_finite(format_args!("database.qtf.blocks[{k}].second_heading"), h)?;
            }
            for (part, m) in [("re", &b.re), ("im", &b.im)] {
                let field = format!("database.qtf.blocks[{k}].{part}");
                if m.len() != n || m.iter().any(|row| row.len() != n) {
                    return Err(Error::invalid(
                        field,
                        format!("{} rows", m.len()),
                        format!("must be {n} x {n} (one row and column per frequency)"),
                    ));
                }
                if m.iter().flatten().any(|v| !v.is_finite()) {
                    return Err(Error::invalid(field, "NaN or infinity", "must be finite"));
                }
            }
        }
        Ok(())
    }
}

impl QtfData {
    /// The QTF in memory (complex matrices); [`QtfData::validate`] first.
    pub fn to_qtf(&self) -> Qtf {
        Qtf {
            omegas: self.omegas.clone(),
            blocks: self
                .blocks
                .iter()
                .map(|b| QtfBlock {
                    dof: b.dof,
                    heading: b.heading,
                    second_heading: b.second_heading.unwrap_or(b.heading),
                    values: b
                        .re
                        .iter()
                        .zip(&b.im)
                        .flat_map(|(re, im)| re.iter().zip(im).map(|(&a, &b)| Complex64::new(a, b)))
                        .collect(),
                })
                .collect(),
        }
    }
}
