//! The FMU's parameters and experiment, and how they become a [`Problem`].
//!
//! The base configuration comes, in this order of preference, from:
//! 1. the String parameter `hydroDatabase` when it is not empty: a path or `file:` URI of a
//!    TOML configuration file ([`crate::scenario::file`]). The native hydrodynamic database of
//!    issue #3 will replace this file format; the parameter keeps its name;
//! 2. `platform.toml` in the FMU's `resources` folder (`fmuResourceLocation`), when present;
//! 3. the embedded default platform ([`default::default_scenario`]).
//!
//! The FMU parameters then always override the base: the sea (JONSWAP `Hs`, `Tp`, `gamma`,
//! `waveDirection`, cos^N spreading, `nDirections`, `seed`), the current, the drag model and
//! coefficients, the drift-damping source, the diagonal of the mooring stiffness and the RK4
//! step. `interaction` and `yawFollowingHeadings` override it unless they are 0 ("the
//! configuration's"), their start value. Everything else (mass, added mass, columns, drift table, off-diagonal stiffness,
//! Newman form, strips, initial condition) comes from the base. The run's start time and
//! duration come from `fmi2SetupExperiment`.

use crate::error::{Error, Result};
use crate::model::{DragModel, DriftDamping, Interaction, YawFollowing};
use crate::model_description::{start, vr};
use crate::scenario::{default, file, Scenario};
use crate::sea_state::{Spectrum, Spreading};
use std::path::{Path, PathBuf};

/// Length of the precomputed records when the master gives no stop time: six hours. The
/// records are built once for the whole run (about 1.3 MB per simulated hour at h = 1 s,
/// twice that at h = 0.5 s), so an unbounded run cannot be precomputed; six hours is twice
/// the usual three-hour storm and keeps an instance near 8 MB.
pub const MAX_DURATION_WITHOUT_STOP_TIME: f64 = 6.0 * 3600.0;

use super::resources::RESOURCE_CONFIG;

/// The FMU's parameters, one field per parameter of modelDescription.xml, initialised from
/// its start values.
#[derive(Debug, Clone, PartialEq)]
pub struct Parameters {
    pub hs: f64,
    pub tp: f64,
    /// 0 = DNV-RP-C205 default.
    pub gamma: f64,
    pub wave_direction: f64,
    /// 0 = long-crested, else cos^N.
    pub spreading_exponent: f64,
    pub current_speed: f64,
    pub current_direction: f64,
    pub cd_slow: f64,
    pub cd_fast: f64,
    pub cd: f64,
    pub stiffness_surge: f64,
    pub stiffness_sway: f64,
    pub stiffness_yaw: f64,
    pub step_size: f64,
    pub n_directions: i32,
    pub seed: i32,
    /// 0 off, 1 separate, 2 combined.
    pub drag_model: i32,
    /// 0 off, 1 table, 2 Aranha.
    pub drift_damping: i32,
    /// 0 = the configuration's, 1 auto, 2 bidirectional, 3 mean-direction, 4 none.
    pub interaction: i32,
    /// 0 = the configuration's, -1 off, n >= 2 records at n body yaw angles.
    pub yaw_following_headings: i32,
    /// Half-width of the covered yaw range about zero, rad; 0 = the full circle.
    pub yaw_following_range: f64,
    /// Path or `file:` URI of a configuration file; empty = resources or embedded default.
    pub hydro_database: String,
}

impl Default for Parameters {
    fn default() -> Self {
        Parameters {
            hs: start::HS,
            tp: start::TP,
            gamma: start::GAMMA,
            wave_direction: start::WAVE_DIRECTION,
            spreading_exponent: start::SPREADING_EXPONENT,
            current_speed: start::CURRENT_SPEED,
            current_direction: start::CURRENT_DIRECTION,
            cd_slow: start::CD_SLOW,
            cd_fast: start::CD_FAST,
            cd: start::CD,
            stiffness_surge: start::STIFFNESS_SURGE,
            stiffness_sway: start::STIFFNESS_SWAY,
            stiffness_yaw: start::STIFFNESS_YAW,
            step_size: start::STEP_SIZE,
            n_directions: start::N_DIRECTIONS,
            seed: start::SEED,
            drag_model: start::DRAG_MODEL,
            drift_damping: start::DRIFT_DAMPING,
            interaction: start::INTERACTION,
            yaw_following_headings: start::YAW_FOLLOWING_HEADINGS,
            yaw_following_range: start::YAW_FOLLOWING_RANGE,
            hydro_database: start::HYDRO_DATABASE.to_string(),
        }
    }
}

impl Parameters {
    /// The Real parameter with value reference `vr`, if there is one.
    pub fn real_mut(&mut self, vr: u32) -> Option<&mut f64> {
        Some(match vr {
            vr::HS => &mut self.hs,
            vr::TP => &mut self.tp,
            vr::GAMMA => &mut self.gamma,
            vr::WAVE_DIRECTION => &mut self.wave_direction,
            vr::SPREADING_EXPONENT => &mut self.spreading_exponent,
            vr::CURRENT_SPEED => &mut self.current_speed,
            vr::CURRENT_DIRECTION => &mut self.current_direction,
            vr::CD_SLOW => &mut self.cd_slow,
            vr::CD_FAST => &mut self.cd_fast,
            vr::CD => &mut self.cd,
            vr::STIFFNESS_SURGE => &mut self.stiffness_surge,
            vr::STIFFNESS_SWAY => &mut self.stiffness_sway,
            vr::STIFFNESS_YAW => &mut self.stiffness_yaw,
            vr::STEP_SIZE => &mut self.step_size,
            vr::YAW_FOLLOWING_RANGE => &mut self.yaw_following_range,
            _ => return None,
        })
    }

    /// The Integer (or Enumeration) parameter with value reference `vr`, if there is one.
    pub fn integer_mut(&mut self, vr: u32) -> Option<&mut i32> {
        Some(match vr {
            vr::N_DIRECTIONS => &mut self.n_directions,
            vr::SEED => &mut self.seed,
            vr::DRAG_MODEL => &mut self.drag_model,
            vr::DRIFT_DAMPING => &mut self.drift_damping,
            vr::INTERACTION => &mut self.interaction,
            vr::YAW_FOLLOWING_HEADINGS => &mut self.yaw_following_headings,
            _ => return None,
        })
    }

    /// The String parameter with value reference `vr`, if there is one.
    pub fn string_mut(&mut self, vr: u32) -> Option<&mut String> {
        match vr {
            vr::HYDRO_DATABASE => Some(&mut self.hydro_database),
            _ => None,
        }
    }

    /// The configuration these parameters describe for `experiment`, validated. The error
    /// names the FMU parameter, or the core's field, and the value.
    pub fn to_scenario(
        &self,
        resources: Option<&Path>,
        experiment: &Experiment,
    ) -> Result<Scenario> {
        self.apply(self.base_scenario(resources)?, experiment)
    }

    /// `base` with these parameters and `experiment` applied, not yet validated (see the
    /// module documentation for what the parameters override). Errors only for an
    /// Integer or Enumeration parameter outside its range.
    pub fn apply<H>(&self, mut c: Scenario<H>, experiment: &Experiment) -> Result<Scenario<H>> {
        c.sea.spectrum = Spectrum::Jonswap {
            hs: self.hs,
            tp: self.tp,
            gamma: (self.gamma != 0.0).then_some(self.gamma),
        };
        c.sea.mean_direction = self.wave_direction;
        c.sea.spreading = if self.spreading_exponent == 0.0 {
            Spreading::LongCrested
        } else {
            Spreading::CosN {
                n: self.spreading_exponent,
            }
        };
        c.sea.n_directions = usize::try_from(self.n_directions)
            .ok()
            .filter(|&n| n >= 1)
            .ok_or_else(|| Error::invalid("nDirections", self.n_directions, "must be >= 1"))?;
        c.sea.seed = u64::try_from(self.seed)
            .map_err(|_| Error::invalid("seed", self.seed, "must not be negative"))?;
        c.current.speed = self.current_speed;
        c.current.direction = self.current_direction;
        c.model.drag = match self.drag_model {
            0 => DragModel::Off,
            1 => DragModel::Separate {
                slow: self.cd_slow,
                fast: self.cd_fast,
            },
            2 => DragModel::Combined { cd: self.cd },
            other => {
                return Err(Error::invalid(
                    "dragModel",
                    other,
                    "must be 0 (off), 1 (separate) or 2 (combined)",
                ))
            }
        };
        c.model.drift_damping = match self.drift_damping {
            0 => DriftDamping::Off,
            1 => DriftDamping::Table,
            2 => DriftDamping::Aranha,
            other => {
                return Err(Error::invalid(
                    "driftDamping",
                    other,
                    "must be 0 (off), 1 (table) or 2 (aranha)",
                ))
            }
        };
        match self.interaction {
            0 => {}
            1 => c.model.interaction = Interaction::Auto,
            2 => c.model.interaction = Interaction::Bidirectional,
            3 => c.model.interaction = Interaction::MeanDirection,
            4 => c.model.interaction = Interaction::None,
            other => {
                return Err(Error::invalid(
                    "interaction",
                    other,
                    "must be 0 (the configuration's), 1 (auto), 2 (bidirectional), \
                     3 (mean-direction) or 4 (none)",
                ))
            }
        }
        match self.yaw_following_headings {
            0 => {}
            -1 => c.model.yaw_following = None,
            n if n >= 2 => {
                let half = self.yaw_following_range;
                c.model.yaw_following = Some(YawFollowing {
                    headings: n as usize,
                    range: (half != 0.0).then_some((-half, half)),
                })
            }
            other => {
                return Err(Error::invalid(
                    "yawFollowingHeadings",
                    other,
                    "must be 0 (the configuration's), -1 (off) or at least 2",
                ))
            }
        }
        let diagonal = [
            self.stiffness_surge,
            self.stiffness_sway,
            self.stiffness_yaw,
        ];
        for (i, k) in diagonal.into_iter().enumerate() {
            c.platform.stiffness[i][i] = k;
        }
        c.run.time_step = self.step_size;
        c.run.start_time = experiment.start_time;
        c.run.duration = experiment.duration();
        Ok(c)
    }

    /// The parameters and experiment that make an instance whose base configuration is
    /// `base` (the file named by `hydro_database`, or the packed default platform when it
    /// is empty) run `config` exactly, seed aside (left at 0: a master sets it per run).
    /// `Err` says why `config` cannot be expressed through the FMU's parameters: a
    /// spectrum other than JONSWAP, cos-2s spreading, or any difference from `base`
    /// outside the overridden fields (checked by applying the result to `base`).
    pub fn for_config<H: Clone + PartialEq>(
        config: &Scenario<H>,
        base: &Scenario<H>,
        hydro_database: &str,
    ) -> std::result::Result<(Parameters, Experiment), String> {
        let Spectrum::Jonswap { hs, tp, gamma } = config.sea.spectrum else {
            return Err(
                "the FMU's sea is a JONSWAP spectrum (Hs, Tp, gamma); this one is not".into(),
            );
        };
        let spreading_exponent = match config.sea.spreading {
            Spreading::LongCrested => 0.0,
            Spreading::CosN { n } => n,
            Spreading::Cos2s { .. } => {
                return Err("the FMU's spreading is cos^N; this sea is spread cos-2s".into())
            }
        };
        let n_directions = i32::try_from(config.sea.n_directions).map_err(|_| {
            format!(
                "n_directions = {} exceeds the FMU's Integer",
                config.sea.n_directions
            )
        })?;
        let (mut cd_slow, mut cd_fast, mut cd) = (start::CD_SLOW, start::CD_FAST, start::CD);
        let drag_model = match config.model.drag {
            DragModel::Off => 0,
            DragModel::Separate { slow, fast } => {
                (cd_slow, cd_fast) = (slow, fast);
                1
            }
            DragModel::Combined { cd: c } => {
                cd = c;
                2
            }
        };
        let drift_damping = match config.model.drift_damping {
            DriftDamping::Off => 0,
            DriftDamping::Table => 1,
            DriftDamping::Aranha => 2,
        };
        let interaction = if config.model.interaction == base.model.interaction {
            0
        } else {
            match config.model.interaction {
                Interaction::Auto => 1,
                Interaction::Bidirectional => 2,
                Interaction::MeanDirection => 3,
                Interaction::None => 4,
            }
        };
        let (yaw_following_headings, yaw_following_range) =
            if config.model.yaw_following == base.model.yaw_following {
                (0, start::YAW_FOLLOWING_RANGE)
            } else {
                match &config.model.yaw_following {
                    None => (-1, start::YAW_FOLLOWING_RANGE),
                    Some(y) => {
                        let headings = i32::try_from(y.headings).map_err(|_| {
                            format!(
                                "{} yaw-following headings exceed the FMU's Integer",
                                y.headings
                            )
                        })?;
                        let half = match y.range {
                            None => 0.0,
                            Some((lo, hi)) if lo == -hi && hi > 0.0 => hi,
                            Some((lo, hi)) => {
                                return Err(format!(
                                    "the FMU's yaw-following range is symmetric about zero; \
                                     this one is [{lo}, {hi}] rad"
                                ))
                            }
                        };
                        (headings, half)
                    }
                }
            };
        let k = &config.platform.stiffness;
        let parameters = Parameters {
            hs,
            tp,
            gamma: gamma.unwrap_or(0.0),
            wave_direction: config.sea.mean_direction,
            spreading_exponent,
            current_speed: config.current.speed,
            current_direction: config.current.direction,
            cd_slow,
            cd_fast,
            cd,
            stiffness_surge: k[0][0],
            stiffness_sway: k[1][1],
            stiffness_yaw: k[2][2],
            step_size: config.run.time_step,
            n_directions,
            seed: 0,
            drag_model,
            drift_damping,
            interaction,
            yaw_following_headings,
            yaw_following_range,
            hydro_database: hydro_database.to_string(),
        };
        let start = config.run.start_time;
        let experiment =
            Experiment::new(start, Some(start + config.run.duration)).map_err(|e| e.to_string())?;
        let mut expected = config.clone();
        expected.sea.seed = 0;
        let applied = parameters
            .apply(base.clone(), &experiment)
            .map_err(|e| e.to_string())?;
        if applied != expected {
            return Err(
                "the configuration differs from the FMU's base in a field the FMU's parameters \
                 do not set (or its start time and duration do not survive stopTime - startTime)"
                    .into(),
            );
        }
        Ok((parameters, experiment))
    }

    fn base_scenario(&self, resources: Option<&Path>) -> Result<Scenario> {
        if !self.hydro_database.is_empty() {
            let path = if self.hydro_database.starts_with("file:") {
                file_uri_to_path(&self.hydro_database).ok_or_else(|| {
                    Error::invalid(
                        "hydroDatabase",
                        &self.hydro_database,
                        "is not a local file URI",
                    )
                })?
            } else {
                PathBuf::from(&self.hydro_database)
            };
            return file::load(&path);
        }
        if let Some(path) = resources
            .map(|r| r.join(RESOURCE_CONFIG))
            .filter(|p| p.is_file())
        {
            return file::load(&path);
        }
        default::default_scenario()
    }
}

/// What `fmi2SetupExperiment` sets.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Experiment {
    pub start_time: f64,
    /// `None` = no stop time: the records cover [`MAX_DURATION_WITHOUT_STOP_TIME`].
    pub stop_time: Option<f64>,
}

impl Default for Experiment {
    fn default() -> Self {
        Experiment {
            start_time: 0.0,
            stop_time: None,
        }
    }
}

impl Experiment {
    /// Checks and builds the experiment of `fmi2SetupExperiment`.
    pub fn new(start_time: f64, stop_time: Option<f64>) -> Result<Experiment> {
        if !start_time.is_finite() {
            return Err(Error::invalid("startTime", start_time, "must be finite"));
        }
        if let Some(stop) = stop_time {
            if !(stop.is_finite() && stop > start_time) {
                return Err(Error::invalid(
                    "stopTime",
                    stop,
                    format!("must be finite and after startTime = {start_time}"),
                ));
            }
        }
        Ok(Experiment {
            start_time,
            stop_time,
        })
    }

    /// The run's duration: stop - start, or the documented maximum.
    pub fn duration(&self) -> f64 {
        self.stop_time
            .map_or(MAX_DURATION_WITHOUT_STOP_TIME, |stop| {
                stop - self.start_time
            })
    }
}

/// The local path of a `file:` URI in any form masters send: `file:///abs/path`,
/// `file://localhost/abs/path`, `file:/abs/path`, with or without a trailing slash, with
/// percent escapes (`%20`). `None` for other schemes, remote hosts, bad escapes or
/// non-UTF-8 results.
pub fn file_uri_to_path(uri: &str) -> Option<PathBuf> {
    let rest = uri.strip_prefix("file:")?;
    let path = match rest.strip_prefix("//") {
        Some(authority_and_path) => {
            let slash = authority_and_path.find('/')?;
            let host = &authority_and_path[..slash];
            if !(host.is_empty() || host.eq_ignore_ascii_case("localhost")) {
                return None;
            }
            &authority_and_path[slash..]
        }
        None => rest,
    };
    if !path.starts_with('/') {
        return None;
    }
    Some(PathBuf::from(percent_decode(path)?))
}

/// Decodes `%XX` escapes; `None` on a malformed escape or a result that is not UTF-8.
fn percent_decode(s: &str) -> Option<String> {
    let bytes = s.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            let hex = s.get(i + 1..i + 3)?;
            if !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
                return None;
            }
            out.push(u8::from_str_radix(hex, 16).ok()?);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8(out).ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model_description::{Causality, VariableType, VARIABLES};
    use crate::problem::{resolve, Hydro, Problem};
    use std::sync::OnceLock;

    /// The embedded default's hydrodynamics, resolved once (the column solver takes a second).
    fn default_hydro() -> &'static Hydro {
        static HYDRO: OnceLock<Hydro> = OnceLock::new();
        HYDRO.get_or_init(|| {
            resolve(&default::default_scenario().unwrap())
                .unwrap()
                .hydro
        })
    }

    /// The checked problem of `p` on the embedded default (the resolved hydrodynamics shared).
    fn problem(p: &Parameters, experiment: &Experiment) -> Result<Problem> {
        let problem = p
            .to_scenario(None, experiment)?
            .with_hydro(default_hydro().clone());
        problem.check()?;
        Ok(problem)
    }

    #[test]
    fn every_uri_form_masters_send() {
        let expected = Path::new("/tmp/fmu x/resources");
        for uri in [
            "file:///tmp/fmu%20x/resources",
            "file:///tmp/fmu%20x/resources/",
            "file://localhost/tmp/fmu%20x/resources",
            "file:/tmp/fmu%20x/resources",
            "file:/tmp/fmu x/resources/",
            "file:///tmp/fmu%20%78/resources",
        ] {
            let path = file_uri_to_path(uri).unwrap_or_else(|| panic!("{uri}"));
            // A trailing slash names the same directory.
            assert_eq!(
                path.components().collect::<Vec<_>>(),
                expected.components().collect::<Vec<_>>(),
                "{uri}"
            );
        }
    }

    #[test]
    fn other_uris_are_refused() {
        for uri in [
            "http://host/resources",
            "file://remote/resources",
            "file:relative/resources",
            "file:///bad%2",
            "file:///bad%zz",
            "file:///bad%+1",
            "file:///not-utf8%ff",
            "/plain/path",
            "",
        ] {
            assert_eq!(file_uri_to_path(uri), None, "{uri}");
        }
    }

    /// Every parameter of the model description has a field here, of its type.
    #[test]
    fn every_parameter_has_a_field() {
        let mut p = Parameters::default();
        for v in VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Parameter)
        {
            let found = match v.var_type.access_type() {
                VariableType::Real => p.real_mut(v.value_reference).is_some(),
                VariableType::Integer => p.integer_mut(v.value_reference).is_some(),
                VariableType::String => p.string_mut(v.value_reference).is_some(),
                _ => false,
            };
            assert!(found, "{}", v.name);
        }
    }

    #[test]
    fn start_values_give_the_default_configuration() {
        let experiment = Experiment::new(0.0, Some(10800.0)).unwrap();
        let scenario = Parameters::default()
            .to_scenario(None, &experiment)
            .unwrap();
        assert_eq!(scenario, default::default_scenario().unwrap());
    }

    #[test]
    fn overrides_and_their_errors() {
        let experiment = Experiment::new(5.0, None).unwrap();
        let p = Parameters {
            spreading_exponent: 4.0,
            n_directions: 7,
            drag_model: 1,
            drift_damping: 0,
            gamma: 2.5,
            ..Parameters::default()
        };
        let c = problem(&p, &experiment).unwrap();
        assert_eq!(c.sea.spreading, Spreading::CosN { n: 4.0 });
        assert_eq!(c.sea.n_directions, 7);
        assert_eq!(
            c.model.drag,
            DragModel::Separate {
                slow: 0.6,
                fast: 0.6
            }
        );
        assert_eq!(c.model.drift_damping, DriftDamping::Off);
        assert_eq!(
            c.sea.spectrum,
            Spectrum::Jonswap {
                hs: 7.0,
                tp: 12.0,
                gamma: Some(2.5)
            }
        );
        assert_eq!(
            (c.run.start_time, c.run.duration),
            (5.0, MAX_DURATION_WITHOUT_STOP_TIME)
        );
        let bad = [
            (
                Parameters {
                    hs: -1.0,
                    ..Parameters::default()
                },
                "hs",
            ),
            (
                Parameters {
                    n_directions: 0,
                    ..Parameters::default()
                },
                "nDirections",
            ),
            (
                Parameters {
                    seed: -3,
                    ..Parameters::default()
                },
                "seed",
            ),
            (
                Parameters {
                    drag_model: 3,
                    ..Parameters::default()
                },
                "dragModel",
            ),
            (
                Parameters {
                    drift_damping: -1,
                    ..Parameters::default()
                },
                "driftDamping",
            ),
            (
                Parameters {
                    interaction: 5,
                    ..Parameters::default()
                },
                "interaction",
            ),
            (
                Parameters {
                    yaw_following_headings: 1,
                    ..Parameters::default()
                },
                "yawFollowingHeadings",
            ),
            (
                Parameters {
                    hydro_database: "/no/such/file.toml".into(),
                    ..Parameters::default()
                },
                "/no/such/file.toml",
            ),
            (
                Parameters {
                    hydro_database: "file://remote/x.toml".into(),
                    ..Parameters::default()
                },
                "hydroDatabase",
            ),
        ];
        for (p, field) in bad {
            let message = problem(&p, &experiment).unwrap_err().to_string();
            assert!(message.contains(field), "{message} should name {field}");
        }
    }

    /// `interaction` and `yawFollowingHeadings` keep the configuration's choice at 0 (their
    /// start value) and override it otherwise; `for_config` finds the parameters back.
    #[test]
    fn interaction_and_yaw_following() {
        let experiment = Experiment::new(0.0, Some(3600.0)).unwrap();
        let base = problem(&Parameters::default(), &experiment).unwrap();
        assert_eq!(base.model.interaction, Interaction::Auto);
        assert_eq!(base.model.yaw_following, None);
        let mut from_file = base.clone();
        from_file.model.interaction = Interaction::None;
        from_file.model.yaw_following = Some(YawFollowing {
            headings: 12,
            range: None,
        });
        let kept = Parameters::default()
            .apply(from_file.clone(), &experiment)
            .unwrap();
        assert_eq!(kept.model, from_file.model);
        let p = Parameters {
            interaction: 3,
            yaw_following_headings: 5,
            yaw_following_range: 0.4,
            ..Parameters::default()
        };
        let c = p.apply(from_file.clone(), &experiment).unwrap();
        assert_eq!(c.model.interaction, Interaction::MeanDirection);
        assert_eq!(
            c.model.yaw_following,
            Some(YawFollowing {
                headings: 5,
                range: Some((-0.4, 0.4))
            })
        );
        let off = Parameters {
            yaw_following_headings: -1,
            ..Parameters::default()
        };
        assert_eq!(
            off.apply(from_file, &experiment)
                .unwrap()
                .model
                .yaw_following,
            None
        );
        // for_config: the parameters that make the default platform run `c`.
        let (found, _) = Parameters::for_config(&c, &base, "").unwrap();
        assert_eq!(
            (
                found.interaction,
                found.yaw_following_headings,
                found.yaw_following_range
            ),
            (3, 5, 0.4)
        );
        let mut lopsided = c.clone();
        lopsided.model.yaw_following = Some(YawFollowing {
            headings: 5,
            range: Some((-0.2, 0.4)),
        });
        let why = Parameters::for_config(&lopsided, &base, "").unwrap_err();
        assert!(why.contains("symmetric"), "{why}");
    }

    #[test]
    fn experiment_checks() {
        assert!(Experiment::new(f64::NAN, None).is_err());
        assert!(Experiment::new(0.0, Some(0.0)).is_err());
        assert!(Experiment::new(0.0, Some(f64::INFINITY)).is_err());
        assert_eq!(Experiment::new(10.0, Some(70.0)).unwrap().duration(), 60.0);
    }

    /// The FMU's start values (modelDescription.xml) describe the same default as this file.
    #[test]
    fn model_description_start_values_match_the_default() {
        use crate::model::{DragModel, DriftDamping};
        use crate::model_description::start;
        use crate::sea_state::{Spectrum, Spreading};
        let c = default::default_scenario().unwrap();
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
}
