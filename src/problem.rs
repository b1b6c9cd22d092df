//! A [`Problem`]: a scenario with its hydrodynamics resolved, checked once, ready for a
//! [`crate::Simulation`].
//!
//! [`resolve`] (`problem/resolve.rs`) turns a [`Scenario`]'s [`DriftSource`] into data
//! ([`Hydro`]): it reads the CSV or database file, or runs the column solver, once.
//! [`Problem::validate`] (`problem/checks.rs`) is the one check of every field;
//! [`crate::RecordPlan::new`] calls it ([`Problem::check`]) before any record is made. This
//! file holds the types and what a problem derives from its data. Errors name
//! fields by their configuration-file keys (`sea.hs`, `current.direction_deg`), in the file's
//! units; the scenario's [`crate::scenario::Origins`] then say where the value was written.

use crate::error::{Error, Result};
use crate::hydro::aranha::aranha_damping;
use crate::hydro::bidirectional::BidirectionalSource;
use crate::hydro::qtf::Qtf;
use crate::hydro::DriftTable;
use crate::model::{DriftDamping, Interaction, SecondOrder};
use crate::scenario::Scenario;
use serde::Serialize;

mod checks;
pub mod inertia;
pub mod motions;
pub mod ranges;
mod resolve;
mod steps;
mod summary;
pub mod wind;
pub use inertia::{BodyData, Inertia, Origin};
pub use resolve::{default_problem, load, resolve, resolve_hydro};

/// The hydrodynamic data of a problem.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Hydro {
    /// What the data are and where they come from, one phrase for the run's summary
    /// ([`Problem::summary`]).
    pub source: String,
    /// The body data the drift source's data hold (a database's mass properties and
    /// low-frequency added mass), for [`Problem::inertia`].
    pub body: BodyData,
    /// Mean drift (and, when given, the wave-drift damping b_ij) per unit amplitude squared.
    pub drift: DriftTable,
    /// The full difference-frequency QTF (uni-directional headings), when the drift source
    /// has one; used by [`SecondOrder::FullQtf`].
    pub qtf: Option<Qtf>,
    /// The bi-directional drift, when the drift source has it (the column-array solver, a
    /// database with a `bidirectional_drift` table); used by [`Interaction::Bidirectional`].
    pub bidirectional: Option<BidirectionalSource>,
}

impl Hydro {
    /// A drift table alone.
    pub fn from_drift(drift: DriftTable) -> Hydro {
        Hydro {
            source: "a drift table".to_string(),
            body: BodyData::default(),
            drift,
            qtf: None,
            bidirectional: None,
        }
    }
}

/// Everything one simulation needs: the scenario with its hydrodynamics resolved.
pub type Problem = Scenario<Hydro>;

/// The finest fraction of a step a time must resolve: times t with |t| eps <=
/// TIME_RESOLUTION h (eps the double's relative spacing, 2.2e-16), so that the step count,
/// the communication points and the records' sample index stay exact.
pub const TIME_RESOLUTION: f64 = 1e-6;

/// The spacing of doubles near `t`, s (an upper bound: |t| eps).
pub fn time_spacing(t: f64) -> f64 {
    t.abs() * f64::EPSILON
}

/// Whether a double resolves times near `t` to [`TIME_RESOLUTION`] of a step `h`.
pub fn time_resolved(t: f64, h: f64) -> bool {
    time_spacing(t) <= TIME_RESOLUTION * h
}

/// The largest |t| that [`time_resolved`] accepts for a step `h`, s (4.5e9 h).
pub fn largest_resolved_time(h: f64) -> f64 {
    TIME_RESOLUTION * h / f64::EPSILON
}

/// The largest share of the spectrum's variance that limiting the default band to the
/// hydrodynamic data may leave out ([`Problem::band`]).
pub const DEFAULT_BAND_TRIM_LIMIT: f64 = 0.01;

/// The default band limited to the hydrodynamic data ([`Problem::band_trim`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BandTrim {
    /// The spectrum's default band, rad/s.
    pub default: (f64, f64),
    /// The band simulated: the default band within the data's frequencies, rad/s.
    pub band: (f64, f64),
    /// The share of the default band's variance left out.
    pub variance_left_out: f64,
}

impl Problem {
    /// The rigid-body mass, yaw inertia and low-frequency added mass the equations of motion
    /// use, each from the configuration or the hydrodynamic data ([`inertia`]'s rule), or
    /// the error that names what is missing.
    pub fn inertia(&self) -> Result<Inertia> {
        Inertia::resolve(&self.platform, &self.hydro.body).map_err(|missing| {
            let data = if missing.data.is_empty() {
                format!("{} holds no mass properties", self.hydro.source)
            } else {
                format!("{} has no mass_properties", missing.data)
            };
            Error::invalid(
                missing.key,
                "(not given)",
                format!("is required: {data}; give it in [platform]"),
            )
        })
    }

    /// The undamped surge natural period 2 pi sqrt((M + A11) / C11), s; `None` without
    /// surge stiffness (or without a mass).
    pub fn surge_natural_period(&self) -> Option<f64> {
        self.inertia()
            .ok()?
            .uncoupled_periods(&self.platform.stiffness)[0]
    }

    /// The default start-up transient, s: [`crate::scenario::TRANSIENT_CYCLES`] surge
    /// natural periods, at most half the run (0 without surge stiffness).
    pub fn default_transient(&self) -> f64 {
        self.surge_natural_period().map_or(0.0, |period| {
            (crate::scenario::TRANSIENT_CYCLES * period).min(0.5 * self.run.duration)
        })
    }

    /// The simulated band (omega_min, omega_max), rad/s: `sea.band` when the user set it;
    /// otherwise the spectrum's default band ([`crate::sea_state::SeaState::band`]), limited
    /// to the frequencies the hydrodynamic data cover (the drift table, and the QTF under
    /// `second_order = "full-qtf"`) when they stop inside it and what is left out holds at
    /// most [`DEFAULT_BAND_TRIM_LIMIT`] of the default band's variance ([`Problem::band_trim`]).
    /// A data file whose last frequency, computed from a printed period, is 2.4999 rad/s
    /// thus serves the default band to 2.5133 rad/s of Tp = 10 s. Beyond the limit the
    /// default band is kept and the coverage checks name the gap.
    pub fn band(&self) -> (f64, f64) {
        self.band_trim()
            .map_or_else(|| self.sea.band(), |trim| trim.band)
    }

    /// How the default band was limited to the data ([`Problem::band`]), or `None` when it
    /// was not (the user set `sea.band`, the data cover the default band, or limiting it
    /// would leave out more than [`DEFAULT_BAND_TRIM_LIMIT`] of the variance).
    pub fn band_trim(&self) -> Option<BandTrim> {
        if self.sea.band.is_some() {
            return None;
        }
        let default = self.sea.band();
        let mut cover = {
            let w = self.hydro.drift.omegas();
            (w[0], w[w.len() - 1])
        };
        if let (SecondOrder::FullQtf, Some(q)) = (self.model.second_order, &self.hydro.qtf) {
            if let (Some(&lo), Some(&hi)) = (q.omegas.first(), q.omegas.last()) {
                cover = (cover.0.max(lo), cover.1.min(hi));
            }
        }
        let tolerance = crate::model::FREQUENCY_MATCH_TOLERANCE;
        let band = (
            if default.0 < cover.0 * (1.0 - tolerance) {
                cover.0
            } else {
                default.0
            },
            if default.1 > cover.1 * (1.0 + tolerance) {
                cover.1
            } else {
                default.1
            },
        );
        if band == default || band.0 >= band.1 {
            return None;
        }
        let variance = |a: f64, b: f64| self.sea_variance(a, b);
        let total = variance(default.0, default.1);
        let left_out = (variance(default.0, band.0) + variance(band.1, default.1)) / total;
        (left_out <= DEFAULT_BAND_TRIM_LIMIT).then_some(BandTrim {
            default,
            band,
            variance_left_out: left_out,
        })
    }

    /// The elevation variance of the sea between `a` and `b` rad/s (m^2): Simpson's rule on
    /// 400 panels of the spectrum's density; zero when b <= a.
    pub(crate) fn sea_variance(&self, a: f64, b: f64) -> f64 {
        if b <= a {
            return 0.0;
        }
        let panels = 400;
        let h = (b - a) / panels as f64;
        let density = |w: f64| self.sea.spectrum.density(w);
        let inner: f64 = (1..panels)
            .map(|i| if i % 2 == 1 { 4.0 } else { 2.0 } * density(a + i as f64 * h))
            .sum();
        (density(a) + inner + density(b)) * h / 3.0
    }

    /// The drift table with the wave-drift damping a run of this problem uses: the table's
    /// own b_ij (`drift_damping = "table"`), Aranha's on its nodes (`"aranha"`, whatever
    /// b_ij the table holds), or `None` (`"off"`).
    pub fn damping_table(&self) -> Result<Option<DriftTable>> {
        Ok(match self.model.drift_damping {
            DriftDamping::Off => None,
            DriftDamping::Table => Some(self.hydro.drift.clone()),
            DriftDamping::Aranha => Some(aranha_damping(
                &self.hydro.drift,
                self.environment.gravity,
                &self.platform.columns,
            )?),
        })
    }

    /// The message of `error` with the settings it names as causes or remedies (those of a
    /// running simulation: [`Error::describe`]) as the user wrote them and where:
    /// `[sea] hs (platform.toml:14)`, `row 3, column 'cd' (cases.csv:4)`, and the drift data
    /// with their source and the `[drift]` that names them. `Display` names the key paths.
    pub fn explain(&self, error: &Error) -> String {
        struct Explained<'a>(&'a Problem, &'a Error);
        impl std::fmt::Display for Explained<'_> {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                let Explained(problem, error) = self;
                error.describe(f, &|key| match key {
                    "drift" => {
                        let source = &problem.hydro.source;
                        match problem.origins.name_and_place(key) {
                            (name, Some(at)) => {
                                format!("the drift data of {name} ({at}; {source})")
                            }
                            (name, None) => format!("the drift data of {name} ({source})"),
                        }
                    }
                    _ => problem.origins.name(key),
                })
            }
        }
        Explained(self, error).to_string()
    }

    /// Whether the cross terms between the directions of a spread sea come from the
    /// bi-directional QTF: the full QTF is selected, the QTF has bi-directional blocks, the
    /// sea has several directions and the interaction is bi-directional (`auto` resolves to
    /// it with such a QTF).
    pub fn cross_terms_from_qtf(&self) -> bool {
        self.model.second_order == SecondOrder::FullQtf
            && self.sea.directions().len() > 1
            && self
                .hydro
                .qtf
                .as_ref()
                .is_some_and(|q| q.is_bidirectional())
            && self.interaction() == Interaction::Bidirectional
    }

    /// The interaction actually used ([`Interaction::Auto`] resolved against the data:
    /// bi-directional when the drift source has the bi-directional drift, or under the full
    /// QTF a bi-directional QTF).
    pub fn interaction(&self) -> Interaction {
        let qtf_has_it = self.model.second_order == SecondOrder::FullQtf
            && self
                .hydro
                .qtf
                .as_ref()
                .is_some_and(|q| q.is_bidirectional());
        match (self.model.interaction, &self.hydro.bidirectional) {
            (Interaction::Auto, Some(_)) => Interaction::Bidirectional,
            (Interaction::Auto, None) if qtf_has_it => Interaction::Bidirectional,
            (Interaction::Auto, None) => Interaction::MeanDirection,
            (chosen, _) => chosen,
        }
    }
}
