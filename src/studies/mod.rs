//! The computations behind the paper's studies (E&S 1996, section 5, Figs 7-15), apart
//! from any plotting: what `slowdrift study` draws.
//!
//! - [`distribution`]: histogram estimate of a probability density, the Gaussian density,
//!   box-plot statistics (quartiles, Tukey whiskers), the sample standard deviation and the
//!   least-squares slope of a log-log law (the scatter of a record-length statistic falls
//!   like `L^-1/2`).
//! - [`waves`]: the wave elevation record of a configuration (Figs 7, 8).
//! - [`blocks`]: statistics per consecutive block of a record (the transient, Fig. 11).
//! - [`parallel_map`]: runs independent simulations on scoped threads.

pub mod blocks;
pub mod distribution;
pub mod waves;

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// `f(0), f(1), ..., f(count - 1)` computed on `threads` scoped threads (at least 1) that
/// take the next index from a shared counter; the results are returned in index order, so
/// they do not depend on the thread count.
pub fn parallel_map<T: Send>(
    count: usize,
    threads: usize,
    f: impl Fn(usize) -> T + Sync,
) -> Vec<T> {
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<T>>> = Mutex::new((0..count).map(|_| None).collect());
    std::thread::scope(|scope| {
        for _ in 0..threads.max(1).min(count.max(1)) {
            scope.spawn(|| loop {
                let index = next.fetch_add(1, Ordering::Relaxed);
                if index >= count {
                    break;
                }
                let value = f(index);
                results.lock().unwrap_or_else(|e| e.into_inner())[index] = Some(value);
            });
        }
    });
    results
        .into_inner()
        .unwrap_or_else(|e| e.into_inner())
        .into_iter()
        .map(|v| v.expect("every index is computed once the scope has joined"))
        .collect()
}
