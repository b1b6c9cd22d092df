//! The one check of a [`Problem`]: [`Problem::validate`] refuses the first field whose value
//! a run cannot take (by its key path, in the file's units), [`Problem::check`] locates it
//! where the user wrote it. The physical ranges are [`super::ranges`], the step against the
//! block and the run [`super::steps`].

use super::{
    largest_resolved_time, ranges, steps, time_resolved, time_spacing, Inertia, Origin, Problem,
};
use crate::error::numbers::{readable, typable_below, written, written_matrix};
use crate::error::{
    require_finite, require_finite_matrix, require_non_negative, require_positive, Error, Result,
};
use crate::hydro::bidirectional::BidirectionalSource;
use crate::hydro::qtf::check_tolerance;
use crate::model::{Dof, DragModel, DriftDamping, Interaction, Mode, SecondOrder, WindProfileKind};
use crate::scenario::limits;

impl Problem {
    /// Times a double resolves to [`TIME_RESOLUTION`] of a step: the start time and, for a
    /// run with an end, the end (`start_time + duration`); an open-ended run is checked as
    /// it goes (`Simulation`). Refused naming the setting that moves the time out of reach.
    fn check_time_resolution(&self) -> Result<()> {
        let run = &self.run;
        let end = run.start_time + run.duration;
        for (key, value, time) in [
            ("run.start_time", run.start_time, run.start_time),
            ("run.duration", run.duration, end),
        ] {
            if time.is_finite() && !time_resolved(time, run.time_step) {
                return Err(Error::invalid(
                    key,
                    value,
                    format!(
                        "reaches t = {} s, where a double resolves time only to {} s: too \
                         coarse for steps of {} s (times within +-{} s keep a millionth of a \
                         step)",
                        readable(time),
                        readable(time_spacing(time)),
                        written(run.time_step),
                        readable(largest_resolved_time(run.time_step))
                    ),
                ));
            }
        }
        Ok(())
    }

    /// [`Problem::validate`], the error located where the user wrote the value.
    pub fn check(&self) -> Result<()> {
        self.validate().map_err(|e| self.origins.locate(e))
    }

    /// Checks every field; the error names the first offending field (by its key path) and
    /// value.
    pub fn validate(&self) -> Result<()> {
        limits::check_sizes(self, None)?;
        ranges::GRAVITY.check("environment.gravity", self.environment.gravity)?;
        ranges::WATER_DENSITY.check("environment.water_density", self.environment.water_density)?;
        // The ranges first: a Tp of 1e-6 s is named as such, not as the steep sea it makes.
        self.check_sea_ranges()?;
        self.sea.validate(self.environment.gravity)?;
        ranges::CURRENT_SPEED.check("current.speed", self.current.speed)?;
        ranges::DIRECTION.check_degrees("current.direction_deg", self.current.direction)?;
        self.check_wind()?;
        self.run_wind()?;
        if self.run.duration.is_nan() || self.run.duration <= 0.0 {
            return Err(Error::invalid(
                "run.duration",
                self.run.duration,
                "must be greater than zero (infinite: an open-ended run)",
            ));
        }
        require_positive("run.time_step", self.run.time_step)?;
        require_positive("run.block_duration", self.run.block_duration)?;
        steps::check_steps(self)?;
        require_finite("run.start_time", self.run.start_time)?;
        self.check_time_resolution()?;
        steps::check_duration(self)?;
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
                require_non_negative("model.cd_slow", slow)?;
                require_non_negative("model.cd_fast", fast)?;
            }
            DragModel::Combined { cd } => require_non_negative("model.cd", cd)?,
        }
        if self.model.drag != DragModel::Off && self.platform.columns.is_empty() {
            return Err(Error::invalid(
                "platform.columns",
                "[]",
                "viscous drag is on but the platform has no columns",
            ));
        }
        if self.model.drift_damping == DriftDamping::Table && !self.hydro.drift.has_damping() {
            return Err(Error::invalid(
                "model.drift_damping",
                DriftDamping::Table.word(),
                "this drift data has no wave-drift damping table (b11 .. b33; the embedded \
                 default has none): the damping choices that work with it are aranha and off",
            ));
        }
        self.validate_yaw_following()?;
        self.validate_qtf()?;
        self.validate_interaction()?;
        ranges::check_initial_state(&self.initial.position, &self.initial.velocity)
    }

    /// The wind (`[wind]`): its direction within a turn either way, its values
    /// (`WindField::validate`) and, when there is wind, its gust spectrum at the reference
    /// height, so that a speed over an averaging period the spectrum does not take is
    /// refused before a run. That refusal names the setting written last of the averaging
    /// period, the spectrum and the profile (the period when none is written); the height of
    /// the spectrum is the reference height, and is named so.
    fn check_wind(&self) -> Result<()> {
        let wind = &self.wind;
        ranges::DIRECTION.check_degrees("wind.direction_deg", wind.direction)?;
        wind.validate()?;
        if !wind.has_gusts() {
            return Ok(());
        }
        let converts = wind.profile.kind() == WindProfileKind::Npd;
        let period = wind.averaging_period;
        let mismatch = !converts && (wind.spectrum_period() - period).abs() > 1e-9 * period;
        wind.gust_spectrum(wind.reference_height)
            .map(drop)
            .map_err(|e| match e {
                Error::InvalidValue { field, reason, .. }
                    if mismatch && field == "wind.averaging_period" =>
                {
                    let keys = ["wind.averaging_period", "wind.spectrum", "wind.profile"];
                    match self.origins.latest(&keys) {
                        "wind.spectrum" => Error::invalid(keys[1], wind.spectrum.word(), reason),
                        "wind.profile" => {
                            Error::invalid(keys[2], wind.profile.kind().word(), reason)
                        }
                        _ => Error::invalid(keys[0], period, reason),
                    }
                }
                Error::InvalidValue {
                    field,
                    value,
                    reason,
                    at,
                } if field == "wind.height" => Error::InvalidValue {
                    field: "wind.reference_height".into(),
                    value,
                    reason,
                    at,
                },
                other => other,
            })
    }

    /// The sea's peak period and band within their physical ranges
    /// ([`ranges`]; `SeaState::validate` has checked their signs and the steepness).
    fn check_sea_ranges(&self) -> Result<()> {
        use crate::sea_state::Spectrum;
        // Hs is bounded by the breaking limit at this Tp (`SeaState::validate`).
        match &self.sea.spectrum {
            Spectrum::Jonswap { tp, .. } | Spectrum::PiersonMoskowitz { tp, .. } => {
                ranges::PEAK_PERIOD.check("sea.tp", *tp)?;
            }
            Spectrum::Tabulated { omega, .. } => {
                if let (Some(first), Some(last)) = (omega.first(), omega.last()) {
                    ranges::BAND.check("sea.omega", *first)?;
                    ranges::BAND.check("sea.omega", *last)?;
                }
            }
        }
        if let Some((lo, hi)) = self.sea.band {
            ranges::BAND.check("sea.band[0]", lo)?;
            ranges::BAND.check("sea.band[1]", hi)?;
        }
        ranges::DIRECTION.check_degrees("sea.direction_deg", self.sea.mean_direction)
    }

    /// The full QTF, when selected: present, covering the band, and its headings covering
    /// every wave direction (bilinear interpolation in the heading pair between data
    /// headings, never extrapolated; with the cross terms from the QTF, every pair of
    /// directions).
    fn validate_qtf(&self) -> Result<()> {
        if let Some(q) = &self.hydro.qtf {
            q.validate()?;
        }
        if self.model.second_order != SecondOrder::FullQtf {
            return Ok(());
        }
        check_tolerance(self.model.qtf_tolerance)?;
        let Some(q) = &self.hydro.qtf else {
            return Err(Error::invalid(
                "model.second_order",
                SecondOrder::FullQtf.word(),
                "needs a QTF: use [drift] source = \"database\" with a database that holds one \
                 (`slowdrift hydro wamit` with a .12d, .11d or .10d file, `slowdrift hydro \
                 nemoh`)",
            ));
        };
        let headings: Vec<f64> = self.sea.directions().iter().map(|d| d.heading).collect();
        let pairs: Vec<(f64, f64)> = if self.cross_terms_from_qtf() {
            headings
                .iter()
                .flat_map(|&a| headings.iter().map(move |&b| (a, b)))
                .collect()
        } else {
            headings.iter().map(|&a| (a, a)).collect()
        };
        for pair in pairs {
            for dof in Dof::ALL {
                q.interpolated(dof, pair).map_err(|e| {
                    Error::invalid(
                        "model.second_order",
                        SecondOrder::FullQtf.word(),
                        format!(
                            "the QTF does not serve the wave direction(s) ({:.3}, {:.3}) deg: {e}",
                            pair.0.to_degrees(),
                            pair.1.to_degrees()
                        ),
                    )
                })?;
            }
        }
        crate::hydro::qtf::check_covers(&q.omegas, self.band())
    }

    /// Yaw following: at least two headings, a finite increasing range that holds the
    /// initial yaw.
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
        if let Some((min, max)) = yaw.range {
            require_finite("model.yaw_following.range_deg[0]", min)?;
            require_finite("model.yaw_following.range_deg[1]", max)?;
            if min >= max {
                return Err(Error::invalid(
                    "model.yaw_following.range_deg",
                    format!("[{:.3}, {:.3}] deg", min.to_degrees(), max.to_degrees()),
                    "needs min < max",
                ));
            }
            let theta = self.initial.position[2];
            if !(min..=max).contains(&theta) {
                return Err(Error::invalid(
                    "initial.heading_deg",
                    format!("{:.3} deg", theta.to_degrees()),
                    format!(
                        "the initial yaw is outside model.yaw_following.range_deg [{:.3}, {:.3}] deg",
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
        if let Some(BidirectionalSource::Table(table)) = &self.hydro.bidirectional {
            table.validate()?;
        }
        let qtf_has_it = self.model.second_order == SecondOrder::FullQtf
            && self
                .hydro
                .qtf
                .as_ref()
                .is_some_and(|q| q.is_bidirectional());
        if self.model.interaction == Interaction::Bidirectional
            && self.hydro.bidirectional.is_none()
            && !qtf_has_it
        {
            return Err(Error::invalid(
                "model.interaction",
                Interaction::Bidirectional.word(),
                "the drift source has no bi-directional drift (it comes from [drift] source = \
                 \"column-array\" or a database with a bidirectional_drift table); use \
                 interaction = \"mean-direction\" to approximate it from the drift table, or \
                 \"none\"",
            ));
        }
        Ok(())
    }

    /// The platform's values: the mass and inertia within their physical ranges (named where
    /// they came from: `platform.mass`, or the database's `mass_properties.mass`), M + A
    /// positive definite, the stiffness storing no negative energy and resolved by the RK4
    /// step, finite damping matrices, the columns within their ranges.
    fn validate_platform(&self) -> Result<()> {
        let p = &self.platform;
        if let Some(added) = &p.added_mass {
            require_finite_matrix("platform.added_mass", added)?;
        }
        let inertia = self.inertia()?;
        let named = |key: &str, origin: &Origin, data_field: &str| match origin {
            Origin::Data { name, .. } => format!("{data_field} of {name}"),
            _ => key.to_string(),
        };
        ranges::MASS.check(
            named(
                "platform.mass",
                &inertia.mass_origin,
                "mass_properties.mass",
            ),
            inertia.mass,
        )?;
        ranges::YAW_INERTIA.check(
            named(
                "platform.yaw_inertia",
                &inertia.yaw_inertia_origin,
                "mass_properties.yaw_inertia",
            ),
            inertia.yaw_inertia,
        )?;
        let rigid = [inertia.mass, inertia.mass, inertia.yaw_inertia];
        let total: [[f64; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|j| inertia.added_mass[i][j] + if i == j { rigid[i] } else { 0.0 })
        });
        if !ranges::mass_matrix_is_positive(&total) {
            return Err(Error::invalid(
                named(
                    "platform.added_mass",
                    &inertia.added_mass_origin,
                    "low_frequency_added_mass",
                ),
                written_matrix(&inertia.added_mass),
                format!(
                    "makes the mass matrix M + A (mass {} kg, yaw inertia {} kg m^2) not \
                     positive definite: no body has such a kinetic energy",
                    written(inertia.mass),
                    written(inertia.yaw_inertia)
                ),
            ));
        }
        require_finite_matrix("platform.stiffness", &p.stiffness)?;
        ranges::check_stiffness(&p.stiffness)?;
        self.check_stiffness_against_the_step(&inertia)?;
        require_finite_matrix("platform.linear_damping", &p.linear_damping)?;
        require_finite_matrix("platform.quadratic_damping", &p.quadratic_damping)?;
        self.validate_columns()?;
        // [platform.motions] checked and its RAOs solvable (problem::motions).
        self.first_order_motions().map(drop)
    }

    /// The columns within their ranges.
    fn validate_columns(&self) -> Result<()> {
        for (k, c) in self.platform.columns.iter().enumerate() {
            ranges::COLUMN_OFFSET.check(format!("platform.columns[{k}].x"), c.x)?;
            ranges::COLUMN_OFFSET.check(format!("platform.columns[{k}].y"), c.y)?;
            ranges::COLUMN_DIAMETER.check(format!("platform.columns[{k}].diameter"), c.diameter)?;
            ranges::COLUMN_DRAFT.check(format!("platform.columns[{k}].draft"), c.draft)?;
        }
        Ok(())
    }

    /// What the drift of the columns needs and nothing a run needs besides (`slowdrift
    /// hydro columns`, `study drift`): the environment and the columns within their ranges,
    /// the error located where the user wrote the value.
    pub fn check_columns(&self) -> Result<()> {
        let checked = ranges::GRAVITY
            .check("environment.gravity", self.environment.gravity)
            .and_then(|()| {
                ranges::WATER_DENSITY
                    .check("environment.water_density", self.environment.water_density)
            })
            .and_then(|()| self.validate_columns());
        checked.map_err(|e| self.origins.locate(e))
    }

    /// Each DOF's undamped natural period must be long enough for the RK4 step to follow:
    /// RK4 is unstable for an oscillator with omega h > 2 sqrt(2) (its stability region on
    /// the imaginary axis), so the period must exceed 2 pi h / (2 sqrt(2)) = 2.22 h. A
    /// stiffness that breaks it is refused naming the stiffness and the step.
    fn check_stiffness_against_the_step(&self, inertia: &Inertia) -> Result<()> {
        const KEYS: [&str; 3] = [
            "platform.stiffness[0][0]",
            "platform.stiffness[1][1]",
            "platform.stiffness[2][2]",
        ];
        let h = self.run.time_step;
        let shortest = 2.0 * std::f64::consts::PI * h / (2.0 * std::f64::consts::SQRT_2);
        for (i, period) in inertia
            .uncoupled_periods(&self.platform.stiffness)
            .into_iter()
            .enumerate()
        {
            if let Some(period) = period.filter(|t| *t <= shortest) {
                return Err(Error::invalid(
                    KEYS[i],
                    self.platform.stiffness[i][i],
                    format!(
                        "gives a natural period of {} s, too short for RK4 steps of {} s \
                         (unstable below 2.22 steps a period): lower the stiffness, or \
                         time_step to {} s or less",
                        readable(period),
                        written(h),
                        typable_below(period * h / shortest)
                    ),
                ));
            }
        }
        Ok(())
    }
}
