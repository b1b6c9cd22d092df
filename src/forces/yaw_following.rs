//! Wave force and damping records that follow the body's yaw
//! (docs/theory.md#the-slowly-varying-force; E&S fig. 2 estimate about 10 % error at 5 deg if
//! ignored).
//!
//! Convention: with the body at yaw theta, a wave propagating towards beta (inertial frame)
//! meets it at the relative heading beta - theta (the drift table's heading, from body x),
//! so the body-frame force D(t; theta) is the mean-position record of the same sea rotated
//! by -theta. Records of D_i and B_ij are built once at body yaw angles theta_j from the
//! same amplitudes (the same sea; only the transfers change, the FFT plan, its scratch and
//! the arithmetic form's elevation series are shared) and interpolated linearly in the
//! instantaneous theta at every RK4 stage:
//!
//!   D(t; theta) = (1 - s) D(t; theta_j) + s D(t; theta_{j+1}),  s = (theta - theta_j) / d_theta.
//!
//! Interpolation error (the linear Lagrange remainder): at each t,
//!   |D(t; theta) - D_lin| <= (theta - theta_j)(theta_{j+1} - theta)/2 max |d^2 D / d theta^2|
//!                        <= d_theta^2 / 8 max |d^2 D / d theta^2| over the interval.
//! Linear because the drift table is itself bilinear in heading: the transfers are only
//! piecewise linear in theta, so a higher order would not converge faster across the
//! table's heading nodes; linear reads two samples per record and stage and reproduces the
//! records exactly at the grid yaws.
//!
//! Memory: headings x (3 force + the non-zero damping records) x N x 8 bytes (N the record
//! length): the default platform's 3-hour record at h = 1 s (N = 21 609, 3 + 7 records)
//! holds 1.73 MB per heading, 62 MB for 36 headings.
//!
//! The elevation and the drag columns' kinematics stay at the mean position and zero yaw.

use super::newman::{NewmanBuilder, NewmanTransfer};
use super::qtf::QtfGroup;
use super::synthesis::{InverseFft, Synthesizer};
use super::transfer::transfers_on_grid;
use super::transfer::DirectionTransfer;
use super::{record_or_zero, take_samples, ForceRecords, Record, SamplePoint};
use crate::error::{Error, Result};
use crate::hydro::DriftTable;
use crate::model::{NewmanForm, YawFollowing};
use crate::sea_state::{Direction, FrequencyGrid, WaveComponents};
use rustfft::num_complex::Complex64;
use std::f64::consts::PI;

/// A fraction this close to a grid yaw (in units of the spacing) is that grid yaw, so a yaw
/// that sits a rounding error off theta_j reads record j exactly.
const SNAP: f64 = 1e-9;

/// The body yaw angles theta_j of the records.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct YawGrid {
    count: usize,
    /// `None`: the full circle, theta_j = 2 pi (j / count - 1/2), periodic.
    range: Option<(f64, f64)>,
}

/// Where a yaw falls on a [`YawGrid`]: records `lo` and `hi` with weights 1 - frac, frac.
/// With yaw following off it points at the mean-position records.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct YawPoint {
    lo: usize,
    hi: usize,
    frac: f64,
}

impl YawPoint {
    /// (lo, hi, frac): records `lo` and `hi` weigh 1 - frac and frac.
    pub(super) fn parts(&self) -> (usize, usize, f64) {
        (self.lo, self.hi, self.frac)
    }

    /// The mean-position records (yaw following off).
    pub const MEAN_POSITION: YawPoint = YawPoint {
        lo: 0,
        hi: 0,
        frac: 0.0,
    };
}

impl YawGrid {
    /// The grid of a (validated: at least 2 headings, min < max) configuration.
    pub fn new(options: &YawFollowing) -> Self {
        YawGrid {
            count: options.headings,
            range: options.range,
        }
    }

    /// Number of yaw angles.
    pub fn len(&self) -> usize {
        self.count
    }

    /// Never empty (at least 2 yaw angles); for clippy's `len_without_is_empty`.
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// Whether the grid covers the full circle (and any yaw).
    pub fn is_periodic(&self) -> bool {
        self.range.is_none()
    }

    /// theta_j, rad. Zero is a grid yaw exactly when the count is even (full circle) or
    /// the range is symmetric and the count odd.
    pub fn yaw(&self, j: usize) -> f64 {
        let n = self.count;
        match self.range {
            None => 2.0 * PI * (j as f64 / n as f64 - 0.5),
            Some((_, max)) if j == n - 1 => max,
            Some((min, max)) => min + (max - min) * (j as f64 / (n - 1) as f64),
        }
    }

    /// Spacing of the yaw angles, rad.
    pub fn spacing(&self) -> f64 {
        match self.range {
            None => 2.0 * PI / self.count as f64,
            Some((min, max)) => (max - min) / (self.count - 1) as f64,
        }
    }

    /// Locates `yaw` (rad, any number of turns on the full circle); a yaw outside a range is
    /// [`Error::YawOutsideRecords`] at `time`.
    pub fn locate(&self, time: f64, yaw: f64) -> Result<YawPoint> {
        let n = self.count;
        let position = match self.range {
            None => ((yaw / (2.0 * PI) + 0.5) * n as f64).rem_euclid(n as f64),
            Some((min, max)) => {
                if !(min..=max).contains(&yaw) {
                    return Err(Error::YawOutsideRecords {
                        time,
                        yaw,
                        covered: (min, max),
                    });
                }
                (yaw - min) / (max - min) * (n - 1) as f64
            }
        };
        let last = if self.is_periodic() { n - 1 } else { n - 2 };
        let mut lo = (position.floor() as usize).min(last);
        let mut frac = position - lo as f64;
        if frac > 1.0 - SNAP {
            lo += 1;
            frac = 0.0;
        } else if frac < SNAP {
            frac = 0.0;
        }
        // Past the last node only the periodic grid can step: it wraps to node 0.
        if lo == n {
            lo = 0;
        }
        let hi = if frac == 0.0 { lo } else { (lo + 1) % n };
        Ok(YawPoint { lo, hi, frac })
    }
}

/// The wave force and damping records of one body yaw angle.
#[derive(Debug, Clone, PartialEq)]
pub struct SlowRecords {
    /// D_i(t; theta_j), body frame: surge, sway (N), yaw (N m).
    pub wave_force: [Record; 3],
    /// B_ij(t; theta_j), rows force, columns velocity; `None` when off.
    pub damping: Option<[[Record; 3]; 3]>,
}

/// Records at every yaw of a [`YawGrid`].
#[derive(Debug, Clone, PartialEq)]
pub struct YawFollowingRecords {
    pub grid: YawGrid,
    /// One set per theta_j, in grid order.
    pub sets: Vec<SlowRecords>,
}

impl YawFollowingRecords {
    /// Builds the records at every theta_j over the grid's period: for each, the table
    /// interpolated at the relative headings beta_k - theta_j of every wave direction k
    /// ([`yaw_transfers`]), then Newman's construction in `form` (the same as
    /// [`ForceRecords::build`] at zero yaw). `table` holds the damping when `with_damping`.
    /// A table whose headings do not cover every relative heading is refused, naming the
    /// gap. Cost: per yaw, one or two FFTs per non-zero coefficient record and direction.
    pub fn build(
        components: &WaveComponents,
        grid: YawGrid,
        table: &DriftTable,
        with_damping: bool,
        form: NewmanForm,
        fft: &InverseFft,
    ) -> Result<Self> {
        let transfers = yaw_transfers(
            table,
            &components.grid,
            &components.directions,
            &grid,
            with_damping,
        )?;
        let transfers: Vec<Vec<NewmanTransfer>> = transfers
            .iter()
            .map(|t| NewmanTransfer::all(form, t))
            .collect();
        let mut synth = Synthesizer::with_fft(&components.grid, fft.clone());
        let mut builder = NewmanBuilder::new(components.grid.count);
        let mut records = YawFollowingRecords {
            grid,
            sets: Vec::new(),
        };
        records.rebuild(
            components,
            &transfers,
            None,
            form,
            &mut synth,
            &mut builder,
            &mut YawWork::default(),
        );
        Ok(records)
    }

    /// [`YawFollowingRecords::build`] into these records (their buffers reused), from the
    /// transfers of every yaw ([`yaw_transfers`]) prepared for `form` ([`NewmanTransfer`]),
    /// through `synth` (a stream's segment when
    /// joined). With `full_qtf` (one set of groups per yaw, the QTF at the relative headings
    /// beta_k - theta_j), the wave force of each yaw comes from the full QTF instead of
    /// Newman's form; the damping stays Newman's, from the transfers.
    #[allow(clippy::too_many_arguments)]
    pub fn rebuild(
        &mut self,
        components: &WaveComponents,
        transfers: &[Vec<NewmanTransfer>],
        full_qtf: Option<&[Vec<QtfGroup>]>,
        form: NewmanForm,
        synth: &mut Synthesizer,
        builder: &mut NewmanBuilder,
        work: &mut YawWork,
    ) {
        let len = synth.output_len();
        let directions = components.directions.len();
        // The arithmetic form's complex elevation series: per direction, independent of yaw.
        work.eta_c.resize_with(directions, Vec::new);
        for (k, series) in work.eta_c.iter_mut().enumerate() {
            match form {
                NewmanForm::Geometric => series.clear(),
                NewmanForm::Arithmetic => {
                    series.resize(len, Complex64::default());
                    synth.complex_series(components.of_direction(k), series);
                }
            }
        }
        self.sets.resize_with(transfers.len(), || SlowRecords {
            wave_force: Default::default(),
            damping: None,
        });
        for (j, (set, transfers)) in self.sets.iter_mut().zip(transfers).enumerate() {
            let with_damping = transfers.iter().any(|t| t.damping.is_some());
            let mut force: [Vec<f64>; 3] =
                std::array::from_fn(|i| take_samples(&mut set.wave_force[i]));
            let mut damping: [[Vec<f64>; 3]; 3] = match &mut set.damping {
                Some(d) => {
                    std::array::from_fn(|i| std::array::from_fn(|j| take_samples(&mut d[i][j])))
                }
                None => Default::default(),
            };
            for (k, transfer) in transfers.iter().enumerate() {
                let amplitudes = components.of_direction(k);
                let e = &work.eta_c[k];
                if full_qtf.is_none() {
                    builder.accumulate_force(synth, amplitudes, e, transfer, &mut force);
                }
                builder.accumulate_damping(synth, amplitudes, e, transfer, &mut damping);
            }
            for group in full_qtf.map_or(&[][..], |q| &q[j][..]) {
                work.qtf_coefficients
                    .resize(components.grid.count, Complex64::default());
                work.qtf_series.resize(len, Complex64::default());
                group.accumulate(
                    synth,
                    components,
                    &mut work.qtf_coefficients,
                    &mut work.qtf_series,
                    &mut force,
                );
            }
            set.wave_force = force.map(record_or_zero);
            set.damping = with_damping.then(|| damping.map(|row| row.map(record_or_zero)));
        }
    }

    /// Bytes held by the samples of every record.
    pub fn bytes(&self) -> usize {
        self.sets
            .iter()
            .flat_map(|s| {
                s.wave_force
                    .iter()
                    .chain(s.damping.iter().flatten().flatten())
            })
            .map(|r| std::mem::size_of_val(r.samples()))
            .sum()
    }
}

/// The buffers of yaw-following builds, kept from one build to the next (a stream's
/// segments).
#[derive(Default, Clone)]
pub struct YawWork {
    eta_c: Vec<Vec<Complex64>>,
    /// Scratch of the full-QTF synthesis.
    qtf_coefficients: Vec<Complex64>,
    qtf_series: Vec<Complex64>,
}

/// The coefficients of every yaw theta_j of `grid` and every wave direction k, at the
/// relative headings beta_k - theta_j (seed-independent: made once per plan). A table
/// whose headings do not cover every relative heading is refused, naming the gap.
pub fn yaw_transfers(
    table: &DriftTable,
    freq: &FrequencyGrid,
    directions: &[Direction],
    grid: &YawGrid,
    with_damping: bool,
) -> Result<Vec<Vec<DirectionTransfer>>> {
    check_relative_headings(table, directions, grid)?;
    (0..grid.len())
        .map(|j| {
            let theta = grid.yaw(j);
            let relative: Vec<Direction> = directions
                .iter()
                .map(|d| Direction {
                    heading: d.heading - theta,
                    weight: d.weight,
                })
                .collect();
            transfers_on_grid(table, freq, &relative, with_damping)
        })
        .collect()
}

/// Refuses a table that lacks a relative heading beta_k - theta_j, naming the uncovered
/// spans (below the table's first heading and above its last, in degrees) and what the
/// table covers.
fn check_relative_headings(
    table: &DriftTable,
    directions: &[Direction],
    grid: &YawGrid,
) -> Result<()> {
    let headings = table.headings();
    let (first, last) = (headings[0], headings[headings.len() - 1]);
    // The band is checked by `transfers_on_grid`; here only the headings.
    let band = (table.omegas()[0], table.omegas()[0]);
    let widen = |span: Option<(f64, f64)>, v: f64| match span {
        None => Some((v, v)),
        Some((lo, hi)) => Some((f64::min(lo, v), f64::max(hi, v))),
    };
    let (mut below, mut above) = (None, None);
    for d in directions {
        for j in 0..grid.len() {
            let relative = d.heading - grid.yaw(j);
            if table.check_covers(band, &[relative]).is_err() {
                // Uncovered headings lie in (last, first + 2 pi) once wrapped; name each by
                // its distance to the nearer end of the table.
                let wrapped = first + (relative - first).rem_euclid(2.0 * PI);
                if wrapped - last <= first + 2.0 * PI - wrapped {
                    above = widen(above, wrapped);
                } else {
                    below = widen(below, wrapped - 2.0 * PI);
                }
            }
        }
    }
    let deg = |v: f64| format!("{:.3}", v.to_degrees());
    let spans: Vec<String> = [below, above]
        .into_iter()
        .flatten()
        .map(|(lo, hi)| format!("[{}, {}] deg", deg(lo), deg(hi)))
        .collect();
    if spans.is_empty() {
        return Ok(());
    }
    let yaws = match grid.range {
        None => "the full circle".to_string(),
        Some((min, max)) => format!("[{}, {}] deg", deg(min), deg(max)),
    };
    Err(Error::invalid(
        "model.yaw_following",
        format!("{} headings over {yaws}", grid.len()),
        format!(
            "the drift table's headings cover [{}, {}] deg only; the relative headings \
             (wave direction - yaw) {} are not covered (never extrapolated): extend the \
             table's headings or narrow model.yaw_following.range_deg",
            deg(first),
            deg(last),
            spans.join(" and ")
        ),
    ))
}

impl ForceRecords {
    /// Locates the body's yaw among the yaw-following records; with yaw following off,
    /// [`YawPoint::MEAN_POSITION`]. An error when the yaw is outside their range.
    #[inline]
    pub fn locate_yaw(&self, time: f64, yaw: f64) -> Result<YawPoint> {
        match &self.yaw_following {
            None => Ok(YawPoint::MEAN_POSITION),
            Some(y) => y.grid.locate(time, yaw),
        }
    }

    /// The slowly varying wave force D(t) at a located time and yaw (body frame).
    #[inline]
    pub fn wave_force_at(&self, at: &SamplePoint, yaw: &YawPoint) -> [f64; 3] {
        match &self.yaw_following {
            None => std::array::from_fn(|i| self.wave_force[i].at(at)),
            Some(y) => {
                let (lo, hi) = (&y.sets[yaw.lo], &y.sets[yaw.hi]);
                std::array::from_fn(|i| blend(&lo.wave_force[i], &hi.wave_force[i], at, yaw))
            }
        }
    }

    /// The wave-drift damping B(t) at a located time and yaw; `None` when off.
    #[inline]
    pub fn damping_at(&self, at: &SamplePoint, yaw: &YawPoint) -> Option<[[f64; 3]; 3]> {
        match &self.yaw_following {
            // `from_fn`, which inlines here, rather than `map`, which did not.
            None => self
                .damping
                .as_ref()
                .map(|b| std::array::from_fn(|i| std::array::from_fn(|j| b[i][j].at(at)))),
            Some(y) => {
                let (lo, hi) = (
                    y.sets[yaw.lo].damping.as_ref()?,
                    y.sets[yaw.hi].damping.as_ref()?,
                );
                Some(std::array::from_fn(|i| {
                    std::array::from_fn(|j| blend(&lo[i][j], &hi[i][j], at, yaw))
                }))
            }
        }
    }

    /// Asks the CPU to bring sample `m` of the records read at every step (the wave force,
    /// the damping, the gust) into its caches, so that a step's reads do not wait on
    /// memory: without it, their dozens of streams (a dozen records per seed, four seeds in
    /// lanes) are more than the CPU's own prefetcher follows. A hint, which changes no
    /// result. The yaw-following records are left to the CPU: which of them a step reads
    /// depends on its yaw.
    pub fn prefetch(&self, m: usize) {
        self.wave_force.iter().for_each(|r| r.prefetch(m));
        if let Some(b) = &self.damping {
            b.iter().flatten().for_each(|r| r.prefetch(m));
        }
        if let Some(gust) = &self.gust {
            gust.prefetch(m);
        }
    }
}

/// (1 - frac) lo + frac hi at a located time; exactly `lo` at frac = 0.
#[inline]
fn blend(lo: &Record, hi: &Record, at: &SamplePoint, yaw: &YawPoint) -> f64 {
    let a = lo.at(at);
    if yaw.frac == 0.0 {
        a
    } else {
        a + yaw.frac * (hi.at(at) - a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(count: usize, range: Option<(f64, f64)>) -> YawGrid {
        YawGrid::new(&YawFollowing {
            headings: count,
            range,
        })
    }

    #[test]
    fn zero_is_a_grid_yaw_exactly() {
        let circle = grid(36, None);
        assert_eq!(circle.yaw(18), 0.0);
        let p = circle.locate(0.0, 0.0).unwrap();
        assert_eq!((p.lo, p.frac), (18, 0.0));
        let range = grid(13, Some((-0.3, 0.3)));
        assert_eq!(range.yaw(6), 0.0);
        assert_eq!(range.yaw(12), 0.3);
        assert_eq!(range.locate(0.0, 0.0).unwrap().lo, 6);
    }

    #[test]
    fn every_grid_yaw_is_located_on_its_node() {
        for g in [grid(36, None), grid(7, Some((-0.2, 0.5)))] {
            for j in 0..g.len() {
                let p = g.locate(0.0, g.yaw(j)).unwrap();
                assert_eq!((p.lo, p.hi, p.frac), (j, j, 0.0), "{g:?} node {j}");
            }
        }
    }

    #[test]
    fn fractions_between_nodes_and_around_the_circle() {
        let g = grid(36, None);
        let step = g.spacing();
        let p = g.locate(0.0, 0.25 * step).unwrap();
        assert_eq!((p.lo, p.hi), (18, 19));
        assert!((p.frac - 0.25).abs() < 1e-12);
        // Just below +pi wraps to the node at -pi; several turns are the same yaw.
        let p = g.locate(0.0, PI - 0.5 * step).unwrap();
        assert_eq!((p.lo, p.hi), (35, 0));
        assert!((p.frac - 0.5).abs() < 1e-12);
        let q = g.locate(0.0, 0.25 * step + 4.0 * PI).unwrap();
        assert_eq!((q.lo, q.hi), (18, 19));
        assert!((q.frac - 0.25).abs() < 1e-9);
        let r = grid(5, Some((-0.2, 0.2)));
        let p = r.locate(0.0, 0.15).unwrap();
        assert_eq!((p.lo, p.hi), (3, 4));
        assert!((p.frac - 0.5).abs() < 1e-12);
    }

    #[test]
    fn a_yaw_outside_the_range_is_refused_naming_it() {
        let g = grid(5, Some((-0.2, 0.2)));
        let e = g.locate(12.5, 0.2 + 1e-12).unwrap_err();
        assert!(
            matches!(e, Error::YawOutsideRecords { yaw, covered: (-0.2, 0.2), .. } if yaw > 0.2)
        );
        let text = e.to_string();
        assert!(text.contains("11.4592 deg"), "{text}");
        assert!(text.contains("[-11.4592, 11.4592] deg"), "{text}");
        assert!(text.contains("t = 12.5 s"), "{text}");
        assert!(g.locate(0.0, f64::NAN).is_err());
        assert!(g.locate(0.0, -0.2).is_ok());
    }
}
