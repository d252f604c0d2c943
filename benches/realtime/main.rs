//! `cargo bench --bench realtime`: how punctual the realtime clock is, against what the
//! kernel gives in the same run.
//!
//! For each period (1 ms, 2 ms) and load (idle; a CPU-bound thread on every core, started
//! here and stopped when the case ends), in the same process and at the same scheduling
//! settings (`MCCL_RT_*`, see docs/clocks-and-tracing.md "The clock"), chunks of two kinds
//! alternate:
//!
//! * reference chunk: a bare loop sleeping to absolute deadlines `start + n × period` with
//!   `clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME)` on a thread set up as the engine
//!   thread is (timer slack, `MCCL_RT_PRIORITY`, `MCCL_RT_CPU`; never a spin); its
//!   lateness is the time it woke minus the deadline. Like the engine it never skips a
//!   deadline: after a stall the deadlines already past are each counted with their own
//!   lateness.
//! * engine chunk: `MCC_InitSystem`, a TMR routine whose timer expires every tick, then
//!   the lateness of every realtime tick as the clock counts it (`Clock::lateness`, what
//!   `MCCL_SimGetClockStats` reports) and of interrupt delivery (the time the routine runs
//!   minus the deadline of the tick that raised it), then `MCC_CloseSystem`.
//!
//! Only one of the two runs at a time, so each sees the machine alone, as a program would:
//! the vCPUs sleep and wake in the same pattern for both (run together, the two threads
//! changed each other's wake-ups). The background load, which on a shared VM changes
//! from second to second, falls on both alike because the chunks are short (`CHUNK`,
//! 250 ms) and many (`PAIRS`, 54), alternating (reference first in even pairs, engine
//! first in odd ones). The case is cut into `BLOCKS` (9) blocks of 6 pairs; in each,
//! the engine's p99 over its chunks is divided by the reference's p99 over its chunks,
//! and the printed ratio is the median of the 9: a single host stall of 100 ms or more
//! (seen on a shared VM: the host does not run the vCPU for that long) is more than 1 % of
//! a case's samples at 1 ms, and would otherwise set the p99 of whichever kind of chunk
//! it hit. The ratio of all chunks pooled and that of each block are printed too.
//!
//! Why 9 blocks: in A/A runs (below) about one block in ten read above 1.5, the
//! reference against itself, and a stretch of seconds in which the host serves a vCPU
//! late spans two or three blocks. The median of 5 then fails now and then with no
//! difference between the two kinds of chunk; the median of 9 needs five such blocks.
//! A systematic excess of the engine shows in most blocks, so it is found as before.
//!
//! Both chunks of a pair run on one CPU (`MCCL_RT_CPU`, applied by the reference thread
//! and by the engine thread alike), pairs 0 and 1 on the first CPU the process may use,
//! 2 and 3 on the next, and so on around. Traced with ftrace (`scripts/rt-trace.sh`),
//! the kernel takes as long to wake either thread on the same CPU, but the two vCPUs of
//! a shared VM are served differently for seconds at a time (median 12 µs on one against
//! 8 µs on the other in the same seconds), and an unpinned thread's CPU is chance: in one
//! run the reference woke 10,584 times on the slow vCPU and 3,359 on the fast one, the
//! engine half and half. Unpinned, that chance decided blocks; pinned, every block
//! compares the two kinds on the same CPUs. `MCCL_RT_BENCH_PIN=0` leaves the threads
//! where the kernel puts them; a program's own `MCCL_RT_CPU` pins every chunk there.
//!
//! The p99 of each kind of wake-up is also printed per CPU it ran on (a vCPU the host
//! serves worse than the other shows there). With `MCCL_RT_BENCH_AA` set, every engine
//! chunk is replaced by a second reference chunk: the ratios then compare the reference
//! with itself and show the spread the benchmark has on this machine (an A/A test).
//!
//! The main thread polls every 20 ms in both kinds of chunk and samples `/proc` each
//! time: the host's steal time and the guest's interrupt time per CPU (`/proc/stat`, 10
//! ms units), and the measured thread's CPU time, run-queue wait (`schedstat`) and page
//! faults (`stat`). Printed: the CPU time and run-queue wait per period of each kind of
//! thread, and every stall (a wake-up 20 ms or more late) with the samples around it, so
//! that a stall can be told apart as the host's (steal time), the guest scheduler's
//! (run-queue wait) or the thread's own (a page fault, a lock: neither of the two).
//!
//! One concept a file in `benches/realtime/`: the reference loop (`reference`), the engine
//! chunk (`engine_chunk`), a case of interleaved chunks and its report (`case`), and what
//! they measure with: the `/proc` samples (`proc_sample`), stalls (`stalls`), lateness per
//! CPU (`by_cpu`), the engine thread's allocations (`alloc_count`), the calling thread
//! (`calling_thread`), the background load (`load`) and where the threads run (`pinning`).

mod alloc_count;
mod by_cpu;
mod calling_thread;
mod case;
mod engine_chunk;
mod load;
mod pinning;
mod proc_sample;
mod reference;
mod stalls;

use by_cpu::by_cpu;
use calling_thread::set_policy;
use case::case;
use pinning::{allowed_cpus, placement};
use std::sync::atomic::AtomicU64;
use std::time::Duration;

/// Pairs of chunks (one reference, one engine) per case.
const PAIRS: usize = 54;
/// How long each chunk measures.
const CHUNK: Duration = Duration::from_millis(250);
/// The pairs are reported in this many blocks (pooled within each); the printed ratio
/// is the median of the blocks' ratios.
const BLOCKS: usize = 9;
/// Deadlines before a chunk's measured window (the thread settles, the card is set up).
const LEAD_TICKS: u64 = 10;
/// A wake-up at least this late is a stall, listed with the kernel's view of it.
const STALL_NS: u64 = 20_000_000;
/// How often the main thread polls (and samples `/proc`) during a chunk.
const POLL: Duration = Duration::from_millis(20);

/// A zero, to initialize arrays of atomics.
#[allow(clippy::declare_interior_mutable_const)]
const Z: AtomicU64 = AtomicU64::new(0);

/// `MCCL_RT_BENCH_AA` set: every engine chunk is replaced by a second reference chunk,
/// so that the printed ratios show the spread the benchmark gives a thread against
/// itself (what a ratio must exceed to say anything about the engine).
fn aa_mode() -> bool {
    std::env::var_os("MCCL_RT_BENCH_AA").is_some()
}

fn main() {
    // Read before anything is pinned.
    allowed_cpus();
    // A filter argument (`cargo bench --bench realtime -- fifo-1ms`) runs only the
    // cases whose name contains it.
    let filter: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    let spin = std::env::var("MCCL_RT_SPIN_US").unwrap_or_default();
    println!(
        "chunks of {} ms, {PAIRS} pairs per case, reference and engine alternating (never at the same time); engine spin MCCL_RT_SPIN_US={:?} (the reference never spins)",
        CHUNK.as_millis(),
        spin
    );
    match placement() {
        Some(why) => println!("{why}"),
        None => println!(
            "each pair of chunks pinned to one CPU (MCCL_RT_CPU), in turn over CPUs {:?}; MCCL_RT_BENCH_PIN=0 leaves them unpinned",
            allowed_cpus()
        ),
    }
    if aa_mode() {
        println!(
            "MCCL_RT_BENCH_AA: every engine chunk is a second reference chunk; the ratios below compare the reference with itself"
        );
    }
    // The per-CPU histograms, made here so that no engine thread allocates them.
    by_cpu();
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
        for period in [1u16, 2] {
            for loaded in [false, true] {
                let name = format!(
                    "{}-{period}ms-{}",
                    if fifo { "fifo" } else { "other" },
                    if loaded { "load" } else { "idle" }
                );
                if filter.is_empty() || filter.iter().any(|f| name.contains(f.as_str())) {
                    case(policy, period, loaded);
                }
            }
        }
    }
}
