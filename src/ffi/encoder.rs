//! Encoder counters (user manual §2.10.1; vendor header "Encoder Control"). The simulated
//! encoder follows the motor: one count per pulse at x4, half at x2, a quarter at x1,
//! reversed by A/B swap or a single inverted phase, scaled by `MCC_SetENCGearRate`.

use super::{
    bits, channel, with_machine, with_machine_channel, word_count, write_out, Card, Channel,
};
use crate::error::{McclError, McclResult};
use crate::machine::triggers::CompareTable;
use crate::vendor::consts as c;
use crate::vendor::DWORD;
use crate::vendor::WORD;
use std::os::raw::{c_int, c_long, c_longlong};

/// The encoder count of a channel.
///
/// # Safety
/// `plValue` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `c_long`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetENCValue(
    plValue: *mut c_long,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(plValue, || {
                with_machine_channel(Channel(wChannel), Card(wCardIndex), |ch| {
                    Ok(ch.encoder() as c_long)
                })
            })
        }
    }
}

/// The encoder count of a channel, 64-bit.
///
/// # Safety
/// `pllValue` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `c_longlong`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetENCValueEx(
    pllValue: *mut c_longlong,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(pllValue, || {
                with_machine_channel(Channel(wChannel), Card(wCardIndex), |ch| Ok(ch.encoder()))
            })
        }
    }
}

/// Sets the encoder count of a channel to `lValue` (|lValue| <= 1e18; the motor does not
/// move).
#[no_mangle]
pub extern "system" fn MCC_SetENCValue(lValue: c_long, wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        // `long` is 32-bit on Windows, 64-bit on Linux: convert portably.
        #[allow(clippy::useless_conversion)]
        let v = crate::config::range::enc_count(i64::from(lValue))?;
        with_machine_channel(Channel(wChannel), Card(wCardIndex), |ch| {
            ch.set_encoder(v);
            Ok(c::NO_ERR)
        })
    }
}

/// Sets the encoder count of a channel to 0.
#[no_mangle]
pub extern "system" fn MCC_ClearENCCounter(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
    Ok(MCC_SetENCValue(0, wChannel, wCardIndex))
        }
}

/// Counts per encoder cycle: 1, 2 or 4 (3, `ENC_RATE_X4`, also means x4). The count
/// keeps its value at the change.
#[no_mangle]
pub extern "system" fn MCC_SetENCInputRate(
    wInputRate: WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        if !(1..=4).contains(&wInputRate) {
            return Err(McclError::Parameter);
        }
        with_machine_channel(Channel(wChannel), Card(wCardIndex), |ch| {
            ch.set_input_rate(wInputRate);
            Ok(c::NO_ERR)
        })
    }
}

/// Scales the encoder's counting (counts per motor pulse at x4, 1e-3..=1e3). The count
/// keeps its value at the change.
#[no_mangle]
pub extern "system" fn MCC_SetENCGearRate(
    dfGearRate: f64,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let r = crate::config::range::enc_gear(dfGearRate)?;
        with_machine_channel(Channel(wChannel), Card(wCardIndex), |ch| {
            ch.set_gear_rate(r);
            Ok(c::NO_ERR)
        })
    }
}

/// Filter clock (divider) of the encoder inputs, kept per card like the other input
/// filter clocks: the simulated encoder has no electrical noise to filter.
#[no_mangle]
pub extern "system" fn MCC_SetENCFilterClock(wDivider: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
    super::local_io::filter(crate::machine::FilterClock::Encoder, wDivider, wCardIndex)
        }
}

fn with_triggers<R>(
    cd: Card,
    f: impl FnOnce(
        &mut crate::machine::triggers::CardTriggers,
        &[crate::machine::Channel; 8],
    ) -> McclResult<R>,
) -> McclResult<R> {
    with_machine(cd, |m, cd| {
        let (t, chans) = m.triggers_and_channels_mut(cd);
        f(t, chans)
    })
}

/// Runs `f` on the triggers of card `wCardIndex` for channel `wChannel` (checked first,
/// `PARAMETER_ERR`), with the card's channels; `NO_ERR` when `f` succeeds.
fn set_channel_triggers(
    wChannel: WORD,
    wCardIndex: WORD,
    f: impl FnOnce(
        &mut crate::machine::triggers::CardTriggers,
        usize,
        &[crate::machine::Channel; 8],
    ) -> McclResult<()>,
) -> McclResult<c_int> {
    let ch = channel(wChannel)?;
    with_triggers(Card(wCardIndex), |t, chans| f(t, ch.0, chans))?;
    Ok(c::NO_ERR)
}

/// What `f` reads from the triggers of card `wCardIndex` for channel `wChannel` (checked
/// first, `PARAMETER_ERR`).
fn channel_triggers<R>(
    wChannel: WORD,
    wCardIndex: WORD,
    f: impl FnOnce(&mut crate::machine::triggers::CardTriggers, usize) -> R,
) -> McclResult<R> {
    let ch = channel(wChannel)?;
    with_triggers(Card(wCardIndex), |t, _| Ok(f(t, ch.0)))
}

/// An encoder count from C (`long`: 32-bit on Windows, 64-bit on Linux), |v| <= 1e18.
fn enc_count(v: c_long) -> McclResult<i64> {
    #[allow(clippy::useless_conversion)]
    crate::config::range::enc_count(i64::from(v))
}

/// Latch type of a channel: `ENC_TRIG_FIRST` (keep the first event) or `ENC_TRIG_LAST`
/// (every event). Setting it re-arms the latch.
#[no_mangle]
pub extern "system" fn MCC_SetENCLatchType(wType: WORD, wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        channel(wChannel)?;
        if wType > c::ENC_TRIG_LAST {
            return Err(McclError::Parameter);
        }
        set_channel_triggers(wChannel, wCardIndex, |t, ch, _| {
            t.set_latch_type(ch, wType);
            Ok(())
        })
    }
}

/// Latch sources of a channel: `ENC_TRIG_INDEX0..7`, `ENC_TRIG_OTP0..7`,
/// `ENC_TRIG_OTN0..7` (the count is latched when that index pulse passes or that limit
/// switch turns active). Setting them re-arms the latch.
#[no_mangle]
pub extern "system" fn MCC_SetENCLatchSource(
    wSource: DWORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        channel(wChannel)?;
        bits(wSource, 0x00FF_FFFF)?;
        set_channel_triggers(wChannel, wCardIndex, |t, ch, _| {
            t.set_latch_source(ch, wSource);
            Ok(())
        })
    }
}

/// The latched count of a channel (0 until something was latched).
///
/// # Safety
/// `plLatchValue` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `c_long`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetENCLatchValue(
    plLatchValue: *mut c_long,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(plLatchValue, || {
                channel_triggers(wChannel, wCardIndex, |t, ch| t.latch_value(ch) as c_long)
            })
        }
    }
}

/// 1 when an index pulse of the channel passed since the last read (the read clears it).
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetENCIndexStatus(
    pwStatus: *mut WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(pwStatus, || {
                channel_triggers(wChannel, wCardIndex, |t, ch| {
                    WORD::from(t.take_index_status(ch))
                })
            })
        }
    }
}

/// The armed compare value of a channel (0 when the stock is empty).
///
/// # Safety
/// `lValue` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `c_long`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetENCCompValue(
    lValue: *mut c_long,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(lValue, || {
                channel_triggers(wChannel, wCardIndex, |t, ch| t.armed_compare(ch) as c_long)
            })
        }
    }
}

/// How many compare values of the channel are waiting (the armed one included).
///
/// # Safety
/// `wCount` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetENCCompStockCount(
    wCount: *mut WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(wCount, || {
                channel_triggers(wChannel, wCardIndex, |t, ch| word_count(t.stock_count(ch)))
            })
        }
    }
}

/// Index pulses of the channel call the encoder routine (`on`) or not.
fn index_trigger(wChannel: WORD, wCardIndex: WORD, on: bool) -> McclResult<c_int> {
    set_channel_triggers(wChannel, wCardIndex, |t, ch, _| {
        t.enable_index(ch, on);
        Ok(())
    })
}

/// The encoder routine is called (`ENCINT.INDEXn`) when an index pulse of the channel
/// passes.
#[no_mangle]
pub extern "system" fn MCC_EnableENCIndexTrigger(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { index_trigger(wChannel, wCardIndex, true) }
}

/// Index pulses no longer call the encoder routine.
#[no_mangle]
pub extern "system" fn MCC_DisableENCIndexTrigger(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { index_trigger(wChannel, wCardIndex, false) }
}

/// Adds a compare value to the channel's stock: when the count reaches it the encoder
/// routine is called (`ENCINT.COMPn`, if the compare trigger is on), trigger-outs and DAC
/// triggers from this channel fire, and the next value of the stock is armed.
#[no_mangle]
pub extern "system" fn MCC_SetENCCompValue(
    lValue: c_long,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        channel(wChannel)?;
        let v = enc_count(lValue)?;
        set_channel_triggers(wChannel, wCardIndex, |t, ch, _| t.push_compare(ch, v))
    }
}

/// Adds the compare values start, start + delta, ... up to end (inclusive) to the stock.
#[no_mangle]
pub extern "system" fn MCC_SetENCCompValueTab(
    lStartValue: c_long,
    lEndValue: c_long,
    lDeltaValue: c_long,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        channel(wChannel)?;
        let (a, b, d) = (enc_count(lStartValue)?, enc_count(lEndValue)?, enc_count(lDeltaValue)?);
        let table = CompareTable::new(a, b, d)?;
        set_channel_triggers(wChannel, wCardIndex, |t, ch, _| t.push_compare_table(ch, &table))
    }
}

/// The channel's compare stock fires (`on`) or not.
fn compare_trigger(wChannel: WORD, wCardIndex: WORD, on: bool) -> McclResult<c_int> {
    set_channel_triggers(wChannel, wCardIndex, |t, ch, chans| {
        t.set_compare_trigger(ch, on, chans);
        Ok(())
    })
}

/// The channel's compare stock is active: values fire as the count reaches them.
#[no_mangle]
pub extern "system" fn MCC_EnableENCCompTrigger(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { compare_trigger(wChannel, wCardIndex, true) }
}

/// The channel's compare stock stops firing (the values stay).
#[no_mangle]
pub extern "system" fn MCC_DisableENCCompTrigger(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { compare_trigger(wChannel, wCardIndex, false) }
}

/// Removes every compare value of the channel.
#[no_mangle]
pub extern "system" fn MCC_EraseENCCompValue(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        set_channel_triggers(wChannel, wCardIndex, |t, ch, _| {
            t.erase_compares(ch);
            Ok(())
        })
    }
}

/// Channels compared together (bit n: channel n): with two or more, their armed values
/// fire together when every one of them is reached within the 3-D tolerance.
#[no_mangle]
pub extern "system" fn MCC_Enable3DCompareChannel(
    wCompareAxisMask: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        bits(wCompareAxisMask, 0xFF)?;
        with_triggers(Card(wCardIndex), |t, _| {
            t.set_compare_mask(wCompareAxisMask);
            Ok(c::NO_ERR)
        })
    }
}

/// Tolerance (counts) of the 3-D compare.
#[no_mangle]
pub extern "system" fn MCC_Set3DCompareTolerance(wTolerance: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        with_triggers(Card(wCardIndex), |t, _| {
            t.set_compare_tolerance(wTolerance);
            Ok(c::NO_ERR)
        })
    }
}
