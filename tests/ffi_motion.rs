//! Motion through the C entry points on the stepped clock, against closed-form values of
//! the vendor's model (docs/decisions.md): acc and dec times in whole periods
//! na = ceil(Ta/T), nd = ceil(Td/T); a line of length L reaching feed F cruises
//! nc = ceil(L/F/T - na/2 - nd/2) periods at V = L/((na+nd)/2 T + nc T); the N = na + nc +
//! nd motion periods are followed by the end period (phase 21), a period with nothing
//! running, and the status reads STOP in period N + 3.

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
    let shared = MCCLPCI_IMP::system::active().unwrap();
    let clock = shared.clock();
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
    // 10 UU at 10 UU/s with 100 ms ramps: na = nd = 100 periods of 1 ms, nc =
    // ceil(10/10/0.001 - 50 - 50) = 900, N = 1100 motion periods; the status reads STOP
    // in period N + 3 = 1103. The first poll ran the first tick.
    let n = ticks_until_stop(0, 5000);
    assert_eq!(n, 1103, "took {n} ticks");
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
    MCCLPCI_IMP::system::active().unwrap().clock().wait_ticks(n);
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
    // A queue's size is set when its group is created: MCC_SetCmdQueueSize changes no
    // queue, as the vendor's library answers (GROUP_PARAMETER_ERR below 1, else
    // RUN_TIME_ERR), busy or not.
    assert_eq!(MCC_SetCmdQueueSize(60, 1), RUN_TIME_ERR);
    assert_eq!(MCC_SetCmdQueueSize(0, 1), GROUP_PARAMETER_ERR);
    assert_eq!(MCC_GetCmdQueueSize(1), 50);
    assert_eq!(MCC_AbortMotion(1, 0), NO_ERR);
    // The abort empties the queue at once; the status runs one more period.
    let mut n = -1;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetCommandCount(&mut n, 1) }, NO_ERR);
    assert_eq!(n, 0);
    tick(2);
    assert_eq!(status(1), GMS_STOP);
    assert_eq!(MCC_SetCmdQueueSize(60, 1), RUN_TIME_ERR);
    assert_eq!(MCC_GetCmdQueueSize(1), 50);
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
    // No ramps: nc = ceil(L/10/0.001) periods at 10 UU/s, 0.01 UU a period.
    assert_eq!(line(1.0, 0.0, 0), 0); // 100 periods
    assert_eq!(line(3.0, 0.0, 1), 0); // 300 periods
    tick(100);
    assert!((pos(0)[0] - 1.0).abs() < 1e-9, "group 0 at its end");
    assert!((pos(1)[0] - 1.0).abs() < 1e-9, "group 1 went 1 UU as well");
    // Group 0 reads STOP three periods after its last (103), group 1 runs on.
    tick(2);
    assert_eq!(status(0), GMS_RUNNING);
    tick(1);
    assert_eq!(status(0), GMS_STOP);
    assert_eq!(status(1), GMS_RUNNING);
    assert!((pos(1)[0] - 1.03).abs() < 1e-9, "1.03 UU after 103 periods");
    tick(199);
    assert_eq!(status(1), GMS_RUNNING);
    tick(1);
    assert_eq!(status(1), GMS_STOP);
    assert_eq!(pos(0)[0], 1.0);
    assert_eq!(pos(1)[0], 3.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn a_channel_belongs_to_one_group() {
    let _g = fresh();
    // Group 0: X on channel 0, Y on channel 1. A group asking for channel 1 as well is
    // refused (PARAMETER_ERR, as the vendor's library answers: scenario overlap_groups);
    // on channel 2 it is made, and takes the next free index.
    assert_eq!(MCC_CreateGroup(0, 1, -1, -1, -1, -1, -1, -1, 0), 0);
    assert_eq!(
        MCC_CreateGroup(1, -1, -1, -1, -1, -1, -1, -1, 0),
        PARAMETER_ERR
    );
    assert_eq!(MCC_CreateGroup(2, -1, -1, -1, -1, -1, -1, -1, 0), 1);
    assert_eq!(init_ms(1, 1), NO_ERR);
    for g in 0..2 {
        assert_eq!(MCC_SetFeedSpeed(10.0, g), 10.0);
        ramps(0.0, g);
    }
    // No ramps: √5 UU at 10 UU/s is ceil(223.6) = 224 periods, STOP in period 227;
    // 3 UU is 300 periods, STOP in period 303.
    assert_eq!(line(1.0, 2.0, 0), 0);
    assert_eq!(line(3.0, 0.0, 1), 0);
    tick(226);
    assert_eq!((status(0), status(1)), (GMS_RUNNING, GMS_RUNNING));
    tick(1);
    assert_eq!((status(0), status(1)), (GMS_STOP, GMS_RUNNING));
    tick(76);
    assert_eq!((status(0), status(1)), (GMS_STOP, GMS_STOP));
    // Each group moves its own axes to their ends: 500 pulses/UU (the default
    // mechanism), 2 UU of Y = 1000 pulses, 3 UU of X = 1500.
    assert_eq!(pulses(0)[..2], [500, 1000]);
    assert_eq!(pulses(1)[0], 1500);
    // Each channel (the encoder counts a pulse each at x4, the default) follows the one
    // axis mapping it.
    assert_eq!(enc(0), 500);
    assert_eq!(enc(1), 1000);
    assert_eq!(enc(2), 1500);
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
    // Hold and continue with nothing to hold or continue change nothing and answer
    // NO_ERR, as the vendor's library answers (scenario hold_conti_misuse).
    assert_eq!(MCC_HoldMotion(0, 0), NO_ERR);
    assert_eq!(MCC_ContiMotion(0), NO_ERR);
    tick(5);
    assert_eq!(status(0), GMS_STOP);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    assert_eq!(MCC_SetAccType(b'T' as std::os::raw::c_char, 0), NO_ERR);
    assert_eq!(MCC_SetDecType(b'T' as std::os::raw::c_char, 0), NO_ERR);
    ramps(100.0, 0);
    assert_eq!(line(10.0, 0.0, 0), 0);
    // na = nd = 100, nc = 900, V = 10: a = V/(na T) = 100 UU/s^2. Held in the
    // acceleration, where the stop ramp's length is off the edge of its rounding (in
    // the cruise v0 = F puts n = floor(Td v0/F/T) + 1 on the edge of 100 and 101):
    // after 50 periods s = a (0.05)^2/2 = 0.125 (trunc(62.5) = 62 pulses at 500
    // pulses/UU) and the last period's mean speed v0 = a x 0.0495 = 4.95.
    tick(50);
    assert_eq!(pulses(0)[0], 62);
    assert!((path_speed(0) - 4.95).abs() < 1e-9);
    assert_eq!(MCC_HoldMotion(0, 0), NO_ERR);
    assert_eq!(
        MCC_HoldMotion(0, 0),
        NO_ERR,
        "a second hold changes nothing"
    );
    // The hold ramps from v0 over n = floor(100 x 4.95/10) + 1 = 50 periods, covering
    // d = v0^2 Td/(2F) = 24.5025 x 0.1/20 = 0.1225125 UU: held at 0.2475125, whole
    // pulses toward 0: trunc(123.756) = 123. The period after shows the hold (phase
    // 22, speed 0), the status reads HOLD two periods later.
    tick(49);
    assert!(
        path_speed(0) > 0.0,
        "still moving in the ramp's last but one period"
    );
    tick(1);
    assert_eq!(pulses(0)[0], 123);
    assert_eq!(pos(0)[0], 123.0 / 500.0);
    tick(1);
    assert_eq!(path_speed(0), 0.0);
    assert_eq!(status(0), GMS_RUNNING);
    tick(1);
    assert_eq!(status(0), GMS_RUNNING);
    tick(1);
    assert_eq!(status(0), GMS_HOLD);
    tick(1000);
    assert_eq!(pulses(0)[0], 123, "stands still while held");
    assert_eq!(status(0), GMS_HOLD);
    // Continue plans the rest, 10 - 0.2475125 = 9.7524875 UU, from rest: nc =
    // ceil(975.24875 - 100) = 876, N = 1076 periods, STOP in period 1079.
    assert_eq!(MCC_ContiMotion(0), NO_ERR);
    assert_eq!(ticks_until_stop(0, 5000), 1079);
    assert_eq!(pos(0)[0], 10.0, "the rest of the same command");

    // AbortMotionEx(t): ramps down over t, empties the queue, refuses motion meanwhile.
    assert_eq!(line(20.0, 0.0, 0), 1);
    assert_eq!(line(30.0, 0.0, 0), 2);
    tick(50);
    assert_eq!(pulses(0)[0], 5062, "10.125, as above");
    assert_eq!(MCC_AbortMotionEx(50.0, 0), NO_ERR);
    assert_eq!(line(0.0, 0.0, 0), ABORT_NOT_FINISH_ERR);
    // A hold ramp with Td = 50 ms: n = floor(50 x 4.95/10) + 1 = 25 periods, d =
    // 24.5025 x 0.05/20 = 0.06125625 UU: 10.18625625, trunc(5093.13) = 5093 pulses;
    // then the end shows as a hold (phase 22: two periods running, one HOLD) and the
    // status reads STOP in period n + 4 = 29.
    tick(25);
    assert_eq!(pulses(0)[0], 5093);
    tick(2);
    assert_eq!(status(0), GMS_RUNNING);
    tick(1);
    assert_eq!(status(0), GMS_HOLD);
    tick(1);
    assert_eq!(status(0), GMS_STOP);
    assert_eq!(pulses(0)[0], 5093);
    let mut n = -1;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetCommandCount(&mut n, 0) }, NO_ERR);
    assert_eq!(n, 0);
    // AbortMotion: at once; the status runs one more period, in which new commands
    // are refused.
    assert_eq!(line(20.0, 0.0, 0), 3);
    tick(300);
    let here = pos(0)[0];
    assert_eq!(MCC_AbortMotion(0, 0), NO_ERR);
    assert_eq!(line(0.0, 0.0, 0), ABORT_NOT_FINISH_ERR, "within its period");
    tick(1);
    assert_eq!(status(0), GMS_RUNNING);
    tick(1);
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
    // 200 ms at 2 ms a period: 100 periods DELAYING, the next with nothing running,
    // STOP the one after (no end period: scenario delay_alone). MCC_CheckDelay is 1
    // while the status is DELAYING, as the vendor's library answers.
    assert_eq!(MCC_DelayMotion(200, 0), 0);
    assert_eq!(MCC_CheckDelay(0), 0, "queued, not started");
    tick(1);
    assert_eq!(status(0), GMS_DELAYING);
    assert_eq!(MCC_CheckDelay(0), 1);
    let mut info = COMMAND_INFO::default();
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetCurCommand(&mut info, 0) }, NO_ERR);
    // Type 8 (a delay) and the ms still to wait after this period in the feed field.
    assert_eq!((info.nType, info.nCommandIndex), (8, 0));
    assert!(
        (info.dfFeedSpeed - 198.0).abs() < 1e-9,
        "ms left: {}",
        info.dfFeedSpeed
    );
    tick(99); // 200 ms
    assert_eq!(status(0), GMS_DELAYING);
    assert_eq!(MCC_CheckDelay(0), 1);
    tick(1);
    assert_eq!(status(0), GMS_RUNNING);
    assert_eq!(MCC_CheckDelay(0), 0);
    tick(1);
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
    // The blend marker takes period 1. Each line: na = nd = 100, nc = ceil(500 - 100)
    // = 400, V = 10, N = 600 periods. Blended, the second starts with the first's
    // deceleration: the first runs in periods 2..601, the second in 502..1101; the
    // ramps (the default S-curve, smoothstep s(x) + s(1 - x) = 1) add up to the
    // cruise speed, which so holds from the first's cruise (102) to the second's
    // deceleration (1001). STOP reads in period 1101 + 3.
    let mut min_cruise = f64::MAX;
    for t in 1..=1103u64 {
        tick(1);
        if (102..=1001).contains(&t) {
            min_cruise = min_cruise.min(path_speed(0));
        }
        assert_eq!(status(0), GMS_RUNNING, "period {t}");
    }
    assert!(
        (min_cruise - 10.0).abs() < 1e-9,
        "speed dipped to {min_cruise}"
    );
    tick(1);
    assert_eq!(status(0), GMS_STOP);
    assert_eq!(pos(0)[0], 10.0);

    // Without blending the first line stops at its end: the marker (period 1), the
    // first line (2..601), its end period (602), the second (603..1202), its end,
    // one period with nothing, STOP in period 1205.
    assert_eq!(MCC_DisableBlend(0), 3);
    assert_eq!(line(15.0, 0.0, 0), 4);
    assert_eq!(line(20.0, 0.0, 0), 5);
    tick(601);
    assert_eq!(pos(0)[0], 15.0);
    tick(1);
    assert_eq!(path_speed(0), 0.0, "the end period of the first line");
    assert_eq!(pos(0)[0], 15.0);
    tick(1);
    assert!(
        pos(0)[0] == 15.0 && path_speed(0) > 0.0,
        "the second starts"
    );
    tick(601);
    assert_eq!(status(0), GMS_RUNNING);
    tick(1);
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
    // The rate is read back as a fraction, from the period after it was set, as the
    // vendor's library reports it (scenario setters_override).
    assert_eq!(MCC_OverrideSpeed(50.0, 0), 50.0);
    assert_eq!(MCC_GetOverrideRate(0), 1.0, "from the next period");
    assert_eq!(MCC_OverrideSpeed(0.0, 0), f64::from(PARAMETER_ERR));
    assert_eq!(MCC_OverrideSpeed(f64::NAN, 0), f64::from(PARAMETER_ERR));
    assert_eq!(line(10.0, 0.0, 0), 0);
    // Planned at 50 % of 10 UU/s from its first period: the ramps keep their 100
    // periods, the cruise at 5 UU/s: nc = ceil(10/5/0.001 - 100) = 1900, N = 2100,
    // STOP in period 2103.
    assert_eq!(ticks_until_stop(0, 10_000), 2103);
    assert_eq!(
        MCC_GetOverrideRate(0),
        0.5,
        "unchanged by the refused rates"
    );
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
    // From (10, 0) through (0, 10) to (-10, 0): center (0, 0), R = 10, CCW. The
    // positions read are whole pulses toward 0 (500 pulses/UU), so within 1/500 UU of
    // the circle (the radius error of a truncation is at most √2/500).
    assert_eq!(MCC_ArcXY(0.0, 10.0, -10.0, 0.0, 0), 1);
    let mut worst: f64 = 0.0;
    let mut types = Vec::new();
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
        if types.last() != Some(&info.nType) {
            types.push(info.nType);
        }
    }
    // A counter-clockwise arc (type 3) through its end period, then the period with
    // nothing running (type 0) before STOP.
    assert_eq!(types, [3, 0]);
    assert!(worst <= 2f64.sqrt() / 500.0 + 1e-12, "radius error {worst}");
    let p = pos(0);
    assert!((p[0] + 10.0).abs() < 1e-9 && p[1].abs() < 1e-9);
    // Collinear points: the vendor's library queues the arc (its index) and fails it
    // when it starts: error record 0xF104, the group stops, the queue is dropped, and
    // every motion command is refused (RUN_TIME_ERR) until MCC_ClearError (scenarios
    // arc_collinear_then_line, arc_bad_in_queue).
    assert_eq!(MCC_ArcXY(0.0, 0.0, 10.0, 0.0, 0), 2);
    tick(1);
    assert_eq!(MCC_GetErrorCode(0), 0xF104);
    assert_eq!(status(0), GMS_STOP);
    assert_eq!(line(0.0, 0.0, 0), RUN_TIME_ERR);
    tick(100);
    assert!((pos(0)[0] + 10.0).abs() < 1e-9, "did not move");
    assert_eq!(MCC_ClearError(0), NO_ERR);
    assert_eq!(MCC_GetErrorCode(0), 0);
    assert_eq!(line(0.0, 0.0, 0), 3);
    ticks_until_stop(0, 10_000);
    assert_eq!(pos(0)[0], 0.0);
    // A circle's direction: 0 clockwise, any other value counter-clockwise, as the
    // vendor's library takes it (scenario arc_bad_dir); a NaN centre is refused and
    // records nothing.
    assert_eq!(MCC_CircleXY(f64::NAN, 0.0, 0, 0), PARAMETER_ERR);
    assert_eq!(MCC_GetErrorCode(0), 0, "argument errors record nothing");
    assert_eq!(MCC_CircleXY(1.0, 0.0, 2, 0), 4);
    let mut info = COMMAND_INFO::default();
    tick(1);
    // SAFETY: valid pointer.
    unsafe { MCC_GetCurCommand(&mut info, 0) };
    assert_eq!(info.nType, 3, "a counter-clockwise circle: an arc's type");
    ticks_until_stop(0, 10_000);
    assert_eq!(
        pos(0)[..2],
        [0.0, 0.0],
        "a whole circle ends where it began"
    );
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn ptp_axis_speed_from_rpm_and_ratio() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    // 3000 rpm / 60 x pitch 1 / gear 1 = 50 UU/s; 50 % -> 25 UU/s.
    assert_eq!(MCC_SetPtPSpeed(50.0, 0), 50.0);
    assert_eq!(MCC_SetPtPSpeed(101.0, 0), f64::from(PARAMETER_ERR));
    // The per-axis PtP times are kept, but a PtP ramps with the group's acc and dec
    // times, as the vendor's library runs it (scenario ptp_axis_times): with those at
    // 0 the axis runs at 25 UU/s from the first period.
    let z = [0.0; 8];
    assert_eq!(
        MCC_SetPtPAccTime(z[0], z[1], z[2], z[3], z[4], z[5], z[6], z[7], 0),
        NO_ERR
    );
    assert_eq!(
        MCC_SetPtPDecTime(z[0], z[1], z[2], z[3], z[4], z[5], z[6], z[7], 0),
        NO_ERR
    );
    ramps(0.0, 0);
    assert_eq!(MCC_PtPX(25.0, 0), 0);
    // 25 UU at 25 UU/s: N = 1000 periods; a PtP shows its last speed one more period,
    // then a period at rest with the command, one with nothing, and STOP in period
    // N + 4 (scenario ptpx_single).
    assert_eq!(ticks_until_stop(0, 10_000), 1004, "25 UU at 25 UU/s");
    assert_eq!(pos(0)[0], 25.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn pulses_never_drift_over_many_moves() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    // The feed is clamped to the system's maximum speed, 100 UU/s by default.
    assert_eq!(MCC_SetFeedSpeed(1000.0, 0), 100.0);
    ramps(0.0, 0);
    assert_eq!(MCC_SetIncrease(0), NO_ERR);
    let mut expect = 0.0f64;
    // A call refused for a full queue takes an index as well, as the vendor's library
    // counts (scenario queue_full: four refused calls after indices 0..3, the next
    // command is 8).
    let mut index = 0;
    for k in 0..100_000u32 {
        let d = if k % 3 == 0 { 0.0013 } else { -0.0007 };
        expect += d;
        let mut r = line(d, 0.0, 0);
        if r == COMMAND_BUFFER_FULL_ERR {
            index += 1;
            ticks_until_stop(0, 1_000_000);
            r = line(d, 0.0, 0);
        }
        assert_eq!(r, index);
        index += 1;
    }
    ticks_until_stop(0, 1_000_000);
    // 33334 x 0.0013 - 66666 x 0.0007 = -3.332 UU, a whole number of pulses (-1666),
    // which the position (whole pulses over 500 pulses/UU) reads exactly.
    let p = pos(0)[0];
    assert!((p - expect).abs() < 1e-9, "{p} vs {expect}");
    assert_eq!(pulses(0)[0], -1666);
    assert_eq!(pulses(0)[0], (p * 500.0).round() as i64);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
