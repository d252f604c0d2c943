//! Motion through the C entry points on the stepped clock, against closed-form values
//! (docs/decisions.md: an unblended move of length L reaching feed F lasts L/F + (Ta+Td)/2).

mod common;

use common::{enc, fresh, init_ms};
use MCCLPCI_IMP::ffi::coordinate::*;
use MCCLPCI_IMP::ffi::motion::*;
use MCCLPCI_IMP::ffi::ptp::*;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::COMMAND_INFO;

fn pos(g: u16) -> [f64; 8] {
    let mut p = [0.0; 8];
    let [a, b, c, d, e, f, h, i] = &mut p;
    // SAFETY: eight valid pointers.
    let r = unsafe { MCC_GetCurPos(a, b, c, d, e, f, h, i, g) };
    assert_eq!(r, NO_ERR);
    p
}

fn pulses(g: u16) -> [i64; 8] {
    let mut p = [0 as std::os::raw::c_long; 8];
    let [a, b, c, d, e, f, h, i] = &mut p;
    // SAFETY: eight valid pointers.
    let r = unsafe { MCC_GetPulsePos(a, b, c, d, e, f, h, i, g) };
    assert_eq!(r, NO_ERR);
    p.map(i64::from)
}

/// Runs ticks one by one until the group stops; returns the number of ticks it took.
fn ticks_until_stop(g: u16, limit: u64) -> u64 {
    let clock = &MCCLPCI_IMP::system::active().unwrap().clock;
    let t0 = clock.ticks();
    while MCC_GetMotionStatus(g) != GMS_STOP {
        assert!(
            clock.ticks() - t0 < limit,
            "did not stop within {limit} ticks"
        );
    }
    clock.ticks() - t0
}

#[test]
fn line_lasts_l_over_f_plus_half_ramps_and_ends_exactly() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    assert_eq!(MCC_SetAccTime(100.0, 0), NO_ERR);
    assert_eq!(MCC_SetDecTime(100.0, 0), NO_ERR);
    assert_eq!(
        MCC_Line(10.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL),
        0
    );
    let st = MCCLPCI_IMP::system::active()
        .unwrap()
        .snapshot(0)
        .unwrap()
        .status;
    assert_ne!(st, GMS_STOP, "queued: no longer stopped");
    // 10 UU at 10 UU/s with 100 ms ramps: 1.0 s + (0.1 + 0.1)/2 = 1.1 s = 1100 ticks of 1 ms.
    // The first poll ran the first tick.
    let n = ticks_until_stop(0, 5000);
    assert_eq!(n, 1100, "took {n} ticks");
    assert_eq!(pos(0)[0], 10.0);
    assert_eq!(pulses(0)[0], 5000, "10 UU x 500 pulses/UU");
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

fn line(x: f64, y: f64, g: u16) -> i32 {
    MCC_Line(x, y, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, g, IMP_AXIS_ALL)
}

fn ramps(ms: f64, g: u16) {
    assert_eq!(MCC_SetAccTime(ms, g), NO_ERR);
    assert_eq!(MCC_SetDecTime(ms, g), NO_ERR);
}

/// The published status, without the stepped clock's tick-on-poll.
fn status(g: u16) -> i32 {
    MCCLPCI_IMP::system::active()
        .unwrap()
        .snapshot(g)
        .unwrap()
        .status
}

fn tick(n: u64) {
    MCCLPCI_IMP::system::active().unwrap().clock.wait_ticks(n);
}

fn path_speed(g: u16) -> f64 {
    MCC_GetCurFeedSpeed(g)
}

#[test]
fn queue_capacity_and_index() {
    let _g = fresh();
    assert_eq!(MCC_CreateGroup(0, 1, -1, -1, -1, -1, -1, -1, 0), 0);
    assert_eq!(MCC_CreateGroupEx(2, 3, -1, -1, -1, -1, -1, -1, 0, 50), 1);
    assert_eq!(init_ms(1, 1), NO_ERR);
    for i in 0..10_000 {
        assert_eq!(line(f64::from(i % 7), 0.0, 0), i);
    }
    assert_eq!(line(1.0, 0.0, 0), COMMAND_BUFFER_FULL_ERR);
    let mut n = -1;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetCommandCount(&mut n, 0) }, NO_ERR);
    assert_eq!(n, 10_000, "nothing started yet on the stepped clock");
    for i in 0..50 {
        assert_eq!(line(f64::from(i), 0.0, 1), i);
    }
    assert_eq!(line(1.0, 0.0, 1), COMMAND_BUFFER_FULL_ERR);
    assert_eq!(MCC_SetCmdQueueSize(60, 1), COMMAND_NOTFINISHED_ERR);
    assert_eq!(MCC_AbortMotion(1, 0), NO_ERR);
    assert_eq!(status(1), GMS_STOP);
    assert_eq!(MCC_SetCmdQueueSize(60, 1), NO_ERR);
    assert_eq!(MCC_ResetCommandIndex(1), NO_ERR);
    assert_eq!(line(1.0, 0.0, 1), 0, "index restarts from 0");
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn two_groups_run_concurrently_and_finish_independently() {
    let _g = fresh();
    assert_eq!(MCC_CreateGroup(0, 1, -1, -1, -1, -1, -1, -1, 0), 0);
    assert_eq!(MCC_CreateGroup(2, 3, -1, -1, -1, -1, -1, -1, 0), 1);
    assert_eq!(init_ms(1, 1), NO_ERR);
    for g in 0..2 {
        assert_eq!(MCC_SetFeedSpeed(10.0, g), 10.0);
        ramps(0.0, g);
    }
    assert_eq!(line(1.0, 0.0, 0), 0); // 100 ms
    assert_eq!(line(3.0, 0.0, 1), 0); // 300 ms
    tick(100);
    assert_eq!(status(0), GMS_STOP);
    assert_eq!(status(1), GMS_RUNNING);
    assert!((pos(1)[0] - 1.0).abs() < 1e-9, "group 1 went 1 UU as well");
    tick(200);
    assert_eq!(status(1), GMS_STOP);
    assert_eq!(pos(0)[0], 1.0);
    assert_eq!(pos(1)[0], 3.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn a_channel_two_groups_map_follows_the_later_group() {
    let _g = fresh();
    // Group 0: X on channel 0, Y on channel 1. Group 1: X on channel 1 as well.
    assert_eq!(MCC_CreateGroup(0, 1, -1, -1, -1, -1, -1, -1, 0), 0);
    assert_eq!(MCC_CreateGroup(1, -1, -1, -1, -1, -1, -1, -1, 0), 1);
    assert_eq!(init_ms(1, 1), NO_ERR);
    for g in 0..2 {
        assert_eq!(MCC_SetFeedSpeed(10.0, g), 10.0);
        ramps(0.0, g);
    }
    assert_eq!(line(1.0, 2.0, 0), 0); // √5 UU at 10 UU/s: 224 ms
    assert_eq!(line(3.0, 0.0, 1), 0); // 300 ms
    tick(400);
    assert_eq!((status(0), status(1)), (GMS_STOP, GMS_STOP));
    // Each group still moves its own axes to their ends: 500 pulses/UU (the default
    // mechanism), 2 UU of Y = 1000 pulses, 3 UU of X = 1500.
    assert_eq!(pulses(0)[..2], [500, 1000]);
    assert_eq!(pulses(1)[0], 1500);
    // The channels (the encoder counts a pulse each at x4, the default) follow the last
    // axis mapping them, in group order: channel 0 only group 0's X, channel 1 group 1's X
    // and not group 0's Y.
    assert_eq!(enc(0), 500);
    assert_eq!(enc(1), 1500);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn the_channels_follow_their_group_after_update_param() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    ramps(0.0, 0);
    assert_eq!(line(1.0, 0.0, 0), 0);
    tick(200);
    assert_eq!(enc(0), 500, "1 UU at 500 pulses/UU");
    // MCC_UpdateParam resets the group: its position and pulses restart from 0 while
    // the motor stays where it is (the encoder keeps counting it).
    assert_eq!(MCC_UpdateParam(), NO_ERR);
    assert_eq!((pos(0)[0], pulses(0)[0], enc(0)), (0.0, 0, 500));
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    ramps(0.0, 0);
    assert_eq!(line(2.0, 0.0, 0), 0); // 200 ms
    tick(300);
    assert_eq!(status(0), GMS_STOP);
    // 2 UU = 1000 pulses more, which the channel still receives after the reset.
    assert_eq!(pulses(0)[0], 1000);
    assert_eq!(enc(0), 1500);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn hold_continue_abort() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_HoldMotion(0, 0), HOLD_ILLEGAL_ERR);
    assert_eq!(MCC_ContiMotion(0), CONTI_ILLEGAL_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    ramps(100.0, 0);
    assert_eq!(line(10.0, 0.0, 0), 0);
    tick(500); // cruising at 10 UU/s
    assert!((path_speed(0) - 10.0).abs() < 1e-9);
    assert_eq!(MCC_HoldMotion(0, 0), NO_ERR);
    assert_eq!(status(0), GMS_HOLD);
    assert_eq!(MCC_HoldMotion(0, 0), HOLD_ILLEGAL_ERR, "already held");
    tick(100); // the hold ramp takes the dec time: 100 ms
    let held = pos(0)[0];
    assert_eq!(path_speed(0), 0.0);
    tick(1000);
    assert_eq!(pos(0)[0], held, "stands still while held");
    assert_eq!(status(0), GMS_HOLD);
    // The hold ramp covers half of the 100 ms at 10 UU/s: 0.5 UU past the hold point.
    // Hold at t = 0.5 s: s = 10 x (0.5 - 0.05) = 4.5; held at 4.5 + 0.5 = 5.0.
    assert!((held - 5.0).abs() < 1e-9, "held at {held}");
    assert_eq!(MCC_ContiMotion(0), NO_ERR);
    assert_eq!(status(0), GMS_RUNNING);
    ticks_until_stop(0, 5000);
    assert_eq!(pos(0)[0], 10.0, "the rest of the same command");

    // AbortMotionEx(t): stops within t, empties the queue, refuses motion meanwhile.
    assert_eq!(line(20.0, 0.0, 0), 1);
    assert_eq!(line(30.0, 0.0, 0), 2);
    tick(500);
    assert_eq!(MCC_AbortMotionEx(50.0, 0), NO_ERR);
    assert_eq!(line(0.0, 0.0, 0), ABORT_NOT_FINISH_ERR);
    tick(50);
    assert_eq!(status(0), GMS_STOP);
    let stop = pos(0)[0];
    // Abort at 5.0 + 4.5 = 14.5 UU at 10 UU/s, ramped to 0 over 50 ms: +0.25 UU.
    assert!((stop - 14.75).abs() < 1e-9, "stopped at {stop}");
    let mut n = -1;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetCommandCount(&mut n, 0) }, NO_ERR);
    assert_eq!(n, 0);
    // AbortMotion: at once.
    assert_eq!(line(20.0, 0.0, 0), 3);
    tick(300);
    let here = pos(0)[0];
    assert_eq!(MCC_AbortMotion(0, 0), NO_ERR);
    assert_eq!(status(0), GMS_STOP);
    tick(10);
    assert_eq!(pos(0)[0], here);
    assert_eq!(MCC_AbortMotionEx(f64::NAN, 0), PARAMETER_ERR);
    assert_eq!(MCC_AbortMotionEx(-1.0, 0), PARAMETER_ERR);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn delay_shows_delaying_for_its_duration() {
    let _g = fresh();
    assert_eq!(init_ms(1, 2), NO_ERR);
    assert_eq!(MCC_DelayMotion(200, 0), 0);
    assert_eq!(MCC_CheckDelay(0), 1, "queued, not started");
    tick(1);
    assert_eq!(status(0), GMS_DELAYING);
    assert_eq!(MCC_CheckDelay(0), 0);
    let mut info = COMMAND_INFO::default();
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetCurCommand(&mut info, 0) }, NO_ERR);
    assert_eq!((info.nType, info.nCommandIndex), (6, 0));
    assert!(
        (info.dfFeedSpeed - 198.0).abs() < 1e-9,
        "ms left: {}",
        info.dfFeedSpeed
    );
    tick(98); // 198 ms
    assert_eq!(status(0), GMS_DELAYING);
    tick(1); // 200 ms
    assert_eq!(status(0), GMS_STOP);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn blending_keeps_path_speed_through_the_join() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    ramps(100.0, 0);
    assert_eq!(MCC_CheckBlend(0), 1);
    assert_eq!(MCC_EnableBlend(0), 0);
    assert_eq!(MCC_CheckBlend(0), 0);
    assert_eq!(line(5.0, 0.0, 0), 1);
    assert_eq!(line(10.0, 0.0, 0), 2);
    // Collinear, equal feed and equal dec/acc time: cruise speed straight through.
    // Total time (5 + 5)/10 + (0.1 + 0.1)/2 = 1.1 s.
    let mut min_cruise = f64::MAX;
    for t in 1..=1100u64 {
        tick(1);
        if (150..=950).contains(&t) {
            min_cruise = min_cruise.min(path_speed(0));
        }
    }
    assert!(
        (min_cruise - 10.0).abs() < 1e-9,
        "speed dipped to {min_cruise}"
    );
    assert_eq!(status(0), GMS_STOP);
    assert_eq!(pos(0)[0], 10.0);

    // Without blending the first line stops at its end: 2 x (0.5 + 0.1) = 1.2 s.
    assert_eq!(MCC_DisableBlend(0), 3);
    assert_eq!(line(15.0, 0.0, 0), 4);
    assert_eq!(line(20.0, 0.0, 0), 5);
    // Near the join (t = 0.6 s) the speed falls to within one tick of acceleration
    // (100 UU/s^2 x 1 ms = 0.1 UU/s) of zero, at 15 UU.
    let mut slowest = (f64::MAX, 0.0);
    for _ in 0..1200 {
        tick(1);
        let v = path_speed(0);
        if v < slowest.0 && (pos(0)[0] - 15.0).abs() < 0.01 {
            slowest = (v, pos(0)[0]);
        }
    }
    assert!(slowest.0 <= 0.1 + 1e-9, "slowest near the join {slowest:?}");
    assert!((slowest.1 - 15.0).abs() < 1e-3);
    assert_eq!(status(0), GMS_STOP);
    assert_eq!(pos(0)[0], 20.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn override_scales_time_and_incremental_targets() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    ramps(100.0, 0);
    assert_eq!(MCC_OverrideSpeed(50.0, 0), 50.0);
    assert_eq!(MCC_GetOverrideRate(0), 50.0);
    assert_eq!(MCC_OverrideSpeed(0.0, 0), f64::from(PARAMETER_ERR));
    assert_eq!(MCC_OverrideSpeed(f64::NAN, 0), f64::from(PARAMETER_ERR));
    assert_eq!(MCC_GetOverrideRate(0), 50.0, "unchanged");
    assert_eq!(line(10.0, 0.0, 0), 0);
    // At 50 % everything takes twice as long: 2.2 s.
    assert_eq!(ticks_until_stop(0, 10_000), 2200);
    assert_eq!(MCC_OverrideSpeed(100.0, 0), 100.0);
    assert_eq!(MCC_SetIncrease(0), NO_ERR);
    assert_eq!(MCC_GetCoordType(0), 0);
    assert_eq!(line(-2.5, 1.0, 0), 1);
    assert_eq!(line(-2.5, 1.0, 0), 2);
    ticks_until_stop(0, 10_000);
    let p = pos(0);
    assert_eq!((p[0], p[1]), (5.0, 2.0));
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn arc_stays_on_its_circle_every_tick() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(20.0, 0), 20.0);
    assert_eq!(line(10.0, 0.0, 0), 0);
    ticks_until_stop(0, 10_000);
    // From (10, 0) through (0, 10) to (-10, 0): center (0, 0), R = 10, CCW.
    assert_eq!(MCC_ArcXY(0.0, 10.0, -10.0, 0.0, 0), 1);
    let mut worst: f64 = 0.0;
    loop {
        tick(1);
        let p = pos(0);
        worst = worst.max(((p[0] * p[0] + p[1] * p[1]).sqrt() - 10.0).abs());
        if status(0) == GMS_STOP {
            break;
        }
        let mut info = COMMAND_INFO::default();
        // SAFETY: valid pointer.
        unsafe { MCC_GetCurCommand(&mut info, 0) };
        assert_eq!(info.nType, 3, "counter-clockwise arc");
    }
    assert!(worst <= 1e-9 * 10.0, "radius error {worst}");
    let p = pos(0);
    assert!((p[0] + 10.0).abs() < 1e-9 && p[1].abs() < 1e-9);
    // Collinear points: PARAMETER_ERR, error record 0xF104, the queue waits for ClearError.
    assert_eq!(MCC_ArcXY(0.0, 0.0, 10.0, 0.0, 0), PARAMETER_ERR);
    assert_eq!(MCC_GetErrorCode(0), 0xF104);
    assert_eq!(line(0.0, 0.0, 0), 2);
    tick(100);
    assert_eq!(status(0), GMS_HOLD);
    assert!((pos(0)[0] + 10.0).abs() < 1e-9, "did not move");
    assert_eq!(MCC_ClearError(0), NO_ERR);
    assert_eq!(MCC_GetErrorCode(0), 0);
    ticks_until_stop(0, 10_000);
    assert_eq!(pos(0)[0], 0.0);
    assert_eq!(
        MCC_CircleXY(0.0, 0.0, 2, 0),
        PARAMETER_ERR,
        "direction 0 or 1"
    );
    assert_eq!(MCC_CircleXY(f64::NAN, 0.0, 0, 0), PARAMETER_ERR);
    assert_eq!(MCC_GetErrorCode(0), 0, "argument errors record nothing");
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn ptp_axis_speed_from_rpm_and_ratio() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    // 3000 rpm / 60 x pitch 1 / gear 1 = 50 UU/s; 50 % -> 25 UU/s.
    assert_eq!(MCC_SetPtPSpeed(50.0, 0), 50.0);
    assert_eq!(MCC_SetPtPSpeed(101.0, 0), f64::from(PARAMETER_ERR));
    let z = [0.0; 8];
    assert_eq!(
        MCC_SetPtPAccTime(z[0], z[1], z[2], z[3], z[4], z[5], z[6], z[7], 0),
        NO_ERR
    );
    assert_eq!(
        MCC_SetPtPDecTime(z[0], z[1], z[2], z[3], z[4], z[5], z[6], z[7], 0),
        NO_ERR
    );
    assert_eq!(MCC_PtPX(25.0, 0), 0);
    assert_eq!(ticks_until_stop(0, 10_000), 1000, "25 UU at 25 UU/s");
    assert_eq!(pos(0)[0], 25.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn pulses_never_drift_over_many_moves() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(1000.0, 0), 1000.0);
    ramps(0.0, 0);
    assert_eq!(MCC_SetIncrease(0), NO_ERR);
    let mut expect = 0.0f64;
    for k in 0..100_000u32 {
        let d = if k % 3 == 0 { 0.0013 } else { -0.0007 };
        expect += d;
        let r = line(d, 0.0, 0);
        if r == COMMAND_BUFFER_FULL_ERR {
            ticks_until_stop(0, 1_000_000);
            assert_eq!(line(d, 0.0, 0), i32::try_from(k).unwrap() % 0x7FFF_FFFF);
        }
    }
    ticks_until_stop(0, 1_000_000);
    let p = pos(0)[0];
    assert!((p - expect).abs() < 1e-9, "{p} vs {expect}");
    assert_eq!(pulses(0)[0], (p * 500.0).round() as i64);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
