//! The shared vocabulary of SlowDrift: the degrees of freedom, the water, the platform's
//! cylinders, and the modelling choices. Every other module may import this one; it imports
//! nothing of the crate.
//!
//! Conventions (docs/theory.md#conventions): SI units and radians; the body frame follows the slow
//! yaw; DOF order surge, sway, yaw.

use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// A slow-drift degree of freedom, in the order of every force and state array of the crate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Dof {
    Surge,
    Sway,
    Yaw,
}

impl Dof {
    /// Surge, sway, yaw: the order of the crate's force arrays.
    pub const ALL: [Dof; 3] = [Dof::Surge, Dof::Sway, Dof::Yaw];

    /// Its name in messages: `surge`, `sway`, `yaw`.
    pub fn name(self) -> &'static str {
        match self {
            Dof::Surge => "surge",
            Dof::Sway => "sway",
            Dof::Yaw => "yaw",
        }
    }
}

/// Headings of hydrodynamic data closer than this are the same heading, rad (0.01 deg: files
/// print headings in degrees with five significant digits). A wave direction of the sea
/// matches a data heading within it (the full QTF is never interpolated in heading).
pub const HEADING_MATCH_TOLERANCE: f64 = 0.01 * PI / 180.0;

/// Frequencies closer than this relative distance are the same frequency, and a band limit
/// this close beyond a data grid's first or last frequency is covered by it (the data's end
/// value is used there; nothing further is extrapolated). Frequencies of hydrodynamic files
/// are computed from printed periods, omega = 2 pi / PER: a period printed with five
/// significant digits is off by up to 5e-5 of itself, so the IEA-15 MW file's 2.5 rad/s comes
/// out as 2.4999... and a band to 2.5 must still be covered. 1e-4 is below the relative
/// step of every real frequency grid (0.05 rad/s at 3 rad/s is 1.7e-2).
pub const FREQUENCY_MATCH_TOLERANCE: f64 = 1e-4;

/// Physical constants of the water (docs/theory.md#conventions).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Environment {
    /// Acceleration of gravity, m/s^2.
    pub gravity: f64,
    /// Water density, kg/m^3.
    pub water_density: f64,
}

impl Default for Environment {
    fn default() -> Self {
        Environment {
            gravity: 9.80665,
            water_density: 1025.0,
        }
    }
}

/// A vertical circular cylinder of the platform (a "column" in the paper and the
/// configuration file): Morison drag strips (E&S 8, 9) and the column solvers. Body frame, m.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Cylinder {
    /// Centre, body frame x (forward), m.
    pub x: f64,
    /// Centre, body frame y (port), m.
    pub y: f64,
    /// Diameter, m.
    pub diameter: f64,
    /// Draft: the keel is at z = -draft, m.
    pub draft: f64,
}

/// Which form of Newman's approximation builds the slowly varying records
/// (docs/theory.md#the-slowly-varying-force).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum NewmanForm {
    /// The paper's form (E&S 4): T_ij = sign * sqrt(T_ii T_jj) where the signs agree, 0 otherwise.
    Geometric,
    /// T_ij = (T_ii + T_jj) / 2.
    Arithmetic,
}

/// How the slowly varying wave force is computed from second-order theory
/// (docs/theory.md#the-slowly-varying-force).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum SecondOrder {
    /// Newman's approximation from the drift table's diagonal, in the form `newman`.
    Newman,
    /// The full difference-frequency QTF of the drift source, factorised at FFT cost
    /// (`forces::QtfFactorisation`), truncated at `qtf_tolerance`.
    FullQtf,
}

/// Whether the components of different directions of a short-crested sea interact in the
/// slowly varying force (docs/theory.md#the-slowly-varying-force; `forces::directional`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Interaction {
    /// The default: [`Interaction::Bidirectional`] when the drift source has bi-directional
    /// drift, else [`Interaction::MeanDirection`]. Without cross terms the slow-drift
    /// variance falls roughly like 1/N_beta as a spread sea is split into more directions
    /// (README "Spread seas"), so some interaction is always on unless asked otherwise.
    Auto,
    /// Each direction's own double sum only (cross-direction terms dropped; the behaviour
    /// before issue #5 part 2).
    None,
    /// Cross terms from T(omega; (beta_k + beta_l)/2) of the uni-directional drift table.
    MeanDirection,
    /// Cross terms from the bi-directional drift of the drift source.
    Bidirectional,
}

impl Interaction {
    /// The word of the configuration file's `[model] interaction` (and of the case table):
    /// `auto`, `none`, `mean-direction`, `bidirectional`.
    pub fn word(self) -> &'static str {
        match self {
            Interaction::Auto => "auto",
            Interaction::None => "none",
            Interaction::MeanDirection => "mean-direction",
            Interaction::Bidirectional => "bidirectional",
        }
    }
}

/// Where the wave-drift damping coefficients b_ij(omega, beta) come from
/// (docs/theory.md#wave-drift-damping-and-current).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum DriftDamping {
    /// No wave-drift damping.
    Off,
    /// The b_ij columns of the drift table.
    Table,
    /// Aranha's formula from the drift table and its derivatives.
    Aranha,
}

/// Morison drag models of the paper (E&S 8, 9).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum DragModel {
    /// No viscous drag.
    Off,
    /// Separate slow and fast parts: C_DS U|U| + C_DL u|u| (E&S 8).
    Separate { slow: f64, fast: f64 },
    /// One coefficient on the total relative velocity: C_D (U + u)|U + u| (E&S 9).
    Combined { cd: f64 },
}

/// Records of the wave force and damping that follow the body's yaw (issue #5 part 3;
/// docs/theory.md#the-slowly-varying-force): built at `headings` body yaw angles theta_j and
/// interpolated linearly in the instantaneous yaw at every RK4 stage.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct YawFollowing {
    /// Number of body yaw angles theta_j (at least 2).
    pub headings: usize,
    /// The covered yaw range [min, max], rad, with theta_j evenly spaced from min to max
    /// (both included); a yaw outside it is an error. `None` = the full circle: theta_j
    /// evenly spaced over [-pi, pi), 360 deg / headings apart, periodic (any yaw is covered).
    pub range: Option<(f64, f64)>,
}

/// Default `qtf_tolerance` of the modelling options (`scenario::ModelOptions`).
pub const DEFAULT_QTF_TOLERANCE: f64 = 1e-6;
