//! Robot kinematics through the C entry points (`MCC_SetKinematicTrans`, the V6
//! commands) with a planar two-link arm written here: joint 0 and 1 are the shoulder
//! and the elbow (radians), links of 100 and 80 UU read from the extension buffer the
//! init callback fills; joints 2..7 carry Z, RX, RY, RZ, A, B unchanged. Posture bit 0
//! chooses the elbow: 0 = elbow up (q1 > 0), 1 = elbow down (q1 < 0).
//!
//! The kinematics are registered before the card starts, as the vendor's library takes
//! them. What the program reads of the group (`MCC_GetCurPos`, `MCC_GetPulsePos`) is the
//! joints, whole pulses of 500 per radian; the tool's point is the forward kinematics of
//! them, which the tests compute here. The joints the engine sends each tick during a
//! path command are the inverse kinematics' results, recorded in the callback; the next
//! tick applies them (the channels' pulses are checked too).

mod common;

use common::fresh;
use parking_lot::Mutex;
use std::ffi::c_void;
use std::os::raw::c_int;
use MCCLPCI_IMP::engine::snapshot::whole_pulses;
use MCCLPCI_IMP::ffi::coordinate::*;
use MCCLPCI_IMP::ffi::kinematics::*;
use MCCLPCI_IMP::ffi::motion::*;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::{BOOL, DWORD};

/// The extension the init callback fills: a marker and the two link lengths.
#[repr(C)]
struct Ext {
    zero_at_init: u64,
    l1: f64,
    l2: f64,
}

static INITS: Mutex<u32> = Mutex::new(0);
/// Every inverse call: (Cartesian in, joints out or None, posture, on which thread).
#[allow(clippy::type_complexity)]
static CALLS: Mutex<Vec<([f64; 8], Option<[f64; 8]>, DWORD)>> = Mutex::new(Vec::new());
/// A position read from inside the inverse kinematics (it must not deadlock).
static READ_INSIDE: Mutex<Option<[f64; 8]>> = Mutex::new(None);
static READ_FROM_INV: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);
static PRE: Mutex<Vec<([f64; 8], [f64; 8])>> = Mutex::new(Vec::new());

const L1: f64 = 100.0;
const L2: f64 = 80.0;

unsafe extern "system" fn init_ext(p: *mut c_void) {
    // SAFETY: the library hands a zeroed buffer of size_of::<Ext>() bytes, 16-aligned.
    let e = unsafe { &mut *p.cast::<Ext>() };
    e.zero_at_init = u64::from(e.zero_at_init == 0 && e.l1 == 0.0 && e.l2 == 0.0);
    e.l1 = L1;
    e.l2 = L2;
    *INITS.lock() += 1;
}

fn links(p: *mut c_void) -> (f64, f64) {
    // SAFETY: the extension the library hands to every call (filled by init_ext).
    let e = unsafe { &*p.cast::<Ext>() };
    (e.l1, e.l2)
}

/// The arm's forward kinematics.
fn fwd(q: &[f64; 8], l: (f64, f64)) -> [f64; 8] {
    let mut c = *q;
    c[0] = l.0 * q[0].cos() + l.1 * (q[0] + q[1]).cos();
    c[1] = l.0 * q[0].sin() + l.1 * (q[0] + q[1]).sin();
    c
}

/// The arm's inverse kinematics (law of cosines); `None` out of reach.
fn inv(c: &[f64; 8], posture: DWORD, l: (f64, f64)) -> Option<[f64; 8]> {
    let (x, y) = (c[0], c[1]);
    let c2 = (x * x + y * y - l.0 * l.0 - l.1 * l.1) / (2.0 * l.0 * l.1);
    if !(-1.0..=1.0).contains(&c2) {
        return None;
    }
    let s2 = (1.0 - c2 * c2).sqrt() * if posture & 1 == 1 { -1.0 } else { 1.0 };
    let q2 = s2.atan2(c2);
    let q1 = y.atan2(x) - (l.1 * s2).atan2(l.0 + l.1 * c2);
    let mut q = *c;
    q[0] = q1;
    q[1] = q2;
    Some(q)
}

unsafe extern "system" fn fwd_cb(
    _g: c_int,
    n: c_int,
    from: *const f64,
    to: *mut f64,
    _posture: *mut DWORD,
    ext: *mut c_void,
) -> BOOL {
    assert_eq!(n, 8);
    // SAFETY: eight doubles each.
    let q = unsafe { *from.cast::<[f64; 8]>() };
    // SAFETY: as above.
    unsafe { *to.cast::<[f64; 8]>() = fwd(&q, links(ext)) };
    1
}

unsafe extern "system" fn inv_cb(
    g: c_int,
    n: c_int,
    from: *const f64,
    _prev: *const f64,
    to: *mut f64,
    posture: *mut DWORD,
    ext: *mut c_void,
) -> BOOL {
    assert_eq!(n, 8);
    // SAFETY: eight doubles, and the posture, valid for the call.
    let (c, p) = unsafe { (*from.cast::<[f64; 8]>(), *posture) };
    let r = inv(&c, p, links(ext));
    CALLS.lock().push((c, r, p));
    if READ_FROM_INV.swap(false, std::sync::atomic::Ordering::Relaxed) {
        let mut v = [0.0; 8];
        let [a, b, cc, d, e, f, h, i] = &mut v;
        // SAFETY: eight valid pointers; no library lock is held while this runs.
        let rc = unsafe { MCC_GetCurPos(a, b, cc, d, e, f, h, i, g as u16) };
        assert_eq!(rc, NO_ERR);
        *READ_INSIDE.lock() = Some(v);
    }
    match r {
        Some(q) => {
            // SAFETY: eight doubles.
            unsafe { *to.cast::<[f64; 8]>() = q };
            1
        }
        None => 0,
    }
}

unsafe extern "system" fn pre_cb(
    _g: c_int,
    _n: c_int,
    cur: *const f64,
    tgt: *const f64,
    off: *mut f64,
    _ext: *mut c_void,
) {
    // SAFETY: eight doubles each.
    unsafe {
        PRE.lock()
            .push((*cur.cast::<[f64; 8]>(), *tgt.cast::<[f64; 8]>()));
        *off.add(1) = 10.0;
    }
}

fn cur_pos(g: u16) -> [f64; 8] {
    let mut p = [0.0; 8];
    let [a, b, c, d, e, f, h, i] = &mut p;
    // SAFETY: eight valid pointers.
    assert_eq!(unsafe { MCC_GetCurPos(a, b, c, d, e, f, h, i, g) }, NO_ERR);
    p
}

fn pulses(g: u16) -> [i64; 8] {
    let mut p = [0 as std::os::raw::c_long; 8];
    let [a, b, c, d, e, f, h, i] = &mut p;
    assert_eq!(
        // SAFETY: eight valid pointers.
        unsafe { MCC_GetPulsePos(a, b, c, d, e, f, h, i, g) },
        NO_ERR
    );
    p.map(i64::from)
}

/// Polls the status (each poll on a virtual clock lets time run) until the group stops.
fn wait_stop(g: u16) {
    for _ in 0..10_000_000 {
        if MCC_GetMotionStatus(g) == GMS_STOP {
            return;
        }
    }
    panic!("group {g} did not stop");
}

/// Default mechanism: 500 pulses per UU (here per radian for the arm's joints), whole
/// pulses as the card counts them.
fn joint_pulses(q: &[f64; 8]) -> [i64; 8] {
    q.map(|x| whole_pulses(x * 500.0))
}

/// The joints of the last inverse kinematics call (the joints the channels carry once
/// a path command ended).
fn last_joints() -> [f64; 8] {
    CALLS
        .lock()
        .last()
        .and_then(|c| c.1)
        .expect("a good last call")
}

/// Registers the arm's kinematics for group 0 (before the card starts).
fn register_arm() {
    let size = std::mem::size_of::<Ext>() as DWORD;
    assert_eq!(
        MCC_SetKinematicTrans(Some(fwd_cb), Some(inv_cb), size, Some(init_ext), 0),
        NO_ERR
    );
}

/// Starts a system (clock `clock`, 1 ms) with group 0 a kinematic arm at joints 0
/// (stretched along +X: Cartesian (180, 0)), then moves its joints to (0, π/2):
/// Cartesian (100 + 80·cos(π/2), 80) = (100, 80).
fn start_arm(clock: &str) {
    std::env::set_var("MCCL_CLOCK", clock);
    CALLS.lock().clear();
    PRE.lock().clear();
    *INITS.lock() = 0;
    register_arm();
    assert_eq!(*INITS.lock(), 0, "initialised when the card starts");
    assert_eq!(common::init(1), NO_ERR);
    assert_eq!(*INITS.lock(), 1, "the extension is initialised once");
    assert_eq!(cur_pos(0), [0.0; 8], "the joints");
    assert_eq!(MCC_SetFeedSpeed(100.0, 0), 100.0);
    assert_eq!(MCC_SetAccTime(50.0, 0), NO_ERR);
    assert_eq!(MCC_SetDecTime(50.0, 0), NO_ERR);
    let h = std::f64::consts::FRAC_PI_2;
    assert!(MCC_PtP_V6(0.0, h, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL) >= 0);
    wait_stop(0);
    // π/2 · 500 = 785.398...: 785 whole pulses; the position read is the joints'.
    assert_eq!(pulses(0)[..2], [0, 785]);
    let p = cur_pos(0);
    assert_eq!((p[0], p[1]), (0.0, 785.0 / 500.0), "{p:?}");
    assert!(
        CALLS.lock().is_empty(),
        "a joint move needs no inverse kinematics"
    );
}

/// Along a line, every joint vector sent is on the line (its forward kinematics within
/// 1e-9 of the line's length from it), moving forward; the end joints are inv(target).
fn line_is_straight(clock: &str) -> Vec<[f64; 8]> {
    start_arm(clock);
    CALLS.lock().clear();
    // From (100, 80) to (150, 20): length sqrt(50² + 60²) = 78.10...
    let (a, b) = ([100.0, 80.0], [150.0, 20.0]);
    assert!(MCC_Line_V6(b[0], b[1], 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, 0, IMP_AXIS_ALL) >= 0);
    wait_stop(0);
    let calls = CALLS.lock().clone();
    let len = (b[0] - a[0]).hypot(b[1] - a[1]);
    let dir = [(b[0] - a[0]) / len, (b[1] - a[1]) / len];
    let mut last_t = -1e-12;
    let mut out = Vec::new();
    // 78.1 UU at 100 UU/s with 50 ms ramps: 0.781 + 0.05 s ≈ 831 ticks, one call each.
    assert!((800..900).contains(&calls.len()), "{} calls", calls.len());
    for (c, q, posture) in &calls {
        let q = q.expect("reachable all along");
        assert_eq!(*posture, 0);
        let p = fwd(&q, (L1, L2));
        let (dx, dy) = (p[0] - a[0], p[1] - a[1]);
        let off_line = (dx * dir[1] - dy * dir[0]).abs();
        assert!(off_line <= 1e-9 * len, "{off_line} off the line at {c:?}");
        let t = dx * dir[0] + dy * dir[1];
        assert!(t >= last_t, "moves forward");
        last_t = t;
        out.push(q);
    }
    let end = inv(&[150.0, 20.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], 0, (L1, L2)).unwrap();
    assert_eq!(
        calls.last().unwrap().1.unwrap(),
        end,
        "end joints = inv(target)"
    );
    assert_eq!(
        pulses(0),
        joint_pulses(&end),
        "the channels carry the end joints"
    );
    assert_eq!(cur_pos(0), joint_pulses(&end).map(|p| p as f64 / 500.0));
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    out
}

#[test]
fn line_v6_joints_lie_on_the_line_stepped_and_fast_alike() {
    let _g = fresh();
    let stepped = line_is_straight("stepped");
    let fast = line_is_straight("fast");
    assert_eq!(stepped, fast, "the same joints under both clocks");
}

#[test]
fn unreachable_target_stops_with_f106_without_a_joint_jump() {
    let _g = fresh();
    start_arm("stepped");
    CALLS.lock().clear();
    // (100, 80) → (250, 80): out of reach (180) at x = sqrt(180² − 80²) = 161.2.
    assert!(
        MCC_Line_V6(
            250.0,
            80.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0,
            0,
            IMP_AXIS_ALL
        ) >= 0
    );
    wait_stop(0);
    assert_eq!(MCC_GetErrorCode(0), 0xF106);
    let calls = CALLS.lock().clone();
    let (fail, good) = (calls[calls.len() - 1], calls[calls.len() - 2]);
    assert!(fail.1.is_none() && fail.0[0] > 161.0);
    let good = good.1.unwrap();
    assert_eq!(
        pulses(0),
        joint_pulses(&good),
        "joints stay at the last good value"
    );
    // No further call, no motion, while the error stands.
    let n = calls.len();
    for _ in 0..100 {
        MCC_GetMotionStatus(0);
    }
    assert_eq!(CALLS.lock().len(), n);
    assert_eq!(pulses(0), joint_pulses(&good));
    // After MCC_ClearError the arm moves on from there.
    assert_eq!(MCC_ClearError(0), NO_ERR);
    assert!(
        MCC_Line_V6(
            100.0,
            80.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0,
            0,
            IMP_AXIS_ALL
        ) >= 0
    );
    wait_stop(0);
    // From where the arm stopped (the last good point): back at (100, 80).
    let t = fwd(&last_joints(), (L1, L2));
    assert!(
        (t[0] - 100.0).abs() < 1e-9 && (t[1] - 80.0).abs() < 1e-9,
        "{t:?}"
    );
    assert_eq!(pulses(0), joint_pulses(&last_joints()));
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn elbow_down_posture_keeps_the_elbow_down_and_callbacks_may_read_positions() {
    let _g = fresh();
    start_arm("stepped");
    // Elbow down at (100, 80): the mirror of the current joints about the line to it.
    let down = inv(&[100.0, 80.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], 1, (L1, L2)).unwrap();
    assert!(
        MCC_PtP_V6(
            down[0],
            down[1],
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0,
            IMP_AXIS_ALL
        ) >= 0
    );
    wait_stop(0);
    CALLS.lock().clear();
    READ_FROM_INV.store(true, std::sync::atomic::Ordering::Relaxed);
    assert!(MCC_Line_V6(120.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1, 0, IMP_AXIS_ALL) >= 0);
    wait_stop(0);
    let calls = CALLS.lock().clone();
    assert!(calls.iter().all(|(_, q, p)| *p == 1 && q.unwrap()[1] < 0.0));
    let read = READ_INSIDE
        .lock()
        .take()
        .expect("read from inside the callback");
    // The first call ran after the first tick of the line: the joints still at the
    // elbow-down pose (whole pulses).
    assert_eq!(read, joint_pulses(&down).map(|p| p as f64 / 500.0));
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn pre_process_offset_moves_the_target() {
    let _g = fresh();
    start_arm("stepped");
    assert_eq!(
        MCC_SetPreProcessMotionCommandCallback(Some(pre_cb), 0),
        NO_ERR
    );
    assert!(
        MCC_Line_V6(
            150.0,
            20.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0,
            0,
            IMP_AXIS_ALL
        ) >= 0
    );
    wait_stop(0);
    let pre = PRE.lock().clone();
    assert_eq!(pre.len(), 1, "called once, when the line is taken");
    assert_eq!((pre[0].0[0], pre[0].0[1]), (100.0, 80.0));
    assert_eq!((pre[0].1[0], pre[0].1[1]), (150.0, 20.0));
    // The offset (0, 10) is added: the arm ends at (150, 30).
    let t = fwd(&last_joints(), (L1, L2));
    assert!(
        (t[0] - 150.0).abs() < 1e-9 && (t[1] - 30.0).abs() < 1e-9,
        "{t:?}"
    );
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn bad_arguments_are_refused_and_change_nothing() {
    let _g = fresh();
    let size = std::mem::size_of::<Ext>() as DWORD;
    // Before the card starts: NULL callbacks, bad groups, an absurd extension size.
    assert_eq!(
        MCC_SetKinematicTrans(None, Some(inv_cb), size, None, 0),
        PARAMETER_ERR
    );
    assert_eq!(
        MCC_SetKinematicTrans(Some(fwd_cb), None, size, None, 0),
        PARAMETER_ERR
    );
    assert_eq!(
        MCC_SetKinematicTrans(Some(fwd_cb), Some(inv_cb), size, Some(init_ext), -1),
        GROUP_PARAMETER_ERR
    );
    assert_eq!(
        MCC_SetKinematicTrans(Some(fwd_cb), Some(inv_cb), size, Some(init_ext), 96),
        GROUP_PARAMETER_ERR
    );
    assert_eq!(
        MCC_SetKinematicTrans(Some(fwd_cb), Some(inv_cb), 1 << 30, Some(init_ext), 0),
        PARAMETER_ERR
    );
    // None of them registered anything: the group starts without kinematics.
    assert_eq!(common::init(1), NO_ERR);
    // Once the card runs, registering is refused, as the vendor's library does.
    assert_eq!(
        MCC_SetKinematicTrans(Some(fwd_cb), Some(inv_cb), size, Some(init_ext), 0),
        RUN_TIME_ERR
    );
    assert_eq!(
        MCC_SetPreProcessMotionCommandCallback(Some(pre_cb), 0),
        COMMAND_NOTACCEPTED_ERR
    );
    // Not kinematic: MCC_PtP_V6 is a synchronised PtP of the axes.
    assert_eq!(
        MCC_PtP_V6(0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL),
        0
    );
    wait_stop(0);
    assert_eq!(pulses(0)[..2], [0, 500]);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    *INITS.lock() = 0;
    register_arm();
    assert_eq!(common::init(1), NO_ERR);
    assert_eq!(*INITS.lock(), 1);
    // NaN and a bad mask: refused, nothing queued.
    let nan = f64::NAN;
    assert_eq!(
        MCC_Line_V6(nan, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, 0, IMP_AXIS_ALL),
        PARAMETER_ERR
    );
    assert_eq!(
        MCC_Line_V6(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, 0, 0x100),
        PARAMETER_ERR
    );
    assert_eq!(
        MCC_PtP_V6(0.0, nan, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL),
        PARAMETER_ERR
    );
    assert_eq!(
        MCC_ArcTheta_V6(
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            90.0,
            0.0,
            0.0,
            0.0,
            0,
            0,
            IMP_AXIS_ALL
        ),
        0,
        "zero normal: queued, as the vendor's library takes an arc with no geometry"
    );
    // It fails as it starts: 0xF104, the arm where it was.
    for _ in 0..1000 {
        if MCC_GetErrorCode(0) != 0 {
            break;
        }
        MCC_GetMotionStatus(0);
    }
    assert_eq!(
        MCC_GetErrorCode(0),
        0xF104,
        "a degenerate arc records 0xF104"
    );
    assert_eq!(MCC_ClearError(0), NO_ERR);
    assert_eq!(
        MCC_Line_V6(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, 7, IMP_AXIS_ALL),
        GROUP_PARAMETER_ERR
    );
    let mut n: c_int = -1;
    // SAFETY: a valid pointer.
    assert_eq!(unsafe { MCC_GetCommandCount(&mut n, 0) }, NO_ERR);
    assert_eq!(n, 0, "nothing queued");
    assert_eq!(MCC_GetMotionStatus(0), GMS_STOP);
    assert_eq!(cur_pos(0), [0.0; 8]);
    assert_eq!(pulses(0), [0; 8]);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

/// The registration is used up by the init that applies it: the next init (after a
/// close) runs without kinematics unless the program registers them again.
#[test]
fn a_registration_serves_one_init() {
    let _g = fresh();
    *INITS.lock() = 0;
    register_arm();
    assert_eq!(common::init(1), NO_ERR);
    assert_eq!(
        MCC_SetPreProcessMotionCommandCallback(Some(pre_cb), 0),
        NO_ERR
    );
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    assert_eq!(common::init(1), NO_ERR);
    assert_eq!(
        MCC_SetPreProcessMotionCommandCallback(Some(pre_cb), 0),
        COMMAND_NOTACCEPTED_ERR,
        "not kinematic"
    );
    assert_eq!(*INITS.lock(), 1);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
