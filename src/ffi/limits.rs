//! Software over-travel check and hardware limit switch check (user manual §2.4.1, §2.6.1;
//! examples manual §19; vendor header "Software Over Travel Check & Hardware Limit Switch
//! Check").

use super::{
    index, update_group, with_group, with_machine_channel, write_out, write_outs, Card, Channel,
};
use crate::engine::safety::limit_check_mode;
use crate::error::McclResult;
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::c_int;

/// Turns the hardware limit switch check on: `HLP_BIDIR` (0), `HLP_UNIDIR` (1),
/// `HLP_BIDIR_GEN_ERR` (2) or `HLP_UNIDIR_GEN_ERR` (3); rules: docs/simulated-machine.md.
#[no_mangle]
pub extern "system" fn MCC_EnableLimitSwitchCheck(nMode: c_int) -> c_int {
    ffi_boundary! {
        let mode = limit_check_mode(nMode)?;
        system::active()?.set_limit_check(Some(mode));
        Ok(c::NO_ERR)
    }
}

/// Turns the hardware limit switch check off.
#[no_mangle]
pub extern "system" fn MCC_DisableLimitSwitchCheck() -> c_int {
    ffi_boundary! {
        system::active()?.set_limit_check(None);
        Ok(c::NO_ERR)
    }
}

/// Sets the software over-travel check of group `g` per axis: nonzero on, as the
/// vendor's library takes it; the axes the group lacks stay off.
fn set_over_travel_check(v: [c_int; 8], g: WORD) -> McclResult<c_int> {
    update_group(g, |g| {
        g.set_over_travel_check(v.map(|x| x != 0));
    })
}

/// Software over-travel check per axis (nonzero on, 0 off): an axis never goes past its
/// dfHighLimit/dfLowLimit; trying stops the group with error 0xF301 + axis.
#[no_mangle]
pub extern "system" fn MCC_SetOverTravelCheck(
    v0: c_int,
    v1: c_int,
    v2: c_int,
    v3: c_int,
    v4: c_int,
    v5: c_int,
    v6: c_int,
    v7: c_int,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let v = [v0, v1, v2, v3, v4, v5, v6, v7];
        set_over_travel_check(v, wGroupIndex)
    }
}

/// Reads the over-travel check per axis (1 on, 0 off).
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetOverTravelCheck(
    p0: *mut c_int,
    p1: *mut c_int,
    p2: *mut c_int,
    p3: *mut c_int,
    p4: *mut c_int,
    p5: *mut c_int,
    p6: *mut c_int,
    p7: *mut c_int,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_outs(p, || {
                with_group(wGroupIndex, |g| Ok(g.over_travel_check().map(c_int::from)))
            })
        }
    }
}

/// A limit switch side from C: 0 (+) or 1 (−).
fn side(wUpDown: WORD) -> McclResult<usize> {
    index(wUpDown, 2)
}

/// Limit switch `wUpDown` of a channel, as it reads now or as latched (1 active).
fn limit_switch(
    wUpDown: WORD,
    wChannel: WORD,
    wCardIndex: WORD,
    latched: bool,
) -> McclResult<WORD> {
    let side = side(wUpDown)?;
    let v = with_machine_channel(Channel(wChannel), Card(wCardIndex), |chan| {
        Ok(if latched {
            chan.latched_limit(side)
        } else {
            chan.limit_switch(side)
        })
    })?;
    Ok(WORD::from(v))
}

/// The limit switch (`wUpDown` 0: +, 1: −) as the wiring setting reads it: 1 active.
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetLimitSwitchStatus(
    pwStatus: *mut WORD,
    wUpDown: WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(pwStatus, || {
                limit_switch(wUpDown, wChannel, wCardIndex, false)
            })
        }
    }
}

/// Whether the limit switch has been active since the latch was last cleared.
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetLatchedLimitSwitchStatus(
    pwStatus: *mut WORD,
    wUpDown: WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(pwStatus, || {
                limit_switch(wUpDown, wChannel, wCardIndex, true)
            })
        }
    }
}

/// Clears the latched limit switch status (it latches again while the switch is active).
#[no_mangle]
pub extern "system" fn MCC_ClearLatchedLimitSwitchStatus(
    wUpDown: WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let side = side(wUpDown)?;
        with_machine_channel(Channel(wChannel), Card(wCardIndex), |chan| {
            chan.clear_latched_limit(side);
            Ok(())
        })?;
        Ok(c::NO_ERR)
    }
}
