//! Trajectory planning controls (user manual §2.6.3; vendor header "Trajectory Planning").

use crate::error::McclResult;
use crate::system;
use crate::vendor::DWORD;

/// Waits `dwTime` ms in the card's time: real time under the realtime clock, virtual time
/// under the fast and stepped clocks (the card runs while the program waits). Before
/// `MCC_InitSystem` it sleeps in real time.
#[no_mangle]
pub extern "system" fn MCC_TimeDelay(dwTime: DWORD) {
    ffi_boundary! {
        match system::active() {
            Ok(shared) => shared.clock().delay_ms(dwTime),
            Err(_) => std::thread::sleep(std::time::Duration::from_millis(u64::from(dwTime))),
        }
        Ok(())
    }
}

use super::{queue, read_published, with_group};
use crate::card::rio::{set_ix, ARIO_SLAVES, RIO_PORTS};
use crate::engine::command::Plan;
use crate::error::McclError;
use crate::vendor::consts as c;
use crate::vendor::{BOOL, WORD};
use std::os::raw::c_int;

/// Decelerates to a stop with the running command's deceleration time and holds
/// (`GMS_HOLD`); with `bBlockEnd` TRUE, holds when the running command ends.
/// `HOLD_ILLEGAL_ERR` when nothing runs or the group is already held.
#[no_mangle]
pub extern "system" fn MCC_HoldMotion(wGroupIndex: WORD, bBlockEnd: BOOL) -> c_int {
    ffi_boundary! { with_group(wGroupIndex, |g| g.hold(bBlockEnd != 0)).map(|()| c::NO_ERR) }
}

/// Resumes held motion with the command's acceleration time; `CONTI_ILLEGAL_ERR` while
/// the hold still decelerates (the hold goes on, as the vendor's library does), nothing
/// done when nothing is held.
#[no_mangle]
pub extern "system" fn MCC_ContiMotion(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { with_group(wGroupIndex, |g| g.conti()).map(|()| c::NO_ERR) }
}

/// Stops at once and empties the queue; with `bBlockEnd` TRUE the running command
/// finishes first.
#[no_mangle]
pub extern "system" fn MCC_AbortMotion(wGroupIndex: WORD, bBlockEnd: BOOL) -> c_int {
    ffi_boundary! { super::update_group(wGroupIndex, |g| g.abort(0.0, bBlockEnd != 0)) }
}

/// Empties the queue and stops within `dfDecTime` ms (0: at once; at most 2^32 − 1).
/// While it decelerates, new motion commands are refused with `ABORT_NOT_FINISH_ERR`.
#[no_mangle]
pub extern "system" fn MCC_AbortMotionEx(dfDecTime: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let t = crate::config::range::time_ms(dfDecTime)?;
        super::update_group(wGroupIndex, |g| g.abort(t, false))
    }
}

/// Single-block mode on: after each command the group waits (`GMS_HOLD`) for
/// `MCC_RunSingleBlock`.
#[no_mangle]
pub extern "system" fn MCC_EnableSingleBlock(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { super::update_group(wGroupIndex, |g| g.set_single_block(true)) }
}

/// Single-block mode off.
#[no_mangle]
pub extern "system" fn MCC_DisableSingleBlock(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { super::update_group(wGroupIndex, |g| g.set_single_block(false)) }
}

/// Lets the next command run in single-block mode (`COMMAND_NOTACCEPTED_ERR` when the
/// mode is off).
#[no_mangle]
pub extern "system" fn MCC_RunSingleBlock(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { with_group(wGroupIndex, |g| g.run_single_block()).map(|()| c::NO_ERR) }
}

/// Blending on, effective at once (not through the queue); `COMMAND_NOTACCEPTED_ERR` on
/// an MC3B group (its moves start and end at rest).
#[no_mangle]
pub extern "system" fn MCC_EnableBlendInstant(wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        with_group(wGroupIndex, |g| {
            if g.is_external() {
                return Err(McclError::NotAccepted);
            }
            g.set_blend_now(true);
            Ok(c::NO_ERR)
        })
    }
}

/// Blending off, effective at once.
#[no_mangle]
pub extern "system" fn MCC_DisableBlendInstant(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { super::update_group(wGroupIndex, |g| g.set_blend_now(false)) }
}

/// Queues "blending on": general motions after it start while the previous one
/// decelerates. Returns the command index.
#[no_mangle]
pub extern "system" fn MCC_EnableBlend(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { queue(wGroupIndex, |ctx| Ok(ctx.marker(Plan::Blend(true)))) }
}

/// Queues "blending off". Returns the command index.
#[no_mangle]
pub extern "system" fn MCC_DisableBlend(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { queue(wGroupIndex, |ctx| Ok(ctx.marker(Plan::Blend(false)))) }
}

/// 0 when blending is on (as the end of the queue will have it), 1 when off.
#[no_mangle]
pub extern "system" fn MCC_CheckBlend(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(c_int::from(!g.blend_queued()))) }
}

/// Queues a delay of `dwTime` ms (> 0) before the next command (`GMS_DELAYING`
/// meanwhile). Returns the command index.
#[no_mangle]
pub extern "system" fn MCC_DelayMotion(dwTime: DWORD, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        if dwTime == 0 {
            return Err(McclError::Parameter);
        }
        queue(wGroupIndex, |ctx| Ok(ctx.delay(f64::from(dwTime))))
    }
}

/// 1 while the group is delaying, 0 otherwise (as the vendor's library answers).
#[no_mangle]
pub extern "system" fn MCC_CheckDelay(wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let status = read_published(wGroupIndex, |p| p.load_status())?;
        Ok(c_int::from(status == c::GMS_DELAYING))
    }
}

/// An override ratio, percent: any positive finite number (the vendor's library takes
/// 0.001 and 5000 alike), at most [`MAX_OVERRIDE`] (a larger one could not be planned).
fn override_rate(r: f64) -> Result<f64, McclError> {
    if r.is_finite() && r > 0.0 && r <= MAX_OVERRIDE {
        Ok(r)
    } else {
        Err(McclError::Parameter)
    }
}

/// Largest override ratio accepted, percent.
pub const MAX_OVERRIDE: f64 = 1.0e6;

/// Scales the running and all later motion to `dfRate` percent of the planned speed from
/// the next period: what runs re-plans the rest of its length from its speed with its
/// acc and dec times. Returns `dfRate`.
#[no_mangle]
pub extern "system" fn MCC_OverrideSpeed(dfRate: f64, wGroupIndex: WORD) -> f64 {
    ffi_boundary! {
    Ok(MCC_OverrideSpeedEx(dfRate, 1, wGroupIndex))
        }
}

/// [`MCC_OverrideSpeed`]; with `bInstant` FALSE the new rate applies from the next
/// command instead of the running one. On an MC3B group the rate applies from the next
/// job; an instant change while the group moves or has commands queued is
/// `COMMAND_NOTACCEPTED_ERR` (the MC3B cannot change the speed of a running move).
#[no_mangle]
pub extern "system" fn MCC_OverrideSpeedEx(dfRate: f64, bInstant: BOOL, wGroupIndex: WORD) -> f64 {
    ffi_boundary! {
        let r = override_rate(dfRate)?;
        with_group(wGroupIndex, |g| {
            if bInstant != 0 && g.is_external() && g.busy() {
                return Err(McclError::NotAccepted);
            }
            g.override_speed(r, bInstant != 0);
            Ok(r)
        })
    }
}

/// The override ratio in effect (1.0 = 100 %, as the vendor's library reports it; a new
/// one from the period after it was set).
#[no_mangle]
pub extern "system" fn MCC_GetOverrideRate(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(g.override_pct() / 100.0)) }
}

/// With `bFix` TRUE the override no longer changes speeds (motion runs at 100 %).
#[no_mangle]
pub extern "system" fn MCC_FixSpeed(bFix: BOOL, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { super::update_group(wGroupIndex, |g| g.fix_speed(bFix != 0)) }
}

/// Obsolete name of [`MCC_OverrideSpeed`].
#[no_mangle]
pub extern "system" fn MCC_SetOverSpeed(dfRate: f64, wGroupIndex: WORD) -> f64 {
    ffi_boundary! {
    Ok(MCC_OverrideSpeedEx(dfRate, 1, wGroupIndex))
        }
}

/// Obsolete name of [`MCC_GetOverrideRate`].
#[no_mangle]
pub extern "system" fn MCC_GetOverSpeed(wGroupIndex: WORD) -> f64 {
    ffi_boundary! {
    Ok(MCC_GetOverrideRate(wGroupIndex))
        }
}

/// Obsolete: changes the feed speed of the running general motion and of the following
/// ones to `dfSpeed` UU/s (the running command ramps to it through the override ratio).
/// Returns the feed speed now in effect.
#[no_mangle]
pub extern "system" fn MCC_ChangeFeedSpeed(dfSpeed: f64, wGroupIndex: WORD) -> f64 {
    ffi_boundary! {
        let v = super::motion::feed_speed(dfSpeed)?;
        with_group(wGroupIndex, |g| {
            g.change_feed_speed(v);
            Ok(v)
        })
    }
}

fn queue_output(wGroupIndex: WORD, o: crate::engine::command::Output) -> McclResult<c_int> {
    queue(wGroupIndex, |ctx| Ok(ctx.marker(Plan::Output(o))))
}

/// Queues a change of the outputs of RIO port (`ario` false: set 0..1, port 0..3) or
/// ARIO slave (`ario` true: slave 0..31 in `wPort`) `wPort` of set `wSet`.
fn queue_remote(
    ario: bool,
    wBitMask: WORD,
    wValue: WORD,
    wSet: WORD,
    wPort: WORD,
    wGroupIndex: WORD,
) -> McclResult<c_int> {
    let ports = if ario { ARIO_SLAVES } else { RIO_PORTS };
    set_ix(wSet)?;
    if usize::from(wPort) >= ports {
        return Err(McclError::Parameter);
    }
    let o = crate::engine::command::Output::Remote {
        ario,
        set: wSet,
        port: wPort,
        mask: wBitMask,
        value: wValue,
    };
    queue_output(wGroupIndex, o)
}

/// Queues a change of the card's local outputs (points 0..7, the servo-on outputs): the
/// bits of `wBitMask` take those of `wValue` when the queue reaches it. Returns the
/// command index.
#[no_mangle]
pub extern "system" fn MCC_QueueLIOOutputValue(
    wBitMask: WORD,
    wValue: WORD,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        super::bits(wBitMask, 0xFF)?;
        let o = crate::engine::command::Output::Local {
            mask: wBitMask,
            value: wValue,
        };
        queue_output(wGroupIndex, o)
    }
}

/// Queues a change of a RIO port's outputs (set 0..1, port 0..3): the bits of
/// `wBitMask` take those of `wValue` when the queue reaches it. Returns the command index.
#[no_mangle]
pub extern "system" fn MCC_QueueRIOOutputValue(
    wBitMask: WORD,
    wValue: WORD,
    wSet: WORD,
    wPort: WORD,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { queue_remote(false, wBitMask, wValue, wSet, wPort, wGroupIndex) }
}

/// Queues a change of an ARIO slave's outputs (set 0..1, slave 0..31 in `wPort`).
/// Returns the command index.
#[no_mangle]
pub extern "system" fn MCC_QueueARIOOutputValue(
    wBitMask: WORD,
    wValue: WORD,
    wSet: WORD,
    wPort: WORD,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { queue_remote(true, wBitMask, wValue, wSet, wPort, wGroupIndex) }
}
