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
/// Line length per axis (UU) and feed (UU/s): 1000·√8 UU at 10 UU/s, about 283 s.
const LEN: f64 = 1000.0;
const FEED: f64 = 10.0;
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

/// Engine wall time per tick, µs, with or without a snapshot published every tick.
fn engine_tick_us(live: bool) -> f64 {
    let shared = MCCLPCI_IMP::system::active().expect("running system");
    shared
        .live_snapshots
        .store(live, std::sync::atomic::Ordering::Relaxed);
    let t = Instant::now();
    MCC_TimeDelay(TICKS);
    let us = t.elapsed().as_secs_f64() / f64::from(TICKS) * 1e6;
    shared
        .live_snapshots
        .store(false, std::sync::atomic::Ordering::Relaxed);
    us
}

/// Floor wall time per tick, µs: `groups` moves of 8 axes sampled and rounded to pulses.
fn floor_tick_us(groups: usize, t0: f64) -> f64 {
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
    t.elapsed().as_secs_f64() / f64::from(TICKS) * 1e6
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

/// (engine, engine publishing every tick, floor), medians over 7 alternating rounds.
fn measure(groups: u16) -> (f64, f64, f64) {
    let (mut e, mut l, mut f) = (Vec::new(), Vec::new(), Vec::new());
    start(groups);
    for round in 0..7 {
        e.push(engine_tick_us(false));
        f.push(floor_tick_us(usize::from(groups), 1.0 + f64::from(round)));
        l.push(engine_tick_us(true));
    }
    assert!(
        (0..groups).all(|g| MCCLPCI_IMP::ffi::status::MCC_GetMotionStatus(g) == GMS_RUNNING),
        "every group still moving during the measurement"
    );
    MCC_CloseSystem();
    (median(&mut e), median(&mut l), median(&mut f))
}

/// `MCCL_TICK_FLOOR_PROFILE=<groups>[,live]`: only the engine, `groups` groups for
/// 200,000 ticks (with a snapshot published every tick with `,live`), to run under a
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
    MCC_TimeDelay(200_000);
    let us = t.elapsed().as_secs_f64() / 200_000.0 * 1e6;
    MCC_CloseSystem();
    println!("profile: {groups} groups, live {live}: engine {us:.3} us per tick");
}

fn main() {
    if let Ok(spec) = std::env::var("MCCL_TICK_FLOOR_PROFILE") {
        return profile(&spec);
    }
    let (e48, l48, f48) = measure(48);
    let (e1, l1, f1) = measure(1);
    println!("tick cost (median of 7 alternating rounds of {TICKS} ticks):");
    println!(
        "  48 groups x 8 axes: engine {e48:.2} us, publishing every tick {l48:.2} us (+{:.0} %), floor {f48:.3} us",
        (l48 / e48 - 1.0) * 100.0
    );
    println!(
        "  1 group x 8 axes:   engine {e1:.3} us, publishing every tick {l1:.3} us (+{:.0} %), floor {f1:.4} us",
        (l1 / e1 - 1.0) * 100.0
    );
    println!(
        "engine/floor ratio: 48 groups {:.2}, 1 group {:.2} (targets <= 1.5, <= 3)",
        e48 / f48,
        e1 / f1
    );
    println!(
        "engine/floor ratio publishing every tick: 48 groups {:.2}, 1 group {:.2} (publishing target: <= 30 % more than the engine)",
        l48 / f48,
        l1 / f1
    );
    println!(
        "fast clock: {:.0}x real time at 48 groups, {:.0}x at 1 group (1 ms ticks; for information)",
        1e3 / e48,
        1e3 / e1
    );
}
