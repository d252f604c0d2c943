//! Cruise ticks (`src/engine/cruise.rs`) change nothing a program can see: the same
//! programs run with them (the default) and without (`MCCL_CRUISE=0`) read the same
//! positions, pulses, encoder counts, index statuses, statuses and command counts after
//! every `MCC_TimeDelay`, to the bit, on the fast and the stepped clock.
//!
//! The program: two cards; group A on card 0 runs lines and an arc with blending, its
//! feed overridden to 50 % and back while it moves; group B on six channels of card 1
//! runs point-to-point moves and a delay, with a dry run in the middle; group C, created
//! first on card 1, stands idle (a group of no axis: a channel belongs to one group
//! only); card 1's last two channels belong to no group (cruise ticks pass over them);
//! 500 pulses a UU and an index pulse every 500 (the defaults), so that the deferred
//! steps pass many. Two channels' motors lag (50 ms and 20 ms), so that where they are
//! depends on every command of every tick, not only on the last ones: a tick's command
//! lost or changed shows. The delays are of
//! 1, 2, 3, 5, ... ticks (runs shorter than, as long as and longer than a cruise plan),
//! then long ones until every group has stopped.
mod common;

use common::{cards, fresh};
use std::os::raw::c_long;
use MCCLPCI_IMP::ffi::coordinate::*;
use MCCLPCI_IMP::ffi::encoder::{MCC_GetENCIndexStatus, MCC_GetENCValue};
use MCCLPCI_IMP::ffi::motion::*;
use MCCLPCI_IMP::ffi::sim::MCCL_SimGetMotor;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;

/// What the program reads after each delay: per group its position (bits), pulses,
/// status and commands left; per channel of both cards the encoder count, the index
/// status and the motor (position bits and pulses output).
#[derive(Debug, PartialEq)]
struct Seen {
    tick: u64,
    groups: Vec<([u64; 8], [c_long; 8], i32, i32)>,
    channels: Vec<(c_long, u16, u64, i64)>,
}

/// The simulated machine: the lagging motors.
const SIM: &str = "
[[card]]
index = 0
[[card.channel]]
index = 2
plant = { lag_ms = 50.0 }
[[card]]
index = 1
[[card.channel]]
index = 1
plant = { lag_ms = 20.0 }
";

fn look(groups: &[u16]) -> Seen {
    let shared = MCCLPCI_IMP::system::active().expect("running");
    let groups = groups
        .iter()
        .map(|&g| {
            let mut p = [0.0; 8];
            let [a, b, c, d, e, f, h, i] = &mut p;
            // SAFETY: eight valid pointers.
            assert_eq!(unsafe { MCC_GetCurPos(a, b, c, d, e, f, h, i, g) }, NO_ERR);
            let mut q = [0 as c_long; 8];
            let [a, b, c, d, e, f, h, i] = &mut q;
            assert_eq!(
                // SAFETY: eight valid pointers.
                unsafe { MCC_GetPulsePos(a, b, c, d, e, f, h, i, g) },
                NO_ERR
            );
            let mut n = 0i32;
            // SAFETY: a valid pointer.
            assert_eq!(unsafe { MCC_GetCommandCount(&mut n, g) }, NO_ERR);
            (p.map(f64::to_bits), q, MCC_GetMotionStatus(g), n)
        })
        .collect();
    let channels = (0..2u16)
        .flat_map(|card| (0..8u16).map(move |ch| (card, ch)))
        .map(|(card, ch)| {
            let (mut e, mut s, mut m, mut n) = (0 as c_long, 0u16, 0.0, 0);
            // SAFETY: valid pointers.
            unsafe {
                assert_eq!(MCC_GetENCValue(&mut e, ch, card), NO_ERR);
                assert_eq!(MCC_GetENCIndexStatus(&mut s, ch, card), NO_ERR);
                assert_eq!(MCCL_SimGetMotor(card, ch, &mut m, &mut n), NO_ERR);
            }
            (e, s, m.to_bits(), n)
        })
        .collect();
    Seen {
        tick: shared.clock().ticks(),
        groups,
        channels,
    }
}

/// Runs the program on `clock` with cruise ticks on or off; returns what it read after
/// every delay and how many ticks were cruise ticks.
fn run(clock: &str, cruise: bool) -> (Vec<Seen>, u64) {
    let _g = fresh();
    std::env::set_var("MCCL_CLOCK", clock);
    std::env::set_var("MCCL_CRUISE", if cruise { "1" } else { "0" });
    let sim = std::env::temp_dir().join(format!("mccl-cruise-{}.toml", std::process::id()));
    std::fs::write(&sim, SIM).expect("a temporary file");
    std::env::set_var("MCCL_SIM", &sim);
    let c = MCC_CreateGroup(-1, -1, -1, -1, -1, -1, -1, -1, 1) as u16;
    let a = MCC_CreateGroup(0, 1, 2, 3, 4, 5, 6, 7, 0) as u16;
    let b = MCC_CreateGroup(0, 1, 2, 3, 4, 5, -1, -1, 1) as u16;
    let mut cfg = cards(2);
    // SAFETY: two valid card descriptions.
    assert_eq!(unsafe { MCC_InitSystem(1, cfg.as_mut_ptr(), 2) }, NO_ERR);
    let groups = [a, b, c];
    MCC_SetFeedSpeed(20.0, a);
    MCC_SetAccTime(50.0, a);
    MCC_SetDecTime(50.0, a);
    MCC_EnableBlend(a);
    assert!(MCC_Line(10.0, 5.0, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0, a, IMP_AXIS_ALL) >= 0);
    assert!(MCC_Line(20.0, -5.0, 2.0, 1.0, 0.0, 0.0, 0.0, 0.0, a, IMP_AXIS_ALL) >= 0);
    assert!(MCC_ArcXY(25.0, 0.0, 20.0, 5.0, a) >= 0);
    MCC_SetPtPSpeed(10.0, b);
    assert!(MCC_PtP(3.0, -2.0, 1.0, 0.5, 4.0, 0.0, -1.0, 2.0, b, IMP_AXIS_ALL) >= 0);
    assert!(MCC_DelayMotion(120, b) >= 0);
    assert!(MCC_PtP(-1.0, 2.0, 0.0, 0.0, 0.0, 3.0, 1.0, 0.0, b, IMP_AXIS_ALL) >= 0);
    let mut seen = vec![look(&groups)];
    let (mut x, mut y) = (1u32, 1u32);
    for step in 0.. {
        MCC_TimeDelay(x);
        (x, y) = (y, x + y);
        match step {
            6 => {
                MCC_OverrideSpeed(50.0, a);
            }
            9 => {
                MCC_OverrideSpeed(100.0, a);
                MCC_EnableDryRun();
            }
            11 => {
                MCC_DisableDryRun();
            }
            _ => {}
        }
        seen.push(look(&groups));
        let moving = groups.iter().any(|&g| MCC_GetMotionStatus(g) != GMS_STOP);
        if !moving && step > 12 {
            break;
        }
        assert!(step < 40, "the program ends");
    }
    let shared = MCCLPCI_IMP::system::active().expect("running");
    let cruised = shared.cruise_ticks();
    MCC_CloseSystem();
    std::env::remove_var("MCCL_CRUISE");
    std::env::remove_var("MCCL_SIM");
    let _ = std::fs::remove_file(&sim);
    (seen, cruised)
}

#[test]
fn a_program_reads_the_same_with_cruise_ticks_and_without() {
    for clock in ["fast", "stepped"] {
        let (full, none) = run(clock, false);
        let (cruising, cruised) = run(clock, true);
        assert_eq!(none, 0, "{clock}: MCCL_CRUISE=0 runs no cruise tick");
        assert_eq!(full.len(), cruising.len(), "{clock}");
        for (k, (f, c)) in full.iter().zip(&cruising).enumerate() {
            assert_eq!(f, c, "{clock}: after delay {k}");
        }
        let ticks = cruising.last().map_or(0, |s| s.tick);
        // Most ticks cruise: the groups move along most of the time.
        assert!(
            cruised > ticks / 2,
            "{clock}: {cruised} of {ticks} ticks cruised"
        );
        // The program covered what it is meant to: moves, index pulses, a stop.
        let last = cruising.last().expect("seen");
        assert!(last.groups.iter().all(|g| g.2 == GMS_STOP), "{clock}");
        assert!(
            cruising.iter().any(|s| s.channels.iter().any(|c| c.1 != 0)),
            "{clock}: index pulses passed"
        );
    }
}

/// An observer looking (the browser panel wants views) while every tick publishes
/// (callbacks registered, `live_snapshots`) still leaves the ticks between its copies
/// cruise ticks: a view is copied at most every `VIEW_EVERY_NS` (20 ms) of real time and
/// at the last tick of a run, and only the tick that copies one needs its channels up to
/// date.
///
/// One group runs a line of 100 UU at 10 UU/s (10 s), past its acceleration (300 ms by
/// default) before the watched runs of 2,000 ticks start, so every tick of them is in the
/// middle of one command. Without an observer 1,998 of them cruise: the run's first tick
/// takes the locks and the last publishes everything; both are full ticks. With one,
/// each copy takes the tick that copies out of the cruise ticks, and the plan after it
/// may begin a tick late: at most 3 ticks a copy. Over `ms` of real time at most
/// `ms / 20 + 1` copies fall due besides the last tick's. So at least
/// `1998 - 3 * (ms / 20 + 1)` cruise. (Before a tick asked whether a copy is due rather
/// than whether an observer looks, it made every tick a full one: 0 cruise ticks.) The
/// last copy shows the channels where the program's pulse positions say they are.
#[test]
fn an_observer_looking_leaves_the_ticks_between_its_copies_cruising() {
    let _g = fresh();
    std::env::set_var("MCCL_CLOCK", "fast");
    std::env::remove_var("MCCL_CRUISE");
    let g = MCC_CreateGroup(0, 1, 2, 3, 4, 5, 6, 7, 0) as u16;
    let mut cfg = cards(1);
    // SAFETY: one valid card description.
    assert_eq!(unsafe { MCC_InitSystem(1, cfg.as_mut_ptr(), 1) }, NO_ERR);
    MCC_SetFeedSpeed(10.0, g);
    assert!(MCC_Line(100.0, 50.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, g, IMP_AXIS_ALL) >= 0);
    MCC_TimeDelay(400);
    let shared = MCCLPCI_IMP::system::active().expect("running");
    shared.publish_every_tick(true);
    // Cruise ticks in 2,000 ticks, and the real time they took, ms.
    let watch = || {
        let before = shared.cruise_ticks();
        let t = std::time::Instant::now();
        MCC_TimeDelay(2000);
        (
            shared.cruise_ticks() - before,
            t.elapsed().as_millis() as u64,
        )
    };
    let (alone, _) = watch();
    assert_eq!(alone, 1998, "without an observer");
    shared.view().want(true);
    let (cruised, ms) = watch();
    let least = 1998u64.saturating_sub(3 * (ms / 20 + 1));
    assert!(
        cruised >= least,
        "{cruised} of 2000 ticks cruised in {ms} ms with an observer (at least {least})"
    );
    let view = shared.view().get();
    assert!(view.made, "the run's last tick copied a view");
    let mut q = [0 as c_long; 8];
    let [a, b, c, d, e, f, h, i] = &mut q;
    assert_eq!(
        // SAFETY: eight valid pointers.
        unsafe { MCC_GetPulsePos(a, b, c, d, e, f, h, i, g) },
        NO_ERR
    );
    let shown: Vec<i64> = view.cards[0].channels.iter().map(|c| c.pulses).collect();
    #[allow(clippy::useless_conversion)] // `long` is 32-bit on Windows
    let read: Vec<i64> = q.iter().map(|&p| i64::from(p)).collect();
    assert_eq!(shown, read, "the view shows the pulses the program reads");
    // 4.4 s at 10 UU/s less half the 0.3 s acceleration: 42.5 UU along the line, whose
    // x is 2/sqrt(5) of it: 38.01 UU, 19,006 pulses (500 a UU), y half that. A tick moves
    // x by 4.5 pulses: within two ticks.
    assert!((read[0] - 19_006).abs() <= 9, "the group moved: {read:?}");
    assert!(
        (read[0] - 2 * read[1]).abs() <= 1,
        "along the line: {read:?}"
    );
    shared.view().want(false);
    MCC_CloseSystem();
}
