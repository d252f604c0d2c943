//! Local I/O outputs (user manual §2.9.2; vendor header "Local I/O Control"): the servo-on
//! signal of each channel, the card's position-ready signal and the 8 LEDs, and their
//! trigger-out by encoder compares. The virtual card keeps the state of each output; the
//! simulated machine reads it.

use super::{
    bits, card, channel, flag, index, with_card_triggers, with_machine, with_machine_channel,
    word_count, write_out, Card,
};
use crate::error::{McclError, McclResult};
use crate::machine::triggers::{TrigOutKind, TrigOutSetting};
use crate::machine::FilterClock;
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::{DWORD, WORD};
use std::os::raw::c_int;

fn servo(wChannel: WORD, wCardIndex: WORD, on: bool) -> McclResult<c_int> {
    let (cd, ch) = (card(wCardIndex)?, channel(wChannel)?);
    let shared = system::active()?;
    let cd = shared.card(cd)?;
    let bit = 1u32 << ch.0;
    shared.set_servo_on(cd, bit, on);
    Ok(c::NO_ERR)
}

/// Turns the servo-on output of one channel on (at once, not queued: user manual §2.3).
#[no_mangle]
pub extern "system" fn MCC_SetServoOn(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { servo(wChannel, wCardIndex, true) }
}

/// Turns the servo-on output of one channel off.
#[no_mangle]
pub extern "system" fn MCC_SetServoOff(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { servo(wChannel, wCardIndex, false) }
}

fn pos_ready(wCardIndex: WORD, on: bool) -> McclResult<c_int> {
    let shared = system::active()?;
    let cd = shared.card(card(wCardIndex)?)?;
    shared.set_pos_ready(cd, on);
    Ok(c::NO_ERR)
}

/// Turns the card's position-ready output on.
#[no_mangle]
pub extern "system" fn MCC_EnablePosReady(wCardIndex: WORD) -> c_int {
    ffi_boundary! { pos_ready(wCardIndex, true) }
}

/// Turns the card's position-ready output off.
#[no_mangle]
pub extern "system" fn MCC_DisablePosReady(wCardIndex: WORD) -> c_int {
    ffi_boundary! { pos_ready(wCardIndex, false) }
}

/// The emergency-stop input of the card: 1 pressed, 0 released.
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetEmgcStopStatus(
    pwStatus: *mut WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(pwStatus, || {
                with_machine(Card(wCardIndex), |m, cd| Ok(WORD::from(m.emergency(cd))))
            })
        }
    }
}

fn led(Channel: WORD, wCardIndex: WORD, on: bool) -> McclResult<c_int> {
    let ch = channel(Channel)?;
    with_machine(Card(wCardIndex), |m, cd| {
        m.card_settings_mut(cd).set_led(ch.0, on);
        Ok(c::NO_ERR)
    })
}

/// Turns a channel's LED output on.
#[no_mangle]
pub extern "system" fn MCC_SetLedLightOn(Channel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { led(Channel, wCardIndex, true) }
}

/// Turns a channel's LED output off.
#[no_mangle]
pub extern "system" fn MCC_SetLedLightOff(Channel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { led(Channel, wCardIndex, false) }
}

/// A channel's LED output: 1 on, 0 off (while an LED trigger-out holds it: its trigger
/// value).
///
/// # Safety
/// `Status` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetLedLightStatus(
    Channel: WORD,
    Status: *mut WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let ch = channel(Channel)?;
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(Status, || {
                with_machine(Card(wCardIndex), |m, cd| Ok(WORD::from(m.led_lit(cd, ch.0))))
            })
        }
    }
}

/// Keeps filter clock `k` of the card (any WORD: the manuals give no range).
pub(super) fn filter(k: FilterClock, Value: WORD, wCardIndex: WORD) -> McclResult<c_int> {
    with_machine(Card(wCardIndex), |m, cd| {
        m.card_settings_mut(cd).set_filter_clock(k, Value);
        Ok(c::NO_ERR)
    })
}

/// Filter clock of the limit switch inputs (kept: the simulated inputs do not bounce).
#[no_mangle]
pub extern "system" fn MCC_SetLimitFilterClk(Value: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { filter(FilterClock::Limit, Value, wCardIndex) }
}

/// Filter clock of the home sensor inputs (kept: the simulated inputs do not bounce).
#[no_mangle]
pub extern "system" fn MCC_SetHomeFilterClk(Value: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { filter(FilterClock::Home, Value, wCardIndex) }
}

/// Filter clock of the general-purpose inputs (kept: the simulated inputs do not bounce).
#[no_mangle]
pub extern "system" fn MCC_SetGpioFilterClk(Value: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { filter(FilterClock::Gpio, Value, wCardIndex) }
}

/// The home sensor of a channel as its go-home wiring (`wSensorMode`) reads it: 1 active.
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetHomeSensorStatus(
    pwStatus: *mut WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let (cd, ch) = (card(wCardIndex)?, channel(wChannel)?);
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(pwStatus, || {
                let mode = system::config(|c| c.home[cd.0][ch.0].wSensorMode);
                with_machine_channel(super::Channel(wChannel), Card(wCardIndex), |chan| {
                    Ok(WORD::from(chan.home_level(mode)))
                })
            })
        }
    }
}

/// A local input point (`LIO_LDI_OTP0..7`, `OTN0..7`, `HOME0..7`).
fn lio_point(wPoint: WORD) -> McclResult<usize> {
    index(wPoint, 24)
}

/// A trigger-out point: a local output or an LED (0..7).
fn out_point(wPoint: WORD) -> McclResult<usize> {
    index(wPoint, 8)
}

/// Trigger type of a local input (`LIO_LDI_OTP0..7`, `OTN0..7`, `HOME0..7`):
/// `LIO_INT_NO`, `LIO_INT_RISE` (default), `LIO_INT_FALL`, `LIO_INT_LEVEL` (every tick
/// while active).
#[no_mangle]
pub extern "system" fn MCC_SetLIOTriggerType(
    wTriggerType: WORD,
    wPoint: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = lio_point(wPoint)?;
        if wTriggerType > c::LIO_INT_LEVEL {
            return Err(McclError::Parameter);
        }
        with_card_triggers(Card(wCardIndex), |t| {
            t.set_input_type(p, wTriggerType);
            Ok(c::NO_ERR)
        })
    }
}

fn lio_trigger(wPoint: WORD, wCardIndex: WORD, on: bool) -> McclResult<c_int> {
    let p = lio_point(wPoint)?;
    with_card_triggers(Card(wCardIndex), |t| {
        t.enable_input(p, on);
        Ok(c::NO_ERR)
    })
}

/// The local-input routine is called (`LIOINT`) on the point's trigger.
#[no_mangle]
pub extern "system" fn MCC_EnableLIOTrigger(wPoint: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { lio_trigger(wPoint, wCardIndex, true) }
}

/// The point no longer calls the local-input routine.
#[no_mangle]
pub extern "system" fn MCC_DisableLIOTrigger(wPoint: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { lio_trigger(wPoint, wCardIndex, false) }
}

/// Compare sources from C: bit n is the compare of channel n (0..7).
fn sources(w: WORD) -> McclResult<u16> {
    bits(w, 0xFF)
}

/// Before an LED trigger-out setting looks at its arguments: INITIAL_MOTION_ERR before
/// init whatever they are. A local output's setting checks its arguments first.
fn trig_out_ready(kind: TrigOutKind) -> McclResult<()> {
    match kind {
        TrigOutKind::Led => super::initialised(),
        TrigOutKind::Local => Ok(()),
    }
}

/// Sets `setting` (as checked from C's value) of trigger-out point `wPoint` (0..7) of
/// `kind` on card `wCardIndex`; checked in this order: [`trig_out_ready`], the setting,
/// the point, the card.
fn set_trig_out(
    kind: TrigOutKind,
    setting: McclResult<TrigOutSetting>,
    wPoint: WORD,
    wCardIndex: WORD,
) -> McclResult<c_int> {
    trig_out_ready(kind)?;
    let s = setting?;
    let p = out_point(wPoint)?;
    with_card_triggers(Card(wCardIndex), |t| {
        t.set_trig_out(kind, p, s);
        Ok(c::NO_ERR)
    })
}

/// Trigger-out of a local output point (0..7: the servo-on output of that channel) on
/// (1) or off (0): when a compare of its source fires, the output takes its trigger
/// value for the trigger period, then returns.
#[no_mangle]
pub extern "system" fn MCC_SetLIOTrigOutEnable(
    wEnable: WORD,
    wPoint: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let s = flag(wEnable).map(TrigOutSetting::Enabled);
        set_trig_out(TrigOutKind::Local, s, wPoint, wCardIndex)
    }
}

/// The value a triggered output takes (1: servo off, 0: servo on, as the examples
/// manual's §26 uses it).
#[no_mangle]
pub extern "system" fn MCC_SetLIOTrigOutValue(
    wValue: WORD,
    wPoint: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let s = flag(wValue).map(TrigOutSetting::Value);
        set_trig_out(TrigOutKind::Local, s, wPoint, wCardIndex)
    }
}

/// The compares (`LIO_SOURCE_COMP0..7` / `IO_TRIG_ENC0..7` bits) that trigger a point.
#[no_mangle]
pub extern "system" fn MCC_SetLIOTrigOutSource(
    wSource: WORD,
    wPoint: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let s = sources(wSource).map(TrigOutSetting::Source);
        set_trig_out(TrigOutKind::Local, s, wPoint, wCardIndex)
    }
}

/// LED trigger-out of LED `wPoint` (0..7, the LED `MCC_SetLedLightOn` of that channel
/// lights) on (1) or off (0): when a compare of its source fires, the LED shows its
/// trigger value for the trigger period (`MCC_SetLIOTrigOutPeriod`, shared with the
/// local outputs), then what `MCC_SetLedLightOn`/`Off` set.
#[no_mangle]
pub extern "system" fn MCC_SetLedTrigOutEnable(
    wEnable: WORD,
    wPoint: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let s = flag(wEnable).map(TrigOutSetting::Enabled);
        set_trig_out(TrigOutKind::Led, s, wPoint, wCardIndex)
    }
}

/// The value a triggered LED shows: 1 lit, 0 dark.
#[no_mangle]
pub extern "system" fn MCC_SetLedTrigOutValue(
    wOutput: WORD,
    wPoint: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let s = flag(wOutput).map(TrigOutSetting::Value);
        set_trig_out(TrigOutKind::Led, s, wPoint, wCardIndex)
    }
}

/// The compares (`LED_TRIG_ENC0..7` bits: compare of channel 0..7) that trigger an LED.
#[no_mangle]
pub extern "system" fn MCC_SetLedTrigOutSource(
    wSource: WORD,
    wPoint: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let s = sources(wSource).map(TrigOutSetting::Source);
        set_trig_out(TrigOutKind::Led, s, wPoint, wCardIndex)
    }
}

/// Trigger values of several points at once: bit n of the mask selects point n.
#[no_mangle]
pub extern "system" fn MCC_SetLIOTrigOutValueEx(
    dwBitMask: DWORD,
    dwBitValue: DWORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        bits(dwBitMask, 0xFF)?;
        with_card_triggers(Card(wCardIndex), |t| {
            t.set_trig_out_values(dwBitMask, dwBitValue);
            Ok(c::NO_ERR)
        })
    }
}

/// How long a triggered output or LED holds its value, ns (rounded up to whole ticks).
#[no_mangle]
pub extern "system" fn MCC_SetLIOTrigOutPeriod(dwPeriod: DWORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        with_card_triggers(Card(wCardIndex), |t| {
            t.set_trig_period_ns(u64::from(dwPeriod));
            Ok(c::NO_ERR)
        })
    }
}

/// Compare values waiting on the channels that trigger local outputs.
///
/// # Safety
/// `wCount` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetLIOCompStockCount(
    wCount: *mut WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(wCount, || {
                with_card_triggers(Card(wCardIndex), |t| {
                    Ok(word_count(t.lio_comp_stock_count()))
                })
            })
        }
    }
}

/// Removes the compare values of the channels that trigger local outputs.
#[no_mangle]
pub extern "system" fn MCC_EraseLIOCompValue(wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        with_card_triggers(Card(wCardIndex), |t| {
            t.erase_lio_comp_values();
            Ok(c::NO_ERR)
        })
    }
}
