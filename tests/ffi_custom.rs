//! Custom motion through the C entry points (`MCC_CustomMotion`, `MCC_CustomMotionEx`,
//! `MCC_InfiniteMotion`), with Rust `extern "system"` callbacks, under the stepped and fast
//! clocks.
//!
//! Timing (docs/compatibility.md, "Custom motion"): the command is taken from the queue at
//! tick 1 after it was queued (position: its start); after tick j the stage calls
//! `interp` with the distance the profile reaches at tick j+1, `s(j·dt)`, so tick j+1
//! shows the offset for `s(j·dt)`. The profile is a line's, on the grid of periods as
//! the vendor's library plans one: with 1 ms ticks, feed F = 10 UU/s and Ta = Td = 0.1 s
//! the ramps take na = nd = 100 periods, the cruise nc = ceil(L/F/dt − 100) whole
//! periods at V = L/(0.1 + nc·dt) (at most F), so the profile lasts D = (200 + nc)·dt:
//!
//! * 'T' ramps: s(t) = V t²/(2 Ta) for t ≤ Ta; cruise s = V·Ta/2 + V·(t − Ta);
//!   deceleration mirrors the acceleration: s = L − V (D − t)²/(2 Td).
//! * 'S' ramps: the speed is V times the smoothstep 3x² − 2x³ of x = t/Ta, so
//!   s = V·Ta·(x³ − x⁴/2) for t ≤ Ta; cruise and deceleration as above.

mod common;

use common::{fresh, init_ms};
use parking_lot::Mutex;
use std::os::raw::{c_int, c_void};
use MCCLPCI_IMP::ffi::coordinate::*;
use MCCLPCI_IMP::ffi::custom::*;
use MCCLPCI_IMP::ffi::motion::*;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;

const F: f64 = 10.0;
const TA: f64 = 0.1;
const DT: f64 = 0.001;

/// The periods at cruise speed of a profile of length `l` (module documentation).
fn cruise_periods(l: f64) -> f64 {
    (l / F / DT - TA / DT).ceil()
}

/// The cruise speed of a profile of length `l`.
fn cruise_speed(l: f64) -> f64 {
    l / (TA + cruise_periods(l) * DT)
}

/// The profile's duration for length `l`, s.
fn duration(l: f64) -> f64 {
    (2.0 * TA / DT + cruise_periods(l)) * DT
}

/// The profile's distance at time t for length `l` (module documentation).
fn profile_s(t: f64, l: f64, s_shape: bool) -> f64 {
    let d = duration(l);
    let v = cruise_speed(l);
    let ramp = |t: f64| {
        let x = t / TA;
        if !s_shape {
            v * t * x * 0.5
        } else {
            v * TA * (x * x * x - 0.5 * x * x * x * x)
        }
    };
    if t >= d {
        l
    } else if t <= TA {
        ramp(t)
    } else if t <= d - TA {
        v * TA / 2.0 + v * (t - TA)
    } else {
        l - ramp(d - t)
    }
}

/// A curve given by its points at arc length s, tabulated (the program's business: the
/// library only hands it distances).
struct Curve {
    /// (s, x, y) at fine steps.
    table: Vec<(f64, f64, f64)>,
}

impl Curve {
    fn from_param(f: impl Fn(f64) -> (f64, f64), n: usize) -> Curve {
        let mut table = Vec::with_capacity(n + 1);
        let (mut s, mut prev) = (0.0, f(0.0));
        table.push((0.0, prev.0, prev.1));
        for i in 1..=n {
            let p = f(i as f64 / n as f64);
            s += ((p.0 - prev.0).powi(2) + (p.1 - prev.1).powi(2)).sqrt();
            table.push((s, p.0, p.1));
            prev = p;
        }
        Curve { table }
    }
    fn len(&self) -> f64 {
        self.table.last().map_or(0.0, |t| t.0)
    }
    /// Point at arc length s (linear between table points), relative to the start.
    fn at(&self, s: f64) -> (f64, f64) {
        let i = self
            .table
            .partition_point(|t| t.0 < s)
            .clamp(1, self.table.len() - 1);
        let (a, b) = (self.table[i - 1], self.table[i]);
        let u = if b.0 > a.0 {
            (s - a.0) / (b.0 - a.0)
        } else {
            1.0
        };
        let u = u.clamp(0.0, 1.0);
        let (x0, y0) = (self.table[0].1, self.table[0].2);
        (a.1 + u * (b.1 - a.1) - x0, a.2 + u * (b.2 - a.2) - y0)
    }
}

/// What the callbacks saw and did.
#[derive(Default)]
struct Log {
    starts: u32,
    cleanups: u32,
    blend_starts: u32,
    blend_ends: u32,
    blend_interval: f64,
    /// (dist, tot, cur[0], cur[1], offset written[0], [1], blending)
    calls: Vec<(f64, f64, f64, f64, f64, f64, bool)>,
    start_pos: [f64; 8],
    get_cur_pos: Vec<(c_int, f64)>,
    queue_own: Option<c_int>,
    close_from_callback: Option<c_int>,
}

/// The program's buffer: the curve, the log, and how the callbacks behave.
struct Prog {
    curve: Curve,
    log: Mutex<Log>,
    tot: f64,
    /// interp returns FALSE once the distance passes this.
    stop_after: f64,
    /// InfiniteMotion sets *AbortThisCommand once the distance passes this.
    abort_after: f64,
    /// interp calls MCC_GetCurPos, queues into its own group and group 1, closes.
    misbehave: bool,
}

impl Prog {
    fn new(curve: Curve) -> Box<Prog> {
        let tot = curve.len();
        Box::new(Prog {
            curve,
            log: Mutex::new(Log::default()),
            tot,
            stop_after: f64::INFINITY,
            abort_after: f64::INFINITY,
            misbehave: false,
        })
    }
    fn buf(&self) -> *mut c_void {
        self as *const Prog as *mut c_void
    }
}

fn prog<'a>(buf: *mut c_void) -> &'a Prog {
    // SAFETY: every test passes a live `Prog` as the buffer.
    unsafe { &*(buf as *const Prog) }
}

extern "system" fn on_start(
    _g: c_int,
    n: c_int,
    _i: c_int,
    _abs: c_int,
    start: *const f64,
    buf: *mut c_void,
) -> f64 {
    let p = prog(buf);
    let mut l = p.log.lock();
    l.starts += 1;
    assert_eq!(n, 8);
    for k in 0..8 {
        // SAFETY: the library passes 8 values.
        l.start_pos[k] = unsafe { *start.add(k) };
    }
    p.tot
}

fn interp_common(
    g: c_int,
    cur: *const f64,
    dist: f64,
    tot: f64,
    next: *mut f64,
    buf: *mut c_void,
    blending: bool,
) -> c_int {
    let p = prog(buf);
    let (x, y) = p.curve.at(dist);
    // SAFETY: the library passes 8 values in `cur` and 8 writable ones in `next`.
    let (c0, c1) = unsafe { (*cur, *cur.add(1)) };
    // SAFETY: as above, `next` holds 8 writable values.
    unsafe {
        *next = x;
        *next.add(1) = y;
    }
    if p.misbehave {
        let mut q = [0.0; 8];
        let [a, b, c, d, e, f, h, i] = &mut q;
        // SAFETY: eight valid pointers.
        let r = unsafe { MCC_GetCurPos(a, b, c, d, e, f, h, i, g as u16) };
        let own = MCC_Line(
            1.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            g as u16,
            IMP_AXIS_ALL,
        );
        let close = MCC_CloseSystem();
        let mut l = p.log.lock();
        l.get_cur_pos.push((r, q[0]));
        l.queue_own.get_or_insert(own);
        l.close_from_callback.get_or_insert(close);
    }
    p.log.lock().calls.push((dist, tot, c0, c1, x, y, blending));
    c_int::from(dist <= p.stop_after)
}

extern "system" fn on_interp(
    g: c_int,
    _n: c_int,
    _i: c_int,
    _start: *const f64,
    cur: *const f64,
    dist: f64,
    tot: f64,
    next: *mut f64,
    buf: *mut c_void,
) -> c_int {
    interp_common(g, cur, dist, tot, next, buf, false)
}

extern "system" fn on_infinite(
    g: c_int,
    _n: c_int,
    _i: c_int,
    _start: *const f64,
    cur: *const f64,
    dist: f64,
    tot: f64,
    next: *mut f64,
    buf: *mut c_void,
    abort: *mut c_int,
) -> c_int {
    let r = interp_common(g, cur, dist, tot, next, buf, false);
    if dist > prog(buf).abort_after {
        // SAFETY: the library passes a writable BOOL.
        unsafe { *abort = 1 };
    }
    r
}

extern "system" fn on_cleanup(_g: c_int, _i: c_int, buf: *mut c_void) {
    prog(buf).log.lock().cleanups += 1;
}

extern "system" fn on_blend_start(
    _g: c_int,
    _n: c_int,
    _i: c_int,
    _abs: c_int,
    _s0: *const f64,
    _s1: *const f64,
    _s2: *const f64,
    _mid: *const f64,
    _e0: *const f64,
    _e1: *const f64,
    _e2: *const f64,
    interval: f64,
    buf: *mut c_void,
) -> c_int {
    let mut l = prog(buf).log.lock();
    l.blend_starts += 1;
    l.blend_interval = interval;
    1
}

extern "system" fn on_blend(
    g: c_int,
    _n: c_int,
    _i: c_int,
    _bs: *const f64,
    _be: *const f64,
    cur: *const f64,
    dist: f64,
    next: *mut f64,
    buf: *mut c_void,
) -> c_int {
    let tot = prog(buf).tot;
    interp_common(g, cur, dist, tot, next, buf, true)
}

extern "system" fn on_blend_end(_g: c_int, _i: c_int, buf: *mut c_void) -> c_int {
    prog(buf).log.lock().blend_ends += 1;
    1
}

/// A position as `MCC_GetCurPos` reads it: whole pulses (500 per UU, the default
/// mechanism) toward 0, a position within 1e-7 pulse of a whole one being that one.
fn read_as(x: f64) -> f64 {
    let p = x * 500.0;
    let whole = if (p - p.round()).abs() <= 1e-7 {
        p.round()
    } else {
        p.trunc()
    };
    whole / 500.0
}

fn pos(g: u16) -> [f64; 8] {
    let mut p = [0.0; 8];
    let [a, b, c, d, e, f, h, i] = &mut p;
    // SAFETY: eight valid pointers.
    let r = unsafe { MCC_GetCurPos(a, b, c, d, e, f, h, i, g) };
    assert_eq!(r, NO_ERR);
    p
}

fn tick(n: u64) {
    MCCLPCI_IMP::system::active().unwrap().clock().wait_ticks(n);
}

fn wait_stop(g: u16) {
    for _ in 0..100_000 {
        if MCC_GetMotionStatus(g) == GMS_STOP {
            // One more tick: the stage after the tick that retired the command cleans up.
            tick(1);
            return;
        }
        tick(1);
    }
    panic!("group {g} did not stop");
}

fn setup(clock: &str, s_shape: bool) {
    std::env::set_var("MCCL_CLOCK", clock);
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(F, 0), F);
    assert_eq!(MCC_SetAccTime(TA * 1000.0, 0), NO_ERR);
    assert_eq!(MCC_SetDecTime(TA * 1000.0, 0), NO_ERR);
    let shape = if s_shape { b'S' } else { b'T' } as std::os::raw::c_char;
    assert_eq!(MCC_SetAccType(shape, 0), NO_ERR);
    assert_eq!(MCC_SetDecType(shape, 0), NO_ERR);
}

fn custom(p: &Prog, g: u16) -> c_int {
    MCC_CustomMotion(
        Some(on_start),
        Some(on_interp),
        Some(on_cleanup),
        p.buf(),
        g,
        IMP_AXIS_ALL,
    )
}

fn ellipse() -> Curve {
    // a = 3, b = 2, one turn from (3, 0).
    Curve::from_param(
        |u| {
            let a = std::f64::consts::TAU * u;
            (3.0 * a.cos(), 2.0 * a.sin())
        },
        200_000,
    )
}

fn sine() -> Curve {
    // y = sin x over one period, x from 0 to 2π.
    Curve::from_param(
        |u| {
            let x = std::f64::consts::TAU * u;
            (x, x.sin())
        },
        200_000,
    )
}

fn spline() -> Curve {
    // A cubic Bézier (0,0) (2,3) (4,-3) (6,0).
    Curve::from_param(
        |u| {
            let v = 1.0 - u;
            let b = [v * v * v, 3.0 * v * v * u, 3.0 * v * u * u, u * u * u];
            (
                b[1] * 2.0 + b[2] * 4.0 + b[3] * 6.0,
                b[1] * 3.0 - b[2] * 3.0,
            )
        },
        200_000,
    )
}

/// Runs `curve` to its end and checks every distance against the profile, every
/// position against the offset given, cleanup once, the end exactly.
fn run_curve(clock: &str, s_shape: bool, curve: Curve) {
    setup(clock, s_shape);
    let p = Prog::new(curve);
    let l = p.tot;
    // Start somewhere else than 0: offsets are from the start.
    assert_eq!(
        MCC_Line(1.0, -2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL),
        0
    );
    assert_eq!(custom(&p, 0), 1);
    wait_stop(0);
    let log = p.log.lock();
    assert_eq!(log.starts, 1);
    assert_eq!(log.cleanups, 1, "cleanup exactly once");
    assert_eq!(&log.start_pos[..2], &[1.0, -2.0]);
    // One call per tick until t = D: D / dt = 200 + nc calls.
    let n = log.calls.len();
    assert_eq!(n as f64, 200.0 + cruise_periods(l), "calls: {n}");
    let mut prev = (0.0, 0.0, 0.0);
    for (m, c) in log.calls.iter().enumerate() {
        let t = (m + 1) as f64 * DT;
        let want = profile_s(t, l, s_shape);
        assert!(
            (c.0 - want).abs() < 1e-9,
            "call {m}: dist {} want {want}",
            c.0
        );
        assert!(c.0 >= prev.0, "monotonic");
        assert_eq!(c.1, l, "tot");
        // The position now is the start plus the offset given by the previous call.
        assert_eq!((c.2, c.3), (1.0 + prev.1, -2.0 + prev.2), "cur at call {m}");
        // Path speed over the tick (the curve is parameterised by arc length, so the
        // speed along it is Δs/dt) = the profile's, within 1e-9.
        let v = (c.0 - prev.0) / DT;
        let want_v = (want - profile_s(t - DT, l, s_shape)) / DT;
        assert!((v - want_v).abs() < 1e-9, "speed {v} want {want_v}");
        prev = (c.0, c.4, c.5);
    }
    assert_eq!(log.calls[n - 1].0, l, "ends at tot");
    // In the middle of the move it cruises: Δs = V·dt, V short of the feed by less
    // than a period's worth (nc < L/F/dt - 100 + 1, so V > F/(1 + F·dt/L)).
    let mid = &log.calls[n / 2 - 1..=n / 2];
    let v = cruise_speed(l);
    assert!(((mid[1].0 - mid[0].0) / DT - v).abs() < 1e-9);
    assert!(v <= F && v > F / (1.0 + F * DT / l), "{v}");
    let end = pos(0);
    let (ex, ey) = p.curve.at(l);
    assert_eq!(
        (end[0], end[1]),
        (read_as(1.0 + ex), read_as(-2.0 + ey)),
        "ends at the last offset"
    );
    drop(log);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    assert_eq!(p.log.lock().cleanups, 1, "not again at close");
}

#[test]
fn ellipse_sine_and_spline_follow_the_profile_t_and_s() {
    let _g = fresh();
    for clock in ["stepped", "fast"] {
        for s in [false, true] {
            run_curve(clock, s, ellipse());
            run_curve(clock, s, sine());
            run_curve(clock, s, spline());
        }
    }
}

fn straight() -> Curve {
    Curve::from_param(|u| (20.0 * u, 0.0), 1000)
}

#[test]
fn hold_continue_override_abort() {
    let _g = fresh();
    setup("stepped", false);
    let p = Prog::new(straight());
    assert_eq!(custom(&p, 0), 0);
    // 20 UU: nc = 1900, V = 20/(0.1 + 1.9) = 10. Tick 1 takes it (position 0), tick j
    // shows s((j−1)·dt): after tick 501, s(0.5) = 0.5 + 10 x 0.4 = 4.5.
    tick(501);
    assert!((pos(0)[0] - 4.5).abs() < 1e-9, "{}", pos(0)[0]);
    assert_eq!(MCC_HoldMotion(0, 0), NO_ERR);
    // The offset for tick 502 was computed before the hold (s(0.501) = 4.51); from there
    // the hold ramps the speed v0 = 10 down over the distance v0² Td/(2F) = 100 x
    // 0.1/20 = 0.5 (as a line's hold): held at 5.01 (2505 pulses).
    tick(200);
    let held = pos(0)[0];
    assert!((held - 5.01).abs() < 1e-9, "held at {held}");
    tick(300);
    assert_eq!(pos(0)[0], held, "stands while held");
    assert_eq!(MCC_GetMotionStatus(0), GMS_HOLD);
    assert_eq!(MCC_ContiMotion(0), NO_ERR);
    tick(300);
    // Override 50 %: what is left is planned again from the speed it has, at 5 UU/s
    // with the acc/dec ramps and whole periods of cruise, so the cruise speed is 5
    // lowered by less than a period's worth of the distance left (about 11.5 UU at
    // 5 UU/s: V > 5/(1 + 5 x 0.001/11.4)).
    assert!(MCC_OverrideSpeed(50.0, 0) >= 0.0);
    tick(300);
    let n0 = p.log.lock().calls.len();
    tick(10);
    let v = {
        let l = p.log.lock();
        (l.calls[n0 + 9].0 - l.calls[n0 + 8].0) / DT
    };
    assert!(
        v <= 5.0 + 1e-9 && v > 5.0 / (1.0 + 5.0 * DT / 11.4),
        "overridden speed {v}"
    );
    // Abort with a 50 ms deceleration: the offset computed before it (the last call's
    // distance, one period ahead of the position shown) is reached, then the stop
    // covers v² Td/(2 F') with the overridden feed F' = 5: v²/200.
    let last = p.log.lock().calls.last().map(|c| c.0).unwrap_or(0.0);
    let here = last - v * DT;
    let shown = pos(0)[0];
    assert_eq!(shown, read_as(here), "shown {shown} here {here}");
    assert!(MCC_AbortMotionEx(50.0, 0) == NO_ERR);
    wait_stop(0);
    let stop = pos(0)[0];
    assert_eq!(
        stop,
        read_as(last + v * v / 200.0),
        "stopped at {stop}, from {here}"
    );
    let l = p.log.lock();
    assert_eq!(l.cleanups, 1, "abort cleans up once");
    assert!(l.calls.windows(2).all(|w| w[1].0 >= w[0].0), "monotonic");
    drop(l);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn override_motion_false_keeps_the_feed() {
    let _g = fresh();
    setup("stepped", false);
    let p = Prog::new(straight());
    assert!(MCC_OverrideSpeed(50.0, 0) >= 0.0);
    let r = MCC_CustomMotionEx(
        Some(on_start),
        Some(on_interp),
        Some(on_cleanup),
        None,
        None,
        None,
        p.buf(),
        0,
        0,
        IMP_AXIS_ALL,
    );
    assert_eq!(r, 0);
    // 20 UU at 10 UU/s: nc = 1900, V = 20/(0.1 + 1.9) = 10, cruising after 500 ticks.
    tick(500);
    let l = p.log.lock();
    let n = l.calls.len();
    let ds = l.calls[n - 1].0 - l.calls[n - 2].0;
    assert!((ds / DT - F).abs() < 1e-9, "feed kept: {}", ds / DT);
    drop(l);
    // With the override (MCC_CustomMotion) the same curve runs at 5 UU/s, planned at
    // the rate in effect when it starts, as a line is (20 UU at 5 UU/s: nc =
    // ceil(4000 - 100) = 3900 periods at V = 20/(0.1 + 3.9) = 5).
    assert_eq!(MCC_AbortMotion(0, 0), NO_ERR);
    tick(2);
    let q = Prog::new(straight());
    assert!(custom(&q, 0) >= 0);
    tick(500);
    let l = q.log.lock();
    let n = l.calls.len();
    let ds = l.calls[n - 1].0 - l.calls[n - 2].0;
    assert!((ds / DT - 5.0).abs() < 1e-9, "overridden: {}", ds / DT);
    drop(l);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    assert_eq!(p.log.lock().cleanups, 1);
    assert_eq!(q.log.lock().cleanups, 1, "close cleans up the running one");
}

/// FALSE from the interpolation callback is a failure, as the vendor's library treats it
/// (recorded scenario `custom_false`): the group stops where the last call that returned
/// TRUE put it (the offset written with FALSE is not used), with error record 0xF107;
/// the line queued behind is dropped, and a new command is refused (`RUN_TIME_ERR`)
/// until `MCC_ClearError`. The cleanup runs once (the vendor's library calls it twice).
#[test]
fn false_stops_the_group_with_error_0xf107() {
    let _g = fresh();
    setup("stepped", false);
    let mut p = Prog::new(straight());
    p.stop_after = 3.0;
    assert_eq!(custom(&p, 0), 0);
    assert_eq!(
        MCC_Line(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL),
        1
    );
    wait_stop(0);
    assert_eq!(MCC_GetErrorCode(0), 0xF107);
    let l = p.log.lock();
    let n = l.calls.len();
    let (last, good) = (l.calls[n - 1], l.calls[n - 2]);
    assert!(
        last.0 > 3.0 && good.0 <= 3.0,
        "FALSE at {}, TRUE before at {}",
        last.0,
        good.0
    );
    assert_eq!(l.cleanups, 1);
    // Whole pulses (500 per UU): at the last good offset, not the FALSE call's.
    let x = pos(0)[0];
    assert!(x <= good.4 && good.4 - x < 1.0 / 500.0, "{x} vs {}", good.4);
    drop(l);
    tick(20);
    assert!((pos(0)[0] - x).abs() < 1e-12, "the line was dropped");
    assert_eq!(
        MCC_Line(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL),
        RUN_TIME_ERR
    );
    assert_eq!(MCC_ClearError(0), NO_ERR);
    assert_eq!(
        MCC_Line(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL),
        2
    );
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn infinite_motion_cruises_until_its_flag() {
    let _g = fresh();
    for clock in ["stepped", "fast"] {
        setup(clock, false);
        let mut p = Prog::new(straight());
        p.tot = 0.0;
        p.abort_after = 15.005;
        let r = MCC_InfiniteMotion(
            Some(on_start),
            Some(on_infinite),
            Some(on_cleanup),
            p.buf(),
            1,
            0,
            IMP_AXIS_ALL,
        );
        assert_eq!(r, 0);
        wait_stop(0);
        let l = p.log.lock();
        // Accelerates to the feed and cruises: s(t) = 0.5 + 10 (t − 0.1) past the ramp, no
        // deceleration; the first call past 15.005 sets the flag: t = 1.551 → s = 15.01.
        let last = l.calls.last().unwrap().0;
        assert!((last - 15.01).abs() < 1e-9, "{last}");
        assert_eq!(l.calls.len(), 1551);
        assert_eq!(l.cleanups, 1);
        drop(l);
        // The program's abort ends one too.
        let q = Prog::new(straight());
        let r = MCC_InfiniteMotion(
            Some(on_start),
            Some(on_infinite),
            Some(on_cleanup),
            q.buf(),
            1,
            0,
            IMP_AXIS_ALL,
        );
        assert_eq!(r, 1);
        tick(100);
        assert_eq!(MCC_AbortMotion(0, 0), NO_ERR);
        tick(2);
        assert_eq!(q.log.lock().cleanups, 1);
        assert_eq!(MCC_CloseSystem(), NO_ERR);
    }
}

#[test]
fn callbacks_may_read_but_not_queue_into_their_group_or_close() {
    let _g = fresh();
    setup("stepped", false);
    let mut p = Prog::new(straight());
    p.misbehave = true;
    assert_eq!(custom(&p, 0), 0);
    tick(50);
    let l = p.log.lock();
    assert!(!l.get_cur_pos.is_empty());
    // MCC_GetCurPos works from the callback and reads the position it was called with
    // (in whole pulses, as it reads every position).
    for (c, g) in l.calls.iter().zip(&l.get_cur_pos) {
        assert_eq!(g.0, NO_ERR);
        assert_eq!(g.1, read_as(c.2));
    }
    assert_eq!(l.queue_own, Some(COMMAND_NOTACCEPTED_ERR));
    assert_eq!(l.close_from_callback, Some(COMMAND_NOTACCEPTED_ERR));
    drop(l);
    assert_eq!(MCC_GetMotionStatus(0), GMS_RUNNING, "the system still runs");
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    assert_eq!(p.log.lock().cleanups, 1);
}

#[test]
fn bad_arguments_queue_nothing() {
    let _g = fresh();
    let p = Prog::new(straight());
    assert_eq!(custom(&p, 0), INITIAL_MOTION_ERR, "before init");
    setup("stepped", false);
    let b = p.buf();
    assert_eq!(
        MCC_CustomMotion(None, Some(on_interp), None, b, 0, IMP_AXIS_ALL),
        PARAMETER_ERR
    );
    assert_eq!(
        MCC_CustomMotion(Some(on_start), None, None, b, 0, IMP_AXIS_ALL),
        PARAMETER_ERR
    );
    assert_eq!(
        MCC_CustomMotion(Some(on_start), Some(on_interp), None, b, 0, 0x100),
        PARAMETER_ERR
    );
    assert_eq!(custom(&p, 200), GROUP_PARAMETER_ERR);
    assert_eq!(
        MCC_InfiniteMotion(Some(on_start), None, None, b, 1, 0, IMP_AXIS_ALL),
        PARAMETER_ERR
    );
    // Ex: some but not all blending callbacks.
    assert_eq!(
        MCC_CustomMotionEx(
            Some(on_start),
            Some(on_interp),
            None,
            Some(on_blend_start),
            None,
            None,
            b,
            0,
            0,
            IMP_AXIS_ALL
        ),
        PARAMETER_ERR
    );
    let mut n = -1;
    // SAFETY: a valid pointer.
    assert_eq!(unsafe { MCC_GetCommandCount(&mut n, 0) }, NO_ERR);
    assert_eq!(n, 0, "nothing queued");
    tick(10);
    assert_eq!(p.log.lock().starts, 0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn a_bad_total_distance_stops_the_group_with_its_record() {
    let _g = fresh();
    setup("stepped", false);
    for tot in [f64::NAN, -1.0, f64::INFINITY] {
        let mut p = Prog::new(straight());
        p.tot = tot;
        assert!(custom(&p, 0) >= 0);
        tick(3);
        assert_eq!(MCC_GetErrorCode(0), 0xF10A);
        assert_eq!(MCC_GetMotionStatus(0), GMS_STOP);
        assert!(p.log.lock().calls.is_empty(), "no interp");
        assert_eq!(p.log.lock().cleanups, 1, "start was called: cleanup too");
        assert_eq!(MCC_ClearError(0), NO_ERR);
    }
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn ex_blending_callbacks_run_over_the_acceleration() {
    let _g = fresh();
    setup("stepped", false);
    let p = Prog::new(straight());
    assert_eq!(MCC_EnableBlend(0), 0);
    let r = MCC_CustomMotionEx(
        Some(on_start),
        Some(on_interp),
        Some(on_cleanup),
        Some(on_blend_start),
        Some(on_blend),
        Some(on_blend_end),
        p.buf(),
        1,
        0,
        IMP_AXIS_ALL,
    );
    assert_eq!(r, 1);
    wait_stop(0);
    let l = p.log.lock();
    assert_eq!(l.blend_starts, 1);
    assert_eq!(l.blend_ends, 1);
    // The interval is the acceleration ramp's distance: F·Ta/2 = 0.5.
    assert!((l.blend_interval - 0.5).abs() < 1e-12);
    // pfnBlending for the calls up to the one reaching 0.5 (t = 0.1: call 100), then
    // pfnInterpolation.
    let blends = l.calls.iter().filter(|c| c.6).count();
    assert_eq!(blends, 100);
    assert!(l.calls[..100].iter().all(|c| c.6));
    assert_eq!(l.cleanups, 1);
    drop(l);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
