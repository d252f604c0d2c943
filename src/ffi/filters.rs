//! The compose axes, the after-interpolation filters, reverse interpolation and the cycle
//! routine (vendor header: "System Management" and the obsolete functions; the manuals
//! do not describe them). docs/compatibility.md, "Filters, reverse interpolation, cycle
//! routine", gives the behaviour and what it rests on.

use super::{update_group, with_group};
use crate::engine::group::{GroupState, MAX_FILTER_PERIODS};
use crate::error::{McclError, McclResult};
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::{BOOL, CYCLE_INTERRUPT_ISR, INTERP, WORD};
use std::os::raw::c_int;

/// The filters change only while the group stands still (its queue empty, its output
/// settled): `COMMAND_NOTFINISHED_ERR` otherwise; `COMMAND_NOTACCEPTED_ERR` on an MC3B
/// group (its device makes its own ramps).
fn still(g: &GroupState) -> McclResult<()> {
    if g.is_external() {
        return Err(McclError::NotAccepted);
    }
    if g.busy() {
        return Err(McclError::NotFinished);
    }
    Ok(())
}

/// Lines queued from now on measure their length, and so their feed speed, over the axes
/// of `wAxesMask` (bit 0 X … bit 7 B; the default is X|Y|Z). `PARAMETER_ERR` for 0 or a
/// bit above B.
#[no_mangle]
pub extern "system" fn MCC_SetComposeAxis(wAxesMask: WORD, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let mask = u32::from(wAxesMask);
        if mask == 0 || mask > 0xFF {
            return Err(McclError::Parameter);
        }
        update_group(wGroupIndex, |g| g.settings_mut().compose = mask)
    }
}

/// Acc/dec after interpolation: general motion queued from now on is interpolated at the
/// feed speed without acc/dec, and the group's output goes through a filter as long as
/// the acceleration time set now (`MCC_SetAccTime`), which makes the ramps and rounds
/// the corners. Only while the group stands still.
#[no_mangle]
pub extern "system" fn MCC_EnableAccDecAfterIPO(wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let dt = system::active()?.clock().period().as_secs_f64();
        with_group(wGroupIndex, |g| {
            still(g)?;
            let periods = (g.settings().acc_ms / 1000.0 / dt).round();
            if !(0.0..=MAX_FILTER_PERIODS as f64).contains(&periods) {
                return Err(McclError::Parameter);
            }
            g.set_acc_after_ipo(Some(periods as usize));
            Ok(c::NO_ERR)
        })
    }
}

/// Acc/dec before interpolation again (the default) for general motion queued from now
/// on; the filter is removed. Only while the group stands still.
#[no_mangle]
pub extern "system" fn MCC_DisableAccDecAfterIPO(wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        with_group(wGroupIndex, |g| {
            still(g)?;
            g.set_acc_after_ipo(None);
            Ok(c::NO_ERR)
        })
    }
}

/// The group's output becomes the mean of its last 5 interpolated positions. Only while
/// the group stands still.
#[no_mangle]
pub extern "system" fn MCC_EnableMovingAverage(wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        with_group(wGroupIndex, |g| {
            still(g)?;
            g.set_moving_average(true);
            Ok(c::NO_ERR)
        })
    }
}

/// The moving average off. Only while the group stands still.
#[no_mangle]
pub extern "system" fn MCC_DisableMovingAverage(wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        with_group(wGroupIndex, |g| {
            still(g)?;
            g.set_moving_average(false);
            Ok(c::NO_ERR)
        })
    }
}

/// Registers the routine called once per interpolation period, after the tick and the
/// interrupt routines, on the engine thread with no lock held (NULL unregisters).
#[no_mangle]
pub extern "system" fn MCC_SetCycleInterruptRoutine(
    pfnCycleIntRoutine: CYCLE_INTERRUPT_ISR,
) -> c_int {
    ffi_boundary! {
        let shared = system::active()?;
        shared.set_cycle_routine(pfnCycleIntRoutine.map_or(0, |f| f as usize));
        Ok(c::NO_ERR)
    }
}

/// Registers the group's reverse interpolation routine (NULL unregisters): while reverse
/// interpolation is enabled it is called after every period in which the group runs a
/// command or stands behind the front of its path; its return value decides the next
/// period: > 0 forward, < 0 one period back along the executed path, 0 pause.
#[no_mangle]
pub extern "system" fn MCC_SetReverseInterpRoutine(
    pfnForwardReverse: INTERP,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let shared = system::active()?;
        let f = pfnForwardReverse.map_or(0, |f| f as usize);
        with_group(wGroupIndex, |g| {
            if g.is_external() {
                return Err(McclError::NotAccepted);
            }
            g.set_reverse_routine(f);
            Ok(())
        })?;
        if f != 0 {
            shared.arm_reverse_routines();
        }
        Ok(c::NO_ERR)
    }
}

/// Reverse interpolation on (`bEnableReverse` non-zero) or off. Turned off behind the
/// front of its path, the group goes forward along the path to the front, then on with
/// its commands.
#[no_mangle]
pub extern "system" fn MCC_EnableReverseInterp(bEnableReverse: BOOL, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        with_group(wGroupIndex, |g| {
            if g.is_external() {
                return Err(McclError::NotAccepted);
            }
            g.enable_reverse(bEnableReverse != 0);
            Ok(c::NO_ERR)
        })
    }
}
