//! The wave-frequency motion of a run against the frequency domain, in every DOF.
//!
//! Real data: the IEA-15 semi's WAMIT import with the `[platform.motions]` of `rao.rs`
//! (skipped with a line when `../shared/data` is absent). The sea is a Pierson-Moskowitz
//! spectrum, whose density is written here from its closed form, at 20 deg so that every
//! DOF moves. The expected statistics are the frequency-domain integrals on the run's own
//! frequencies omega_j (spacing d_omega):
//!
//! ```text
//! E[x_i^2]       = sum_j |xi_i|^2 S d_omega        E[x_i'^2]     = sum_j omega^2 |xi_i|^2 S d_omega
//! E[eta x_i]     = sum_j Re xi_i S d_omega          E[eta x_i']   = -sum_j omega Im xi_i S d_omega
//! ```
//!
//! (eta = Re sum a_j e^{i omega_j t}, x_i = Re sum a_j xi_ij e^{i omega_j t}, E|a_j|^2 = 2 S
//! d_omega), xi interpolated here linearly in frequency and heading from the RAOs of the
//! problem (the RAO solve itself is checked against the raw files in `rao.rs`). The record
//! of one seed has |a_j|^2 / 2 = S d_omega E_j with E_j independent unit exponentials, so
//! each estimate is sum_j w_j E_j with standard deviation sqrt(sum_j w_j^2): the tolerance
//! is four of those (over the seeds) plus the window's share (a 3-hour window of a longer
//! block). The covariances with the elevation check the phase convention (a conjugated
//! RAO flips E[eta x'], a wrong heading moves sway and roll).

use crate::rao::{iea15_root_or_skip, toml_matrix, I_ROLL_PITCH, I_YAW, MASS, ZG};
use crate::wamit::{temp_dir, write};
use rustfft::num_complex::Complex64;
use rustfft::FftPlanner;
use slowdrift::hydro::io::wamit::{self, WamitOptions};
use slowdrift::hydro::rao::Rao;
use slowdrift::Simulation;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

const HS: f64 = 4.0;
const TP: f64 = 10.0;
const HEADING_DEG: f64 = 20.0;
const DURATION: f64 = 10800.0;
const SEEDS: u64 = 4;
const DOFS: [&str; 6] = ["surge", "sway", "heave", "roll", "pitch", "yaw"];

/// Pierson-Moskowitz, one-sided, m^2 s/rad: 5/16 Hs^2 wp^4 / w^5 exp(-5/4 (wp/w)^4).
fn pierson_moskowitz(w: f64) -> f64 {
    let wp = 2.0 * PI / TP;
    5.0 / 16.0 * HS * HS * wp.powi(4) / w.powi(5) * (-1.25 * (wp / w).powi(4)).exp()
}

/// The IEA-15 configuration of this file, with `model` lines added to `[model]`.
fn configuration(dir: &Path, root: &Path, seed: u64, model: &str) -> PathBuf {
    let json = dir.join("iea15.json");
    if !json.exists() {
        wamit::import(root, &WamitOptions::default())
            .unwrap()
            .database
            .save(&json)
            .unwrap();
        // The `.12d`'s drift has the heading 0 alone: copied to every 45 deg so that the
        // sea's 20 deg is covered (the slow drift is not what this file checks).
        let mut database: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
        let rows = database["drift"].as_array().unwrap().clone();
        let copies: Vec<serde_json::Value> = (-4..4)
            .flat_map(|k| {
                rows.iter().map(move |row| {
                    let mut row = row.clone();
                    row["heading"] = serde_json::json!(k as f64 * PI / 4.0);
                    row
                })
            })
            .collect();
        database["drift"] = serde_json::Value::Array(copies);
        std::fs::write(&json, serde_json::to_string(&database).unwrap()).unwrap();
    }
    let tensor = [
        [I_ROLL_PITCH, 0.0, 0.0],
        [0.0, I_ROLL_PITCH, 0.0],
        [0.0, 0.0, I_YAW],
    ];
    let mut c_ext = [[0.0; 6]; 6];
    c_ext[0][0] = 7.0e4;
    c_ext[1][1] = 7.0e4;
    c_ext[5][5] = 5.0e7;
    let mut b_ext = [[0.0; 6]; 6];
    b_ext[2][2] = 5.0e5;
    b_ext[3][3] = 2.0e9;
    b_ext[4][4] = 2.0e9;
    b_ext[5][5] = 5.0e8;
    write(
        dir,
        &format!("iea15-{seed}.toml"),
        &format!(
            "[sea]\nspectrum = \"pierson-moskowitz\"\nhs = {HS}\ntp = {TP}\nband = [0.3, 1.5]\n\
             direction_deg = {HEADING_DEG}\nseed = {seed}\n\n\
             [run]\nduration = {DURATION}\n\n\
             [platform]\nmass = {MASS:e}\nyaw_inertia = {I_YAW:e}\n\
             stiffness = [[7.0e4, 0, 0], [0, 7.0e4, 0], [0, 0, 5.0e7]]\n\n\
             [platform.motions]\ncentre_of_gravity = [0.0, 0.0, {ZG:e}]\ninertia = {}\n\
             external_stiffness = {}\nexternal_damping = {}\n\n\
             [model]\ndrift_damping = \"off\"\n{model}\n\n\
             [drift]\nsource = \"database\"\nfile = \"iea15.json\"\n",
            toml_matrix(&tensor),
            toml_matrix(&c_ext),
            toml_matrix(&b_ext)
        ),
    )
}

/// xi(omega, beta) by linear interpolation in frequency and heading (inside the table).
fn rao_at(rao: &Rao, w: f64, beta: f64) -> [Complex64; 6] {
    let bracket = |nodes: &[f64], x: f64| {
        let k = nodes.partition_point(|&v| v <= x).clamp(1, nodes.len() - 1);
        (k - 1, k, (x - nodes[k - 1]) / (nodes[k] - nodes[k - 1]))
    };
    let (w0, w1, s) = bracket(&rao.omegas, w);
    let (h0, h1, r) = bracket(&rao.headings, beta);
    std::array::from_fn(|i| {
        let v = |n: usize, h: usize| rao.values[n][h][i];
        (v(w0, h0) * (1.0 - r) + v(w0, h1) * r) * (1.0 - s)
            + (v(w1, h0) * (1.0 - r) + v(w1, h1) * r) * s
    })
}

/// An estimate sum_j w_j E_j: its expectation and standard deviation for one seed.
#[derive(Default, Clone, Copy)]
struct Expected {
    mean: f64,
    variance: f64,
}

impl Expected {
    fn add(&mut self, w: f64) {
        self.mean += w;
        self.variance += w * w;
    }

    /// Four standard deviations of the mean over the seeds plus `floor`.
    fn tolerance(&self, floor: f64) -> f64 {
        4.0 * (self.variance / SEEDS as f64).sqrt() + floor
    }
}

/// The body-frame motion x_b = R(-theta) x_wf of the outputs (translations and the small
/// rotation vector turn alike; heave and yaw do not turn).
fn body_frame(x: [f64; 6], theta: f64) -> [f64; 6] {
    let (s, c) = theta.sin_cos();
    let back = |u: f64, v: f64| [c * u + s * v, -s * u + c * v];
    let [a, b] = back(x[0], x[1]);
    let [r, p] = back(x[3], x[4]);
    [a, b, x[2], r, p, x[5]]
}

/// One-sided band power of a series from its periodogram, between `lo` and `hi` rad/s.
fn band_power(series: &[f64], dt: f64, lo: f64, hi: f64) -> f64 {
    let n = series.len();
    let mut x: Vec<Complex64> = series.iter().map(|&v| Complex64::new(v, 0.0)).collect();
    FftPlanner::new().plan_fft_forward(n).process(&mut x);
    let d_omega = 2.0 * PI / (n as f64 * dt);
    (1..n / 2)
        .filter(|&m| (lo..hi).contains(&(m as f64 * d_omega)))
        .map(|m| 2.0 * x[m].norm_sqr() / (n * n) as f64)
        .sum()
}

/// Every DOF's wave-frequency motion: its variance, its band powers, its rate's variance
/// and its covariances with the elevation are the frequency-domain integrals.
#[test]
fn the_motion_of_a_run_is_the_raos_on_its_sea_in_every_dof() {
    let Some(root) = iea15_root_or_skip() else {
        return;
    };
    let dir = temp_dir("wave-frequency-spectra");
    let beta = HEADING_DEG.to_radians();
    let bands = [(0.3, 0.6), (0.6, 0.9), (0.9, 1.5)];
    // Sums over the seeds: x^2, x'^2, eta x, eta x', band powers.
    let mut measured = [[0.0; 4]; 6];
    let mut measured_bands = [[0.0; 3]; 6];
    let mut expected = [[Expected::default(); 4]; 6];
    let mut expected_bands = [[Expected::default(); 3]; 6];
    let mut eta_variance = 0.0;
    for seed in 1..=SEEDS {
        let config = configuration(&dir, &root, seed, "");
        let problem = slowdrift::problem::load(&config).unwrap();
        let rao = problem
            .first_order_motions()
            .unwrap()
            .expect("RAOs from [platform.motions]")
            .rao;
        let mut simulation = Simulation::new(problem).unwrap();
        if seed == 1 {
            let grid = simulation.grid().clone();
            for j in 0..grid.count {
                let w = grid.omega(j);
                let s_dw = pierson_moskowitz(w) * grid.d_omega;
                eta_variance += s_dw;
                let xi = rao_at(&rao, w, beta);
                for i in 0..6 {
                    let e = &mut expected[i];
                    e[0].add(xi[i].norm_sqr() * s_dw);
                    e[1].add(w * w * xi[i].norm_sqr() * s_dw);
                    e[2].add(xi[i].re * s_dw);
                    e[3].add(-w * xi[i].im * s_dw);
                    for (b, &(lo, hi)) in bands.iter().enumerate() {
                        if (lo..hi).contains(&w) {
                            expected_bands[i][b].add(xi[i].norm_sqr() * s_dw);
                        }
                    }
                }
            }
        }
        let steps = DURATION as usize;
        let mut x = vec![[0.0; 6]; steps];
        let mut v = vec![[0.0; 6]; steps];
        let mut eta = vec![0.0; steps];
        for m in 0..steps {
            let o = simulation.outputs().unwrap();
            let theta = o.position[2];
            x[m] = body_frame(o.motion.wave_frequency, theta);
            // The rates of the totals less the slow drift's, turned back: d/dt R x_b =
            // R x_b' + theta' R J x_b.
            let mut rate = o.motion.total_rate;
            rate[0] -= o.velocity[0];
            rate[1] -= o.velocity[1];
            rate[5] -= o.velocity[2];
            let w = o.motion.wave_frequency;
            let td = o.velocity[2];
            let turned = [
                rate[0] + td * w[1],
                rate[1] - td * w[0],
                rate[2],
                rate[3] + td * w[4],
                rate[4] - td * w[3],
                rate[5],
            ];
            v[m] = body_frame(turned, theta);
            eta[m] = o.wave_elevation;
            simulation.step([0.0; 3]).unwrap();
        }
        let n = steps as f64;
        for i in 0..6 {
            let series: Vec<f64> = x.iter().map(|r| r[i]).collect();
            measured[i][0] += series.iter().map(|a| a * a).sum::<f64>() / n;
            measured[i][1] += v.iter().map(|r| r[i] * r[i]).sum::<f64>() / n;
            measured[i][2] += eta.iter().zip(&series).map(|(e, a)| e * a).sum::<f64>() / n;
            measured[i][3] += eta.iter().zip(&v).map(|(e, r)| e * r[i]).sum::<f64>() / n;
            for (b, &(lo, hi)) in bands.iter().enumerate() {
                measured_bands[i][b] += band_power(&series, 1.0, lo, hi);
            }
        }
    }
    let seeds = SEEDS as f64;
    let names = ["E[x^2]", "E[x'^2]", "E[eta x]", "E[eta x']"];
    for i in 0..6 {
        for k in 0..4 {
            let got = measured[i][k] / seeds;
            let e = expected[i][k];
            // The window's share: 3 % of the variance, or of sqrt(var eta var x) for a
            // covariance.
            let scale = match k {
                0 | 1 => expected[i][k].mean,
                2 => (eta_variance * expected[i][0].mean).sqrt(),
                _ => (eta_variance * expected[i][1].mean).sqrt(),
            };
            let tolerance = e.tolerance(0.03 * scale);
            eprintln!(
                "{} {}: run {got:.5e}, frequency domain {:.5e} +- {tolerance:.2e}",
                DOFS[i], names[k], e.mean
            );
            assert!(
                (got - e.mean).abs() <= tolerance,
                "{} {}: run {got:e}, frequency domain {:e} +- {tolerance:e}",
                DOFS[i],
                names[k],
                e.mean
            );
        }
        let total = expected[i][0].mean;
        for (b, &(lo, hi)) in bands.iter().enumerate() {
            let got = measured_bands[i][b] / seeds;
            let e = expected_bands[i][b];
            let tolerance = e.tolerance(0.05 * e.mean + 0.01 * total);
            eprintln!(
                "{} band [{lo}, {hi}] rad/s: run {got:.5e}, |RAO|^2 S {:.5e} +- {tolerance:.2e}",
                DOFS[i], e.mean
            );
            assert!(
                (got - e.mean).abs() <= tolerance,
                "{} band [{lo}, {hi}]: run {got:e}, |RAO|^2 S {:e}",
                DOFS[i],
                e.mean
            );
        }
    }
    // Every DOF moves: the check above is not of zeros.
    for i in 0..6 {
        assert!(expected[i][0].mean > 0.0, "{} does not move", DOFS[i]);
    }
}

/// The totals are the slow drift plus the wave-frequency motion turned by the slow yaw; the
/// slow drift is the same with the motion on or off, bit for bit (the equations do not use
/// it); off, the wave-frequency outputs are zero and the totals the slow drift.
#[test]
fn the_totals_add_the_motion_to_an_unchanged_slow_drift() {
    let Some(root) = iea15_root_or_skip() else {
        return;
    };
    let dir = temp_dir("wave-frequency-totals");
    let on = configuration(&dir, &root, 7, "");
    let off_dir = temp_dir("wave-frequency-totals-off");
    let off = configuration(&off_dir, &root, 7, "wave_frequency_motion = \"off\"");
    let mut with = Simulation::new(slowdrift::problem::load(&on).unwrap()).unwrap();
    let mut without = Simulation::new(slowdrift::problem::load(&off).unwrap()).unwrap();
    let mut moved = 0.0f64;
    for _ in 0..2000 {
        let (a, b) = (with.outputs().unwrap(), without.outputs().unwrap());
        assert_eq!(a.position, b.position);
        assert_eq!(a.velocity, b.velocity);
        assert_eq!(b.motion.wave_frequency, [0.0; 6]);
        let q = b.position;
        assert_eq!(b.motion.total, [q[0], q[1], 0.0, 0.0, 0.0, q[2]]);
        let w = a.motion.wave_frequency;
        let (s, c) = q[2].sin_cos();
        let expected = [q[0] + w[0], q[1] + w[1], w[2], w[3], w[4], q[2] + w[5]];
        assert_eq!(a.motion.total, expected);
        // The inertial wave-frequency translation has the body-frame one's length.
        let body = [c * w[0] + s * w[1], -s * w[0] + c * w[1]];
        assert!((body[0].hypot(body[1]) - w[0].hypot(w[1])).abs() < 1e-12);
        moved = moved.max(w[2].abs());
        with.step([0.0; 3]).unwrap();
        without.step([0.0; 3]).unwrap();
    }
    assert!(moved > 0.1, "heave reached only {moved} m");
    let summary = slowdrift::problem::load(&off)
        .unwrap()
        .summary()
        .unwrap()
        .join("\n");
    assert!(
        summary.contains("wave-frequency motion: off ([model] wave_frequency_motion)"),
        "{summary}"
    );
}

/// The FMU gives the same whole motion as the native run of its configuration, bit for bit;
/// `waveFrequencyMotion` = 0 (off) makes the wave-frequency outputs zero and the totals the
/// slow drift, which is unchanged.
#[test]
fn the_fmu_outputs_the_whole_motion_and_turns_it_off() {
    use crate::fmu::{bits, native_outputs, Fmu};
    use slowdrift::fmi2::model_description::vr;
    use slowdrift::fmi2::types::fmi2Status;
    let Some(root) = iea15_root_or_skip() else {
        return;
    };
    let dir = temp_dir("wave-frequency-fmu");
    let config = configuration(&dir, &root, 3, "");
    let stop = 300.0;
    let run = |off: bool| {
        let fmu = Fmu::new(if off { "motion-off" } else { "motion-on" });
        assert_eq!(fmu.setup(0.0, Some(stop)), fmi2Status::fmi2OK);
        let path = config.to_str().unwrap();
        assert_eq!(fmu.set_string(vr::HYDRO_DATABASE, path), fmi2Status::fmi2OK);
        if off {
            assert_eq!(
                fmu.set_int(vr::WAVE_FREQUENCY_MOTION, 0),
                fmi2Status::fmi2OK
            );
        }
        assert_eq!(fmu.init(), fmi2Status::fmi2OK, "{}", fmu.messages());
        fmu
    };
    let (on, off) = (run(false), run(true));
    let mut problem = slowdrift::problem::load(&config).unwrap();
    problem.run.duration = stop;
    let mut native = Simulation::new(problem).unwrap();
    let total = [
        vr::X_TOTAL,
        vr::Y_TOTAL,
        vr::Z_TOTAL,
        vr::ROLL_TOTAL,
        vr::PITCH_TOTAL,
    ];
    let wave_frequency = [
        vr::X_WF,
        vr::Y_WF,
        vr::Z_WF,
        vr::ROLL_WF,
        vr::PITCH_WF,
        vr::YAW_WF,
    ];
    let mut heave = 0.0f64;
    for n in 0..stop as usize {
        let t = n as f64;
        assert_eq!(
            bits(&on.outputs()),
            bits(&native_outputs(&native.outputs().unwrap())),
            "t = {t} s"
        );
        let (_, slow) = off.get_reals(&[vr::X, vr::Y, vr::THETA]);
        let (_, moved) = on.get_reals(&[vr::X, vr::Y, vr::THETA]);
        assert_eq!(slow, moved, "the slow drift is the same, t = {t} s");
        let (_, zeros) = off.get_reals(&wave_frequency);
        assert_eq!(zeros, [0.0; 6]);
        let (_, totals) = off.get_reals(&total);
        assert_eq!(totals, [slow[0], slow[1], 0.0, 0.0, 0.0]);
        let (_, z) = on.get_reals(&[vr::Z_WF]);
        heave = heave.max(z[0].abs());
        on.step_with(t, 1.0, [0.0; 3]);
        off.step_with(t, 1.0, [0.0; 3]);
        native.advance(1.0, [0.0; 3]).unwrap();
    }
    assert!(heave > 0.1, "heave reached only {heave} m");
}

/// With yaw following, the motion records at each body yaw theta_j of the grid are those of
/// the mean position in the same sea turned by -theta_j (the relative heading is all the
/// RAOs see): a run at 20 deg with records at 12 yaws against runs at 20 deg - theta_j.
#[test]
fn yaw_following_motion_is_the_sea_at_the_relative_heading() {
    let Some(root) = iea15_root_or_skip() else {
        return;
    };
    let dir = temp_dir("wave-frequency-yaw");
    let config = configuration(&dir, &root, 5, "yaw_following = { headings = 12 }");
    let mut problem = slowdrift::problem::load(&config).unwrap();
    problem.run.duration = 600.0;
    let following = Simulation::new(problem.clone()).unwrap();
    let sets = &following.records().motion.as_ref().unwrap().sets;
    assert_eq!(sets.len(), 12);
    for (j, set) in sets.iter().enumerate() {
        let theta = 2.0 * PI * (j as f64 / 12.0 - 0.5);
        let mut turned = problem.clone();
        turned.model.yaw_following = None;
        turned.sea.mean_direction = HEADING_DEG.to_radians() - theta;
        let mean_position = Simulation::new(turned).unwrap();
        let own = &mean_position.records().motion.as_ref().unwrap().sets[0];
        for i in 0..6 {
            let (a, b) = (set.position[i].samples(), own.position[i].samples());
            let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let worst = a
                .iter()
                .zip(b)
                .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
            assert!(
                worst <= 1e-12 * scale,
                "yaw {:.0} deg, DOF {i}: {worst:e} of {scale:e}",
                theta.to_degrees()
            );
        }
    }
}

/// RAOs that leave more than 1 % of the band's variance without motion are refused, naming
/// the RAOs' range and the switch; with the motion off the same sea runs. The embedded
/// default's RAOs end at 2 rad/s, inside its default band (0.26 .. 2.09 rad/s), and its
/// summary states the share left out.
#[test]
fn raos_that_miss_the_band_are_refused_unless_the_motion_is_off() {
    let mut problem = slowdrift::problem::default_problem().unwrap();
    let summary = problem.summary().unwrap().join("\n");
    assert!(
        summary
            .contains("the RAOs span 0.04 to 2 rad/s, the band outside (0.08 % of its variance)"),
        "{summary}"
    );
    problem.sea.band = Some((0.5, 3.0));
    match &mut problem.sea.spectrum {
        slowdrift::sea_state::Spectrum::Jonswap { tp, hs, .. } => {
            *tp = 5.0;
            *hs = 2.0;
        }
        other => panic!("{other:?}"),
    }
    problem.run.duration = 100.0;
    let message = Simulation::new(problem.clone()).unwrap_err().to_string();
    assert!(
        message.contains("first-order motions")
            && message.contains("RAOs on [0.04, 2] rad/s")
            && message.contains("wave_frequency_motion = \"off\""),
        "{message}"
    );
    problem.model.wave_frequency_motion = slowdrift::model::WaveFrequencyMotion::Off;
    Simulation::new(problem).unwrap();
}
