//! One engine chunk: the system started on the realtime clock with a TMR routine that
//! records the lateness of every interrupt delivery, the clock's own lateness of its
//! ticks, and the clock statistics a program reads.

use crate::alloc_count::{ENGINE_ALLOCS, ON_ENGINE};
use crate::by_cpu::record_by_cpu;
use crate::calling_thread::{cpu, gettid};
use crate::proc_sample::{poll, Sample, MEASURED_TID};
use crate::stalls::record_stall;
use crate::{LEAD_TICKS, STALL_NS};
use std::sync::atomic::{AtomicBool, AtomicI32, AtomicPtr, AtomicU64, Ordering};
use std::sync::Arc;
use MCCLPCI_IMP::clock::latency::LatencyHistogram;
use MCCLPCI_IMP::clock::monotonic_ns as mono_ns;
use MCCLPCI_IMP::engine::Shared;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::SYS_CARD_CONFIG;

/// The running engine and the histogram the TMR routine records into (set while an
/// engine chunk runs; the bench keeps both alive until after `MCC_CloseSystem`).
static SHARED: AtomicPtr<Shared> = AtomicPtr::new(std::ptr::null_mut());
pub(crate) static ENGINE_TICKS: AtomicU64 = AtomicU64::new(0);
static ISR_ON: AtomicBool = AtomicBool::new(false);
static ISR_HIST: AtomicPtr<LatencyHistogram> = AtomicPtr::new(std::ptr::null_mut());
static ENGINE_CPU: AtomicI32 = AtomicI32::new(-1);
static ENGINE_STALLED: AtomicBool = AtomicBool::new(false);

unsafe extern "system" fn on_timer(_: *mut MCCLPCI_IMP::vendor::TMRINT) {
    let now = mono_ns();
    let (s, h) = (
        SHARED.load(Ordering::Acquire),
        ISR_HIST.load(Ordering::Acquire),
    );
    if s.is_null() || h.is_null() || !ISR_ON.load(Ordering::Acquire) {
        return;
    }
    // SAFETY: both point at values the bench keeps alive while the engine runs.
    let (s, h) = unsafe { (&*s, &*h) };
    // During delivery the tick in progress is `ticks()` (it counts when it ends).
    let due = s.clock().deadline_ns(s.clock().ticks());
    let late = now.saturating_sub(due);
    h.record_ns(late);
    ON_ENGINE.with(|e| e.set(true));
    let c = cpu();
    record_by_cpu(1, c, late);
    let before = ENGINE_CPU.swap(c, Ordering::Relaxed);
    if MEASURED_TID.load(Ordering::Relaxed) == 0 {
        MEASURED_TID.store(gettid(), Ordering::Release);
    }
    if late >= STALL_NS && !ENGINE_STALLED.load(Ordering::Relaxed) {
        record_stall(now, late, before, c, true);
    }
    ENGINE_STALLED.store(late >= STALL_NS, Ordering::Relaxed);
}

/// One engine chunk: `ticks` realtime ticks of `period_ms` with a TMR routine each tick,
/// measured into `tick_h` and `isr_h`. Returns the missed ticks.
pub(crate) fn engine_chunk(
    period_ms: u16,
    ticks: u64,
    tick_h: &LatencyHistogram,
    isr_h: &Arc<LatencyHistogram>,
    samples: &mut Vec<Sample>,
    print_stats: bool,
) -> u64 {
    use MCCLPCI_IMP::ffi::timer::*;
    std::env::set_var("MCCL_CLOCK", "realtime");
    MCC_CloseSystem();
    MCC_CloseAllGroups();
    MEASURED_TID.store(0, Ordering::Release);
    let mut one = [SYS_CARD_CONFIG {
        wCardType: IMP_III_8_AXIS_PCI_CARD,
        ..Default::default()
    }; 1];
    assert_eq!(
        // SAFETY: one valid card description.
        unsafe { MCC_InitSystem(i32::from(period_ms), one.as_mut_ptr(), 1) },
        NO_ERR
    );
    let shared = MCCLPCI_IMP::system::active().unwrap();
    SHARED.store(Arc::as_ptr(&shared) as *mut Shared, Ordering::Release);
    ISR_HIST.store(Arc::as_ptr(isr_h) as *mut _, Ordering::Release);
    assert_eq!(
        MCCLPCI_IMP::ffi::isr::MCC_SetTMRRoutine(Some(on_timer), 0),
        NO_ERR
    );
    // The timer expires once per tick: period_ms x 100000 x 10 ns.
    assert_eq!(MCC_SetTimer(u32::from(period_ms) * 100_000, 0), NO_ERR);
    assert_eq!(MCC_EnableTimerTrigger(0), NO_ERR);
    assert_eq!(MCC_EnableTimer(0), NO_ERR);
    // The measured window starts half a period after tick LEAD_TICKS from now was due
    // (no tick is in progress then), so not while this thread configures the card.
    let period_ns = u64::from(period_ms) * 1_000_000;
    let start = shared
        .clock()
        .deadline_ns(shared.clock().ticks() + LEAD_TICKS)
        + period_ns / 2;
    MCCLPCI_IMP::clock::sleep_until_ns(start);
    let then = shared.clock().lateness().snapshot();
    ENGINE_STALLED.store(false, Ordering::Relaxed);
    ISR_ON.store(true, Ordering::Release);
    let (first, a0) = (
        shared.clock().ticks(),
        ENGINE_ALLOCS.load(Ordering::Relaxed),
    );
    poll(1, samples, &|| shared.clock().ticks() >= first + ticks);
    ISR_ON.store(false, Ordering::Release);
    let (last, a1) = (
        shared.clock().ticks(),
        ENGINE_ALLOCS.load(Ordering::Relaxed),
    );
    tick_h.merge_since(shared.clock().lateness(), &then);
    ENGINE_ALLOC_SUM.fetch_add(a1 - a0, Ordering::Relaxed);
    ENGINE_TICKS.fetch_add(last - first, Ordering::Relaxed);
    if print_stats {
        print_clock_stats();
    }
    MCC_CloseSystem();
    SHARED.store(std::ptr::null_mut(), Ordering::Release);
    ISR_HIST.store(std::ptr::null_mut(), Ordering::Release);
    shared.clock().missed()
}
pub(crate) static ENGINE_ALLOC_SUM: AtomicU64 = AtomicU64::new(0);

fn print_clock_stats() {
    use MCCLPCI_IMP::ffi::sim::{MCCL_SimGetClockStats, MCCL_CLOCK_STATS};
    let mut st = MCCL_CLOCK_STATS::default();
    // SAFETY: a valid, writable struct.
    assert_eq!(unsafe { MCCL_SimGetClockStats(&mut st) }, NO_ERR);
    println!(
        "  MCCL_SimGetClockStats (last engine chunk): ticks {}, missed {}, p50 {:.0} us, p99 {:.0} us, p99.9 {:.0} us, max {:.0} us",
        st.ullTicks, st.ullMissed, st.dfP50Us, st.dfP99Us, st.dfP999Us, st.dfMaxUs
    );
    let edges = st
        .ullBucket
        .iter()
        .map(|b| b.to_string())
        .collect::<Vec<_>>()
        .join(" ");
    println!("  buckets (<16us, 16-32, ..., >=262144us): {edges}");
}
