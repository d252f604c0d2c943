//! Coordinate management (user manual §2.6.1, §2.6.5; vendor header "Coordinate
//! Management").

use super::{axis_mask, index, snapshot_outs, with_group, write_outs};
use crate::error::McclError;
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::{DWORD, WORD};
use std::os::raw::{c_int, c_long, c_longlong};

/// Following motion commands take absolute coordinates (the default).
#[no_mangle]
pub extern "C" fn MCC_SetAbsolute(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { super::update_group(wGroupIndex, |g| g.settings.absolute = true) }
}

/// Following motion commands take increments from the end of the previous command.
#[no_mangle]
pub extern "C" fn MCC_SetIncrease(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { super::update_group(wGroupIndex, |g| g.settings.absolute = false) }
}

/// 1 for absolute coordinates, 0 for incremental.
#[no_mangle]
pub extern "C" fn MCC_GetCoordType(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(c_int::from(g.settings.absolute))) }
}

/// Current command position in user coordinates (UU). Under the fast and stepped clocks
/// a read repeated at the same virtual time while the group moves runs one tick, so a
/// program that waits by reading positions makes progress.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetCurPos(
    pdfX: *mut f64,
    pdfY: *mut f64,
    pdfZ: *mut f64,
    pdfU: *mut f64,
    pdfV: *mut f64,
    pdfW: *mut f64,
    pdfA: *mut f64,
    pdfB: *mut f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [pdfX, pdfY, pdfZ, pdfU, pdfV, pdfW, pdfA, pdfB];
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_outs(p, || {
                let shared = system::active()?;
                shared.poll_position(wGroupIndex);
                let s = shared.snapshot(wGroupIndex)?;
                // A kinematic group: the forward kinematics of its joints.
                Ok(super::kinematics::cur_pos(wGroupIndex)?.unwrap_or(s.pos))
            })
        }
    }
}

/// Current command position in reference coordinates: the user coordinates before
/// `MCC_DefinePos`/`MCC_DefineOrigin` moved them (UU).
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetCurRefPos(
    pdfX: *mut f64,
    pdfY: *mut f64,
    pdfZ: *mut f64,
    pdfU: *mut f64,
    pdfV: *mut f64,
    pdfW: *mut f64,
    pdfA: *mut f64,
    pdfB: *mut f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [pdfX, pdfY, pdfZ, pdfU, pdfV, pdfW, pdfA, pdfB];
        // SAFETY: forwarded under this function's contract.
        unsafe { snapshot_outs(p, wGroupIndex, |s| s.ref_pos) }
    }
}

/// Pulse position per axis: round(reference position x dwPPR x dfGearRatio / dfPitch),
/// sign reversed when wPosToEncoderDir = 1.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetPulsePos(
    plX: *mut c_long,
    plY: *mut c_long,
    plZ: *mut c_long,
    plU: *mut c_long,
    plV: *mut c_long,
    plW: *mut c_long,
    plA: *mut c_long,
    plB: *mut c_long,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [plX, plY, plZ, plU, plV, plW, plA, plB];
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_outs(p, || {
                let s = system::active()?.snapshot(wGroupIndex)?;
                // A kinematic group: its joints' pulses.
                let pulses = super::kinematics::joint_pulses(wGroupIndex)?.unwrap_or(s.pulses);
                Ok(pulses.map(|v| v as c_long))
            })
        }
    }
}

/// [`MCC_GetPulsePos`] with 64-bit results on every platform.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetPulsePosEx(
    plX: *mut c_longlong,
    plY: *mut c_longlong,
    plZ: *mut c_longlong,
    plU: *mut c_longlong,
    plV: *mut c_longlong,
    plW: *mut c_longlong,
    plA: *mut c_longlong,
    plB: *mut c_longlong,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [plX, plY, plZ, plU, plV, plW, plA, plB];
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_outs(p, || {
                let s = system::active()?.snapshot(wGroupIndex)?;
                // A kinematic group: its joints' pulses.
                Ok(super::kinematics::joint_pulses(wGroupIndex)?.unwrap_or(s.pulses))
            })
        }
    }
}

/// The current position of one axis becomes 0 (only while the group is stopped,
/// `COMMAND_NOTFINISHED_ERR` otherwise).
#[no_mangle]
pub extern "C" fn MCC_DefineOrigin(wAxis: WORD, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let a = index(wAxis, 8)?;
        with_group(wGroupIndex, |g| g.define_pos(a, 0.0)).map(|()| c::NO_ERR)
    }
}

/// The current position of one axis becomes `dfPos` (only while stopped).
#[no_mangle]
pub extern "C" fn MCC_DefinePos(wAxis: WORD, dfPos: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let a = index(wAxis, 8)?;
        let v = super::finite(dfPos)?;
        with_group(wGroupIndex, |g| g.define_pos(a, v)).map(|()| c::NO_ERR)
    }
}

/// For the axes in the mask, the command position becomes the position the card has
/// actually output (the pulse counter converted back to UU), removing any fraction of a
/// pulse. Only while stopped.
#[no_mangle]
pub extern "C" fn MCC_DefinePosHere(wGroupIndex: WORD, dwAxisMask: DWORD) -> c_int {
    ffi_boundary! {
        axis_mask(dwAxisMask)?;
        with_group(wGroupIndex, |g| {
            if g.busy() {
                return Err(McclError::NotFinished);
            }
            for i in (0..8).filter(|i| dwAxisMask & (1 << i) != 0) {
                g.sync_to_output(i)?;
            }
            Ok(c::NO_ERR)
        })
    }
}
