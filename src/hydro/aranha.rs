//! Wave-drift damping from the zero-speed drift by Aranha's formula (Aranha 1994,
//! J. Fluid Mech. 275; deep water; docs/theory.md#wave-drift-damping-and-current).
//!
//! For the force (or moment) F_i(omega, beta) of waves propagating in direction beta
//! relative to the body, and a slow body velocity (U_1, U_2) in the body frame,
//! F_i(U) = F_i(0) - b_i1 U_1 - b_i2 U_2 with
//!   b_i1 = (omega/g) [cos(beta) (4 F_i + omega dF_i/domega) - 2 sin(beta) dF_i/dbeta]
//!   b_i2 = (omega/g) [sin(beta) (4 F_i + omega dF_i/domega) + 2 cos(beta) dF_i/dbeta]
//! for i = surge, sway and the yaw moment. In head seas b_11 = (omega/g)(4 F + omega F'):
//! a body moving against the waves (U_1 < 0) feels more drift. Negative values (where the
//! drift falls steeply with frequency) are kept.
//!
//! Yaw-rate column b_i6: Aranha gives none. Approximation used here: the translational
//! drift is shared equally by the platform's N_c columns at (x_c, y_c), each column damps
//! its own local velocity (-r y_c, r x_c) with b/N_c, and the moments are summed:
//! `b_16 = -<y> b_11 + <x> b_12`, `b_26 = -<y> b_21 + <x> b_22`,
//! `b_66 = <x^2> b_22 + <y^2> b_11 - <x y> (b_12 + b_21)`,
//! with `<.>` the mean over the columns. Without columns, b_i6 = 0.
//!
//! Derivatives come from the table: second-order finite differences on its (possibly
//! non-uniform) frequency and heading nodes, wrapping in heading when the table covers the
//! circle. The formula needs dF/dbeta, so a table with a single heading is refused.

use super::DriftTable;
use crate::error::{Error, Result};
use crate::model::{Cylinder, DriftDamping, Mode};
use std::f64::consts::PI;

/// Damping table b_ij on the drift table's own nodes.
pub fn aranha_damping(
    table: &DriftTable,
    gravity: f64,
    columns: &[Cylinder],
) -> Result<DriftTable> {
    let omegas = table.omegas();
    let headings = table.headings();
    if headings.len() < 2 {
        return Err(Error::invalid(
            "model.drift_damping",
            DriftDamping::Aranha.word(),
            format!(
                "Aranha's formula needs dF/dbeta but the drift table has the single heading \
                 {:.3} deg; give b_ij columns (drift_damping = table), more headings, or \
                 drift_damping = off",
                headings[0].to_degrees()
            ),
        ));
    }
    let moments = ColumnMoments::of(columns);
    let periodic = table.is_periodic_in_heading();
    let mut damping = Vec::with_capacity(headings.len() * omegas.len());
    for (ih, &beta) in headings.iter().enumerate() {
        for (iw, &omega) in omegas.iter().enumerate() {
            let f = table.drift_at_node(ih, iw);
            let df_domega = derivative(omegas, iw, false, |i| table.drift_at_node(ih, i));
            let df_dbeta = derivative(headings, ih, periodic, |i| table.drift_at_node(i, iw));
            let mut b = aranha_coefficients(omega, beta, f, df_domega, df_dbeta, gravity);
            moments.fill_yaw_rate_column(&mut b);
            damping.push(b);
        }
    }
    Ok(table.clone().with_damping(damping))
}

/// Aranha's b_ij at one (omega, beta) from the drift F_i (surge, sway, yaw), dF_i/domega
/// and dF_i/dbeta (module doc): rows i = surge, sway, yaw; columns j = surge, sway velocity
/// filled, the yaw-rate column (index 2) left zero: the module doc's per-column
/// approximation fills it.
pub fn aranha_coefficients(
    omega: f64,
    beta: f64,
    f: [f64; 3],
    df_domega: [f64; 3],
    df_dbeta: [f64; 3],
    gravity: f64,
) -> [[f64; 3]; 3] {
    let (sin, cos) = beta.sin_cos();
    let mut b = [[0.0; 3]; 3];
    for i in 0..3 {
        let radial = 4.0 * f[i] + omega * df_domega[i];
        b[i][0] = omega / gravity * (cos * radial - 2.0 * sin * df_dbeta[i]);
        b[i][1] = omega / gravity * (sin * radial + 2.0 * cos * df_dbeta[i]);
    }
    b
}

/// Mean position moments of the columns, for the yaw-rate approximation (module doc).
pub(crate) struct ColumnMoments {
    mean_x: f64,
    mean_y: f64,
    mean_xx: f64,
    mean_yy: f64,
    mean_xy: f64,
}

impl ColumnMoments {
    pub(crate) fn of(columns: &[Cylinder]) -> Self {
        let n = columns.len().max(1) as f64;
        let sum = |f: &dyn Fn(&Cylinder) -> f64| columns.iter().map(f).sum::<f64>() / n;
        ColumnMoments {
            mean_x: sum(&|c| c.x),
            mean_y: sum(&|c| c.y),
            mean_xx: sum(&|c| c.x * c.x),
            mean_yy: sum(&|c| c.y * c.y),
            mean_xy: sum(&|c| c.x * c.y),
        }
    }

    /// Fills b_16, b_26, b_66 from the translational columns (module doc).
    pub(crate) fn fill_yaw_rate_column(&self, b: &mut [[f64; 3]; 3]) {
        b[0][2] = -self.mean_y * b[0][0] + self.mean_x * b[0][1];
        b[1][2] = -self.mean_y * b[1][0] + self.mean_x * b[1][1];
        b[2][2] =
            self.mean_xx * b[1][1] + self.mean_yy * b[0][0] - self.mean_xy * (b[0][1] + b[1][0]);
    }
}

/// d/dx of a 3-vector sampled on nodes `x` at node `i`: the derivative of the quadratic
/// through three neighbouring nodes (centred inside, one-sided at the ends unless periodic
/// with period 2 pi); the slope of the line for two nodes.
fn derivative(x: &[f64], i: usize, periodic: bool, value: impl Fn(usize) -> [f64; 3]) -> [f64; 3] {
    let n = x.len();
    if n == 1 {
        return [0.0; 3];
    }
    if n == 2 && !periodic {
        let (a, b) = (value(0), value(1));
        return std::array::from_fn(|k| (b[k] - a[k]) / (x[1] - x[0]));
    }
    // Three nodes (abscissa, index) around i.
    let node = |j: isize| -> (f64, usize) {
        let wrapped = j.rem_euclid(n as isize) as usize;
        let shift = (j - wrapped as isize) / n as isize;
        (x[wrapped] + shift as f64 * 2.0 * PI, wrapped)
    };
    let centre = if periodic {
        i as isize
    } else {
        (i as isize).clamp(1, n as isize - 2)
    };
    let stencil = [node(centre - 1), node(centre), node(centre + 1)];
    let xs = stencil.map(|(xv, _)| xv);
    let fs = stencil.map(|(_, idx)| value(idx));
    let at = x[i];
    let weights = quadratic_derivative_weights(xs, at);
    std::array::from_fn(|k| weights[0] * fs[0][k] + weights[1] * fs[1][k] + weights[2] * fs[2][k])
}

/// Weights w such that sum w_m f(x_m) is the derivative at `at` of the quadratic through
/// (x_0, f_0), (x_1, f_1), (x_2, f_2).
fn quadratic_derivative_weights(x: [f64; 3], at: f64) -> [f64; 3] {
    let [x0, x1, x2] = x;
    [
        ((at - x1) + (at - x2)) / ((x0 - x1) * (x0 - x2)),
        ((at - x0) + (at - x2)) / ((x1 - x0) * (x1 - x2)),
        ((at - x0) + (at - x1)) / ((x2 - x0) * (x2 - x1)),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hydro::DriftRow;

    /// Drift F_1 = c omega^2 cos(beta), F_2 = c omega^2 sin(beta), F_6 = 0: quadratics in
    /// omega, so the finite differences in omega are exact; in beta they converge as h^2.
    fn table(n_headings: usize) -> DriftTable {
        let c = 1.0e4;
        let mut rows = Vec::new();
        for ih in 0..n_headings {
            let beta = 2.0 * PI * ih as f64 / n_headings as f64;
            for iw in 1..=6 {
                let w = 0.2 * iw as f64;
                rows.push(DriftRow {
                    omega: w,
                    heading: beta,
                    drift: [c * w * w * beta.cos(), c * w * w * beta.sin(), 0.0],
                    damping: None,
                });
            }
        }
        DriftTable::from_rows(&rows).unwrap()
    }

    #[test]
    fn head_sea_limit_and_isotropy() {
        // For F = c w^2 (cos b, sin b): 4F + w F' = 6 c w^2 (cos, sin), dF1/db = -c w^2 sin,
        // dF2/db = c w^2 cos. Then b_11 = (w/g) 6 c w^2 at b = 0 (the head-sea limit
        // (w/g)(4F + wF')), b_22 = (w/g) 2 c w^2, b_12 = b_21 = 0 — at every heading.
        let g = 9.80665;
        let t = aranha_damping(&table(72), g, &[]).unwrap();
        for &beta in &[0.0, 0.7, 2.0, 4.5] {
            let w = 0.8;
            let b = t.damping(w, beta).unwrap().unwrap();
            let c = 1.0e4;
            let (cb, sb) = (beta.cos(), beta.sin());
            // body-frame b for this isotropic drift: rotate the head-sea tensor by beta
            let (along, across) = (6.0 * c * w.powi(3) / g, 2.0 * c * w.powi(3) / g);
            let expect = [
                [
                    along * cb * cb + across * sb * sb,
                    (along - across) * cb * sb,
                ],
                [
                    (along - across) * cb * sb,
                    along * sb * sb + across * cb * cb,
                ],
            ];
            for i in 0..2 {
                for j in 0..2 {
                    // heading interpolation + finite differences at 5 deg spacing
                    assert!(
                        (b[i][j] - expect[i][j]).abs() < 2e-3 * along,
                        "beta {beta} b[{i}][{j}] = {} vs {}",
                        b[i][j],
                        expect[i][j]
                    );
                }
            }
        }
    }

    #[test]
    fn yaw_rate_column_from_a_square_of_columns() {
        let g = 9.80665;
        let columns: Vec<Cylinder> = [(35.0, 35.0), (-35.0, 35.0), (-35.0, -35.0), (35.0, -35.0)]
            .iter()
            .map(|&(x, y)| Cylinder {
                x,
                y,
                diameter: 20.0,
                draft: 30.0,
            })
            .collect();
        let t = aranha_damping(&table(36), g, &columns).unwrap();
        let b = t.damping(0.8, 0.0).unwrap().unwrap();
        // Centroid at the origin: no coupling into surge/sway; b_66 = 35^2 (b_11 + b_22).
        assert!(b[0][2].abs() < 1e-9 * b[0][0].abs());
        assert!(b[1][2].abs() < 1e-9 * b[0][0].abs());
        let expect = 35.0f64.powi(2) * (b[0][0] + b[1][1]);
        assert!((b[2][2] - expect).abs() < 1e-9 * expect);
    }

    #[test]
    fn single_heading_is_refused() {
        let rows = vec![
            DriftRow {
                omega: 0.5,
                heading: 0.0,
                drift: [1.0, 0.0, 0.0],
                damping: None,
            },
            DriftRow {
                omega: 0.6,
                heading: 0.0,
                drift: [1.0, 0.0, 0.0],
                damping: None,
            },
        ];
        let t = DriftTable::from_rows(&rows).unwrap();
        let err = aranha_damping(&t, 9.8, &[]).unwrap_err().to_string();
        assert!(err.contains("single heading"), "{err}");
    }

    /// At a table's end frequencies (and at the end headings of a table that does not
    /// cover the circle) the derivative is the one-sided second-order difference: for the
    /// cubic F_1 = c w^3 cos(beta) the error of b_11 at the first and last node falls as h^2
    /// (4x when the spacing halves; a first-order one-sided difference's would fall 2x).
    /// Likewise b_21 at the last heading of a table over 0-45 deg, which takes dF_2/dbeta.
    #[test]
    fn end_nodes_are_second_order() {
        let (c, g) = (1.0e4, 9.80665);
        let table = |spacing: f64| {
            let headings = [0.0, PI / 8.0, PI / 4.0];
            let mut rows = Vec::new();
            for &beta in &headings {
                for k in 0..=((0.4 / spacing).round() as usize) {
                    let w = 0.4 + k as f64 * spacing;
                    rows.push(DriftRow {
                        omega: w,
                        heading: beta,
                        drift: [c * w.powi(3) * beta.cos(), c * w.powi(3) * beta.sin(), 0.0],
                        damping: None,
                    });
                }
            }
            aranha_damping(&DriftTable::from_rows(&rows).unwrap(), g, &[]).unwrap()
        };
        // Exact, for F = c w^3 (cos b, sin b): 4F + w F' = 7 c w^3 (cos b, sin b); at b = 0
        // b_11 = (w/g) 7 c w^3, whatever dF/db.
        let exact_11 = |w: f64| w / g * 7.0 * c * w.powi(3);
        for w in [0.4, 0.8] {
            let errors: Vec<f64> = [0.05, 0.025]
                .iter()
                .map(|&h| {
                    let b = table(h).damping_at_node(0, ((w - 0.4) / h).round() as usize);
                    (b.unwrap()[0][0] - exact_11(w)).abs()
                })
                .collect();
            let ratio = errors[0] / errors[1];
            assert!(
                (3.5..4.5).contains(&ratio),
                "w {w}: errors {errors:?}, ratio {ratio}"
            );
        }
        // The heading derivative at the last heading (45 deg, the table's end: no wrap), for
        // F = c w^2 (cos b, sin b), whose frequency derivative the stencil takes exactly:
        // b_21 = (w/g)(cos b 6 c w^2 sin b - 2 sin b c w^2 cos b) = (w/g) 4 c w^2 sin b cos b.
        let exact_21 = |w: f64, b: f64| w / g * 4.0 * c * w * w * b.sin() * b.cos();
        let coarse = |n: usize| {
            let headings: Vec<f64> = (0..=n).map(|k| PI / 4.0 * k as f64 / n as f64).collect();
            let rows: Vec<DriftRow> = headings
                .iter()
                .flat_map(|&beta| {
                    [0.5, 0.6, 0.7].map(|w: f64| DriftRow {
                        omega: w,
                        heading: beta,
                        drift: [c * w * w * beta.cos(), c * w * w * beta.sin(), 0.0],
                        damping: None,
                    })
                })
                .collect();
            let t = aranha_damping(&DriftTable::from_rows(&rows).unwrap(), g, &[]).unwrap();
            (t.damping_at_node(n, 1).unwrap()[1][0] - exact_21(0.6, PI / 4.0)).abs()
        };
        let ratio = coarse(2) / coarse(4);
        assert!((3.0..5.0).contains(&ratio), "heading ends: ratio {ratio}");
    }

    #[test]
    fn quadratic_weights_differentiate_quadratics_exactly() {
        let x = [0.1, 0.4, 1.0];
        let f = |v: f64| 3.0 * v * v - v + 2.0;
        for at in x {
            let w = quadratic_derivative_weights(x, at);
            let d: f64 = (0..3).map(|m| w[m] * f(x[m])).sum();
            assert!((d - (6.0 * at - 1.0)).abs() < 1e-12);
        }
    }
}
