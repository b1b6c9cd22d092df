//! Core benchmarks: `cargo bench --bench core`.
//!
//! 1. `records/records_3h`: the force records of a 3-hour run at h = 0.5 s (records at
//!    0.25 s): Newman geometric drift force in 3 DOF and the 3x3 wave-drift damping
//!    (Aranha) on the four-column platform, long-crested waves from 30 deg. Measured as
//!    transfers_on_grid + ForceRecords::build, next to one complex FFT of the same length
//!    (`records/fft_len`, in single precision as the records' transforms run). The ratio
//!    records/FFT is timed again with `Instant` and printed.
//! 2. `step/rk4_step_no_drag`, `step/rk4_step_drag_4x20`: one `Simulation::step`.
//! 3. `run/run_3h_1s_stepping`, `run/run_3h_1s_new_and_stepping`: a 3-hour run at h = 1 s
//!    without drag (Aranha damping on), stepping only, and `Simulation::new` + stepping.
//!    `Simulation::new` makes the first segment of the record stream: one block of
//!    `run.block_duration` (16384 s) plus halos and the join's ramp, whatever the run's
//!    duration, so this is one block's records, not a 3-hour record.
//! 4. Record memory of a Simulation (its current segment) for runs of 1, 3, 6 and 100 h and
//!    open-ended, at blocks of 4096 s and 16384 s (printed, not timed): the same for every
//!    run length, proportional to the block.
//! 5. `hydro/read_oc4_12d`: reading the OC4 semisubmersible's WAMIT QTF file
//!    (`marin_semi.12d`, 1.2 MB, 9576 lines) from the shared data directory
//!    (`$SLOWDRIFT_DATA` or `../shared/data`); skipped with a notice if it is absent.
//! 6. `hydro/columns_100x37`: `ColumnArray::drift_table` of the paper's four columns
//!    (radius 10 m on a 70 m square, deep water) at 100 frequencies 0.05..3 rad/s and 37
//!    headings 0..360 deg: scattering, near- and far-field drift, exciting forces and
//!    Aranha damping with the solver's own derivatives. Target: well under 1 s.
//!
//! 7. `full_qtf/factorised_2048_rank*`, `full_qtf/direct_binned_2048`: the slowly varying
//!    force from a full QTF (56-point grid, like OC4's) at N_omega = 2048 components:
//!    factorised synthesis against the direct double sum on the same interpolated QTF, in the
//!    time domain (timed per sample, extrapolated to the record) and binned by difference
//!    frequency with one inverse FFT. Target: >= 100x faster than the direct
//!    double sum at a relative error < 1e-6, memory linear in N_omega x rank.
//! 8. `segment/cross_join_default`: the cost of making the next segment, on the default
//!    problem (combined drag on 4 columns x 20 strips, Aranha damping, h = 1 s) run
//!    open-ended: restored at 16383 s and stepped to 16384 s untimed, then the one step that
//!    starts in segment 1 and makes it from segment 0's tails, timed. Printed against
//!    stepping one block (16384 steps) and `Simulation::new` for runs of 1 h, 6 h, 100 h and
//!    open-ended (flat: the records do not depend on the duration).
//!
//! 9. The depth kernel's rank for the default platform and a deep-draft spar
//!    (printed).
//!
//! Targets (issue): records <= 30 FFTs, step < 1 us (no drag) and < 10 us (drag 4 x 20),
//! 3-hour run at 1 s < 50 ms, OC4 .12d read < 100 ms. Record memory: bounded by one block
//! (the same for every run length, open-ended included).
//!
//! Profile of `records_3h` (perf, 2-core VM): the build does 11 FFTs (1 elevation, 3 force,
//! 7 non-zero damping records) plus one plan (~3 FFTs of twiddles) and transfers_on_grid
//! (~2 FFTs); most of the rest is the kernel faulting in the ~4.5 MB of fresh record and
//! scratch memory of every build (about a quarter of the time, in exc_page_fault and
//! clear_page). Records that stay zero are never allocated, and the geometric form needs no
//! per-direction complex elevation buffer.

#[path = "../tests/all/common.rs"]
mod common;

use common::{four_columns, oscillator_platform, snapshot_at_step};
mod timing;

use criterion::Criterion;
use rustfft::num_complex::{Complex32, Complex64};
use rustfft::FftPlanner;
use slowdrift::forces::{
    plan_inverse_fft, transfers_on_grid, DepthBasis, DirectionTransfer, ForceRecords, InverseFft,
    QtfFactorisation, RecordOptions, Synthesizer, KINEMATICS_TOLERANCE,
};
use slowdrift::hydro::aranha::aranha_damping;
use slowdrift::hydro::column_drift::isolated_columns_table;
use slowdrift::hydro::columns::ColumnArray;
use slowdrift::hydro::io::wamit::{read_difference_qtf, WamitOptions};
use slowdrift::hydro::qtf::MIN_QTF_TOLERANCE;
use slowdrift::hydro::{DriftRow, DriftTable};
use slowdrift::model::{
    DragModel, DriftDamping, Environment, Interaction, NewmanForm, SecondOrder,
    WaveFrequencyMotion, DEFAULT_QTF_TOLERANCE,
};
use slowdrift::problem::Hydro;
use slowdrift::scenario::{
    Current, InitialCondition, ModelOptions, Platform, Run, DEFAULT_BLOCK_DURATION,
};
use slowdrift::sea_state::{FrequencyGrid, SeaState, Spectrum, Spreading, WaveComponents};
use slowdrift::{Problem, RecordPlan, Simulation};
use std::hint::black_box;
use std::time::Duration;
use timing::median_time;

const THREE_HOURS: f64 = 3.0 * 3600.0;

// ---------------------------------------------------------------- configuration builder

/// Isolated-columns drift over omega 0.05 .. 3 rad/s and headings every 10 deg, plus a
/// small artificial yaw drift (the square array alone has none): a 5 m lever on the
/// horizontal drift, times sin(2 beta), so that every record of the 3 DOF is non-zero.
fn drift_table(environment: &Environment) -> DriftTable {
    let omegas: Vec<f64> = (1..=60).map(|i| 0.05 * i as f64).collect();
    let headings: Vec<f64> = (0..36).map(|i| (10.0 * i as f64).to_radians()).collect();
    let base = isolated_columns_table(&four_columns(), environment, &omegas, &headings).unwrap();
    let mut rows = Vec::with_capacity(omegas.len() * headings.len());
    for (ih, &heading) in base.headings().iter().enumerate() {
        for (iw, &omega) in base.omegas().iter().enumerate() {
            let [surge, sway, yaw] = base.drift_at_node(ih, iw);
            let extra = 5.0 * surge.hypot(sway) * (2.0 * heading).sin();
            rows.push(DriftRow {
                omega,
                heading,
                drift: [surge, sway, yaw + extra],
                damping: None,
            });
        }
    }
    DriftTable::from_rows(&rows).unwrap()
}

/// Four columns on an oscillator platform: 100 s surge/sway, 60 s yaw, 5 % damping.
fn platform() -> Platform {
    let mass = 4.0e7;
    Platform {
        columns: four_columns(),
        ..oscillator_platform(mass, mass * 40.0 * 40.0, [100.0, 100.0, 60.0], 0.05)
    }
}

/// JONSWAP Hs 6 m, Tp 10 s, long-crested from 30 deg; Newman geometric; Aranha damping.
fn bench_problem(duration: f64, time_step: f64, drag: DragModel) -> Problem {
    let environment = Environment::default();
    let drift = drift_table(&environment);
    Problem {
        environment,
        sea: SeaState {
            spectrum: Spectrum::Jonswap {
                hs: 6.0,
                tp: 10.0,
                gamma: Some(3.3),
            },
            spreading: Spreading::LongCrested,
            mean_direction: 30.0f64.to_radians(),
            n_directions: 1,
            seed: 1996,
            band: None,
        },
        current: Current::default(),
        wind: slowdrift::wind::WindField::default(),
        run: Run {
            duration,
            time_step,
            start_time: 0.0,
            block_duration: DEFAULT_BLOCK_DURATION,
            memory_limit: slowdrift::scenario::limits::DEFAULT_MEMORY_LIMIT,
        },
        platform: platform(),
        hydro: Hydro::from_drift(drift),
        model: ModelOptions {
            second_order: SecondOrder::Newman,
            qtf_tolerance: DEFAULT_QTF_TOLERANCE,
            newman: NewmanForm::Geometric,
            interaction: Interaction::None,
            drift_damping: DriftDamping::Aranha,
            drag,
            strips_per_column: 20,
            yaw_following: None,
            wave_frequency_motion: WaveFrequencyMotion::On,
        },
        initial: InitialCondition::default(),
        origins: Default::default(),
    }
}

// ---------------------------------------------------------------- 1. records vs one FFT

/// What `Simulation::new` computes before the timed record build: the wave components and
/// the Aranha damping table.
struct RecordInputs {
    components: WaveComponents,
    damping_table: DriftTable,
    gravity: f64,
}

impl RecordInputs {
    fn new(problem: &Problem) -> Self {
        let grid = FrequencyGrid::new(
            problem.run.start_time,
            problem.run.duration,
            0.5 * problem.run.time_step,
            problem.sea.band(),
        )
        .unwrap();
        let components = WaveComponents::generate(&problem.sea, grid);
        let damping_table = aranha_damping(
            &problem.hydro.drift,
            problem.environment.gravity,
            &problem.platform.columns,
        )
        .unwrap();
        RecordInputs {
            components,
            damping_table,
            gravity: problem.environment.gravity,
        }
    }

    /// The coefficients on the grid (`transfers_on_grid`).
    fn transfers(&self) -> Vec<DirectionTransfer> {
        transfers_on_grid(
            &self.damping_table,
            &self.components.grid,
            &self.components.directions,
            true,
        )
        .unwrap()
    }

    /// transfers_on_grid + ForceRecords::build planning its FFT, as `Simulation::new` does
    /// (no drag).
    fn build(&self) -> ForceRecords {
        self.build_with(&self.transfers(), None)
    }

    /// ForceRecords::build from coefficients on the grid and, when given, a planned FFT:
    /// the work of a seed whose `RecordPlan` exists.
    fn build_with(
        &self,
        transfers: &[DirectionTransfer],
        fft: Option<&InverseFft>,
    ) -> ForceRecords {
        ForceRecords::build(
            &self.components,
            transfers,
            &RecordOptions {
                newman: NewmanForm::Geometric,
                full_qtf: None,
                drag_columns: &[],
                strips_per_column: 20,
                gravity: self.gravity,
                fft,
            },
        )
    }

    /// FFTs done by `ForceRecords::build`: one per direction for the elevation, and per
    /// direction and non-zero coefficient record one for each sign present (geometric).
    fn fft_count(&self) -> (usize, usize, usize) {
        let transfers = transfers_on_grid(
            &self.damping_table,
            &self.components.grid,
            &self.components.directions,
            true,
        )
        .unwrap();
        let ffts = |t: &[f64]| {
            usize::from(t.iter().any(|&v| v > 0.0)) + usize::from(t.iter().any(|&v| v < 0.0))
        };
        let (mut force, mut damping) = (0, 0);
        for tr in &transfers {
            force += tr.drift.iter().map(|t| ffts(t)).sum::<usize>();
            if let Some(b) = &tr.damping {
                damping += b.iter().flatten().map(|t| ffts(t)).sum::<usize>();
            }
        }
        (transfers.len(), force, damping)
    }
}

/// One in-place inverse complex FFT of `len` points, planned once, in the precision the
/// records' transforms run in (single: `forces::synthesis`).
struct OneFft {
    fft: InverseFft,
    buffer: Vec<Complex32>,
    scratch: Vec<Complex32>,
}

impl OneFft {
    fn new(len: usize) -> Self {
        let fft = FftPlanner::new().plan_fft_inverse(len);
        let scratch = vec![Complex32::default(); fft.get_inplace_scratch_len()];
        let buffer = (0..len)
            .map(|m| Complex32::new((m as f32 * 0.37).sin(), (m as f32 * 0.11).cos()))
            .collect();
        OneFft {
            fft,
            buffer,
            scratch,
        }
    }

    fn run(&mut self) {
        self.fft
            .process_with_scratch(&mut self.buffer, &mut self.scratch);
        black_box(&self.buffer);
    }
}

fn bench_records(c: &mut Criterion, report: &mut Vec<String>) {
    let inputs = RecordInputs::new(&bench_problem(THREE_HOURS, 0.5, DragModel::Off));
    let len = inputs.components.grid.len;
    let mut fft = OneFft::new(len);

    let mut group = c.benchmark_group("records");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(4));
    group.bench_function("records_3h", |b| b.iter(|| black_box(inputs.build())));
    group.bench_function(format!("fft_{len}"), |b| b.iter(|| fft.run()));
    group.finish();

    // The ratio, timed directly (criterion does not compute ratios).
    let records = median_time(15, || {
        black_box(inputs.build());
    });
    let one_fft = median_time(301, || fft.run());
    // Parts of the build, for the profile.
    let transfers = median_time(15, || {
        black_box(
            transfers_on_grid(
                &inputs.damping_table,
                &inputs.components.grid,
                &inputs.components.directions,
                true,
            )
            .unwrap(),
        );
    });
    let planning = median_time(15, || {
        black_box(Synthesizer::new(&inputs.components.grid));
    });
    let (directions, force_ffts, damping_ffts) = inputs.fft_count();
    let built = inputs.build();
    let nonzero_damping = built.damping.as_ref().map_or(0, |b| {
        b.iter()
            .flatten()
            .filter(|r| !r.samples().is_empty())
            .count()
    });
    let nonzero_force = built
        .wave_force
        .iter()
        .filter(|r| !r.samples().is_empty())
        .count();
    // The first build's one-time work included: no target (the 30 x is the plan's line below,
    // docs/benchmarks.md#records).
    report.push(format!(
        "records_3h, a first build (planning the FFT and the table onto the grid included, \
         cold): {:.2} ms = {:.1} x one FFT of {len} points ({:.1} us); one-time work, no target",
        records.as_secs_f64() * 1e3,
        records.as_secs_f64() / one_fft.as_secs_f64(),
        one_fft.as_secs_f64() * 1e6,
    ));
    report.push(format!(
        "  components {} ({} direction(s)); non-zero records: force {nonzero_force}/3, \
         damping {nonzero_damping}/9; FFTs in build: {} elevation + {force_ffts} force + \
         {damping_ffts} damping = {}",
        inputs.components.grid.count,
        directions,
        directions,
        directions + force_ffts + damping_ffts
    ));
    report.push(format!(
        "  of which transfers_on_grid {:.2} ms ({:.1} FFTs), ForceRecords::build ~{:.2} ms",
        transfers.as_secs_f64() * 1e3,
        transfers.as_secs_f64() / one_fft.as_secs_f64(),
        (records - transfers.min(records)).as_secs_f64() * 1e3
    ));
    report.push(format!(
        "  of which planning the FFT (Synthesizer::new) {:.2} ms ({:.1} FFTs)",
        planning.as_secs_f64() * 1e3,
        planning.as_secs_f64() / one_fft.as_secs_f64(),
    ));
    // The records of a seed from its RecordPlan: the FFT planned and the coefficients on the
    // grid beforehand, as the reference FFT is planned beforehand.
    let (transfers, fft) = (
        inputs.transfers(),
        plan_inverse_fft(&inputs.components.grid),
    );
    let seed = median_time(15, || {
        black_box(inputs.build_with(&transfers, Some(&fft)));
    });
    let ratio = seed.as_secs_f64() / one_fft.as_secs_f64();
    report.push(format!(
        "records_3h from a RecordPlan (cold, FFT planned and coefficients on the grid \
         beforehand, like the reference FFT): {:.2} ms = {ratio:.1} x one FFT; target <= 30x: {}",
        seed.as_secs_f64() * 1e3,
        if ratio <= 30.0 { "met" } else { "NOT met" }
    ));
    // A seed's records as runs make them: the first segment of the stream from the seed's
    // plan (`Simulation::with_plan`: one block's transforms, the quadratic records at every
    // second sample where their band allows, `forces::refine`), against one FFT of the
    // block's N points.
    let problem = bench_problem(THREE_HOURS, 0.5, DragModel::Off);
    let plan = std::sync::Arc::new(RecordPlan::new(&problem).unwrap());
    let block_len = plan.grid().len;
    let mut block_fft = OneFft::new(block_len);
    let segment = median_time(15, || {
        black_box(Simulation::with_plan(problem.clone(), &plan).unwrap());
    });
    let one_block_fft = median_time(301, || block_fft.run());
    let ratio = segment.as_secs_f64() / one_block_fft.as_secs_f64();
    report.push(format!(
        "records_3h, a seed's first segment from its plan (Simulation::with_plan, cold; \
         quadratic records at their bandwidth: {}): {:.2} ms = {ratio:.1} x one FFT of the \
         block's {block_len} points ({:.1} us); target <= 12x: {}",
        plan.refines(),
        segment.as_secs_f64() * 1e3,
        one_block_fft.as_secs_f64() * 1e6,
        if ratio <= 12.0 { "met" } else { "NOT met" }
    ));
}

/// The records again after [`slowdrift::allocator::retain_freed_memory`], the setting of
/// the CLI and the Monte Carlo benchmark: the builds then reuse the memory freed by the
/// previous build instead of fresh pages that the kernel must fault in and zero. Run last,
/// because the setting is process-wide and would change every later measurement.
fn bench_records_warm(report: &mut Vec<String>) {
    let inputs = RecordInputs::new(&bench_problem(THREE_HOURS, 0.5, DragModel::Off));
    let mut fft = OneFft::new(inputs.components.grid.len);
    let retained = slowdrift::allocator::retain_freed_memory();
    let records = median_time(15, || {
        black_box(inputs.build());
    });
    let one_fft = median_time(301, || fft.run());
    let ratio = records.as_secs_f64() / one_fft.as_secs_f64();
    report.push(format!(
        "records_3h with freed memory kept (allocator setting taken: {retained}): {:.2} ms = \
         {ratio:.1} x one FFT ({:.1} us); target <= 30x: {}",
        records.as_secs_f64() * 1e3,
        one_fft.as_secs_f64() * 1e6,
        if ratio <= 30.0 { "met" } else { "NOT met" }
    ));
}

// ---------------------------------------------------------------- 2. one RK4 step

/// A simulation that is stepped past its end is reset to the start (amortised, cheap).
fn bench_steps(c: &mut Criterion, report: &mut Vec<String>) {
    let cases = [
        ("rk4_step_no_drag", DragModel::Off, 1e-6),
        ("rk4_step_drag_4x20", DragModel::Combined { cd: 1.0 }, 10e-6),
    ];
    let duration = 1800.0;
    let mut group = c.benchmark_group("step");
    group
        .sample_size(20)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    let mut sims = Vec::new();
    for (name, drag, _) in &cases {
        let mut sim = Simulation::new(bench_problem(duration, 0.5, *drag)).unwrap();
        let limit = duration - 1.0;
        group.bench_function(*name, |b| {
            b.iter(|| {
                if sim.time() >= limit {
                    sim.reset().unwrap();
                }
                sim.step(black_box([0.0; 3])).unwrap();
            })
        });
        sims.push(sim);
    }
    group.finish();
    for ((name, _, target), sim) in cases.iter().zip(&mut sims) {
        // 1000 steps per repetition, reset outside the timing.
        let t = median_time(31, || {
            sim.reset().unwrap();
            for _ in 0..1000 {
                sim.step(black_box([0.0; 3])).unwrap();
            }
        }) / 1000;
        report.push(format!(
            "{name}: {:.3} us per step (Instant, 1000-step batches); target < {:.0} us: {}",
            t.as_secs_f64() * 1e6,
            target * 1e6,
            if t.as_secs_f64() < *target {
                "met"
            } else {
                "NOT met"
            }
        ));
    }
}

// ---------------------------------------------------------------- 3. a 3-hour run at 1 s

fn run_3h(sim: &mut Simulation) {
    sim.reset().unwrap();
    let steps = (THREE_HOURS / 1.0).round() as usize;
    for _ in 0..steps {
        sim.step(black_box([0.0; 3])).unwrap();
    }
    black_box(sim.position());
}

fn bench_run(c: &mut Criterion, report: &mut Vec<String>) {
    let cfg = bench_problem(THREE_HOURS, 1.0, DragModel::Off);
    let mut sim = Simulation::new(cfg.clone()).unwrap();
    let mut group = c.benchmark_group("run");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(4));
    group.bench_function("run_3h_1s_stepping", |b| b.iter(|| run_3h(&mut sim)));
    group.bench_function("run_3h_1s_new_and_stepping", |b| {
        b.iter(|| {
            let mut s = Simulation::new(black_box(cfg.clone())).unwrap();
            run_3h(&mut s);
        })
    });
    group.finish();
    let stepping = median_time(11, || run_3h(&mut sim));
    let whole = median_time(11, || {
        let mut s = Simulation::new(black_box(cfg.clone())).unwrap();
        run_3h(&mut s);
    });
    report.push(format!(
        "run_3h_1s: stepping {:.2} ms, new + stepping {:.2} ms (10800 steps, Aranha damping, \
         no drag; new makes one block of {} s, FFT N = {}, not a 3-hour record); target < 50 \
         ms: stepping {}, new + stepping {}",
        stepping.as_secs_f64() * 1e3,
        whole.as_secs_f64() * 1e3,
        cfg.run.block_duration,
        sim.grid().len,
        if stepping.as_secs_f64() < 0.05 {
            "met"
        } else {
            "NOT met"
        },
        if whole.as_secs_f64() < 0.05 {
            "met"
        } else {
            "NOT met"
        },
    ));
}

// ---------------------------------------------------------------- 4. record memory

fn record_bytes(records: &ForceRecords) -> usize {
    let mut samples = records.elevation.samples().len();
    samples += records
        .wave_force
        .iter()
        .map(|r| r.samples().len())
        .sum::<usize>();
    if let Some(b) = &records.damping {
        samples += b.iter().flatten().map(|r| r.samples().len()).sum::<usize>();
    }
    // Drag kinematics: the depth terms' series and the window of rows, each group of
    // columns that share them once.
    samples * std::mem::size_of::<f64>() + records.kinematics.bytes()
}

/// Record memory of a Simulation (its current segment, `record_bytes`) for runs of 1, 3, 6
/// and 100 hours and open-ended, at blocks of 4096 s and 16384 s; the open-ended run again
/// in a late segment (restored at 1000 h). Printed, not timed.
fn memory(report: &mut Vec<String>) {
    report.push(
        "record memory of a Simulation, its current segment (h = 0.5 s, records at 0.25 s, \
         force + 3x3 damping = 11 records, no drag):"
            .into(),
    );
    for block in [4096.0, DEFAULT_BLOCK_DURATION] {
        let mut sizes = Vec::new();
        for hours in [1.0, 3.0, 6.0, 100.0, f64::INFINITY] {
            let mut problem = bench_problem(hours * 3600.0, 0.5, DragModel::Off);
            problem.run.block_duration = block;
            let sim = Simulation::new(problem).unwrap();
            let bytes = record_bytes(sim.records());
            let run = if hours.is_finite() {
                format!("{hours} h")
            } else {
                "open-ended".into()
            };
            report.push(format!(
                "  block {block} s, run {run}: {} samples per record (FFT N = {}), {bytes} bytes \
                 = {:.3} MB",
                sim.records().clock.len,
                sim.grid().len,
                bytes as f64 / 1e6
            ));
            sizes.push(bytes);
            if !hours.is_finite() {
                // The same simulation in a late segment: restored at 1000 h.
                let mut sim = sim;
                let steps = (1000.0 * 3600.0 / 0.5) as u64;
                sim.restore(&snapshot_at_step(&sim.snapshot(), steps))
                    .unwrap();
                let late = record_bytes(sim.records());
                report.push(format!(
                    "  block {block} s, open-ended, restored at 1000 h (segment {}): {late} bytes",
                    sim.segment()
                ));
                sizes.push(late);
            }
        }
        let same = sizes.iter().all(|&b| b == sizes[0]);
        report.push(format!(
            "  block {block} s: {} for every run length ({:.3} MB per block, {:.3} MB per hour \
             of block)",
            if same { "the same" } else { "NOT the same" },
            sizes[0] as f64 / 1e6,
            sizes[0] as f64 / 1e6 / (block / 3600.0)
        ));
    }
}

// ---------------------------------------------------------------- 8. open-ended records

/// The default problem (combined drag on 4 columns x 20 strips, Aranha damping, h = 1 s)
/// with run duration `duration`.
fn default_with_duration(duration: f64) -> Problem {
    let mut problem = slowdrift::problem::default_problem().expect("the default problem");
    problem.run.duration = duration;
    problem
}

/// The cost of making the next segment: an open-ended run of the default problem restored
/// (untimed) at 16383 s, one untimed step to 16384 s (still in segment 0), then the timed
/// step that starts at 16384 s in segment 1 and makes it from segment 0's tails. Against
/// stepping one block (16384 steps inside segment 0) and `Simulation::new` (the plan and the
/// first segment) for runs of 1 h, 6 h, 100 h and open-ended.
fn bench_segments(c: &mut Criterion, report: &mut Vec<String>) {
    let problem = default_with_duration(f64::INFINITY);
    let mut sim = Simulation::new(problem.clone()).unwrap();
    let h = problem.run.time_step;
    let block_steps = (problem.run.block_duration / h).round() as u64;
    for _ in 0..block_steps - 1 {
        sim.step([0.0; 3]).unwrap();
    }
    let before_join = sim.snapshot();
    assert_eq!(before_join.time(), problem.run.block_duration - h);
    // One crossing, untimed: restore (rebuilds segment 0), a step inside it, the crossing.
    let cross = |sim: &mut Simulation| -> Duration {
        sim.restore(&before_join).unwrap();
        sim.step(black_box([0.0; 3])).unwrap();
        assert_eq!(sim.segment(), 0);
        let start = std::time::Instant::now();
        sim.step(black_box([0.0; 3])).unwrap();
        let elapsed = start.elapsed();
        assert_eq!(sim.segment(), 1);
        elapsed
    };
    let mut group = c.benchmark_group("segment");
    group
        .sample_size(20)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(5));
    group.bench_function("cross_join_default", |b| {
        b.iter_custom(|n| (0..n).map(|_| cross(&mut sim)).sum())
    });
    group.finish();

    let mut crossings: Vec<Duration> = (0..31).map(|_| cross(&mut sim)).collect();
    crossings.sort();
    let crossing = crossings[crossings.len() / 2];
    // Stepping one block inside segment 0 (reset: back to segment 0, outside the timing).
    let block = {
        let mut times: Vec<Duration> = (0..7)
            .map(|_| {
                sim.reset().unwrap();
                let start = std::time::Instant::now();
                for _ in 0..block_steps {
                    sim.step(black_box([0.0; 3])).unwrap();
                }
                let elapsed = start.elapsed();
                assert_eq!(sim.segment(), 0);
                elapsed
            })
            .collect();
        times.sort();
        times[times.len() / 2]
    };
    let per_step = block.as_secs_f64() / block_steps as f64;
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    report.push(format!(
        "open-ended records, default problem (combined drag 4 x 20, Aranha, h = 1 s, block \
         {} s, FFT N = {}):",
        problem.run.block_duration,
        sim.grid().len
    ));
    report.push(format!(
        "  the step that crosses into segment 1 (makes it from segment 0's tails): {:.2} ms \
         median of 31 (range {:.2}-{:.2} ms) = {:.0} ordinary steps",
        ms(crossing),
        ms(crossings[0]),
        ms(crossings[crossings.len() - 1]),
        crossing.as_secs_f64() / per_step
    ));
    report.push(format!(
        "  stepping one block ({block_steps} steps inside segment 0): {:.1} ms median of 7 \
         ({:.3} us per step); the segment adds {:.3} us per step amortised ({:.1} %)",
        ms(block),
        per_step * 1e6,
        crossing.as_secs_f64() / block_steps as f64 * 1e6,
        100.0 * crossing.as_secs_f64() / block.as_secs_f64()
    ));
    let mut line = String::from("  Simulation::new (plan + first segment):");
    for hours in [1.0, 6.0, 100.0, f64::INFINITY] {
        let p = default_with_duration(hours * 3600.0);
        let t = median_time(11, || {
            black_box(Simulation::new(black_box(p.clone())).unwrap());
        });
        let run = if hours.is_finite() {
            format!("{hours} h")
        } else {
            "open-ended".into()
        };
        line.push_str(&format!(" {run} {:.1} ms;", ms(t)));
    }
    line.pop();
    report.push(line + " (medians of 11)");
}

/// The rank of the drag kinematics' depth kernel (`forces::depth_basis`) on the default
/// sea's block grid, for the default platform's columns (draft 30 m, 20 strips) and a
/// deep-draft spar's (120 m, as the OC3 Hywind, at 20 and 40 strips), and the time to
/// make one basis. Printed, not timed by criterion.
fn depth_ranks(report: &mut Vec<String>) {
    let problem = default_with_duration(f64::INFINITY);
    let sim = Simulation::new(problem.clone()).unwrap();
    let components = WaveComponents::generate(&problem.sea, sim.grid().clone());
    let gravity = problem.environment.gravity;
    report.push(format!(
        "drag kinematics' depth kernel on the default sea (N_omega = {}), tolerance {:e} \
         (relative rms velocity):",
        components.grid.count, KINEMATICS_TOLERANCE
    ));
    for (draft, strips) in [(30.0, 20), (120.0, 20), (120.0, 40)] {
        let basis = DepthBasis::new(
            &components.grid,
            components.expected_power(),
            draft,
            strips,
            gravity,
        );
        let t = median_time(11, || {
            black_box(DepthBasis::new(
                &components.grid,
                components.expected_power(),
                draft,
                strips,
                gravity,
            ));
        });
        report.push(format!(
            "  draft {draft} m, {strips} strips: rank {} (expected relative rms error {:.1e}): \
             {} transforms per column group instead of {}; basis made in {:.2} ms",
            basis.rank(),
            basis.discarded(),
            1 + basis.rank(),
            1 + strips,
            t.as_secs_f64() * 1e3
        ));
    }
}

// ---------------------------------------------------------------- 5. WAMIT import

fn bench_wamit(c: &mut Criterion, report: &mut Vec<String>) {
    let path = common::shared_data_dir().join("wamit/oc4-semi/marin_semi.12d");
    if !path.is_file() {
        let notice = format!(
            "hydro/read_oc4_12d: skipped, data absent at {}",
            path.display()
        );
        println!("{notice}");
        report.push(notice);
        return;
    }
    let options = WamitOptions::default();
    let mut group = c.benchmark_group("hydro");
    group
        .sample_size(20)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    group.bench_function("read_oc4_12d", |b| {
        b.iter(|| read_difference_qtf(black_box(&path), &options).unwrap())
    });
    group.finish();
    let t = median_time(21, || {
        black_box(read_difference_qtf(&path, &options).unwrap());
    });
    report.push(format!(
        "read_oc4_12d: {:.2} ms (Instant median, 9576 lines, 56 x 56 x 6 QTF); target < 100 ms: {}",
        t.as_secs_f64() * 1e3,
        if t.as_secs_f64() < 0.1 {
            "met"
        } else {
            "NOT met"
        }
    ));
}

// ---------------------------------------------------------------- 6. column-array hydrodynamics

fn bench_columns(c: &mut Criterion, report: &mut Vec<String>) {
    let environment = Environment::default();
    let array = ColumnArray::new(four_columns(), None).unwrap();
    let omegas: Vec<f64> = (0..100).map(|i| 0.05 + 2.95 * i as f64 / 99.0).collect();
    let headings: Vec<f64> = (0..37).map(|i| (10.0 * i as f64).to_radians()).collect();
    let table = || array.drift_table(&environment, &omegas, &headings).unwrap();
    let mut group = c.benchmark_group("hydro");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(6));
    group.bench_function("columns_100x37", |b| b.iter(|| black_box(table())));
    group.finish();
    let time = median_time(5, || {
        black_box(table());
    });
    report.push(format!(
        "hydro/columns_100x37: {:.1} ms (four columns, 100 frequencies x 37 headings, drift \
         near + far, excitation, Aranha damping); under 1 s (issue asks well under): {}",
        time.as_secs_f64() * 1e3,
        if time.as_secs_f64() < 1.0 {
            "yes"
        } else {
            "no"
        }
    ));
}

// ---------------------------------------------------------------- 7. full QTF at FFT cost

/// A smooth, indefinite, complex Hermitian QTF (N/m^2) differing from Newman's (the
/// analytic QTF of tests/full_qtf.rs).
fn analytic_qtf(w1: f64, w2: f64) -> Complex64 {
    let amplitude = 2.0e4 * (1.0 + w1 * w2) * (-(w1 - w2).powi(2) / 0.3).exp()
        - 1.5e4 * (2.5 * w1).sin() * (2.5 * w2).sin();
    amplitude * Complex64::from_polar(1.0, 3.0 * (w1 - w2))
}

/// Bilinear interpolation of the QTF `m` given on `omegas` at (w1, w2) (inside the grid).
fn bilinear(omegas: &[f64], m: &[Complex64], w1: f64, w2: f64) -> Complex64 {
    let n = omegas.len();
    let locate = |w: f64| {
        let k = omegas.partition_point(|&o| o <= w).clamp(1, n - 1) - 1;
        (k, (w - omegas[k]) / (omegas[k + 1] - omegas[k]))
    };
    let ((i, s), (j, t)) = (locate(w1), locate(w2));
    let at = |a: usize, b: usize| m[a * n + b];
    (1.0 - s) * (1.0 - t) * at(i, j)
        + s * (1.0 - t) * at(i + 1, j)
        + (1.0 - s) * t * at(i, j + 1)
        + s * t * at(i + 1, j + 1)
}

/// The full QTF at N_omega = 2048 components in the band 0.3 .. 2.5 rad/s (records at
/// 0.5 s, N = 11 760 samples, 98 min), from a 56-point QTF grid 0.25 .. 3 rad/s (the OC4
/// file's size): the factorised synthesis (factor interpolation + one FFT per retained term)
/// against the direct double sum over the band on the same interpolated QTF, (a) in the
/// time domain at every sample (one sample timed, median of 7, extrapolated to the record; the
/// error checked on 8 samples), (b) binned by difference
/// frequency with one inverse FFT (timed with the 2048^2 interpolated QTF already built).
fn bench_full_qtf(c: &mut Criterion, report: &mut Vec<String>) {
    let count = 2048;
    let dt = 0.5;
    let duration = 5850.0;
    let wide = FrequencyGrid::new(0.0, duration, dt, (0.3, 2.5)).unwrap();
    let band = (wide.omega(0), wide.omega(count - 1) + 0.5 * wide.d_omega);
    let grid = FrequencyGrid::new(0.0, duration, dt, band).unwrap();
    assert_eq!(grid.count, count);
    let sea = SeaState {
        spectrum: Spectrum::Jonswap {
            hs: 6.0,
            tp: 10.0,
            gamma: None,
        },
        spreading: Spreading::LongCrested,
        mean_direction: 0.0,
        n_directions: 1,
        seed: 7,
        band: Some(band),
    };
    let components = WaveComponents::generate(&sea, grid.clone());
    let a = components.of_direction(0);
    let omegas: Vec<f64> = (0..56).map(|i| 0.25 + 2.75 * i as f64 / 55.0).collect();
    let raw: Vec<Complex64> = omegas
        .iter()
        .flat_map(|&x| omegas.iter().map(move |&y| analytic_qtf(x, y)))
        .collect();
    let tolerance = 1e-7;
    let factors = QtfFactorisation::new(&omegas, &raw, tolerance).unwrap();
    let full_rank = QtfFactorisation::new(&omegas, &raw, MIN_QTF_TOLERANCE).unwrap();
    let len = grid.len;
    let mut synth = Synthesizer::new(&grid);
    let mut coefficients = vec![Complex64::default(); count];
    let mut series = vec![Complex64::default(); len];
    let mut factorised = |f: &QtfFactorisation| {
        let g = f.on_grid(&grid).unwrap();
        let mut out = Vec::new();
        g.accumulate(&mut synth, a, &mut coefficients, &mut series, &mut out);
        out
    };

    // The interpolated QTF on the simulation grid, for the direct sums (67 MB).
    let t: Vec<Complex64> = (0..count * count)
        .map(|k| bilinear(&omegas, &raw, grid.omega(k / count), grid.omega(k % count)))
        .collect();
    let inverse = FftPlanner::new().plan_fft_inverse(len);
    let binned = |t: &[Complex64]| {
        // F = Re C_0 + 2 Re sum_{k >= 1} C_k e^{i k d_omega t}, C_k = sum_j a_{j+k} a_j* T_{j+k, j}.
        let mut x = vec![Complex64::default(); len];
        for k in 0..count {
            let mut c = Complex64::default();
            for j in 0..count - k {
                c += a[j + k] * a[j].conj() * t[(j + k) * count + j];
            }
            x[k] = if k == 0 {
                Complex64::new(0.5 * c.re, 0.0)
            } else {
                c
            };
        }
        inverse.process(&mut x);
        x.iter().map(|z| 2.0 * z.re).collect::<Vec<f64>>()
    };
    let time_domain = |m: usize| {
        let time = grid.time(m) - grid.start_time;
        let r: Vec<Complex64> = (0..count)
            .map(|i| a[i] * Complex64::from_polar(1.0, grid.omega(i) * time))
            .collect();
        let mut total = 0.0;
        for i in 0..count {
            let row = &t[i * count..(i + 1) * count];
            let mut s = Complex64::default();
            for (rj, tij) in r.iter().zip(row) {
                s += rj.conj() * tij;
            }
            total += (r[i] * s).re;
        }
        total
    };

    let mut group = c.benchmark_group("full_qtf");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(4));
    group.bench_function(format!("factorised_2048_rank{}", factors.rank()), |b| {
        b.iter(|| black_box(factorised(&factors)))
    });
    group.bench_function("direct_binned_2048", |b| b.iter(|| black_box(binned(&t))));
    group.finish();

    let fast = factorised(&factors);
    let reference = binned(&t);
    let scale = reference.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let error = fast
        .iter()
        .zip(&reference)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        / scale;
    let samples = [0usize, 1, 977, 3001, 5555, 8000, 10_000, len - 2];
    let direct_error = samples
        .iter()
        .map(|&m| (time_domain(m) - fast[m]).abs() / scale)
        .fold(0.0f64, f64::max);
    let t_fast = median_time(11, || {
        black_box(factorised(&factors));
    });
    let t_full_rank = median_time(5, || {
        black_box(factorised(&full_rank));
    });
    let t_binned = median_time(5, || {
        black_box(binned(&t));
    });
    let t_sample = median_time(7, || {
        black_box(time_domain(977));
    });
    let t_direct = t_sample.as_secs_f64() * len as f64;
    let ms = |d: f64| d * 1e3;
    report.push(format!(
        "full_qtf (N_omega = {count}, records N = {len}, QTF 56 x 56, rank {} at tolerance {tolerance:e}):",
        factors.rank()
    ));
    report.push(format!(
        "  factorised: {:.2} ms (rank {}), {:.2} ms at full rank 56; factors {} x 56 x 16 B \
         on the QTF's frequencies + {count} brackets x 16 B = {:.0} kB",
        ms(t_fast.as_secs_f64()),
        factors.rank(),
        ms(t_full_rank.as_secs_f64()),
        factors.rank(),
        ((factors.rank() * 56 + count) * 16) as f64 / 1e3
    ));
    report.push(format!(
        "  direct double sum, time domain: {:.2} ms per sample x {len} samples = {:.1} s \
         (extrapolated from one sample, median of 7): {:.0}x slower (target >= 100x: {}); \
         max error on 8 samples {direct_error:.1e} of max |F|",
        ms(t_sample.as_secs_f64()),
        t_direct,
        t_direct / t_fast.as_secs_f64(),
        if t_direct / t_fast.as_secs_f64() >= 100.0 {
            "met"
        } else {
            "NOT met"
        }
    ));
    report.push(format!(
        "  direct double sum binned by difference frequency + 1 inverse FFT: {:.1} ms \
         (interpolated 2048^2 QTF prebuilt, {:.0} MB, not timed): {:.1}x slower; \
         max error over the record {error:.1e} of max |F| (target < 1e-6: {})",
        ms(t_binned.as_secs_f64()),
        (count * count * 16) as f64 / 1e6,
        t_binned.as_secs_f64() / t_fast.as_secs_f64(),
        if error < 1e-6 && direct_error < 1e-6 {
            "met"
        } else {
            "NOT met"
        }
    ));
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    let mut report = Vec::new();
    bench_records(&mut c, &mut report);
    bench_steps(&mut c, &mut report);
    bench_run(&mut c, &mut report);
    memory(&mut report);
    bench_segments(&mut c, &mut report);
    depth_ranks(&mut report);
    bench_wamit(&mut c, &mut report);
    bench_columns(&mut c, &mut report);
    bench_full_qtf(&mut c, &mut report);
    bench_records_warm(&mut report);
    c.final_summary();
    println!("\n==== slowdrift core summary (std::time::Instant medians) ====");
    for line in report {
        println!("{line}");
    }
}
