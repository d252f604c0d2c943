//! `cargo bench --bench realtime`: how punctual the realtime clock is, against what the
//! kernel gives in the same run.
//!
//! For each period (1 ms, 2 ms) and load (idle; a CPU-bound thread on every core, started
//! here and stopped when the case ends), in the same process and at the same scheduling
//! settings (`MCCL_RT_*`, see docs/clocks-and-tracing.md "The clock"):
//!
//! * reference: a bare loop sleeping to absolute deadlines `start + n × period` with
//!   `clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME)`; its lateness is the time it woke
//!   minus the deadline. Like the engine it never skips a deadline: after a stall the
//!   deadlines already past are each counted with their own lateness.
//! * engine tick: the lateness of every realtime tick, as the clock counts it
//!   (`Clock::lateness`, what `MCCL_SimGetClockStats` reports), over the reference's
//!   time span (the ticks while the program configures the card and starts the
//!   reference are left out of the comparison; `MCCL_SimGetClockStats`, printed once per
//!   case, counts them).
//! * interrupt delivery: a TMR routine whose timer expires every tick; its lateness is the
//!   time the routine runs minus the deadline of the tick that raised it.
//!
//! The reference runs at the same time as the engine, its deadlines half a period after
//! the engine's (so the two never want the CPU at the same moment): the host's
//! background load, which on a shared machine changes from second to second and now and
//! then stalls every normal thread for a long time, falls on both alike. Percentiles come
//! from the same histogram type (1 µs resolution below 64 µs, 3 % above).

use std::sync::atomic::{AtomicBool, AtomicPtr, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};
use MCCLPCI_IMP::clock::latency::LatencyHistogram;
use MCCLPCI_IMP::engine::Shared;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::SYS_CARD_CONFIG;

/// Engine runs per case (each `MCC_InitSystem` .. `MCC_CloseSystem`).
const CHUNKS: u64 = 3;

/// Counts allocations (of any thread) so that the engine's per tick can be shown.
struct Counting;
static ALLOCS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
// SAFETY: forwards to the system allocator unchanged; only counts calls.
unsafe impl std::alloc::GlobalAlloc for Counting {
    unsafe fn alloc(&self, l: std::alloc::Layout) -> *mut u8 {
        ALLOCS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: same contract as the caller's.
        unsafe { std::alloc::System.alloc(l) }
    }
    unsafe fn dealloc(&self, p: *mut u8, l: std::alloc::Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { std::alloc::System.dealloc(p, l) }
    }
    unsafe fn realloc(&self, p: *mut u8, l: std::alloc::Layout, n: usize) -> *mut u8 {
        ALLOCS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: same contract as the caller's.
        unsafe { std::alloc::System.realloc(p, l, n) }
    }
}
#[global_allocator]
static GLOBAL: Counting = Counting;

use MCCLPCI_IMP::clock::monotonic_ns as mono_ns;

/// The bare loop: `ticks` absolute-deadline sleeps of `period_ns`, the first to
/// `first`, on a thread set up as the engine thread is.
fn reference(
    period_ns: u64,
    first: u64,
    ticks: u64,
    into: &Arc<LatencyHistogram>,
) -> std::thread::JoinHandle<()> {
    let h = into.clone();
    std::thread::Builder::new()
        .name("reference".into())
        .spawn(move || {
            MCCLPCI_IMP::engine::thread::setup_current_thread(true);
            for n in 0..ticks {
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
                h.record_ns(mono_ns().saturating_sub(d));
            }
        })
        .unwrap()
}

/// The running engine and the histogram the TMR routine records into (set while an
/// engine chunk runs; the bench keeps both alive until after `MCC_CloseSystem`).
static SHARED: AtomicPtr<Shared> = AtomicPtr::new(std::ptr::null_mut());
static ENGINE_ALLOCS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
static ENGINE_TICKS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
static ISR_ON: AtomicBool = AtomicBool::new(false);
static ISR_HIST: AtomicPtr<LatencyHistogram> = AtomicPtr::new(std::ptr::null_mut());

unsafe extern "C" fn on_timer(_: *mut MCCLPCI_IMP::vendor::TMRINT) {
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
    h.record_ns(now.saturating_sub(s.clock.deadline_ns(s.clock.ticks())));
}

/// One engine chunk: `ticks` realtime ticks of `period_ms` with a TMR routine each tick.
/// Returns the missed ticks; adds to the tick and interrupt histograms.
fn engine(
    period_ms: u16,
    ticks: u64,
    reference_h: &Arc<LatencyHistogram>,
    tick_h: &LatencyHistogram,
    isr_h: &Arc<LatencyHistogram>,
    print_stats: bool,
) -> u64 {
    use MCCLPCI_IMP::ffi::timer::*;
    std::env::set_var("MCCL_CLOCK", "realtime");
    MCC_CloseSystem();
    MCC_CloseAllGroups();
    let mut one = [SYS_CARD_CONFIG {
        wCardType: IMP_III_8_AXIS_PCI_CARD,
        ..Default::default()
    }; 1];
    // SAFETY: one valid card description.
    assert_eq!(
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
    // The reference loop, due half a period after each of the engine's next ticks.
    let period_ns = u64::from(period_ms) * 1_000_000;
    let next = shared.clock.deadline_ns(shared.clock.ticks() + 10) + period_ns / 2;
    let reference = reference(period_ns, next, ticks, reference_h);
    // The engine is measured over the reference's time span (so not while this thread
    // configures it or spawns the reference). Only the engine thread allocates meanwhile
    // (this thread sleeps, the load threads and the reference loop do not), so the
    // allocations counted are the engine's.
    MCCLPCI_IMP::clock::sleep_until_ns(next);
    let then = shared.clock.lateness().snapshot();
    ISR_ON.store(true, Ordering::Release);
    let (first, a0) = (shared.clock.ticks(), ALLOCS.load(Ordering::Relaxed));
    while shared.clock.ticks() < first + ticks {
        std::thread::sleep(Duration::from_millis(20));
    }
    let (last, a1) = (shared.clock.ticks(), ALLOCS.load(Ordering::Relaxed));
    reference.join().unwrap();
    ISR_ON.store(false, Ordering::Release);
    tick_h.merge_since(shared.clock.lateness(), &then);
    ENGINE_ALLOCS.fetch_add(a1 - a0, Ordering::Relaxed);
    ENGINE_TICKS.fetch_add(last - first, Ordering::Relaxed);
    if print_stats {
        print_clock_stats();
    }
    MCC_CloseSystem();
    SHARED.store(std::ptr::null_mut(), Ordering::Release);
    ISR_HIST.store(std::ptr::null_mut(), Ordering::Release);
    shared.clock.missed()
}

fn print_clock_stats() {
    use MCCLPCI_IMP::ffi::sim::{MCCL_SimGetClockStats, MCCL_CLOCK_STATS};
    let mut st = MCCL_CLOCK_STATS::default();
    // SAFETY: a valid, writable struct.
    assert_eq!(unsafe { MCCL_SimGetClockStats(&mut st) }, NO_ERR);
    println!(
        "  MCCL_SimGetClockStats (this chunk): ticks {}, missed {}, p50 {:.0} us, p99 {:.0} us, p99.9 {:.0} us, max {:.0} us",
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

fn line(name: &str, h: &LatencyHistogram) -> String {
    format!(
        "  {name:<20} p50 {:>6.0} us  p99 {:>6.0} us  p99.9 {:>6.0} us  max {:>6.0} us  ({} samples)",
        h.quantile_us(0.5),
        h.quantile_us(0.99),
        h.quantile_us(0.999),
        h.max_us(),
        h.count()
    )
}

/// A CPU-bound thread on every core until `stop` (or 10 minutes at the latest).
fn start_load(stop: &Arc<AtomicBool>) -> Vec<std::thread::JoinHandle<()>> {
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

/// Sets the calling thread's scheduling policy; whether it was allowed.
fn set_policy(policy: libc::c_int, prio: libc::c_int) -> bool {
    let p = libc::sched_param {
        sched_priority: prio,
    };
    // SAFETY: the calling thread and a valid sched_param.
    unsafe { libc::pthread_setschedparam(libc::pthread_self(), policy, &p) == 0 }
}

fn case(policy: &str, period_ms: u16, loaded: bool, ticks: u64) {
    let stop = Arc::new(AtomicBool::new(false));
    let load = if loaded {
        start_load(&stop)
    } else {
        Vec::new()
    };
    let reference_h = Arc::new(LatencyHistogram::new());
    let tick_h = LatencyHistogram::new();
    let isr_h = Arc::new(LatencyHistogram::new());
    let mut missed = 0;
    ENGINE_ALLOCS.store(0, Ordering::Relaxed);
    ENGINE_TICKS.store(0, Ordering::Relaxed);
    let label = format!(
        "{policy}, period {period_ms} ms, {}",
        if loaded {
            format!("{} CPU-bound threads", load.len())
        } else {
            "idle".to_string()
        }
    );
    println!("{label}:");
    for c in 0..CHUNKS {
        missed += engine(
            period_ms,
            ticks / CHUNKS,
            &reference_h,
            &tick_h,
            &isr_h,
            c + 1 == CHUNKS,
        );
    }
    stop.store(true, Ordering::Relaxed);
    for t in load {
        let _ = t.join();
    }
    println!("{}", line("reference sleep", &reference_h));
    println!("{}", line("engine tick", &tick_h));
    println!("{}", line("interrupt delivery", &isr_h));
    println!(
        "  missed ticks: {missed}; engine allocations per tick: {:.3}",
        ENGINE_ALLOCS.load(Ordering::Relaxed) as f64
            / ENGINE_TICKS.load(Ordering::Relaxed).max(1) as f64
    );
    let r = reference_h.quantile_us(0.99).max(1.0);
    println!(
        "realtime lateness ratio p99: tick {:.2}, interrupt {:.2} ({label}; reference p99 {:.0} us)",
        tick_h.quantile_us(0.99) / r,
        isr_h.quantile_us(0.99) / r,
        reference_h.quantile_us(0.99)
    );
}

fn main() {
    // A filter argument (`cargo bench --bench realtime -- fifo-1ms`) runs only the
    // cases whose name contains it.
    let filter: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    for fifo in [false, true] {
        let policy = if fifo {
            // The engine thread (MCCL_RT_PRIORITY) and the reference thread (the same
            // set-up) run SCHED_FIFO 50; the load threads stay SCHED_OTHER.
            if !set_policy(libc::SCHED_FIFO, 50) {
                println!("SCHED_FIFO is not permitted here: the SCHED_FIFO cases are skipped");
                continue;
            }
            set_policy(libc::SCHED_OTHER, 0);
            std::env::set_var("MCCL_RT_PRIORITY", "50");
            "SCHED_FIFO 50"
        } else {
            std::env::remove_var("MCCL_RT_PRIORITY");
            "SCHED_OTHER"
        };
        for (period, ticks) in [(1u16, 15_000u64), (2, 7_500)] {
            for loaded in [false, true] {
                let name = format!(
                    "{}-{period}ms-{}",
                    if fifo { "fifo" } else { "other" },
                    if loaded { "load" } else { "idle" }
                );
                if filter.is_empty() || filter.iter().any(|f| name.contains(f.as_str())) {
                    case(policy, period, loaded, ticks);
                }
            }
        }
    }
}
