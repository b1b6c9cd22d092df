//! Bi-directional mean drift T(omega; beta_p, beta_q): the data that couples the wave
//! components of two directions of a short-crested sea (docs/theory.md#the-slowly-varying-force;
//! E&S 3).
//!
//! Convention (as [`super::columns::BidirectionalDrift`]): two regular waves of one
//! frequency with complex amplitudes a_p, a_q (project convention Re[a e^{i omega t}], phase
//! at the body origin) and headings beta_p, beta_q give the mean force
//! F = sum_{p,q} a_p conj(a_q) T(beta_p, beta_q); T is Hermitian in the heading pair,
//! T(beta_q, beta_p) = conj T(beta_p, beta_q), and T(beta, beta) is the uni-directional
//! drift. Surge and sway in N/m^2, yaw in N m/m^2, per unit amplitude squared, body frame.
//!
//! Three sources, one per [`BidirectionalSource`] variant or [`mean_direction_pairs`]:
//! - the column-array solver, evaluated exactly at the sea's directions;
//! - a tabulated T on a frequency x heading x heading grid (the native database's optional
//!   `bidirectional_drift`), interpolated linearly in omega and bilinearly in the two
//!   headings, never extrapolated (headings wrap only when the table covers the circle);
//! - no bi-directional data: the mean-direction rule T(omega; beta_k, beta_l) ~
//!   T(omega; (beta_k + beta_l)/2) from the uni-directional drift table (real, symmetric,
//!   so Hermitian; exact for k = l).

use super::columns::ColumnArray;
use super::heading_grid::{heading_bracket, Bracket};
use super::DriftTable;
use crate::error::numbers::{written, written_complex};
use crate::error::{require_finite, require_positive, Error, Result};
use crate::model::{Environment, FREQUENCY_MATCH_TOLERANCE};
use rustfft::num_complex::Complex64;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Relative tolerance of a band limit against a data frequency it lies on.
const GRID_TOLERANCE: f64 = 1e-9;

/// Largest relative departure from T(beta_q, beta_p) = conj T(beta_p, beta_q) a table may
/// show (relative to its largest value): the solver's tables are Hermitian to round-off.
const HERMITIAN_TOLERANCE: f64 = 1e-6;

/// T(omega_n; beta_k, beta_l) for the N_beta directions of a sea, at frequencies omega_n of
/// the data (interpolated linearly onto the simulation grid by `forces::directional`).
#[derive(Debug, Clone, PartialEq)]
pub struct DirectionPairs {
    /// Data frequencies, rad/s, increasing.
    pub omegas: Vec<f64>,
    /// Number of directions N_beta.
    pub directions: usize,
    /// Index (n * directions + k) * directions + l: (surge, sway, yaw).
    pub values: Vec<[Complex64; 3]>,
}

impl DirectionPairs {
    /// T(omega_n; beta_k, beta_l).
    pub fn get(&self, n: usize, k: usize, l: usize) -> [Complex64; 3] {
        self.values[(n * self.directions + k) * self.directions + l]
    }
}

/// A tabulated bi-directional drift (the database's `bidirectional_drift`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BidirectionalTable {
    /// Frequencies, rad/s, strictly increasing.
    pub omegas: Vec<f64>,
    /// Headings, rad, strictly increasing, within one turn.
    pub headings: Vec<f64>,
    /// `re[n][p][q]` = Re T(omega_n; beta_p, beta_q) for (surge, sway, yaw).
    pub re: Vec<Vec<Vec<[f64; 3]>>>,
    /// Imaginary parts, same layout.
    pub im: Vec<Vec<Vec<[f64; 3]>>>,
}

/// Where the bi-directional drift of a configuration comes from.
#[derive(Debug, Clone, Serialize)]
pub enum BidirectionalSource {
    /// The column-array solver at the data frequencies `omegas` (those of the drift table it
    /// also made), evaluated at the sea's exact directions.
    ColumnArray {
        array: ColumnArray,
        omegas: Vec<f64>,
    },
    /// A table, interpolated.
    Table(BidirectionalTable),
    /// A table compiled into the library as JSON (`hydro::default_platform`), read when a
    /// spread sea first needs it (each [`BidirectionalSource::pairs`]); `name` says which in
    /// errors and stands for it in fingerprints (the drift table beside it, fingerprinted in
    /// full, changes whenever the data are made anew).
    Embedded {
        name: &'static str,
        #[serde(skip)]
        json: &'static str,
    },
}

/// Equal sources: as derived, except that two embedded tables at the same address are
/// equal without comparing their 5.6 MB of text (a record plan compares the problem's
/// hydrodynamics with its own for every seed it serves).
impl PartialEq for BidirectionalSource {
    fn eq(&self, other: &Self) -> bool {
        use BidirectionalSource::*;
        match (self, other) {
            (
                ColumnArray { array, omegas },
                ColumnArray {
                    array: other_array,
                    omegas: other_omegas,
                },
            ) => array == other_array && omegas == other_omegas,
            (Table(table), Table(other)) => table == other,
            (
                Embedded { name, json },
                Embedded {
                    name: other_name,
                    json: other_json,
                },
            ) => name == other_name && (std::ptr::eq(*json, *other_json) || json == other_json),
            _ => false,
        }
    }
}

impl BidirectionalSource {
    /// T at the data frequencies that cover `band` (the first at or below it to the first at
    /// or above it) for every pair of `headings`. Errors name an uncovered band or heading.
    pub fn pairs(
        &self,
        environment: &Environment,
        band: (f64, f64),
        headings: &[f64],
    ) -> Result<DirectionPairs> {
        match self {
            BidirectionalSource::ColumnArray { array, omegas } => {
                let range = covering_range(omegas, band, "drift.omega")?;
                let nd = headings.len();
                let mut values = Vec::with_capacity(range.len() * nd * nd);
                for &omega in &omegas[range.clone()] {
                    let t = array.bidirectional_drift(environment, omega, headings)?;
                    for k in 0..nd {
                        for l in 0..nd {
                            values.push(t.get(k, l));
                        }
                    }
                }
                Ok(DirectionPairs {
                    omegas: omegas[range].to_vec(),
                    directions: nd,
                    values,
                })
            }
            BidirectionalSource::Table(table) => table.pairs(band, headings),
            BidirectionalSource::Embedded { name, json } => {
                BidirectionalTable::parse(json, name)?.pairs(band, headings)
            }
        }
    }
}

/// The mean-direction rule T(omega; beta_k, beta_l) ~ T(omega; (beta_k + beta_l)/2) from the
/// uni-directional `table`, at the table's frequencies that cover `band`. The headings of a
/// spread sea lie within +-90 deg of the mean, so the arithmetic mean of two is the
/// direction halfway between them.
pub fn mean_direction_pairs(
    table: &DriftTable,
    band: (f64, f64),
    headings: &[f64],
) -> Result<DirectionPairs> {
    let range = covering_range(table.omegas(), band, "drift.omega")?;
    let omegas = table.omegas()[range].to_vec();
    let nd = headings.len();
    let mut values = vec![[Complex64::default(); 3]; omegas.len() * nd * nd];
    for k in 0..nd {
        for l in 0..nd {
            let mean = 0.5 * (headings[k] + headings[l]);
            let mut n = 0;
            table.for_each_along_heading(mean, &omegas, |t, _| {
                values[(n * nd + k) * nd + l] = t.map(|v| Complex64::new(v, 0.0));
                n += 1;
            })?;
        }
    }
    Ok(DirectionPairs {
        omegas,
        directions: nd,
        values,
    })
}

/// Indices of `omegas` (increasing) from the last at or below band.0 to the first at or
/// above band.1; an error naming `field` when the grid does not reach that far.
fn covering_range(omegas: &[f64], band: (f64, f64), field: &str) -> Result<std::ops::Range<usize>> {
    let (lo, hi) = (omegas[0], omegas[omegas.len() - 1]);
    if band.0 < lo * (1.0 - FREQUENCY_MATCH_TOLERANCE)
        || band.1 > hi * (1.0 + FREQUENCY_MATCH_TOLERANCE)
    {
        return Err(Error::invalid(
            field,
            format!("[{}, {}] rad/s", written(lo), written(hi)),
            format!(
                "the bi-directional drift does not cover the wave band [{:.4}, {:.4}] rad/s \
                 (nothing is extrapolated); extend the data or narrow [sea] band",
                band.0, band.1
            ),
        ));
    }
    let start = omegas
        .partition_point(|&w| w <= band.0 * (1.0 + GRID_TOLERANCE))
        .saturating_sub(1);
    let end = (omegas.partition_point(|&w| w < band.1 * (1.0 - GRID_TOLERANCE)) + 1)
        .max(start + 2)
        .min(omegas.len());
    Ok(end.saturating_sub(2).min(start)..end)
}

impl BidirectionalTable {
    /// A table from its JSON text (the database's `bidirectional_drift` value), validated;
    /// `name` says where the text came from in errors.
    pub fn parse(json: &str, name: &str) -> Result<Self> {
        let table: BidirectionalTable = serde_json::from_str(json).map_err(|e| Error::Parse {
            path: name.to_string(),
            line: (e.line() > 0).then(|| e.line()),
            message: e.to_string(),
        })?;
        table.validate().map_err(|e| Error::Parse {
            path: name.to_string(),
            line: None,
            message: e.to_string(),
        })?;
        Ok(table)
    }

    /// Checks the shapes, grids, finiteness and the Hermitian symmetry in the heading pair;
    /// errors name the field (`database.bidirectional_drift...`).
    pub fn validate(&self) -> Result<()> {
        let field = "database.bidirectional_drift";
        let (nw, nh) = (self.omegas.len(), self.headings.len());
        if nw < 2 || nh < 1 {
            return Err(Error::invalid(
                format!("{field}.omegas"),
                format!("{nw} frequencies, {nh} headings"),
                "needs at least 2 frequencies and 1 heading",
            ));
        }
        for (n, &w) in self.omegas.iter().enumerate() {
            require_positive(&format!("{field}.omegas[{n}]"), w)?;
            if n > 0 && w <= self.omegas[n - 1] {
                return Err(Error::invalid(
                    format!("{field}.omegas[{n}]"),
                    w,
                    "frequencies must be strictly increasing",
                ));
            }
        }
        for (p, &h) in self.headings.iter().enumerate() {
            require_finite(format_args!("{field}.headings[{p}]"), h)?;
            if p > 0 && h <= self.headings[p - 1] {
                return Err(Error::invalid(
                    format!("{field}.headings[{p}]"),
                    h,
                    "headings must be strictly increasing",
                ));
            }
        }
        if self.headings[nh - 1] - self.headings[0] >= 2.0 * PI {
            return Err(Error::invalid(
                format!("{field}.headings"),
                format!(
                    "{} .. {} rad",
                    written(self.headings[0]),
                    written(self.headings[nh - 1])
                ),
                "must lie within one turn (list 0 or 360 deg, not both)",
            ));
        }
        for (part, values) in [("re", &self.re), ("im", &self.im)] {
            let shape_ok = values.len() == nw
                && values
                    .iter()
                    .all(|m| m.len() == nh && m.iter().all(|r| r.len() == nh));
            if !shape_ok {
                return Err(Error::invalid(
                    format!("{field}.{part}"),
                    "shape",
                    format!("must be {nw} x {nh} x {nh} (frequencies x headings x headings)"),
                ));
            }
            for (n, m) in values.iter().enumerate() {
                for (p, r) in m.iter().enumerate() {
                    for (q, v) in r.iter().enumerate() {
                        for (i, x) in v.iter().enumerate() {
                            require_finite(format_args!("{field}.{part}[{n}][{p}][{q}][{i}]"), *x)?;
                        }
                    }
                }
            }
        }
        let scale = self
            .re
            .iter()
            .chain(&self.im)
            .flatten()
            .flatten()
            .flatten()
            .fold(0.0f64, |m, v| m.max(v.abs()));
        for n in 0..nw {
            for p in 0..nh {
                for q in 0..nh {
                    for i in 0..3 {
                        let gap = (self.value(n, p, q)[i] - self.value(n, q, p)[i].conj()).norm();
                        if gap > HERMITIAN_TOLERANCE * scale {
                            let (here, mirror) = (self.value(n, p, q)[i], self.value(n, q, p)[i]);
                            return Err(Error::invalid(
                                format!("{field}[{n}][{p}][{q}][{i}]"),
                                written_complex(here.re, here.im),
                                format!(
                                    "T(beta_q, beta_p) must equal conj T(beta_p, beta_q): \
                                     [{q}][{p}] is {}",
                                    written_complex(mirror.re, mirror.im)
                                ),
                            ));
                        }
                    }
                }
            }
        }
        Ok(())
    }

    /// T(omega_n; beta_p, beta_q) at a node.
    pub fn value(&self, n: usize, p: usize, q: usize) -> [Complex64; 3] {
        let (re, im) = (self.re[n][p][q], self.im[n][p][q]);
        std::array::from_fn(|i| Complex64::new(re[i], im[i]))
    }

    /// Heading bracket of `heading`; an error when the table does not reach it.
    fn heading_bracket(&self, heading: f64) -> Result<Bracket> {
        heading_bracket(&self.headings, heading).ok_or_else(|| {
            Error::invalid(
                "database.bidirectional_drift.headings",
                format!("{:.3} deg", heading.to_degrees()),
                format!(
                    "a wave direction outside the bi-directional table's headings [{:.3}, {:.3}] \
                     deg (nothing is extrapolated)",
                    self.headings[0].to_degrees(),
                    self.headings[self.headings.len() - 1].to_degrees()
                ),
            )
        })
    }

    /// Bilinear interpolation in the heading pair at the table's frequencies covering `band`.
    fn pairs(&self, band: (f64, f64), headings: &[f64]) -> Result<DirectionPairs> {
        let range = covering_range(&self.omegas, band, "database.bidirectional_drift.omegas")?;
        let brackets = headings
            .iter()
            .map(|&h| self.heading_bracket(h))
            .collect::<Result<Vec<_>>>()?;
        let nd = headings.len();
        let mut values = Vec::with_capacity(range.len() * nd * nd);
        for n in range.clone() {
            for bk in &brackets {
                for bl in &brackets {
                    let mut v = [Complex64::default(); 3];
                    for (p, wp) in [(bk.lo, 1.0 - bk.frac), (bk.hi, bk.frac)] {
                        for (q, wq) in [(bl.lo, 1.0 - bl.frac), (bl.hi, bl.frac)] {
                            let node = self.value(n, p, q);
                            for i in 0..3 {
                                v[i] += wp * wq * node[i];
                            }
                        }
                    }
                    values.push(v);
                }
            }
        }
        Ok(DirectionPairs {
            omegas: self.omegas[range].to_vec(),
            directions: nd,
            values,
        })
    }

    /// The column solver's bi-directional drift on a table grid (e.g. for a database).
    pub fn from_column_array(
        array: &ColumnArray,
        environment: &Environment,
        omegas: &[f64],
        headings: &[f64],
    ) -> Result<Self> {
        let nh = headings.len();
        let mut re = Vec::with_capacity(omegas.len());
        let mut im = Vec::with_capacity(omegas.len());
        for &omega in omegas {
            let t = array.bidirectional_drift(environment, omega, headings)?;
            let part = |f: fn(&Complex64) -> f64| -> Vec<Vec<[f64; 3]>> {
                (0..nh)
                    .map(|p| (0..nh).map(|q| t.get(p, q).map(|v| f(&v))).collect())
                    .collect()
            };
            re.push(part(|v| v.re));
            im.push(part(|v| v.im));
        }
        Ok(BidirectionalTable {
            omegas: omegas.to_vec(),
            headings: headings.to_vec(),
            re,
            im,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Cylinder;

    fn two_columns() -> ColumnArray {
        let column = |x: f64, y: f64| Cylinder {
            x,
            y,
            diameter: 16.0,
            draft: 20.0,
        };
        ColumnArray::new(vec![column(30.0, 10.0), column(-25.0, -20.0)], None).unwrap()
    }

    /// The table interpolates exactly at its nodes and the column source gives the solver's
    /// values; between nodes the bilinear interpolation of a smooth T converges at order 2
    /// in the heading step.
    #[test]
    fn table_matches_the_solver_at_nodes_and_converges_between() {
        let env = Environment::default();
        let array = two_columns();
        let omegas = [0.4, 0.5, 0.6];
        let headings: Vec<f64> = (0..36).map(|i| (i as f64 * 10.0).to_radians()).collect();
        let table =
            BidirectionalTable::from_column_array(&array, &env, &omegas, &headings).unwrap();
        table.validate().unwrap();
        let source = BidirectionalSource::ColumnArray {
            array: array.clone(),
            omegas: omegas.to_vec(),
        };
        let at = [headings[3], headings[35], headings[0]];
        let exact = source.pairs(&env, (0.45, 0.55), &at).unwrap();
        let tabled = table.pairs((0.45, 0.55), &at).unwrap();
        assert_eq!(exact.omegas, omegas);
        for (a, b) in exact.values.iter().zip(&tabled.values) {
            for i in 0..3 {
                assert!((a[i] - b[i]).norm() <= 1e-12 * (1.0 + a[i].norm()));
            }
        }
        // Off the nodes: bilinear error ~ f (1 - f) h^2 / 2 T'', so a point at a quarter of
        // a 10 deg cell and the middle of a 5 deg cell has errors in the ratio
        // (0.1875 x 100) / (0.25 x 25) = 3.
        let error = |step_deg: f64| {
            let n = (360.0 / step_deg) as usize;
            let hs: Vec<f64> = (0..n).map(|i| (i as f64 * step_deg).to_radians()).collect();
            let t = BidirectionalTable::from_column_array(&array, &env, &[0.45, 0.5], &hs).unwrap();
            // Mid-cell of the 5 deg grid, quarter-cell of the 10 deg grid (one wraps).
            let off = [(42.5f64).to_radians(), (-17.5f64).to_radians()];
            let interpolated = t.pairs((0.46, 0.49), &off).unwrap();
            let truth = array.bidirectional_drift(&env, 0.45, &off).unwrap();
            let mut worst: f64 = 0.0;
            for k in 0..2 {
                for l in 0..2 {
                    worst = worst.max((interpolated.get(0, k, l)[0] - truth.get(k, l)[0]).norm());
                }
            }
            worst
        };
        let ratio = error(10.0) / error(5.0);
        assert!((2.4..3.6).contains(&ratio), "order-2 ratio {ratio}");
    }

    #[test]
    fn gaps_and_broken_tables_are_named() {
        let env = Environment::default();
        let headings = [0.0, 0.5, 1.0];
        let table =
            BidirectionalTable::from_column_array(&two_columns(), &env, &[0.4, 0.6], &headings)
                .unwrap();
        let e = table.pairs((0.3, 0.5), &[0.2]).unwrap_err().to_string();
        assert!(
            e.contains("bidirectional_drift.omegas") && e.contains("0.3000"),
            "{e}"
        );
        let e = table.pairs((0.45, 0.5), &[1.2]).unwrap_err().to_string();
        assert!(
            e.contains("68.755 deg") && e.contains("[0.000, 57.296]"),
            "{e}"
        );
        let mut broken = table.clone();
        broken.im[1][0][2][1] += 1.0;
        let e = broken.validate().unwrap_err().to_string();
        assert!(e.contains("bidirectional_drift[1][0][2][1]"), "{e}");
        let mut short = table;
        short.re[0].pop();
        let e = short.validate().unwrap_err().to_string();
        assert!(
            e.contains("bidirectional_drift.re") && e.contains("2 x 3 x 3"),
            "{e}"
        );
    }
}
