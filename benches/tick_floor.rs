//! `cargo bench --bench tick_floor`: the engine's cost per tick against the arithmetic a
//! tick fundamentally needs (issue #18), measured in one run so the ratio holds on any
//! machine.
//!
//! * **engine**: the fast clock running `groups` groups of 8 axes, all moving along a
//!   line (as `benches/engine.rs` runs it), wall time per tick of `MCC_TimeDelay`;
//!   also with a snapshot published every tick, as under the realtime clock.
//! * **floor**: the crate's own planner sampling the same lines (`PathMove::sample_into`
//!   of 8 axes) and rounding every axis to pulses, per tick, results kept live.
//!
//! Engine and floor alternate over 7 rounds; the printed figures are the medians.

use std::hint::black_box;
use std::time::Instant;
use MCCLPCI_IMP::engine::snapshot::round_pulses;
use MCCLPCI_IMP::ffi::motion::{MCC_Line, MCC_SetFeedSpeed};
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::MCC_TimeDelay;
use MCCLPCI_IMP::planner::{Path, PathMove, Shape};
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::SYS_CARD_CONFIG;

/// Ticks per engine measurement (1 ms each, so the lines, 100 s long, never end).
const TICKS: u32 = 5_000;
/// Line length per axis (UU) and feed (UU/s): X, Y and Z compose the path, 1000·√3 UU at
/// 10 UU/s, about 173 s (173,000 ticks; a measurement runs about 105,000).
const LEN: f64 = 1000.0;
const FEED: f64 = 10.0;
/// Ticks of the profile mode (`MCCL_TICK_FLOOR_PROFILE`): the lines run 173,000.
const PROFILE_TICKS: u32 = 150_000;
/// Pulses per UU of every channel (the default mechanism parameters).
const PULSES_PER_UU: f64 = 1000.0;

/// Starts `groups` groups (8 per card, every group on all 8 channels of its card) on the
/// fast clock, each moving along the same 8-axis line.
fn start(groups: u16) {
    std::env::set_var("MCCL_CLOCK", "fast");
    MCC_CloseSystem();
    assert_eq!(MCC_CloseAllGroups(), NO_ERR);
    let cards = groups.div_ceil(8);
    for g in 0..groups {
        assert_eq!(
            MCC_CreateGroup(0, 1, 2, 3, 4, 5, 6, 7, i32::from(g / 8)),
            i32::from(g)
        );
    }
    let mut cfg = vec![
        SYS_CARD_CONFIG {
            wCardType: IMP_III_8_AXIS_PCI_CARD,
            ..Default::default()
        };
        usize::from(cards)
    ];
    // SAFETY: `cards` valid card descriptions.
    assert_eq!(
        unsafe { MCC_InitSystem(1, cfg.as_mut_ptr(), cards) },
        NO_ERR
    );
    for g in 0..groups {
        MCC_SetFeedSpeed(FEED, g);
        assert!(MCC_Line(LEN, LEN, LEN, LEN, LEN, LEN, LEN, LEN, g, IMP_AXIS_ALL) >= 0);
    }
    MCC_TimeDelay(400); // past the acceleration: the groups cruise from here on
}

/// CPU time the engine thread (named `mccl-engine`) has used, ns (`/proc` schedstat).
fn engine_cpu_ns() -> u64 {
    for e in std::fs::read_dir("/proc/self/task")
        .expect("/proc")
        .flatten()
    {
        let comm = std::fs::read_to_string(e.path().join("comm")).unwrap_or_default();
        if comm.trim() == "mccl-engine" {
            let st = std::fs::read_to_string(e.path().join("schedstat")).unwrap_or_default();
            return st
                .split(' ')
                .next()
                .and_then(|v| v.parse().ok())
                .unwrap_or(0);
        }
    }
    panic!("no mccl-engine thread")
}

/// CPU time the calling thread has used, ns.
fn thread_cpu_ns() -> u64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: a valid timespec to write; CLOCK_THREAD_CPUTIME_ID exists on Linux.
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    u64::try_from(ts.tv_sec).unwrap_or(0) * 1_000_000_000 + u64::try_from(ts.tv_nsec).unwrap_or(0)
}

/// Engine time per tick, µs, with or without a snapshot published every tick: (wall,
/// CPU time of the engine thread).
fn engine_tick_us(live: bool) -> (f64, f64) {
    let shared = MCCLPCI_IMP::system::active().expect("running system");
    shared
        .live_snapshots
        .store(live, std::sync::atomic::Ordering::Relaxed);
    let c = engine_cpu_ns();
    let t = Instant::now();
    MCC_TimeDelay(TICKS);
    let us = t.elapsed().as_secs_f64() / f64::from(TICKS) * 1e6;
    let cpu = (engine_cpu_ns() - c) as f64 / f64::from(TICKS) / 1e3;
    shared
        .live_snapshots
        .store(false, std::sync::atomic::Ordering::Relaxed);
    (us, cpu)
}

/// Floor time per tick, µs: `groups` moves of 8 axes sampled and rounded to pulses:
/// (wall, CPU time of this thread).
fn floor_tick_us(groups: usize, t0: f64) -> (f64, f64) {
    let start = [0.0; 8];
    let end = [LEN; 8];
    let moves: Vec<PathMove> = (0..groups)
        .map(|_| {
            PathMove::new(Path::line(&start, &end), FEED, 0.3, 0.3, Shape::T, Shape::T)
                .expect("a valid line")
        })
        .collect();
    let mut pos = [0.0; 8];
    let mut vel = [0.0; 8];
    let mut pulses = vec![[0i64; 8]; groups];
    let c = thread_cpu_ns();
    let t = Instant::now();
    for k in 0..TICKS {
        let tk = t0 + f64::from(k) * 1e-3;
        for (m, p) in moves.iter().zip(pulses.iter_mut()) {
            m.sample_into(black_box(tk), &mut pos, &mut vel);
            for (out, x) in p.iter_mut().zip(pos) {
                *out = round_pulses(x * PULSES_PER_UU);
            }
        }
        black_box(&mut pulses);
        black_box(&vel);
    }
    let wall = t.elapsed().as_secs_f64() / f64::from(TICKS) * 1e6;
    let cpu = (thread_cpu_ns() - c) as f64 / f64::from(TICKS) / 1e3;
    (wall, cpu)
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

/// Medians over 7 alternating rounds of one way of timing (wall or CPU), µs per tick.
#[derive(Debug, Clone, Copy)]
struct Costs {
    engine: f64,
    publishing: f64,
    floor: f64,
}

/// The costs of `groups` groups: (wall time, CPU time), medians over 7 alternating
/// rounds.
fn measure(groups: u16) -> (Costs, Costs) {
    let mut v: [Vec<f64>; 6] = Default::default();
    start(groups);
    for round in 0..7 {
        let (w, c) = engine_tick_us(false);
        v[0].push(w);
        v[3].push(c);
        let (w, c) = floor_tick_us(usize::from(groups), 1.0 + f64::from(round));
        v[2].push(w);
        v[5].push(c);
        let (w, c) = engine_tick_us(true);
        v[1].push(w);
        v[4].push(c);
    }
    assert!(
        (0..groups).all(|g| MCCLPCI_IMP::ffi::status::MCC_GetMotionStatus(g) == GMS_RUNNING),
        "every group still moving during the measurement"
    );
    MCC_CloseSystem();
    let [a, b, c, d, e, f] = v.map(|mut x| median(&mut x));
    (
        Costs {
            engine: a,
            publishing: b,
            floor: c,
        },
        Costs {
            engine: d,
            publishing: e,
            floor: f,
        },
    )
}

/// `MCCL_TICK_FLOOR_PROFILE=<groups>[,live]`: only the engine, `groups` groups for
/// 150,000 ticks (the lines still run) (with a snapshot published every tick with `,live`), to run under a
/// profiler (`perf record`); prints the time per tick.
fn profile(spec: &str) {
    let (n, live) = match spec.split_once(',') {
        Some((n, l)) => (n, l == "live"),
        None => (spec, false),
    };
    let groups: u16 = n
        .trim()
        .parse()
        .expect("MCCL_TICK_FLOOR_PROFILE=<groups>[,live]");
    start(groups);
    let shared = MCCLPCI_IMP::system::active().expect("running system");
    shared
        .live_snapshots
        .store(live, std::sync::atomic::Ordering::Relaxed);
    let t = Instant::now();
    MCC_TimeDelay(PROFILE_TICKS);
    let us = t.elapsed().as_secs_f64() / f64::from(PROFILE_TICKS) * 1e6;
    MCC_CloseSystem();
    println!("profile: {groups} groups, live {live}: engine {us:.3} us per tick");
}

fn main() {
    if let Ok(spec) = std::env::var("MCCL_TICK_FLOOR_PROFILE") {
        return profile(&spec);
    }
    let (wall48, cpu48) = measure(48);
    let (wall1, cpu1) = measure(1);
    println!("tick cost, CPU time of the thread that runs it (median of 7 alternating rounds of {TICKS} ticks):");
    for (name, c) in [("48 groups x 8 axes", cpu48), ("1 group x 8 axes  ", cpu1)] {
        println!(
            "  {name}: engine {:.3} us, publishing every tick {:.3} us (+{:.0} %), floor {:.4} us",
            c.engine,
            c.publishing,
            (c.publishing / c.engine - 1.0) * 100.0,
            c.floor
        );
    }
    println!(
        "engine/floor ratio: 48 groups {:.2}, 1 group {:.2} (targets <= 1.5, <= 3)",
        cpu48.engine / cpu48.floor,
        cpu1.engine / cpu1.floor
    );
    println!(
        "engine/floor ratio publishing every tick: 48 groups {:.2}, 1 group {:.2} (publishing adds {:.0} %, {:.0} %; target <= 30 %)",
        cpu48.publishing / cpu48.floor,
        cpu1.publishing / cpu1.floor,
        (cpu48.publishing / cpu48.engine - 1.0) * 100.0,
        (cpu1.publishing / cpu1.engine - 1.0) * 100.0
    );
    println!(
        "wall time: engine/floor 48 groups {:.2}, 1 group {:.2}; publishing {:.2}, {:.2}",
        wall48.engine / wall48.floor,
        wall1.engine / wall1.floor,
        wall48.publishing / wall48.floor,
        wall1.publishing / wall1.floor
    );
    println!(
        "fast clock: {:.0}x real time at 48 groups, {:.0}x at 1 group (1 ms ticks, wall time; for information)",
        1e3 / wall48.engine,
        1e3 / wall1.engine
    );
}
