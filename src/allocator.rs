//! Allocator tuning for programs that build and drop many simulations (Monte Carlo
//! campaigns): a process-wide setting, so only programs call it (the CLI's `main`, the
//! Monte Carlo benchmark), never the library on its own.
//!
//! Each run allocates its records (43 MB for a 2^14 s run with drag on 4 x 20 strips) and
//! frees them at its end. glibc's malloc returns large freed blocks to the kernel (blocks
//! above the mmap threshold are unmapped, a heap top above the trim threshold is
//! trimmed), so the next run's records land on fresh pages that the kernel must fault in
//! and zero: measured with perf, a quarter of a run's time in the kernel, and two threads
//! faulting at once scale poorly. Raising both thresholds keeps the freed memory in the
//! process for the next run; the resident size stays at the largest run's.
//!
//! Besides `fmi2/`, this is the crate's only unsafe code: one call into the C library.
#![allow(unsafe_code)]

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
    /// glibc accepts both values (it refuses an mmap threshold above its maximum).
    #[test]
    fn glibc_takes_the_setting() {
        assert!(super::retain_freed_memory());
    }
}
