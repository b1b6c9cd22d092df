//! Directional spreading and its discretisation into N_beta directions
//! (E&S 11; DNV-RP-C205 sec. 3.5.8; docs/theory.md#sea-state).

use crate::error::{require_positive, Result};
use serde::Serialize;
use std::f64::consts::PI;

/// Number of Simpson panels used to integrate the spreading function over one cell.
const SIMPSON_PANELS_PER_CELL: usize = 256;

/// Directional spreading function D(beta - beta_0).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum Spreading {
    /// One direction: the mean direction (the N -> infinity limit).
    LongCrested,
    /// The paper's form (E&S 11): D = C_N cos^N(beta - beta_0) on |beta - beta_0| <= 90 deg.
    CosN { n: f64 },
    /// DNV's cos-2s form: D = C_s cos^(2s)((beta - beta_0)/2), restricted to +-90 deg and
    /// renormalised there, like every spreading here.
    Cos2s { s: f64 },
}

/// One discrete direction of propagation and the fraction of the variance it carries.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Direction {
    /// Direction of propagation, rad from +X, counter-clockwise.
    pub heading: f64,
    /// Fraction of the total variance (the weights of all directions sum to 1).
    pub weight: f64,
}

impl Spreading {
    /// Checks the exponent.
    pub fn validate(&self) -> Result<()> {
        match self {
            Spreading::LongCrested => Ok(()),
            Spreading::CosN { n } => require_positive("sea.spreading_exponent", *n),
            Spreading::Cos2s { s } => require_positive("sea.spreading_exponent", *s),
        }
    }

    /// Unnormalised shape of D at angle `rel` from the mean direction, |rel| <= pi/2.
    fn shape(&self, rel: f64) -> f64 {
        match self {
            // Never integrated: `discretise` returns the single mean direction first.
            Spreading::LongCrested => 1.0,
            Spreading::CosN { n } => rel.cos().max(0.0).powf(*n),
            Spreading::Cos2s { s } => (0.5 * rel).cos().powf(2.0 * s),
        }
    }

    /// Splits +-90 deg about `mean` into `count` equal cells; each direction sits at its
    /// cell centre with weight = integral of D over the cell (Simpson), renormalised so the
    /// weights sum to 1 (so the total variance is preserved exactly).
    pub fn discretise(&self, mean: f64, count: usize) -> Vec<Direction> {
        if matches!(self, Spreading::LongCrested) || count <= 1 {
            return vec![Direction {
                heading: mean,
                weight: 1.0,
            }];
        }
        let width = PI / count as f64;
        let raw: Vec<f64> = (0..count)
            .map(|k| {
                let lo = -0.5 * PI + k as f64 * width;
                simpson(|x| self.shape(x), lo, lo + width, SIMPSON_PANELS_PER_CELL)
            })
            .collect();
        let total: f64 = raw.iter().sum();
        raw.iter()
            .enumerate()
            .map(|(k, w)| Direction {
                heading: mean - 0.5 * PI + (k as f64 + 0.5) * width,
                weight: w / total,
            })
            .collect()
    }
}

/// Composite Simpson rule with an even number of panels.
fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, panels: usize) -> f64 {
    let h = (b - a) / panels as f64;
    let inner: f64 = (1..panels)
        .map(|i| {
            let factor = if i % 2 == 1 { 4.0 } else { 2.0 };
            factor * f(a + i as f64 * h)
        })
        .sum();
    (f(a) + inner + f(b)) * h / 3.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cos2_weights_match_the_closed_form_cell_integrals() {
        // integral of (2/pi) cos^2 t dt = (2/pi)(t/2 + sin(2t)/4)
        let antiderivative = |t: f64| (2.0 / PI) * (t / 2.0 + (2.0 * t).sin() / 4.0);
        let dirs = Spreading::CosN { n: 2.0 }.discretise(0.3, 7);
        let width = PI / 7.0;
        for d in &dirs {
            let rel = d.heading - 0.3;
            let exact = antiderivative(rel + width / 2.0) - antiderivative(rel - width / 2.0);
            assert!(
                (d.weight - exact).abs() < 1e-12,
                "{} vs {}",
                d.weight,
                exact
            );
        }
        let total: f64 = dirs.iter().map(|d| d.weight).sum();
        assert!((total - 1.0).abs() < 1e-14);
    }

    #[test]
    fn directions_are_symmetric_about_the_mean() {
        let dirs = Spreading::Cos2s { s: 5.0 }.discretise(1.0, 9);
        for k in 0..9 {
            let (a, b) = (dirs[k], dirs[8 - k]);
            assert!((a.heading - 1.0 + (b.heading - 1.0)).abs() < 1e-14);
            assert!((a.weight - b.weight).abs() < 1e-14);
        }
        assert!((dirs[4].heading - 1.0).abs() < 1e-14);
    }

    #[test]
    fn long_crested_is_one_direction() {
        assert_eq!(
            Spreading::LongCrested.discretise(0.5, 15),
            vec![Direction {
                heading: 0.5,
                weight: 1.0
            }]
        );
    }
}
