//! A panic inside the library (a defect, injected here with `crate::fault`) returns
//! `RUN_TIME_ERR` and leaves a defined state: the interrupted group — or, from the engine
//! tick, every group — stops where it stands, drops its queue and records 0xF1FF.

use super::motion::*;
use super::status::*;
use super::system::*;
use super::tests::{fresh, init_ms};
use super::trajectory::*;
use crate::engine::safety::ERR_INTERNAL;
use crate::vendor::consts::*;
use std::time::Duration;

fn x(g: u16) -> f64 {
    crate::system::active().unwrap().snapshot(g).unwrap().pos[0]
}

fn line_x(x: f64) -> i32 {
    MCC_Line(x, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL)
}

/// Runs ticks one by one until group 0 stops; returns how many it took.
fn ticks_until_stop(limit: u64) -> u64 {
    let shared = crate::system::active().unwrap();
    let clock = shared.clock();
    let t0 = clock.ticks();
    while MCC_GetMotionStatus(0) != GMS_STOP {
        assert!(
            clock.ticks() - t0 < limit,
            "did not stop within {limit} ticks"
        );
    }
    clock.ticks() - t0
}

#[test]
fn a_panic_while_queueing_stops_the_group_with_a_record_and_the_next_move_is_exact() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    assert_eq!(MCC_SetAccTime(100.0, 0), NO_ERR);
    assert_eq!(MCC_SetDecTime(100.0, 0), NO_ERR);
    assert_eq!(line_x(2.0), 0);
    ticks_until_stop(5000);
    assert_eq!(x(0), 2.0);

    // The panic strikes after the queue's end moved to X=10 but before the command was
    // queued: without recovery the next move would be planned from X=10.
    crate::fault::arm("enqueue");
    assert_eq!(line_x(10.0), RUN_TIME_ERR);
    assert!(crate::fault::fired());
    assert_eq!(
        MCC_GetErrorCode(0),
        ERR_INTERNAL,
        "the group records the panic"
    );
    assert_eq!(MCC_GetMotionStatus(0), GMS_STOP);
    assert_eq!(x(0), 2.0, "it stands where it was");

    assert_eq!(MCC_ClearError(0), NO_ERR);
    assert_eq!(
        line_x(5.0),
        2,
        "the next command index follows the failed one"
    );
    // From X=2 to X=5: 3 UU at 10 UU/s with 100 ms ramps = 0.3 s + 0.1 s = 400 ticks
    // of motion, and the status reads STOP three periods after the last, as the
    // vendor's library shows it: 403. Planned from X=10 it would be 5 UU: 603 ticks.
    assert_eq!(ticks_until_stop(5000), 403);
    assert_eq!(x(0), 5.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

/// Group 0 moving along X on a 1 ms card, 300 ticks into a 10 UU line; fault `point`
/// armed, a delay of `ticks` on another thread (without recovery the engine thread dies
/// and the delay waits forever). Returns X before and where the group stopped, having
/// checked that it stopped with `ERR_INTERNAL` and stands.
fn stops_after_a_fault_at(point: &'static str, ticks: u32) -> (f64, f64) {
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    assert_eq!(line_x(10.0), 0);
    MCC_TimeDelay(300);
    let clock = crate::system::active().unwrap().clock().period();
    assert_eq!(clock, Duration::from_millis(1));
    let before = x(0);
    assert!(before > 0.0 && before < 10.0, "moving: X = {before}");

    crate::fault::arm(point);
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        MCC_TimeDelay(ticks);
        let _ = tx.send(());
    });
    assert!(
        rx.recv_timeout(Duration::from_secs(20)).is_ok(),
        "the engine still ticks after a panic at {point}"
    );
    assert!(crate::fault::fired());
    assert_eq!(MCC_GetErrorCode(0), ERR_INTERNAL);
    assert_eq!(MCC_GetMotionStatus(0), GMS_STOP);
    let stopped_at = x(0);
    MCC_TimeDelay(100);
    assert_eq!(x(0), stopped_at, "the group stands");
    (before, stopped_at)
}

#[test]
fn a_panic_in_the_engine_tick_stops_every_group_and_the_clock_goes_on() {
    let _g = fresh();
    let (before, stopped_at) = stops_after_a_fault_at("group tick", 10);
    assert!(stopped_at >= before && stopped_at < 10.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn a_panic_in_a_cruise_tick_stops_every_group_and_the_clock_goes_on() {
    // As above, in a tick of a quiet run that only moves the group along (a cruise tick,
    // `Shared::tick`'s cruise instance, the only place the point is passed): the run of 50 ticks
    // cruises from its second tick on.
    let _g = fresh();
    let (before, stopped_at) = stops_after_a_fault_at("cruise tick", 50);
    assert!(stopped_at > before && stopped_at < 10.0);
    // The channel was brought up to date: its encoder follows the group's pulses.
    let (mut enc, mut p) = (0, [0; 8]);
    let [a, b, c, d, e, f, g, h] = &mut p;
    // SAFETY: valid pointers.
    unsafe {
        assert_eq!(super::encoder::MCC_GetENCValue(&mut enc, 0, 0), NO_ERR);
        assert_eq!(
            super::coordinate::MCC_GetPulsePos(a, b, c, d, e, f, g, h, 0),
            NO_ERR
        );
    }
    assert_eq!(enc, p[0]);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
