//! FMU benchmark: `cargo bench --bench fmu`.
//!
//! What the FMI 2.0 C ABI adds over the core per communication step (under
//! 1 us per fmi2DoStep). Both sides run the default platform with the default sea and drag
//! (the embedded default.toml: combined drag on 4 columns x 20 strips, Aranha damping) for a
//! three-hour run at a 1 s step, in the same process and the same run:
//!
//! - `fmu/core_advance_1s`: `Simulation::advance(1.0, f)` on a `Simulation` of the default
//!   `Problem`;
//! - `fmu/fmi2DoStep_1s`: `fmi2DoStep(c, t, 1.0, fmi2True)` through the exported functions
//!   (`slowdrift::fmi2::exports`), called in-process on an instance with its start values,
//!   `fmi2SetupExperiment(0, 10800)` and the same held input f. Same configuration, so the
//!   same records and the same arithmetic: the bench checks that both end on the same state
//!   bit for bit;
//! - `fmu/core_advance_outputs_1s`: `advance` followed by `outputs()` (position, velocity,
//!   elevation and the wave, damping and drag forces at the new state), which is what
//!   fmi2DoStep computes: it evaluates the outputs once per step so that fmi2GetReal only
//!   copies. With drag on 80 strips that evaluation is most of the difference between
//!   fmi2DoStep and a bare `advance`;
//! - `fmu/fmi2_cycle_1s`: a master's whole step: `fmi2SetReal` (3 inputs) + `fmi2DoStep` +
//!   `fmi2GetReal` (16 outputs), against `core_advance_outputs_1s`.
//!
//! When a run reaches the end of the records both sides roll back to t = 0 outside the timed
//! region (`Simulation::restore`, `fmi2SetFMUstate`). The summary at the end times
//! interleaved three-hour runs of both sides with `Instant` and prints the medians and the
//! per-step overhead. (Three hours stay inside the first segment of the records, a block of
//! 16384 s: no join is crossed in these runs.)
//!
//! Last, the FMU's initialisation (fmi2Instantiate + fmi2SetupExperiment + enter and exit
//! initialisation mode; fmi2FreeInstance outside the timing) for stop times of 1 h, 6 h and
//! 100 h and none (stopTimeDefined = fmi2False): flat, since the records are made one block
//! at a time whatever the stop time. Timed with the packed FMU's resources (its
//! `platform.toml`, written by `write_resources` into a temporary folder) and without (no
//! fmuResourceLocation: the embedded default); both read the default platform's data
//! compiled into the library, whose reading is timed on its own at the end (from its
//! MessagePack twin, as every instance reads it, and as JSON, for comparison). And the
//! initialisation of the embedded default (stop time 3 h) with the wave-frequency motion on
//! and off (`waveFrequencyMotion` 1 and 0), alternated: the cost of its records; and with
//! wind and without (`windSpeed` 20 m/s, NPD gusts, and 0), alternated: the cost of the gust
//! records.

use criterion::Criterion;
use slowdrift::fmi2::exports::*;
use slowdrift::fmi2::model_description::{vr, GUID};
use slowdrift::fmi2::resources::write_resources;
use slowdrift::fmi2::types::*;
use slowdrift::hydro::default_platform::{without_bidirectional, DATABASE, DATABASE_NAME};
use slowdrift::hydro::io::database::HydroDatabase;
use slowdrift::problem::default_problem;
use slowdrift::{Outputs, Simulation};
use std::ffi::CString;
use std::hint::black_box;
use std::ptr;
use std::time::{Duration, Instant};

const THREE_HOURS: f64 = 3.0 * 3600.0;
const STEPS: u64 = 10_800; // 20 chunks of 540 in the summary
const DT: f64 = 1.0;
/// A held external force (N, N, N m), the same on both sides.
const F: [f64; 3] = [1.0e5, -5.0e4, 1.0e7];
const INPUTS: [u32; 3] = [vr::FX_EXT, vr::FY_EXT, vr::MZ_EXT];
/// The 16 outputs, value references 30..45 (modelDescription.xml).
const OUTPUTS: [u32; 16] = [
    30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45,
];

fn ok(status: fmi2Status, what: &str) {
    assert_eq!(status, fmi2Status::fmi2OK, "{what}");
}

/// The core side: a `Simulation` of the default configuration over three hours.
struct Core {
    sim: Simulation,
    start: slowdrift::Snapshot,
    steps: u64,
}

impl Core {
    fn new() -> Core {
        let mut config = default_problem().expect("default config");
        config.run.duration = THREE_HOURS;
        config.run.start_time = 0.0;
        let sim = Simulation::new(config).expect("simulation");
        let start = sim.snapshot();
        Core {
            sim,
            start,
            steps: 0,
        }
    }

    fn rewind(&mut self) {
        self.sim.restore(&self.start).unwrap();
        self.steps = 0;
    }

    fn step(&mut self) {
        self.sim.advance(DT, black_box(F)).unwrap();
        self.steps += 1;
    }

    fn cycle(&mut self, out: &mut [f64; 16]) {
        self.sim.advance(DT, black_box(F)).unwrap();
        let o: Outputs = self.sim.outputs().unwrap();
        let f = &o.forces;
        out[..3].copy_from_slice(&o.position);
        out[3..6].copy_from_slice(&o.velocity);
        out[6] = o.wave_elevation;
        out[7..10].copy_from_slice(&f.wave);
        out[10..13].copy_from_slice(&f.damping);
        out[13..].copy_from_slice(&f.drag);
        black_box(out);
        self.steps += 1;
    }
}

/// The FMU side: one instance driven through the exported C functions.
struct Fmu {
    c: fmi2Component,
    start: fmi2FMUstate,
    steps: u64,
}

impl Fmu {
    fn new() -> Fmu {
        let name = CString::new("bench").unwrap();
        let guid = CString::new(GUID).unwrap();
        // No resource location: the embedded default platform; no callbacks: no logger.
        let c = unsafe {
            fmi2Instantiate(
                name.as_ptr(),
                fmi2Type::fmi2CoSimulation,
                guid.as_ptr(),
                ptr::null(),
                ptr::null(),
                fmi2False,
                fmi2False,
            )
        };
        assert!(!c.is_null(), "fmi2Instantiate");
        unsafe {
            ok(
                fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2True, THREE_HOURS),
                "fmi2SetupExperiment",
            );
            ok(fmi2EnterInitializationMode(c), "enter");
            ok(fmi2SetReal(c, INPUTS.as_ptr(), 3, F.as_ptr()), "inputs");
            ok(fmi2ExitInitializationMode(c), "exit");
        }
        let mut start: fmi2FMUstate = ptr::null_mut();
        ok(unsafe { fmi2GetFMUstate(c, &mut start) }, "fmi2GetFMUstate");
        Fmu { c, start, steps: 0 }
    }

    fn rewind(&mut self) {
        ok(
            unsafe { fmi2SetFMUstate(self.c, self.start) },
            "fmi2SetFMUstate",
        );
        self.steps = 0;
    }

    fn step(&mut self) {
        let t = self.steps as f64 * DT;
        let s = unsafe { fmi2DoStep(self.c, black_box(t), DT, fmi2True) };
        debug_assert_eq!(s, fmi2Status::fmi2OK);
        black_box(s);
        self.steps += 1;
    }

    fn cycle(&mut self, out: &mut [f64; 16]) {
        let t = self.steps as f64 * DT;
        let f = black_box(F);
        unsafe {
            let s1 = fmi2SetReal(self.c, INPUTS.as_ptr(), 3, f.as_ptr());
            let s2 = fmi2DoStep(self.c, t, DT, fmi2True);
            let s3 = fmi2GetReal(self.c, OUTPUTS.as_ptr(), 16, out.as_mut_ptr());
            black_box((s1, s2, s3));
        }
        black_box(out);
        self.steps += 1;
    }

    fn outputs(&self) -> [f64; 16] {
        let mut out = [0.0; 16];
        ok(
            unsafe { fmi2GetReal(self.c, OUTPUTS.as_ptr(), 16, out.as_mut_ptr()) },
            "fmi2GetReal",
        );
        out
    }
}

impl Drop for Fmu {
    fn drop(&mut self) {
        unsafe {
            fmi2FreeFMUstate(self.c, &mut self.start);
            fmi2FreeInstance(self.c);
        }
    }
}

/// Times `iters` calls of `step`, rewinding (untimed) whenever a run reaches three hours.
fn timed<S>(
    side: &mut S,
    iters: u64,
    steps: impl Fn(&S) -> u64,
    rewind: impl Fn(&mut S),
    mut step: impl FnMut(&mut S),
) -> Duration {
    let mut total = Duration::ZERO;
    let mut left = iters;
    while left > 0 {
        if steps(side) >= STEPS {
            rewind(side);
        }
        let chunk = left.min(STEPS - steps(side));
        let t0 = Instant::now();
        for _ in 0..chunk {
            step(side);
        }
        total += t0.elapsed();
        left -= chunk;
    }
    total
}

fn check_same_run(core: &mut Core, fmu: &mut Fmu) {
    core.rewind();
    fmu.rewind();
    let mut a = [0.0; 16];
    for _ in 0..STEPS {
        core.cycle(&mut a);
        fmu.step();
    }
    let b = fmu.outputs();
    assert!(
        a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits()),
        "core and FMU differ after three hours: {a:?} vs {b:?}"
    );
    core.rewind();
    fmu.rewind();
}

/// Seconds of one FMU initialisation of the default platform with stop time `stop`
/// (`None`: stopTimeDefined = fmi2False), and of its part in fmi2ExitInitializationMode
/// (the simulation and its first segment of records). `resources`: the fmuResourceLocation
/// (a `file:` URI of a folder written by `write_resources`, as in the packed FMU), or none
/// (the embedded default). Timed:
/// fmi2Instantiate, fmi2SetupExperiment, fmi2EnterInitializationMode and
/// fmi2ExitInitializationMode; fmi2FreeInstance after the timing.
fn initialisation(stop: Option<f64>, resources: Option<&CString>) -> (f64, f64) {
    initialisation_with(stop, resources, &[], &[])
}

/// [`initialisation`] with the Integer and Real parameters `integers` and `reals` (value
/// reference, value) set after fmi2SetupExperiment.
fn initialisation_with(
    stop: Option<f64>,
    resources: Option<&CString>,
    integers: &[(u32, i32)],
    reals: &[(u32, f64)],
) -> (f64, f64) {
    let name = CString::new("init").unwrap();
    let guid = CString::new(GUID).unwrap();
    let (defined, stop_time) = match stop {
        Some(t) => (fmi2True, t),
        None => (fmi2False, 0.0),
    };
    let location = resources.map_or(ptr::null(), |r| r.as_ptr());
    let start = Instant::now();
    let c = unsafe {
        fmi2Instantiate(
            name.as_ptr(),
            fmi2Type::fmi2CoSimulation,
            guid.as_ptr(),
            location,
            ptr::null(),
            fmi2False,
            fmi2False,
        )
    };
    assert!(!c.is_null(), "fmi2Instantiate");
    let exit;
    unsafe {
        ok(
            fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, defined, stop_time),
            "fmi2SetupExperiment",
        );
        for (reference, value) in integers {
            ok(fmi2SetInteger(c, reference, 1, value), "fmi2SetInteger");
        }
        for (reference, value) in reals {
            ok(fmi2SetReal(c, reference, 1, value), "fmi2SetReal");
        }
        ok(fmi2EnterInitializationMode(c), "enter");
        let before_exit = Instant::now();
        ok(fmi2ExitInitializationMode(c), "exit");
        exit = before_exit.elapsed();
    }
    let total = start.elapsed();
    black_box(c);
    unsafe { fmi2FreeInstance(c) };
    (total.as_secs_f64(), exit.as_secs_f64())
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let mut c = Criterion::default()
        .configure_from_args()
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    let mut core = Core::new();
    let mut fmu = Fmu::new();
    check_same_run(&mut core, &mut fmu);

    {
        let mut g = c.benchmark_group("fmu");
        g.bench_function("core_advance_1s", |b| {
            b.iter_custom(|n| timed(&mut core, n, |s| s.steps, Core::rewind, Core::step))
        });
        g.bench_function("fmi2DoStep_1s", |b| {
            b.iter_custom(|n| timed(&mut fmu, n, |s| s.steps, Fmu::rewind, Fmu::step))
        });
        let mut out = [0.0; 16];
        g.bench_function("core_advance_outputs_1s", |b| {
            b.iter_custom(|n| {
                timed(
                    &mut core,
                    n,
                    |s| s.steps,
                    Core::rewind,
                    |s| s.cycle(&mut out),
                )
            })
        });
        g.bench_function("fmi2_cycle_1s", |b| {
            b.iter_custom(|n| timed(&mut fmu, n, |s| s.steps, Fmu::rewind, |s| s.cycle(&mut out)))
        });
        g.finish();
    }
    c.final_summary();

    // Interleaved three-hour runs, Instant medians: four independent runs (two cores, two
    // FMU instances) advance in alternating chunks of CHUNK steps, so that a change of the
    // machine's load hits all four alike.
    const ROUNDS: usize = 15;
    const CHUNK: u64 = 540;
    let mut core2 = Core::new();
    let mut fmu2 = Fmu::new();
    let mut out = [0.0; 16];
    let per_step = |d: Duration| d.as_secs_f64() / STEPS as f64 * 1e9;
    let mut t: [Vec<f64>; 4] = Default::default();
    let mut d: [Vec<f64>; 2] = Default::default();
    for _ in 0..ROUNDS {
        core.rewind();
        core2.rewind();
        fmu.rewind();
        fmu2.rewind();
        let mut total = [Duration::ZERO; 4];
        for _ in 0..STEPS / CHUNK {
            total[0] += timed(&mut core, CHUNK, |s| s.steps, Core::rewind, Core::step);
            total[1] += timed(
                &mut core2,
                CHUNK,
                |s| s.steps,
                Core::rewind,
                |s| s.cycle(&mut out),
            );
            total[2] += timed(&mut fmu, CHUNK, |s| s.steps, Fmu::rewind, Fmu::step);
            total[3] += timed(
                &mut fmu2,
                CHUNK,
                |s| s.steps,
                Fmu::rewind,
                |s| s.cycle(&mut out),
            );
        }
        let [advance, with_outputs, do_step, cycle] = total.map(per_step);
        for (v, x) in t.iter_mut().zip([advance, with_outputs, do_step, cycle]) {
            v.push(x);
        }
        d[0].push(do_step - advance);
        d[1].push(cycle - with_outputs);
    }
    let [advance, with_outputs, do_step, cycle] = t.map(median);
    let [over_advance, over_cycle] = d.map(median);
    println!(
        "\n==== slowdrift FMU summary ({ROUNDS} interleaved 3-hour runs at 1 s, default platform \
         and drag, Instant medians per step) ===="
    );
    println!("core and FMU end on the same state bit for bit after {STEPS} steps (checked)");
    println!("Simulation::advance(1.0, f)                 {advance:7.0} ns");
    println!("advance + outputs()                         {with_outputs:7.0} ns");
    println!("fmi2DoStep(c, t, 1.0)                       {do_step:7.0} ns");
    println!("fmi2SetReal(3) + fmi2DoStep + fmi2GetReal(16) {cycle:5.0} ns");
    println!(
        "fmi2DoStep - advance: {over_advance:.0} ns per step, the C ABI layer (state check, panic \
         firewall, time check; outputs are computed at the first fmi2GetReal) (target < 1000 ns: {})",
        if over_advance < 1000.0 {
            "met"
        } else {
            "NOT met"
        }
    );
    println!("whole master step (set inputs, step, get outputs) - (advance + outputs): {over_cycle:.0} ns");

    // FMU initialisation for several stop times, interleaved rounds, medians: with the
    // packed FMU's resources and without (the embedded default).
    let dir = std::env::temp_dir().join(format!("slowdrift-fmu-bench-{}", std::process::id()));
    write_resources(&dir).expect("resources");
    let uri = CString::new(format!("file://{}", dir.display())).unwrap();
    let stops: [(&str, Option<f64>); 4] = [
        ("stopTime = 1 h", Some(3600.0)),
        ("stopTime = 6 h", Some(6.0 * 3600.0)),
        ("stopTime = 100 h", Some(100.0 * 3600.0)),
        ("no stopTime", None),
    ];
    for (what, resources, rounds) in [
        ("with the packed FMU's resources", Some(&uri), 15),
        ("without resources (the embedded default)", None, 5),
    ] {
        initialisation(None, resources); // warm-up
        let mut init: Vec<(Vec<f64>, Vec<f64>)> = vec![Default::default(); stops.len()];
        for _ in 0..rounds {
            for ((_, stop), (total, exit)) in stops.iter().zip(&mut init) {
                let (t, e) = initialisation(*stop, resources);
                total.push(t);
                exit.push(e);
            }
        }
        println!(
            "\nFMU initialisation {what}: fmi2Instantiate + fmi2SetupExperiment + enter/exit \
             initialisation mode (fmi2FreeInstance untimed), medians of {rounds} interleaved rounds:"
        );
        for ((what, _), (total, exit)) in stops.iter().zip(init) {
            println!(
                "{what:<18} {:7.1} ms (of which fmi2ExitInitializationMode {:.1} ms)",
                median(total) * 1e3,
                median(exit) * 1e3
            );
        }
    }
    std::fs::remove_dir_all(&dir).ok();

    // The wave-frequency motion's cost (target: at most 25 % more initialisation with it
    // on than off): the embedded default, stop time 3 h, on and off alternated.
    let rounds = 31;
    let motion = |code: i32| {
        initialisation_with(
            Some(THREE_HOURS),
            None,
            &[(vr::WAVE_FREQUENCY_MOTION, code)],
            &[],
        )
        .0
    };
    motion(1); // warm-up
    let (mut on, mut off) = (Vec::new(), Vec::new());
    for _ in 0..rounds {
        on.push(motion(1));
        off.push(motion(0));
    }
    let (on, off) = (median(on), median(off));
    println!(
        "\nFMU initialisation of the embedded default, stop time 3 h, medians of {rounds} \
         alternated rounds: waveFrequencyMotion = 1 (on) {:.2} ms, = 0 (off) {:.2} ms: \
         {:+.1} % (target at most +25 %: {})",
        on * 1e3,
        off * 1e3,
        (on / off - 1.0) * 100.0,
        if on <= 1.25 * off { "met" } else { "NOT met" }
    );

    // The wind's cost (target: initialisation with wind at most 10 % slower than without):
    // the embedded default, stop time 3 h, windSpeed 20 m/s (NPD gusts, one gust transform
    // per segment) and 0 alternated.
    let wind = |speed: f64| {
        initialisation_with(Some(THREE_HOURS), None, &[], &[(vr::WIND_SPEED, speed)]).0
    };
    wind(20.0); // warm-up
    let (mut windy, mut calm) = (Vec::new(), Vec::new());
    for _ in 0..rounds {
        windy.push(wind(20.0));
        calm.push(wind(0.0));
    }
    let (windy, calm) = (median(windy), median(calm));
    println!(
        "\nFMU initialisation of the embedded default, stop time 3 h, medians of {rounds} \
         alternated rounds: windSpeed = 20 m/s (NPD) {:.2} ms, = 0 {:.2} ms: {:+.1} % (target \
         at most +10 %: {})",
        windy * 1e3,
        calm * 1e3,
        (windy / calm - 1.0) * 100.0,
        if windy <= 1.10 * calm {
            "met"
        } else {
            "NOT met"
        }
    );

    // The part of each initialisation that reads the compiled-in database (about 1.0 MB of
    // JSON, read from its MessagePack twin per instance), and the same data parsed as JSON,
    // alternated.
    let (mut messagepack, mut json) = (Vec::new(), Vec::new());
    for _ in 0..15 {
        let start = Instant::now();
        black_box(without_bidirectional().expect("database"));
        messagepack.push(start.elapsed().as_secs_f64());
        let start = Instant::now();
        black_box(HydroDatabase::parse(DATABASE, DATABASE_NAME).expect("database"));
        json.push(start.elapsed().as_secs_f64());
    }
    println!(
        "\nof which the compiled-in default_platform.json, read from its MessagePack twin \
         (default_platform::without_bidirectional), median of 15: {:.2} ms; parsed as JSON \
         (HydroDatabase::parse), alternated: {:.2} ms",
        median(messagepack) * 1e3,
        median(json) * 1e3
    );
}
