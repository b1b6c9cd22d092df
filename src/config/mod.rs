//! The complete description of one simulation, in SI units and radians.
//!
//! [`Config`] is what [`crate::Simulation::new`] takes. The TOML file reader
//! ([`file`]) and the embedded default platform ([`default_platform`]) both produce it;
//! degrees exist only in the file format and are converted there, once.

pub mod default_platform;
pub mod file;

use crate::error::{
    require_finite, require_finite_matrix, require_non_negative, require_positive, Error, Result,
};
use crate::hydro::bidirectional::BidirectionalSource;
use crate::hydro::database::QtfData;
use crate::hydro::DriftTable;
use crate::model::Dof;
use crate::model::HEADING_MATCH_TOLERANCE;
use crate::model::{
    Cylinder, DragModel, DriftDamping, Environment, Interaction, NewmanForm, SecondOrder,
    YawFollowing, DEFAULT_QTF_TOLERANCE,
};
use crate::sea_state::SeaState;

/// Steady, depth-uniform current (E&S section 3).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Current {
    /// Speed, m/s (0 = no current).
    pub speed: f64,
    /// Direction towards which the current flows, rad from +X, counter-clockwise.
    pub direction: f64,
}

/// Run length and time step.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// Simulated duration, s. The wave record is built at least this long, so it never repeats.
    pub duration: f64,
    /// RK4 step h, s. Force records are sampled at h/2 so that every RK4 stage lands on a sample.
    pub time_step: f64,
    /// Time of the first sample, s.
    pub start_time: f64,
}

/// Rigid-body and mooring data of the platform in the 3 slow-drift DOFs (surge, sway, yaw).
///
/// Matrices are indexed (surge, sway, yaw). Mass, added mass and damping act in the body
/// frame; the stiffness acts on the inertial position (X, Y, theta), as in E&S 1.
#[derive(Debug, Clone, PartialEq)]
pub struct Platform {
    /// Mass, kg.
    pub mass: f64,
    /// Yaw moment of inertia about the body origin, kg m^2.
    pub yaw_inertia: f64,
    /// Low-frequency added mass A (kg, kg m, kg m^2).
    pub added_mass: [[f64; 3]; 3],
    /// Mooring stiffness C (N/m, N, N m/rad) acting on (X, Y, theta).
    pub stiffness: [[f64; 3]; 3],
    /// Extra linear damping on the body-frame velocity (N s/m, ...).
    pub linear_damping: [[f64; 3]; 3],
    /// Extra quadratic damping: force_i = sum_j Bq_ij v_j |v_j| on the body-frame velocity.
    pub quadratic_damping: [[f64; 3]; 3],
    /// Columns for viscous drag (empty = no drag elements).
    pub columns: Vec<Cylinder>,
}

/// Modelling choices.
#[derive(Debug, Clone, PartialEq)]
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
        }
    }
}

/// Initial slow-drift state, inertial frame: (X, Y, theta) in m, m, rad and their rates.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct InitialCondition {
    pub position: [f64; 3],
    pub velocity: [f64; 3],
}

/// Everything one simulation needs.
#[derive(Debug, Clone, PartialEq)]
pub struct Config {
    pub environment: Environment,
    pub sea: SeaState,
    pub current: Current,
    pub run: Run,
    pub platform: Platform,
    pub drift: DriftTable,
    /// The full difference-frequency QTF (uni-directional headings), when the drift source
    /// has one; used by [`SecondOrder::FullQtf`].
    pub qtf: Option<QtfData>,
    /// The bi-directional drift, when the drift source has it (the column-array solver, a
    /// database with a `bidirectional_drift` table); used by [`Interaction::Bidirectional`].
    pub bidirectional: Option<BidirectionalSource>,
    pub model: ModelOptions,
    pub initial: InitialCondition,
}

/// Slow-drift cycles dropped as start-up transient by default (E&S section 5: the
/// statistics settle after about ten cycles of the surge natural period).
pub const TRANSIENT_CYCLES: f64 = 10.0;

impl Config {
    /// The undamped surge natural period 2 pi sqrt((M + A11) / C11), s; `None` without
    /// surge stiffness.
    pub fn surge_natural_period(&self) -> Option<f64> {
        let p = &self.platform;
        (p.stiffness[0][0] > 0.0).then(|| {
            2.0 * std::f64::consts::PI * ((p.mass + p.added_mass[0][0]) / p.stiffness[0][0]).sqrt()
        })
    }

    /// The default start-up transient, s: [`TRANSIENT_CYCLES`] surge natural periods, at
    /// most half the run (0 without surge stiffness).
    pub fn default_transient(&self) -> f64 {
        self.surge_natural_period().map_or(0.0, |period| {
            (TRANSIENT_CYCLES * period).min(0.5 * self.run.duration)
        })
    }

    /// Checks every field; the error names the first offending field and value.
    pub fn validate(&self) -> Result<()> {
        require_positive("environment.gravity", self.environment.gravity)?;
        require_positive("environment.water_density", self.environment.water_density)?;
        self.sea.validate()?;
        require_non_negative("current.speed", self.current.speed)?;
        require_finite("current.direction", self.current.direction)?;
        require_positive("run.duration", self.run.duration)?;
        require_positive("run.time_step", self.run.time_step)?;
        require_finite("run.start_time", self.run.start_time)?;
        if self.run.time_step > self.run.duration {
            return Err(Error::invalid(
                "run.time_step",
                self.run.time_step,
                format!("is longer than run.duration = {}", self.run.duration),
            ));
        }
        self.validate_platform()?;
        if self.model.strips_per_column == 0 {
            return Err(Error::invalid(
                "model.strips_per_column",
                0,
                "must be at least 1",
            ));
        }
        match self.model.drag {
            DragModel::Off => {}
            DragModel::Separate { slow, fast } => {
                require_non_negative("model.drag.slow", slow)?;
                require_non_negative("model.drag.fast", fast)?;
            }
            DragModel::Combined { cd } => require_non_negative("model.drag.cd", cd)?,
        }
        if self.model.drag != DragModel::Off && self.platform.columns.is_empty() {
            return Err(Error::invalid(
                "platform.columns",
                "[]",
                "viscous drag is on but the platform has no columns",
            ));
        }
        if self.model.drift_damping == DriftDamping::Table && !self.drift.has_damping() {
            return Err(Error::invalid(
                "model.drift_damping",
                "table",
                "the drift table has no b_ij columns",
            ));
        }
        self.validate_yaw_following()?;
        self.validate_qtf()?;
        self.validate_interaction()?;
        for (i, v) in self.initial.position.iter().enumerate() {
            require_finite(&format!("initial.position[{i}]"), *v)?;
        }
        for (i, v) in self.initial.velocity.iter().enumerate() {
            require_finite(&format!("initial.velocity[{i}]"), *v)?;
        }
        Ok(())
    }

    /// The full QTF, when selected: present, with surge, sway and yaw at every wave
    /// direction's heading (within 0.01 deg; no interpolation in heading), covering the band.
    fn validate_qtf(&self) -> Result<()> {
        if let Some(q) = &self.qtf {
            q.validate()?;
        }
        if self.model.second_order != SecondOrder::FullQtf {
            return Ok(());
        }
        crate::forces::check_tolerance(self.model.qtf_tolerance)?;
        let Some(q) = &self.qtf else {
            return Err(Error::invalid(
                "model.second_order",
                "full-qtf",
                "needs a QTF: use [drift] source = \"database\" with a database that holds one \
                 (`slowdrift hydro wamit` with a .12d, .11d or .10d file)",
            ));
        };
        let missing: Vec<String> = self
            .sea
            .directions()
            .iter()
            .filter(|d| {
                Dof::ALL
                    .iter()
                    .any(|&dof| q.block(dof, d.heading, HEADING_MATCH_TOLERANCE).is_none())
            })
            .map(|d| format!("{:.3}", d.heading.to_degrees()))
            .collect();
        if !missing.is_empty() {
            let mut have: Vec<String> = q
                .blocks
                .iter()
                .map(|b| format!("{:.3}", b.heading.to_degrees()))
                .collect();
            have.dedup();
            return Err(Error::invalid(
                "model.second_order",
                "full-qtf",
                format!(
                    "the QTF has no surge, sway and yaw blocks at the wave heading(s) {} deg \
                     (it has {} deg); the full QTF is not interpolated in heading, so every \
                     direction of the sea needs its own QTF heading",
                    missing.join(", "),
                    have.join(", ")
                ),
            ));
        }
        crate::forces::check_covers(&q.omegas, self.sea.band())
    }

    /// Yaw following: at least two headings, a finite increasing range that holds the
    /// initial yaw, Newman's approximation (the full QTF is not interpolated in heading).
    fn validate_yaw_following(&self) -> Result<()> {
        let Some(yaw) = &self.model.yaw_following else {
            return Ok(());
        };
        if yaw.headings < 2 {
            return Err(Error::invalid(
                "model.yaw_following.headings",
                yaw.headings,
                "must be at least 2",
            ));
        }
        if self.model.second_order == SecondOrder::FullQtf {
            return Err(Error::invalid(
                "model.yaw_following",
                format!("{} headings", yaw.headings),
                "needs second_order = \"newman\": the full QTF is not interpolated in heading",
            ));
        }
        if let Some((min, max)) = yaw.range {
            require_finite("model.yaw_following.range[0]", min)?;
            require_finite("model.yaw_following.range[1]", max)?;
            if min >= max {
                return Err(Error::invalid(
                    "model.yaw_following.range",
                    format!("[{:.3}, {:.3}] deg", min.to_degrees(), max.to_degrees()),
                    "needs min < max",
                ));
            }
            let theta = self.initial.position[2];
            if !(min..=max).contains(&theta) {
                return Err(Error::invalid(
                    "initial.position[2]",
                    format!("{:.3} deg", theta.to_degrees()),
                    format!(
                        "the initial yaw is outside model.yaw_following.range [{:.3}, {:.3}] deg",
                        min.to_degrees(),
                        max.to_degrees()
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Bi-directional interaction needs bi-directional data; a table must be sound.
    fn validate_interaction(&self) -> Result<()> {
        if let Some(BidirectionalSource::Table(table)) = &self.bidirectional {
            table.validate()?;
        }
        if self.model.interaction == Interaction::Bidirectional && self.bidirectional.is_none() {
            return Err(Error::invalid(
                "model.interaction",
                "bidirectional",
                "the drift source has no bi-directional drift (it comes from [drift] source =                  \"column-array\" or a database with a bidirectional_drift table); use                  interaction = \"mean-direction\" to approximate it from the drift table, or                  \"none\"",
            ));
        }
        Ok(())
    }

    /// The interaction actually used ([`Interaction::Auto`] resolved against the data).
    pub fn interaction(&self) -> Interaction {
        match (self.model.interaction, &self.bidirectional) {
            (Interaction::Auto, Some(_)) => Interaction::Bidirectional,
            (Interaction::Auto, None) => Interaction::MeanDirection,
            (chosen, _) => chosen,
        }
    }

    fn validate_platform(&self) -> Result<()> {
        let p = &self.platform;
        require_positive("platform.mass", p.mass)?;
        require_positive("platform.yaw_inertia", p.yaw_inertia)?;
        require_finite_matrix("platform.added_mass", &p.added_mass)?;
        require_finite_matrix("platform.stiffness", &p.stiffness)?;
        require_finite_matrix("platform.linear_damping", &p.linear_damping)?;
        require_finite_matrix("platform.quadratic_damping", &p.quadratic_damping)?;
        for (k, c) in p.columns.iter().enumerate() {
            require_finite(&format!("platform.columns[{k}].x"), c.x)?;
            require_finite(&format!("platform.columns[{k}].y"), c.y)?;
            require_positive(&format!("platform.columns[{k}].diameter"), c.diameter)?;
            require_positive(&format!("platform.columns[{k}].draft"), c.draft)?;
        }
        Ok(())
    }
}
