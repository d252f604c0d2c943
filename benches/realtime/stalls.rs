//! Stalls (wake-ups at least `STALL_NS` late), recorded without allocating by the
//! measured threads and listed after the case with the `/proc` samples around each.

use crate::proc_sample::Sample;
use crate::Z;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};

/// Stalls seen in the running case: (monotonic ns of the wake-up, lateness ns, CPU
/// before the sleep, CPU after; is the engine), in a fixed array so that recording one
/// allocates nothing.
const STALLS_MAX: usize = 64;
#[allow(clippy::declare_interior_mutable_const)]
const Z4: [AtomicU64; 4] = [Z, Z, Z, Z];
static STALLS: [[AtomicU64; 4]; STALLS_MAX] = [Z4; STALLS_MAX];
pub(crate) static STALL_N: AtomicUsize = AtomicUsize::new(0);

pub(crate) fn record_stall(t: u64, late: u64, cpu_before: i32, cpu_after: i32, engine: bool) {
    let i = STALL_N.fetch_add(1, Ordering::Relaxed);
    if let Some(e) = STALLS.get(i) {
        e[0].store(t, Ordering::Relaxed);
        e[1].store(late, Ordering::Relaxed);
        e[2].store(
            (cpu_before as u32 as u64) << 32 | cpu_after as u32 as u64,
            Ordering::Relaxed,
        );
        e[3].store(u64::from(engine), Ordering::Relaxed);
    }
}

/// Lists the stalls recorded since the case began, with the `/proc` samples around each.
pub(crate) fn print_stalls(case_start: u64, samples: &[Sample]) {
    let n = STALL_N.load(Ordering::Relaxed);
    let ncpu = std::thread::available_parallelism()
        .map_or(2, |n| n.get())
        .min(8);
    for e in STALLS.iter().take(n.min(STALLS_MAX)) {
        let (t, late) = (e[0].load(Ordering::Relaxed), e[1].load(Ordering::Relaxed));
        let cpus = e[2].load(Ordering::Relaxed);
        let who = if e[3].load(Ordering::Relaxed) == 1 {
            "engine"
        } else {
            "reference"
        };
        // The samples bracketing [t - late, t].
        let from = samples.iter().rev().find(|s| s.t <= t - late);
        let to = samples.iter().find(|s| s.t >= t);
        let seen = match (from, to) {
            (Some(a), Some(b)) => {
                let steal = (0..ncpu)
                    .map(|c| {
                        format!(
                            "cpu{c} {}/{} ms",
                            (b.steal[c] - a.steal[c]) * 10,
                            (b.irq[c] - a.irq[c]) * 10
                        )
                    })
                    .collect::<Vec<_>>()
                    .join(", ");
                // Both samples must have read the same, living thread (a reference
                // thread may have ended before the sample after its last stall).
                let thread = if a.tid != 0 && a.tid == b.tid && a.cpu_ns != 0 && b.cpu_ns != 0 {
                    format!(
                        "the thread waited {:.1} ms in the run queue, page faults {} minor, {} major",
                        b.run_delay.saturating_sub(a.run_delay) as f64 / 1e6,
                        b.faults.0.saturating_sub(a.faults.0),
                        b.faults.1.saturating_sub(a.faults.1)
                    )
                } else {
                    "the thread was not sampled on both sides".to_string()
                };
                format!(
                    "over {:.0} ms around it: host steal/guest irq+softirq {steal}; {thread}",
                    (b.t - a.t) as f64 / 1e6,
                )
            }
            _ => "no /proc samples around it".to_string(),
        };
        println!(
            "  stall: {who} woke {:.1} ms late at +{:.3} s, CPU {} -> {}; {seen}",
            late as f64 / 1e6,
            (t - case_start) as f64 / 1e9,
            (cpus >> 32) as u32 as i32,
            cpus as u32 as i32
        );
    }
    if n > STALLS_MAX {
        println!("  ({} more stalls not listed)", n - STALLS_MAX);
    }
}
