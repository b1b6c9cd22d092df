//! A hint to the CPU that a record's sample will be read soon.

// The one unsafe call: the prefetch instruction, which reads nothing and cannot fault.
#![allow(unsafe_code)]

/// Asks the CPU to bring `slice[i]` into its caches (nothing when `i` is past the end).
#[inline(always)]
pub(super) fn prefetch<T>(slice: &[T], i: usize) {
    #[cfg(target_arch = "x86_64")]
    if let Some(x) = slice.get(i) {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        // SAFETY: a prefetch of a valid address; it reads nothing the program sees.
        unsafe { _mm_prefetch::<_MM_HINT_T0>((x as *const T).cast::<i8>()) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (slice, i);
}
