//! First-order motions of the rigid body in regular waves: the response amplitude operators
//! (RAOs), 6 DOF, from the radiation-diffraction coefficients and the body's matrices.
//!
//! For each frequency omega and heading beta, the complex amplitudes xi (per unit wave
//! amplitude) solve (Newman, "Marine Hydrodynamics", 1977, §6.16 and §6.18; WAMIT manual v7.4
//! §3.4)
//!
//! ```text
//! [ -omega^2 (M + A(omega)) + i omega (B(omega) + B_ext) + C_hs + C_ext ] xi = X(omega, beta)
//! ```
//!
//! Conventions:
//! - time: a motion is Re{xi e^{i omega t}} (WAMIT's and the crate's, docs/theory.md#conventions),
//!   its phase relative to the incident-wave elevation at the reference point, a positive
//!   phase leading the wave; the velocity is i omega xi, hence + i omega B.
//! - DOFs: surge, sway, heave (m/m), roll, pitch, yaw (rad/m), about the body reference point
//!   (WAMIT's body origin), right-handed axes with z up; roll, pitch and yaw positive about
//!   +x, +y, +z.
//! - M: the rigid-body mass matrix about the reference point ([`crate::hydro::rigid_body`]);
//!   C_hs as the diffraction code gives it; C_ext and B_ext the rest: the mooring's linearised
//!   stiffness, the weight's restoring when C_hs leaves it out
//!   ([`crate::hydro::rigid_body::RigidBody::weight_stiffness`]), and the viscous damping a
//!   potential-flow code does not have (without it the response at resonance is set by the
//!   radiation damping alone, which is small in heave, roll and pitch for a semi-submersible).

use crate::error::numbers::written;
use crate::error::{require_finite, require_finite_matrix, require_positive, Error, Result};
use crate::model::FREQUENCY_MATCH_TOLERANCE;
use nalgebra::Matrix6;
use rustfft::num_complex::Complex64;
use serde::{Deserialize, Serialize};

/// Smallest ratio of the smallest to the largest pivot of the equilibrated system (rows and
/// columns scaled to a largest entry of one) below which it is refused as singular: a double
/// resolves 1e-16, and a pivot 1e-12 of the largest leaves a solution with no digit to trust.
const SINGULAR_PIVOT_RATIO: f64 = 1e-12;

/// The first-order radiation-diffraction coefficients of a body on one frequency grid (the
/// database's `first_order`), SI, about the body reference point, DOFs surge to yaw.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FirstOrder {
    /// Frequencies, rad/s, strictly increasing.
    pub omegas: Vec<f64>,
    /// Headings, rad, strictly increasing.
    pub headings: Vec<f64>,
    /// Added mass A(omega) per frequency (kg, kg m, kg m^2).
    pub added_mass: Vec<[[f64; 6]; 6]>,
    /// Radiation damping B(omega) per frequency (N s/m, N s, N m s/rad).
    pub damping: Vec<[[f64; 6]; 6]>,
    /// Re X(omega, beta): `excitation_re[omega][heading][dof]`, N/m, N m/m per unit
    /// amplitude, Re{X e^{i omega t}}.
    pub excitation_re: Vec<Vec<[f64; 6]>>,
    /// Im X(omega, beta), same layout.
    pub excitation_im: Vec<Vec<[f64; 6]>>,
    /// Hydrostatic restoring C_hs (N/m, N, N m/rad) as the code gives it.
    pub hydrostatics: [[f64; 6]; 6],
}

/// The body's side of the equation of motion, 6x6 about the reference point.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyMatrices {
    /// Rigid-body mass matrix M.
    pub mass: [[f64; 6]; 6],
    /// External linear stiffness C_ext: the mooring, and the weight when C_hs leaves it out.
    pub stiffness: [[f64; 6]; 6],
    /// External linear damping B_ext (viscous).
    pub damping: [[f64; 6]; 6],
}

/// RAOs: xi(omega, beta) per unit wave amplitude (m/m for surge, sway, heave; rad/m for roll,
/// pitch, yaw), Re{xi e^{i omega t}}, about the body reference point.
#[derive(Debug, Clone, PartialEq)]
pub struct Rao {
    /// Frequencies, rad/s, strictly increasing.
    pub omegas: Vec<f64>,
    /// Headings, rad, strictly increasing.
    pub headings: Vec<f64>,
    /// `values[omega][heading][dof]`.
    pub values: Vec<Vec<[Complex64; 6]>>,
}

/// RAOs as the database writes them (its `rao`): real and imaginary parts apart.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RaoTable {
    /// Frequencies, rad/s, strictly increasing.
    pub omegas: Vec<f64>,
    /// Headings, rad, strictly increasing.
    pub headings: Vec<f64>,
    /// Re xi: `re[omega][heading][dof]`.
    pub re: Vec<Vec<[f64; 6]>>,
    /// Im xi, same layout.
    pub im: Vec<Vec<[f64; 6]>>,
}

impl FirstOrder {
    /// The coefficients from a radiation solution (`radiation_omegas`, A, B) and an
    /// excitation (`excitation_omegas`, `headings`, X[omega][heading][dof]) computed on the
    /// same frequencies: each excitation frequency must be a radiation frequency within
    /// [`FREQUENCY_MATCH_TOLERANCE`] and the other way round; the error lists those that are
    /// not. The grid kept is the radiation one.
    pub fn from_parts(
        radiation_omegas: &[f64],
        added_mass: &[[[f64; 6]; 6]],
        damping: &[[[f64; 6]; 6]],
        excitation_omegas: &[f64],
        headings: &[f64],
        excitation: &[Vec<[Complex64; 6]>],
        hydrostatics: [[f64; 6]; 6],
    ) -> Result<FirstOrder> {
        let same =
            |a: f64, b: f64| (a - b).abs() <= FREQUENCY_MATCH_TOLERANCE * a.abs().max(b.abs());
        let unmatched = |from: &[f64], to: &[f64]| -> Vec<String> {
            from.iter()
                .filter(|&&w| !to.iter().any(|&v| same(w, v)))
                .map(|w| format!("{w:.6}"))
                .collect()
        };
        let only_excitation = unmatched(excitation_omegas, radiation_omegas);
        let only_radiation = unmatched(radiation_omegas, excitation_omegas);
        if !only_excitation.is_empty() || !only_radiation.is_empty() {
            return Err(Error::invalid(
                "first_order.omegas",
                format!(
                    "{} radiation, {} excitation frequencies",
                    radiation_omegas.len(),
                    excitation_omegas.len()
                ),
                format!(
                    "the added mass and damping and the excitation must be given at the same \
                     frequencies (within {FREQUENCY_MATCH_TOLERANCE} relative); excitation only: \
                     [{}] rad/s; radiation only: [{}] rad/s",
                    only_excitation.join(", "),
                    only_radiation.join(", ")
                ),
            ));
        }
        let mut excitation_re = Vec::with_capacity(radiation_omegas.len());
        let mut excitation_im = Vec::with_capacity(radiation_omegas.len());
        for &w in radiation_omegas {
            let k = excitation_omegas
                .iter()
                .position(|&v| same(w, v))
                .expect("matched above");
            excitation_re.push(excitation[k].iter().map(|x| x.map(|z| z.re)).collect());
            excitation_im.push(excitation[k].iter().map(|x| x.map(|z| z.im)).collect());
        }
        let first_order = FirstOrder {
            omegas: radiation_omegas.to_vec(),
            headings: headings.to_vec(),
            added_mass: added_mass.to_vec(),
            damping: damping.to_vec(),
            excitation_re,
            excitation_im,
            hydrostatics,
        };
        first_order.validate()?;
        Ok(first_order)
    }

    /// X(omega_n, beta_h) for the six DOFs.
    pub fn excitation(&self, n: usize, h: usize) -> [Complex64; 6] {
        let (re, im) = (&self.excitation_re[n][h], &self.excitation_im[n][h]);
        std::array::from_fn(|i| Complex64::new(re[i], im[i]))
    }

    /// Checks the grids, the shapes and finiteness; errors name the field
    /// (`database.first_order...`).
    pub fn validate(&self) -> Result<()> {
        let field = "database.first_order";
        let (nw, nh) = (self.omegas.len(), self.headings.len());
        check_grids(field, &self.omegas, &self.headings)?;
        for (part, n) in [
            ("added_mass", self.added_mass.len()),
            ("damping", self.damping.len()),
        ] {
            if n != nw {
                return Err(Error::invalid(
                    format!("{field}.{part}"),
                    format!("{n} matrices"),
                    format!("must be one 6x6 matrix per frequency ({nw})"),
                ));
            }
        }
        for (n, (a, b)) in self.added_mass.iter().zip(&self.damping).enumerate() {
            require_finite_matrix(format_args!("{field}.added_mass[{n}]"), a)?;
            require_finite_matrix(format_args!("{field}.damping[{n}]"), b)?;
        }
        check_values(field, "excitation_re", &self.excitation_re, nw, nh)?;
        check_values(field, "excitation_im", &self.excitation_im, nw, nh)?;
        require_finite_matrix(format_args!("{field}.hydrostatics"), &self.hydrostatics)
    }
}

impl BodyMatrices {
    /// Checks that every entry is finite.
    pub fn validate(&self) -> Result<()> {
        require_finite_matrix("rao.mass", &self.mass)?;
        require_finite_matrix("rao.stiffness", &self.stiffness)?;
        require_finite_matrix("rao.damping", &self.damping)
    }
}

impl RaoTable {
    /// Checks the grids, the shapes and finiteness; errors name the field
    /// (`database.rao...`).
    pub fn validate(&self) -> Result<()> {
        let field = "database.rao";
        let (nw, nh) = (self.omegas.len(), self.headings.len());
        check_grids(field, &self.omegas, &self.headings)?;
        check_values(field, "re", &self.re, nw, nh)?;
        check_values(field, "im", &self.im, nw, nh)
    }

    /// The RAOs in memory (complex); [`RaoTable::validate`] first.
    pub fn to_rao(&self) -> Rao {
        Rao {
            omegas: self.omegas.clone(),
            headings: self.headings.clone(),
            values: self
                .re
                .iter()
                .zip(&self.im)
                .map(|(re, im)| {
                    re.iter()
                        .zip(im)
                        .map(|(r, i)| std::array::from_fn(|k| Complex64::new(r[k], i[k])))
                        .collect()
                })
                .collect(),
        }
    }
}

impl From<&Rao> for RaoTable {
    fn from(rao: &Rao) -> Self {
        let part = |f: fn(&Complex64) -> f64| -> Vec<Vec<[f64; 6]>> {
            rao.values
                .iter()
                .map(|row| row.iter().map(|x| x.each_ref().map(f)).collect())
                .collect()
        };
        RaoTable {
            omegas: rao.omegas.clone(),
            headings: rao.headings.clone(),
            re: part(|z| z.re),
            im: part(|z| z.im),
        }
    }
}

/// The RAOs of `first_order` with the body's matrices: the module's equation solved at every
/// frequency and heading (one LU factorisation per frequency, with full pivoting on the
/// system scaled to unit rows and columns). Refused: non-finite coefficients, a system
/// singular at a frequency (a free body at omega = 0, a DOF with neither inertia nor
/// stiffness), a non-finite result.
pub fn solve(first_order: &FirstOrder, body: &BodyMatrices) -> Result<Rao> {
    first_order.validate()?;
    body.validate()?;
    let mut values = Vec::with_capacity(first_order.omegas.len());
    for (n, &w) in first_order.omegas.iter().enumerate() {
        let system = Matrix6::from_fn(|i, j| {
            let mass = body.mass[i][j] + first_order.added_mass[n][i][j];
            let damping = body.damping[i][j] + first_order.damping[n][i][j];
            let stiffness = body.stiffness[i][j] + first_order.hydrostatics[i][j];
            Complex64::new(-w * w * mass + stiffness, w * damping)
        });
        let at = |reason: String| {
            Error::invalid(
                format!("rao at omega = {} rad/s", written(w)),
                "the equation of motion",
                reason,
            )
        };
        // Equilibrate: D_r K D_c with unit largest entry per row, then per column.
        let mut rows = [1.0; 6];
        let mut columns = [1.0; 6];
        for (i, r) in rows.iter_mut().enumerate() {
            let largest = (0..6).map(|j| system[(i, j)].norm()).fold(0.0, f64::max);
            if largest == 0.0 {
                return Err(at(format!(
                    "singular: DOF {} has no mass, added mass, damping or stiffness",
                    i + 1
                )));
            }
            *r = 1.0 / largest;
        }
        for (j, c) in columns.iter_mut().enumerate() {
            let largest = (0..6)
                .map(|i| (system[(i, j)] * rows[i]).norm())
                .fold(0.0, f64::max);
            *c = 1.0 / largest;
        }
        let scaled = Matrix6::from_fn(|i, j| system[(i, j)] * rows[i] * columns[j]);
        let lu = scaled.full_piv_lu();
        let pivots: Vec<f64> = (0..6).map(|k| lu.u()[(k, k)].norm()).collect();
        let largest = pivots.iter().copied().fold(0.0, f64::max);
        let smallest = pivots.iter().copied().fold(f64::INFINITY, f64::min);
        if smallest <= SINGULAR_PIVOT_RATIO * largest {
            return Err(at(format!(
                "singular (smallest pivot {} of the largest, below {SINGULAR_PIVOT_RATIO}): \
                 a DOF without stiffness at omega = 0, or a body without mass or stiffness in \
                 a DOF; give the mooring's stiffness or leave omega = 0 out",
                written(smallest / largest)
            )));
        }
        let mut row = Vec::with_capacity(first_order.headings.len());
        for (h, &heading) in first_order.headings.iter().enumerate() {
            let force = first_order.excitation(n, h);
            let rhs = nalgebra::Vector6::from_fn(|i, _| force[i] * rows[i]);
            let scaled_xi = lu.solve(&rhs).ok_or_else(|| at("singular".into()))?;
            let xi: [Complex64; 6] = std::array::from_fn(|j| scaled_xi[j] * columns[j]);
            for (j, x) in xi.iter().enumerate() {
                if !(x.re.is_finite() && x.im.is_finite()) {
                    return Err(at(format!(
                        "the motion of DOF {} at heading {:.3} deg is not finite",
                        j + 1,
                        heading.to_degrees()
                    )));
                }
            }
            row.push(xi);
        }
        values.push(row);
    }
    Ok(Rao {
        omegas: first_order.omegas.clone(),
        headings: first_order.headings.clone(),
        values,
    })
}

/// Frequencies positive and strictly increasing (at least one), headings finite and
/// strictly increasing (at least one).
fn check_grids(field: &str, omegas: &[f64], headings: &[f64]) -> Result<()> {
    if omegas.is_empty() || headings.is_empty() {
        return Err(Error::invalid(
            format!("{field}.omegas"),
            format!("{} frequencies, {} headings", omegas.len(), headings.len()),
            "needs at least 1 frequency and 1 heading",
        ));
    }
    for (n, &w) in omegas.iter().enumerate() {
        require_positive(&format!("{field}.omegas[{n}]"), w)?;
        if n > 0 && w <= omegas[n - 1] {
            return Err(Error::invalid(
                format!("{field}.omegas[{n}]"),
                w,
                "frequencies must be strictly increasing",
            ));
        }
    }
    for (p, &h) in headings.iter().enumerate() {
        require_finite(format_args!("{field}.headings[{p}]"), h)?;
        if p > 0 && h <= headings[p - 1] {
            return Err(Error::invalid(
                format!("{field}.headings[{p}]"),
                h,
                "headings must be strictly increasing",
            ));
        }
    }
    Ok(())
}

/// `values` is n_omega x n_heading x 6, finite.
fn check_values(
    field: &str,
    part: &str,
    values: &[Vec<[f64; 6]>],
    nw: usize,
    nh: usize,
) -> Result<()> {
    if values.len() != nw || values.iter().any(|r| r.len() != nh) {
        return Err(Error::invalid(
            format!("{field}.{part}"),
            "shape",
            format!("must be {nw} x {nh} x 6 (frequencies x headings x DOFs)"),
        ));
    }
    for (n, r) in values.iter().enumerate() {
        for (h, v) in r.iter().enumerate() {
            for (i, x) in v.iter().enumerate() {
                require_finite(format_args!("{field}.{part}[{n}][{h}][{i}]"), *x)?;
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One DOF at a time: a diagonal system is m-s-d per DOF, xi = X / (c - w^2 (m + a)
    /// + i w (b + b_ext)), the closed form of a damped oscillator.
    #[test]
    fn diagonal_system_is_six_oscillators() {
        let diag = |v: [f64; 6]| -> [[f64; 6]; 6] {
            let mut m = [[0.0; 6]; 6];
            for i in 0..6 {
                m[i][i] = v[i];
            }
            m
        };
        let omegas = vec![0.2, 0.7, 1.3];
        let a = diag([1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        let b = diag([0.1, 0.2, 0.3, 0.4, 0.5, 0.6]);
        let x: Vec<Vec<[Complex64; 6]>> = omegas
            .iter()
            .map(|&w| vec![std::array::from_fn(|i| Complex64::new(w, i as f64 - 2.0))])
            .collect();
        let c = diag([10.0, 0.0, 30.0, 40.0, 50.0, 0.0]);
        let fo = FirstOrder::from_parts(&omegas, &[a; 3], &[b; 3], &omegas, &[0.5], &x, c).unwrap();
        let body = BodyMatrices {
            mass: diag([7.0; 6]),
            stiffness: diag([0.0, 5.0, 0.0, 0.0, 0.0, 1.0]),
            damping: diag([0.01; 6]),
        };
        let rao = solve(&fo, &body).unwrap();
        for (n, &w) in omegas.iter().enumerate() {
            for i in 0..6 {
                let k = Complex64::new(
                    c[i][i] + body.stiffness[i][i] - w * w * (7.0 + a[i][i]),
                    w * (b[i][i] + 0.01),
                );
                let expected = x[n][0][i] / k;
                assert!(
                    (rao.values[n][0][i] - expected).norm() <= 1e-14 * expected.norm(),
                    "DOF {i} at {w}: {} vs {expected}",
                    rao.values[n][0][i]
                );
            }
        }
        let table = RaoTable::from(&rao);
        table.validate().unwrap();
        assert_eq!(table.to_rao(), rao);
    }

    #[test]
    fn singular_and_mismatched_and_non_finite_are_refused() {
        let omegas = [0.5];
        let zero = [[0.0; 6]; 6];
        let x = vec![vec![[Complex64::new(1.0, 0.0); 6]]];
        let fo =
            FirstOrder::from_parts(&omegas, &[zero], &[zero], &omegas, &[0.0], &x, zero).unwrap();
        let mut mass = zero;
        for (i, row) in mass.iter_mut().enumerate().take(5) {
            row[i] = 1.0;
        }
        let body = BodyMatrices {
            mass,
            stiffness: zero,
            damping: zero,
        };
        let err = solve(&fo, &body).unwrap_err().to_string();
        assert!(
            err.contains("omega = 0.5") && err.contains("DOF 6"),
            "{err}"
        );
        // Yaw with mass equal to its stiffness / w^2: exactly at resonance, undamped.
        let mut body = body;
        body.mass[5][5] = 4.0;
        body.stiffness[5][5] = 1.0;
        let err = solve(&fo, &body).unwrap_err().to_string();
        assert!(err.contains("singular"), "{err}");
        // Pitch and yaw rows alike (a rank-deficient mass, no row of zeros): the pivot test.
        body.mass[4] = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0];
        body.mass[5] = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0];
        body.stiffness[5][5] = 0.0;
        let err = solve(&fo, &body).unwrap_err().to_string();
        assert!(err.contains("smallest pivot"), "{err}");
        let err = FirstOrder::from_parts(
            &[0.5, 0.6],
            &[zero; 2],
            &[zero; 2],
            &[0.5, 0.61],
            &[0.0],
            &[x[0].clone(), x[0].clone()],
            zero,
        )
        .unwrap_err()
        .to_string();
        assert!(
            err.contains("excitation only: [0.610000]")
                && err.contains("radiation only: [0.600000]"),
            "{err}"
        );
        let mut nan = fo.clone();
        nan.damping[0][2][2] = f64::NAN;
        let err = solve(&nan, &body).unwrap_err().to_string();
        assert!(
            err.contains("database.first_order.damping[0][2][2]"),
            "{err}"
        );
    }
}
