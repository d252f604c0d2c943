//! Position control (user manual §2.6.4, §2.7; INTERFACE.md "Position Control"): loop
//! gains (kept and reported: the simulated plant is set by the configuration), error
//! counters, pulse speed and acceleration limits, tracking error, compensation.

use super::{axis, card, channel, finite, guard, outs8, update_group, with_group, write8};
use crate::error::{McclError, McclResult};
use crate::machine::MAX_PULSE_LIMIT;
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::{DWORD, SYS_COMP_PARAM, WORD};
use std::os::raw::{c_char, c_int};

fn with_card<R>(
    wCardIndex: WORD,
    f: impl FnOnce(&mut crate::machine::Machine, usize) -> McclResult<R>,
) -> McclResult<R> {
    let shared = system::active()?;
    let cd = shared.card(card(wCardIndex)?)?;
    let mut m = shared.machine.lock();
    f(&mut m, cd)
}

fn set_gains(k: usize, v: [WORD; 8], wCardIndex: WORD) -> c_int {
    guard(|| {
        if v.iter().any(|&g| g > 255) {
            return Err(McclError::Parameter);
        }
        with_card(wCardIndex, |m, cd| {
            m.settings[cd].gains[k] = v;
            Ok(c::NO_ERR)
        })
    })
}

/// # Safety
/// Every pointer must be NULL or writable.
unsafe fn get_gains(k: usize, p: [*mut WORD; 8], wCardIndex: WORD) -> c_int {
    guard(|| {
        outs8(&p)?;
        let v = with_card(wCardIndex, |m, cd| Ok(m.settings[cd].gains[k]))?;
        // SAFETY: checked non-null; the caller passes writable WORDs.
        unsafe { write8(&p, v) };
        Ok(c::NO_ERR)
    })
}

/// Proportional gain per channel (0..255).
#[no_mangle]
pub extern "C" fn MCC_SetPGain(
    wGain0: WORD,
    wGain1: WORD,
    wGain2: WORD,
    wGain3: WORD,
    wGain4: WORD,
    wGain5: WORD,
    wGain6: WORD,
    wGain7: WORD,
    wCardIndex: WORD,
) -> c_int {
    set_gains(
        0,
        [
            wGain0, wGain1, wGain2, wGain3, wGain4, wGain5, wGain6, wGain7,
        ],
        wCardIndex,
    )
}

/// Reads the proportional gains.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetPGain(
    pwGain0: *mut WORD,
    pwGain1: *mut WORD,
    pwGain2: *mut WORD,
    pwGain3: *mut WORD,
    pwGain4: *mut WORD,
    pwGain5: *mut WORD,
    pwGain6: *mut WORD,
    pwGain7: *mut WORD,
    wCardIndex: WORD,
) -> c_int {
    // SAFETY: forwarded under this function's contract.
    unsafe {
        get_gains(
            0,
            [
                pwGain0, pwGain1, pwGain2, pwGain3, pwGain4, pwGain5, pwGain6, pwGain7,
            ],
            wCardIndex,
        )
    }
}

/// Integral gain per channel (0..255).
#[no_mangle]
pub extern "C" fn MCC_SetIGain(
    wGain0: WORD,
    wGain1: WORD,
    wGain2: WORD,
    wGain3: WORD,
    wGain4: WORD,
    wGain5: WORD,
    wGain6: WORD,
    wGain7: WORD,
    wCardIndex: WORD,
) -> c_int {
    set_gains(
        1,
        [
            wGain0, wGain1, wGain2, wGain3, wGain4, wGain5, wGain6, wGain7,
        ],
        wCardIndex,
    )
}

/// Reads the integral gains.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetIGain(
    pwGain0: *mut WORD,
    pwGain1: *mut WORD,
    pwGain2: *mut WORD,
    pwGain3: *mut WORD,
    pwGain4: *mut WORD,
    pwGain5: *mut WORD,
    pwGain6: *mut WORD,
    pwGain7: *mut WORD,
    wCardIndex: WORD,
) -> c_int {
    // SAFETY: forwarded under this function's contract.
    unsafe {
        get_gains(
            1,
            [
                pwGain0, pwGain1, pwGain2, pwGain3, pwGain4, pwGain5, pwGain6, pwGain7,
            ],
            wCardIndex,
        )
    }
}

/// Derivative gain per channel (0..255).
#[no_mangle]
pub extern "C" fn MCC_SetDGain(
    wGain0: WORD,
    wGain1: WORD,
    wGain2: WORD,
    wGain3: WORD,
    wGain4: WORD,
    wGain5: WORD,
    wGain6: WORD,
    wGain7: WORD,
    wCardIndex: WORD,
) -> c_int {
    set_gains(
        2,
        [
            wGain0, wGain1, wGain2, wGain3, wGain4, wGain5, wGain6, wGain7,
        ],
        wCardIndex,
    )
}

/// Reads the derivative gains.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetDGain(
    pwGain0: *mut WORD,
    pwGain1: *mut WORD,
    pwGain2: *mut WORD,
    pwGain3: *mut WORD,
    pwGain4: *mut WORD,
    pwGain5: *mut WORD,
    pwGain6: *mut WORD,
    pwGain7: *mut WORD,
    wCardIndex: WORD,
) -> c_int {
    // SAFETY: forwarded under this function's contract.
    unsafe {
        get_gains(
            2,
            [
                pwGain0, pwGain1, pwGain2, pwGain3, pwGain4, pwGain5, pwGain6, pwGain7,
            ],
            wCardIndex,
        )
    }
}

/// Feed-forward gain per channel (0..255).
#[no_mangle]
pub extern "C" fn MCC_SetFGain(
    wGain0: WORD,
    wGain1: WORD,
    wGain2: WORD,
    wGain3: WORD,
    wGain4: WORD,
    wGain5: WORD,
    wGain6: WORD,
    wGain7: WORD,
    wCardIndex: WORD,
) -> c_int {
    set_gains(
        3,
        [
            wGain0, wGain1, wGain2, wGain3, wGain4, wGain5, wGain6, wGain7,
        ],
        wCardIndex,
    )
}

/// Reads the feed-forward gains.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetFGain(
    pwGain0: *mut WORD,
    pwGain1: *mut WORD,
    pwGain2: *mut WORD,
    pwGain3: *mut WORD,
    pwGain4: *mut WORD,
    pwGain5: *mut WORD,
    pwGain6: *mut WORD,
    pwGain7: *mut WORD,
    wCardIndex: WORD,
) -> c_int {
    // SAFETY: forwarded under this function's contract.
    unsafe {
        get_gains(
            3,
            [
                pwGain0, pwGain1, pwGain2, pwGain3, pwGain4, pwGain5, pwGain6, pwGain7,
            ],
            wCardIndex,
        )
    }
}

fn set_divider(k: usize, v: DWORD, wCardIndex: WORD) -> c_int {
    guard(|| {
        if v == 0 {
            return Err(McclError::Parameter);
        }
        with_card(wCardIndex, |m, cd| {
            m.settings[cd].dividers[k] = v;
            Ok(c::NO_ERR)
        })
    })
}

/// Clock divider of the integral term (>= 1).
#[no_mangle]
pub extern "C" fn MCC_SetIGainClockDivider(dwClockDivider: DWORD, wCardIndex: WORD) -> c_int {
    set_divider(0, dwClockDivider, wCardIndex)
}

/// Clock divider of the derivative term (>= 1).
#[no_mangle]
pub extern "C" fn MCC_SetDGainClockDivider(dwClockDivider: DWORD, wCardIndex: WORD) -> c_int {
    set_divider(1, dwClockDivider, wCardIndex)
}

/// The closed-loop error counter per channel: pulses output minus the motor's position.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetErrorCount(
    pnErrCount0: *mut c_int,
    pnErrCount1: *mut c_int,
    pnErrCount2: *mut c_int,
    pnErrCount3: *mut c_int,
    pnErrCount4: *mut c_int,
    pnErrCount5: *mut c_int,
    pnErrCount6: *mut c_int,
    pnErrCount7: *mut c_int,
    wCardIndex: WORD,
) -> c_int {
    guard(|| {
        let p = [
            pnErrCount0,
            pnErrCount1,
            pnErrCount2,
            pnErrCount3,
            pnErrCount4,
            pnErrCount5,
            pnErrCount6,
            pnErrCount7,
        ];
        outs8(&p)?;
        let v = with_card(wCardIndex, |m, cd| {
            Ok(std::array::from_fn(|ch| {
                m.cards[cd][ch]
                    .error_count()
                    .clamp(i64::from(c_int::MIN), i64::from(c_int::MAX)) as c_int
            }))
        })?;
        // SAFETY: checked non-null; the caller passes writable ints.
        unsafe { write8(&p, v) };
        Ok(c::NO_ERR)
    })
}

/// Thresholds of the closed-loop error counter of one channel (kept for the PCL
/// interrupt).
#[no_mangle]
pub extern "C" fn MCC_SetErrorCountThreshold(
    wChannel: WORD,
    wPlusThreshold: WORD,
    wMinusThreshold: WORD,
    wCardIndex: WORD,
) -> c_int {
    guard(|| {
        let ch = channel(wChannel)?;
        with_card(wCardIndex, |m, cd| {
            m.settings[cd].error_threshold[ch.0] = (wPlusThreshold, wMinusThreshold);
            Ok(c::NO_ERR)
        })
    })
}

fn pulse_limits(v: [c_int; 8]) -> McclResult<[i32; 8]> {
    if v.iter().any(|&x| !(1..=MAX_PULSE_LIMIT).contains(&x)) {
        return Err(McclError::Parameter);
    }
    Ok(v)
}

/// Most pulses per interpolation period per channel (1..32767, default 32767). More
/// stops the group with error 0xF203.
#[no_mangle]
pub extern "C" fn MCC_SetMaxPulseSpeed(
    nPulse0: c_int,
    nPulse1: c_int,
    nPulse2: c_int,
    nPulse3: c_int,
    nPulse4: c_int,
    nPulse5: c_int,
    nPulse6: c_int,
    nPulse7: c_int,
    wCardIndex: WORD,
) -> c_int {
    guard(|| {
        let v = pulse_limits([
            nPulse0, nPulse1, nPulse2, nPulse3, nPulse4, nPulse5, nPulse6, nPulse7,
        ])?;
        with_card(wCardIndex, |m, cd| {
            for (ch, x) in m.cards[cd].iter_mut().zip(v) {
                ch.max_speed = x;
            }
            Ok(c::NO_ERR)
        })
    })
}

/// Reads the pulse speed limits.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetMaxPulseSpeed(
    pnSpeed0: *mut c_int,
    pnSpeed1: *mut c_int,
    pnSpeed2: *mut c_int,
    pnSpeed3: *mut c_int,
    pnSpeed4: *mut c_int,
    pnSpeed5: *mut c_int,
    pnSpeed6: *mut c_int,
    pnSpeed7: *mut c_int,
    wCardIndex: WORD,
) -> c_int {
    guard(|| {
        let p = [
            pnSpeed0, pnSpeed1, pnSpeed2, pnSpeed3, pnSpeed4, pnSpeed5, pnSpeed6, pnSpeed7,
        ];
        outs8(&p)?;
        let v = with_card(wCardIndex, |m, cd| {
            Ok(std::array::from_fn(|ch| m.cards[cd][ch].max_speed))
        })?;
        // SAFETY: checked non-null; the caller passes writable ints.
        unsafe { write8(&p, v) };
        Ok(c::NO_ERR)
    })
}

/// Most change of pulses per period from one period to the next (1..32767, default
/// 32767). More stops the group with error 0xF204.
#[no_mangle]
pub extern "C" fn MCC_SetMaxPulseAcc(
    nPulseAcc0: c_int,
    nPulseAcc1: c_int,
    nPulseAcc2: c_int,
    nPulseAcc3: c_int,
    nPulseAcc4: c_int,
    nPulseAcc5: c_int,
    nPulseAcc6: c_int,
    nPulseAcc7: c_int,
    wCardIndex: WORD,
) -> c_int {
    guard(|| {
        let v = pulse_limits([
            nPulseAcc0, nPulseAcc1, nPulseAcc2, nPulseAcc3, nPulseAcc4, nPulseAcc5, nPulseAcc6,
            nPulseAcc7,
        ])?;
        with_card(wCardIndex, |m, cd| {
            for (ch, x) in m.cards[cd].iter_mut().zip(v) {
                ch.max_acc = x;
            }
            Ok(c::NO_ERR)
        })
    })
}

/// Reads the pulse acceleration limits.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetMaxPulseAcc(
    pnPulseAcc0: *mut c_int,
    pnPulseAcc1: *mut c_int,
    pnPulseAcc2: *mut c_int,
    pnPulseAcc3: *mut c_int,
    pnPulseAcc4: *mut c_int,
    pnPulseAcc5: *mut c_int,
    pnPulseAcc6: *mut c_int,
    pnPulseAcc7: *mut c_int,
    wCardIndex: WORD,
) -> c_int {
    guard(|| {
        let p = [
            pnPulseAcc0,
            pnPulseAcc1,
            pnPulseAcc2,
            pnPulseAcc3,
            pnPulseAcc4,
            pnPulseAcc5,
            pnPulseAcc6,
            pnPulseAcc7,
        ];
        outs8(&p)?;
        let v = with_card(wCardIndex, |m, cd| {
            Ok(std::array::from_fn(|ch| m.cards[cd][ch].max_acc))
        })?;
        // SAFETY: checked non-null; the caller passes writable ints.
        unsafe { write8(&p, v) };
        Ok(c::NO_ERR)
    })
}

/// Tracking error check on for the axes in the mask: a following error above the
/// axis's limit (`MCC_SetTrackErrorLimit`) stops the group with error 0xF801 + axis.
#[no_mangle]
pub extern "C" fn MCC_EnableTrackError(wGroupIndex: WORD, dwAxisMask: DWORD) -> c_int {
    guard(|| {
        if dwAxisMask & !0xFF != 0 {
            return Err(McclError::Parameter);
        }
        update_group(wGroupIndex, |g| g.track_mask |= dwAxisMask)
    })
}

/// Tracking error check off for every axis.
#[no_mangle]
pub extern "C" fn MCC_DisableTrackError(wGroupIndex: WORD) -> c_int {
    guard(|| update_group(wGroupIndex, |g| g.track_mask = 0))
}

/// The tracking error limit of one axis, UU (finite, >= 0).
#[no_mangle]
pub extern "C" fn MCC_SetTrackErrorLimit(dfLimit: f64, cAxis: c_char, wGroupIndex: WORD) -> c_int {
    guard(|| {
        let v = finite(dfLimit)?;
        if v < 0.0 {
            return Err(McclError::Parameter);
        }
        let a = axis(cAxis)?;
        update_group(wGroupIndex, |g| g.track_limit[a] = v)
    })
}

/// Reads the tracking error limit of one axis (infinite until set).
///
/// # Safety
/// `pdfLimit` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetTrackErrorLimit(
    pdfLimit: *mut f64,
    cAxis: c_char,
    wGroupIndex: WORD,
) -> c_int {
    guard(|| {
        super::out_ok(pdfLimit)?;
        let a = axis(cAxis)?;
        let v = with_group(wGroupIndex, |g| Ok(g.track_limit[a]))?;
        // SAFETY: checked non-null; the caller passes a writable double.
        unsafe { super::write_out(pdfLimit, v) };
        Ok(c::NO_ERR)
    })
}

/// Compensation tables of one channel (§2.7.5); they take effect at
/// `MCC_UpdateCompParam`. `dwInterval` 0 turns compensation off; `wHome_No` <= 255.
///
/// # Safety
/// `pstCompParam` must be NULL (refused with `PARAMETER_ERR`) or point to a
/// `SYS_COMP_PARAM`.
#[no_mangle]
pub unsafe extern "C" fn MCC_SetCompParam(
    pstCompParam: *mut SYS_COMP_PARAM,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    guard(|| {
        let (cd, ch) = (card(wCardIndex)?, channel(wChannel)?);
        // SAFETY: NULL is refused; otherwise the caller passes a SYS_COMP_PARAM.
        let p = unsafe { super::read_in(pstCompParam) }?;
        if p.wHome_No > 255 {
            return Err(McclError::Parameter);
        }
        system::with(|s| s.config.comp[cd.0][ch.0] = Some(p));
        Ok(c::NO_ERR)
    })
}

/// Applies the compensation tables set with `MCC_SetCompParam`.
#[no_mangle]
pub extern "C" fn MCC_UpdateCompParam() -> c_int {
    guard(|| {
        let comp = system::with(|s| s.config.comp.clone());
        let shared = system::active()?;
        let mut m = shared.machine.lock();
        for (cd, chans) in m.cards.iter_mut().enumerate() {
            for (ch, chan) in chans.iter_mut().enumerate() {
                if let Some(p) = &comp[cd][ch] {
                    chan.set_compensation(p);
                }
            }
        }
        Ok(c::NO_ERR)
    })
}
