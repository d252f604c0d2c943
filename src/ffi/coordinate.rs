//! Coordinate management (user manual §2.6.1, §2.6.5; vendor header "Coordinate
//! Management").

use super::{axis_mask, index, read_published, with_group, write_outs};
use crate::error::{McclError, McclResult};
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::{DWORD, WORD};
use std::os::raw::{c_int, c_long, c_longlong};

/// Following motion commands take absolute coordinates (the default).
#[no_mangle]
pub extern "system" fn MCC_SetAbsolute(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { super::update_group(wGroupIndex, |g| g.settings_mut().absolute = true) }
}

/// Following motion commands take increments from the end of the previous command.
#[no_mangle]
pub extern "system" fn MCC_SetIncrease(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { super::update_group(wGroupIndex, |g| g.settings_mut().absolute = false) }
}

/// 1 for absolute coordinates, 0 for incremental.
#[no_mangle]
pub extern "system" fn MCC_GetCoordType(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(c_int::from(g.settings().absolute))) }
}

/// The position of group `g` as the machine counts it (its pulses in UU, with the shift
/// `MCC_DefineOrigin` made and the compensation its channels add, as the vendor's library
/// counts it); for a kinematic group its joints.
fn cur_pos(g: WORD) -> McclResult<[f64; 8]> {
    let shared = system::active()?;
    shared.poll_position(g);
    Ok(shared
        .published(g)?
        .load_machine_pos(&shared.compensation(g)))
}

/// The pulse position of group `g` per axis; for a kinematic group its joints'.
fn pulse_pos(g: WORD) -> McclResult<[i64; 8]> {
    let shared = system::active()?;
    let published = shared.published(g)?;
    Ok(published.load_pulses(&shared.compensation(g)))
}

/// Current position as the machine counts it: the pulse count in UU (whole pulses, as
/// the vendor's library reports), which `MCC_DefineOrigin` does not move. Under the
/// fast and stepped clocks a read repeated at the same virtual time while the group
/// moves runs one tick, so a program that waits by reading positions makes progress.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetCurPos(
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
        unsafe { write_outs(p, || cur_pos(wGroupIndex)) }
    }
}

/// Current position in the program's coordinates, the frame commands' targets are in
/// (`MCC_DefineOrigin` makes an axis's 0 here), whole pulses in UU.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetCurRefPos(
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
        unsafe { write_outs(p, || read_published(wGroupIndex, |p| p.load_program_pos())) }
    }
}

/// Pulse position per axis: round(reference position x dwPPR x dfGearRatio / dfPitch),
/// sign reversed when wPosToEncoderDir is nonzero.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetPulsePos(
    p0: *mut c_long,
    p1: *mut c_long,
    p2: *mut c_long,
    p3: *mut c_long,
    p4: *mut c_long,
    p5: *mut c_long,
    p6: *mut c_long,
    p7: *mut c_long,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe { write_outs(p, || pulse_pos(wGroupIndex).map(|p| p.map(|v| v as c_long))) }
    }
}

/// [`MCC_GetPulsePos`] with 64-bit results on every platform.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetPulsePosEx(
    p0: *mut c_longlong,
    p1: *mut c_longlong,
    p2: *mut c_longlong,
    p3: *mut c_longlong,
    p4: *mut c_longlong,
    p5: *mut c_longlong,
    p6: *mut c_longlong,
    p7: *mut c_longlong,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe { write_outs(p, || pulse_pos(wGroupIndex)) }
    }
}

/// The current position of one axis becomes 0 (only while the group is stopped,
/// `COMMAND_NOTFINISHED_ERR` otherwise).
#[no_mangle]
pub extern "system" fn MCC_DefineOrigin(wAxis: WORD, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let a = index(wAxis, 8).map_err(|_| McclError::Group)?;
        with_group(wGroupIndex, |g| g.define_pos(a, 0.0)).map(|()| c::NO_ERR)
    }
}

/// The position of one axis becomes `dfPos` in the program's coordinates and in the
/// machine's pulse count alike (as the vendor's library does; only while stopped).
#[no_mangle]
pub extern "system" fn MCC_DefinePos(wAxis: WORD, dfPos: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let a = index(wAxis, 8).map_err(|_| McclError::Group)?;
        let v = super::finite(dfPos)?;
        with_group(wGroupIndex, |g| g.set_pos(a, v)).map(|()| c::NO_ERR)
    }
}

/// For the axes in the mask, the command position becomes the position the card has
/// actually output (the pulse counter converted back to UU), removing any fraction of a
/// pulse. Only while stopped.
#[no_mangle]
pub extern "system" fn MCC_DefinePosHere(wGroupIndex: WORD, dwAxisMask: DWORD) -> c_int {
    ffi_boundary! {
        axis_mask(dwAxisMask)?;
        with_group(wGroupIndex, |g| g.define_pos_here(dwAxisMask))?;
        Ok(c::NO_ERR)
    }
}
