//! Drag, current and wave-drift damping against closed forms (E&S 8, 9, section 3;
//! docs/theory.md#wave-drift-damping-and-current, docs/theory.md#viscous-drag).

use crate::common::*;
use slowdrift::hydro::{DriftRow, DriftTable};
use slowdrift::model::{DragModel, DriftDamping};
use slowdrift::Simulation;

/// Runs to the end and returns the mean position over the second half.
fn mean_position(sim: &mut Simulation) -> [f64; 3] {
    let run = sim.problem().run.clone();
    let steps = (run.duration / run.time_step).round() as usize;
    let mut sum = [0.0; 3];
    let mut count = 0.0;
    for n in 0..steps {
        sim.step([0.0; 3]).unwrap();
        if n >= steps / 2 {
            for (s, p) in sum.iter_mut().zip(sim.position()) {
                *s += p;
            }
            count += 1.0;
        }
    }
    sum.map(|s| s / count)
}

/// With waves of negligible height, a steady current U_c gives the static Morison force
/// 1/2 rho C D draft U_c^2 per column along the current: the offset is that over k.
#[test]
fn steady_current_gives_the_static_morison_offset() {
    let speed = 1.2;
    let direction = 30f64.to_radians();
    for drag in [
        DragModel::Separate {
            slow: 0.8,
            fast: 0.0,
        },
        DragModel::Combined { cd: 0.8 },
    ] {
        let mut problem = base_problem(3000.0, 1.0, 1);
        problem.sea.spectrum = jonswap(1e-6, 10.0);
        problem.platform.columns = four_columns();
        problem.model.drag = drag;
        problem.current.speed = speed;
        problem.current.direction = direction;
        let k = problem.platform.stiffness[0][0];
        let force = 4.0 * 0.5 * 1025.0 * 0.8 * 20.0 * 30.0 * speed * speed;
        let mut sim = Simulation::new(problem).unwrap();
        let mean = mean_position(&mut sim);
        let expected = [force * direction.cos() / k, force * direction.sin() / k];
        for i in 0..2 {
            assert!(
                (mean[i] - expected[i]).abs() < 1e-6 * expected[0].abs(),
                "{drag:?} dof {i}: {} vs {}",
                mean[i],
                expected[i]
            );
        }
        // Symmetric square of columns: no yaw moment from a uniform current.
        assert!(mean[2].abs() < 1e-9, "yaw {}", mean[2]);
    }
}

/// The current enters the wave-drift damping as an apparent velocity: the mean force gains
/// B_mean U_c with B_mean = 2 integral S b dw (docs/theory.md#wave-drift-damping-and-current), so
/// the mean surge
/// offset is (2 int S T + 2 int S b11 U_c) / k. Constant b gives a closed form.
#[test]
fn current_through_drift_damping_shifts_the_mean_force() {
    let b11 = 3.0e3; // N s/m per m^2 of amplitude
    let mut rows = Vec::new();
    for ih in 0..36 {
        let beta = (ih as f64 * 10.0).to_radians();
        for iw in 1..=150 {
            let omega = 0.02 * iw as f64;
            let mut b = [[0.0; 3]; 3];
            b[0][0] = b11;
            rows.push(DriftRow {
                omega,
                heading: beta,
                drift: smooth_drift(omega, beta),
                damping: Some(b),
            });
        }
    }
    let table = DriftTable::from_rows(&rows).unwrap();
    let run = |current: f64| {
        let mut problem = base_problem(16_384.0, 1.0, 4);
        problem.hydro.drift = table.clone();
        problem.model.drift_damping = DriftDamping::Table;
        problem.current.speed = current;
        let mut sim = Simulation::new(problem).unwrap();
        let records = sim.records().clone();
        let b_mean: f64 = records.damping.as_ref().unwrap()[0][0]
            .samples()
            .iter()
            .sum::<f64>()
            / records.clock.len as f64;
        (mean_position(&mut sim)[0], b_mean, sim.problem().clone())
    };
    let (still, b_mean, problem) = run(0.0);
    let (with_current, _, _) = run(0.5);
    let k = problem.platform.stiffness[0][0];
    // Same seed and grid: the wave force is identical; only B(t) U_c differs. The record's
    // mean of B(t) is sum |a_i|^2 b (exactly, over the period), and its expectation
    // 2 int S b dw.
    let (lo, hi) = problem.sea.band();
    let expected_b = 2.0 * b11 * simpson(|w| problem.sea.spectrum.density(w), lo, hi, 4000);
    assert!(
        (b_mean / expected_b - 1.0).abs() < 0.1,
        "B mean {b_mean} vs 2 int S b = {expected_b}"
    );
    let shift = with_current - still;
    let expected_shift = b_mean * 0.5 / k;
    // The run's average of B(t) U_c over half the record differs from the full-period mean
    // by the slow fluctuation of B; allow 5 %.
    assert!(
        (shift / expected_shift - 1.0).abs() < 0.05,
        "shift {shift} vs {expected_shift}"
    );
    assert!(
        shift > 0.0,
        "a following current adds drift in the wave direction"
    );
}

/// Waves alone on a column platform: the combined model's drag on the wave zone adds a mean
/// force in the wave direction (E&S section 4), and the separate model with C_DS = 0 and
/// C_DL > 0 too; neither makes sway or yaw in head seas on a symmetric platform.
#[test]
fn wave_zone_drag_adds_mean_drift_in_the_wave_direction() {
    let baseline = {
        let mut problem = base_problem(8192.0, 1.0, 2);
        problem.platform.columns = four_columns();
        mean_position(&mut Simulation::new(problem).unwrap())
    };
    for drag in [
        DragModel::Combined { cd: 1.0 },
        DragModel::Separate {
            slow: 0.0,
            fast: 1.0,
        },
    ] {
        let mut problem = base_problem(8192.0, 1.0, 2);
        problem.platform.columns = four_columns();
        problem.model.drag = drag;
        let mean = mean_position(&mut Simulation::new(problem).unwrap());
        assert!(
            mean[0] > baseline[0],
            "{drag:?}: {} vs {}",
            mean[0],
            baseline[0]
        );
        assert!(
            mean[1].abs() < 1e-9 * mean[0].abs() && mean[2].abs() < 1e-12,
            "{drag:?}: {mean:?}"
        );
    }
}
