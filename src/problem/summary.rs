//! What a run uses and where each part comes from: one line per choice that matters (the
//! data, the masses, the stiffness and the natural periods it gives, the damping, the
//! drag), printed by `slowdrift simulate` and `montecarlo` before they run and logged by
//! the FMU at initialisation. Values in SI units, four significant digits.

use super::{Inertia, Origin, Problem};
use crate::error::numbers::written;
use crate::error::Result;
use crate::model::{DragModel, DriftDamping, Mode, WaveFrequencyMotion};

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
