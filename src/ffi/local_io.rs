//! Local I/O outputs (user manual §2.9.2; INTERFACE.md "Local I/O Control"): the servo-on
//! signal of each channel and the card's position-ready signal. The virtual card keeps
//! the state of each output; the simulated machine reads it.

use super::{card, channel, guard};
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::c_int;
use std::sync::atomic::Ordering;

fn servo(wChannel: WORD, wCardIndex: WORD, on: bool) -> c_int {
    guard(|| {
        let (cd, ch) = (card(wCardIndex)?, channel(wChannel)?);
        let shared = system::active()?;
        let cd = shared.card(cd)?;
        let bit = 1u32 << ch.0;
        if on {
            shared.servo_on[cd].fetch_or(bit, Ordering::AcqRel);
        } else {
            shared.servo_on[cd].fetch_and(!bit, Ordering::AcqRel);
        }
        Ok(c::NO_ERR)
    })
}

/// Turns the servo-on output of one channel on (at once, not queued: user manual §2.3).
#[no_mangle]
pub extern "C" fn MCC_SetServoOn(wChannel: WORD, wCardIndex: WORD) -> c_int {
    servo(wChannel, wCardIndex, true)
}

/// Turns the servo-on output of one channel off.
#[no_mangle]
pub extern "C" fn MCC_SetServoOff(wChannel: WORD, wCardIndex: WORD) -> c_int {
    servo(wChannel, wCardIndex, false)
}

fn pos_ready(wCardIndex: WORD, on: bool) -> c_int {
    guard(|| {
        let shared = system::active()?;
        let cd = shared.card(card(wCardIndex)?)?;
        shared.pos_ready[cd].store(on, Ordering::Release);
        Ok(c::NO_ERR)
    })
}

/// Turns the card's position-ready output on.
#[no_mangle]
pub extern "C" fn MCC_EnablePosReady(wCardIndex: WORD) -> c_int {
    pos_ready(wCardIndex, true)
}

/// Turns the card's position-ready output off.
#[no_mangle]
pub extern "C" fn MCC_DisablePosReady(wCardIndex: WORD) -> c_int {
    pos_ready(wCardIndex, false)
}

/// The emergency-stop input of the card: 1 pressed, 0 released.
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetEmgcStopStatus(pwStatus: *mut WORD, wCardIndex: WORD) -> c_int {
    guard(|| {
        super::out_ok(pwStatus)?;
        let shared = system::active()?;
        let cd = shared.card(card(wCardIndex)?)?;
        let v = shared.machine.lock().emergency[cd];
        // SAFETY: checked non-null; the caller passes a writable WORD.
        unsafe { super::write_out(pwStatus, WORD::from(v)) };
        Ok(c::NO_ERR)
    })
}

fn led(Channel: WORD, wCardIndex: WORD, on: bool) -> c_int {
    guard(|| {
        let ch = channel(Channel)?;
        let shared = system::active()?;
        let cd = shared.card(card(wCardIndex)?)?;
        let mut m = shared.machine.lock();
        let bit = 1u8 << ch.0;
        if on {
            m.settings[cd].leds |= bit;
        } else {
            m.settings[cd].leds &= !bit;
        }
        Ok(c::NO_ERR)
    })
}

/// Turns a channel's LED output on.
#[no_mangle]
pub extern "C" fn MCC_SetLedLightOn(Channel: WORD, wCardIndex: WORD) -> c_int {
    led(Channel, wCardIndex, true)
}

/// Turns a channel's LED output off.
#[no_mangle]
pub extern "C" fn MCC_SetLedLightOff(Channel: WORD, wCardIndex: WORD) -> c_int {
    led(Channel, wCardIndex, false)
}

/// A channel's LED output: 1 on, 0 off.
///
/// # Safety
/// `Status` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetLedLightStatus(
    Channel: WORD,
    Status: *mut WORD,
    wCardIndex: WORD,
) -> c_int {
    guard(|| {
        let ch = channel(Channel)?;
        super::out_ok(Status)?;
        let shared = system::active()?;
        let cd = shared.card(card(wCardIndex)?)?;
        let v = shared.machine.lock().settings[cd].leds >> ch.0 & 1;
        // SAFETY: checked non-null; the caller passes a writable WORD.
        unsafe { super::write_out(Status, WORD::from(v)) };
        Ok(c::NO_ERR)
    })
}

fn filter(k: usize, Value: WORD, wCardIndex: WORD) -> c_int {
    guard(|| {
        let shared = system::active()?;
        let cd = shared.card(card(wCardIndex)?)?;
        shared.machine.lock().settings[cd].filters[k] = Value;
        Ok(c::NO_ERR)
    })
}

/// Filter clock of the limit switch inputs (kept: the simulated inputs do not bounce).
#[no_mangle]
pub extern "C" fn MCC_SetLimitFilterClk(Value: WORD, wCardIndex: WORD) -> c_int {
    filter(0, Value, wCardIndex)
}

/// Filter clock of the home sensor inputs (kept: the simulated inputs do not bounce).
#[no_mangle]
pub extern "C" fn MCC_SetHomeFilterClk(Value: WORD, wCardIndex: WORD) -> c_int {
    filter(1, Value, wCardIndex)
}

/// Filter clock of the general-purpose inputs (kept: the simulated inputs do not bounce).
#[no_mangle]
pub extern "C" fn MCC_SetGpioFilterClk(Value: WORD, wCardIndex: WORD) -> c_int {
    filter(2, Value, wCardIndex)
}

/// The home sensor of a channel as its go-home wiring (`wSensorMode`) reads it: 1 active.
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetHomeSensorStatus(
    pwStatus: *mut WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    guard(|| {
        let (cd, ch) = (card(wCardIndex)?, channel(wChannel)?);
        super::out_ok(pwStatus)?;
        let mode = system::with(|s| s.config.home[cd.0][ch.0].wSensorMode);
        let shared = system::active()?;
        let cd = shared.card(cd)?;
        let m = shared.machine.lock();
        let v = m.cards[cd][ch.0].home_level(mode);
        // SAFETY: checked non-null; the caller passes a writable WORD.
        unsafe { super::write_out(pwStatus, WORD::from(v)) };
        Ok(c::NO_ERR)
    })
}
