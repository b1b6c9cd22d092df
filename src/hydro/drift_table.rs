//! The mean drift table T_i(omega, beta) (surge, sway: N/m^2; yaw: N m/m^2, per unit wave
//! amplitude squared, body frame) and optional wave-drift damping b_ij(omega, beta)
//! (N s/m per m^2 of amplitude, ...), on a rectangular (frequency x heading) grid.
//!
//! Interpolation is bilinear; headings wrap around when the table covers the full circle.
//! Nothing is extrapolated: a frequency or heading outside the table is an error that
//! names the gap.

use super::heading_grid::{heading_bracket, is_periodic, Bracket};
use crate::error::numbers::{readable, written};
use crate::error::{require_finite, Error, Result};
use crate::model::FREQUENCY_MATCH_TOLERANCE;
use serde::Serialize;
use std::f64::consts::PI;

/// Relative tolerance when matching headings and frequencies.
const GRID_TOLERANCE: f64 = 1e-9;
/// How closely a heading 360 deg after the first must repeat the first's drift (relative to
/// the table's largest value) to be accepted as the same direction listed twice.
const CLOSING_HEADING_TOLERANCE: f64 = 1e-6;

/// One row of a drift table as a user writes it.
#[derive(Debug, Clone, PartialEq)]
pub struct DriftRow {
    /// Wave frequency, rad/s.
    pub omega: f64,
    /// Wave heading (direction of propagation relative to the body x axis), rad.
    pub heading: f64,
    /// Mean drift per unit amplitude squared: surge, sway (N/m^2), yaw (N m/m^2).
    pub drift: [f64; 3],
    /// Wave-drift damping b_ij, rows = force (surge, sway, yaw), columns = velocity
    /// (surge, sway, yaw rate), per unit amplitude squared.
    pub damping: Option<[[f64; 3]; 3]>,
}

/// Drift (and damping) on a frequency x heading grid.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DriftTable {
    omegas: Vec<f64>,
    headings: Vec<f64>,
    /// Heading-major: index `ih * omegas.len() + iw`.
    drift: Vec<[f64; 3]>,
    damping: Option<Vec<[[f64; 3]; 3]>>,
}

impl DriftTable {
    /// Builds a table from rows in any heading order. Within each heading the frequencies
    /// must be strictly increasing; every heading must have the same frequencies; damping
    /// is given on every row or on none.
    pub fn from_rows(rows: &[DriftRow]) -> Result<Self> {
        if rows.is_empty() {
            return Err(Error::invalid(
                "drift.rows",
                "[]",
                "the drift table is empty",
            ));
        }
        let has_damping = rows[0].damping.is_some();
        for (r, row) in rows.iter().enumerate() {
            validate_row(r, row, has_damping)?;
        }
        // The headings, sorted, one per direction (within GRID_TOLERANCE), from one sweep
        // of the rows in heading order, and the rows grouped by heading in the order given:
        // O(R log R) for R rows.
        let mut by_heading: Vec<usize> = (0..rows.len()).collect();
        by_heading.sort_by(|&a, &b| rows[a].heading.total_cmp(&rows[b].heading));
        let mut headings: Vec<f64> = Vec::new();
        let mut group_of = vec![0; rows.len()];
        for &r in &by_heading {
            let h = rows[r].heading;
            if !headings.last().is_some_and(|&kept| same(kept, h)) {
                headings.push(h);
            }
            group_of[r] = headings.len() - 1;
        }
        let mut groups: Vec<Vec<(usize, &DriftRow)>> = vec![Vec::new(); headings.len()];
        for (r, row) in rows.iter().enumerate() {
            groups[group_of[r]].push((r, row));
        }
        let omegas: Vec<f64> = groups[0].iter().map(|(_, r)| r.omega).collect();
        for (ih, (&h, these)) in headings.iter().zip(&groups).enumerate() {
            check_frequencies(h, these, &omegas)?;
            if ih > 0 && h - headings[ih - 1] <= GRID_TOLERANCE {
                return Err(Error::invalid(
                    "drift.heading",
                    h.to_degrees(),
                    "duplicated heading",
                ));
            }
        }
        // Every heading's rows now list the frequencies of `omegas` in order.
        let drift = groups.iter().flatten().map(|(_, row)| row.drift).collect();
        let damping = has_damping.then(|| {
            let rows = groups.iter().flatten();
            rows.map(|(_, row)| row.damping.unwrap_or_default())
                .collect()
        });
        if headings.last().expect("non-empty") - headings[0] > 2.0 * PI + GRID_TOLERANCE {
            return Err(Error::invalid(
                "drift.heading",
                format!(
                    "{} .. {} deg",
                    readable(headings[0].to_degrees()),
                    readable(headings.last().unwrap().to_degrees())
                ),
                "headings span more than 360 deg",
            ));
        }
        let mut table = DriftTable {
            omegas,
            headings,
            drift,
            damping,
        };
        table.drop_closing_heading()?;
        Ok(table)
    }

    /// A table listing both ends of the circle (0 and 360 deg, or -180 and 180 deg) lists one
    /// direction twice: its last heading's values must equal the first's (relative
    /// [`CLOSING_HEADING_TOLERANCE`] of the largest value), and that duplicate is dropped, so
    /// the headings stay distinct directions and wrap around.
    fn drop_closing_heading(&mut self) -> Result<()> {
        let n = self.headings.len();
        let (first, last) = (self.headings[0], self.headings[n - 1]);
        if n < 2 || (last - first - 2.0 * PI).abs() > GRID_TOLERANCE * (1.0 + last.abs()) {
            return Ok(());
        }
        let nw = self.omegas.len();
        let scale = self
            .drift
            .iter()
            .flatten()
            .fold(0.0f64, |m, v| m.max(v.abs()))
            .max(f64::MIN_POSITIVE);
        for iw in 0..nw {
            let (a, b) = (self.drift[iw], self.drift[(n - 1) * nw + iw]);
            if a.iter()
                .zip(&b)
                .any(|(x, y)| (x - y).abs() > CLOSING_HEADING_TOLERANCE * scale)
            {
                return Err(Error::invalid(
                    "drift.heading",
                    format!(
                        "{} and {} deg",
                        readable(first.to_degrees()),
                        readable(last.to_degrees())
                    ),
                    format!(
                        "are the same direction but their drift differs at omega = {} rad/s",
                        written(self.omegas[iw])
                    ),
                ));
            }
        }
        self.headings.pop();
        self.drift.truncate((n - 1) * nw);
        if let Some(damping) = self.damping.as_mut() {
            damping.truncate((n - 1) * nw);
        }
        Ok(())
    }

    /// Frequencies of the grid, rad/s, increasing.
    pub fn omegas(&self) -> &[f64] {
        &self.omegas
    }

    /// Headings of the grid, rad, increasing.
    pub fn headings(&self) -> &[f64] {
        &self.headings
    }

    /// Whether the table carries damping coefficients b_ij.
    pub fn has_damping(&self) -> bool {
        self.damping.is_some()
    }

    /// Drift at grid node (heading ih, frequency iw).
    pub fn drift_at_node(&self, ih: usize, iw: usize) -> [f64; 3] {
        self.drift[ih * self.omegas.len() + iw]
    }

    /// Damping at grid node (heading ih, frequency iw), when the table has damping.
    pub fn damping_at_node(&self, ih: usize, iw: usize) -> Option<[[f64; 3]; 3]> {
        self.damping
            .as_ref()
            .map(|table| table[ih * self.omegas.len() + iw])
    }

    /// The same grid with damping coefficients replaced (heading-major like the drift).
    pub fn with_damping(mut self, damping: Vec<[[f64; 3]; 3]>) -> Self {
        assert_eq!(
            damping.len(),
            self.drift.len(),
            "one damping matrix per node"
        );
        self.damping = Some(damping);
        self
    }

    /// Whether the headings wrap around: the table covers the full circle up to at most one
    /// regular heading step.
    pub fn is_periodic_in_heading(&self) -> bool {
        is_periodic(&self.headings)
    }

    /// Checks that [omega_min, omega_max] and every heading in `headings` can be
    /// interpolated; the error names the gap.
    pub fn check_covers(&self, band: (f64, f64), headings: &[f64]) -> Result<()> {
        let (lo, hi) = (self.omegas[0], self.omegas[self.omegas.len() - 1]);
        if band.0 < lo * (1.0 - FREQUENCY_MATCH_TOLERANCE)
            || band.1 > hi * (1.0 + FREQUENCY_MATCH_TOLERANCE)
        {
            return Err(Error::invalid(
                "drift.omega",
                format!("[{}, {}] rad/s", written(lo), written(hi)),
                format!(
                    "the drift table does not cover the wave band [{:.4}, {:.4}] rad/s; \
                     extend the table or narrow [sea] band",
                    band.0, band.1
                ),
            ));
        }
        for &h in headings {
            self.heading_bracket(h)?;
        }
        Ok(())
    }

    /// Bilinear interpolation of the drift at (omega, heading).
    pub fn drift(&self, omega: f64, heading: f64) -> Result<[f64; 3]> {
        self.interpolate(omega, heading, |ih, iw| self.drift_at_node(ih, iw))
    }

    /// Bilinear interpolation of the damping at (omega, heading); `None` if the table has none.
    pub fn damping(&self, omega: f64, heading: f64) -> Result<Option<[[f64; 3]; 3]>> {
        let Some(table) = &self.damping else {
            return Ok(None);
        };
        let nw = self.omegas.len();
        let flat = self.interpolate(omega, heading, |ih, iw| flatten(&table[ih * nw + iw]))?;
        Ok(Some(unflatten(&flat)))
    }

    /// Bilinear interpolation at one heading for every frequency of `omegas` (increasing),
    /// handing `visit` the drift and, when the table has it, the damping at each. Same values
    /// as [`DriftTable::drift`] and [`DriftTable::damping`], with one heading bracket and a
    /// walking frequency bracket instead of two searches per frequency.
    pub fn for_each_along_heading(
        &self,
        heading: f64,
        omegas: &[f64],
        mut visit: impl FnMut([f64; 3], Option<[[f64; 3]; 3]>),
    ) -> Result<()> {
        let (Some(&first), Some(&last)) = (omegas.first(), omegas.last()) else {
            return Ok(());
        };
        self.frequency_bracket(first)?;
        self.frequency_bracket(last)?;
        let h = self.heading_bracket(heading)?;
        let nw = self.omegas.len();
        let mut upper = 1;
        for &omega in omegas {
            let w = if nw == 1 {
                Bracket {
                    lo: 0,
                    hi: 0,
                    frac: 0.0,
                }
            } else {
                let omega = omega.clamp(self.omegas[0], self.omegas[nw - 1]);
                while upper < nw - 1 && self.omegas[upper] < omega {
                    upper += 1;
                }
                let (a, b) = (self.omegas[upper - 1], self.omegas[upper]);
                Bracket {
                    lo: upper - 1,
                    hi: upper,
                    frac: (omega - a) / (b - a),
                }
            };
            let corners = [
                (h.lo * nw + w.lo, (1.0 - h.frac) * (1.0 - w.frac)),
                (h.lo * nw + w.hi, (1.0 - h.frac) * w.frac),
                (h.hi * nw + w.lo, h.frac * (1.0 - w.frac)),
                (h.hi * nw + w.hi, h.frac * w.frac),
            ];
            let mut drift = [0.0; 3];
            for &(node, weight) in corners.iter().filter(|(_, w)| *w != 0.0) {
                for (d, v) in drift.iter_mut().zip(self.drift[node]) {
                    *d += weight * v;
                }
            }
            let damping = self.damping.as_ref().map(|table| {
                let mut b = [[0.0; 3]; 3];
                for &(node, weight) in corners.iter().filter(|(_, w)| *w != 0.0) {
                    for (row, node_row) in b.iter_mut().zip(&table[node]) {
                        for (v, n) in row.iter_mut().zip(node_row) {
                            *v += weight * n;
                        }
                    }
                }
                b
            });
            visit(drift, damping);
        }
        Ok(())
    }

    fn interpolate<const N: usize>(
        &self,
        omega: f64,
        heading: f64,
        node: impl Fn(usize, usize) -> [f64; N],
    ) -> Result<[f64; N]> {
        let w = self.frequency_bracket(omega)?;
        let h = self.heading_bracket(heading)?;
        let mut out = [0.0; N];
        for (ih, wh) in [(h.lo, 1.0 - h.frac), (h.hi, h.frac)] {
            for (iw, ww) in [(w.lo, 1.0 - w.frac), (w.hi, w.frac)] {
                let weight = wh * ww;
                if weight != 0.0 {
                    for (o, v) in out.iter_mut().zip(node(ih, iw)) {
                        *o += weight * v;
                    }
                }
            }
        }
        Ok(out)
    }

    fn frequency_bracket(&self, omega: f64) -> Result<Bracket> {
        let w = &self.omegas;
        let (lo, hi) = (w[0], w[w.len() - 1]);
        if omega < lo * (1.0 - FREQUENCY_MATCH_TOLERANCE)
            || omega > hi * (1.0 + FREQUENCY_MATCH_TOLERANCE)
        {
            return Err(Error::invalid(
                "drift.omega",
                omega,
                format!(
                    "outside the drift table's frequencies [{}, {}] rad/s",
                    written(lo),
                    written(hi)
                ),
            ));
        }
        if w.len() == 1 {
            return Ok(Bracket {
                lo: 0,
                hi: 0,
                frac: 0.0,
            });
        }
        let omega = omega.clamp(lo, hi);
        let i = w.partition_point(|&v| v <= omega).clamp(1, w.len() - 1);
        Ok(Bracket {
            lo: i - 1,
            hi: i,
            frac: (omega - w[i - 1]) / (w[i] - w[i - 1]),
        })
    }

    /// Whether the table's headings reach `heading` (rad, any number of turns) without
    /// extrapolation.
    pub fn covers_heading(&self, heading: f64) -> bool {
        heading_bracket(&self.headings, heading).is_some()
    }

    fn heading_bracket(&self, heading: f64) -> Result<Bracket> {
        heading_bracket(&self.headings, heading).ok_or_else(|| {
            Error::invalid(
                "drift.heading",
                format!("{:.3} deg", heading.to_degrees()),
                format!(
                    "the drift table's headings cover [{:.3}, {:.3}] deg only",
                    self.headings[0].to_degrees(),
                    self.headings[self.headings.len() - 1].to_degrees()
                ),
            )
        })
    }
}

fn same(a: f64, b: f64) -> bool {
    (a - b).abs() <= GRID_TOLERANCE * (1.0 + a.abs().max(b.abs()))
}

fn flatten(m: &[[f64; 3]; 3]) -> [f64; 9] {
    let mut out = [0.0; 9];
    for i in 0..3 {
        out[3 * i..3 * i + 3].copy_from_slice(&m[i]);
    }
    out
}

fn unflatten(v: &[f64; 9]) -> [[f64; 3]; 3] {
    [[v[0], v[1], v[2]], [v[3], v[4], v[5]], [v[6], v[7], v[8]]]
}

fn validate_row(r: usize, row: &DriftRow, has_damping: bool) -> Result<()> {
    require_finite(format_args!("drift.rows[{r}].omega"), row.omega)?;
    if row.omega <= 0.0 {
        return Err(Error::invalid(
            format!("drift.rows[{r}].omega"),
            row.omega,
            "must be greater than zero",
        ));
    }
    require_finite(format_args!("drift.rows[{r}].heading"), row.heading)?;
    for (i, v) in row.drift.iter().enumerate() {
        require_finite(format_args!("drift.rows[{r}].drift[{i}]"), *v)?;
    }
    match (&row.damping, has_damping) {
        (Some(b), true) => {
            for (i, line) in b.iter().enumerate() {
                for (j, v) in line.iter().enumerate() {
                    require_finite(format_args!("drift.rows[{r}].b{}{}", i + 1, j + 1), *v)?;
                }
            }
            Ok(())
        }
        (None, false) => Ok(()),
        _ => Err(Error::invalid(
            format!("drift.rows[{r}].damping"),
            if has_damping { "missing" } else { "present" },
            "give damping on every row of the drift table or on none",
        )),
    }
}

fn check_frequencies(heading: f64, rows: &[(usize, &DriftRow)], reference: &[f64]) -> Result<()> {
    for pair in rows.windows(2) {
        let ((_, a), (r, b)) = (pair[0], pair[1]);
        if b.omega <= a.omega {
            let what = if same(a.omega, b.omega) {
                "duplicated"
            } else {
                "not increasing"
            };
            return Err(Error::invalid(
                format!("drift.rows[{r}].omega"),
                b.omega,
                format!(
                    "frequency {what} within heading {:.3} deg",
                    heading.to_degrees()
                ),
            ));
        }
    }
    // Both lists increase: they hold the same frequencies exactly when they pair up in order.
    if rows.len() == reference.len()
        && rows
            .iter()
            .zip(reference)
            .all(|((_, row), &w)| same(row.omega, w))
    {
        return Ok(());
    }
    for &w in reference {
        if !rows.iter().any(|(_, row)| same(row.omega, w)) {
            return Err(Error::invalid(
                "drift.rows",
                format!(
                    "omega = {}, heading = {:.3} deg",
                    written(w),
                    heading.to_degrees()
                ),
                "hole in the drift table: this (frequency, heading) pair is missing",
            ));
        }
    }
    if let Some((r, extra)) = rows
        .iter()
        .find(|(_, row)| !reference.iter().any(|&w| same(w, row.omega)))
    {
        return Err(Error::invalid(
            format!("drift.rows[{r}].omega"),
            extra.omega,
            "hole in the drift table: this frequency is missing at the other headings",
        ));
    }
    Err(Error::invalid(
        "drift.rows",
        format!("heading = {:.3} deg", heading.to_degrees()),
        "frequencies closer than the matching tolerance within one heading",
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A periodic table with damping whose values vary in both directions.
    fn table() -> DriftTable {
        let mut rows = Vec::new();
        for ih in 0..12 {
            let heading = (30.0 * ih as f64).to_radians();
            for iw in 1..=9 {
                let omega = 0.1 * iw as f64 + 0.01 * (iw * iw) as f64;
                let f = |k: f64| (k * omega).sin() * (heading + k).cos();
                rows.push(DriftRow {
                    omega,
                    heading,
                    drift: [f(1.0), f(2.0), f(3.0)],
                    damping: Some(std::array::from_fn(|i| {
                        std::array::from_fn(|j| f(4.0 + (3 * i + j) as f64))
                    })),
                });
            }
        }
        DriftTable::from_rows(&rows).unwrap()
    }

    /// 0 and 360 deg listed both: the duplicate is dropped and the table wraps, so Aranha's
    /// heading derivative stays finite at head seas; a mismatched closing heading is refused.
    #[test]
    fn both_ends_of_the_circle_are_one_direction() {
        let rows_for = |skew: f64| -> Vec<DriftRow> {
            let mut rows = Vec::new();
            for ih in 0..=12 {
                let heading = (30.0 * ih as f64).to_radians();
                for iw in 1..=5 {
                    let omega = 0.2 * iw as f64;
                    let f = 1.0e4 * omega * omega + if ih == 12 { skew } else { 0.0 };
                    rows.push(DriftRow {
                        omega,
                        heading,
                        drift: [f * heading.cos(), f * heading.sin(), 0.0],
                        damping: None,
                    });
                }
            }
            rows
        };
        let t = DriftTable::from_rows(&rows_for(0.0)).unwrap();
        assert_eq!(t.headings().len(), 12);
        assert!(t.is_periodic_in_heading());
        let b = crate::hydro::aranha::aranha_damping(&t, 9.80665, &[]).unwrap();
        let at_head_seas = b.damping(0.5, 0.0).unwrap().unwrap();
        assert!(at_head_seas.iter().flatten().all(|v| v.is_finite()));
        let err = DriftTable::from_rows(&rows_for(50.0))
            .unwrap_err()
            .to_string();
        assert!(err.contains("same direction"), "{err}");
    }

    #[test]
    fn walking_along_a_heading_equals_pointwise_interpolation() {
        let t = table();
        let omegas: Vec<f64> = (0..200).map(|i| 0.11 + 1.0 * i as f64 / 199.0).collect();
        for heading in [0.0, 0.4, 3.0, 5.9, -0.2] {
            let mut j = 0;
            t.for_each_along_heading(heading, &omegas, |drift, damping| {
                assert_eq!(drift, t.drift(omegas[j], heading).unwrap());
                let expected = t.damping(omegas[j], heading).unwrap().unwrap();
                let got = damping.unwrap();
                for i in 0..3 {
                    for k in 0..3 {
                        assert!((got[i][k] - expected[i][k]).abs() < 1e-15);
                    }
                }
                j += 1;
            })
            .unwrap();
            assert_eq!(j, omegas.len());
        }
        assert!(t
            .for_each_along_heading(0.0, &[0.05, 0.5], |_, _| {})
            .is_err());
    }
}
