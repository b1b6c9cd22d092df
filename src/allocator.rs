//! The system allocator, directly: a probe of whether the process can allocate a size
//! ([`can_allocate`], for the memory budget, `record_plan::budget`), and allocator tuning for
//! programs that build and drop many simulations (Monte Carlo campaigns:
//! [`retain_freed_memory`], a process-wide setting, so only programs call it (the CLI's
//! `main`, the Monte Carlo benchmark), never the library on its own).
//!
//! Each run allocates its records (43 MB for a 2^14 s run with drag on 4 x 20 strips) and
//! frees them at its end. glibc's malloc returns large freed blocks to the kernel (blocks
//! above the mmap threshold are unmapped, a heap top above the trim threshold is
//! trimmed), so the next run's records land on fresh pages that the kernel must fault in
//! and zero: measured with perf, a quarter of a run's time in the kernel, and two threads
//! faulting at once scale poorly. Raising both thresholds keeps the freed memory in the
//! process for the next run; the resident size stays at the largest run's.
//!
//! Besides `fmi2/`, this is the crate's only unsafe code: one call into the C library and
//! one allocation and release through the system allocator.
#![allow(unsafe_code)]

use std::alloc::{GlobalAlloc, Layout, System};

/// Whether the system allocator gives `bytes` now: they are allocated (never touched, so no
/// page is faulted in) and released at once. False when the process's limit (`setrlimit`
/// RLIMIT_AS, a container's) or the machine's overcommit policy refuses them. Through the
/// system allocator, not the global one, so that a program's counting or tracking
/// allocator does not see the probe as memory held.
pub fn can_allocate(bytes: usize) -> bool {
    let Ok(layout) = Layout::from_size_align(bytes.max(1), 16) else {
        return false;
    };
    // SAFETY: the layout has a non-zero size; the block, when given, is released with the
    // same layout and never read or written. `black_box`: an allocation that is freed unused
    // may otherwise be removed by the optimiser, which assumes it succeeds (a probe of 1e18
    // bytes inlined with its size answered true).
    unsafe {
        let block = std::hint::black_box(System.alloc(layout));
        if block.is_null() {
            return false;
        }
        System.dealloc(block, layout);
    }
    true
}

/// The largest mmap threshold glibc accepts on 64-bit targets (HEAP_MAX_SIZE / 2, 32 MiB).
#[cfg(all(target_os = "linux", target_env = "gnu"))]
const MMAP_THRESHOLD_MAX: libc::c_int = 32 << 20;

/// Keeps freed memory in the process (glibc: `mallopt` of `M_MMAP_THRESHOLD` and
/// `M_TRIM_THRESHOLD`); true when the allocator took the setting. Elsewhere it does
/// nothing and returns false. Call it at the start of `main`, before other threads exist.
pub fn retain_freed_memory() -> bool {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    {
        // SAFETY: mallopt only changes allocator parameters; it takes integers and touches no
        // memory of ours. glibc serialises it with the arenas' locks.
        unsafe {
            libc::mallopt(libc::M_MMAP_THRESHOLD, MMAP_THRESHOLD_MAX) == 1
                && libc::mallopt(libc::M_TRIM_THRESHOLD, libc::c_int::MAX) == 1
        }
    }
    #[cfg(not(all(target_os = "linux", target_env = "gnu")))]
    {
        false
    }
}

#[cfg(all(test, target_os = "linux", target_env = "gnu"))]
mod tests {
    /// A small size is given; a size beyond any address space is refused, not aborted on:
    /// one whose layout cannot exist, and one the allocator is asked for (2^62 bytes, a
    /// constant the optimiser sees through inlining).
    #[test]
    fn the_probe_gives_small_sizes_and_refuses_impossible_ones() {
        assert!(super::can_allocate(1 << 20));
        assert!(!super::can_allocate(usize::MAX / 2));
        assert!(!super::can_allocate(1 << 62));
    }

    /// glibc accepts both values (it refuses an mmap threshold above its maximum).
    #[test]
    fn glibc_takes_the_setting() {
        assert!(super::retain_freed_memory());
    }
}
