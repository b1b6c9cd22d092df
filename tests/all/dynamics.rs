//! Time integration and equations of motion (docs/theory.md#equations-of-motion,
//! docs/theory.md#checks-with-known-answers): RK4's order on a
//! forced damped oscillator with an exact solution, its energy behaviour on an undamped
//! oscillator (closed-form amplification factor), energy conservation through
//! `Simulation`, the rotation of the body-frame wave force by S(theta), and `advance` with
//! interpolated stages against `step`.

use crate::common::*;
use slowdrift::dynamics::rk4_step;
use slowdrift::Simulation;
use std::convert::Infallible;
use std::f64::consts::PI;

/// Forced damped oscillator x'' + 2 zeta w x' + w^2 x = F0 cos(W t).
struct Forced {
    w: f64,
    zeta: f64,
    f0: f64,
    big_w: f64,
    x0: f64,
    v0: f64,
}

impl Forced {
    /// Exact (x, x') at t: particular A cos Wt + B sin Wt plus the underdamped homogeneous
    /// solution e^{-zeta w t}(C1 cos wd t + C2 sin wd t), constants from x(0), x'(0).
    fn exact(&self, t: f64) -> [f64; 2] {
        let (w, z, bw) = (self.w, self.zeta, self.big_w);
        let det = (w * w - bw * bw).powi(2) + (2.0 * z * w * bw).powi(2);
        let a = self.f0 * (w * w - bw * bw) / det;
        let b = self.f0 * 2.0 * z * w * bw / det;
        let wd = w * (1.0 - z * z).sqrt();
        let c1 = self.x0 - a;
        let c2 = (self.v0 + z * w * c1 - bw * b) / wd;
        let decay = (-z * w * t).exp();
        let (s, c) = (wd * t).sin_cos();
        let (sw, cw) = (bw * t).sin_cos();
        let x = decay * (c1 * c + c2 * s) + a * cw + b * sw;
        let v = decay * (-z * w * (c1 * c + c2 * s) + wd * (-c1 * s + c2 * c))
            + bw * (-a * sw + b * cw);
        [x, v]
    }

    fn integrate(&self, t_end: f64, h: f64) -> [f64; 2] {
        let steps = (t_end / h).round() as usize;
        let mut y = [self.x0, self.v0];
        for n in 0..steps {
            let t = n as f64 * h;
            y = rk4_step(t, &y, h, |t, y| {
                Ok::<_, Infallible>([
                    y[1],
                    self.f0 * (self.big_w * t).cos()
                        - 2.0 * self.zeta * self.w * y[1]
                        - self.w * self.w * y[0],
                ])
            })
            .unwrap();
        }
        y
    }
}

#[test]
fn rk4_is_fourth_order_on_a_forced_damped_oscillator() {
    let osc = Forced {
        w: 1.0,
        zeta: 0.1,
        f0: 1.0,
        big_w: 0.7,
        x0: 1.0,
        v0: 0.0,
    };
    // The exact solution satisfies the initial conditions (checks the constants).
    let start = osc.exact(0.0);
    assert!((start[0] - osc.x0).abs() < 1e-14 && (start[1] - osc.v0).abs() < 1e-14);
    let exact = osc.exact(10.0);
    let errors: Vec<f64> = [0.2, 0.1, 0.05, 0.025]
        .iter()
        .map(|&h| {
            let y = osc.integrate(10.0, h);
            (y[0] - exact[0]).hypot(y[1] - exact[1])
        })
        .collect();
    for pair in errors.windows(2) {
        let order = (pair[0] / pair[1]).log2();
        assert!(
            (3.8..=4.2).contains(&order),
            "observed order {order} (errors {errors:?})"
        );
    }
    // Far above round-off, so the orders measure truncation error.
    assert!(errors[3] > 1e-11, "{errors:?}");
}

/// |R(i y)|^2 for RK4's stability polynomial R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24:
/// exactly 1 - y^6/72 + y^8/576. On x'' = -w^2 x RK4 multiplies the energy by this per step
/// (the step map is R(h w J), J skew, i.e. |R(i w h)| times a rotation).
fn rk4_energy_factor(y: f64) -> f64 {
    1.0 - y.powi(6) / 72.0 + y.powi(8) / 576.0
}

fn harmonic_energy_error(steps_per_period: usize, periods: usize) -> (f64, f64) {
    let w = 2.0 * PI / 30.0;
    let h = 30.0 / steps_per_period as f64;
    let mut y = [1.0, 0.3];
    let energy = |y: &[f64; 2]| 0.5 * (w * w * y[0] * y[0] + y[1] * y[1]);
    let e0 = energy(&y);
    let steps = steps_per_period * periods;
    for n in 0..steps {
        y = rk4_step(n as f64 * h, &y, h, |_, y| {
            Ok::<_, Infallible>([y[1], -w * w * y[0]])
        })
        .unwrap();
    }
    let measured = 1.0 - energy(&y) / e0;
    let predicted = 1.0 - rk4_energy_factor(w * h).powi(steps as i32);
    (measured, predicted)
}

#[test]
fn rk4_energy_loss_on_an_undamped_oscillator_follows_the_closed_form() {
    // RK4 is slightly dissipative: energy falls by y^6/72 per step (y = w h), so over a fixed
    // time the relative loss is ~ (t w / 72) (w h)^5: fifth order in h, 32x per halving.
    let (coarse, coarse_predicted) = harmonic_energy_error(100, 100);
    let (fine, fine_predicted) = harmonic_energy_error(200, 100);
    for (m, p) in [(coarse, coarse_predicted), (fine, fine_predicted)] {
        assert!(m > 0.0, "RK4 must lose, not gain, energy: {m}");
        // Round-off over 2e4 steps is ~1e-12, far below the 1e-3 relative tolerance.
        assert!((m - p).abs() < 1e-3 * p, "measured {m}, closed form {p}");
    }
    // Bounds at h = T/100 and T/200 over 100 periods (closed form: 8.6e-6 and 2.7e-7).
    assert!(coarse < 1e-5, "{coarse}");
    assert!(fine < 1e-6, "{fine}");
    let ratio = coarse / fine;
    assert!(
        (ratio / 32.0 - 1.0).abs() < 0.05,
        "halving h divides the loss by {ratio}"
    );
}

#[test]
fn undamped_platform_conserves_energy_up_to_rk4_dissipation() {
    // Equal surge and sway mass, no added mass: S M S^T = M, so the yaw rotation drops out
    // and surge, sway and yaw are three uncoupled undamped oscillators. Each DOF's energy
    // must then follow RK4's closed-form factor exactly (to round-off), and the physical
    // energy is conserved to within that factor.
    let h = 1.0;
    let periods = [60.0, 60.0, 40.0];
    let duration = 20.0 * 60.0;
    let mut problem = base_problem(duration + 10.0, h, 11);
    problem.hydro.drift = drift_table(|_, _| [0.0; 3]);
    problem.platform.linear_damping = [[0.0; 3]; 3];
    problem.initial.position = [1.0, 0.5, 0.01];
    let inertia = {
        let i = problem.inertia().unwrap();
        [i.mass, i.mass, i.yaw_inertia]
    };
    let stiffness: Vec<f64> = (0..3).map(|i| problem.platform.stiffness[i][i]).collect();
    let mut sim = Simulation::new(problem).unwrap();
    assert!(sim
        .records()
        .wave_force
        .iter()
        .all(|r| r.samples().iter().all(|&v| v == 0.0)));
    let energy = |q: [f64; 3], v: [f64; 3]| -> [f64; 3] {
        std::array::from_fn(|i| 0.5 * stiffness[i] * q[i] * q[i] + 0.5 * inertia[i] * v[i] * v[i])
    };
    let e0 = energy(sim.position(), sim.velocity());
    let steps = (duration / h) as i32;
    for _ in 0..steps {
        sim.step([0.0; 3]).unwrap();
    }
    let e1 = energy(sim.position(), sim.velocity());
    let total0: f64 = e0.iter().sum();
    let total1: f64 = e1.iter().sum();
    let mut predicted_total = 0.0;
    for i in 0..3 {
        let factor = rk4_energy_factor(2.0 * PI / periods[i] * h).powi(steps);
        predicted_total += e0[i] * factor;
        assert!(
            (e1[i] / e0[i] - factor).abs() < 1e-9,
            "DOF {i}: energy ratio {} vs RK4 factor {factor}",
            e1[i] / e0[i]
        );
    }
    assert!(((total1 - predicted_total) / total0).abs() < 1e-9);
    // The dissipation itself is small: 2.2e-5 (surge, sway) and 2.5e-4 (yaw) by the closed
    // form; yaw holds 15 % of the initial energy, so the total loses 5.7e-5.
    let loss = 1.0 - total1 / total0;
    assert!(loss > 0.0 && loss < 1e-4, "relative energy loss {loss}");
}

fn rotation_config(theta0: f64) -> slowdrift::Problem {
    let mut problem = base_problem(300.0, 1.0, 5);
    problem.hydro.drift = drift_table(|w, _| {
        let surge = 2.0e4 * (1.0 + w * w);
        [surge, 0.3 * surge, 50.0 * surge]
    });
    problem.sea.mean_direction = 30f64.to_radians();
    problem.platform.linear_damping = [[0.0; 3]; 3];
    problem.initial.position = [0.0, 0.0, theta0];
    problem
}

#[test]
fn wave_force_is_the_body_frame_force_rotated_by_the_yaw() {
    let theta0 = 0.3;
    let mut yawed = Simulation::new(rotation_config(theta0)).unwrap();
    let mut straight = Simulation::new(rotation_config(0.0)).unwrap();
    // The records are computed at the mean position: identical whatever the yaw.
    assert_eq!(yawed.records(), straight.records());
    for n in 0..=100 {
        if n > 0 {
            yawed.step([0.0; 3]).unwrap();
            straight.step([0.0; 3]).unwrap();
        }
        if n % 10 != 0 {
            continue;
        }
        let t = yawed.time();
        let at = yawed.records().clock.locate(t).unwrap();
        let body: [f64; 3] = std::array::from_fn(|i| yawed.records().wave_force[i].at(&at));
        assert!(body.iter().all(|v| v.abs() > 0.0), "t = {t}: {body:?}");
        let theta = yawed.position()[2];
        if n == 0 {
            assert_eq!(theta, theta0);
        }
        let (s, c) = theta.sin_cos();
        let expected = [
            c * body[0] - s * body[1],
            s * body[0] + c * body[1],
            body[2],
        ];
        let got = yawed.outputs().unwrap().forces.wave;
        let scale = body[0].hypot(body[1]);
        for i in 0..2 {
            assert!(
                (got[i] - expected[i]).abs() <= 1e-12 * scale,
                "t = {t}, i = {i}: {got:?} vs {expected:?}"
            );
        }
        assert!((got[2] - expected[2]).abs() <= 1e-12 * body[2].abs());
        // Rotation keeps the horizontal magnitude.
        assert!((got[0].hypot(got[1]) - scale).abs() <= 1e-12 * scale);
        // At zero yaw the inertial force is the body-frame record itself.
        if n == 0 {
            assert_eq!(straight.outputs().unwrap().forces.wave, body);
        }
    }
    // Yaw stiffness pulls theta back from 0.3 rad: the check ran at several yaw angles.
    assert!((yawed.position()[2] - theta0).abs() > 0.01);
}

#[test]
fn advance_in_whole_steps_is_step() {
    let problem = base_problem(200.0, 1.0, 3);
    let mut stepped = Simulation::new(problem.clone()).unwrap();
    let mut advanced = Simulation::new(problem).unwrap();
    for _ in 0..40 {
        for _ in 0..3 {
            stepped.step([1.0e4, 0.0, 0.0]).unwrap();
        }
        advanced.advance(3.0, [1.0e4, 0.0, 0.0]).unwrap();
        assert_eq!(stepped.snapshot(), advanced.snapshot());
    }
}

/// Narrow-band waves: difference frequencies below 0.2 rad/s, so the force is smooth on the
/// 0.5 s record spacing and cubic interpolation between samples costs ~ (0.2 * 0.5)^4 * 3/128
/// = 2e-6 relative.
fn smooth_force_config() -> slowdrift::Problem {
    let mut problem = base_problem(200.0, 1.0, 9);
    problem.sea.band = Some((0.55, 0.75));
    problem
}

fn run_advance(interval: f64, end: f64) -> [f64; 6] {
    let mut sim = Simulation::new(smooth_force_config()).unwrap();
    let count = (end / interval).round() as usize;
    for _ in 0..count {
        sim.advance(interval, [0.0; 3]).unwrap();
    }
    assert_eq!(sim.time(), end);
    let (q, v) = (sim.position(), sim.velocity());
    [q[0], q[1], q[2], v[0], v[1], v[2]]
}

#[test]
fn advance_with_interpolated_stages_converges_at_fourth_order() {
    // Intervals that are exact binary fractions so that every run lands on t = 150 exactly:
    // 2.5 -> 3 substeps of 5/6 s, 1.25 -> 2 of 0.625 s, 0.3125 and 0.0625 -> 1 substep each.
    // None is a multiple of h = 1 s and every substep puts stages between the 0.5 s samples,
    // so they use the cubic interpolation; all runs integrate the same interpolated force.
    let end = 150.0;
    let mut stepped = Simulation::new(smooth_force_config()).unwrap();
    for _ in 0..150 {
        stepped.step([0.0; 3]).unwrap();
    }
    let a = {
        let (q, v) = (stepped.position(), stepped.velocity());
        [q[0], q[1], q[2], v[0], v[1], v[2]]
    };
    let b = run_advance(2.5, end);
    let c = run_advance(1.25, end);
    let d = run_advance(0.3125, end);
    let reference = run_advance(0.0625, end);
    // Surge is the DOF the head seas drive; compare in surge (position, and velocity scaled
    // by the natural frequency).
    let wn = 2.0 * PI / 60.0;
    let distance = |x: &[f64; 6]| (x[0] - reference[0]).hypot((x[3] - reference[3]) / wn);
    let amplitude = reference[0].hypot(reference[3] / wn);
    assert!(amplitude > 1e-3, "surge response too small: {amplitude}");
    let (ea, eb, ec, ed) = (distance(&a), distance(&b), distance(&c), distance(&d));
    // RK4 with h = 1 s on a response below 0.2 rad/s: relative error below (0.2 h)^4 = 1.6e-3.
    for (name, e) in [("step h=1", ea), ("advance 5/6", eb), ("advance 0.625", ec)] {
        assert!(
            e < 1.6e-3 * amplitude,
            "{name}: error {e}, amplitude {amplitude}"
        );
    }
    // Fourth order against the h = 0.0625 reference (whose own error is (0.0625/0.3125)^4
    // = 0.16 % of the finest run's): substeps 1 -> 0.625 -> 0.3125.
    let order_ac = (ea / ec).ln() / 1.6f64.ln();
    let order_cd = (ec / ed).log2();
    assert!(
        (3.7..=4.3).contains(&order_ac) && (3.7..=4.3).contains(&order_cd),
        "orders {order_ac}, {order_cd} (errors {ea}, {eb}, {ec}, {ed})"
    );
    // The 5/6 s substep sits between the two.
    assert!(ec < eb && eb < ea, "errors {ea}, {eb}, {ec}");
}
