//! States are checked like parameters: a restored state beyond the
//! documented bounds of a physical state is refused naming the value; a step that leaves
//! them, or an output that is not finite, is an error that names its cause (the force that
//! alone would leave the bounds within a step, the external input, or the step itself),
//! judged against closed forms: the RK4 stability limit of an undamped oscillator and the
//! velocity a force gives a mass in one step. Through the FMU: a forged state with
//! velocities of 1e200 m/s is refused by fmi2DeSerializeFMUstate; an Hs of 1e200 m is
//! refused as steeper than waves can be; an output that would be infinite is fmi2Error,
//! never fmi2OK.

use crate::common::{base_problem, drift_table, smooth_drift};
use crate::fmu::*;
use slowdrift::bounds::{MAX_SPEED, MAX_YAW_RATE};
use slowdrift::error::Cause;
use slowdrift::fmi2::exports::*;
use slowdrift::fmi2::model_description::vr;
use slowdrift::fmi2::types::*;
use slowdrift::problem::Hydro;
use slowdrift::{Error, Simulation, Snapshot};
use std::f64::consts::PI;

/// The oscillator of `common::base_problem` with surge period `period` and linear damping
/// rate c/m = `rate` (1/s) stepped by h = 1 s. RK4 is stable for an undamped oscillator
/// with omega h below 2 sqrt(2) = 2.83 (the boundary of its stability region on the
/// imaginary axis): a stiffness with a period of 2 s (omega h = 3.14) is refused before the
/// run, naming the stiffness and the step, while a period of 4 s (omega h = 1.57) stays
/// bounded. On the real axis the region ends at -2.785: a damping rate of 4/s at that
/// period (roots -0.76 and -3.24 1/s) grows without bound, and the error blames the step.
#[test]
fn an_unstable_step_is_blamed_on_the_step() {
    let run = |period: f64, rate: f64| {
        let mut p = base_problem(20_000.0, 1.0, 1);
        let m = p.inertia().unwrap().mass;
        p.platform.stiffness[0][0] = m * (2.0 * PI / period).powi(2);
        p.platform.linear_damping = [[0.0; 3]; 3];
        p.platform.linear_damping[0][0] = rate * m;
        p.initial.velocity[0] = 0.1;
        let mut sim = Simulation::new(p)?;
        for _ in 0..2000 {
            sim.step([0.0; 3])?;
        }
        Ok::<_, Error>(sim.position()[0])
    };
    assert!(run(4.0, 0.0).unwrap().abs() < 1.0);
    let refused = run(2.0, 0.0).unwrap_err().to_string();
    assert!(
        refused.contains("invalid platform.stiffness[0][0]")
            && refused.contains("natural period of 2 s, too short for RK4 steps of 1 s"),
        "{refused}"
    );
    match run(4.0, 4.0) {
        Err(Error::Unphysical {
            cause: Cause::Step,
            what,
            ..
        }) => {
            assert!(what.starts_with("the state became X"), "{what}");
        }
        other => panic!("{other:?}"),
    }
    let message = run(4.0, 4.0).unwrap_err().to_string();
    assert!(message.ends_with("reduce run.time_step"), "{message}");
}

/// An external force whose impulse over one step alone exceeds the speed bound:
/// F h / m = 2e10 N x 1 s / 1e7 kg = 2000 m/s > 1000 m/s, blamed on the input; one of half
/// the bound's impulse (5e9 N: 500 m/s) is not.
#[test]
fn an_excessive_input_is_blamed_on_the_input() {
    let mut sim = Simulation::new(base_problem(1000.0, 1.0, 1)).unwrap();
    let mass = sim.problem().inertia().unwrap().mass;
    assert_eq!(mass, 1.0e7);
    let force = 2.0 * MAX_SPEED * mass;
    let error = sim.step([force, 0.0, 0.0]).unwrap_err();
    assert!(
        matches!(error, Error::Unphysical { cause: Cause::External { dof: 0, value }, .. } if value == force),
        "{error:?}"
    );
    let text = error.to_string();
    assert!(
        text.contains("the external force input there is 2e10 N in X"),
        "{text}"
    );
    // The state is unchanged by the refused step, and half the impulse steps.
    assert_eq!(sim.time(), 0.0);
    sim.step([0.5 * MAX_SPEED * mass, 0.0, 0.0]).unwrap();
}

/// Drift coefficients near 1e307 N/m^2 (finite: the largest double is 1.8e308) in a sea of
/// Hs = 500 m, Tp = 50 s (steepness 0.128, below the breaking limit 1/7) make the mean
/// wave force m0 T = (Hs^2 / 16) T = 1.6e4 x 1e307 overflow: the outputs are refused
/// (never an infinite force returned as a value), naming the wave force and the settings
/// it grows with.
#[test]
fn an_infinite_force_is_refused_naming_the_wave_force() {
    let mut p = base_problem(1000.0, 1.0, 1);
    p.sea.spectrum = crate::common::jonswap(500.0, 50.0);
    p.hydro = Hydro::from_drift(drift_table(|w, b| smooth_drift(w, b).map(|v| v * 5e302)));
    let mut sim = Simulation::new(p).unwrap();
    let error = sim.outputs().unwrap_err();
    match &error {
        Error::Unphysical {
            what,
            cause: Cause::Force { force, .. },
            ..
        } => {
            assert_eq!(what, "the output F_wave is not finite");
            assert_eq!(*force, "wave force");
        }
        other => panic!("{other:?}"),
    }
    assert!(error.to_string().contains("it grows with sea.hs, drift"));
    assert!(matches!(
        sim.step([0.0; 3]),
        Err(Error::Unphysical {
            cause: Cause::Force { .. },
            ..
        })
    ));
}

/// A snapshot with a speed or a yaw rate beyond the bounds is refused when restored, and
/// when read from bytes; one just within them is restored.
#[test]
fn restored_states_beyond_the_bounds_are_refused() {
    let mut sim = Simulation::new(base_problem(1000.0, 1.0, 1)).unwrap();
    let good = sim.snapshot().to_bytes();
    // Velocity X' is the 7th 8-byte word (origin, count, step, X, Y, theta, X', ...).
    let with_word = |word: usize, value: f64| {
        let mut bytes = good;
        bytes[word * 8..word * 8 + 8].copy_from_slice(&value.to_le_bytes());
        bytes
    };
    for (word, value, name) in [
        (6, 1e200, "Xdot = 1e200 m/s"),
        (6, -1.5 * MAX_SPEED, "Xdot = -1500 m/s"),
        (8, 2.0 * MAX_YAW_RATE, "thetadot = 20 rad/s"),
    ] {
        let message = Snapshot::from_bytes(&with_word(word, value))
            .unwrap_err()
            .to_string();
        assert!(message.contains(name), "{message}");
    }
    let within = Snapshot::from_bytes(&with_word(6, 0.99 * MAX_SPEED)).unwrap();
    sim.restore(&within).unwrap();
    assert_eq!(sim.velocity()[0], 0.99 * MAX_SPEED);
}

/// The FMU: a serialized state whose velocities are 1e200 m/s, resealed with a good
/// checksum, is refused by fmi2DeSerializeFMUstate naming the value; the instance is then
/// still usable (the refusal changes nothing).
#[test]
fn the_fmu_refuses_a_forged_state_with_absurd_velocities() {
    let fmu = Fmu::running("forged", 1, 0.0, 0.0, Some(3600.0));
    fmu.step_with(0.0, 1.0, [0.0; 3]);
    let mut state: fmi2FMUstate = std::ptr::null_mut();
    assert_eq!(
        unsafe { fmi2GetFMUstate(fmu.c, &mut state) },
        fmi2Status::fmi2OK
    );
    let mut size = 0usize;
    assert_eq!(
        unsafe { fmi2SerializedFMUstateSize(fmu.c, state, &mut size) },
        fmi2Status::fmi2OK
    );
    let mut bytes = vec![0u8; size];
    assert_eq!(
        unsafe { fmi2SerializeFMUstate(fmu.c, state, bytes.as_mut_ptr() as *mut _, size) },
        fmi2Status::fmi2OK
    );
    // The snapshot is the last 96 bytes before the 8-byte checksum; its velocities are its
    // words 6-8 (module doc of fmi2::state).
    let snapshot = size - 8 - Snapshot::BYTES;
    for word in 6..9 {
        let at = snapshot + 8 * word;
        bytes[at..at + 8].copy_from_slice(&1e200f64.to_le_bytes());
    }
    reseal(&mut bytes);
    let mut forged: fmi2FMUstate = std::ptr::null_mut();
    let status =
        unsafe { fmi2DeSerializeFMUstate(fmu.c, bytes.as_ptr() as *const _, size, &mut forged) };
    assert_eq!(status, fmi2Status::fmi2Error, "{}", fmu.messages());
    let message = fmu.last_message().message;
    assert!(message.contains("Xdot = 1e200 m/s"), "{message}");
    assert!(forged.is_null());
    unsafe { fmi2FreeFMUstate(fmu.c, &mut state) };
}

/// Hs = 1e200 m through the FMU: refused at initialisation as steeper than waves can be
/// (Hs / L_p with L_p = g Tp^2 / (2 pi) = 224.8 m at the default Tp = 12 s: the limit 1/7
/// is an Hs of 32.1 m), not by a misleading "reduce the step".
#[test]
fn the_fmu_refuses_an_hs_steeper_than_waves_can_be() {
    for (hs, written, refused) in [
        (1e200, "1e200", true),
        (33.0, "33", true),
        (31.0, "", false),
    ] {
        let fmu = Fmu::new("steep");
        assert_eq!(fmu.setup(0.0, Some(3600.0)), fmi2Status::fmi2OK);
        assert_eq!(fmu.set_real(vr::HS, hs), fmi2Status::fmi2OK);
        let status = fmu.init();
        if refused {
            assert_eq!(status, fmi2Status::fmi2Error);
            let message = fmu.last_message().message;
            assert!(
                message.contains(&format!(
                    "FMU parameter Hs = {written}: a sea steeper than waves"
                )) && message.contains("exceeds the breaking limit 1/7"),
                "{message}"
            );
        } else {
            assert_eq!(status, fmi2Status::fmi2OK, "{}", fmu.messages());
        }
    }
}

/// Through the FMU, an overflow: a `hydroDatabase` configuration with drift of 1e307 N/m^2
/// in a sea of Hs = 7 m, Tp = 12 s, whose Newman coefficients sqrt(T) a overflow the
/// single-precision transform (as its Aranha damping would overflow in double):
/// initialisation, whose first outputs would not be finite, is fmi2Error naming the output
/// and the force, never fmi2OK. (The FMU runs the file's sea: no parameter is set but the
/// file.)
#[test]
fn the_fmu_never_returns_an_infinite_output() {
    let example = include_str!("../data/example.toml");
    let drift_start = example.find("[drift]").unwrap();
    let mut text = example[..drift_start]
        .replace("hs = 3.0 ", "hs = 7.0 ")
        .replace("tp = 9.0 ", "tp = 12.0 ")
        .replace("band = [0.3, 2.0]", "band = [0.06, 0.5]");
    assert!(text.contains("hs = 7.0") && text.contains("band = [0.06, 0.5]"));
    text.push_str(
        "[drift]\nsource = \"table\"\nfields = [\"omega\", \"beta_deg\", \"surge\", \"sway\", \"yaw\"]\n\
         rows = [[0.02, 0.0, 1e307, 0.0, 0.0], [0.5, 0.0, 1e307, 0.0, 0.0],\n\
         [0.02, 90.0, 0.0, 1e307, 0.0], [0.5, 90.0, 0.0, 1e307, 0.0]]\n",
    );
    let path = std::env::temp_dir().join(format!("slowdrift-overflow-{}.toml", std::process::id()));
    std::fs::write(&path, text).unwrap();
    let fmu = Fmu::new("overflow");
    assert_eq!(fmu.setup(0.0, Some(3600.0)), fmi2Status::fmi2OK);
    assert_eq!(
        fmu.set_string(vr::HYDRO_DATABASE, path.to_str().unwrap()),
        fmi2Status::fmi2OK
    );
    let status = fmu.init();
    std::fs::remove_file(&path).ok();
    assert_eq!(status, fmi2Status::fmi2Error, "{}", fmu.messages());
    let message = fmu.last_message().message;
    assert!(
        message.contains(
            "the output F_wave is not finite at t = 0 s: the wave force there is NaN N in X"
        ),
        "{message}"
    );
    let (status, _) = fmu.get_reals(&output_vrs());
    assert_eq!(status, fmi2Status::fmi2Error);
}
