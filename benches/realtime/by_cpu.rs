//! The lateness of each kind of wake-up per CPU it ran on, recorded over the run and
//! printed per case.

use crate::aa_mode;
use MCCLPCI_IMP::clock::latency::LatencyHistogram;

/// CPUs the per-CPU lateness is kept for (a wake-up on a higher one counts for the last).
const CPUS: usize = 8;

/// Lateness per kind of wake-up (0: the reference loop's, 1: interrupt delivery) and
/// CPU it ran on, over the whole run (a case reads what it added, [`by_cpu_since`]).
/// Made before the first chunk, so the engine thread never allocates it.
static BY_CPU: std::sync::OnceLock<Vec<LatencyHistogram>> = std::sync::OnceLock::new();

pub(crate) fn by_cpu() -> &'static [LatencyHistogram] {
    BY_CPU.get_or_init(|| (0..2 * CPUS).map(|_| LatencyHistogram::new()).collect())
}

/// Records `late` ns for a wake-up of `kind` on CPU `cpu`.
pub(crate) fn record_by_cpu(kind: usize, cpu: i32, late: u64) {
    let c = usize::try_from(cpu).unwrap_or(0).min(CPUS - 1);
    if let Some(h) = by_cpu().get(kind * CPUS + c) {
        h.record_ns(late);
    }
}

/// What each per-CPU histogram gained since `then` (a snapshot of [`by_cpu`]).
pub(crate) fn by_cpu_since(then: &[LatencyHistogram]) -> Vec<LatencyHistogram> {
    by_cpu()
        .iter()
        .zip(then)
        .map(|(now, then)| {
            let h = LatencyHistogram::new();
            h.merge_since(now, then);
            h
        })
        .collect()
}

/// The p99 lateness of each kind of wake-up on each CPU it ran on in the case, and how
/// many it had there: a vCPU the host serves worse shows as a higher p99 there for
/// whichever kind of chunk ran on it.
pub(crate) fn print_by_cpu(h: &[LatencyHistogram]) {
    let kind = |k: usize, name: &str| {
        let cpus: Vec<String> = (0..CPUS)
            .filter_map(|c| {
                h.get(k * CPUS + c)
                    .filter(|h| h.count() > 0)
                    .map(|h| (c, h))
            })
            .map(|(c, h)| format!("cpu{c} {:.0} us ({})", h.quantile_us(0.99), h.count()))
            .collect();
        format!("{name} {}", cpus.join(", "))
    };
    println!(
        "  p99 by CPU (wake-ups): {}; {}",
        kind(0, "reference sleep"),
        kind(
            1,
            if aa_mode() {
                "second reference (A/A)"
            } else {
                "interrupt delivery"
            }
        )
    );
}
