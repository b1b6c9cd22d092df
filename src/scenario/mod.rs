//! What the user asked for: a [`Scenario`], in SI units and radians, with its hydrodynamic
//! data named but not yet computed ([`DriftSource`]: "the column solver on this grid", "this
//! database file"). Reading a scenario does no numerical work; `problem::resolve`
//! runs the readers and solvers once and gives the `problem::Problem` a simulation
//! takes.
//!
//! The TOML reader ([`file`](mod@file)), the embedded default ([`default`]) and the override table
//! ([`overrides`]: the FMU parameters and the case-table columns) all produce or change a
//! scenario. Degrees exist only in the file formats and are converted there, once.

pub mod default;
pub mod file;
pub mod limits;
mod lines;
mod origin;
pub mod overrides;

pub use origin::{Origins, Written};

use crate::model::{
    Cylinder, DragModel, DriftDamping, Environment, Interaction, NewmanForm, SecondOrder,
    WaveFrequencyMotion, YawFollowing, DEFAULT_QTF_TOLERANCE,
};
use crate::sea_state::SeaState;
use crate::wind::{WindField, WindLoad};
use serde::Serialize;
use std::path::PathBuf;

/// Steady, depth-uniform current (E&S section 3).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Current {
    /// Speed, m/s (0 = no current).
    pub speed: f64,
    /// Direction towards which the current flows, rad from +X, counter-clockwise.
    pub direction: f64,
}

/// Run length and time step.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Run {
    /// Simulated duration, s (`f64::INFINITY` for an open-ended run, the FMU's without a
    /// stop time). The records do not depend on it: the same seed gives the same sea over
    /// the common span of two runs of any durations.
    pub duration: f64,
    /// RK4 step h, s. Force records are sampled at h/2 so that every RK4 stage lands on a sample.
    pub time_step: f64,
    /// Time of the first sample, s.
    pub start_time: f64,
    /// Length of a block of the record stream, s: the records are synthesised and held one
    /// block at a time (`forces::stream`), so memory does not grow with the duration.
    pub block_duration: f64,
    /// The memory the run's records may take, bytes (`run.memory_limit_gb`; default
    /// [`limits::DEFAULT_MEMORY_LIMIT`]): a configuration whose estimate exceeds it is refused
    /// before anything is allocated (`record_plan::budget`). A resource bound, not part of
    /// what is simulated: not fingerprinted.
    #[serde(skip)]
    pub memory_limit: f64,
}

/// Default [`Run::block_duration`], s: 2^14 s (4.6 hours), so that runs of up to 2^14 s
/// (the paper's Fig. 10 records, a three-hour storm) are one block.
pub const DEFAULT_BLOCK_DURATION: f64 = 16384.0;

/// Rigid-body and mooring data of the platform in the 3 slow-drift DOFs (surge, sway, yaw).
///
/// Matrices are indexed (surge, sway, yaw). Mass, added mass and damping act in the body
/// frame; the stiffness acts on the inertial position (X, Y, theta), as in E&S 1.
///
/// The mass, yaw inertia and added mass are what the configuration gives (`None`: it gives
/// none); the values a run uses follow one rule with the hydrodynamic data
/// (`Problem::inertia`, `problem::inertia`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Platform {
    /// Mass, kg.
    pub mass: Option<f64>,
    /// Yaw moment of inertia about the body origin, kg m^2.
    pub yaw_inertia: Option<f64>,
    /// Low-frequency added mass A (kg, kg m, kg m^2).
    pub added_mass: Option<[[f64; 3]; 3]>,
    /// Mooring stiffness C (N/m, N, N m/rad) acting on (X, Y, theta).
    pub stiffness: [[f64; 3]; 3],
    /// Extra linear damping on the body-frame velocity (N s/m, ...).
    pub linear_damping: [[f64; 3]; 3],
    /// Extra quadratic damping: force_i = sum_j Bq_ij v_j |v_j| on the body-frame velocity.
    pub quadratic_damping: [[f64; 3]; 3],
    /// The platform's columns: Morison drag strips and the column solvers (empty = none).
    pub columns: Vec<Cylinder>,
    /// The rigid body of the first-order (wave-frequency) motions in 6 DOF
    /// (`[platform.motions]`), when the configuration gives it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub motions: Option<Motions>,
    /// The wind's force on the platform, its coefficients (`[platform.wind]`), when the
    /// configuration gives them.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wind: Option<WindLoad>,
}

/// What the first-order motions (RAOs, docs/theory.md#first-order-motions-raos) need beyond
/// the radiation-diffraction data and the platform's mass: `[platform.motions]`. Body frame
/// (x forward, y to port, z up) about the body reference point, the data's origin; DOFs
/// surge, sway, heave, roll, pitch, yaw. The slow-drift equations do not use it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Motions {
    /// Centre of gravity (x_g, y_g, z_g) from the reference point, m.
    pub centre_of_gravity: [f64; 3],
    /// The inertia about the centre of gravity.
    pub inertia: BodyInertia,
    /// Linear stiffness besides the hydrostatics and the weight (the mooring's,
    /// linearised), 6x6: N/m, N, N m/m, N m/rad.
    pub external_stiffness: [[f64; 6]; 6],
    /// Linear damping besides the radiation damping (viscous: a potential-flow code has
    /// none, and the heave, roll and pitch resonances need it), 6x6: N s/m, N s, N m s/m,
    /// N m s/rad.
    pub external_damping: [[f64; 6]; 6],
}

/// The inertia of the body about its centre of gravity, body axes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum BodyInertia {
    /// Radii of gyration (r_x, r_y, r_z) about axes through the centre of gravity, m:
    /// I = m diag(r_x^2, r_y^2, r_z^2), no products of inertia.
    RadiiOfGyration([f64; 3]),
    /// The inertia tensor, kg m^2, symmetric, off-diagonal entries with their minus sign
    /// (I_xy = -sum m x y).
    Tensor([[f64; 3]; 3]),
}

/// Modelling choices.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModelOptions {
    pub second_order: SecondOrder,
    /// Relative trace-norm share of the QTF's eigenvalues that may be discarded (full QTF).
    pub qtf_tolerance: f64,
    /// The form of Newman's approximation: the wave force under [`SecondOrder::Newman`],
    /// and the wave-drift damping records always.
    pub newman: NewmanForm,
    /// Interaction between the directions of a short-crested sea (arithmetic Newman form
    /// across directions, whatever `newman` is; `forces::directional`).
    pub interaction: Interaction,
    pub drift_damping: DriftDamping,
    pub drag: DragModel,
    /// Number of Morison strips per column, from the keel to the instantaneous free surface.
    pub strips_per_column: usize,
    /// Wave force and damping records that follow the yaw; `None` (the default) = the
    /// paper's records at the mean position and zero yaw.
    pub yaw_following: Option<YawFollowing>,
    /// Whether the RAOs' wave-frequency motion is added to the slow drift (outputs only).
    pub wave_frequency_motion: WaveFrequencyMotion,
}

impl Default for ModelOptions {
    fn default() -> Self {
        ModelOptions {
            second_order: SecondOrder::Newman,
            qtf_tolerance: DEFAULT_QTF_TOLERANCE,
            newman: NewmanForm::Geometric,
            interaction: Interaction::Auto,
            drift_damping: DriftDamping::Aranha,
            drag: DragModel::Off,
            strips_per_column: 20,
            yaw_following: None,
            wave_frequency_motion: WaveFrequencyMotion::On,
        }
    }
}

/// Initial slow-drift state, inertial frame: (X, Y, theta) in m, m, rad and their rates.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct InitialCondition {
    pub position: [f64; 3],
    pub velocity: [f64; 3],
}

/// A frequency and heading grid on which a column solver tabulates the drift.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ColumnGrid {
    /// Lowest and highest frequency, rad/s.
    pub omega_min: f64,
    pub omega_max: f64,
    /// Number of frequencies, evenly spaced from `omega_min` to `omega_max`.
    pub n_omega: usize,
    /// Heading step, rad: headings from 0 up to (not including) a full turn.
    pub heading_step: f64,
}

/// Where the mean drift (and, with it, the QTF and the bi-directional drift) comes from: the
/// `[drift]` section of the configuration, as the user named it. Nothing here is computed or
/// read until `problem::resolve`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum DriftSource {
    /// A table given in the configuration file, already checked and sorted.
    Table(crate::hydro::DriftTable),
    /// A CSV drift table (`hydro::io::drift_csv`).
    Csv(PathBuf),
    /// A native hydro database (`hydro::io::database`); `bidirectional_from_columns` takes the
    /// bi-directional drift from the deep-water column solver on the platform's columns at the
    /// database's drift frequencies instead of the database's own table.
    Database {
        path: PathBuf,
        bidirectional_from_columns: bool,
    },
    /// The default platform's radiation-diffraction database, compiled into the library
    /// (`hydro::default_platform`, made by `tests/bem`).
    DefaultPlatform,
    /// The closed-form drift of each column as an isolated, infinitely deep cylinder
    /// (`hydro::column_drift`; no interaction).
    IsolatedColumns(ColumnGrid),
    /// The columns as an interacting array (Linton & Evans 1990, `hydro::columns`); `depth`
    /// in m for bottom-mounted columns, `None` for deep water and infinitely deep columns.
    ColumnArray {
        grid: ColumnGrid,
        depth: Option<f64>,
    },
}

/// One simulation as described: the sea, the platform, the run and the modelling choices,
/// with its hydrodynamics `H`: a [`DriftSource`] in a scenario as the user wrote it, the data
/// themselves in a `problem::Problem` (`Scenario<Hydro>`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Scenario<H = DriftSource> {
    pub environment: Environment,
    pub sea: SeaState,
    pub current: Current,
    /// The wind (`[wind]`; none by default). Not serialised when calm, so that a
    /// scenario without wind keeps the fingerprint it had before wind existed.
    #[serde(skip_serializing_if = "WindField::is_calm")]
    pub wind: WindField,
    pub run: Run,
    pub platform: Platform,
    pub hydro: H,
    pub model: ModelOptions,
    pub initial: InitialCondition,
    /// Where each setting was written, for error messages (not part of what is simulated:
    /// origins always compare equal and are not fingerprinted).
    #[serde(skip)]
    pub origins: Origins,
}

/// Default number of discrete directions of a short-crested sea.
pub const DEFAULT_N_DIRECTIONS: usize = 15;

/// Slow-drift cycles dropped as start-up transient by default (E&S section 5: the
/// statistics settle after about ten cycles of the surge natural period).
pub const TRANSIENT_CYCLES: f64 = 10.0;

impl<H> Scenario<H> {
    /// The same scenario with other hydrodynamics.
    pub fn with_hydro<K>(self, hydro: K) -> Scenario<K> {
        Scenario {
            environment: self.environment,
            sea: self.sea,
            current: self.current,
            wind: self.wind,
            run: self.run,
            platform: self.platform,
            hydro,
            model: self.model,
            initial: self.initial,
            origins: self.origins,
        }
    }
}
