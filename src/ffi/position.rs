//! Position control (user manual §2.6.4, §2.7; vendor header "Position Control"): loop
//! gains (kept and reported: the simulated plant is set by the configuration), error
//! counters, pulse speed and acceleration limits, tracking error, compensation.

use super::{
    axis, axis_mask, channel, finite, set_channel_config, update_group, with_group, with_machine,
    write_out, write_outs, Card,
};
use crate::config::Config;
use crate::error::{McclError, McclResult};
use crate::machine::{Gain, Gains, PulseLimit, MAX_PULSE_LIMIT};
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::{DWORD, SYS_COMP_PARAM, WORD};
use std::os::raw::{c_char, c_int};

fn set_gains(k: Gain, v: [WORD; 8], wCardIndex: WORD) -> McclResult<c_int> {
    let g = Gains::new(v)?;
    with_machine(Card(wCardIndex), |m, cd| {
        m.card_settings_mut(cd).set_gains(k, g);
        Ok(c::NO_ERR)
    })
}

fn gains(k: Gain, wCardIndex: WORD) -> McclResult<[WORD; 8]> {
    with_machine(Card(wCardIndex), |m, cd| Ok(m.card_settings(cd).gains(k)))
}

/// Proportional gain per channel (0..255).
#[no_mangle]
pub extern "system" fn MCC_SetPGain(
    v0: WORD,
    v1: WORD,
    v2: WORD,
    v3: WORD,
    v4: WORD,
    v5: WORD,
    v6: WORD,
    v7: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let v = [v0, v1, v2, v3, v4, v5, v6, v7];
        set_gains(Gain::P, v, wCardIndex)
    }
}

/// Integral gain per channel (0..255).
#[no_mangle]
pub extern "system" fn MCC_SetIGain(
    v0: WORD,
    v1: WORD,
    v2: WORD,
    v3: WORD,
    v4: WORD,
    v5: WORD,
    v6: WORD,
    v7: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let v = [v0, v1, v2, v3, v4, v5, v6, v7];
        set_gains(Gain::I, v, wCardIndex)
    }
}

/// Derivative gain per channel (0..255).
#[no_mangle]
pub extern "system" fn MCC_SetDGain(
    v0: WORD,
    v1: WORD,
    v2: WORD,
    v3: WORD,
    v4: WORD,
    v5: WORD,
    v6: WORD,
    v7: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let v = [v0, v1, v2, v3, v4, v5, v6, v7];
        set_gains(Gain::D, v, wCardIndex)
    }
}

/// Feed-forward gain per channel (0..255).
#[no_mangle]
pub extern "system" fn MCC_SetFGain(
    v0: WORD,
    v1: WORD,
    v2: WORD,
    v3: WORD,
    v4: WORD,
    v5: WORD,
    v6: WORD,
    v7: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let v = [v0, v1, v2, v3, v4, v5, v6, v7];
        set_gains(Gain::FeedForward, v, wCardIndex)
    }
}

/// Reads the proportional gains.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetPGain(
    p0: *mut WORD,
    p1: *mut WORD,
    p2: *mut WORD,
    p3: *mut WORD,
    p4: *mut WORD,
    p5: *mut WORD,
    p6: *mut WORD,
    p7: *mut WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe { write_outs(p, || gains(Gain::P, wCardIndex)) }
    }
}

/// Reads the integral gains.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetIGain(
    p0: *mut WORD,
    p1: *mut WORD,
    p2: *mut WORD,
    p3: *mut WORD,
    p4: *mut WORD,
    p5: *mut WORD,
    p6: *mut WORD,
    p7: *mut WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe { write_outs(p, || gains(Gain::I, wCardIndex)) }
    }
}

/// Reads the derivative gains.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetDGain(
    p0: *mut WORD,
    p1: *mut WORD,
    p2: *mut WORD,
    p3: *mut WORD,
    p4: *mut WORD,
    p5: *mut WORD,
    p6: *mut WORD,
    p7: *mut WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe { write_outs(p, || gains(Gain::D, wCardIndex)) }
    }
}

/// Reads the feed-forward gains.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetFGain(
    p0: *mut WORD,
    p1: *mut WORD,
    p2: *mut WORD,
    p3: *mut WORD,
    p4: *mut WORD,
    p5: *mut WORD,
    p6: *mut WORD,
    p7: *mut WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe { write_outs(p, || gains(Gain::FeedForward, wCardIndex)) }
    }
}

fn set_divider(k: usize, v: DWORD, wCardIndex: WORD) -> McclResult<c_int> {
    if v == 0 {
        return Err(McclError::Parameter);
    }
    with_machine(Card(wCardIndex), |m, cd| {
        m.card_settings_mut(cd).set_divider(k, v);
        Ok(c::NO_ERR)
    })
}

/// Clock divider of the integral term (>= 1).
#[no_mangle]
pub extern "system" fn MCC_SetIGainClockDivider(dwClockDivider: DWORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { set_divider(0, dwClockDivider, wCardIndex) }
}

/// Clock divider of the derivative term (>= 1).
#[no_mangle]
pub extern "system" fn MCC_SetDGainClockDivider(dwClockDivider: DWORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { set_divider(1, dwClockDivider, wCardIndex) }
}

/// Each channel's closed-loop error counter, clamped to the range of C's `int`.
fn error_counts(wCardIndex: WORD) -> McclResult<[c_int; 8]> {
    with_machine(Card(wCardIndex), |m, cd| {
        Ok(std::array::from_fn(|ch| {
            m.cards()[cd][ch]
                .error_count()
                .clamp(i64::from(c_int::MIN), i64::from(c_int::MAX)) as c_int
        }))
    })
}

/// The closed-loop error counter per channel: pulses output minus the motor's position.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetErrorCount(
    p0: *mut c_int,
    p1: *mut c_int,
    p2: *mut c_int,
    p3: *mut c_int,
    p4: *mut c_int,
    p5: *mut c_int,
    p6: *mut c_int,
    p7: *mut c_int,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe { write_outs(p, || error_counts(wCardIndex)) }
    }
}

/// Thresholds of the closed-loop error counter of one channel (kept for the PCL
/// interrupt).
#[no_mangle]
pub extern "system" fn MCC_SetErrorCountThreshold(
    wChannel: WORD,
    wPlusThreshold: WORD,
    wMinusThreshold: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let ch = channel(wChannel)?;
        with_machine(Card(wCardIndex), |m, cd| {
            m.card_settings_mut(cd).set_error_threshold(ch.0, wPlusThreshold, wMinusThreshold);
            Ok(c::NO_ERR)
        })
    }
}

/// Sets the pulse limits `k` of card `wCardIndex`, each in 1..=[`MAX_PULSE_LIMIT`].
/// Under `MCC_InitSimulation` the vendor's library takes none (`COMMAND_NOTACCEPTED_ERR`
/// once the values are checked): the card is simulated there too.
fn set_pulse_limits(k: PulseLimit, v: [c_int; 8], wCardIndex: WORD) -> McclResult<c_int> {
    if v.iter().any(|&x| !(1..=MAX_PULSE_LIMIT).contains(&x)) {
        return Err(McclError::Parameter);
    }
    if crate::system::is_simulation() {
        crate::system::active()?.card(super::card(wCardIndex)?)?;
        return Err(McclError::NotAccepted);
    }
    with_machine(Card(wCardIndex), |m, cd| {
        m.set_pulse_limits(cd, k, v);
        Ok(c::NO_ERR)
    })
}

/// The pulse limits `k` of card `wCardIndex`; -1 for the channels its type lacks, as the
/// vendor's library reads them.
fn pulse_limits(k: PulseLimit, wCardIndex: WORD) -> McclResult<[c_int; 8]> {
    let mut v = with_machine(Card(wCardIndex), |m, cd| Ok(m.pulse_limits(cd, k)))?;
    let n = crate::system::card_channels(usize::from(wCardIndex));
    v.iter_mut().skip(n).for_each(|x| *x = -1);
    Ok(v)
}

/// Most pulses per interpolation period per channel (1..2^31 − 1, default 1,000,000).
/// More stops the group with error 0xF203.
#[no_mangle]
pub extern "system" fn MCC_SetMaxPulseSpeed(
    v0: c_int,
    v1: c_int,
    v2: c_int,
    v3: c_int,
    v4: c_int,
    v5: c_int,
    v6: c_int,
    v7: c_int,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let v = [v0, v1, v2, v3, v4, v5, v6, v7];
        set_pulse_limits(PulseLimit::Speed, v, wCardIndex)
    }
}

/// Most change of pulses per period from one period to the next (1..2^31 − 1,
/// default 1,000,000). More stops the group with error 0xF204.
#[no_mangle]
pub extern "system" fn MCC_SetMaxPulseAcc(
    v0: c_int,
    v1: c_int,
    v2: c_int,
    v3: c_int,
    v4: c_int,
    v5: c_int,
    v6: c_int,
    v7: c_int,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let v = [v0, v1, v2, v3, v4, v5, v6, v7];
        set_pulse_limits(PulseLimit::Acc, v, wCardIndex)
    }
}

/// Reads the pulse speed limits.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetMaxPulseSpeed(
    p0: *mut c_int,
    p1: *mut c_int,
    p2: *mut c_int,
    p3: *mut c_int,
    p4: *mut c_int,
    p5: *mut c_int,
    p6: *mut c_int,
    p7: *mut c_int,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe { write_outs(p, || pulse_limits(PulseLimit::Speed, wCardIndex)) }
    }
}

/// Reads the pulse acceleration limits.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetMaxPulseAcc(
    p0: *mut c_int,
    p1: *mut c_int,
    p2: *mut c_int,
    p3: *mut c_int,
    p4: *mut c_int,
    p5: *mut c_int,
    p6: *mut c_int,
    p7: *mut c_int,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe { write_outs(p, || pulse_limits(PulseLimit::Acc, wCardIndex)) }
    }
}

/// Tracking error check on for the axes in the mask: a following error above the
/// axis's limit (`MCC_SetTrackErrorLimit`) stops the group with error 0xF801 + axis.
#[no_mangle]
pub extern "system" fn MCC_EnableTrackError(wGroupIndex: WORD, dwAxisMask: DWORD) -> c_int {
    ffi_boundary! {
        axis_mask(dwAxisMask)?;
        update_group(wGroupIndex, |g| g.enable_track_error(dwAxisMask))
    }
}

/// Tracking error check off for every axis.
#[no_mangle]
pub extern "system" fn MCC_DisableTrackError(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { update_group(wGroupIndex, |g| g.disable_track_error()) }
}

/// The tracking error limit of one axis, UU (>= 0, a distance of the axis in the
/// position range: |limit| x pulses per UU <= 1e15).
#[no_mangle]
pub extern "system" fn MCC_SetTrackErrorLimit(
    dfLimit: f64,
    cAxis: c_char,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let a = axis(cAxis)?;
        let v = finite(dfLimit)?.abs();
        with_group(wGroupIndex, |g| g.set_track_error_limit(a, v))?;
        Ok(c::NO_ERR)
    }
}

/// Reads the tracking error limit of one axis (infinite until set).
///
/// # Safety
/// `pdfLimit` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetTrackErrorLimit(
    pdfLimit: *mut f64,
    cAxis: c_char,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(pdfLimit, || {
                let a = axis(cAxis)?;
                let v = with_group(wGroupIndex, |g| g.own_axis(a).map(|()| g.track_limit(a)))?;
                Ok(v)
            })
        }
    }
}

/// Compensation tables of one channel (§2.7.5); they take effect at
/// `MCC_UpdateCompParam`. `dwInterval` 0 turns compensation off; `wHome_No` <= 255.
///
/// # Safety
/// `pstCompParam` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `SYS_COMP_PARAM`.
#[no_mangle]
pub unsafe extern "system" fn MCC_SetCompParam(
    pstCompParam: *mut SYS_COMP_PARAM,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { set_channel_config(pstCompParam, wChannel, wCardIndex, Config::set_comp_param) }
    }
}

/// Applies the compensation tables set with `MCC_SetCompParam`.
#[no_mangle]
pub extern "system" fn MCC_UpdateCompParam() -> c_int {
    ffi_boundary! {
        let comp = system::config(|c| c.comp.clone());
        system::active()?.lock_machine().apply_compensation(&comp);
        Ok(c::NO_ERR)
    }
}

/// In-position mode (`IPM_ONETIME_BLOCK`, `IPM_ONETIME_UNBLOCK`, `IPM_SETTLE_BLOCK`,
/// `IPM_SETTLE_UNBLOCK`; user manual §2.7.2).
#[no_mangle]
pub extern "system" fn MCC_SetInPosMode(wMode: WORD, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        if wMode > c::IPM_SETTLE_UNBLOCK {
            return Err(McclError::Parameter);
        }
        update_group(wGroupIndex, |g| g.inpos_settings_mut().mode = wMode)
    }
}

/// Longest time (ms) the in-position check waits after a command's last pulse.
#[no_mangle]
pub extern "system" fn MCC_SetInPosMaxCheckTime(wMaxCheckTime: WORD, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        update_group(wGroupIndex, |g| g.inpos_settings_mut().set_max_check_ms(wMaxCheckTime))
    }
}

/// How long (ms) the axes must stay within tolerance in the `IPM_SETTLE_*` modes.
#[no_mangle]
pub extern "system" fn MCC_SetInPosSettleTime(wSettleTime: WORD, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        update_group(wGroupIndex, |g| g.inpos_settings_mut().set_settle_ms(wSettleTime))
    }
}

fn inpos_marker(wGroupIndex: WORD, dwAxisMask: DWORD, on: bool) -> McclResult<c_int> {
    axis_mask(dwAxisMask)?;
    super::queue(wGroupIndex, |ctx| {
        Ok(ctx.marker(crate::engine::command::Plan::InPos(on, dwAxisMask)))
    })
}

/// Queues "in-position check on" for the axes in the mask (user manual §2.3 G). Returns
/// the command index.
#[no_mangle]
pub extern "system" fn MCC_EnableInPos(wGroupIndex: WORD, dwAxisMask: DWORD) -> c_int {
    ffi_boundary! { inpos_marker(wGroupIndex, dwAxisMask, true) }
}

/// Queues "in-position check off" for the axes in the mask. Returns the command index.
#[no_mangle]
pub extern "system" fn MCC_DisableInPos(wGroupIndex: WORD, dwAxisMask: DWORD) -> c_int {
    ffi_boundary! { inpos_marker(wGroupIndex, dwAxisMask, false) }
}

/// Sets the in-position tolerances of group `g`, UU, as the vendor's library takes them:
/// any value, kept as whole pulses (`GroupState::set_inpos_tolerances`); the axes the
/// group lacks ignore theirs.
fn set_tolerances(v: [f64; 8], g: WORD) -> McclResult<c_int> {
    with_group(g, |g| {
        g.set_inpos_tolerances(v);
        Ok(())
    })?;
    Ok(c::NO_ERR)
}

/// In-position tolerance per axis, UU, kept as whole pulses: the magnitude of the
/// value truncated to a 32-bit pulse count (the vendor's library takes any value).
#[no_mangle]
pub extern "system" fn MCC_SetInPosToleranceEx(
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
        set_tolerances(v, wGroupIndex)
    }
}

/// Reads the in-position tolerances, UU.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetInPosToleranceEx(
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
        unsafe { write_outs(p, || with_group(wGroupIndex, |g| Ok(g.inpos_settings().tolerance))) }
    }
}

/// In-position status per axis: 0xFF once in position (held until the next command),
/// 0 otherwise.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetInPosStatus(
    p0: *mut crate::vendor::BYTE,
    p1: *mut crate::vendor::BYTE,
    p2: *mut crate::vendor::BYTE,
    p3: *mut crate::vendor::BYTE,
    p4: *mut crate::vendor::BYTE,
    p5: *mut crate::vendor::BYTE,
    p6: *mut crate::vendor::BYTE,
    p7: *mut crate::vendor::BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe { write_outs(p, || with_group(wGroupIndex, |g| Ok(g.inpos_status()))) }
    }
}

/// Obsolete name of [`MCC_SetInPosMaxCheckTime`].
#[no_mangle]
pub extern "system" fn MCC_SetInPosCheckTime(wCheckTime: WORD, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
    Ok(MCC_SetInPosMaxCheckTime(wCheckTime, wGroupIndex))
        }
}

/// Obsolete: the settle (stable) time of the in-position check, ms.
#[no_mangle]
pub extern "system" fn MCC_GetInPosStableTime(wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        with_group(wGroupIndex, |g| Ok(g.inpos_settings().settle_ms()))
    }
}

/// Obsolete: in-position tolerance per axis in pulses (converted to UU with each axis's
/// pulses per UU).
#[no_mangle]
pub extern "system" fn MCC_SetInPosTolerance(
    v0: WORD,
    v1: WORD,
    v2: WORD,
    v3: WORD,
    v4: WORD,
    v5: WORD,
    v6: WORD,
    v7: WORD,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let v = [v0, v1, v2, v3, v4, v5, v6, v7];
        update_group(wGroupIndex, |g| g.set_inpos_tolerances_pulses(v))
    }
}

/// Obsolete: reads the in-position tolerances in pulses.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetInPosTolerance(
    p0: *mut WORD,
    p1: *mut WORD,
    p2: *mut WORD,
    p3: *mut WORD,
    p4: *mut WORD,
    p5: *mut WORD,
    p6: *mut WORD,
    p7: *mut WORD,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_outs(p, || {
                with_group(wGroupIndex, |g| Ok(g.inpos_tolerances_pulses()))
            })
        }
    }
}
