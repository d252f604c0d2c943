//! The core's `Card` and the library's engine run the same tick: a program through the C
//! ABI on the stepped clock and the same commands given to a `Card` read the same
//! positions (to the bit), pulses, statuses and channel outputs after every tick.
//!
//! The program: group 0 on channels 0 and 1 of one card, 1 ms ticks; three lines with
//! blending on, the feed overridden to 40 % and back while they run, then a hold and a
//! continue. The card is given the same commands at the same ticks, planned with
//! its group's context, as the C entry points plan them.
mod common;

use common::{fresh, init};
use mccl_core::config::{default_mac_param, GroupDef, AXES, CARDS};
use mccl_core::engine::card::Card;
use mccl_core::engine::command::Plan;
use mccl_core::machine::{ChannelSpec, Machine};
use mccl_core::vendor::SYS_ENCODER_CONFIG;
use std::os::raw::c_long;
use std::time::Duration;
use MCCLPCI_IMP::ffi::coordinate::*;
use MCCLPCI_IMP::ffi::motion::*;
use MCCLPCI_IMP::ffi::sim::MCCL_SimGetMotor;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;

/// What one tick shows: positions (bits), pulses, status, and the two channels' output.
#[derive(Debug, PartialEq)]
struct Seen {
    pos: [u64; 2],
    pulses: [i64; 2],
    status: i32,
    out: [i64; 2],
}

/// What the engine shows of group 0 and channels 0, 1 through the C ABI.
fn engine_seen() -> Seen {
    let mut p = [0.0; 8];
    let [a, b, c, d, e, f, h, i] = &mut p;
    // SAFETY: eight valid pointers.
    assert_eq!(unsafe { MCC_GetCurPos(a, b, c, d, e, f, h, i, 0) }, NO_ERR);
    let mut q = [0 as c_long; 8];
    let [a, b, c, d, e, f, h, i] = &mut q;
    assert_eq!(
        // SAFETY: eight valid pointers.
        unsafe { MCC_GetPulsePos(a, b, c, d, e, f, h, i, 0) },
        NO_ERR
    );
    let out = [0u16, 1].map(|ch| {
        let (mut m, mut n) = (0.0, 0);
        // SAFETY: valid pointers.
        assert_eq!(unsafe { MCCL_SimGetMotor(0, ch, &mut m, &mut n) }, NO_ERR);
        n
    });
    #[allow(clippy::useless_conversion)] // `long` is 32-bit on Windows
    Seen {
        pos: [p[0].to_bits(), p[1].to_bits()],
        pulses: [i64::from(q[0]), i64::from(q[1])],
        status: MCC_GetMotionStatus(0),
        out,
    }
}

/// What the card shows of its group 0 and channels 0, 1.
fn card_seen(card: &Card) -> Seen {
    let g = card.group(0).expect("group 0");
    let s = g.snapshot();
    let chan = |ch| card.machine().channel(0, ch).expect("a channel");
    Seen {
        pos: [s.pos[0].to_bits(), s.pos[1].to_bits()],
        pulses: [s.pulses[0], s.pulses[1]],
        status: s.status,
        out: [chan(0).output_pulses(), chan(1).output_pulses()],
    }
}

/// The card the engine runs: one card, group 0 on channels 0 and 1, the default
/// parameters and an ideal machine.
fn facade() -> Card {
    let mac = [[default_mac_param(); AXES]; CARDS];
    let enc = [[SYS_ENCODER_CONFIG::default(); AXES]; CARDS];
    let machine = Machine::new(&mac, &enc, |_, _| ChannelSpec::default(), |_| false, 1);
    // As MCC_CreateGroup(0, 1, -1, ..., 0) makes it.
    let xy = GroupDef::new([0, 1, -1, -1, -1, -1, -1, -1], 0, MOTION_QUEUE_SIZE).expect("a group");
    Card::new(machine, &[(0, xy)], &mac, Duration::from_millis(1))
}

/// A point of the XY plane as the group's eight axes.
fn xy(x: f64, y: f64) -> [f64; AXES] {
    let mut p = [0.0; AXES];
    p[0] = x;
    p[1] = y;
    p
}

#[test]
fn the_engine_and_the_card_show_the_same_every_tick() {
    let _g = fresh();
    assert_eq!(MCC_CreateGroup(0, 1, -1, -1, -1, -1, -1, -1, 0), 0);
    assert_eq!(init(1), NO_ERR);
    let mut card = facade();
    // The settings, on both.
    MCC_SetFeedSpeed(20.0, 0);
    MCC_SetAccTime(50.0, 0);
    MCC_SetDecTime(50.0, 0);
    MCC_EnableBlend(0);
    {
        let s = card.group_mut(0).expect("group 0").settings_mut();
        s.feed = 20.0;
        s.acc_ms = 50.0;
        s.dec_ms = 50.0;
    }
    card.queue(0, |c| Ok(c.marker(Plan::Blend(true))))
        .expect("blending on");
    for (x, y) in [(10.0, 5.0), (20.0, -5.0), (20.0, 5.0)] {
        assert!(MCC_Line(x, y, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL) >= 0);
        // As MCC_Line plans it: the target resolved with the group's context.
        card.queue(0, |c| c.line(c.resolve(&xy(x, y), 0xFF)))
            .expect("line");
    }
    assert_eq!(engine_seen(), card_seen(&card), "before the first tick");
    let mut ticks = 0;
    while ticks < 20_000 {
        match ticks {
            300 => {
                assert_eq!(MCC_OverrideSpeed(40.0, 0), 40.0);
                card.group_mut(0)
                    .expect("group 0")
                    .override_speed(40.0, true);
            }
            900 => {
                assert_eq!(MCC_OverrideSpeed(100.0, 0), 100.0);
                card.group_mut(0)
                    .expect("group 0")
                    .override_speed(100.0, true);
            }
            1200 => {
                assert_eq!(MCC_HoldMotion(0, 0), NO_ERR);
                card.group_mut(0)
                    .expect("group 0")
                    .hold(false)
                    .expect("hold");
            }
            1500 => {
                assert_eq!(MCC_ContiMotion(0), NO_ERR);
                card.group_mut(0)
                    .expect("group 0")
                    .conti()
                    .expect("continue");
            }
            _ => {}
        }
        MCC_TimeDelay(1);
        card.tick();
        ticks += 1;
        assert_eq!(engine_seen(), card_seen(&card), "tick {ticks}");
        if ticks > 1500 && MCC_GetMotionStatus(0) == GMS_STOP {
            break;
        }
    }
    assert!(
        ticks > 1500 && ticks < 20_000,
        "the program ends: {ticks} ticks"
    );
    assert_eq!(card.ticks(), ticks);
    // Where the last line ends.
    assert_eq!(
        card.group(0).expect("group 0").snapshot().pos[..2],
        [20.0, 5.0]
    );
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
