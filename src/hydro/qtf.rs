//! The full difference-frequency QTF in memory, per unit wave amplitude squared:
//! T(w_i, w_j) for one DOF at one uni-directional heading, with
//! F(t) = Re sum_i sum_j a_i a_j* T(w_i, w_j) e^{i (w_i - w_j) t}
//! (docs/theory.md#the-slowly-varying-force; the
//! crate's convention e^{i omega t}). Surge and sway in N/m^2, yaw in N m/m^2, body frame.
//! The database stores it as real and imaginary parts (`hydro::io::database`).

use super::heading_grid::heading_bracket;
use crate::error::{Error, Result};
use crate::model::{Dof, FREQUENCY_MATCH_TOLERANCE, HEADING_MATCH_TOLERANCE};
use rustfft::num_complex::Complex64;
use serde::Serialize;
use std::f64::consts::PI;

/// A QTF on its frequency grid: one block per (DOF, heading).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Qtf {
    /// Frequencies, rad/s, strictly increasing.
    pub omegas: Vec<f64>,
    pub blocks: Vec<QtfBlock>,
}

/// T(w_i, w_j; beta1, beta2) of one DOF for one heading pair: uni-directional when
/// beta1 = beta2, else the bi-directional QTF of waves at w_i from beta1 and at w_j from
/// beta2, F(t) = Re sum_{i,k} sum_{j,l} a_ik a_jl* T(w_i, w_j; b_k, b_l) e^{i (w_i - w_j) t}
/// (docs/theory.md#the-slowly-varying-force).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct QtfBlock {
    pub dof: Dof,
    /// Heading beta1 of the waves at w_i, relative to the body x axis, rad.
    pub heading: f64,
    /// Heading beta2 of the waves at w_j, rad (equal to `heading`: uni-directional).
    pub second_heading: f64,
    /// Row-major n x n values, `[i * n + j]` = T(w_i, w_j).
    #[serde(serialize_with = "re_im_pairs")]
    pub values: Vec<Complex64>,
}

/// Complex values as [re, im] pairs.
fn re_im_pairs<S: serde::Serializer>(
    values: &[Complex64],
    out: S,
) -> std::result::Result<S::Ok, S::Error> {
    use serde::ser::SerializeSeq;
    let mut seq = out.serialize_seq(Some(values.len()))?;
    for z in values {
        seq.serialize_element(&[z.re, z.im])?;
    }
    seq.end()
}

impl QtfBlock {
    /// Whether the block is uni-directional (beta1 = beta2).
    pub fn is_unidirectional(&self) -> bool {
        self.heading == self.second_heading
    }
}

/// a - b brought into [-pi, pi).
fn apart(a: f64, b: f64) -> f64 {
    (a - b + PI).rem_euclid(2.0 * PI) - PI
}

impl Qtf {
    /// The uni-directional block of `dof` at `heading` (rad, within `tolerance`, modulo
    /// 2 pi), if any.
    pub fn block(&self, dof: Dof, heading: f64, tolerance: f64) -> Option<&QtfBlock> {
        self.pair_block(dof, (heading, heading), tolerance)
    }

    /// The block of `dof` for the heading pair (beta1, beta2) (rad, each within
    /// `tolerance`, modulo 2 pi), if any.
    pub fn pair_block(&self, dof: Dof, headings: (f64, f64), tolerance: f64) -> Option<&QtfBlock> {
        self.blocks.iter().find(|b| {
            b.dof == dof
                && apart(b.heading, headings.0).abs() <= tolerance
                && apart(b.second_heading, headings.1).abs() <= tolerance
        })
    }

    /// Whether the QTF has bi-directional blocks (beta1 != beta2).
    pub fn is_bidirectional(&self) -> bool {
        self.blocks.iter().any(|b| !b.is_unidirectional())
    }

    /// T(w_i, w_j; beta1, beta2) of `dof` on the QTF's own grid (n x n, row-major) for
    /// headings that need not be data headings: bilinear in the heading pair between the
    /// data headings (those of the uni-directional blocks, wrapping around only when they
    /// cover the circle), never extrapolated:
    ///   T(b1, b2) = sum_{p, q} w_p(b1) w_q(b2) T(H_p, H_q),
    /// w the linear weights of the two data headings around each. With uni-directional data
    /// only, b1 = b2 is interpolated along the diagonal, (1 - f) T(H_p, H_p) + f T(H_p+1,
    /// H_p+1), and b1 != b2 is refused; bilinear weights are the same for (b1, b2) and
    /// (b2, b1), so a Hermitian QTF stays Hermitian in (w, beta). A heading within
    /// [`HEADING_MATCH_TOLERANCE`] of a data heading is that heading (its block, bit for
    /// bit). Errors name the heading and what the data cover.
    pub fn interpolated(&self, dof: Dof, headings: (f64, f64)) -> Result<Vec<Complex64>> {
        let nodes = self.sorted_headings();
        if nodes.is_empty() {
            return Err(Error::invalid(
                "qtf.blocks",
                "no uni-directional block",
                "interpolating in heading needs the QTF at its data headings (blocks with \
                 beta1 = beta2)",
            ));
        }
        let weights = |b: f64| -> Result<Vec<(f64, f64)>> {
            if let Some(&h) = nodes
                .iter()
                .find(|&&h| apart(h, b).abs() <= HEADING_MATCH_TOLERANCE)
            {
                return Ok(vec![(h, 1.0)]);
            }
            let bracket = heading_bracket(&nodes, b).ok_or_else(|| {
                Error::invalid(
                    "qtf.headings",
                    format!("{:.3} deg", b.to_degrees()),
                    format!(
                        "a wave direction outside the QTF's headings {} deg (nothing is \
                         extrapolated in heading)",
                        nodes
                            .iter()
                            .map(|h| format!("{:.3}", h.to_degrees()))
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                )
            })?;
            Ok([
                (nodes[bracket.lo], 1.0 - bracket.frac),
                (nodes[bracket.hi], bracket.frac),
            ]
            .into_iter()
            .filter(|(_, w)| *w != 0.0)
            .collect())
        };
        let (first, second) = (weights(headings.0)?, weights(headings.1)?);
        let corners: Vec<((f64, f64), f64)> = if self.is_bidirectional() {
            first
                .iter()
                .flat_map(|&(p, wp)| second.iter().map(move |&(q, wq)| ((p, q), wp * wq)))
                .collect()
        } else if first == second {
            first.iter().map(|&(p, w)| ((p, p), w)).collect()
        } else {
            return Err(Error::invalid(
                "qtf.blocks",
                format!(
                    "({:.3}, {:.3}) deg",
                    headings.0.to_degrees(),
                    headings.1.to_degrees()
                ),
                "a pair of different headings needs a bi-directional QTF (blocks with \
                 second_heading); this QTF is uni-directional",
            ));
        };
        let n = self.omegas.len();
        let mut out = vec![Complex64::default(); n * n];
        for ((p, q), w) in corners {
            let block = self.pair_block(dof, (p, q), 1e-12).ok_or_else(|| {
                Error::invalid(
                    "qtf.blocks",
                    format!(
                        "{} at ({:.3}, {:.3}) deg",
                        dof.name(),
                        p.to_degrees(),
                        q.to_degrees()
                    ),
                    "missing: interpolating in heading needs every pair of the data headings \
                     around the wave directions",
                )
            })?;
            if w == 1.0 {
                out.copy_from_slice(&block.values);
            } else {
                for (o, v) in out.iter_mut().zip(&block.values) {
                    *o += w * v;
                }
            }
        }
        Ok(out)
    }

    /// The distinct headings of the uni-directional blocks, rad, increasing.
    fn sorted_headings(&self) -> Vec<f64> {
        let mut headings = self.headings();
        headings.sort_by(f64::total_cmp);
        headings
    }

    /// Checks the frequencies (positive, strictly increasing) and every block's size and
    /// finiteness.
    pub fn validate(&self) -> Result<()> {
        let n = self.omegas.len();
        for (k, w) in self.omegas.iter().enumerate() {
            if !(w.is_finite() && *w > 0.0) || (k > 0 && *w <= self.omegas[k - 1]) {
                return Err(Error::invalid(
                    format!("qtf.omegas[{k}]"),
                    w,
                    "frequencies must be positive and strictly increasing",
                ));
            }
        }
        for (k, b) in self.blocks.iter().enumerate() {
            if b.values.len() != n * n {
                return Err(Error::invalid(
                    format!("qtf.blocks[{k}]"),
                    format!("{} values", b.values.len()),
                    format!("must be {n} x {n} (one row and column per frequency)"),
                ));
            }
            if !b.heading.is_finite()
                || !b.second_heading.is_finite()
                || b.values
                    .iter()
                    .any(|z| !(z.re.is_finite() && z.im.is_finite()))
            {
                return Err(Error::invalid(
                    format!("qtf.blocks[{k}]"),
                    "NaN or infinity",
                    "must be finite",
                ));
            }
        }
        Ok(())
    }

    /// The distinct headings of the uni-directional blocks, rad, in the order they first
    /// appear.
    pub fn headings(&self) -> Vec<f64> {
        let mut headings: Vec<f64> = Vec::new();
        for b in self.blocks.iter().filter(|b| b.is_unidirectional()) {
            if !headings.contains(&b.heading) {
                headings.push(b.heading);
            }
        }
        headings
    }
}

/// Smallest accepted truncation tolerance: below it the discarded eigenvalues are the
/// round-off of the decomposition itself (about n * 1e-16 of the largest).
pub const MIN_QTF_TOLERANCE: f64 = 1e-12;

/// Refuses a tolerance outside [[`MIN_QTF_TOLERANCE`], 1).
pub fn check_tolerance(tolerance: f64) -> Result<()> {
    if (MIN_QTF_TOLERANCE..1.0).contains(&tolerance) {
        Ok(())
    } else {
        Err(Error::invalid(
            "model.qtf_tolerance",
            tolerance,
            format!(
                "must be at least {MIN_QTF_TOLERANCE} (below it the discarded eigenvalues are \
                 round-off) and below 1"
            ),
        ))
    }
}

/// Refuses a QTF grid that does not cover `band` (rad/s) within
/// [`FREQUENCY_MATCH_TOLERANCE`], naming the gap.
pub fn check_covers(omegas: &[f64], band: (f64, f64)) -> Result<()> {
    let (low, high) = (omegas[0], omegas[omegas.len() - 1]);
    let mut gaps = Vec::new();
    if band.0 < low * (1.0 - FREQUENCY_MATCH_TOLERANCE) {
        gaps.push(format!("{:.4} .. {low:.4} rad/s", band.0));
    }
    if band.1 > high * (1.0 + FREQUENCY_MATCH_TOLERANCE) {
        gaps.push(format!("{high:.4} .. {:.4} rad/s", band.1));
    }
    if gaps.is_empty() {
        return Ok(());
    }
    Err(Error::invalid(
        "qtf.omegas",
        format!("[{low:.4}, {high:.4}] rad/s"),
        format!(
            "the QTF does not cover the wave band [{:.4}, {:.4}] rad/s: no data for {} \
             (nothing is extrapolated; narrow [sea] band or supply QTF data there)",
            band.0,
            band.1,
            gaps.join(" and ")
        ),
    ))
}
