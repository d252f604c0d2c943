//! The reference: a bare loop sleeping to absolute deadlines on a thread set up as the
//! engine thread is, and one chunk of it.

use crate::by_cpu::record_by_cpu;
use crate::calling_thread::{cpu, gettid};
use crate::proc_sample::{poll, Sample, MEASURED_TID};
use crate::stalls::record_stall;
use crate::{LEAD_TICKS, STALL_NS};
use std::sync::atomic::Ordering;
use std::sync::Arc;
use MCCLPCI_IMP::clock::latency::LatencyHistogram;
use MCCLPCI_IMP::clock::monotonic_ns as mono_ns;

/// The bare loop: `ticks` absolute-deadline sleeps of `period_ns`, the first to
/// `first`, on a thread set up as the engine thread is.
fn reference(
    period_ns: u64,
    first: u64,
    ticks: u64,
    into: &Arc<LatencyHistogram>,
    kind: usize,
) -> std::thread::JoinHandle<()> {
    let h = into.clone();
    std::thread::Builder::new()
        .name("reference".into())
        .spawn(move || {
            MCCLPCI_IMP::engine::thread::setup_current_thread(true);
            MEASURED_TID.store(gettid(), Ordering::Release);
            let (mut last_cpu, mut stalled) = (cpu(), false);
            for n in 0..LEAD_TICKS + ticks {
                let d = first + n * period_ns;
                let ts = libc::timespec {
                    tv_sec: (d / 1_000_000_000) as libc::time_t,
                    tv_nsec: (d % 1_000_000_000) as libc::c_long,
                };
                // SAFETY: `ts` is a valid timespec; the remainder is unused (NULL) with
                // TIMER_ABSTIME. Interrupted sleeps are retried.
                while unsafe {
                    libc::clock_nanosleep(
                        libc::CLOCK_MONOTONIC,
                        libc::TIMER_ABSTIME,
                        &ts,
                        std::ptr::null_mut(),
                    )
                } == libc::EINTR
                {}
                let now = mono_ns();
                let late = now.saturating_sub(d);
                if n >= LEAD_TICKS {
                    h.record_ns(late);
                    let c = cpu();
                    record_by_cpu(kind, c, late);
                    if late >= STALL_NS && !stalled {
                        record_stall(now, late, last_cpu, c, false);
                    }
                    stalled = late >= STALL_NS;
                    last_cpu = c;
                }
            }
        })
        .unwrap()
}

/// One reference chunk: `ticks` deadlines measured into `h`, its wake-ups counted per
/// CPU as `kind` (0; 1 for the stand-in of an engine chunk in the A/A mode).
pub(crate) fn reference_chunk(
    period_ns: u64,
    ticks: u64,
    h: &Arc<LatencyHistogram>,
    samples: &mut Vec<Sample>,
    kind: usize,
) {
    MEASURED_TID.store(0, Ordering::Release);
    let first = mono_ns() + period_ns;
    let r = reference(period_ns, first, ticks, h, kind);
    poll(kind, samples, &|| r.is_finished());
    r.join().unwrap();
}
