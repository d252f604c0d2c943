//! Robot kinematics as the vendor's library takes them (recorded scenarios
//! `kine_ptp_v6`, `kine_after_init`): `MCC_SetKinematicTrans` before the card starts is
//! accepted and applied by the init (the extension's initialiser runs there), after it
//! `RUN_TIME_ERR`; a kinematic group reads its joints, and `MCC_PtP_V6` moves them as
//! `MCC_SyncPtP` moves the axes of any group, period for period.
//!
//! The machine: the default mechanism (500 pulses per UU, 3000 rpm, pitch 1: PtP speed
//! at 100 % is 50 UU/s), 1 ms periods, stepped clock. Group 0 (channels 0..2) is a
//! two-link arm (links 200 and 150, joints in degrees, joint 2 is Z); group 1
//! (channels 3..5) has no kinematics. Both move to (22, −81, 5) at the same time, at
//! 100 % PtP speed with 100 ms T-ramps; a cycle routine records what a program reads of
//! each group every period.

mod common;

use common::fresh;
use parking_lot::Mutex;
use std::ffi::c_void;
use std::os::raw::{c_int, c_long};
use MCCLPCI_IMP::ffi::coordinate::*;
use MCCLPCI_IMP::ffi::filters::MCC_SetCycleInterruptRoutine;
use MCCLPCI_IMP::ffi::kinematics::*;
use MCCLPCI_IMP::ffi::motion::*;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::MCC_TimeDelay;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::{BOOL, COMMAND_INFO, DWORD};

static INITS: Mutex<u32> = Mutex::new(0);

unsafe extern "system" fn init_ext(_p: *mut c_void) {
    *INITS.lock() += 1;
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
    let q = unsafe { *from.cast::<[f64; 8]>() };
    let (a, b) = (q[0].to_radians(), (q[0] + q[1]).to_radians());
    let mut c = q;
    c[0] = 200.0 * a.cos() + 150.0 * b.cos();
    c[1] = 200.0 * a.sin() + 150.0 * b.sin();
    // SAFETY: as above.
    unsafe { *to.cast::<[f64; 8]>() = c };
    1
}

unsafe extern "system" fn inv_cb(
    _g: c_int,
    _n: c_int,
    _from: *const f64,
    _prev: *const f64,
    _to: *mut f64,
    _posture: *mut DWORD,
    _ext: *mut c_void,
) -> BOOL {
    // Point-to-point moves never ask for it.
    panic!("no inverse kinematics in a joint move");
}

/// What a program reads of one group in one period.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Read {
    status: c_int,
    pos: [f64; 8],
    pulses: [c_long; 8],
    speed: [f64; 8],
    feed: f64,
    cmd: (c_int, c_int, f64, c_int, [f64; 8]),
}

fn read(g: u16) -> Read {
    let mut pos = [0.0; 8];
    let mut pulses: [c_long; 8] = [0; 8];
    let mut speed = [0.0; 8];
    let mut k = COMMAND_INFO::default();
    // SAFETY: valid pointers throughout.
    unsafe {
        let [a, b, c, d, e, f, h, i] = &mut pos;
        assert_eq!(MCC_GetCurPos(a, b, c, d, e, f, h, i, g), NO_ERR);
        let [a, b, c, d, e, f, h, i] = &mut pulses;
        assert_eq!(MCC_GetPulsePos(a, b, c, d, e, f, h, i, g), NO_ERR);
        let [a, b, c, d, e, f, h, i] = &mut speed;
        assert_eq!(MCC_GetSpeed(a, b, c, d, e, f, h, i, g), NO_ERR);
        MCC_GetCurCommand(&mut k, g);
    }
    Read {
        status: MCC_GetMotionStatus(g),
        pos,
        pulses,
        speed,
        feed: MCC_GetCurFeedSpeed(g),
        cmd: (
            k.nType,
            k.nCommandIndex,
            k.dfFeedSpeed,
            k.nMotionPhase,
            k.dfPos,
        ),
    }
}

/// Every period: (group 0, group 1).
static PERIODS: Mutex<Vec<(Read, Read)>> = Mutex::new(Vec::new());

extern "system" fn cycle() {
    let r = (read(0), read(1));
    PERIODS.lock().push(r);
}

#[test]
fn registered_before_init_and_the_joints_move_as_a_sync_ptp() {
    let _g = fresh();
    assert_eq!(MCC_CloseAllGroups(), NO_ERR);
    assert_eq!(MCC_CreateGroup(0, 1, 2, -1, -1, -1, -1, -1, 0), 0);
    assert_eq!(MCC_CreateGroup(3, 4, 5, -1, -1, -1, -1, -1, 0), 1);
    assert_eq!(
        MCC_SetKinematicTrans(Some(fwd_cb), Some(inv_cb), 16, Some(init_ext), 0),
        NO_ERR
    );
    assert_eq!(*INITS.lock(), 0, "not before the card starts");
    assert_eq!(common::init(1), NO_ERR);
    assert_eq!(*INITS.lock(), 1, "once, by the init");
    assert_eq!(
        MCC_SetKinematicTrans(Some(fwd_cb), Some(inv_cb), 16, Some(init_ext), 0),
        RUN_TIME_ERR
    );
    for g in 0..2 {
        assert_eq!(MCC_SetPtPSpeed(100.0, g), 100.0);
        assert_eq!(MCC_SetAccType(b'T' as std::os::raw::c_char, g), NO_ERR);
        assert_eq!(MCC_SetDecType(b'T' as std::os::raw::c_char, g), NO_ERR);
        assert_eq!(MCC_SetAccTime(100.0, g), NO_ERR);
        assert_eq!(MCC_SetDecTime(100.0, g), NO_ERR);
    }
    PERIODS.lock().clear();
    assert_eq!(MCC_SetCycleInterruptRoutine(Some(cycle)), NO_ERR);
    assert_eq!(
        MCC_PtP_V6(22.0, -81.0, 5.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL),
        0
    );
    assert_eq!(
        MCC_SyncPtP(22.0, -81.0, 5.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1, IMP_AXIS_ALL),
        0
    );
    // 81 UU at 50 UU/s with 100 ms ramps: 1.62 s + 0.1 s = 1720 periods, then the
    // status lag; 2000 periods see it all.
    MCC_TimeDelay(2000);
    assert_eq!(MCC_SetCycleInterruptRoutine(None), NO_ERR);
    let periods = PERIODS.lock().clone();
    assert!(periods.len() >= 2000);
    for (n, (robot, plain)) in periods.iter().enumerate() {
        assert_eq!(
            robot, plain,
            "period {n}: the robot reads as a SyncPtP group"
        );
    }
    let (end, _) = periods[1900];
    assert_eq!(end.status, GMS_STOP);
    assert_eq!(
        &end.pos[..3],
        &[22.0, -81.0, 5.0],
        "the joints, not the tool"
    );
    assert_eq!(&end.pulses[..3], &[11_000, -40_500, 2_500]);
    // Half way (period 860, at speed): the joints, which a tool on the arc between
    // cannot be (its X would be near 300).
    let (mid, _) = periods[860];
    assert!(mid.pos[0] > 5.0 && mid.pos[0] < 17.0, "{:?}", mid.pos);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
