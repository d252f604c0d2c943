//! Point-to-point acc/dec settings per axis (user manual §2.6.2 II; vendor header
//! "Point-to-Point Motion").

use super::{shape, shape_code, with_group, write_outs};

/// A shape as a `char` output: 0 'T', 1 'S'.
fn shape_byte(s: crate::planner::Shape) -> c_char {
    shape_code(s) as c_char
}
use crate::engine::command::Settings;
use crate::error::{McclError, McclResult};
use crate::vendor::WORD;
use std::os::raw::c_char;
use std::os::raw::c_int;

fn shapes(v: [c_char; 8]) -> Result<[crate::planner::Shape; 8], McclError> {
    let mut out = [crate::planner::Shape::T; 8];
    for (o, c) in out.iter_mut().zip(v) {
        *o = shape(c)?;
    }
    Ok(out)
}

fn times(v: [f64; 8]) -> Result<[f64; 8], McclError> {
    v.iter()
        .try_for_each(|&t| crate::config::range::time_ms(t).map(|_| ()))?;
    Ok(v)
}

/// Stores the per-axis values `v` (an error if the check refused them) in the PtP setting
/// `field` of group `g`.
fn set_ptp<T>(
    g: WORD,
    v: McclResult<[T; 8]>,
    field: impl FnOnce(&mut Settings) -> &mut [T; 8],
) -> McclResult<c_int> {
    let v = v?;
    super::update_group(g, |grp| *field(grp.settings_mut()) = v)
}

/// PtP acceleration shape per axis ('T' or 'S').
#[no_mangle]
pub extern "system" fn MCC_SetPtPAccType(
    v0: c_char,
    v1: c_char,
    v2: c_char,
    v3: c_char,
    v4: c_char,
    v5: c_char,
    v6: c_char,
    v7: c_char,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let v = [v0, v1, v2, v3, v4, v5, v6, v7];
        set_ptp(wGroupIndex, shapes(v), |s| &mut s.ptp_acc)
    }
}

/// PtP deceleration shape per axis ('T' or 'S').
#[no_mangle]
pub extern "system" fn MCC_SetPtPDecType(
    v0: c_char,
    v1: c_char,
    v2: c_char,
    v3: c_char,
    v4: c_char,
    v5: c_char,
    v6: c_char,
    v7: c_char,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let v = [v0, v1, v2, v3, v4, v5, v6, v7];
        set_ptp(wGroupIndex, shapes(v), |s| &mut s.ptp_dec)
    }
}

/// PtP acceleration time per axis, ms (0..=2^32 − 1).
#[no_mangle]
pub extern "system" fn MCC_SetPtPAccTime(
    v0: f64,
    v1: f64,
    v2: f64,
    v3: f64,
    v4: f64,
    v5: f64,
    v6: f64,
    v7: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let v = [v0, v1, v2, v3, v4, v5, v6, v7];
        set_ptp(wGroupIndex, times(v), |s| &mut s.ptp_acc_ms)
    }
}

/// PtP deceleration time per axis, ms (0..=2^32 − 1).
#[no_mangle]
pub extern "system" fn MCC_SetPtPDecTime(
    v0: f64,
    v1: f64,
    v2: f64,
    v3: f64,
    v4: f64,
    v5: f64,
    v6: f64,
    v7: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let v = [v0, v1, v2, v3, v4, v5, v6, v7];
        set_ptp(wGroupIndex, times(v), |s| &mut s.ptp_dec_ms)
    }
}

/// Reads the PtP acceleration shapes: 0 'T', 1 'S' (as the vendor's library answers).
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetPtPAccType(
    p0: *mut c_char,
    p1: *mut c_char,
    p2: *mut c_char,
    p3: *mut c_char,
    p4: *mut c_char,
    p5: *mut c_char,
    p6: *mut c_char,
    p7: *mut c_char,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_outs(p, || {
                with_group(wGroupIndex, |g| Ok(g.settings().ptp_acc.map(shape_byte)))
            })
        }
    }
}

/// Reads the PtP deceleration shapes: 0 'T', 1 'S'.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetPtPDecType(
    p0: *mut c_char,
    p1: *mut c_char,
    p2: *mut c_char,
    p3: *mut c_char,
    p4: *mut c_char,
    p5: *mut c_char,
    p6: *mut c_char,
    p7: *mut c_char,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_outs(p, || {
                with_group(wGroupIndex, |g| Ok(g.settings().ptp_dec.map(shape_byte)))
            })
        }
    }
}

/// Reads the PtP acceleration times, ms.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetPtPAccTime(
    p0: *mut f64,
    p1: *mut f64,
    p2: *mut f64,
    p3: *mut f64,
    p4: *mut f64,
    p5: *mut f64,
    p6: *mut f64,
    p7: *mut f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe { write_outs(p, || with_group(wGroupIndex, |g| Ok(g.settings().ptp_acc_ms))) }
    }
}

/// Reads the PtP deceleration times, ms.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetPtPDecTime(
    p0: *mut f64,
    p1: *mut f64,
    p2: *mut f64,
    p3: *mut f64,
    p4: *mut f64,
    p5: *mut f64,
    p6: *mut f64,
    p7: *mut f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe { write_outs(p, || with_group(wGroupIndex, |g| Ok(g.settings().ptp_dec_ms))) }
    }
}
