//! Morison drag on vertical columns in strips from the keel to the instantaneous free
//! surface (E&S 8, 9; docs/theory.md#viscous-drag).
//!
//! On a strip of height dz and diameter D, with U the column's slow velocity relative to
//! the current (body motion minus current, including the yaw-rate term) and u the fast
//! wave-particle velocity, the force on the body is
//! - separate model (E&S 8): dF = 1/2 rho D dz (C_DS (-U)|U| + C_DL u|u|)
//! - combined model (E&S 9): dF = 1/2 rho D dz C_D w|w|, w = u - U
//!
//! with |.| the horizontal vector norm. Everything is in the body frame.

mod lanes;
mod sums;

pub use lanes::{drag_forces, LaneDrag, LANES};

use super::kinematics::{ColumnKinematics, ColumnState, Kinematics, StripVelocities};
use super::record::SamplePoint;
use super::value::Value;
use crate::model::{Cylinder, DragModel};
use sums::{single, StripSums};

/// Drag on the body, body frame: (Fx, Fy, Mz).
///
/// `velocity` is the body's slow velocity in the body frame (u, v, r) and `current` the
/// current velocity in the body frame (x, y components).
pub fn drag_force(
    kinematics: &Kinematics,
    at: &SamplePoint,
    model: DragModel,
    water_density: f64,
    velocity: [f64; 3],
    current: [f64; 2],
) -> [f64; 3] {
    let mut total = [0.0; 3];
    if model == DragModel::Off {
        return total;
    }
    let mut seen = SeenSums::new();
    for col in kinematics.columns() {
        let state = col.at(at);
        let column = (col.column, col.strips());
        let strips = ColumnStrips::of(column, state.eta(), model, water_density, velocity, current);
        let bits = single_bits(strips.offset);
        let fast = seen.sum(col.group(), bits, || {
            strip_sum(&state, col.strips(), strips.offset)
        });
        strips.add_force(&mut total, column, model, fast);
    }
    total
}

/// The column groups a drag evaluation remembers the strip sums of ([`SeenSums`]).
const SEEN: usize = 8;

/// The strip sums taken at one instant, by column group (the first [`SEEN`] groups), with
/// the offsets they were taken at (`B`: their bits in single precision). A strip sum
/// depends on the row (or the interpolated strips) and the offset rounded to single
/// precision alone ([`StripSums`]), and the columns of a group read the same kinematics: a
/// column whose group was summed at offsets that round to the same floats has that sum, bit
/// for bit. In head seas the two columns of a group at the same x move alike and see the
/// same current, so one sum serves both.
struct SeenSums<B, F> {
    sums: [Option<(B, F)>; SEEN],
}

impl<B: PartialEq + Copy, F: Copy> SeenSums<B, F> {
    fn new() -> Self {
        SeenSums { sums: [None; SEEN] }
    }

    /// Group `group`'s sums at the offsets `bits`: those remembered, else `make`'s
    /// (remembered for the next column of the group).
    #[inline]
    fn sum(&mut self, group: usize, bits: B, make: impl FnOnce() -> F) -> F {
        match self.sums.get_mut(group) {
            Some(Some((seen, sum))) if *seen == bits => *sum,
            Some(slot) => {
                let sum = make();
                *slot = Some((bits, sum));
                sum
            }
            None => make(),
        }
    }
}

/// An offset as the strip sums take it: rounded to single precision ([`single`]), as bits.
#[inline]
fn single_bits(offset: [f64; 2]) -> [u32; 2] {
    single(offset).map(f32::to_bits)
}

/// Adds one column's drag at a located instant to `total` (body frame (Fx, Fy, Mz)).
#[inline]
fn add_column_force(
    total: &mut [f64; 3],
    col: &ColumnKinematics,
    at: &SamplePoint,
    model: DragModel,
    water_density: f64,
    velocity: [f64; 3],
    current: [f64; 2],
) {
    let state = col.at(at);
    let column = (col.column, col.strips());
    let strips = ColumnStrips::of(column, state.eta(), model, water_density, velocity, current);
    let fast = strip_sum(&state, col.strips(), strips.offset);
    strips.add_force(total, column, model, fast);
}

/// One column's terms of E&S 8, 9 that are the same on all its strips, at one instant: one
/// seed's (`f64`), or the lanes' side by side ([`Wide`](crate::forces::Wide), each lane's
/// bits its seed's alone).
#[derive(Debug, Clone, Copy)]
struct ColumnStrips<V = f64> {
    /// The column's slow velocity relative to the current, U (body x, y), m/s.
    slow: [V; 2],
    /// What the strips' sum takes from each u_j: U in the combined model (w = u - U), 0 in
    /// the separate one (its fast term u|u|).
    offset: [V; 2],
    /// 1/2 rho D dz, dz the wetted length (keel to the free surface) over the strips.
    scale: V,
}

impl<V: Value> ColumnStrips<V> {
    /// The terms of column `c` of `strips` strips, for the free-surface elevation `eta` at
    /// its centre, the body's slow velocity (u, v, r) and the current (x, y) (body frame).
    #[inline]
    fn of(
        (c, strips): (&Cylinder, usize),
        eta: V,
        model: DragModel,
        water_density: f64,
        velocity: [V; 3],
        current: [V; 2],
    ) -> Self {
        let [u, v, r] = velocity;
        let slow = [
            u - r * V::splat(c.y) - current[0],
            v + r * V::splat(c.x) - current[1],
        ];
        let wetted = (V::splat(c.draft) + eta).max(V::splat(0.0));
        let dz = wetted / V::splat(strips as f64);
        let offset = match model {
            DragModel::Combined { .. } => slow,
            _ => [V::splat(0.0); 2],
        };
        ColumnStrips {
            slow,
            offset,
            scale: V::splat(0.5 * water_density * c.diameter) * dz,
        }
    }

    /// Adds the column's force (Fx, Fy) and its moment about the origin to `total`, from the
    /// strips' sum `fast` = sum_j w_j |w_j| (w_j = u_j - offset).
    #[inline]
    fn add_force(
        &self,
        total: &mut [V; 3],
        (c, strips): (&Cylinder, usize),
        model: DragModel,
        fast: [V; 2],
    ) {
        let (slow, splat) = (self.slow, V::splat);
        let f = match model {
            DragModel::Off => [splat(0.0); 2],
            DragModel::Combined { cd } => [splat(cd) * fast[0], splat(cd) * fast[1]],
            DragModel::Separate {
                slow: cds,
                fast: cdl,
            } => {
                // The slow term is the same on every strip.
                let s = splat(strips as f64)
                    * splat(cds)
                    * (slow[0] * slow[0] + slow[1] * slow[1]).sqrt();
                [
                    -s * slow[0] + splat(cdl) * fast[0],
                    -s * slow[1] + splat(cdl) * fast[1],
                ]
            }
        };
        total[0] = total[0] + self.scale * f[0];
        total[1] = total[1] + self.scale * f[1];
        total[2] = total[2] + self.scale * (splat(c.x) * f[1] - splat(c.y) * f[0]);
    }
}

/// Strips interpolated at a time between samples: their velocities sit in a buffer of
/// this length on the stack. Even, as [`StripSums::add`] takes it.
const CHUNK: usize = 32;

/// sum_j w_j |w_j| over the column's strips, w_j = u_j - offset: the strip sum of E&S 8, 9
/// before the coefficient and the factor 1/2 rho D dz, in single precision
/// ([`StripSums`]).
#[inline]
fn strip_sum(state: &ColumnState, strips: usize, offset: [f64; 2]) -> [f64; 2] {
    let (mut sums, offset) = (StripSums::default(), single(offset));
    match state.velocities_on_sample() {
        Some(StripVelocities::Interleaved(velocities)) => sums.add(velocities, offset),
        Some(StripVelocities::AlongX(velocities)) => sums.add(velocities, offset),
        None => {
            let mut buffer = [[0.0f32; 2]; CHUNK];
            for first in (0..strips).step_by(CHUNK) {
                let chunk = &mut buffer[..CHUNK.min(strips - first)];
                for (j, u) in chunk.iter_mut().enumerate() {
                    *u = single(state.velocity(first + j));
                }
                sums.add(chunk, offset);
            }
        }
    }
    sums.total()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::forces::kinematics::column_kinematics;
    use crate::forces::{RecordClock, Synthesizer};
    use crate::model::Cylinder;
    use crate::sea_state::{FrequencyGrid, SeaState, Spectrum, Spreading, WaveComponents};

    /// E&S 8 and 9 strip by strip, written out in double precision with `hypot` on each
    /// strip's velocities as the records give them (no pairs, no single precision), and
    /// the sizes that bound the single-precision strip sum's error ([`StripSums`]): scale c
    /// |w| (|o| + |u| + |w|) summed over the strips, o the sum's offset (times the lever
    /// |x| + |y| in yaw).
    fn by_strips(
        kinematics: &Kinematics,
        at: &SamplePoint,
        model: DragModel,
        velocity: [f64; 3],
        current: [f64; 2],
    ) -> ([f64; 3], [f64; 3]) {
        let mut total = [0.0; 3];
        let mut sizes = [0.0; 3];
        for col in kinematics.columns() {
            let c = col.column;
            let state = col.at(at);
            let n = col.strips();
            let dz = (c.draft + state.eta()).max(0.0) / n as f64;
            let slow = [
                velocity[0] - velocity[2] * c.y - current[0],
                velocity[1] + velocity[2] * c.x - current[1],
            ];
            for j in 0..n {
                let u = state.velocity(j);
                let (f, size) = match model {
                    DragModel::Off => ([0.0; 2], 0.0),
                    DragModel::Combined { cd } => {
                        let w = [u[0] - slow[0], u[1] - slow[1]];
                        let m = w[0].hypot(w[1]);
                        let reach = slow[0].hypot(slow[1]) + u[0].hypot(u[1]) + m;
                        ([cd * w[0] * m, cd * w[1] * m], cd * m * reach)
                    }
                    DragModel::Separate { slow: cds, fast } => {
                        let (ms, mf) = (slow[0].hypot(slow[1]), u[0].hypot(u[1]));
                        let f = [
                            -cds * slow[0] * ms + fast * u[0] * mf,
                            -cds * slow[1] * ms + fast * u[1] * mf,
                        ];
                        // The fast sum's offset is zero: w = u.
                        (f, fast * mf * 2.0 * mf)
                    }
                };
                let scale = 0.5 * 1025.0 * c.diameter * dz;
                total[0] += scale * f[0];
                total[1] += scale * f[1];
                total[2] += scale * (c.x * f[1] - c.y * f[0]);
                sizes[0] += scale * size;
                sizes[1] += scale * size;
                sizes[2] += scale * size * (c.x.abs() + c.y.abs());
            }
        }
        (total, sizes)
    }

    /// The wave components of a JONSWAP sea (Hs 8 m, Tp 11 s) of `directions` directions
    /// about `mean_direction` (rad), seed `seed`, on a 400-s block at 0.5 s, and its records'
    /// clock.
    fn sea_records(
        spreading: Spreading,
        mean_direction: f64,
        directions: usize,
        seed: u64,
    ) -> (WaveComponents, RecordClock) {
        let sea = SeaState {
            spectrum: Spectrum::Jonswap {
                hs: 8.0,
                tp: 11.0,
                gamma: None,
            },
            spreading,
            mean_direction,
            n_directions: directions,
            seed,
            band: None,
        };
        let grid = FrequencyGrid::new(0.0, 400.0, 0.5, sea.band()).unwrap();
        let components = WaveComponents::generate(&sea, grid);
        let clock = RecordClock {
            start_time: 0.0,
            dt: components.grid.dt,
            len: components.grid.len,
        };
        (components, clock)
    }

    /// The columns of one group (the two at x = 30 m in waves along x: one key) read the
    /// same kinematics, and the drag takes their strip sums once where their offsets round
    /// to the same floats: it gives the force of every column summed on its own
    /// (`add_column_force`, column by column), bit for bit, at zero yaw rate (one sum
    /// serves the pair) and at a yaw rate that parts their offsets, in both drag models,
    /// on a sample and between samples, with the rows in the window and without.
    #[test]
    fn a_group_summed_once_gives_each_columns_force() {
        let (components, clock) = sea_records(Spreading::LongCrested, 0.0, 1, 5);
        let grid = &components.grid;
        let columns = [(30.0, 10.0), (-20.0, 15.0), (30.0, -10.0)].map(|(x, y)| Cylinder {
            x,
            y,
            diameter: 12.0,
            draft: 25.0,
        });
        let mut synth = Synthesizer::new(grid);
        let unmade = column_kinematics(&components, &columns, 20, 9.81, &mut synth);
        let group = |c: usize| unmade.column(c).group();
        assert_eq!(
            group(0),
            group(2),
            "the columns at x = 30 m share their records"
        );
        assert_ne!(group(0), group(1));
        let mut made = unmade.clone();
        made.make_rows(0, 1);
        let models = [
            DragModel::Combined { cd: 0.7 },
            DragModel::Separate {
                slow: 0.9,
                fast: 0.6,
            },
        ];
        for kinematics in [&unmade, &made] {
            for model in models {
                for t in [100.0, 12.25] {
                    let at = clock.locate(t).unwrap();
                    for velocity in [[0.3, -0.2, 0.0], [0.3, -0.2, 0.004]] {
                        let current = [0.5, 0.1];
                        let mut want = [0.0; 3];
                        for col in kinematics.columns() {
                            add_column_force(
                                &mut want, &col, &at, model, 1025.0, velocity, current,
                            );
                        }
                        let got = drag_force(kinematics, &at, model, 1025.0, velocity, current);
                        assert_eq!(
                            got.map(f64::to_bits),
                            want.map(f64::to_bits),
                            "{model:?}, t {t}, velocity {velocity:?}: {got:?} against {want:?}"
                        );
                    }
                }
            }
        }
    }

    /// The single-precision strip sums equal the plain strip-by-strip sum in double
    /// precision for odd and even strip counts below, at and above a chunk, on samples and
    /// between them, with the rows in the records' window and without, within
    /// [`StripSums`]' bound: (ceil(n/2) + 6) 2^-24 of the sizes sum |w| (|o| + |u| + |w|).
    #[test]
    fn drag_equals_the_strip_by_strip_sum() {
        let (components, clock) = sea_records(Spreading::CosN { n: 4.0 }, 0.4, 3, 3);
        let grid = &components.grid;
        let columns = [(30.0, 10.0, 25.0), (-20.0, 15.0, 18.0)].map(|(x, y, draft)| Cylinder {
            x,
            y,
            diameter: 12.0,
            draft,
        });
        let mut synth = Synthesizer::new(grid);
        for strips in [7, 20, CHUNK, 2 * CHUNK + 5] {
            let unmade = column_kinematics(&components, &columns, strips, 9.81, &mut synth);
            // With the rows in the records' window (the whole record here) and without.
            let mut made = unmade.clone();
            made.make_rows(0, 1);
            for (kinematics, model) in [&unmade, &made].into_iter().flat_map(|k| {
                [
                    DragModel::Combined { cd: 0.7 },
                    DragModel::Separate {
                        slow: 0.9,
                        fast: 0.6,
                    },
                ]
                .map(|model| (k, model))
            }) {
                for t in [12.0, 100.5, 233.7] {
                    let at = clock.locate(t).unwrap();
                    let (velocity, current) = ([0.3, -0.2, 0.004], [0.5, 0.1]);
                    let (want, sizes) = by_strips(kinematics, &at, model, velocity, current);
                    let bound = (strips.div_ceil(2) + 6) as f64 * f64::from(f32::EPSILON) / 2.0;
                    let got = drag_force(kinematics, &at, model, 1025.0, velocity, current);
                    for i in 0..3 {
                        let error = (got[i] - want[i]).abs() / sizes[i];
                        assert!(
                            error <= bound,
                            "{strips} strips, {model:?}, t {t}, dof {i}: {} vs {} ({error:.1e} \
                             of the sizes, bound {bound:.1e})",
                            got[i],
                            want[i]
                        );
                    }
                }
            }
        }
    }
}
