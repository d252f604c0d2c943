//! The engine thread's allocations, counted by the global allocator (only on the engine
//! thread, which the TMR routine marks), so that those per tick can be shown.

use std::sync::atomic::{AtomicU64, Ordering};

thread_local! {
    /// Set on the engine thread by the TMR routine: allocations are counted there only.
    pub(crate) static ON_ENGINE: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Counts the engine thread's allocations, so that those per tick can be shown.
struct Counting;
pub(crate) static ENGINE_ALLOCS: AtomicU64 = AtomicU64::new(0);
fn count_alloc() {
    if ON_ENGINE.try_with(std::cell::Cell::get).unwrap_or(false) {
        ENGINE_ALLOCS.fetch_add(1, Ordering::Relaxed);
    }
}
// SAFETY: forwards to the system allocator unchanged; only counts calls.
unsafe impl std::alloc::GlobalAlloc for Counting {
    unsafe fn alloc(&self, l: std::alloc::Layout) -> *mut u8 {
        count_alloc();
        // SAFETY: same contract as the caller's.
        unsafe { std::alloc::System.alloc(l) }
    }
    unsafe fn dealloc(&self, p: *mut u8, l: std::alloc::Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { std::alloc::System.dealloc(p, l) }
    }
    unsafe fn realloc(&self, p: *mut u8, l: std::alloc::Layout, n: usize) -> *mut u8 {
        count_alloc();
        // SAFETY: same contract as the caller's.
        unsafe { std::alloc::System.realloc(p, l, n) }
    }
}
#[global_allocator]
static GLOBAL: Counting = Counting;
