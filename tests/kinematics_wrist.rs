//! Robot kinematics through the C entry points with a Cartesian robot carrying a rotary
//! wrist, written here: joints 0..2 are the wrist's X, Y, Z (UU), joint 5 its angle
//! (degrees, in the W channel); the tool point sits D = 10 UU from the wrist axis, so
//! the tool is at (x + D·cos θ, y + D·sin θ, z) with orientation RZ = θ. The V6 moves
//! turn the wrist while the tool point follows the line, arc or circle; the orientation
//! is interpolated linearly with the path (docs/compatibility.md, "Robot kinematics").
//! The kinematics are registered before the card starts; what the program reads of the
//! group is the joints, and the tool's point is their forward kinematics, computed here.
//! Runs on the fast clock.

mod common;

use common::fresh;
use parking_lot::Mutex;
use std::ffi::c_void;
use std::os::raw::c_int;
use MCCLPCI_IMP::ffi::coordinate::*;
use MCCLPCI_IMP::ffi::kinematics::*;
use MCCLPCI_IMP::ffi::motion::*;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::{BOOL, DWORD};

const D: f64 = 10.0;

/// Every inverse call: (Cartesian in, joints out).
static CALLS: Mutex<Vec<([f64; 8], [f64; 8])>> = Mutex::new(Vec::new());

fn fwd(q: &[f64; 8]) -> [f64; 8] {
    let mut c = *q;
    let t = q[5].to_radians();
    c[0] = q[0] + D * t.cos();
    c[1] = q[1] + D * t.sin();
    c
}

fn inv(c: &[f64; 8]) -> [f64; 8] {
    let mut q = *c;
    let t = c[5].to_radians();
    q[0] = c[0] - D * t.cos();
    q[1] = c[1] - D * t.sin();
    q
}

unsafe extern "system" fn fwd_cb(
    _g: c_int,
    _n: c_int,
    from: *const f64,
    to: *mut f64,
    _posture: *mut DWORD,
    _ext: *mut c_void,
) -> BOOL {
    // SAFETY: eight doubles each.
    unsafe { *to.cast::<[f64; 8]>() = fwd(&*from.cast::<[f64; 8]>()) };
    1
}

unsafe extern "system" fn inv_cb(
    _g: c_int,
    _n: c_int,
    from: *const f64,
    _prev: *const f64,
    to: *mut f64,
    _posture: *mut DWORD,
    _ext: *mut c_void,
) -> BOOL {
    // SAFETY: eight doubles each.
    let c = unsafe { *from.cast::<[f64; 8]>() };
    let q = inv(&c);
    CALLS.lock().push((c, q));
    // SAFETY: eight doubles.
    unsafe { *to.cast::<[f64; 8]>() = q };
    1
}

/// The tool's point: the forward kinematics of the joints the last move ended with.
fn tool() -> [f64; 8] {
    fwd(&CALLS.lock().last().expect("a move ran").1)
}

fn cur_pos() -> [f64; 8] {
    let mut p = [0.0; 8];
    let [a, b, c, d, e, f, h, i] = &mut p;
    // SAFETY: eight valid pointers.
    assert_eq!(unsafe { MCC_GetCurPos(a, b, c, d, e, f, h, i, 0) }, NO_ERR);
    p
}

fn pulses() -> [i64; 8] {
    let mut p = [0 as std::os::raw::c_long; 8];
    let [a, b, c, d, e, f, h, i] = &mut p;
    assert_eq!(
        // SAFETY: eight valid pointers.
        unsafe { MCC_GetPulsePos(a, b, c, d, e, f, h, i, 0) },
        NO_ERR
    );
    p.map(i64::from)
}

fn wait_stop() {
    for _ in 0..10_000_000 {
        if MCC_GetMotionStatus(0) == GMS_STOP {
            return;
        }
    }
    panic!("did not stop");
}

/// Runs a queued move and returns the inverse calls it made.
fn run() -> Vec<([f64; 8], [f64; 8])> {
    CALLS.lock().clear();
    wait_stop();
    assert_eq!(MCC_GetErrorCode(0), 0);
    CALLS.lock().clone()
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

#[test]
fn wrist_turns_while_the_tool_follows_lines_arcs_and_circles() {
    let _g = fresh();
    std::env::set_var("MCCL_CLOCK", "fast");
    assert_eq!(
        MCC_SetKinematicTrans(Some(fwd_cb), Some(inv_cb), 0, None, 0),
        NO_ERR
    );
    assert_eq!(common::init(1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(100.0, 0), 100.0);
    // Joints 0: the tool at (10, 0, 0), RZ 0; the group reads its joints.
    assert_eq!(cur_pos(), [0.0; 8]);

    // Line to (110, 0) turning RZ 0 → 90: per component linear, so at tool x the angle
    // is 90·(x − 10)/100; the tool stays on y = 0 (within 1e-9 of the length, 100).
    assert!(
        MCC_Line_V6(
            110.0,
            0.0,
            0.0,
            0.0,
            0.0,
            90.0,
            0.0,
            0.0,
            0,
            0,
            IMP_AXIS_ALL
        ) >= 0
    );
    let calls = run();
    assert!(calls.len() > 100);
    for (c, q) in &calls {
        let p = fwd(q);
        assert!(close(p[1], 0.0, 1e-9 * 100.0), "{p:?} off the line");
        assert!(
            close(p[5], 90.0 * (p[0] - D) / 100.0, 1e-9 * 100.0),
            "{p:?}"
        );
        assert_eq!(p[5], c[5]);
    }
    let end = inv(&[110.0, 0.0, 0.0, 0.0, 0.0, 90.0, 0.0, 0.0]);
    assert_eq!(calls.last().unwrap().1, end);
    // Pulses (500 per UU / degree): wrist at (110 − 10·cos 90°, −10), θ = 90.
    let p = pulses();
    assert_eq!((p[0], p[1], p[5]), (55_000, -5_000, 45_000));
    assert_eq!(
        cur_pos(),
        p.map(|x| x as f64 / 500.0),
        "the joints, whole pulses"
    );
    let c = tool();
    assert!(close(c[0], 110.0, 1e-12) && close(c[1], 0.0, 1e-12) && c[5] == 90.0);

    // Full circle about (60, 0) counter-clockwise, RZ 90 → 450: every tool point 50
    // from the center, the angle linear in the arc length (2π·50 = 314.16).
    assert!(MCC_CircleXY_V6(60.0, 0.0, 0.0, 0.0, 450.0, CIR_CCW as u8, 0, 0) >= 0);
    let calls = run();
    let len = std::f64::consts::TAU * 50.0;
    let mut last = 90.0;
    for (_, q) in &calls {
        let p = fwd(q);
        let r = (p[0] - 60.0).hypot(p[1]);
        assert!(close(r, 50.0, 1e-9 * len), "radius {r}");
        assert!(p[5] >= last, "the wrist turns one way");
        last = p[5];
        // Counter-clockwise from (110, 0): the polar angle of the tool point, unwrapped,
        // is the fraction of the turn; RZ = 90 + 360·fraction.
        let mut phi = p[1].atan2(p[0] - 60.0).to_degrees();
        if phi < -1e-6 || (phi < 1e-6 && p[5] > 270.0) {
            phi += 360.0;
        }
        assert!(close(p[5], 90.0 + phi, 1e-6), "{} vs {}", p[5], 90.0 + phi);
    }
    let c = tool();
    assert!(close(c[0], 110.0, 1e-9) && close(c[1], 0.0, 1e-9) && c[5] == 450.0);

    // ArcTheta_V6: 90° about the axis through (60, 0, 0) along +Z: to (60, 50), RZ → 540.
    assert!(
        MCC_ArcTheta_V6(
            60.0,
            0.0,
            0.0,
            0.0,
            0.0,
            1.0,
            90.0,
            0.0,
            0.0,
            540.0,
            0,
            0,
            IMP_AXIS_ALL
        ) >= 0
    );
    run();
    let c = tool();
    assert!(close(c[0], 60.0, 1e-9) && close(c[1], 50.0, 1e-9) && c[5] == 540.0);

    // Circle_V6 from (60, 50) through (10, 0) and (60, −50): the same circle, one turn.
    assert!(
        MCC_Circle_V6(
            10.0,
            0.0,
            0.0,
            60.0,
            -50.0,
            0.0,
            0.0,
            0.0,
            540.0,
            0,
            0,
            IMP_AXIS_ALL
        ) >= 0
    );
    for (_, q) in run() {
        let p = fwd(&q);
        assert!(close((p[0] - 60.0).hypot(p[1]), 50.0, 1e-9 * len));
        assert_eq!(p[5], 540.0, "RZ stays");
    }
    let c = tool();
    assert!(close(c[0], 60.0, 1e-9) && close(c[1], 50.0, 1e-9));

    // Arc_V6 from (60, 50) through (110, 0) to (60, −50), RZ 540 → 450; mask without RZ:
    // RZ stays.
    let no_rz = IMP_AXIS_ALL & !IMP_AXIS_W;
    assert!(MCC_Arc_V6(110.0, 0.0, 0.0, 60.0, -50.0, 0.0, 0.0, 0.0, 450.0, 0, 0, no_rz) >= 0);
    for (_, q) in run() {
        let p = fwd(&q);
        assert!(close((p[0] - 60.0).hypot(p[1]), 50.0, 1e-9 * len));
        assert!(p[0] >= 60.0 - 1e-9, "through (110, 0), the right half");
        assert_eq!(p[5], 540.0);
    }
    let c = tool();
    assert!(close(c[0], 60.0, 1e-9) && close(c[1], -50.0, 1e-9) && c[5] == 540.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
