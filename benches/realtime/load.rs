//! The background load of a loaded case: a CPU-bound thread on every core.

use crate::calling_thread::set_policy;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// A CPU-bound thread on every core until `stop` (or 10 minutes at the latest).
pub(crate) fn start_load(stop: &Arc<AtomicBool>) -> Vec<std::thread::JoinHandle<()>> {
    let n = std::thread::available_parallelism().map_or(2, |n| n.get());
    (0..n)
        .map(|_| {
            let stop = stop.clone();
            std::thread::spawn(move || {
                set_policy(libc::SCHED_OTHER, 0);
                let end = Instant::now() + Duration::from_secs(600);
                let mut x = 1u64;
                while !stop.load(Ordering::Relaxed) && Instant::now() < end {
                    for _ in 0..10_000 {
                        x = std::hint::black_box(x.wrapping_mul(6364136223846793005) + 1);
                    }
                }
            })
        })
        .collect()
}
