//! The drag of several seeds of one case at the same instant, one seed per vector lane
//! (docs/architecture.md#seeds-in-lanes).
//!
//! One seed's strip sum is two chains (`sums::StripSums`: the even strips' and the odd
//! strips', each in strip order), so each addition waits for the one before.
//! [`drag_forces`] takes the strips of [`LANES`] seeds together: strips j and j + 1 of
//! every lane in one register of 8 floats, each lane's sums kept apart
//! (`sums::lane_sums`). The lanes' chains run side by side, and each lane does the
//! operations of [`super::drag_force`] in the same order, so each lane's force is that of
//! the one-seed path bit for bit, whichever instruction set runs it ([`Isa`]).

use super::sums::lane_sums;
use super::{add_column_force, single_bits, strip_sum, ColumnStrips, SeenSums};
use crate::forces::isa::Isa;
use crate::forces::kinematics::{Kinematics, StripVelocities};
use crate::forces::record::SamplePoint;
use crate::forces::value::{Value, Wide};
use crate::model::DragModel;

/// Seeds stepped together: four doubles fill an AVX2 register.
pub const LANES: usize = 4;

/// One lane's seed at an instant: its columns' kinematics records, located at the
/// instant, and its body's slow velocity (u, v, r) and the current (x, y), body frame.
#[derive(Debug, Clone, Copy)]
pub struct LaneDrag<'a> {
    pub kinematics: &'a Kinematics,
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
    // The lanes' totals side by side: (Fx, Fy, Mz) of lane l in lane l of each.
    let mut totals = [Wide::splat(0.0); 3];
    if model != DragModel::Off {
        // Lanes past `lanes.len()` repeat the last one (their results are not kept).
        let padded: [&LaneDrag; LANES] = [0, 1, 2, 3].map(|l| &lanes[l.min(lanes.len() - 1)]);
        // As in `drag_force`, the sums of a column group are taken once per offset.
        let mut seen = SeenSums::new();
        for c in 0..lanes[0].kinematics.len() {
            let columns = padded.map(|lane| lane.kinematics.column(c));
            let rows: [_; LANES] = std::array::from_fn(|l| columns[l].row_on_sample(&padded[l].at));
            let [Some((e0, r0)), Some((e1, r1)), Some((e2, r2)), Some((e3, r3))] = rows else {
                // Some lane between samples (or its row not made): each lane alone.
                for (l, lane) in lanes.iter().enumerate() {
                    let mut total = totals.map(|t| t.lane(l));
                    let (v, u) = (lane.velocity, lane.current);
                    add_column_force(
                        &mut total,
                        &columns[l],
                        &lane.at,
                        model,
                        water_density,
                        v,
                        u,
                    );
                    (0..3).for_each(|i| totals[i].0[l] = total[i]);
                }
                continue;
            };
            // Lanes of one case: one column, as lane 0 has it.
            let column = (columns[0].column, columns[0].strips());
            debug_assert!(columns.iter().all(|k| (k.column, k.strips()) == column));
            let velocity = Wide::gather(|l| padded[l].velocity);
            let current = Wide::gather(|l| padded[l].current);
            let eta = Wide([e0, e1, e2, e3]);
            let strips = ColumnStrips::of(column, eta, model, water_density, velocity, current);
            let offsets: [[f64; 2]; LANES] =
                std::array::from_fn(|l| strips.offset.map(|o| o.lane(l)));
            // Lanes of one case: one group, as lane 0 has it.
            let group = columns[0].group();
            debug_assert!(columns.iter().all(|k| k.group() == group));
            let fast = seen.sum(group, offsets.map(single_bits), || match [r0, r1, r2, r3] {
                [StripVelocities::AlongX(a), StripVelocities::AlongX(b), StripVelocities::AlongX(c), StripVelocities::AlongX(d)] => {
                    lane_sums(isa, [a, b, c, d], offsets)
                }
                [StripVelocities::Interleaved(a), StripVelocities::Interleaved(b), StripVelocities::Interleaved(c), StripVelocities::Interleaved(d)] => {
                    lane_sums(isa, [a, b, c, d], offsets)
                }
                // Lanes of one case share their layout; any others are summed lane by lane.
                _ => std::array::from_fn(|l| {
                    let column = &columns[l];
                    strip_sum(&column.at(&padded[l].at), column.strips(), offsets[l])
                }),
            });
            strips.add_force(&mut totals, column, model, Wide::gather(|l| fast[l]));
        }
    }
    std::array::from_fn(|l| {
        if l < lanes.len() {
            totals.map(|t| t.lane(l))
        } else {
            [0.0; 3]
        }
    })
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
    /// for every instruction set this CPU runs: 1 to 4 lanes of four seeds' kinematics of 1
    /// to 21 strips (odd and even counts: an odd last strip goes to the even sums), in waves
    /// along x (rows of u_x alone) and spread (u_x and u_y), on samples (the lanes' sums side
    /// by side) and between them (each lane alone), each lane at its own slow velocity, and
    /// with the lanes at different instants (some on a sample, some not); with the rows in
    /// the records' window and without (each recombined where it is read), which give the
    /// same bits.
    #[test]
    fn each_lane_is_the_one_seed_drag_bit_for_bit() {
        // The first and last columns are one group in waves along x (one key: same x and
        // draft), whose strip sums are taken once where their offsets round alike.
        let columns =
            [(30.0, 10.0, 25.0), (-20.0, 15.0, 18.0), (30.0, -10.0, 25.0)].map(|(x, y, draft)| {
                Cylinder {
                    x,
                    y,
                    diameter: 12.0,
                    draft,
                }
            });
        let cases = [1, 2, 7, 8, 10, 21].into_iter().flat_map(|strips| {
            [
                (strips, 0.0, Spreading::LongCrested),
                (strips, 0.4, Spreading::CosN { n: 4.0 }),
            ]
        });
        for (strips, direction, spreading) in cases {
            let unmade: Vec<Kinematics> = (0..LANES as u64)
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
                    column_kinematics(&components, &columns, strips, 9.81, &mut synth)
                })
                .collect();
            let clock = RecordClock {
                start_time: 0.0,
                dt: 0.5,
                len: 800,
            };
            // The window from sample 0 holds every instant below (the rows to 512 s).
            let mut made = unmade.clone();
            made.iter_mut().for_each(|k| k.make_rows(0, 1));
            let on = clock.locate(100.0).unwrap();
            assert!(made[0].column(0).row_on_sample(&on).is_some());
            assert!(unmade[0].column(0).row_on_sample(&on).is_none());
            let mut in_window = Vec::new();
            for kinematics in [&unmade, &made] {
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
                                kinematics: &kinematics[l],
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
                                        lane.kinematics,
                                        &lane.at,
                                        model,
                                        1025.0,
                                        lane.velocity,
                                        current,
                                    );
                                    assert_eq!(
                                    got[l].map(f64::to_bits),
                                    alone.map(f64::to_bits),
                                    "{strips} strips, {spreading:?}, {model:?}, {isa:?}, {n} lanes, lane {l} at {}",
                                    times[l]
                                );
                                    in_window.push(got[l].map(f64::to_bits));
                                }
                                assert!(got[n..].iter().all(|f| *f == [0.0; 3]));
                            }
                        }
                    }
                }
            }
            let (without, with) = in_window.split_at(in_window.len() / 2);
            assert_eq!(
                without, with,
                "{strips} strips, {spreading:?}: the window changes nothing"
            );
        }
    }
}
