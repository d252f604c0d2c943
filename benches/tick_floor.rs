//! `cargo bench --bench tick_floor`: the engine's cost per tick against the arithmetic a
//! tick fundamentally needs, measured in one run so the ratio holds on any
//! machine.
//!
//! * **engine**: the fast clock running `groups` groups of [`AXES_PER_GROUP`] axes, all
//!   moving along a line, per tick of `MCC_TimeDelay`: the engine thread's CPU time (its
//!   CPU-time clock) and wall time; also with a snapshot published every tick, as under
//!   the realtime clock. Each group has channels of its own (the vendor's library lets no
//!   two groups share one): 48 groups of 2 axes fill 12 cards.
//! * **floor**: the crate's own planner on the same lines, computing what a program reads
//!   of a group each period (its 8 positions and speeds, its feed speed, its channels'
//!   pulses) as the engine computes it, results kept live: the calling thread's CPU time
//!   and wall time (see [`floor_tick_us`]).
//!
//! Engine and floor alternate over [`ROUNDS`] short rounds. The headline ratios are the
//! medians of each round's own ratio (engine over the floor measured next to it, the
//! engine publishing over the engine not publishing): this VM's host runs the same code
//! at speeds up to 2x apart for tens of milliseconds at a time, and a ratio of two
//! measurements taken a millisecond apart cancels that. The medians of the costs
//! themselves are printed too.

#[path = "support/engine_thread.rs"]
mod engine_thread;

use engine_thread::{cpu_clock_ns, engine_cpu_clock, thread_cpu_ns};
use std::hint::black_box;
use std::time::Instant;
use MCCLPCI_IMP::engine::snapshot::whole_pulses;
use MCCLPCI_IMP::ffi::motion::{MCC_Line, MCC_SetFeedSpeed};
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::MCC_TimeDelay;
use MCCLPCI_IMP::planner::{Path, PathMove, Shape};
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::SYS_CARD_CONFIG;

/// Group-ticks a round's engine measurement runs (1 ms ticks): 2,000 ticks of 48 groups,
/// [`MAX_ROUND_TICKS`] of 1 group (see [`round_ticks`]).
const ROUND_GROUP_TICKS: u32 = 96_000;
/// The most ticks a round runs: the rounds of 1 group, 2 × 31 × 20,000 ticks, stay
/// within the line.
const MAX_ROUND_TICKS: u32 = 20_000;
/// Alternating rounds: each measures the engine, the floor and the engine publishing.
const ROUNDS: u32 = 31;
/// Line length per axis (UU) and feed (UU/s): X and Y compose the path, 10000·√2 UU at
/// 10 UU/s, about 1414 s (1,414,213 ticks; the rounds of 1 group run 1,242,400 and the
/// profile mode 150,400), so the groups cruise through every measurement.
const LEN: f64 = 10_000.0;
const FEED: f64 = 10.0;
/// Ticks of the profile mode (`MCCL_TICK_FLOOR_PROFILE`).
const PROFILE_TICKS: u32 = 150_000;
/// Pulses per UU of every channel (the default mechanism parameters).
const PULSES_PER_UU: f64 = 1000.0;
/// Axes of every group: 48 groups of their own channels fit 12 cards of 8 channels.
const AXES_PER_GROUP: usize = 2;
/// Groups per card.
const GROUPS_PER_CARD: u16 = (8 / AXES_PER_GROUP) as u16;

/// Starts `groups` groups ([`GROUPS_PER_CARD`] per card, each on channels of its own) on
/// the fast clock, each moving along the same line of [`AXES_PER_GROUP`] axes.
fn start(groups: u16) {
    std::env::set_var("MCCL_CLOCK", "fast");
    MCC_CloseSystem();
    assert_eq!(MCC_CloseAllGroups(), NO_ERR);
    let cards = groups.div_ceil(GROUPS_PER_CARD);
    for g in 0..groups {
        let first = i32::from(g % GROUPS_PER_CARD) * AXES_PER_GROUP as i32;
        let mut map = [-1; 8];
        for (a, m) in map.iter_mut().take(AXES_PER_GROUP).enumerate() {
            *m = first + a as i32;
        }
        assert_eq!(
            MCC_CreateGroup(
                map[0],
                map[1],
                map[2],
                map[3],
                map[4],
                map[5],
                map[6],
                map[7],
                i32::from(g / GROUPS_PER_CARD)
            ),
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
    assert_eq!(
        // SAFETY: `cards` valid card descriptions.
        unsafe { MCC_InitSystem(1, cfg.as_mut_ptr(), cards) },
        NO_ERR
    );
    for g in 0..groups {
        MCC_SetFeedSpeed(FEED, g);
        let mask = (1 << AXES_PER_GROUP) - 1;
        assert!(MCC_Line(LEN, LEN, LEN, LEN, LEN, LEN, LEN, LEN, g, mask) >= 0);
    }
    MCC_TimeDelay(400); // past the acceleration: the groups cruise from here on
}

/// Engine time per tick, µs, with or without a snapshot published every tick: (wall,
/// CPU time of the engine thread, read on its clock `engine`).
/// Ticks per engine measurement of `groups` groups, the floor's the same.
///
/// Every call of `MCC_TimeDelay` costs the engine a fixed amount besides its ticks (its
/// thread woken, the run's end published, the program woken; measured by
/// [`call_cost_us`], about 5.5 µs of engine CPU time on this VM), which 2,000 ticks of 1
/// group (about 0.2 ms) would carry as 3 % of the tick: a round of 1 group runs
/// 20,000 ticks, and the call's cost is printed on its own. At 48 groups 2,000 ticks
/// carry it as 0.2 %, and a longer round would run the host's speed changes into it.
fn round_ticks(groups: u16) -> u32 {
    (ROUND_GROUP_TICKS / u32::from(groups.max(1))).min(MAX_ROUND_TICKS)
}

fn engine_tick_us(live: bool, engine: libc::clockid_t, ticks: u32) -> (f64, f64) {
    let shared = MCCLPCI_IMP::system::active().expect("running system");
    shared.publish_every_tick(live);
    let c = cpu_clock_ns(engine);
    let t = Instant::now();
    MCC_TimeDelay(ticks);
    let us = t.elapsed().as_secs_f64() / f64::from(ticks) * 1e6;
    let cpu = (cpu_clock_ns(engine) - c) as f64 / f64::from(ticks) / 1e3;
    shared.publish_every_tick(false);
    (us, cpu)
}

/// Floor time per tick, µs: what one period of `groups` moving groups must compute for
/// what a program reads of them (`MCC_GetCurPos`, `MCC_GetSpeed` and
/// `MCC_GetCurFeedSpeed` of all 8 axes, `MCC_GetPulsePos` of the [`AXES_PER_GROUP`]
/// channels), as the engine computes it: the fraction of the path covered after `k`
/// periods (`TickProfile::fraction`), the 8 positions on the path (`Path::point_at`),
/// the 8 speeds from the last period's positions, the feed speed over X, Y, Z, and the
/// channels' whole pulses: (wall, CPU time of this thread). `k0` is the period the rounds
/// start at.
fn floor_tick_us(groups: usize, k0: u64, ticks: u32) -> (f64, f64) {
    let start = [0.0; 8];
    let mut end = [0.0; 8];
    end[..AXES_PER_GROUP].fill(LEN);
    let moves: Vec<PathMove> = (0..groups)
        .map(|_| {
            PathMove::new(
                Path::line(&start, &end),
                FEED,
                (300, 300),
                (Shape::T, Shape::T),
                1e-3,
            )
        })
        .collect();
    let mut pos = vec![[0.0; 8]; groups];
    let mut vel = [0.0; 8];
    let mut feed = 0.0;
    let mut pulses = vec![[0i64; AXES_PER_GROUP]; groups];
    let c = thread_cpu_ns();
    let t = Instant::now();
    for k in 0..ticks {
        let kk = black_box(k0 + u64::from(k));
        for ((m, p), out) in moves.iter().zip(pos.iter_mut()).zip(pulses.iter_mut()) {
            let x = m.path.point_at(m.profile.fraction(kk));
            for ((v, q), xi) in vel.iter_mut().zip(p.iter_mut()).zip(x) {
                *v = (xi - *q) / 1e-3;
                *q = xi;
            }
            feed = (vel[0] * vel[0] + vel[1] * vel[1] + vel[2] * vel[2]).sqrt();
            for (o, xi) in out.iter_mut().zip(x) {
                *o = whole_pulses(xi * PULSES_PER_UU);
            }
        }
        black_box(&mut pulses);
        black_box(&vel);
        black_box(feed);
    }
    let wall = t.elapsed().as_secs_f64() / f64::from(ticks) * 1e6;
    let cpu = (thread_cpu_ns() - c) as f64 / f64::from(ticks) / 1e3;
    (wall, cpu)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

/// One round: µs per tick of the engine, the engine publishing every tick, and the
/// floor.
#[derive(Debug, Clone, Copy)]
struct Round {
    engine: f64,
    publishing: f64,
    floor: f64,
}

/// What the rounds of `groups` groups gave, one way of timing (wall or CPU).
#[derive(Debug, Clone)]
struct Rounds(Vec<Round>);

impl Rounds {
    /// The median of `f` over the rounds.
    fn median(&self, f: impl Fn(&Round) -> f64) -> f64 {
        median(self.0.iter().map(f).collect())
    }

    /// Median engine/floor ratio of the rounds.
    fn ratio(&self) -> f64 {
        self.median(|r| r.engine / r.floor)
    }

    /// Median (engine publishing)/floor ratio of the rounds.
    fn ratio_publishing(&self) -> f64 {
        self.median(|r| r.publishing / r.floor)
    }

    /// Median of what publishing every tick adds to the engine's tick, %.
    fn publishing_adds(&self) -> f64 {
        self.median(|r| (r.publishing / r.engine - 1.0) * 100.0)
    }
}

/// Engine CPU time of one call of `MCC_TimeDelay(1)`, µs (median of 31 batches of 200
/// calls): one tick and what every call costs besides its ticks.
fn call_cost_us(engine: libc::clockid_t) -> f64 {
    const CALLS: u32 = 200;
    median(
        (0..ROUNDS)
            .map(|_| {
                let c = cpu_clock_ns(engine);
                for _ in 0..CALLS {
                    MCC_TimeDelay(1);
                }
                (cpu_clock_ns(engine) - c) as f64 / f64::from(CALLS) / 1e3
            })
            .collect(),
    )
}

/// What the rounds of some groups gave.
struct Measured {
    /// Timed by wall time.
    wall: Rounds,
    /// Timed by the CPU time of the thread that runs it.
    cpu: Rounds,
    /// [`call_cost_us`] with the groups moving.
    call_us: f64,
}

/// The rounds of `groups` groups.
fn measure(groups: u16) -> Measured {
    let (mut wall, mut cpu) = (Vec::new(), Vec::new());
    start(groups);
    let engine = engine_cpu_clock();
    let ticks = round_ticks(groups);
    for round in 0..ROUNDS {
        let (we, ce) = engine_tick_us(false, engine, ticks);
        let (wf, cf) = floor_tick_us(usize::from(groups), 1000 + u64::from(round) * 1000, ticks);
        let (wp, cp) = engine_tick_us(true, engine, ticks);
        wall.push(Round {
            engine: we,
            publishing: wp,
            floor: wf,
        });
        cpu.push(Round {
            engine: ce,
            publishing: cp,
            floor: cf,
        });
    }
    let call_us = call_cost_us(engine);
    assert!(
        (0..groups).all(|g| MCCLPCI_IMP::ffi::status::MCC_GetMotionStatus(g) == GMS_RUNNING),
        "every group still moving during the measurement"
    );
    MCC_CloseSystem();
    Measured {
        wall: Rounds(wall),
        cpu: Rounds(cpu),
        call_us,
    }
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
    shared.publish_every_tick(live);
    let t = Instant::now();
    let cruised = shared.cruise_ticks();
    MCC_TimeDelay(PROFILE_TICKS);
    let us = t.elapsed().as_secs_f64() / f64::from(PROFILE_TICKS) * 1e6;
    let cruised = shared.cruise_ticks() - cruised;
    MCC_CloseSystem();
    println!(
        "profile: {groups} groups, live {live}: engine {us:.3} us per tick, {cruised} of {PROFILE_TICKS} ticks cruise ticks"
    );
}

fn main() {
    if let Ok(spec) = std::env::var("MCCL_TICK_FLOOR_PROFILE") {
        return profile(&spec);
    }
    let m48 = measure(48);
    let m1 = measure(1);
    let (cpu48, cpu1) = (&m48.cpu, &m1.cpu);
    println!(
        "tick cost, CPU time of the thread that runs it (medians of {ROUNDS} alternating rounds of {} ticks at 48 groups, {} at 1 group):",
        round_ticks(48),
        round_ticks(1)
    );
    for (name, r) in [("48 groups", cpu48), ("1 group  ", cpu1)] {
        println!(
            "  {name}: engine {:.3} us, publishing every tick {:.3} us, floor {:.4} us",
            r.median(|r| r.engine),
            r.median(|r| r.publishing),
            r.median(|r| r.floor),
        );
    }
    println!(
        "engine/floor ratio: 48 groups {:.2}, 1 group {:.2} (targets <= 1.5, <= 3; medians of the rounds' ratios)",
        cpu48.ratio(),
        cpu1.ratio()
    );
    println!(
        "engine/floor ratio publishing every tick: 48 groups {:.2}, 1 group {:.2} (publishing adds {:.0} %, {:.0} %; target <= 30 %)",
        cpu48.ratio_publishing(),
        cpu1.ratio_publishing(),
        cpu48.publishing_adds(),
        cpu1.publishing_adds()
    );
    println!(
        "wall time: engine/floor 48 groups {:.2}, 1 group {:.2}; publishing {:.2}, {:.2}",
        m48.wall.ratio(),
        m1.wall.ratio(),
        m48.wall.ratio_publishing(),
        m1.wall.ratio_publishing()
    );
    println!(
        "one call of MCC_TimeDelay(1), 1 group moving: {:.2} us of engine CPU time (the tick and what every call costs besides its ticks; for information)",
        m1.call_us
    );
    println!(
        "fast clock: {:.0}x real time at 48 groups, {:.0}x at 1 group (1 ms ticks, wall time; for information)",
        1e3 / m48.wall.median(|r| r.engine),
        1e3 / m1.wall.median(|r| r.engine)
    );
}
