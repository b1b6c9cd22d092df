//! The wind's gust records against their spectra, each through the public API: the Welch
//! spectrum of a long stream of gust records in bands against the integral of the gust
//! spectrum (docs/theory.md#wind), for spectra of three shapes.

use crate::common::{simpson, welch_bands_match};
use slowdrift::forces::{plan_inverse_fft, GustStream, Record, Segments};
use slowdrift::sea_state::FrequencyGrid;
use slowdrift::wind::GustSpectrum;

/// 96 joined segments of 2048 samples at 0.5 s (27 hours): the Welch estimate (segments of
/// 1024 samples, Hann, 50 % overlap) in bands of 8 bins from 0.05 to 2.5 rad/s within five
/// standard deviations of Welch's scatter (plus 3 % for the join's ramps and the bins' own
/// width) of the integral of S_u per rad/s over each band, for NPD, Kaimal and Harris.
#[test]
fn gust_records_have_their_spectrum() {
    let segments = Segments {
        block: 2048,
        ramp: 256,
    };
    let dt = 0.5;
    let grid = FrequencyGrid::new(0.0, segments.span() as f64 * dt, dt, (0.3, 1.0)).unwrap();
    let spectra = [
        GustSpectrum::Npd {
            speed: 25.0,
            height: 40.0,
        },
        GustSpectrum::Kaimal {
            speed: 15.0,
            turbulence_intensity: 0.12,
            length_scale: 340.0,
        },
        GustSpectrum::Harris {
            speed: 20.0,
            drag_coefficient: 0.002,
        },
    ];
    for spectrum in spectra {
        let mut gusts = GustStream::new(&spectrum, &grid, segments, plan_inverse_fft(&grid));
        let mut record = Record::zero();
        let mut samples = Vec::new();
        for k in 0..96 {
            gusts.build(21, k, k > 0, &mut record);
            samples.extend_from_slice(&record.samples()[1..1 + segments.block]);
        }
        let (checked, worst) =
            welch_bands_match(&samples, dt, 1024, 8, (0.05, 2.5), 0.03, |a, b| {
                simpson(|w| spectrum.density_per_rad(w), a, b, 64)
            });
        assert!(checked >= 20, "{spectrum:?}: {checked} bands");
        println!("{spectrum:?}: {checked} bands, worst {worst:.2} sd");
    }
}

/// A platform in a wind along +X on a table of C_x = 1 at every angle (C_y = C_mz = 0),
/// A_x = 3000 m^2, force height 10 m, with surge and sway period `period` s, linear damping
/// ratio `zeta` and mass `mass`, under a sea of Hs 1 mm (its drift force is negligible: 1e-6
/// of a 1-m sea's).
fn windy_problem(
    speed: f64,
    spectrum: slowdrift::model::WindSpectrumKind,
    (mass, period, zeta): (f64, f64, f64),
    duration: f64,
    seed: u64,
) -> slowdrift::Problem {
    use slowdrift::wind::{CoefficientTable, WindCoefficients, WindField, WindLoad};
    let mut problem = crate::common::base_problem(duration, 0.5, seed);
    problem.sea.spectrum = slowdrift::sea_state::Spectrum::PiersonMoskowitz { hs: 1e-3, tp: 10.0 };
    problem.platform =
        crate::common::oscillator_platform(mass, 1e12, [period, period, 100.0], zeta);
    let angles: Vec<f64> = [-180.0f64, -90.0, 0.0, 90.0]
        .iter()
        .map(|d| d.to_radians())
        .collect();
    problem.platform.wind = Some(WindLoad {
        height: 10.0,
        coefficients: WindCoefficients::Table(CoefficientTable {
            cx: vec![1.0; 4],
            cy: vec![0.0; 4],
            cmz: vec![0.0; 4],
            angles,
            area_x: 3000.0,
            area_y: 3000.0,
            length: 50.0,
            centre: [0.0, 0.0],
        }),
    });
    problem.wind = WindField {
        speed,
        spectrum,
        ..WindField::default()
    };
    problem
}

const AREA: f64 = 3000.0;
const AIR: f64 = 1.225;

/// A steady wind (no gust) damps a free surge oscillation by rho_air C A U (the linearised
/// d/du of 1/2 rho C A (U - u)^2): the logarithmic decrement of the oscillation about the
/// mean offset F / k equals 2 pi zeta / sqrt(1 - zeta^2), zeta = rho C A U / (2 sqrt(k m)),
/// within 2 % (the quadratic term's share, (u / U)^2, is 0.1 %).
#[test]
fn a_steady_wind_damps_the_slow_drift() {
    use std::f64::consts::PI;
    let (speed, mass) = (20.0, 5.0e7);
    let mut problem = windy_problem(
        speed,
        slowdrift::model::WindSpectrumKind::Constant,
        (mass, 150.0, 0.0),
        1500.0,
        1,
    );
    let k = problem.platform.stiffness[0][0];
    let mean_force = 0.5 * AIR * AREA * speed * speed;
    let offset = mean_force / k;
    problem.initial.position = [offset + 3.0, 0.0, 0.0];
    let mut sim = slowdrift::Simulation::new(problem).unwrap();
    let mut x = Vec::new();
    while sim.time() < 1500.0 {
        x.push(sim.outputs().unwrap().position[0] - offset);
        sim.step([0.0; 3]).unwrap();
    }
    // Successive maxima of the oscillation (three-point peaks).
    let peaks: Vec<f64> = (1..x.len() - 1)
        .filter(|&i| x[i] > x[i - 1] && x[i] >= x[i + 1] && x[i] > 0.0)
        .map(|i| x[i])
        .collect();
    assert!(peaks.len() >= 4, "{peaks:?}");
    let decrement = (peaks[0] / peaks[3]).ln() / 3.0;
    let zeta = AIR * AREA * speed / (2.0 * (k * mass).sqrt());
    let expected = 2.0 * PI * zeta / (1.0 - zeta * zeta).sqrt();
    assert!(
        (decrement / expected - 1.0).abs() < 0.02,
        "decrement {decrement} vs {expected} (zeta {zeta})"
    );
}

/// The platform held (mass 1e10 kg, surge period 2 pi s, critically half-damped: it moves
/// by 1e-4 m and 1e-4 m/s): the wind force's mean is 1/2 rho A (U^2 + sigma_u^2)
/// within four standard errors, and its Welch spectrum in bands from 0.02 to 1.5 rad/s is
/// the linearised gust force's, (2 F / U)^2 S_u = (rho A U)^2 S_u, within five standard
/// deviations and 3 % (the u^2 term's share is sigma_u^2 / (2 U^2), 0.5 % here).
#[test]
fn the_gust_force_of_a_held_platform_is_the_linearised_spectrum() {
    let speed = 20.0;
    let problem = windy_problem(
        speed,
        slowdrift::model::WindSpectrumKind::Npd,
        (1e10, 2.0 * std::f64::consts::PI, 0.5),
        32768.0,
        4,
    );
    let wind = problem.run_wind().unwrap().unwrap().gusts.unwrap();
    assert!((wind.mean - speed).abs() < 1e-9, "NPD at 10 m: U0 itself");
    let mut sim = slowdrift::Simulation::new(problem).unwrap();
    let mut force = Vec::new();
    let mut speeds = Vec::new();
    while sim.time() < 32768.0 {
        let out = sim.outputs().unwrap();
        force.push(out.forces.wind[0]);
        speeds.push(out.wind_speed);
        sim.step([0.0; 3]).unwrap();
    }
    let n = force.len() as f64;
    let variance_u = {
        let m = speeds.iter().sum::<f64>() / n;
        speeds.iter().map(|u| (u - m).powi(2)).sum::<f64>() / n
    };
    let mean = force.iter().sum::<f64>() / n;
    let expected = 0.5 * AIR * AREA * (speed * speed + variance_u);
    let linear = AIR * AREA * speed;
    // sd of the mean: sqrt(S_F(0) / (2 T)) with S_F(0) per Hz = linear^2 S_u(f = 0).
    let sd = (linear * linear * wind.spectrum.density(0.0) / (2.0 * n * 0.5)).sqrt();
    assert!(
        (mean - expected).abs() < 4.0 * sd,
        "{mean} vs {expected} (sd {sd})"
    );
    let (checked, worst) = welch_bands_match(&force, 0.5, 2048, 8, (0.02, 1.5), 0.03, |a, b| {
        linear * linear * simpson(|w| wind.spectrum.density_per_rad(w), a, b, 64)
    });
    assert!(checked >= 20, "{checked}");
    println!("held platform: {checked} bands, worst {worst:.2} sd");
}

/// Wind alone on the oscillator: the slow-drift surge variance over 8 seeds of 2^15 s
/// against the frequency-domain integral of |H|^2 (rho A U)^2 S_u with the wind's damping
/// rho A U in H, within four standard errors of the seeds' mean (their own scatter) and
/// 3 % (the quadratic terms).
#[test]
fn surge_under_gusts_matches_the_frequency_domain() {
    let (speed, mass, zeta) = (20.0, 5.0e7, 0.02);
    let runs: Vec<f64> = slowdrift::studies::parallel_map(8, 2, |i| {
        let problem = windy_problem(
            speed,
            slowdrift::model::WindSpectrumKind::Npd,
            (mass, 150.0, zeta),
            32768.0 + 1500.0,
            100 + i as u64,
        );
        let mut sim = slowdrift::Simulation::new(problem).unwrap();
        let mut x = Vec::new();
        while sim.time() < 32768.0 + 1500.0 {
            if sim.time() >= 1500.0 {
                x.push(sim.outputs().unwrap().position[0]);
            }
            sim.step([0.0; 3]).unwrap();
        }
        let n = x.len() as f64;
        let m = x.iter().sum::<f64>() / n;
        x.iter().map(|v| (v - m).powi(2)).sum::<f64>() / n
    });
    let problem = windy_problem(
        speed,
        slowdrift::model::WindSpectrumKind::Npd,
        (mass, 150.0, zeta),
        100.0,
        1,
    );
    let wind = problem.run_wind().unwrap().unwrap().gusts.unwrap();
    let k = problem.platform.stiffness[0][0];
    let damping = problem.platform.linear_damping[0][0] + AIR * AREA * speed;
    let linear = AIR * AREA * speed;
    let transfer = |w: f64| 1.0 / ((k - mass * w * w).powi(2) + (damping * w).powi(2));
    // The records' band: d_omega / 2 of the 16384-s block to the Nyquist frequency of 0.25 s.
    let (lo, hi) = (std::f64::consts::PI / 16384.0, 4.0 * std::f64::consts::PI);
    let expected = simpson(
        |w| linear * linear * wind.spectrum.density_per_rad(w) * transfer(w),
        lo,
        hi,
        200_000,
    );
    let mean = runs.iter().sum::<f64>() / runs.len() as f64;
    let sd = (runs.iter().map(|v| (v - mean).powi(2)).sum::<f64>()
        / (runs.len() as f64 - 1.0)
        / runs.len() as f64)
        .sqrt();
    println!("surge variance {mean} +- {sd} vs {expected}");
    assert!(
        (mean - expected).abs() < 4.0 * sd + 0.03 * expected,
        "{mean} +- {sd} vs {expected}"
    );
}

/// One seed, one wind and one sea: the wind speed of a run of 20 000 s is the first part of a
/// run of 40 000 s bit for bit (the gusts do not depend on the stop time), and the wave
/// elevation with the wind is the elevation without it, bit for bit (adding wind does not
/// change the sea).
#[test]
fn the_wind_of_a_seed_does_not_depend_on_the_stop_time_or_touch_the_sea() {
    let run = |duration: f64, speed: f64| {
        let problem = windy_problem(
            speed,
            slowdrift::model::WindSpectrumKind::Kaimal,
            (5.0e7, 150.0, 0.05),
            duration,
            8,
        );
        let mut sim = slowdrift::Simulation::new(problem).unwrap();
        let mut out = Vec::new();
        while sim.time() < 20_000.0 {
            let o = sim.outputs().unwrap();
            out.push((o.wind_speed, o.wave_elevation));
            sim.step([0.0; 3]).unwrap();
        }
        out
    };
    let short = run(20_000.0, 15.0);
    assert_eq!(short, run(40_000.0, 15.0));
    let calm = run(20_000.0, 0.0);
    assert!(calm.iter().all(|(u, _)| *u == 0.0));
    assert!(short.iter().zip(&calm).all(|(w, c)| w.1 == c.1));
    assert!(short.iter().any(|(u, _)| (u - short[0].0).abs() > 0.1));
}

/// `study motion`'s slow-drift prediction with wind on the oscillator of
/// [`surge_under_gusts_matches_the_frequency_domain`]: the wind damping it linearises is
/// rho A U (the closed form), its gust part's surge variance the hand integral of |H|^2
/// (rho A U)^2 S_u within 3 % (a coarser grid, and it integrates from 0 where the records
/// start at half the block's lowest frequency), and the waves' part of a 1-mm sea nil.
#[test]
fn the_motion_prediction_takes_the_wind() {
    use slowdrift::studies::motion_spectra::SlowDriftPrediction;
    let (speed, mass, zeta) = (20.0, 5.0e7, 0.02);
    let problem = windy_problem(
        speed,
        slowdrift::model::WindSpectrumKind::Npd,
        (mass, 150.0, zeta),
        100.0,
        1,
    );
    let prediction = SlowDriftPrediction::new(&problem).unwrap();
    let wind_damping = prediction.damping[0].wind;
    assert!(
        (wind_damping / (AIR * AREA * speed) - 1.0).abs() < 1e-6,
        "{wind_damping}"
    );
    let wind = problem.run_wind().unwrap().unwrap().gusts.unwrap();
    let k = problem.platform.stiffness[0][0];
    let damping = problem.platform.linear_damping[0][0] + AIR * AREA * speed;
    let linear = AIR * AREA * speed;
    let hand = simpson(
        |w| {
            linear * linear * wind.spectrum.density_per_rad(w)
                / ((k - mass * w * w).powi(2) + (damping * w).powi(2))
        },
        std::f64::consts::PI / 16384.0,
        4.0 * std::f64::consts::PI,
        200_000,
    );
    let predicted = prediction.variance(0);
    assert!(
        (predicted / hand - 1.0).abs() < 0.03,
        "{predicted} vs {hand}"
    );
    let waves: f64 = prediction
        .mu()
        .enumerate()
        .map(|(m, _)| prediction.wave_density(0, m))
        .sum::<f64>()
        * prediction.d_mu;
    assert!(waves < 1e-6 * predicted, "{waves}");
}

/// The FMU with `windSpeed` = 15 m/s, `windDirection` = 0.5 rad and `windSpectrum` = 5
/// (kaimal) over the packed default gives every output, the wind's (`windVelocity`,
/// `Fx_wind`, `Fy_wind`, `Mz_wind`) and the motion, of the library's run of the default with
/// that `[wind]`, bit for bit over 200 steps of 1 s under a varying external force;
/// `windSpeed` = 0 (the other wind parameters set all the same) gives wind outputs of zero
/// and the default's run without wind.
#[test]
fn the_fmu_wind_outputs_are_the_librarys() {
    use crate::fmu::{bits, default_platform, external, native_outputs, Fmu};
    use slowdrift::fmi2::model_description::vr;
    use slowdrift::fmi2::types::fmi2Status;
    use slowdrift::model::{Mode, WindSpectrumKind};
    use slowdrift::scenario::overrides::by_fmu;
    let stop = 200.0;
    let kaimal = 5;
    let spectrum = by_fmu("windSpectrum").unwrap();
    assert_eq!(
        spectrum.code_of(WindSpectrumKind::Kaimal.word()),
        Some(kaimal)
    );
    let run = |speed: f64| {
        let fmu = Fmu::new(&format!("wind-{speed}"));
        assert_eq!(fmu.setup(0.0, Some(stop)), fmi2Status::fmi2OK);
        assert_eq!(fmu.set_real(vr::WIND_SPEED, speed), fmi2Status::fmi2OK);
        assert_eq!(fmu.set_real(vr::WIND_DIRECTION, 0.5), fmi2Status::fmi2OK);
        assert_eq!(fmu.set_int(vr::WIND_SPECTRUM, kaimal), fmi2Status::fmi2OK);
        assert_eq!(fmu.init(), fmi2Status::fmi2OK, "{}", fmu.messages());
        fmu
    };
    let native = |speed: f64| {
        let mut problem = default_platform().clone();
        problem.wind.speed = speed;
        problem.wind.direction = 0.5;
        problem.wind.spectrum = WindSpectrumKind::Kaimal;
        problem.run.duration = stop;
        slowdrift::Simulation::new(problem).unwrap()
    };
    let (windy, calm) = (run(15.0), run(0.0));
    let (mut windy_native, mut calm_native) = (native(15.0), native(0.0));
    let mut calm_default = crate::fmu::native(1, 0.0, 0.0, stop);
    let wind = [vr::WIND_VELOCITY, vr::FX_WIND, vr::FY_WIND, vr::MZ_WIND];
    let (mut speeds, mut pushed) = (Vec::new(), 0.0f64);
    for n in 0..stop as usize {
        let t = n as f64;
        let expected = native_outputs(&windy_native.outputs().unwrap());
        assert_eq!(bits(&windy.outputs()), bits(&expected), "t = {t} s");
        let calm_expected = native_outputs(&calm_native.outputs().unwrap());
        assert_eq!(bits(&calm.outputs()), bits(&calm_expected), "t = {t} s");
        assert_eq!(
            bits(&calm_expected),
            bits(&native_outputs(&calm_default.outputs().unwrap())),
            "t = {t} s: no wind is the default's run"
        );
        let (_, zeros) = calm.get_reals(&wind);
        assert_eq!(zeros, [0.0; 4], "t = {t} s");
        let (_, blown) = windy.get_reals(&wind);
        speeds.push(blown[0]);
        pushed = pushed.max(blown[1].hypot(blown[2]));
        for (fmu, sim) in [(&windy, &mut windy_native), (&calm, &mut calm_native)] {
            fmu.step_with(t, 1.0, external(n));
            sim.advance(1.0, external(n)).unwrap();
        }
        calm_default.advance(1.0, external(n)).unwrap();
    }
    let spread = speeds
        .iter()
        .fold(0.0f64, |m, u| m.max((u - speeds[0]).abs()));
    assert!(speeds.iter().all(|u| *u > 5.0), "{speeds:?}");
    assert!(spread > 0.1, "the gusts move the wind speed: {spread} m/s");
    assert!(pushed > 1.0e4, "the wind pushes: {pushed} N");
}

/// The input wind (`wind.source = "input"`) against the records' constant wind: on the
/// default platform's six API areas under a power-law profile (whose shape is the same at
/// every speed), a run whose input holds U(25 m) = 15 (25/10)^0.12 m/s gives the wind force
/// and the motion of a run with a constant wind of 15 m/s at 10 m, to 1e-9 relative over
/// 600 s: two routes to the speed at each area's height. With the input at 0 (still air),
/// the wind force only damps: Fx_wind Xdot <= 0 at every step, and not all zero.
#[test]
fn an_input_wind_is_the_records_wind_of_the_same_speed() {
    use slowdrift::model::{WindSource, WindSpectrumKind};
    use slowdrift::wind::WindProfile;
    let (stop, speed, exponent) = (600.0, 15.0, 0.12);
    let problem = |source: WindSource| {
        let mut p = crate::fmu::default_platform().clone();
        p.run.duration = stop;
        p.wind.direction = 0.5;
        p.wind.profile = WindProfile::PowerLaw { exponent };
        p.wind.spectrum = WindSpectrumKind::Constant;
        p.wind.source = source;
        p.wind.speed = if source == WindSource::Records {
            speed
        } else {
            0.0
        };
        slowdrift::Simulation::new(p).unwrap()
    };
    let at_force = speed * (25.0f64 / 10.0).powf(exponent);
    let (mut records, mut input, mut still) = (
        problem(WindSource::Records),
        problem(WindSource::Input),
        problem(WindSource::Input),
    );
    input.hold_wind_input(at_force).unwrap();
    let (mut worst, mut damped) = (0.0f64, 0.0f64);
    for _ in 0..(stop as usize) {
        for sim in [&mut records, &mut input, &mut still] {
            sim.advance(1.0, [0.0; 3]).unwrap();
        }
        let (a, b) = (records.outputs().unwrap(), input.outputs().unwrap());
        assert!((b.wind_speed / at_force - 1.0).abs() < 1e-12);
        for i in 0..3 {
            let scale = a.forces.wind[0].abs();
            worst = worst.max((a.forces.wind[i] - b.forces.wind[i]).abs() / scale);
        }
        worst = worst.max((a.position[0] - b.position[0]).abs() / a.position[0].abs());
        let s = still.outputs().unwrap();
        assert_eq!(s.wind_speed, 0.0);
        let power = s.forces.wind[0] * s.velocity[0];
        assert!(power <= 0.0, "still air pushes: {power}");
        damped = damped.max(-power);
    }
    assert!(worst < 1e-9, "input vs records: {worst:e}");
    assert!(damped > 0.0, "still air damps");
}

/// The FMU's input `windVelocity_ext` with `windSource` = 1: every output equals the
/// library's run of the same source holding the same speeds, bit for bit, over 100 steps of
/// 1 s with a speed that changes each step; `windVelocity` is the speed the last step held;
/// a negative speed is refused (fmi2Error) naming windVelocity_ext; a state saved and
/// restored in a fresh instance brings the held speed back (the outputs equal).
#[test]
fn the_fmu_wind_input_is_the_librarys() {
    use crate::fmu::{bits, default_platform, native_outputs, Fmu};
    use slowdrift::fmi2::model_description::vr;
    use slowdrift::fmi2::types::fmi2Status;
    use slowdrift::model::WindSource;
    let stop = 100.0;
    let fmu = Fmu::new("wind-input");
    assert_eq!(fmu.setup(0.0, Some(stop)), fmi2Status::fmi2OK);
    assert_eq!(fmu.set_int(vr::WIND_SOURCE, 1), fmi2Status::fmi2OK);
    assert_eq!(fmu.set_real(vr::WIND_DIRECTION, -0.3), fmi2Status::fmi2OK);
    assert_eq!(
        fmu.set_real(vr::WIND_VELOCITY_EXT, 12.0),
        fmi2Status::fmi2OK
    );
    assert_eq!(fmu.init(), fmi2Status::fmi2OK, "{}", fmu.messages());
    let mut problem = default_platform().clone();
    problem.wind.source = WindSource::Input;
    problem.wind.direction = -0.3;
    problem.run.duration = stop;
    let mut native = slowdrift::Simulation::new(problem).unwrap();
    native.hold_wind_input(12.0).unwrap();
    let speed = |n: usize| 12.0 + 4.0 * (n as f64 / 7.0).sin();
    let mut saved = None;
    for n in 0..stop as usize {
        let expected = native_outputs(&native.outputs().unwrap());
        assert_eq!(bits(&fmu.outputs()), bits(&expected), "t = {n} s");
        let held = if n == 0 { 12.0 } else { speed(n - 1) };
        assert_eq!(fmu.get_reals(&[vr::WIND_VELOCITY]).1, [held]);
        if n == 50 {
            use crate::fmu::{free_state, get_state, serialize};
            let state = get_state(&fmu);
            saved = Some((serialize(&fmu, state), expected));
            free_state(&fmu, state);
        }
        assert_eq!(
            fmu.set_real(vr::WIND_VELOCITY_EXT, speed(n)),
            fmi2Status::fmi2OK
        );
        assert_eq!(fmu.step(n as f64, 1.0), fmi2Status::fmi2OK);
        native.hold_wind_input(speed(n)).unwrap();
        native.advance(1.0, [0.0; 3]).unwrap();
    }
    assert_eq!(
        fmu.set_real(vr::WIND_VELOCITY_EXT, -1.0),
        fmi2Status::fmi2Error
    );
    assert!(
        fmu.last_message().message.contains("windVelocity_ext = -1"),
        "{}",
        fmu.messages()
    );
    let (bytes, expected) = saved.unwrap();
    let fresh = Fmu::new("restored");
    crate::fmi2_state::restore(&fresh, &bytes).unwrap();
    assert_eq!(bits(&fresh.outputs()), bits(&expected));
}
