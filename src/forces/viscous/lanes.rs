//! The drag of several seeds of one case at the same instant, one seed per vector lane
//! (docs/architecture.md#seeds-in-lanes).
//!
//! One seed's strip sum is a chain: each strip's w_j |w_j| is added to the sum of the
//! strips before it, in strip order, so each addition waits for the one before.
//! [`drag_forces`] takes the strips of [`LANES`] seeds together: strip j of every lane,
//! then strip j + 1, each lane's sum kept apart. The lanes' chains run side by side in one
//! vector register, and each lane does the operations of [`super::drag_force`] in the same
//! order, so each lane's force is that of the one-seed path bit for bit, whichever
//! instruction set runs it ([`Isa`]).

// The one unsafe call: the AVX2 build of the lanes' sums, made only where the CPU has AVX2.
#![allow(unsafe_code)]

use super::{add_column_force, strip_sum, ColumnStrips, Velocity};
use crate::forces::isa::Isa;
use crate::forces::kinematics::{ColumnKinematics, StripVelocities};
use crate::forces::record::SamplePoint;
use crate::model::DragModel;

/// Seeds stepped together: four doubles fill an AVX2 register.
pub const LANES: usize = 4;

/// One lane's seed at an instant: its columns' kinematics records, located at the
/// instant, and its body's slow velocity (u, v, r) and the current (x, y), body frame.
#[derive(Debug, Clone, Copy)]
pub struct LaneDrag<'a> {
    pub columns: &'a [ColumnKinematics],
    pub at: SamplePoint,
    pub velocity: [f64; 3],
    pub current: [f64; 2],
}

/// The drag on each lane's body, body frame (Fx, Fy, Mz), as [`super::drag_force`] gives
/// it for that lane alone, bit for bit: `lanes` (1 to [`LANES`] seeds of one case, their
/// columns alike) at one instant. The strips are summed lane by lane side by side when
/// every lane's instant falls on a sample (a contiguous row of each record), else each
/// lane alone. Entries past `lanes.len()` are zero.
pub fn drag_forces(
    lanes: &[LaneDrag],
    model: DragModel,
    water_density: f64,
    isa: Isa,
) -> [[f64; 3]; LANES] {
    assert!(
        (1..=LANES).contains(&lanes.len()),
        "1 to {LANES} lanes, not {}",
        lanes.len()
    );
    let mut totals = [[0.0; 3]; LANES];
    if model == DragModel::Off {
        return totals;
    }
    // Lanes past `lanes.len()` repeat the last one (their results are not kept).
    let padded: [&LaneDrag; LANES] = [0, 1, 2, 3].map(|l| &lanes[l.min(lanes.len() - 1)]);
    for c in 0..lanes[0].columns.len() {
        let mut strips = [None; LANES];
        let mut velocities = [None; LANES];
        for (l, lane) in padded.iter().enumerate() {
            let column = &lane.columns[c];
            if let Some((eta, row)) = column.row_on_sample(&lane.at) {
                let (v, u) = (lane.velocity, lane.current);
                strips[l] = Some(ColumnStrips::of(column, eta, model, water_density, v, u));
                velocities[l] = Some(row);
            }
        }
        let [Some(s0), Some(s1), Some(s2), Some(s3)] = strips else {
            // Some lane between samples: each lane alone.
            for (total, lane) in totals.iter_mut().zip(lanes) {
                let (column, v, u) = (&lane.columns[c], lane.velocity, lane.current);
                add_column_force(total, column, &lane.at, model, water_density, v, u);
            }
            continue;
        };
        let strips = [s0, s1, s2, s3];
        let offsets = [s0.offset, s1.offset, s2.offset, s3.offset];
        let fast = match velocities {
            [Some(StripVelocities::AlongX(a)), Some(StripVelocities::AlongX(b)), Some(StripVelocities::AlongX(c)), Some(StripVelocities::AlongX(d))] => {
                sums(isa, [a, b, c, d], offsets)
            }
            [Some(StripVelocities::Interleaved(a)), Some(StripVelocities::Interleaved(b)), Some(StripVelocities::Interleaved(c)), Some(StripVelocities::Interleaved(d))] => {
                sums(isa, [a, b, c, d], offsets)
            }
            // Lanes of one case share their layout; any others are summed lane by lane.
            _ => {
                let mut fast = [[0.0; 2]; LANES];
                for (l, lane) in padded.iter().enumerate() {
                    let column = &lane.columns[c];
                    fast[l] = strip_sum(&column.at(&lane.at), column.strips(), offsets[l]);
                }
                fast
            }
        };
        for (l, (total, lane)) in totals.iter_mut().zip(lanes).enumerate() {
            strips[l].add_force(total, &lane.columns[c], model, fast[l]);
        }
    }
    totals
}

/// Each lane's sum_j w_j |w_j| over its row's strips (w_j = u_j - offset), compiled for
/// `isa`; the rows are of one length.
fn sums<V: Stored>(isa: Isa, rows: [&[V]; LANES], offsets: [[f64; 2]; LANES]) -> [[f64; 2]; LANES] {
    match isa {
        Isa::Baseline => lane_sums(rows, offsets),
        #[cfg(target_arch = "x86_64")]
        // SAFETY: `Isa::Avx2` is only made where the CPU reports AVX2 (`Isa::detect`,
        // `Isa::available`).
        Isa::Avx2 => unsafe { lane_sums_avx2(rows, offsets) },
    }
}

/// A strip's velocity as the records store it on a sample: (u_x, u_y) in single
/// precision (u_y = 0 in waves along x, where only u_x is stored).
trait Stored: Velocity {
    fn xy32(&self) -> [f32; 2];
}

impl Stored for [f32; 2] {
    #[inline(always)]
    fn xy32(&self) -> [f32; 2] {
        *self
    }
}

impl Stored for f32 {
    #[inline(always)]
    fn xy32(&self) -> [f32; 2] {
        [*self, 0.0]
    }
}

/// [`lane_sums`] written in AVX2 instructions, one register per quantity with lane l in
/// element l: strip j's velocities gathered across the lanes, then per lane the operations
/// of `add_w_abs_w` in its order (w = u - offset, w_x^2 + w_y^2 as two products and a sum,
/// rounded to single precision, its root there, widened back; sum += w * |w|), each a
/// separate instruction, so no product is fused into an addition (`_mm256_mul_pd` and
/// `_mm256_add_pd` are never contracted) and each lane's sum is the one-seed sum bit for
/// bit.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn lane_sums_avx2<V: Stored>(rows: [&[V]; LANES], offsets: [[f64; 2]; LANES]) -> [[f64; 2]; LANES] {
    use std::arch::x86_64::{
        _mm256_add_pd, _mm256_cvtpd_ps, _mm256_cvtps_pd, _mm256_mul_pd, _mm256_setr_pd,
        _mm256_setzero_pd, _mm256_sub_pd, _mm_setr_ps, _mm_sqrt_ps,
    };
    let n = rows[0].len();
    // Sliced one by one: `array::map` is a call here, once per column and instant.
    let (r0, r1, r2, r3) = (&rows[0][..n], &rows[1][..n], &rows[2][..n], &rows[3][..n]);
    let off_x = _mm256_setr_pd(offsets[0][0], offsets[1][0], offsets[2][0], offsets[3][0]);
    let off_y = _mm256_setr_pd(offsets[0][1], offsets[1][1], offsets[2][1], offsets[3][1]);
    let mut sum_x = _mm256_setzero_pd();
    let mut sum_y = _mm256_setzero_pd();
    for j in 0..n {
        let [a, b, c, d] = [r0[j].xy32(), r1[j].xy32(), r2[j].xy32(), r3[j].xy32()];
        let x = _mm256_cvtps_pd(_mm_setr_ps(a[0], b[0], c[0], d[0]));
        let y = _mm256_cvtps_pd(_mm_setr_ps(a[1], b[1], c[1], d[1]));
        let wx = _mm256_sub_pd(x, off_x);
        let wy = _mm256_sub_pd(y, off_y);
        let squared = _mm256_add_pd(_mm256_mul_pd(wx, wx), _mm256_mul_pd(wy, wy));
        let norm = _mm256_cvtps_pd(_mm_sqrt_ps(_mm256_cvtpd_ps(squared)));
        sum_x = _mm256_add_pd(sum_x, _mm256_mul_pd(wx, norm));
        sum_y = _mm256_add_pd(sum_y, _mm256_mul_pd(wy, norm));
    }
    let (xs, ys) = (elements(sum_x), elements(sum_y));
    std::array::from_fn(|l| [xs[l], ys[l]])
}

/// The 4 doubles of an AVX register, element 0 first.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn elements(v: std::arch::x86_64::__m256d) -> [f64; LANES] {
    use std::arch::x86_64::{
        _mm256_castpd256_pd128, _mm256_extractf128_pd, _mm_cvtsd_f64, _mm_unpackhi_pd,
    };
    let (low, high) = (_mm256_castpd256_pd128(v), _mm256_extractf128_pd::<1>(v));
    [
        _mm_cvtsd_f64(low),
        _mm_cvtsd_f64(_mm_unpackhi_pd(low, low)),
        _mm_cvtsd_f64(high),
        _mm_cvtsd_f64(_mm_unpackhi_pd(high, high)),
    ]
}

/// The lanes' strip sums side by side: strip j of every lane, then strip j + 1. Per lane,
/// the operations of `add_w_abs_w` in its order: w = u - offset in double precision, the
/// squared norm rounded to single precision and its root taken there, then
/// sum += w * |w| strip after strip (the product and the sum in double precision; no
/// fused multiply-add, which Rust never makes on its own).
#[inline(always)]
fn lane_sums<V: Velocity>(rows: [&[V]; LANES], offsets: [[f64; 2]; LANES]) -> [[f64; 2]; LANES] {
    let n = rows[0].len();
    let rows = rows.map(|r| &r[..n]);
    let mut sum_x = [0.0f64; LANES];
    let mut sum_y = [0.0f64; LANES];
    // Strip j of every lane, then strip j + 1: the rows are read across lanes.
    #[allow(clippy::needless_range_loop)]
    for j in 0..n {
        let w: [[f64; 2]; LANES] = std::array::from_fn(|l| {
            let [x, y] = rows[l][j].xy();
            [x - offsets[l][0], y - offsets[l][1]]
        });
        let norm: [f32; LANES] =
            std::array::from_fn(|l| ((w[l][0] * w[l][0] + w[l][1] * w[l][1]) as f32).sqrt());
        for l in 0..LANES {
            let m = f64::from(norm[l]);
            sum_x[l] += w[l][0] * m;
            sum_y[l] += w[l][1] * m;
        }
    }
    std::array::from_fn(|l| [sum_x[l], sum_y[l]])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::forces::kinematics::column_kinematics;
    use crate::forces::viscous::drag_force;
    use crate::forces::{RecordClock, Synthesizer};
    use crate::model::Cylinder;
    use crate::sea_state::{FrequencyGrid, SeaState, Spectrum, Spreading, WaveComponents};

    /// Each lane's drag from `drag_forces` is `drag_force` for that lane alone, bit for bit,
    /// for every instruction set this CPU runs: 1 to 4 lanes of four seeds' kinematics, in
    /// waves along x (rows of u_x alone) and spread (u_x and u_y), on samples (the lanes'
    /// sums side by side) and between them (each lane alone), each lane at its own slow
    /// velocity, and with the lanes at different instants (some on a sample, some not).
    #[test]
    fn each_lane_is_the_one_seed_drag_bit_for_bit() {
        let columns = [(30.0, 10.0, 25.0), (-20.0, 15.0, 18.0)].map(|(x, y, draft)| Cylinder {
            x,
            y,
            diameter: 12.0,
            draft,
        });
        for (direction, spreading) in [
            (0.0, Spreading::LongCrested),
            (0.4, Spreading::CosN { n: 4.0 }),
        ] {
            let kinematics: Vec<_> = (0..LANES as u64)
                .map(|seed| {
                    let sea = SeaState {
                        spectrum: Spectrum::Jonswap {
                            hs: 8.0,
                            tp: 11.0,
                            gamma: None,
                        },
                        spreading: spreading.clone(),
                        mean_direction: direction,
                        n_directions: 3,
                        seed,
                        band: None,
                    };
                    let grid = FrequencyGrid::new(0.0, 400.0, 0.5, sea.band()).unwrap();
                    let components = WaveComponents::generate(&sea, grid);
                    let mut synth = Synthesizer::new(&components.grid);
                    column_kinematics(&components, &columns, 21, 9.81, &mut synth)
                })
                .collect();
            let clock = RecordClock {
                start_time: 0.0,
                dt: 0.5,
                len: 800,
            };
            let velocity = |l: usize| [0.3 - 0.1 * l as f64, -0.2, 0.004 * l as f64];
            let current = [0.5, 0.1];
            for times in [[100.0; LANES], [12.25; LANES], [100.0, 12.25, 233.5, 7.0]] {
                for model in [
                    DragModel::Combined { cd: 0.7 },
                    DragModel::Separate {
                        slow: 0.9,
                        fast: 0.6,
                    },
                ] {
                    let lanes: Vec<LaneDrag> = (0..LANES)
                        .map(|l| LaneDrag {
                            columns: &kinematics[l],
                            at: clock.locate(times[l]).unwrap(),
                            velocity: velocity(l),
                            current,
                        })
                        .collect();
                    for isa in Isa::available() {
                        for n in 1..=LANES {
                            let got = drag_forces(&lanes[..n], model, 1025.0, isa);
                            for (l, lane) in lanes[..n].iter().enumerate() {
                                let alone = drag_force(
                                    lane.columns,
                                    &lane.at,
                                    model,
                                    1025.0,
                                    lane.velocity,
                                    current,
                                );
                                assert_eq!(
                                    got[l].map(f64::to_bits),
                                    alone.map(f64::to_bits),
                                    "{spreading:?}, {model:?}, {isa:?}, {n} lanes, lane {l} at {}",
                                    times[l]
                                );
                            }
                            assert!(got[n..].iter().all(|f| *f == [0.0; 3]));
                        }
                    }
                }
            }
        }
    }
}
