//! Straight moves: a line of the axes in the mask at the feed speed, point-to-point
//! motion (each axis its own profile, or all synchronised), and their one-axis forms.

use crate::error::McclResult;
use crate::ffi::{axis_mask, finite8, queue};
use crate::vendor::consts as c;
use crate::vendor::{DWORD, WORD};
use std::os::raw::c_int;

fn ptp(args: [f64; 8], g: WORD, m: DWORD, sync: bool) -> McclResult<c_int> {
    let args = finite8(args)?;
    let m = axis_mask(m)?;
    // A kinematic group's PtP moves its joints.
    if let Some(i) = crate::ffi::kinematics::joint_ptp(args, g, m, sync)? {
        return Ok(i);
    }
    queue(g, |ctx| {
        ctx.ptp(ctx.resolve(&args, m), ctx.settings.ptp_ratio, sync)
    })
}

fn one(axis: usize, v: f64) -> [f64; 8] {
    let mut a = [0.0; 8];
    a[axis] = v;
    a
}

fn line(args: [f64; 8], g: WORD, m: DWORD) -> McclResult<c_int> {
    let args = finite8(args)?;
    let m = axis_mask(m)?;
    queue(g, |ctx| ctx.line(ctx.resolve(&args, m)))
}

/// Point-to-point motion: every axis in the mask runs its own profile at the PtP ratio;
/// axes start together and need not arrive together. Returns the command index.
#[no_mangle]
pub extern "system" fn MCC_PtP(
    dfX0: f64,
    dfX1: f64,
    dfX2: f64,
    dfX3: f64,
    dfX4: f64,
    dfX5: f64,
    dfX6: f64,
    dfX7: f64,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> c_int {
    ffi_boundary! {
        let args = [dfX0, dfX1, dfX2, dfX3, dfX4, dfX5, dfX6, dfX7];
        ptp(args, wGroupIndex, dwAxisMask, false)
    }
}

/// Synchronised point-to-point motion: all axes start and end together, paced by the
/// slowest. Returns the command index.
#[no_mangle]
pub extern "system" fn MCC_SyncPtP(
    dfX0: f64,
    dfX1: f64,
    dfX2: f64,
    dfX3: f64,
    dfX4: f64,
    dfX5: f64,
    dfX6: f64,
    dfX7: f64,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> c_int {
    ffi_boundary! {
        let args = [dfX0, dfX1, dfX2, dfX3, dfX4, dfX5, dfX6, dfX7];
        ptp(args, wGroupIndex, dwAxisMask, true)
    }
}

/// Linear motion of the axes in the mask at the feed speed (only X/Y/Z count for the
/// path speed; U..B start and end with them). Returns the command index.
#[no_mangle]
pub extern "system" fn MCC_Line(
    dfX0: f64,
    dfX1: f64,
    dfX2: f64,
    dfX3: f64,
    dfX4: f64,
    dfX5: f64,
    dfX6: f64,
    dfX7: f64,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> c_int {
    ffi_boundary! {
        let args = [dfX0, dfX1, dfX2, dfX3, dfX4, dfX5, dfX6, dfX7];
        line(args, wGroupIndex, dwAxisMask)
    }
}

/// Point-to-point motion of X alone.
#[no_mangle]
pub extern "system" fn MCC_PtPX(dfX: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(0, dfX), wGroupIndex, c::IMP_AXIS_X, false) }
}

/// Point-to-point motion of Y alone.
#[no_mangle]
pub extern "system" fn MCC_PtPY(dfY: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(1, dfY), wGroupIndex, c::IMP_AXIS_Y, false) }
}

/// Point-to-point motion of Z alone.
#[no_mangle]
pub extern "system" fn MCC_PtPZ(dfZ: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(2, dfZ), wGroupIndex, c::IMP_AXIS_Z, false) }
}

/// Point-to-point motion of U alone.
#[no_mangle]
pub extern "system" fn MCC_PtPU(dfU: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(3, dfU), wGroupIndex, c::IMP_AXIS_U, false) }
}

/// Point-to-point motion of V alone.
#[no_mangle]
pub extern "system" fn MCC_PtPV(dfV: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(4, dfV), wGroupIndex, c::IMP_AXIS_V, false) }
}

/// Point-to-point motion of W alone.
#[no_mangle]
pub extern "system" fn MCC_PtPW(dfW: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(5, dfW), wGroupIndex, c::IMP_AXIS_W, false) }
}

/// Point-to-point motion of A alone.
#[no_mangle]
pub extern "system" fn MCC_PtPA(dfA: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(6, dfA), wGroupIndex, c::IMP_AXIS_A, false) }
}

/// Point-to-point motion of B alone.
#[no_mangle]
pub extern "system" fn MCC_PtPB(dfB: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(7, dfB), wGroupIndex, c::IMP_AXIS_B, false) }
}

/// Linear motion of X alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineX(dfX: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(0, dfX), wGroupIndex, c::IMP_AXIS_X) }
}

/// Linear motion of Y alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineY(dfY: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(1, dfY), wGroupIndex, c::IMP_AXIS_Y) }
}

/// Linear motion of Z alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineZ(dfZ: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(2, dfZ), wGroupIndex, c::IMP_AXIS_Z) }
}

/// Linear motion of U alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineU(dfU: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(3, dfU), wGroupIndex, c::IMP_AXIS_U) }
}

/// Linear motion of V alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineV(dfV: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(4, dfV), wGroupIndex, c::IMP_AXIS_V) }
}

/// Linear motion of W alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineW(dfW: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(5, dfW), wGroupIndex, c::IMP_AXIS_W) }
}

/// Linear motion of A alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineA(dfA: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(6, dfA), wGroupIndex, c::IMP_AXIS_A) }
}

/// Linear motion of B alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineB(dfB: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(7, dfB), wGroupIndex, c::IMP_AXIS_B) }
}
