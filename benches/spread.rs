//! Initialisation cost of short-crested seas: `cargo bench --bench spread`.
//!
//! `Simulation::new` (wave components, the first segment of the records at h/2, the drag
//! kinematics of 4 columns x 20 strips, and for spread seas the cross-direction terms) on
//! the default platform, whose drift table and column array are built once outside the
//! timing. The run is 3 hours, but the records are one block of `run.block_duration`
//! (16384 s) whatever the duration: the transforms span the block plus the halo and the
//! join's ramp.
//! - `long_crested`: N_beta = 1 (the reference cost);
//! - `spread15_none`, `spread15_mean_direction`, `spread15_bidirectional`: cos^2 over
//!   N_beta = 15 directions; `bidirectional` includes solving the column array for
//!   T(omega; beta_k, beta_l) at the 15 exact directions on every data frequency of the band.
//!
//! Target: N_beta = 15 costs at most N_beta^2 = 225 times the long-crested
//! initialisation. The ratios are printed at the end (medians of interleaved runs timed with
//! `Instant`, since criterion does not compute ratios).

mod timing;

use criterion::Criterion;
use slowdrift::model::Interaction;
use slowdrift::problem::default_problem;
use slowdrift::sea_state::Spreading;
use slowdrift::{Problem, Simulation};
use std::hint::black_box;
use std::time::Duration;
use timing::median_time;

const N_BETA: usize = 15;

fn spread(base: &Problem, interaction: Interaction) -> Problem {
    let mut config = base.clone();
    config.sea.spreading = Spreading::CosN { n: 2.0 };
    config.sea.n_directions = N_BETA;
    config.model.interaction = interaction;
    config
}

fn main() {
    let base = default_problem().expect("the default platform");
    let cases = [
        ("long_crested", base.clone()),
        ("spread15_none", spread(&base, Interaction::None)),
        (
            "spread15_mean_direction",
            spread(&base, Interaction::MeanDirection),
        ),
        (
            "spread15_bidirectional",
            spread(&base, Interaction::Bidirectional),
        ),
    ];
    let mut c = Criterion::default().configure_from_args();
    let mut group = c.benchmark_group("spread_init");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(5));
    for (name, config) in &cases {
        group.bench_function(*name, |b| {
            b.iter(|| black_box(Simulation::new(config.clone()).expect("valid")))
        });
    }
    group.finish();

    let times: Vec<f64> = cases
        .iter()
        .map(|(_, config)| {
            median_time(7, || {
                black_box(Simulation::new(config.clone()).expect("valid"));
            })
            .as_secs_f64()
        })
        .collect();
    println!(
        "\n=== Short-crested initialisation (Simulation::new, default platform, 3-hour run at h = \
         1 s: records of one {} s block, N = {}) ===",
        base.run.block_duration,
        Simulation::new(base.clone()).expect("valid").grid().len
    );
    for ((name, _), t) in cases.iter().zip(&times) {
        println!(
            "{name:<26} {:8.1} ms  = {:6.1} x long-crested",
            1e3 * t,
            t / times[0]
        );
    }
    println!(
        "target: N_beta = {N_BETA} at most N_beta^2 = {} x long-crested",
        N_BETA * N_BETA
    );
}
