//! FMI call sequences as a fuzz target: an input's bytes are a program, each operation an
//! opcode byte and argument bytes that pick values from tables of hostile and ordinary
//! ones (so that byte mutations are program mutations). The program drives one instance
//! through the exported C functions in any order; what must hold whatever the order: no
//! panic reaches the firewall (it would log "panic caught"), fmi2GetReal never answers
//! fmi2OK with a value that is not finite, every fmi2Error has a log line.

use super::{Outcome, Target};
use crate::fmu::{deserialize, output_vrs, Fmu, INPUTS};
use slowdrift::fmi2::exports::*;
use slowdrift::fmi2::model_description::{VariableType, VARIABLES};
use slowdrift::fmi2::types::*;
use std::ptr;

const REALS: &[f64] = &[
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    7.0,
    12.0,
    33.0,
    100.0,
    1e-3,
    1e-300,
    1e16,
    1e300,
    f64::NAN,
    f64::INFINITY,
    -f64::INFINITY,
    3.3,
    1000.0,
];
/// Integers: no count that is legal but slow (the bounds and the budget refuse the rest).
const INTEGERS: &[i32] = &[0, 1, -1, 2, 3, 5, 7, 36, 361, 100_000, i32::MAX, i32::MIN];
const STEPS: &[f64] = &[1.0, 0.5, 2.25, 10.0, 0.0, -1.0, 1e-9, f64::NAN, 1e9, 3600.0];

/// Operations, by opcode (the opcode byte modulo their number).
const OPERATIONS: usize = 13;

fn real_vrs() -> Vec<u32> {
    VARIABLES
        .iter()
        .filter(|v| v.var_type == VariableType::Real)
        .map(|v| v.value_reference)
        .chain([9999])
        .collect()
}

fn integer_vrs() -> Vec<u32> {
    VARIABLES
        .iter()
        .filter(|v| v.var_type == VariableType::Integer)
        .map(|v| v.value_reference)
        .chain([9999])
        .collect()
}

fn string_vrs() -> Vec<u32> {
    VARIABLES
        .iter()
        .filter(|v| v.var_type == VariableType::String)
        .map(|v| v.value_reference)
        .collect()
}

/// Byte `k` of the program, 0 past its end.
fn arg(program: &[u8], k: usize) -> usize {
    program.get(k).copied().unwrap_or(0) as usize
}

fn pick<T: Copy>(table: &[T], b: usize) -> T {
    table[b % table.len()]
}

/// Runs one program; the first broken invariant is the finding.
fn run(program: &[u8], dir: &std::path::Path) -> Outcome {
    let paths = [
        String::new(),
        dir.join("absent.toml").display().to_string(),
        "/dev/zero".into(),
        dir.display().to_string(),
        dir.join("valid.toml").display().to_string(),
        "file:///no/such/file.toml".into(),
    ];
    std::fs::write(
        dir.join("valid.toml"),
        slowdrift::scenario::default::DEFAULT_CONFIG_TOML,
    )
    .unwrap();
    let (reals, integers, strings) = (real_vrs(), integer_vrs(), string_vrs());
    let fmu = Fmu::new("fuzz");
    let mut time = 0.0;
    let mut saved: fmi2FMUstate = ptr::null_mut();
    let mut k = 0;
    let mut errors = 0;
    // The operations and their statuses, a letter each: the outcome that guides the corpus.
    let mut trace = String::new();
    while k < program.len().min(240) {
        let (op, a, b) = (arg(program, k), arg(program, k + 1), arg(program, k + 2));
        k += 3;
        let status = match op % OPERATIONS {
            0 => {
                time = pick(REALS, a);
                let stop = (b % 2 == 0).then(|| time + pick(STEPS, b) * 100.0);
                fmu.setup(time, stop)
            }
            1 => fmu.set_real(pick(&reals, a), pick(REALS, b)),
            2 => fmu.set_int(pick(&integers, a), pick(INTEGERS, b)),
            3 => fmu.set_string(pick(&strings, a), &paths[b % paths.len()]),
            4 => unsafe { fmi2EnterInitializationMode(fmu.c) },
            5 => unsafe { fmi2ExitInitializationMode(fmu.c) },
            6 => {
                let h = pick(STEPS, a);
                let s = fmu.set_reals(&INPUTS, &[pick(REALS, b), 0.0, 0.0]);
                let t = if b % 5 == 0 { time + 1.0 } else { time };
                let status = fmu.step(t, h);
                if status == fmi2Status::fmi2OK && s == fmi2Status::fmi2OK {
                    time = t + h;
                }
                status
            }
            7 => {
                let (status, values) = fmu.get_reals(&output_vrs());
                if status == fmi2Status::fmi2OK && values.iter().any(|v| !v.is_finite()) {
                    return Outcome::Finding(format!("fmi2GetReal OK with {values:?}"));
                }
                status
            }
            8 => {
                if !saved.is_null() {
                    unsafe { fmi2FreeFMUstate(fmu.c, &mut saved) };
                }
                unsafe { fmi2GetFMUstate(fmu.c, &mut saved) }
            }
            9 => unsafe { fmi2SetFMUstate(fmu.c, saved) },
            10 => {
                // The saved state serialised, one byte changed, read back and set.
                let mut size = 0usize;
                let s = unsafe { fmi2SerializedFMUstateSize(fmu.c, saved, &mut size) };
                if s != fmi2Status::fmi2OK || size > 1 << 20 {
                    s
                } else {
                    let mut bytes = vec![0u8; size];
                    unsafe { fmi2SerializeFMUstate(fmu.c, saved, bytes.as_mut_ptr().cast(), size) };
                    if size > 0 {
                        bytes[(a * 256 + b) % size] ^= 1 << (a % 8);
                    }
                    let (s, mut state) = deserialize(&fmu, &bytes);
                    if s == fmi2Status::fmi2OK {
                        unsafe { fmi2SetFMUstate(fmu.c, state) };
                        unsafe { fmi2FreeFMUstate(fmu.c, &mut state) };
                    }
                    s
                }
            }
            11 => {
                time = 0.0;
                unsafe { fmi2Reset(fmu.c) }
            }
            _ => unsafe { fmi2Terminate(fmu.c) },
        };
        trace.push((b'a' + (op % OPERATIONS) as u8) as char);
        trace.push(match status {
            fmi2Status::fmi2OK => 'o',
            fmi2Status::fmi2Error => 'E',
            _ => 'w',
        });
        if status == fmi2Status::fmi2Error {
            errors += 1;
            if fmu.entries().last().map(|e| e.status) != Some(fmi2Status::fmi2Error) {
                return Outcome::Finding(format!("fmi2Error without its log line (op {op})"));
            }
        }
        if let Some(e) = fmu
            .entries()
            .iter()
            .find(|e| e.message.contains("panic caught"))
        {
            return Outcome::Finding(format!("a panic reached the firewall: {}", e.message));
        }
        fmu.clear_log();
    }
    if !saved.is_null() {
        unsafe { fmi2FreeFMUstate(fmu.c, &mut saved) };
    }
    Outcome::Done(if errors == 0 { Ok(()) } else { Err(trace) })
}

/// Programs: the legal sequence (setup, parameters, initialisation, steps, outputs, a
/// state saved, restored and serialised), and one that sets a configuration file.
pub fn target() -> Target {
    let legal = vec![
        0, 0, 0, 2, 0, 3, 4, 0, 0, 5, 0, 0, 6, 0, 1, 6, 0, 1, 7, 0, 0, 8, 0, 0, 6, 0, 1, 9, 0, 0,
        10, 1, 1, 7, 0, 0, 11, 0, 0, 12, 0, 0,
    ];
    let with_file = vec![0, 0, 0, 3, 0, 4, 4, 0, 0, 5, 0, 0, 6, 0, 1, 7, 0, 0];
    assert_eq!(OPERATIONS, 13);
    Target {
        name: "fmi_calls",
        seeds: vec![legal, with_file],
        run: Box::new(run),
    }
}
