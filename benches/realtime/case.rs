//! One case (a scheduling policy, a period, idle or loaded): its pairs of chunks in
//! blocks, and what is printed of them, the ratios last.

use crate::by_cpu::{by_cpu, by_cpu_since, print_by_cpu};
use crate::engine_chunk::{engine_chunk, ENGINE_ALLOC_SUM, ENGINE_TICKS};
use crate::load::start_load;
use crate::pinning::pair_cpu;
use crate::proc_sample::USE;
use crate::reference::reference_chunk;
use crate::stalls::{print_stalls, STALL_N};
use crate::{aa_mode, BLOCKS, CHUNK, PAIRS};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use MCCLPCI_IMP::clock::latency::LatencyHistogram;
use MCCLPCI_IMP::clock::monotonic_ns as mono_ns;

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

pub(crate) fn case(policy: &str, period_ms: u16, loaded: bool) {
    let stop = Arc::new(AtomicBool::new(false));
    let load = if loaded {
        start_load(&stop)
    } else {
        Vec::new()
    };
    let label = format!(
        "{policy}, period {period_ms} ms, {}",
        if loaded {
            format!("{} CPU-bound threads", load.len())
        } else {
            "idle".to_string()
        }
    );
    println!("{label}:");
    let period_ns = u64::from(period_ms) * 1_000_000;
    let ticks = u64::try_from(CHUNK.as_nanos()).unwrap_or(0) / period_ns;
    let reference_h = LatencyHistogram::new();
    let tick_h = LatencyHistogram::new();
    let isr_h = LatencyHistogram::new();
    let mut blocks = Vec::new();
    let mut missed = 0;
    let mut samples = Vec::with_capacity(PAIRS * 2 * 20);
    ENGINE_ALLOC_SUM.store(0, Ordering::Relaxed);
    ENGINE_TICKS.store(0, Ordering::Relaxed);
    STALL_N.store(0, Ordering::Relaxed);
    for u in USE.iter().flatten() {
        u.store(0, Ordering::Relaxed);
    }
    let case_start = mono_ns();
    let by_cpu_then: Vec<LatencyHistogram> = by_cpu().iter().map(|h| h.snapshot()).collect();
    for block in 0..BLOCKS {
        let r = Arc::new(LatencyHistogram::new());
        let t = LatencyHistogram::new();
        let i = Arc::new(LatencyHistogram::new());
        for pair in block * PAIRS / BLOCKS..(block + 1) * PAIRS / BLOCKS {
            if let Some(cpu) = pair_cpu(pair) {
                // Read by both kinds of thread when they are set up (the reference's
                // `setup_current_thread`, the engine's in `MCC_InitSystem`).
                std::env::set_var("MCCL_RT_CPU", cpu.to_string());
            }
            for engine_now in [pair % 2 == 1, pair % 2 == 0] {
                if engine_now && aa_mode() {
                    let a = Arc::new(LatencyHistogram::new());
                    reference_chunk(period_ns, ticks, &a, &mut samples, 1);
                    t.merge(&a);
                    i.merge(&a);
                } else if engine_now {
                    missed +=
                        engine_chunk(period_ms, ticks, &t, &i, &mut samples, pair + 1 == PAIRS);
                } else {
                    reference_chunk(period_ns, ticks, &r, &mut samples, 0);
                }
            }
        }
        let rp = r.quantile_us(0.99).max(1.0);
        blocks.push((t.quantile_us(0.99) / rp, i.quantile_us(0.99) / rp));
        reference_h.merge(&r);
        tick_h.merge(&t);
        isr_h.merge(&i);
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
        ENGINE_ALLOC_SUM.load(Ordering::Relaxed) as f64
            / ENGINE_TICKS.load(Ordering::Relaxed).max(1) as f64
    );
    let per_deadline = |k: usize| {
        let span = USE[k][2].load(Ordering::Relaxed).max(1) as f64 / period_ns as f64;
        format!(
            "CPU {:.1} us, run-queue wait {:.1} us",
            USE[k][0].load(Ordering::Relaxed) as f64 / span / 1e3,
            USE[k][1].load(Ordering::Relaxed) as f64 / span / 1e3
        )
    };
    println!(
        "  per period, the reference thread: {}; the {} thread: {}",
        per_deadline(0),
        if aa_mode() {
            "second reference"
        } else {
            "engine"
        },
        per_deadline(1)
    );
    println!(
        "  p99 ratio tick / interrupt in each block of the case (time order): {}",
        blocks
            .iter()
            .map(|(t, i)| format!("{t:.2}/{i:.2}"))
            .collect::<Vec<_>>()
            .join(" ")
    );
    print_stalls(case_start, &samples);
    print_by_cpu(&by_cpu_since(&by_cpu_then));
    // The median of the blocks' ratios: a single host stall (100 ms and more seen on
    // this VM: the host does not run the vCPU) is more than 1 % of a case's samples at
    // 1 ms and would set the pooled p99 of whichever kind of chunk it hit.
    let median = |f: fn(&(f64, f64)) -> f64| {
        let mut v: Vec<f64> = blocks.iter().map(f).collect();
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    // The stretches the median leaves out: blocks over the limits (in A/A runs about
    // one block in ten is over 1.5).
    println!(
        "  blocks over the limits: tick > 1.5 in {} of {BLOCKS}, interrupt > 2 in {} of {BLOCKS}",
        blocks.iter().filter(|b| b.0 > 1.5).count(),
        blocks.iter().filter(|b| b.1 > 2.0).count()
    );
    let rp = reference_h.quantile_us(0.99).max(1.0);
    println!(
        "realtime lateness ratio p99: tick {:.2}, interrupt {:.2} (median of {BLOCKS} blocks of interleaved chunks; all chunks pooled: {:.2}, {:.2}; {label}; reference p99 {:.0} us)",
        median(|b| b.0),
        median(|b| b.1),
        tick_h.quantile_us(0.99) / rp,
        isr_h.quantile_us(0.99) / rp,
        reference_h.quantile_us(0.99)
    );
}
