//! The slowly varying force from the full difference-frequency QTF at FFT cost
//! (docs/theory.md#the-slowly-varying-force).
//!
//! Definition (WAMIT's and the crate's convention, e^{i omega t}; the WAMIT import stores
//! the file's Re + i Im unchanged):
//!   F(t) = Re sum_i sum_j a_i a_j* T(w_i, w_j) e^{i (w_i - w_j) t}.
//! Only the Hermitian part (T + T^H)/2 contributes (the anti-Hermitian part pairs (i, j)
//! with (j, i) into purely imaginary terms), so it is the Hermitian part that is factorised,
//! exactly; a QTF filled by symmetry is Hermitian already.
//!
//! Factorisation: on the QTF's own n-point grid, the eigen-decomposition of the Hermitian
//! matrix T = sum_r s_r u_r u_r^H (s_r real, of either sign; u_r orthonormal), terms sorted
//! by decreasing |s_r|. The rank R is the smallest with
//!   discarded = sum_{r >= R} |s_r| / sum_r |s_r| <= tolerance
//! (the trace-norm share of the dropped terms). It bounds the force error rigorously:
//! |F - F_R|(t) = |sum_{r >= R} s_r |U_r(t)|^2| <= discarded * sum_r |s_r| * (sum_i |a_i|)^2,
//! since |U_r(t)| <= sum_i |a_i| max_i |u_r(w_i)| and interpolated unit vectors have no
//! component above 1.
//!
//! Interpolation: the factors u_r are interpolated linearly in omega onto the simulation
//! grid. Linear interpolation is a linear map L, so the factorised QTF on the simulation grid
//! is L T_R L^T: the bilinear interpolation (in w_i and w_j) of the truncated QTF. The
//! truncation error (above) and the interpolation error (of bilinear interpolation of the
//! true QTF, O(h^2) in the QTF grid step h) are therefore separate; the tests check each.
//! Nothing is extrapolated: the QTF grid must cover the wave band.
//!
//! Synthesis: F(t) = sum_r s_r |U_r(t)|^2 with U_r(t) = sum_i a_i u_r(w_i) e^{i w_i t}: one
//! complex FFT per retained term. (The general factorisation T = sum_r u_r s_r v_r^H of an
//! SVD needs U_r and V_r, two FFTs per term, F = sum_r s_r Re[U_r V_r*]; for a Hermitian T
//! the SVD has v_r = +-u_r, so V_r = +-U_r and one FFT suffices.) Memory: the factors,
//! count x R complex numbers, and one record-length buffer.

use super::synthesis::Synthesizer;
use crate::error::{Error, Result};
use crate::hydro::qtf::{check_covers, check_tolerance};
use crate::sea_state::{FrequencyGrid, WaveComponents};
use nalgebra::{DMatrix, SymmetricEigen};
use rustfft::num_complex::Complex64;

/// A Hermitian QTF factorised on its own grid and truncated: sum_r s_r u_r u_r^H; over
/// one wave direction, or jointly over (frequency, direction) pairs of a spread sea.
#[derive(Debug, Clone, PartialEq)]
pub struct QtfFactorisation {
    /// The QTF's frequencies, rad/s, strictly increasing.
    omegas: Vec<f64>,
    /// The number of wave directions the factors span (the vectors are direction-major:
    /// `[k * n + i]` for direction k, frequency i).
    directions: usize,
    /// Retained eigenvalues s_r (N/m^2 or N m/m^2), by decreasing |s_r|.
    eigenvalues: Vec<f64>,
    /// Retained unit eigenvectors u_r, one value per QTF frequency.
    vectors: Vec<Vec<Complex64>>,
    /// Trace-norm share of the discarded terms, <= the tolerance.
    discarded: f64,
}

impl QtfFactorisation {
    /// Factorises the n x n QTF `matrix` (row-major, `[i * n + j]` = T(w_i, w_j)) given on
    /// `omegas` and keeps the fewest terms whose discarded trace-norm share is at most
    /// `tolerance` (in [`crate::hydro::qtf::MIN_QTF_TOLERANCE`], 1)).
    pub fn new(omegas: &[f64], matrix: &[Complex64], tolerance: f64) -> Result<Self> {
        Self::across_directions(omegas, 1, matrix, tolerance)
    }

    /// Factorises the QTF of a spread sea over (frequency, direction) pairs: `matrix` is
    /// (n D) x (n D), row-major, `[(k n + i) * n D + (l n + j)]` = T(w_i, w_j; b_k, b_l) for
    /// the D = `directions` wave directions. It is Hermitian when T(w_j, w_i; b_l, b_k) =
    /// conj T(w_i, w_j; b_k, b_l), and
    /// F(t) = Re sum_{i,k} sum_{j,l} a_ik a_jl* T e^{i (w_i - w_j) t} = sum_r s_r |U_r(t)|^2
    /// with U_r = sum_{i,k} a_ik u_r(k n + i) e^{i w_i t}: one FFT per retained term,
    /// whatever D, the cross terms between directions included.
    pub fn across_directions(
        omegas: &[f64],
        directions: usize,
        matrix: &[Complex64],
        tolerance: f64,
    ) -> Result<Self> {
        check_tolerance(tolerance)?;
        let n = omegas.len();
        if n < 2
            || omegas.windows(2).any(|w| w[1] <= w[0])
            || omegas[0] <= 0.0
            || omegas.iter().any(|w| !w.is_finite())
        {
            return Err(Error::invalid(
                "qtf.omegas",
                format!("{n} frequencies"),
                "need at least 2 positive, strictly increasing frequencies",
            ));
        }
        let m = n * directions;
        if directions == 0
            || matrix.len() != m * m
            || matrix
                .iter()
                .any(|z| !(z.re.is_finite() && z.im.is_finite()))
        {
            return Err(Error::invalid(
                "qtf.matrix",
                format!("{} values", matrix.len()),
                format!("must be {m} x {m} finite values"),
            ));
        }
        let n = m;
        let hermitian = DMatrix::from_fn(n, n, |i, j| {
            0.5 * (matrix[i * n + j] + matrix[j * n + i].conj())
        });
        let eigen = SymmetricEigen::new(hermitian);
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&a, &b| {
            eigen.eigenvalues[b]
                .abs()
                .total_cmp(&eigen.eigenvalues[a].abs())
        });
        let total: f64 = eigen.eigenvalues.iter().map(|s| s.abs()).sum();
        // Keep terms until what is left is within the tolerance.
        let mut left = total;
        let mut rank = 0;
        while rank < n && left > tolerance * total {
            left -= eigen.eigenvalues[order[rank]].abs();
            rank += 1;
        }
        let kept = &order[..rank];
        let discarded = if total > 0.0 {
            order[rank..]
                .iter()
                .fold(0.0, |sum, &r| sum + eigen.eigenvalues[r].abs())
                / total
        } else {
            0.0
        };
        Ok(QtfFactorisation {
            omegas: omegas.to_vec(),
            directions,
            eigenvalues: kept.iter().map(|&r| eigen.eigenvalues[r]).collect(),
            vectors: kept
                .iter()
                .map(|&r| eigen.eigenvectors.column(r).iter().copied().collect())
                .collect(),
            discarded,
        })
    }

    /// Retained rank R.
    pub fn rank(&self) -> usize {
        self.eigenvalues.len()
    }

    /// Size of the factorised matrix (the full rank): the QTF grid's n times the directions.
    pub fn size(&self) -> usize {
        self.omegas.len() * self.directions
    }

    /// The number of wave directions the factors span.
    pub fn directions(&self) -> usize {
        self.directions
    }

    /// Trace-norm share of the discarded terms (<= the tolerance).
    pub fn discarded(&self) -> f64 {
        self.discarded
    }

    /// Retained eigenvalues s_r, by decreasing magnitude.
    pub fn eigenvalues(&self) -> &[f64] {
        &self.eigenvalues
    }

    /// The factors interpolated linearly onto the components of `grid`; an error naming the
    /// gap when the QTF's frequencies do not cover the grid's band. The factors stay on the
    /// QTF's own frequencies with each component's bracket (a few kB, where the factors
    /// on the grid would take R x N_omega x 16 B per DOF); they are interpolated as the
    /// records are made.
    pub fn on_grid(&self, grid: &FrequencyGrid) -> Result<GridQtf> {
        let band = (grid.omega(0), grid.omega(grid.count - 1));
        check_covers(&self.omegas, band)?;
        Ok(GridQtf {
            eigenvalues: self.eigenvalues.clone(),
            count: grid.count,
            directions: self.directions,
            brackets: (0..grid.count)
                .map(|j| bracket(&self.omegas, grid.omega(j)))
                .collect(),
            vectors: self.vectors.clone(),
        })
    }
}

/// A factorised QTF on a simulation grid: T(w_i, w_j; b_k, b_l) = sum_r s_r f_r(k, w_i)
/// f_r(l, w_j)* over the directions it spans (one, or a spread sea's jointly), f_r the
/// factor u_r interpolated linearly from the QTF's frequencies to the grid's components.
#[derive(Debug, Clone, PartialEq)]
pub struct GridQtf {
    eigenvalues: Vec<f64>,
    /// The grid's component count.
    count: usize,
    /// The number of wave directions the factors span.
    directions: usize,
    /// Per grid component: the QTF frequency k below it and the weight s of k + 1
    /// ([`bracket`]).
    brackets: Vec<(usize, f64)>,
    /// u_r at the QTF's frequencies, direction-major (`[k * n + i]`), one vector per
    /// retained term.
    vectors: Vec<Vec<Complex64>>,
}

/// The full QTF's records of a group of consecutive wave directions: one direction, or
/// every direction of a spread sea jointly (the cross terms from the bi-directional QTF).
#[derive(Debug, Clone, PartialEq)]
pub struct QtfGroup {
    /// Index of the group's first wave direction.
    pub first_direction: usize,
    /// Surge, sway, yaw, each spanning the same directions.
    pub dofs: [GridQtf; 3],
}

impl QtfGroup {
    /// Adds the group's force records (surge, sway, yaw) to `force`
    /// ([`GridQtf::accumulate`] per DOF, on the amplitudes of the group's directions);
    /// `coefficients` (grid count) and `series` (the synthesizer's output length) are
    /// scratch.
    pub fn accumulate(
        &self,
        synth: &mut Synthesizer,
        components: &WaveComponents,
        coefficients: &mut [Complex64],
        series: &mut [Complex64],
        force: &mut [Vec<f64>; 3],
    ) {
        let first = self.first_direction;
        let amplitudes = components.of_directions(first..first + self.dofs[0].directions());
        for (out, t) in force.iter_mut().zip(&self.dofs) {
            t.accumulate(synth, amplitudes, coefficients, series, out);
        }
    }
}

impl GridQtf {
    /// Retained rank R.
    pub fn rank(&self) -> usize {
        self.eigenvalues.len()
    }

    /// The number of wave directions the factors span.
    pub fn directions(&self) -> usize {
        self.directions
    }

    /// u_r over the QTF's frequencies for direction k (within the group).
    fn vector(&self, r: usize, k: usize) -> &[Complex64] {
        let n = self.vectors[r].len() / self.directions;
        &self.vectors[r][k * n..(k + 1) * n]
    }

    /// Term r's factor f_r(k, w_j) at component j of direction k (within the group).
    fn factor(&self, r: usize, k: usize, j: usize) -> Complex64 {
        interpolate(self.vector(r, k), self.brackets[j])
    }

    /// The represented QTF between components i and j of the first direction (for checks;
    /// O(R)).
    pub fn value(&self, i: usize, j: usize) -> Complex64 {
        self.value_between((i, 0), (j, 0))
    }

    /// The represented QTF between component i of direction k and component j of
    /// direction l (`(i, k)`, `(j, l)`; directions counted within the group).
    pub fn value_between(&self, (i, k): (usize, usize), (j, l): (usize, usize)) -> Complex64 {
        self.eigenvalues
            .iter()
            .enumerate()
            .map(|(r, s)| *s * self.factor(r, k, i) * self.factor(r, l, j).conj())
            .sum()
    }

    /// Adds sum_r s_r |U_r(t_m)|^2, U_r = sum_{i,k} a_ik f_r(k, w_i) e^{i w_i t_m}, to `out`
    /// (allocated to the synthesizer's output length when first needed; left alone at rank
    /// 0). `amplitudes` are those of the directions the factors span, direction-major
    /// (`WaveComponents::of_directions`); `coefficients` (grid count) and `series` (the
    /// synthesizer's output length) are scratch.
    pub fn accumulate(
        &self,
        synth: &mut Synthesizer,
        amplitudes: &[Complex64],
        coefficients: &mut [Complex64],
        series: &mut [Complex64],
        out: &mut Vec<f64>,
    ) {
        for (r, s) in self.eigenvalues.iter().enumerate() {
            for (k, a) in amplitudes.chunks(self.count).enumerate() {
                let u = self.vector(r, k);
                let terms = a
                    .iter()
                    .zip(&self.brackets)
                    .map(|(a, &b)| a * interpolate(u, b));
                for (c, term) in coefficients.iter_mut().zip(terms) {
                    *c = if k == 0 { term } else { *c + term };
                }
            }
            synth.complex_series(coefficients, series);
            out.resize(series.len(), 0.0);
            for (o, p) in out.iter_mut().zip(series.iter()) {
                *o += s * p.norm_sqr();
            }
        }
    }
}

/// The linear interpolation (1 - s) u_i + s u_{i+1} of `u` at the bracket (i, s) (u_i itself
/// at a node).
#[inline]
fn interpolate(u: &[Complex64], (i, s): (usize, f64)) -> Complex64 {
    if s == 0.0 {
        u[i]
    } else {
        (1.0 - s) * u[i] + s * u[i + 1]
    }
}

/// Lower node k and weight s of `w` in `omegas` (covered, within the frequency match
/// tolerance: a `w` just beyond an end takes the end's value): w = (1 - s) w_k + s w_{k+1};
/// s is exactly 0 at a node.
fn bracket(omegas: &[f64], w: f64) -> (usize, f64) {
    let w = w.clamp(omegas[0], omegas[omegas.len() - 1]);
    let above = omegas.partition_point(|&o| o <= w);
    let k = above.saturating_sub(1).min(omegas.len() - 2);
    if omegas[k] == w {
        return (k, 0.0);
    }
    (k, (w - omegas[k]) / (omegas[k + 1] - omegas[k]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hydro::qtf::MIN_QTF_TOLERANCE;

    fn smooth_qtf(w1: f64, w2: f64) -> Complex64 {
        // A smooth positive kernel less an oscillating rank-1 term: indefinite.
        let amplitude = 1.0e4 * (1.0 + w1 * w2) * (-(w1 - w2).powi(2) / 0.5).exp()
            - 2.0e4 * (4.0 * w1).sin() * (4.0 * w2).sin();
        amplitude * Complex64::from_polar(1.0, 2.0 * (w1 - w2))
    }

    fn sampled(omegas: &[f64]) -> Vec<Complex64> {
        omegas
            .iter()
            .flat_map(|&a| omegas.iter().map(move |&b| smooth_qtf(a, b)))
            .collect()
    }

    fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
        (0..n)
            .map(|i| a + (b - a) * i as f64 / (n - 1) as f64)
            .collect()
    }

    #[test]
    fn complex_hermitian_eigen_decomposition_reconstructs_the_qtf() {
        let omegas = linspace(0.2, 2.5, 40);
        let t = sampled(&omegas);
        let full = QtfFactorisation::new(&omegas, &t, MIN_QTF_TOLERANCE).unwrap();
        let scale = t.iter().fold(0.0f64, |m, z| m.max(z.norm()));
        let n = omegas.len();
        for i in 0..n {
            for j in 0..n {
                let r: Complex64 = full
                    .eigenvalues
                    .iter()
                    .zip(&full.vectors)
                    .map(|(s, u)| *s * u[i] * u[j].conj())
                    .sum();
                assert!((r - t[i * n + j]).norm() < 1e-11 * scale, "({i}, {j})");
            }
        }
        assert!(
            full.eigenvalues.iter().any(|&s| s < 0.0),
            "indefinite QTF: {:?}",
            full.eigenvalues
        );
    }

    #[test]
    fn rank_grows_as_the_tolerance_shrinks_and_discarded_stays_below_it() {
        let omegas = linspace(0.2, 2.5, 40);
        let t = sampled(&omegas);
        let mut last = 0;
        for tolerance in [1e-2, 1e-4, 1e-6, 1e-9] {
            let f = QtfFactorisation::new(&omegas, &t, tolerance).unwrap();
            assert!(f.discarded() <= tolerance);
            assert!(
                f.rank() >= last && f.rank() < f.size(),
                "{tolerance}: {}",
                f.rank()
            );
            last = f.rank();
        }
    }

    /// The interpolation error, separately from the truncation: the factorised QTF on a
    /// fine grid against the analytic QTF converges at O(h^2) in the QTF grid step.
    #[test]
    fn interpolation_error_is_second_order_in_the_qtf_step() {
        let grid = FrequencyGrid::new(0.0, 600.0, 0.25, (0.3, 2.0)).unwrap();
        let error = |n: usize| {
            let omegas = linspace(0.25, 2.1, n);
            let g = QtfFactorisation::new(&omegas, &sampled(&omegas), MIN_QTF_TOLERANCE)
                .unwrap()
                .on_grid(&grid)
                .unwrap();
            let mut worst = 0.0f64;
            for i in (0..grid.count).step_by(3) {
                for j in (0..grid.count).step_by(3) {
                    let exact = smooth_qtf(grid.omega(i), grid.omega(j));
                    worst = worst.max((g.value(i, j) - exact).norm());
                }
            }
            worst
        };
        let (coarse, fine) = (error(21), error(41));
        let order = (coarse / fine).log2();
        assert!(
            (1.8..2.3).contains(&order),
            "order {order}: {coarse} -> {fine}"
        );
    }

    #[test]
    fn a_qtf_short_of_the_band_is_refused_naming_the_gap() {
        let omegas = linspace(0.5, 1.5, 10);
        let f = QtfFactorisation::new(&omegas, &sampled(&omegas), 1e-6).unwrap();
        let grid = FrequencyGrid::new(0.0, 600.0, 0.25, (0.3, 2.0)).unwrap();
        let message = f.on_grid(&grid).unwrap_err().to_string();
        assert!(
            message.contains("0.5000 rad/s") && message.contains("1.5000 .."),
            "{message}"
        );
        for bad in [0.0, 1e-13, 1.0, f64::NAN] {
            assert!(QtfFactorisation::new(&omegas, &sampled(&omegas), bad).is_err());
        }
    }
}
