//! Coordinate management (user manual §2.6.1, §2.6.5; vendor header "Coordinate
//! Management").

use super::{axis_mask, index, read_published, with_group};
use crate::error::McclResult;
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::{DWORD, WORD};
use std::os::raw::{c_int, c_long, c_longlong};

/// Following motion commands take absolute coordinates (the default).
#[no_mangle]
pub extern "system" fn MCC_SetAbsolute(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { super::update_group(wGroupIndex, |g| g.settings.absolute = true) }
}

/// Following motion commands take increments from the end of the previous command.
#[no_mangle]
pub extern "system" fn MCC_SetIncrease(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { super::update_group(wGroupIndex, |g| g.settings.absolute = false) }
}

/// 1 for absolute coordinates, 0 for incremental.
#[no_mangle]
pub extern "system" fn MCC_GetCoordType(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(c_int::from(g.settings.absolute))) }
}

/// The command position of group `g` in user coordinates, UU; for a kinematic group the
/// forward kinematics of its joints.
fn cur_pos(g: WORD) -> McclResult<[f64; 8]> {
    let shared = system::active()?;
    shared.poll_position(g);
    match super::kinematics::cur_pos(&shared, g)? {
        Some(cart) => Ok(cart),
        None => Ok(shared.published(g)?.load_pos()),
    }
}

/// The pulse position of group `g` per axis; for a kinematic group its joints' pulses.
fn pulse_pos(g: WORD) -> McclResult<[i64; 8]> {
    let shared = system::active()?;
    let published = shared.published(g)?;
    match super::kinematics::joint_pulses(&shared, g)? {
        Some(joints) => Ok(joints),
        None => Ok(published.load_pulses()),
    }
}

per_axis_getters! {
    /// Current command position in user coordinates (UU). Under the fast and stepped clocks
    /// a read repeated at the same virtual time while the group moves runs one tick, so a
    /// program that waits by reading positions makes progress.
    MCC_GetCurPos(f64; wGroupIndex)
        = cur_pos(wGroupIndex);
    /// Current command position in reference coordinates: the user coordinates before
    /// `MCC_DefinePos`/`MCC_DefineOrigin` moved them (UU).
    MCC_GetCurRefPos(f64; wGroupIndex)
        = read_published(wGroupIndex, |p| p.load_ref_pos());
    /// Pulse position per axis: round(reference position x dwPPR x dfGearRatio / dfPitch),
    /// sign reversed when wPosToEncoderDir = 1.
    MCC_GetPulsePos(c_long; wGroupIndex)
        = pulse_pos(wGroupIndex).map(|p| p.map(|v| v as c_long));
    /// [`MCC_GetPulsePos`] with 64-bit results on every platform.
    MCC_GetPulsePosEx(c_longlong; wGroupIndex)
        = pulse_pos(wGroupIndex);
}

/// The current position of one axis becomes 0 (only while the group is stopped,
/// `COMMAND_NOTFINISHED_ERR` otherwise).
#[no_mangle]
pub extern "system" fn MCC_DefineOrigin(wAxis: WORD, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let a = index(wAxis, 8)?;
        with_group(wGroupIndex, |g| g.define_pos(a, 0.0)).map(|()| c::NO_ERR)
    }
}

/// The current position of one axis becomes `dfPos` (only while stopped).
#[no_mangle]
pub extern "system" fn MCC_DefinePos(wAxis: WORD, dfPos: f64, wGroupIndex: WORD) -> c_int {
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
pub extern "system" fn MCC_DefinePosHere(wGroupIndex: WORD, dwAxisMask: DWORD) -> c_int {
    ffi_boundary! {
        axis_mask(dwAxisMask)?;
        with_group(wGroupIndex, |g| g.define_pos_here(dwAxisMask))?;
        Ok(c::NO_ERR)
    }
}
