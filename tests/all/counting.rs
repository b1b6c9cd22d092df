//! The test binary's allocator: the system allocator, counting this thread's allocations
//! the bytes this thread holds (allocated minus freed) and their peak, for the tests that check that
//! the stepping loop allocates nothing and that memory does not grow with a run's length.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
    static LIVE_BYTES: Cell<isize> = const { Cell::new(0) };
    static PEAK_BYTES: Cell<isize> = const { Cell::new(0) };
}

fn held(delta: isize) {
    LIVE_BYTES.with(|b| {
        let live = b.get() + delta;
        b.set(live);
        PEAK_BYTES.with(|p| p.set(p.get().max(live)));
    });
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.with(|n| n.set(n.get() + 1));
        held(layout.size() as isize);
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        held(-(layout.size() as isize));
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.with(|n| n.set(n.get() + 1));
        held(new_size as isize - layout.size() as isize);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static COUNTING: Counting = Counting;

/// Allocations (and reallocations) made by this thread so far.
pub fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

/// Bytes allocated by this thread and not yet freed.
pub fn live_bytes() -> isize {
    LIVE_BYTES.with(Cell::get)
}

/// Starts a new peak: from now, [`peak_bytes`] is the most this thread has held since.
pub fn reset_peak() {
    PEAK_BYTES.with(|p| p.set(live_bytes()));
}

/// The most bytes this thread has held at once since [`reset_peak`].
pub fn peak_bytes() -> isize {
    PEAK_BYTES.with(Cell::get)
}
