//! The compose axes, the after-interpolation filters, the cycle routine and reverse
//! interpolation through the C entry points, on the stepped clock with 1 ms ticks
//! (`MCC_GetMotionStatus` and `wait_ticks(n)` run ticks; the numbers are derived by hand
//! in the comments). docs/compatibility.md, "Filters, reverse interpolation, cycle
//! routine".

mod common;

use common::{fresh, init_ms};
use std::os::raw::{c_int, c_void};
use std::sync::atomic::{AtomicI32, AtomicU64, Ordering};
use MCCLPCI_IMP::ffi::filters::*;
use MCCLPCI_IMP::ffi::motion::*;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::vendor::consts::*;

fn pos(g: u16) -> [f64; 8] {
    MCCLPCI_IMP::system::active()
        .unwrap()
        .snapshot(g)
        .unwrap()
        .pos
}

fn tick(n: u64) {
    MCCLPCI_IMP::system::active().unwrap().clock().wait_ticks(n);
}

fn ticks() -> u64 {
    MCCLPCI_IMP::system::active().unwrap().clock().ticks()
}

/// Runs ticks until the group stops; the number of ticks it took.
fn ticks_until_stop(g: u16, limit: u64) -> u64 {
    let t0 = ticks();
    while MCC_GetMotionStatus(g) != GMS_STOP {
        assert!(ticks() - t0 < limit, "did not stop within {limit} ticks");
    }
    ticks() - t0
}

fn ramps(ms: f64) {
    assert_eq!(MCC_SetAccTime(ms, 0), NO_ERR);
    assert_eq!(MCC_SetDecTime(ms, 0), NO_ERR);
}

fn line(p: [f64; 8]) -> i32 {
    MCC_Line(
        p[0],
        p[1],
        p[2],
        p[3],
        p[4],
        p[5],
        p[6],
        p[7],
        0,
        IMP_AXIS_ALL,
    )
}

/// X's speed as read (`MCC_GetSpeed`: the period's move over the period).
fn speed_x() -> f64 {
    let mut v = [0.0; 8];
    let [a, b, c, d, e, f, g, h] = &mut v;
    // SAFETY: eight valid pointers.
    assert_eq!(unsafe { MCC_GetSpeed(a, b, c, d, e, f, g, h, 0) }, NO_ERR);
    v[0]
}

/// Every axis's speed as read (`MCC_GetSpeed`).
fn speeds() -> [f64; 8] {
    let mut v = [0.0; 8];
    let [a, b, c, d, e, f, g, h] = &mut v;
    // SAFETY: eight valid pointers.
    assert_eq!(unsafe { MCC_GetSpeed(a, b, c, d, e, f, g, h, 0) }, NO_ERR);
    v
}

fn close(a: f64, b: f64, what: &str) {
    assert!((a - b).abs() < 1e-9, "{what}: {a} vs {b}");
}

#[test]
fn compose_axes_measure_the_feed() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    ramps(100.0);
    // Refused: no axis, a bit above B, a group that does not run.
    assert_eq!(MCC_SetComposeAxis(0, 0), PARAMETER_ERR);
    assert_eq!(MCC_SetComposeAxis(0x100, 0), PARAMETER_ERR);
    assert_eq!(MCC_SetComposeAxis(0b1011, 7), GROUP_PARAMETER_ERR);

    // Default X|Y|Z: (3, 4, U 12) is 5 long: na = nd = 100 periods, nc = ceil(500 -
    // 100) = 400 at V = 5/(0.1 + 0.4) = 10, N = 600 periods, STOP read in period 603;
    // at full speed X/Y move 10 UU/s, U follows at 12/5 of it.
    assert_eq!(line([3.0, 4.0, 0.0, 12.0, 0.0, 0.0, 0.0, 0.0]), 0);
    tick(300);
    let v = speeds();
    close(v[0].hypot(v[1]), 10.0, "X/Y speed");
    close(v[3], 24.0, "U speed");
    assert_eq!(ticks_until_stop(0, 2000), 303);
    assert_eq!(pos(0)[..4], [3.0, 4.0, 0.0, 12.0]);

    // X|Y|U: back to 0 is sqrt(9 + 16 + 144) = 13 long: nc = ceil(1300 - 100) = 1200
    // at V = 13/1.3 = 10, N = 1400 periods, STOP in period 1403; at full speed
    // |d(x, y, u)/dt| = 10.
    assert_eq!(MCC_SetComposeAxis(0b1011, 0), NO_ERR);
    assert_eq!(line([0.0; 8]), 1);
    tick(700);
    let v = speeds();
    let s = [0, 1, 3].iter().map(|&i| v[i].powi(2)).sum::<f64>().sqrt();
    close(s, 10.0, "X/Y/U speed");
    close(
        MCC_GetCurFeedSpeed(0),
        10.0,
        "path speed over the compose axes",
    );
    assert_eq!(ticks_until_stop(0, 3000), 703);
    assert_eq!(pos(0), [0.0; 8]);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn acc_dec_after_interpolation_rounds_the_corner_and_adds_its_time() {
    let _g = fresh();
    assert_eq!(MCC_EnableAccDecAfterIPO(0), INITIAL_MOTION_ERR);
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    assert_eq!(MCC_EnableAccDecAfterIPO(9), GROUP_PARAMETER_ERR);

    // Acc time 0: the filter is 0 periods long and the raw interpolation is what runs:
    // each 1 UU line at 10 UU/s for 100 periods and its end period (1..100, 101;
    // 102..201, 202), then a period with nothing running and STOP in period 204, as
    // without the filter (checked last).
    ramps(0.0);
    assert_eq!(MCC_EnableAccDecAfterIPO(0), NO_ERR);
    assert_eq!(line([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]), 0);
    assert_eq!(line([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]), 1);
    let unfiltered = ticks_until_stop(0, 1000);
    assert_eq!(pos(0)[..2], [1.0, 1.0]);
    assert_eq!(line([0.0; 8]), 2);
    // Not while the group moves.
    assert_eq!(MCC_EnableAccDecAfterIPO(0), COMMAND_NOTFINISHED_ERR);
    ticks_until_stop(0, 1000);

    // Acc time 100 ms: L = 100 periods, the output is the trapezoidal mean of the raw
    // positions p(k-100) .. p(k) (ends ½, / 100). Raw: x = k/100 for k <= 100, then
    // the first line's end period (101), then y = (k-101)/100 for k = 102..201.
    ramps(100.0);
    assert_eq!(MCC_EnableAccDecAfterIPO(0), NO_ERR);
    assert_eq!(line([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]), 3);
    assert_eq!(line([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]), 4);
    // Tick 1: only p(1) = 0.01, weighing ½: x = 0.005 / 100, read as 0 whole pulses
    // (0.025 of one); the speed read is 0.00005 UU over 1 ms.
    tick(1);
    assert_eq!(pos(0)[0], 0.0);
    close(speed_x(), 0.05, "first period: the ramp starts");
    // Tick 150, the window around the corner (1, 0):
    // x = (p50/2 + Σ51..100 j/100 + 49·1 + 1/2)/100 = (0.25 + 37.75 + 49 + 0.5)/100 = 0.875
    // y = (Σ102..149 (k-101)/100 + 0.49/2)/100 = (11.76 + 0.245)/100 = 0.12005
    // within 0.18 of the chord x + y = 1 from the corner: the corner is rounded. Read in
    // whole pulses: 437 and 60 of 500 per UU.
    tick(149);
    let p = pos(0);
    close(p[0], 0.874, "x at the corner");
    close(p[1], 0.12, "y at the corner");
    // The raw motion last changes at 201, the window holds only the end from 301: the
    // status reads STOP in period 301, exactly at the end.
    assert_eq!(ticks_until_stop(0, 1000), 151);
    assert_eq!(pos(0)[..2], [1.0, 1.0]);
    assert_eq!(MCC_DisableAccDecAfterIPO(0), NO_ERR);
    // Acc/dec before interpolation again: na = nd = 100, nc = ceil(100 - 100) = 0, V =
    // 1/0.1 = 10, N = 200 periods, STOP read in period 203.
    assert_eq!(line([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]), 5);
    assert_eq!(ticks_until_stop(0, 1000), 203);
    assert_eq!(pos(0)[..2], [1.0, 0.0]);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    assert_eq!(unfiltered, 204, "a filter of 0 periods changes no timing");
}

#[test]
fn moving_average_of_five_positions() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    assert_eq!(MCC_EnableMovingAverage(3), GROUP_PARAMETER_ERR);
    // No acc/dec at all, so the raw positions are x(k) = k/100 for k = 1..100.
    ramps(0.0);
    assert_eq!(MCC_EnableMovingAverage(0), NO_ERR);
    assert_eq!(line([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]), 0);
    // Mean of x(k-4..k), x(j) = 0 for j <= 0:
    // k=1: 0.01/5 = 0.002, k=2: 0.03/5 = 0.006, k=3: 0.06/5 = 0.012, k=4: 0.1/5 = 0.02,
    // then x(k-2): the raw path 2 periods late.
    for want in [0.002, 0.006, 0.012, 0.02, 0.03, 0.04] {
        tick(1);
        close(pos(0)[0], want, "moving average");
    }
    tick(44); // tick 50
    close(pos(0)[0], 0.48, "x(48)");
    // The raw line ends at tick 100, the mean 4 ticks later, exactly at 1, and the
    // status reads STOP then (after the raw line's STOP, in period 103).
    assert_eq!(ticks_until_stop(0, 1000), 54);
    assert_eq!(pos(0)[0], 1.0);
    assert_eq!(MCC_DisableMovingAverage(0), NO_ERR);
    // Unfiltered, 100 periods, STOP read in period 103.
    assert_eq!(line([0.0; 8]), 1);
    assert_eq!(ticks_until_stop(0, 1000), 103);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

static CYCLES: AtomicU64 = AtomicU64::new(0);

extern "system" fn count_cycle() {
    CYCLES.fetch_add(1, Ordering::SeqCst);
}

#[test]
fn cycle_routine_runs_once_per_period() {
    let _g = fresh();
    assert_eq!(
        MCC_SetCycleInterruptRoutine(Some(count_cycle)),
        INITIAL_MOTION_ERR
    );
    assert_eq!(init_ms(1, 1), NO_ERR);
    CYCLES.store(0, Ordering::SeqCst);
    assert_eq!(MCC_SetCycleInterruptRoutine(Some(count_cycle)), NO_ERR);
    let t0 = ticks();
    tick(37);
    assert_eq!(ticks() - t0, 37);
    assert_eq!(CYCLES.load(Ordering::SeqCst), 37);
    assert_eq!(MCC_SetCycleInterruptRoutine(None), NO_ERR);
    tick(5);
    assert_eq!(CYCLES.load(Ordering::SeqCst), 37, "unregistered");
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

/// The routine's script: call c returns 1 for c < FWD, -1 for FWD <= c < FWD + BACK,
/// then 1 again; it records its last arguments.
static CALLS: AtomicI32 = AtomicI32::new(0);
static LAST_CMD: AtomicI32 = AtomicI32::new(-2);
static LAST_TIME: AtomicI32 = AtomicI32::new(-2);
const FWD: i32 = 300;
const BACK: i32 = 120;

extern "system" fn retract(group: c_int, cmd: c_int, time: c_int, buf: *mut c_void) -> c_int {
    assert!(group == 0 && buf.is_null());
    let c = CALLS.fetch_add(1, Ordering::SeqCst) + 1;
    LAST_CMD.store(cmd, Ordering::SeqCst);
    LAST_TIME.store(time, Ordering::SeqCst);
    if (FWD..FWD + BACK).contains(&c) {
        -1
    } else {
        1
    }
}

#[test]
fn reverse_interpolation_retraces_the_path_exactly() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    ramps(100.0);
    assert_eq!(MCC_EnableReverseInterp(1, 5), GROUP_PARAMETER_ERR);
    CALLS.store(0, Ordering::SeqCst);
    assert_eq!(MCC_SetReverseInterpRoutine(Some(retract), 0), NO_ERR);
    assert_eq!(MCC_EnableReverseInterp(1, 0), NO_ERR);
    // 10 UU along X (U follows to 5): na = nd = 100, nc = ceil(1000 - 100) = 900, N =
    // 1100 periods unreversed, STOP read in period 1103.
    assert_eq!(line([10.0, 0.0, 0.0, 5.0, 0.0, 0.0, 0.0, 0.0]), 0);
    let mut seen = vec![pos(0)];
    for _ in 0..FWD {
        tick(1);
        seen.push(pos(0));
    }
    assert_eq!(LAST_CMD.load(Ordering::SeqCst), 0);
    assert_eq!(
        LAST_TIME.load(Ordering::SeqCst),
        FWD,
        "periods command 0 has run"
    );
    // Calls FWD .. FWD+BACK-1 say back: tick FWD + j stands where tick FWD - j stood.
    let (f, b) = (FWD as usize, BACK as usize);
    for j in 1..=b {
        tick(1);
        assert_eq!(pos(0), seen[f - j], "back {j}");
    }
    assert_eq!(
        LAST_TIME.load(Ordering::SeqCst),
        FWD,
        "the command stood still"
    );
    let st = MCCLPCI_IMP::system::active()
        .unwrap()
        .snapshot(0)
        .unwrap()
        .status;
    assert_eq!(st, GMS_RUNNING);
    // Forward again along the recorded path: tick FWD + BACK + j at tick FWD - BACK + j.
    for j in 1..=b {
        tick(1);
        assert_eq!(pos(0), seen[f - b + j], "forward {j}");
    }
    // Then the command goes on and ends as it would have, 2·BACK ticks later.
    let n = ticks_until_stop(0, 5000);
    assert_eq!(FWD as u64 + 2 * BACK as u64 + n, 1103 + 2 * BACK as u64);
    assert_eq!(pos(0)[..4], [10.0, 0.0, 0.0, 5.0]);
    assert_eq!(MCC_EnableReverseInterp(0, 0), NO_ERR);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

static DECISION: AtomicI32 = AtomicI32::new(1);

extern "system" fn steer(_g: c_int, _c: c_int, _t: c_int, _b: *mut c_void) -> c_int {
    DECISION.load(Ordering::SeqCst)
}

#[test]
fn reverse_pause_and_abort_behind_the_front() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    DECISION.store(1, Ordering::SeqCst);
    assert_eq!(MCC_SetReverseInterpRoutine(Some(steer), 0), NO_ERR);
    assert_eq!(MCC_EnableReverseInterp(1, 0), NO_ERR);
    assert_eq!(line([10.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]), 0);
    let mut seen = vec![pos(0)];
    for _ in 0..201 {
        tick(1);
        seen.push(pos(0));
    }
    // The call after tick 201 was made with DECISION 1: tick 202 goes forward (to where
    // the commands take it, seen[202] unrecorded here); the calls after 202..210 say
    // back: ticks 203..211 step back 9 periods, to tick 193's position.
    DECISION.store(-1, Ordering::SeqCst);
    tick(10);
    assert_eq!(pos(0), seen[193]);
    // Tick 212 still goes back (decided after tick 211), then 0 pauses.
    DECISION.store(0, Ordering::SeqCst);
    tick(5);
    assert_eq!(pos(0), seen[192]);
    let st = MCCLPCI_IMP::system::active()
        .unwrap()
        .snapshot(0)
        .unwrap()
        .status;
    assert_eq!(st, GMS_RUNNING, "paused behind the front");
    // An abort behind the front stops there; that is now the end of the path.
    assert_eq!(MCCLPCI_IMP::ffi::trajectory::MCC_AbortMotion(0, 0), NO_ERR);
    DECISION.store(1, Ordering::SeqCst);
    tick(20);
    assert_eq!(pos(0), seen[192]);
    let st = MCCLPCI_IMP::system::active()
        .unwrap()
        .snapshot(0)
        .unwrap()
        .status;
    assert_eq!(st, GMS_STOP);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
