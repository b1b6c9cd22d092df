//! What a run uses and where each part comes from: one line per choice that matters (the
//! data, the masses, the stiffness and the natural periods it gives, the damping, the
//! drag, the wind), printed by `slowdrift simulate` and `montecarlo` before they run and logged by
//! the FMU at initialisation. Values in SI units, four significant digits.

use super::{Inertia, Origin, Problem};
use crate::error::numbers::{readable, written};
use crate::error::Result;
use crate::model::{DragModel, DriftDamping, Mode, WaveFrequencyMotion, WindSpectrumKind};

/// The band over which the wind line gives the turbulence intensity the gust spectrum
/// implies, Hz: from a period of about 3 hours to 1 s, the slow drift's and well beyond.
const WIND_BAND: (f64, f64) = (1e-4, 1.0);

/// The DOFs' names in the lines, with the units of a stiffness and a mass of each.
const DOFS: [(&str, &str, &str); 3] = [
    ("surge", "N/m", "kg"),
    ("sway", "N/m", "kg"),
    ("yaw", "N m/rad", "kg m^2"),
];

/// A value with four significant digits, as `1.264e7`.
fn value(x: f64) -> String {
    if x == 0.0 {
        "0".to_string()
    } else {
        format!("{x:.3e}")
    }
}

impl Problem {
    /// The lines of the run's summary (module doc); the error of a problem without a mass
    /// ([`Problem::inertia`]).
    pub fn summary(&self) -> Result<Vec<String>> {
        let inertia = self.inertia()?;
        let mut lines = vec![format!("data: {}", self.hydro.source)];
        lines.extend(mass_lines(&inertia));
        lines.extend(self.stiffness_lines(&inertia));
        lines.push(self.damping_line());
        lines.push(self.drag_line());
        lines.push(self.wind_line()?);
        lines.push(self.motions_line()?);
        lines.extend(inertia.notes.iter().cloned());
        Ok(lines)
    }

    /// The stiffness, and the natural periods it gives with the mass, or what restores a
    /// DOF without it (nothing inside: an external mooring must).
    fn stiffness_lines(&self, inertia: &Inertia) -> Vec<String> {
        let c = &self.platform.stiffness;
        let diagonal: Vec<String> = DOFS
            .iter()
            .enumerate()
            .map(|(i, (dof, unit, _))| format!("{dof} {} {unit}", value(c[i][i])))
            .collect();
        let coupled = (0..3).any(|i| (0..3).any(|j| i != j && c[i][j] != 0.0));
        let mut lines = vec![format!(
            "stiffness {}{} ([platform] stiffness)",
            diagonal.join(", "),
            if coupled {
                ", with off-diagonal terms"
            } else {
                ""
            }
        )];
        let periods = inertia.uncoupled_periods(c);
        let mut known = Vec::new();
        let mut free = Vec::new();
        for ((dof, _, _), period) in DOFS.iter().zip(periods) {
            match period {
                Some(t) => known.push(format!("{dof} {t:.1} s")),
                None => free.push(*dof),
            }
        }
        if !known.is_empty() {
            lines.push(format!(
                "natural periods {} (uncoupled: 2 pi sqrt((M + A)_ii / C_ii))",
                known.join(", ")
            ));
        }
        if !free.is_empty() {
            lines.push(format!(
                "no stiffness in {}: nothing inside restores the platform there (an external \
                 mooring must, through the external force)",
                free.join(", ")
            ));
        }
        lines
    }

    fn damping_line(&self) -> String {
        let p = &self.platform;
        let wave_drift = match self.model.drift_damping {
            DriftDamping::Aranha => "Aranha's formula from the drift table",
            DriftDamping::Table => "the drift table's b_ij",
            DriftDamping::Off => DriftDamping::Off.word(),
        };
        let nonzero = |m: &[[f64; 3]; 3]| m.iter().flatten().any(|v| *v != 0.0);
        let extra = match (nonzero(&p.linear_damping), nonzero(&p.quadratic_damping)) {
            (false, false) => "none",
            (true, false) => "linear ([platform] linear_damping)",
            (false, true) => "quadratic ([platform] quadratic_damping)",
            (true, true) => "linear and quadratic ([platform])",
        };
        format!("wave-drift damping: {wave_drift}; extra damping: {extra}")
    }

    /// The first-order motions (`problem::motions`): where the RAOs come from and the
    /// natural periods they have, or why there are none.
    fn motions_line(&self) -> Result<String> {
        let motions = self.motions_source_line()?;
        Ok(match (self.model.wave_frequency_motion, motions.1) {
            (WaveFrequencyMotion::Off, true) => format!(
                "{}; wave-frequency motion: off ([model] wave_frequency_motion), the totals are \
                 the slow drift",
                motions.0
            ),
            (_, true) => format!(
                "{}; wave-frequency motion: on (outputs *_wf and *_total; the slow-drift \
                 equations do not use it){}",
                motions.0,
                self.first_order_motions()?
                    .map(|m| self.rao_gap(&m.rao))
                    .filter(|(share, _)| *share > 0.0)
                    .map(|(share, (lo, hi))| format!(
                        "; the RAOs span {lo} to {hi} rad/s, the band outside ({:.2} % of its \
                         variance) moves the body not at all",
                        share * 100.0
                    ))
                    .unwrap_or_default()
            ),
            (_, false) => motions.0,
        })
    }

    /// [`Problem::motions_line`]'s first part, and whether there are RAOs.
    fn motions_source_line(&self) -> Result<(String, bool)> {
        let has = |line: String| (line, true);
        let none = |line: String| (line, false);
        Ok(match self.first_order_motions()? {
            Some(motions) => {
                let periods: Vec<String> = motions
                    .natural_periods
                    .iter()
                    .map(|(dof, t)| format!("{dof} {t:.1} s"))
                    .collect();
                has(format!(
                    "first-order motions: RAOs {}{}",
                    motions.source,
                    if periods.is_empty() {
                        String::new()
                    } else {
                        format!(
                            "; natural periods {} (uncoupled, with A(omega_n))",
                            periods.join(", ")
                        )
                    }
                ))
            }
            None if self.hydro.body.first_order.is_some() => none(format!(
                "first-order motions: none ({} has first-order coefficients: give [platform.motions] for its RAOs)",
                self.hydro.body.name
            )),
            None => none(
                "first-order motions: none (the data have no first-order coefficients or RAOs)"
                    .to_string(),
            ),
        })
    }

    /// The wind (`[wind]`): none when calm; the input's when the speed is the FMU's input;
    /// else the speed as given (its averaging period,
    /// height and direction), the profile and the spectrum, and at the height of the wind
    /// force (`[platform.wind]`, its form) the mean the gusts fluctuate about (over the
    /// spectrum's averaging period) with the standard deviation and turbulence intensity
    /// (sigma / that mean) of the gust spectrum over [`WIND_BAND`].
    fn wind_line(&self) -> Result<String> {
        let wind = &self.wind;
        let Some(run) = self.run_wind()? else {
            return Ok("wind: none".to_string());
        };
        let z = run.height;
        let form = match self.platform.wind.as_ref().map(|w| &w.coefficients) {
            Some(crate::wind::WindCoefficients::Areas(areas)) => {
                let n = areas.len();
                format!(
                    "{n} projected area{} (API RP 2SK)",
                    if n == 1 { "" } else { "s" }
                )
            }
            _ => "coefficients against the relative angle".to_string(),
        };
        let Some(gusts) = run.gusts else {
            return Ok(format!(
                "wind: the FMU's input windVelocity_ext, the speed at the force's height {} m \
                 (0 m/s outside an FMU: still air), towards {} deg; on {form} ([platform.wind])",
                written(z),
                readable(wind.direction.to_degrees()),
            ));
        };
        let mean = gusts.mean;
        let gust_words = match wind.spectrum {
            WindSpectrumKind::Constant => "no gusts".to_string(),
            _ => {
                let sigma = gusts.spectrum.variance(WIND_BAND.0, WIND_BAND.1)?.sqrt();
                format!(
                    "turbulence intensity {:.3} (sigma {sigma:.2} m/s over {} to {} Hz)",
                    sigma / mean,
                    written(WIND_BAND.0),
                    written(WIND_BAND.1)
                )
            }
        };
        Ok(format!(
            "wind: {} m/s, the {} s mean at {} m, towards {} deg; profile {}, spectrum {}; at \
             the force's height {} m the {} s mean {mean:.2} m/s, {gust_words}; on {form} \
             ([platform.wind])",
            written(wind.speed),
            written(wind.averaging_period),
            written(wind.reference_height),
            readable(wind.direction.to_degrees()),
            wind.profile.kind().word(),
            wind.spectrum.word(),
            written(z),
            written(wind.spectrum_period()),
        ))
    }

    fn drag_line(&self) -> String {
        let strips = format!(
            "{} strips on each of {} columns",
            self.model.strips_per_column,
            self.platform.columns.len()
        );
        match self.model.drag {
            DragModel::Off => "drag: off".to_string(),
            DragModel::Combined { cd } => {
                format!("drag: combined (E&S 9), cd {}, {strips}", written(cd))
            }
            DragModel::Separate { slow, fast } => format!(
                "drag: separate (E&S 8), cd_slow {}, cd_fast {}, {strips}",
                written(slow),
                written(fast)
            ),
        }
    }
}

/// The mass and yaw inertia (one line when they come from the same place) and the added
/// mass, each with where it came from.
fn mass_lines(inertia: &Inertia) -> Vec<String> {
    let mass = format!("mass {} kg", value(inertia.mass));
    let yaw = format!("yaw inertia {} kg m^2", value(inertia.yaw_inertia));
    let mut lines = if inertia.mass_origin == inertia.yaw_inertia_origin {
        vec![format!("{mass}, {yaw} ({})", inertia.mass_origin)]
    } else {
        vec![
            format!("{mass} ({})", inertia.mass_origin),
            format!("{yaw} ({})", inertia.yaw_inertia_origin),
        ]
    };
    let a = &inertia.added_mass;
    let added = match inertia.added_mass_origin {
        Origin::Zero => "added mass 0".to_string(),
        _ => {
            let diagonal: Vec<String> = DOFS
                .iter()
                .enumerate()
                .map(|(i, (dof, _, unit))| format!("{dof} {} {unit}", value(a[i][i])))
                .collect();
            format!("added mass {}", diagonal.join(", "))
        }
    };
    lines.push(format!("{added} ({})", inertia.added_mass_origin));
    lines
}

#[cfg(test)]
mod tests {
    use crate::problem::resolve;
    use crate::scenario::file::parse;
    use crate::wind::GustSpectrum;
    use crate::Problem;
    use std::path::Path;

    const MINIMAL: &str = include_str!("../../tests/data/minimal.toml");

    /// MINIMAL with a `[wind]` section of `keys`, resolved.
    /// MINIMAL with `[wind]` `keys` on one projected area whose height, `force_height`, is
    /// the force's.
    fn with_wind(keys: &str, force_height: f64) -> Problem {
        let area = format!(
            "[platform.wind]\nheight = {force_height}\n[[platform.wind.areas]]\nx = 0.0\n\
             y = 0.0\nheight = {force_height}\narea_x = 100.0\narea_y = 100.0\n\
             shape_coefficient = 1.0\n\n"
        );
        let text = MINIMAL.replace("[drift]", &format!("[wind]\n{keys}\n\n{area}[drift]"));
        let problem = resolve(&parse(&text, "test.toml", Path::new(".")).unwrap()).unwrap();
        problem.check().unwrap();
        problem
    }

    /// The summary's line that starts with "wind:".
    fn wind_line(problem: &Problem) -> String {
        let lines = problem.summary().unwrap();
        let wind: Vec<&String> = lines.iter().filter(|l| l.starts_with("wind:")).collect();
        assert_eq!(wind.len(), 1, "{lines:?}");
        wind[0].clone()
    }

    /// No wind is one line saying so.
    #[test]
    fn calm_is_no_wind() {
        let problem = with_wind("", 10.0);
        assert_eq!(wind_line(&problem), "wind: none");
        let problem = with_wind("speed = 0\nspectrum = \"kaimal\"", 10.0);
        assert_eq!(wind_line(&problem), "wind: none");
    }

    /// The NPD wind: the speed as given, and at the reference height its 1-hour mean with
    /// the intensity the spectrum implies over 1e-4 to 1 Hz: sigma from the spectrum's
    /// band variance (7.0992 m^2/s^2 over all frequencies at 20 m/s and 10 m, I = 0.133,
    /// docs/theory.md#wind; the band holds 89 %: 0.13 m^2/s^2 lie below 1e-4 Hz, where S is
    /// about S(0) = 1280 m^2/s^2 per Hz, and 0.6 above 1 Hz in its f^-5/3 tail).
    #[test]
    fn the_wind_line_gives_the_mean_and_the_intensity_of_the_spectrum() {
        let problem = with_wind("speed = 20.0\ndirection_deg = 30.0", 10.0);
        let line = wind_line(&problem);
        let npd = GustSpectrum::Npd {
            speed: 20.0,
            height: 10.0,
        };
        let sigma = npd.variance(1e-4, 1.0).unwrap().sqrt();
        assert!(
            sigma * sigma < 7.0992 - 0.6 && sigma * sigma > 7.0992 - 1.0,
            "{sigma}"
        );
        assert_eq!(
            line,
            format!(
                "wind: 20 m/s, the 3600 s mean at 10 m, towards 30 deg; profile npd, spectrum \
                 npd; at the force's height 10 m the 3600 s mean 20.00 m/s, turbulence \
                 intensity {:.3} (sigma {sigma:.2} m/s over 1e-4 to 1 Hz); on 1 projected \
                 area (API RP 2SK) ([platform.wind])",
                sigma / 20.0
            )
        );
        assert!(line.contains("turbulence intensity 0.12"), "{line}");
    }

    /// Harris from the 10-min mean at 50 m with the power law: its mean at 50 m is the speed
    /// given, and its variance 6.6776 kappa U10^2 (docs/theory.md#wind) with U10 = 20
    /// (10/50)^0.12 brought down by the power law, the intensity relative to the mean at 50 m.
    /// The constant wind has no gusts.
    #[test]
    fn the_wind_line_brings_the_spectrum_to_the_reference_height() {
        let problem = with_wind(
            "speed = 20.0\nreference_height = 50.0\naveraging_period = 600\n\
             profile = \"power-law\"\nspectrum = \"harris\"",
            50.0,
        );
        let line = wind_line(&problem);
        let u10 = 20.0 * 0.2f64.powf(0.12);
        let whole = (6.6776 * 0.002 * u10 * u10).sqrt() / 20.0;
        let shown: f64 = line
            .split("turbulence intensity ")
            .nth(1)
            .and_then(|rest| rest.split(' ').next())
            .and_then(|i| i.parse().ok())
            .unwrap_or_else(|| panic!("{line}"));
        assert!(
            shown < whole + 5e-4 && shown > 0.95 * whole,
            "{shown} vs {whole}: {line}"
        );
        assert!(
            line.starts_with(
                "wind: 20 m/s, the 600 s mean at 50 m, towards 0 deg; profile power-law, \
                 spectrum harris; at the force's height 50 m the 600 s mean 20.00 m/s, "
            ),
            "{line}"
        );
        let constant = with_wind("speed = 12.0\nspectrum = \"constant\"", 10.0);
        assert!(
            wind_line(&constant)
                .contains("at the force's height 10 m the 3600 s mean 12.00 m/s, no gusts"),
            "{}",
            wind_line(&constant)
        );
    }
}
