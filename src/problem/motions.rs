//! The first-order (wave-frequency) motions a problem's data and configuration give: the
//! RAOs (docs/theory.md#first-order-motions-raos) and where they came from.
//!
//! One rule (docs/configuration.md, "First-order motions"):
//! - `[platform.motions]` given: the RAOs are solved from the data's first-order
//!   coefficients (a WAMIT import's `.1`, `.3` or `.2` and `.hst`) with the body's mass
//!   matrix (the platform's mass, `Problem::inertia`, with the centre of gravity and inertia
//!   of `[platform.motions]`), the weight's restoring (-m g z_g in roll and pitch: the data's
//!   hydrostatics hold the buoyancy's part alone, as WAMIT writes `.hst` for a body whose
//!   mass it was not given), and the section's external stiffness and damping. Data without
//!   first-order coefficients are an error naming the section.
//! - not given: the RAOs the data hold, if any (a WAMIT `.4`; NEMOH's, solved at import
//!   with its Mechanics/);
//! - else none.
//!
//! Units: RAOs per unit wave amplitude, m/m (surge, sway, heave) and rad/m (roll, pitch,
//! yaw), Re{xi e^{i omega t}} about the body reference point.

use super::Problem;
use crate::error::numbers::written;
use crate::error::{require_finite, require_finite_matrix, require_positive, Error, Result};
use crate::hydro::rao::{self, BodyMatrices, FirstOrder, Rao};
use crate::hydro::rigid_body::RigidBody;
use crate::scenario::{BodyInertia, Motions};

/// The names of the six DOFs, in order.
pub const DOF_NAMES: [&str; 6] = ["surge", "sway", "heave", "roll", "pitch", "yaw"];

/// Fixed-point iterations for a natural frequency with frequency-dependent added mass.
const PERIOD_ITERATIONS: usize = 200;

/// The RAOs of a problem and where they came from.
#[derive(Debug, Clone, PartialEq)]
pub struct FirstOrderMotions {
    pub rao: Rao,
    /// Where the RAOs came from, one phrase for the summary.
    pub source: String,
    /// The uncoupled natural periods of heave, roll and pitch where the body is restored
    /// there, s: 2 pi / omega_n with omega_n^2 = C_ii / (M_ii + A_ii(omega_n)) (A
    /// interpolated linearly in omega, held at the grid's ends); solved RAOs only.
    pub natural_periods: Vec<(&'static str, f64)>,
}

impl Problem {
    /// The first-order motions of the module's rule: `None` where the problem has none.
    pub fn first_order_motions(&self) -> Result<Option<FirstOrderMotions>> {
        let data = &self.hydro.body;
        let Some(motions) = &self.platform.motions else {
            return Ok(data.rao.as_ref().map(|table| FirstOrderMotions {
                rao: table.to_rao(),
                source: format!("held by {}", data.name),
                natural_periods: Vec::new(),
            }));
        };
        let Some(first_order) = &data.first_order else {
            return Err(Error::invalid(
                "platform.motions",
                "a rigid body",
                format!(
                    "needs the first-order coefficients of a radiation-diffraction code, and \
                     {} has none (a database made by slowdrift hydro wamit from the .1, .3 or \
                     .2 and .hst files, or by slowdrift hydro nemoh from its .tec results, has \
                     them)",
                    self.hydro.source
                ),
            ));
        };
        check(motions)?;
        let mass = self.inertia()?.mass;
        let body = rigid_body(mass, motions);
        let weight = body.weight_stiffness(self.environment.gravity);
        let matrices = BodyMatrices {
            mass: body.mass_matrix(),
            stiffness: std::array::from_fn(|i| {
                std::array::from_fn(|j| weight[i][j] + motions.external_stiffness[i][j])
            }),
            damping: motions.external_damping,
        };
        let rao = rao::solve(first_order, &matrices)?;
        Ok(Some(FirstOrderMotions {
            rao,
            source: format!(
                "solved from the first-order coefficients of {} with [platform.motions]",
                data.name
            ),
            natural_periods: natural_periods(first_order, &matrices),
        }))
    }
}

impl Problem {
    /// The share of the simulated band's elevation variance at frequencies the RAOs do not
    /// reach (below their first or above their last frequency), where the wave-frequency
    /// motion takes them as zero (`forces::motion`); and the RAOs' range, rad/s.
    pub fn rao_gap(&self, rao: &Rao) -> (f64, (f64, f64)) {
        let (lo, hi) = (rao.omegas[0], rao.omegas[rao.omegas.len() - 1]);
        let (a, b) = self.band();
        let tolerance = crate::model::FREQUENCY_MATCH_TOLERANCE;
        let below = if a < lo * (1.0 - tolerance) {
            self.sea_variance(a, lo.min(b))
        } else {
            0.0
        };
        let above = if b > hi * (1.0 + tolerance) {
            self.sea_variance(hi.max(a), b)
        } else {
            0.0
        };
        let total = self.sea_variance(a, b);
        let share = if total > 0.0 {
            (below + above) / total
        } else {
            0.0
        };
        (share, (lo, hi))
    }

    /// [`Problem::rao_gap`] within [`super::DEFAULT_BAND_TRIM_LIMIT`] of the band's variance,
    /// else refused naming the first-order motions, the RAOs' range and the band.
    pub fn check_rao_gap(&self, rao: &Rao) -> Result<()> {
        let (share, (lo, hi)) = self.rao_gap(rao);
        if share <= super::DEFAULT_BAND_TRIM_LIMIT {
            return Ok(());
        }
        let (a, b) = self.band();
        Err(Error::invalid(
            "first-order motions",
            format!("RAOs on [{}, {}] rad/s", written(lo), written(hi)),
            format!(
                "leave out {:.1} % of the variance of the wave band [{a:.4}, {b:.4}] rad/s (at \
                 most {} % may be left without motion; nothing is extrapolated): narrow [sea] \
                 band, give RAOs over the band, or turn the wave-frequency motion off ([model] \
                 wave_frequency_motion = \"off\")",
                share * 100.0,
                super::DEFAULT_BAND_TRIM_LIMIT * 100.0
            ),
        ))
    }
}

/// The rigid body of `[platform.motions]` with the platform's `mass`.
fn rigid_body(mass: f64, motions: &Motions) -> RigidBody {
    match motions.inertia {
        BodyInertia::RadiiOfGyration(radii) => {
            RigidBody::from_radii_of_gyration(mass, motions.centre_of_gravity, radii)
        }
        BodyInertia::Tensor(inertia) => RigidBody {
            mass,
            centre_of_gravity: motions.centre_of_gravity,
            inertia,
        },
    }
}

/// Checks `[platform.motions]`, naming its keys: finite values, positive radii of
/// gyration, a symmetric tensor whose principal moments are positive and satisfy the
/// triangle inequality (I_1 + I_2 >= I_3: a body's, of any mass distribution).
fn check(motions: &Motions) -> Result<()> {
    for (k, v) in motions.centre_of_gravity.iter().enumerate() {
        require_finite(format_args!("platform.motions.centre_of_gravity[{k}]"), *v)?;
    }
    match &motions.inertia {
        BodyInertia::RadiiOfGyration(radii) => {
            for (k, r) in radii.iter().enumerate() {
                require_positive(&format!("platform.motions.radii_of_gyration[{k}]"), *r)?;
            }
        }
        BodyInertia::Tensor(tensor) => check_tensor(tensor)?,
    }
    require_finite_matrix(
        "platform.motions.external_stiffness",
        &motions.external_stiffness,
    )?;
    require_finite_matrix(
        "platform.motions.external_damping",
        &motions.external_damping,
    )
}

/// An inertia tensor a body can have (see [`check`]).
fn check_tensor(tensor: &[[f64; 3]; 3]) -> Result<()> {
    const KEY: &str = "platform.motions.inertia";
    require_finite_matrix(KEY, tensor)?;
    for (i, j) in [(1, 0), (2, 0), (2, 1)] {
        let (a, b) = (tensor[i][j], tensor[j][i]);
        if a != b {
            return Err(Error::invalid(
                format!("{KEY}[{i}][{j}]"),
                written(a),
                format!("the tensor must be symmetric: [{j}][{i}] = {}", written(b)),
            ));
        }
    }
    let m = nalgebra::Matrix3::from_fn(|i, j| tensor[i][j]);
    let mut moments: Vec<f64> = m.symmetric_eigenvalues().iter().copied().collect();
    moments.sort_by(f64::total_cmp);
    if moments[0] <= 0.0 || moments[0] + moments[1] < moments[2] * (1.0 - 1e-12) {
        return Err(Error::invalid(
            KEY,
            format!(
                "principal moments {}, {}, {} kg m^2",
                written(moments[0]),
                written(moments[1]),
                written(moments[2])
            ),
            "no body has them: each must be positive and none larger than the sum of the \
             other two",
        ));
    }
    Ok(())
}

/// The uncoupled natural periods of heave, roll and pitch (see
/// [`FirstOrderMotions::natural_periods`]) where the total stiffness C_hs + C_ext is
/// positive, by the fixed-point iteration omega <- sqrt(C / (M + A(omega))) from
/// A(lowest frequency) until it moves by less than 1e-12 relative.
fn natural_periods(first_order: &FirstOrder, body: &BodyMatrices) -> Vec<(&'static str, f64)> {
    let mut periods = Vec::new();
    // Heave, roll and pitch.
    for (i, dof) in DOF_NAMES.iter().enumerate().take(5).skip(2) {
        let c = first_order.hydrostatics[i][i] + body.stiffness[i][i];
        if c <= 0.0 {
            continue;
        }
        let added =
            |w: f64| interpolate(&first_order.omegas, |n| first_order.added_mass[n][i][i], w);
        let mut w = (c / (body.mass[i][i] + added(0.0))).sqrt();
        let mut converged = false;
        for _ in 0..PERIOD_ITERATIONS {
            let next = (c / (body.mass[i][i] + added(w))).sqrt();
            converged = (next - w).abs() <= 1e-12 * w;
            w = next;
            if converged {
                break;
            }
        }
        // A mass matrix with M_ii + A_ii <= 0 somewhere, or an iteration that does not
        // settle: no period stated.
        if converged && w.is_finite() && w > 0.0 {
            periods.push((*dof, 2.0 * std::f64::consts::PI / w));
        }
    }
    periods
}

/// `value(n)` at the grid `omegas` interpolated linearly at `w`, held at the ends.
fn interpolate(omegas: &[f64], value: impl Fn(usize) -> f64, w: f64) -> f64 {
    let last = omegas.len() - 1;
    if w <= omegas[0] {
        return value(0);
    }
    if w >= omegas[last] {
        return value(last);
    }
    let k = omegas.partition_point(|&o| o <= w) - 1;
    let t = (w - omegas[k]) / (omegas[k + 1] - omegas[k]);
    value(k) + t * (value(k + 1) - value(k))
}
