//! The group's settings of general motion, as C sets and reads them: the acceleration and
//! deceleration shapes and times, the feed speed and the point-to-point speed ratio; and
//! the speeds the group runs at now.

use crate::config::range::time_ms;
use crate::error::{McclError, McclResult};
use crate::ffi::{read_published, shape, shape_code, with_group, write_outs};
use crate::system;
use crate::vendor::WORD;
use std::os::raw::{c_char, c_int};

/// A feed speed from C, as the vendor's library takes it: its size (−1 is 1), not 0, at
/// most the speed range's top, then at most the system maximum (`MCC_SetSysMaxSpeed`).
pub(in crate::ffi) fn feed_speed(v: f64) -> McclResult<f64> {
    let v = v.abs();
    // NaN fails both comparisons: refused too.
    if v.is_nan() || v <= 0.0 || v > crate::config::range::MAX_SPEED {
        return Err(McclError::Parameter);
    }
    Ok(system::config(|c| c.feed_speed(v)))
}

/// The ratio of point-to-point speed: a percentage in (0, 100].
fn ptp_ratio(r: f64) -> McclResult<f64> {
    if r > 0.0 && r <= 100.0 {
        Ok(r)
    } else {
        Err(McclError::Parameter)
    }
}

/// An acc or dec time from C, ms: in the time range, kept in whole ms (rounded up) as the
/// vendor's library keeps it.
fn ramp_ms(t: f64) -> McclResult<f64> {
    Ok(crate::planner::whole_ms(time_ms(t)?))
}

/// Acceleration shape of general motion: 'T' (trapezoid) or 'S' (S-curve).
#[no_mangle]
pub extern "system" fn MCC_SetAccType(cAccType: c_char, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let v = shape(cAccType)?;
        crate::ffi::update_group(wGroupIndex, |g| g.settings_mut().acc = v)
    }
}

/// Deceleration shape of general motion: 'T' or 'S'.
#[no_mangle]
pub extern "system" fn MCC_SetDecType(cDecType: c_char, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let v = shape(cDecType)?;
        crate::ffi::update_group(wGroupIndex, |g| g.settings_mut().dec = v)
    }
}

/// Time to accelerate from 0 to the feed speed, ms (0..=2^32 − 1; default 300).
/// Kept in whole ms, rounded up.
#[no_mangle]
pub extern "system" fn MCC_SetAccTime(dfAccTime: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let v = ramp_ms(dfAccTime)?;
        crate::ffi::update_group(wGroupIndex, |g| g.settings_mut().acc_ms = v)
    }
}

/// Time to decelerate from the feed speed to 0, ms (0..=2^32 − 1; default 300), kept
/// in whole ms, rounded up.
#[no_mangle]
pub extern "system" fn MCC_SetDecTime(dfDecTime: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let v = ramp_ms(dfDecTime)?;
        crate::ffi::update_group(wGroupIndex, |g| g.settings_mut().dec_ms = v)
    }
}

/// Feed speed of following general motion, UU/s (> 0; a negative one counts by its
/// size). A speed above `MCC_SetSysMaxSpeed` becomes that maximum. Returns the feed
/// speed now in effect.
#[no_mangle]
pub extern "system" fn MCC_SetFeedSpeed(dfFeedSpeed: f64, wGroupIndex: WORD) -> f64 {
    ffi_boundary! {
        let v = feed_speed(dfFeedSpeed)?;
        with_group(wGroupIndex, |g| {
            g.settings_mut().feed = v;
            Ok(v)
        })
    }
}

/// Point-to-point speed ratio, percent of each axis's maximum safe speed
/// (0 < r <= 100). Returns the ratio now in effect.
#[no_mangle]
pub extern "system" fn MCC_SetPtPSpeed(dfRatio: f64, wGroupIndex: WORD) -> f64 {
    ffi_boundary! {
        let v = ptp_ratio(dfRatio)?;
        with_group(wGroupIndex, |g| {
            g.settings_mut().ptp_ratio = v;
            Ok(v)
        })
    }
}

/// The acceleration shape: 0 'T', 1 'S' (as the vendor's library answers).
#[no_mangle]
pub extern "system" fn MCC_GetAccType(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(shape_code(g.settings().acc))) }
}

/// The deceleration shape: 0 'T', 1 'S'.
#[no_mangle]
pub extern "system" fn MCC_GetDecType(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(shape_code(g.settings().dec))) }
}

/// The acceleration time, ms.
#[no_mangle]
pub extern "system" fn MCC_GetAccTime(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(g.settings().acc_ms)) }
}

/// The deceleration time, ms.
#[no_mangle]
pub extern "system" fn MCC_GetDecTime(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(g.settings().dec_ms)) }
}

/// The feed speed of following general motion, UU/s.
#[no_mangle]
pub extern "system" fn MCC_GetFeedSpeed(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(g.settings().feed)) }
}

/// The point-to-point speed ratio, percent.
#[no_mangle]
pub extern "system" fn MCC_GetPtPSpeed(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(g.settings().ptp_ratio)) }
}

/// The current tangential speed (UU/s): X/Y/Z path speed, or the fastest aux axis.
#[no_mangle]
pub extern "system" fn MCC_GetCurFeedSpeed(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { read_published(wGroupIndex, |p| p.load_motion().path_speed()) }
}

/// The current speed of every axis, UU/s (signed).
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetSpeed(
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
        unsafe { write_outs(p, || read_published(wGroupIndex, |p| p.load_motion().vel)) }
    }
}
