//! The modelling choices: `[model]`.

use super::{chosen, refused, required};
use crate::model::YawFollowing;
use crate::model::{
    DragKind, DragModel, DriftDamping, Interaction, Mode, NewmanForm, SecondOrder,
    WaveFrequencyMotion,
};
use crate::scenario::ModelOptions;
use serde::Deserialize;

/// `[model]`; absent keys take [`ModelOptions::default`].
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ModelFile {
    second_order: Option<SecondOrder>,
    qtf_tolerance: Option<f64>,
    newman: Option<NewmanForm>,
    interaction: Option<Interaction>,
    drift_damping: Option<DriftDamping>,
    drag: Option<DragKind>,
    /// Drag coefficient of the combined model.
    cd: Option<f64>,
    /// Slow drag coefficient of the separate model.
    cd_slow: Option<f64>,
    /// Fast drag coefficient of the separate model.
    cd_fast: Option<f64>,
    strips_per_column: Option<usize>,
    yaw_following: Option<YawFollowingFile>,
    wave_frequency_motion: Option<WaveFrequencyMotion>,
}

/// `model.yaw_following`: `{ headings = n }` (the full circle) or
/// `{ headings = n, range_deg = [min, max] }`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct YawFollowingFile {
    headings: usize,
    range_deg: Option<[f64; 2]>,
}

impl ModelFile {
    pub(super) fn into_core(self) -> Result<ModelOptions, String> {
        let default = ModelOptions::default();
        let (second_order, qtf_tolerance) = match self.second_order {
            None | Some(SecondOrder::Newman) => {
                refused(
                    &self.qtf_tolerance,
                    "qtf_tolerance",
                    &format!(
                        "second_order is \"{}\" (the default)",
                        SecondOrder::Newman.word()
                    ),
                )?;
                (SecondOrder::Newman, default.qtf_tolerance)
            }
            Some(SecondOrder::FullQtf) => (
                SecondOrder::FullQtf,
                self.qtf_tolerance.unwrap_or(default.qtf_tolerance),
            ),
        };
        let drag = match self.drag {
            None => {
                let because = format!("drag is {} (the default)", DragKind::Off.word());
                self.refuse_coefficients(&[], &because)?;
                default.drag
            }
            Some(kind) => self.drag(kind)?,
        };
        Ok(ModelOptions {
            second_order,
            qtf_tolerance,
            newman: self.newman.unwrap_or(default.newman),
            interaction: self.interaction.unwrap_or(default.interaction),
            drift_damping: self.drift_damping.unwrap_or(default.drift_damping),
            drag,
            strips_per_column: self.strips_per_column.unwrap_or(default.strips_per_column),
            yaw_following: self.yaw_following.map(|y| YawFollowing {
                headings: y.headings,
                range: y
                    .range_deg
                    .map(|[min, max]| (min.to_radians(), max.to_radians())),
            }),
            wave_frequency_motion: self
                .wave_frequency_motion
                .unwrap_or(default.wave_frequency_motion),
        })
    }

    /// The drag model `kind` with its coefficients, the others refused.
    fn drag(&self, kind: DragKind) -> Result<DragModel, String> {
        let because = chosen("drag", kind);
        Ok(match kind {
            DragKind::Off => {
                self.refuse_coefficients(&[], &because)?;
                DragModel::Off
            }
            DragKind::Separate => {
                self.refuse_coefficients(&["cd_slow", "cd_fast"], &because)?;
                DragModel::Separate {
                    slow: required(self.cd_slow, "cd_slow", &because)?,
                    fast: required(self.cd_fast, "cd_fast", &because)?,
                }
            }
            DragKind::Combined => {
                self.refuse_coefficients(&["cd"], &because)?;
                DragModel::Combined {
                    cd: required(self.cd, "cd", &because)?,
                }
            }
        })
    }

    /// Refuses every drag coefficient that is given but not in `used`.
    fn refuse_coefficients(&self, used: &[&str], because: &str) -> Result<(), String> {
        for (key, value) in [
            ("cd", self.cd),
            ("cd_slow", self.cd_slow),
            ("cd_fast", self.cd_fast),
        ] {
            if !used.contains(&key) {
                refused(&value, key, because)?;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::{error_text, minimal_with, read, MINIMAL};
    use super::*;

    /// Every word of the `[model]` modes reads back as its mode.
    #[test]
    fn the_modes_read_their_words() {
        for mode in SecondOrder::ALL {
            let text = minimal_with(&format!("[model]\nsecond_order = \"{}\"", mode.word()));
            assert_eq!(read(&text).expect("a known word").model.second_order, *mode);
        }
        for mode in NewmanForm::ALL {
            let text = minimal_with(&format!("[model]\nnewman = \"{}\"", mode.word()));
            assert_eq!(read(&text).expect("a known word").model.newman, *mode);
        }
        for mode in Interaction::ALL {
            let text = minimal_with(&format!("[model]\ninteraction = \"{}\"", mode.word()));
            assert_eq!(read(&text).expect("a known word").model.interaction, *mode);
        }
        for mode in DriftDamping::ALL {
            let text = minimal_with(&format!("[model]\ndrift_damping = \"{}\"", mode.word()));
            assert_eq!(
                read(&text).expect("a known word").model.drift_damping,
                *mode
            );
        }
        let keep = Interaction::VOCABULARY
            .keep()
            .expect("interaction's keep word");
        let text = minimal_with(&format!("[model]\ninteraction = \"{keep}\""));
        assert!(
            error_text(&text).contains(&format!("unknown variant `{keep}`")),
            "the FMU's keep word is not a word of the file"
        );
    }

    #[test]
    fn drag_takes_the_coefficients_of_its_model_only() {
        let drag = |keys: &str| read(&minimal_with(&format!("[model]\n{keys}")));
        assert_eq!(
            drag("drag = \"combined\"\ncd = 0.7").unwrap().model.drag,
            DragModel::Combined { cd: 0.7 }
        );
        assert_eq!(
            drag("drag = \"separate\"\ncd_slow = 0.5\ncd_fast = 0.9")
                .unwrap()
                .model
                .drag,
            DragModel::Separate {
                slow: 0.5,
                fast: 0.9
            }
        );
        let message = |keys: &str| drag(keys).expect_err("refused").to_string();
        assert!(message("drag = \"combined\"").contains("cd is required when drag = \"combined\""));
        assert!(message("drag = \"combined\"\ncd = 0.7\ncd_slow = 0.5")
            .contains("cd_slow does not apply when drag = \"combined\""));
        assert!(
            message("drag = \"off\"\ncd = 0.7").contains("cd does not apply when drag = \"off\"")
        );
        assert!(message("cd = 0.7").contains("cd does not apply when drag is off (the default)"));
        let text = format!("{MINIMAL}\n[model]\nqtf_tolerance = 1e-4\n");
        assert!(error_text(&text).contains(
            "qtf_tolerance does not apply when second_order is \"newman\" (the default)"
        ));
    }

    #[test]
    fn yaw_following_reads_headings_and_a_range_in_degrees() {
        let with = |model: &str| minimal_with(&format!("[model]\n{model}"));
        let circle = read(&with("yaw_following = { headings = 36 }")).expect("valid");
        assert_eq!(
            circle.model.yaw_following,
            Some(YawFollowing {
                headings: 36,
                range: None
            })
        );
        let text = with("yaw_following = { headings = 13, range_deg = [-15.0, 15.0] }");
        let range = read(&text).expect("valid").model.yaw_following.unwrap();
        assert_eq!(range.range, Some((-15f64.to_radians(), 15f64.to_radians())));
        assert_eq!(read(MINIMAL).unwrap().model.yaw_following, None);
        let e = read(&with("yaw_following = { headings = 36, range = [1, 2] }"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("range"), "{e}");
    }
}
