//! Timing helpers shared by the benchmarks (a module folder, so cargo does not take it for
//! a benchmark of its own).

use std::time::{Duration, Instant};

/// Median of `reps` timings of `f` after one warm-up call.
pub fn median_time(reps: usize, mut f: impl FnMut()) -> Duration {
    f();
    let mut times: Vec<Duration> = (0..reps)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed()
        })
        .collect();
    times.sort();
    times[reps / 2]
}
