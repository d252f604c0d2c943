//! Software over-travel check and hardware limit switch check (user manual §2.4.1, §2.6.1;
//! examples manual §19; vendor header "Software Over Travel Check & Hardware Limit Switch
//! Check").

use super::{card, channel, update_group, with_group, Out};
use crate::error::McclError;
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::c_int;
use std::sync::atomic::Ordering;

/// Turns the hardware limit switch check on: `HLP_BIDIR` (0), `HLP_UNIDIR` (1),
/// `HLP_BIDIR_GEN_ERR` (2) or `HLP_UNIDIR_GEN_ERR` (3); see the README for the rules.
#[no_mangle]
pub extern "C" fn MCC_EnableLimitSwitchCheck(nMode: c_int) -> c_int {
    ffi_boundary! {
        if !(c::HLP_BIDIR..=c::HLP_UNIDIR_GEN_ERR).contains(&nMode) {
            return Err(McclError::Parameter);
        }
        system::active()?
            .limit_check
            .store(nMode, Ordering::Release);
        Ok(c::NO_ERR)
    }
}

/// Turns the hardware limit switch check off.
#[no_mangle]
pub extern "C" fn MCC_DisableLimitSwitchCheck() -> c_int {
    ffi_boundary! {
        system::active()?.limit_check.store(-1, Ordering::Release);
        Ok(c::NO_ERR)
    }
}

fn flag(v: c_int) -> Result<bool, McclError> {
    match v {
        0 => Ok(false),
        1 => Ok(true),
        _ => Err(McclError::Parameter),
    }
}

/// Software over-travel check per axis (1 on, 0 off): an axis never goes past its
/// dfHighLimit/dfLowLimit; trying stops the group with error 0xF301 + axis.
#[no_mangle]
pub extern "C" fn MCC_SetOverTravelCheck(
    nOTCheck0: c_int,
    nOTCheck1: c_int,
    nOTCheck2: c_int,
    nOTCheck3: c_int,
    nOTCheck4: c_int,
    nOTCheck5: c_int,
    nOTCheck6: c_int,
    nOTCheck7: c_int,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let v = [
            nOTCheck0, nOTCheck1, nOTCheck2, nOTCheck3, nOTCheck4, nOTCheck5, nOTCheck6, nOTCheck7,
        ];
        let mut f = [false; 8];
        for (o, x) in f.iter_mut().zip(v) {
            *o = flag(x)?;
        }
        update_group(wGroupIndex, |g| g.ot_check = f)
    }
}

/// Reads the over-travel check per axis (1 on, 0 off).
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetOverTravelCheck(
    pnOTCheck0: *mut c_int,
    pnOTCheck1: *mut c_int,
    pnOTCheck2: *mut c_int,
    pnOTCheck3: *mut c_int,
    pnOTCheck4: *mut c_int,
    pnOTCheck5: *mut c_int,
    pnOTCheck6: *mut c_int,
    pnOTCheck7: *mut c_int,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [
            pnOTCheck0, pnOTCheck1, pnOTCheck2, pnOTCheck3, pnOTCheck4, pnOTCheck5, pnOTCheck6,
            pnOTCheck7,
        ];
        // SAFETY: NULL or writable, as this function's contract requires.
        let p = unsafe { Out::each(p) }?;
        let v = with_group(wGroupIndex, |g| Ok(g.ot_check.map(c_int::from)))?;
        super::write_each(p, v);
        Ok(c::NO_ERR)
    }
}

fn limit_status(
    pwStatus: *mut WORD,
    wUpDown: WORD,
    wChannel: WORD,
    wCardIndex: WORD,
    latched: bool,
) -> Result<c_int, McclError> {
    let (cd, ch) = (card(wCardIndex)?, channel(wChannel)?);
    if wUpDown > 1 {
        return Err(McclError::Parameter);
    }
    // SAFETY: NULL or writable, as this function's contract requires.
    let pwStatus = unsafe { Out::new(pwStatus) }?;
    let shared = system::active()?;
    let cd = shared.card(cd)?;
    let m = shared.machine.lock();
    let chan = m.channel(cd, ch.0).ok_or(McclError::Parameter)?;
    let v = if latched {
        chan.latched[usize::from(wUpDown)]
    } else if wUpDown == 0 {
        chan.levels().plus
    } else {
        chan.levels().minus
    };
    pwStatus.write(WORD::from(v));
    Ok(c::NO_ERR)
}

/// The limit switch (`wUpDown` 0: +, 1: −) as the wiring setting reads it: 1 active.
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetLimitSwitchStatus(
    pwStatus: *mut WORD,
    wUpDown: WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! { limit_status(pwStatus, wUpDown, wChannel, wCardIndex, false) }
}

/// Whether the limit switch has been active since the latch was last cleared.
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetLatchedLimitSwitchStatus(
    pwStatus: *mut WORD,
    wUpDown: WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! { limit_status(pwStatus, wUpDown, wChannel, wCardIndex, true) }
}

/// Clears the latched limit switch status (it latches again while the switch is active).
#[no_mangle]
pub extern "C" fn MCC_ClearLatchedLimitSwitchStatus(
    wUpDown: WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let (cd, ch) = (card(wCardIndex)?, channel(wChannel)?);
        if wUpDown > 1 {
            return Err(McclError::Parameter);
        }
        let shared = system::active()?;
        let cd = shared.card(cd)?;
        let mut m = shared.machine.lock();
        let chan = m.channel_mut(cd, ch.0).ok_or(McclError::Parameter)?;
        let active = if wUpDown == 0 {
            chan.levels().plus
        } else {
            chan.levels().minus
        };
        chan.latched[usize::from(wUpDown)] = active;
        Ok(c::NO_ERR)
    }
}
