//! The depth kernel of the drag kinematics in a few terms.
//!
//! Strip j of a column sits at the stretched level z_j = -d + (j + 1/2) d / n
//! (`kinematics.rs`), and its horizontal velocity is
//!   u_j(t) = Re sum_i A_i K_ij e^{i omega_i t},   K_ij = omega_i e^{k_i z_j},  k_i = omega_i^2 / g,
//! with A_i the column's direction sums (x and y components, deep water,
//! docs/theory.md#viscous-drag). K is smooth in z and numerically of low rank. With the weights
//! p_i = E(|A_x,i|^2 + |A_y,i|^2) = E sum_k |a_{i,k}|^2 (the same for every column, block and
//! seed: [`WaveComponents::expected_power`]), the Gram matrix G = K^T diag(p) K
//! (strips x strips) is, by Parseval over the record, the expected record mean of
//! u_j u_l*. Its eigenvectors V (eigenvalues lambda_0 >= lambda_1 >= ...) give the terms
//!   g_q(t) = Re sum_i A_i (K V)_iq e^{i omega_i t},   one transform each, and
//!   u_j(t) ~ sum_{q < R} V_jq g_q(t),
//! the orthogonal projection of the strips' velocity vector onto the R leading directions.
//! Its expected mean-square error over the record, summed over the strips, is
//! sum_{q >= R} lambda_q; R is the smallest rank with
//!   sum_{q >= R} lambda_q <= tolerance^2 sum_q lambda_q,  tolerance = [`KINEMATICS_TOLERANCE`],
//! so the rms velocity error over strips and time is at most 1e-6 of the rms velocity, in
//! expectation (the tests measure it against the per-strip records).
//!
//! The basis depends on the grid, the spectrum, the draft and the strips, never on the block
//! or the seed: consecutive blocks' terms join as the strips' series would (the
//! recombination by V is linear and fixed). The [`crate::RecordPlan`] makes it once for all
//! the seeds and segments it serves.

use crate::sea_state::{FrequencyGrid, WaveComponents};
use nalgebra::{DMatrix, SymmetricEigen};

/// Relative rms velocity error the truncated depth kernel allows (see the module notes).
pub const KINEMATICS_TOLERANCE: f64 = 1e-6;

/// The most terms a depth kernel keeps, whatever the strips: it bounds the kinematics
/// records' memory before they are made (`record_plan::budget`). The eigenvalues fall off
/// exponentially: the kernels of drafts of 30 to 120 m with 12 to 200 strips keep 8 to 12
/// terms at [`KINEMATICS_TOLERANCE`] (`tests::the_rank_stays_below_its_cap`); a kernel
/// that needed more would keep these and report its larger error in
/// [`DepthBasis::discarded`].
pub const MAX_RANK: usize = 16;

/// The leading terms of one column's depth kernel.
#[derive(Debug, Clone, PartialEq)]
pub struct DepthBasis {
    draft: f64,
    strips: usize,
    /// The weights it was made with (components' expected power), its key with the draft.
    power: Vec<f64>,
    /// (K V)_iq, term-major: `profiles[q * count + i]`, m/s per m of amplitude.
    profiles: Vec<f64>,
    /// V_jq, term-major: `mix[q * strips + j]`.
    mix: Vec<f64>,
    rank: usize,
    /// sqrt(sum_{q >= R} lambda_q / sum_q lambda_q): the expected relative rms error.
    discarded: f64,
}

impl DepthBasis {
    /// The basis of a column of `draft` (m) with `strips` strips on `grid` for the
    /// components' expected power `power` ([`WaveComponents::expected_power`]), truncated at
    /// [`KINEMATICS_TOLERANCE`].
    pub fn new(
        grid: &FrequencyGrid,
        power: &[f64],
        draft: f64,
        strips: usize,
        gravity: f64,
    ) -> Self {
        debug_assert_eq!(power.len(), grid.count);
        let count = grid.count;
        // K_ij by e^{k z_j} = e^{k z_0} (e^{k dz})^j: two exponentials per frequency;
        // strip-major, `kernel[j * count + i]`.
        let dz = draft / strips as f64;
        let mut kernel = vec![0.0; count * strips];
        for i in 0..count {
            let omega = grid.omega(i);
            let k = omega * omega / gravity;
            let growth = (k * dz).exp();
            let mut value = omega * (k * (-draft + 0.5 * dz)).exp();
            for j in 0..strips {
                kernel[j * count + i] = value;
                value *= growth;
            }
        }
        // G_jl = sum_i p_i K_ij K_il = sum_i p_i omega_i^2 e^{k_i (z_j + z_l)} depends on
        // j + l only (z_j + z_l = -2d + (j + l + 1) dz): 2 strips - 1 sums (a Hankel matrix).
        let mut sums = vec![0.0; 2 * strips - 1];
        for (i, &p) in power.iter().enumerate() {
            let omega = grid.omega(i);
            let k = omega * omega / gravity;
            let growth = (k * dz).exp();
            let mut value = p * omega * omega * (k * (-2.0 * draft + dz)).exp();
            for h in sums.iter_mut() {
                *h += value;
                value *= growth;
            }
        }
        let gram = DMatrix::from_fn(strips, strips, |j, l| sums[j + l]);
        let eigen = SymmetricEigen::new(gram);
        let mut order: Vec<usize> = (0..strips).collect();
        order.sort_by(|&a, &b| eigen.eigenvalues[b].total_cmp(&eigen.eigenvalues[a]));
        let lambda: Vec<f64> = order
            .iter()
            .map(|&q| eigen.eigenvalues[q].max(0.0))
            .collect();
        let total: f64 = lambda.iter().sum();
        let mut rank = 0;
        let mut left = total;
        while rank < strips.min(MAX_RANK) && left > KINEMATICS_TOLERANCE.powi(2) * total {
            left -= lambda[rank];
            rank += 1;
        }
        let left: f64 = lambda[rank..].iter().sum();
        let mut mix = Vec::with_capacity(rank * strips);
        let mut profiles = Vec::with_capacity(rank * count);
        for &q in &order[..rank] {
            let v = eigen.eigenvectors.column(q);
            mix.extend(v.iter().copied());
            let start = profiles.len();
            profiles.resize(start + count, 0.0);
            let profile = &mut profiles[start..];
            for (&vj, column) in v.iter().zip(kernel.chunks_exact(count)) {
                for (p, &k) in profile.iter_mut().zip(column) {
                    *p += vj * k;
                }
            }
        }
        DepthBasis {
            draft,
            strips,
            power: power.to_vec(),
            profiles,
            mix,
            rank,
            discarded: if total > 0.0 {
                (left / total).sqrt()
            } else {
                0.0
            },
        }
    }

    /// Whether this is the basis of a column of `draft` with `strips` strips on these
    /// components' grid and spectrum.
    pub fn fits(&self, components: &WaveComponents, draft: f64, strips: usize) -> bool {
        self.fits_draft(draft, strips) && self.is_on(components)
    }

    /// Whether this is the basis of a column of `draft` with `strips` strips (on whatever
    /// grid and spectrum).
    pub fn fits_draft(&self, draft: f64, strips: usize) -> bool {
        self.draft == draft && self.strips == strips
    }

    /// Whether this basis was made on these components' grid and spectrum (their expected
    /// power, which every block of a stream shares).
    pub fn is_on(&self, components: &WaveComponents) -> bool {
        self.power == components.expected_power()
    }

    /// The number of terms kept, R.
    pub fn rank(&self) -> usize {
        self.rank
    }

    /// The expected relative rms velocity error of the truncation (<= the tolerance).
    pub fn discarded(&self) -> f64 {
        self.discarded
    }

    /// (K V)_iq of term q over the band's components i.
    pub fn profile(&self, q: usize) -> &[f64] {
        let count = self.profiles.len() / self.rank.max(1);
        &self.profiles[q * count..(q + 1) * count]
    }

    /// V_jq of term q over the strips j.
    pub fn mix(&self, q: usize) -> &[f64] {
        &self.mix[q * self.strips..(q + 1) * self.strips]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sea_state::{SeaState, Spectrum, Spreading};

    /// The kernels of drafts of 30 to 120 m with 12 to 200 strips, on the default sea's
    /// grid (JONSWAP Hs 6 m, Tp 10 s, a 16 384-s block at 0.5 s), meet the tolerance with
    /// fewer terms than the cap (which bounds the records' memory): the cap does not bind.
    #[test]
    fn the_rank_stays_below_its_cap() {
        let sea = SeaState {
            spectrum: Spectrum::Jonswap {
                hs: 6.0,
                tp: 10.0,
                gamma: Some(3.3),
            },
            spreading: Spreading::LongCrested,
            mean_direction: 0.0,
            n_directions: 1,
            seed: 1,
            band: None,
        };
        let grid = FrequencyGrid::new(0.0, 16384.0, 0.5, sea.band()).unwrap();
        let power = WaveComponents::expected_power_of(&sea, &grid);
        for draft in [30.0, 60.0, 120.0] {
            for strips in [12, 20, 40, 200] {
                let basis = DepthBasis::new(&grid, &power, draft, strips, 9.80665);
                println!("draft {draft} m, {strips} strips: rank {}", basis.rank());
                assert!(
                    basis.discarded() <= KINEMATICS_TOLERANCE,
                    "{draft} {strips}"
                );
                assert!(
                    basis.rank() < MAX_RANK,
                    "{draft} {strips}: {}",
                    basis.rank()
                );
            }
        }
    }
}
