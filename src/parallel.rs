//! The crate's one thread pool: independent computations on scoped threads that take the
//! next index from a shared counter, so the work balances itself and the results depend
//! only on their index, never on the thread count or the order in which they finish.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::Duration;

/// Computes `f(0), ..., f(count - 1)` on `threads` scoped threads (at least 1, at most
/// `count`). On the calling thread, `on_event` receives `Some((index, value))` as each one
/// finishes (in finishing order) and `None` every `tick` while none finishes. Returns when
/// every index is done. A computation that may panic catches it itself: a panic in `f`
/// propagates when the scope joins.
pub fn run_indexed<T: Send>(
    count: usize,
    threads: usize,
    f: impl Fn(usize) -> T + Sync,
    tick: Duration,
    mut on_event: impl FnMut(Option<(usize, T)>),
) {
    let next = AtomicUsize::new(0);
    let (sender, receiver) = mpsc::channel();
    std::thread::scope(|scope| {
        for _ in 0..threads.max(1).min(count.max(1)) {
            let sender = sender.clone();
            let (next, f) = (&next, &f);
            scope.spawn(move || loop {
                let index = next.fetch_add(1, Ordering::Relaxed);
                if index >= count {
                    break;
                }
                if sender.send((index, f(index))).is_err() {
                    break;
                }
            });
        }
        drop(sender);
        loop {
            match receiver.recv_timeout(tick) {
                Ok(done) => on_event(Some(done)),
                Err(mpsc::RecvTimeoutError::Timeout) => on_event(None),
                Err(mpsc::RecvTimeoutError::Disconnected) => break,
            }
        }
    });
}

/// `f(0), ..., f(count - 1)` computed on `threads` threads (`run_indexed`), returned in
/// index order.
pub fn map<T: Send>(count: usize, threads: usize, f: impl Fn(usize) -> T + Sync) -> Vec<T> {
    let mut results: Vec<Option<T>> = (0..count).map(|_| None).collect();
    run_indexed(count, threads, f, Duration::from_secs(3600), |event| {
        if let Some((index, value)) = event {
            results[index] = Some(value);
        }
    });
    results
        .into_iter()
        .map(|v| v.expect("every index is computed once the scope has joined"))
        .collect()
}
