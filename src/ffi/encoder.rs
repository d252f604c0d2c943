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

pointer_fns! {
    /// The encoder count of a channel.
    MCC_GetENCValue(plValue: c_long; wChannel, wCardIndex) = write_out(plValue, || {
        with_machine_channel(Channel(wChannel), Card(wCardIndex), |ch| {
            Ok(ch.encoder() as c_long)
        })
    });
    /// The encoder count of a channel, 64-bit.
    MCC_GetENCValueEx(pllValue: c_longlong; wChannel, wCardIndex) = write_out(pllValue, || {
        with_machine_channel(Channel(wChannel), Card(wCardIndex), |ch| Ok(ch.encoder()))
    });
}

/// Sets the encoder count of a channel to `lValue` (|lValue| <= 1e18; the motor does not
/// move).
#[no_mangle]
pub extern "C" fn MCC_SetENCValue(lValue: c_long, wChannel: WORD, wCardIndex: WORD) -> c_int {
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
pub extern "C" fn MCC_ClearENCCounter(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
    Ok(MCC_SetENCValue(0, wChannel, wCardIndex))
        }
}

/// Counts per encoder cycle: 1, 2 or 4 (3, `ENC_RATE_X4`, also means x4). The count
/// keeps its value at the change.
#[no_mangle]
pub extern "C" fn MCC_SetENCInputRate(wInputRate: WORD, wChannel: WORD, wCardIndex: WORD) -> c_int {
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
pub extern "C" fn MCC_SetENCGearRate(dfGearRate: f64, wChannel: WORD, wCardIndex: WORD) -> c_int {
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
pub extern "C" fn MCC_SetENCFilterClock(wDivider: WORD, wCardIndex: WORD) -> c_int {
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
    with_machine(cd, |m, cd| f(&mut m.triggers[cd], &m.cards[cd]))
}

/// Latch type of a channel: `ENC_TRIG_FIRST` (keep the first event) or `ENC_TRIG_LAST`
/// (every event). Setting it re-arms the latch.
#[no_mangle]
pub extern "C" fn MCC_SetENCLatchType(wType: WORD, wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        let ch = channel(wChannel)?;
        if wType > c::ENC_TRIG_LAST {
            return Err(McclError::Parameter);
        }
        with_triggers(Card(wCardIndex), |t, _| {
            t.set_latch_type(ch.0, wType);
            Ok(c::NO_ERR)
        })
    }
}

/// Latch sources of a channel: `ENC_TRIG_INDEX0..7`, `ENC_TRIG_OTP0..7`,
/// `ENC_TRIG_OTN0..7` (the count is latched when that index pulse passes or that limit
/// switch turns active). Setting them re-arms the latch.
#[no_mangle]
pub extern "C" fn MCC_SetENCLatchSource(wSource: DWORD, wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        let ch = channel(wChannel)?;
        bits(wSource, 0x00FF_FFFF)?;
        with_triggers(Card(wCardIndex), |t, _| {
            t.set_latch_source(ch.0, wSource);
            Ok(c::NO_ERR)
        })
    }
}

/// The latched count of a channel (0 until something was latched).
///
/// # Safety
/// `plLatchValue` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetENCLatchValue(
    plLatchValue: *mut c_long,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let ch = channel(wChannel)?;
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(plLatchValue, || {
                with_triggers(Card(wCardIndex), |t, _| Ok(t.latch_value(ch.0) as c_long))
            })
        }
    }
}

fn index_trigger(wChannel: WORD, wCardIndex: WORD, on: bool) -> McclResult<c_int> {
    let ch = channel(wChannel)?;
    with_triggers(Card(wCardIndex), |t, _| {
        t.index_enabled[ch.0] = on;
        Ok(c::NO_ERR)
    })
}

on_off! {
    /// The encoder routine is called (`ENCINT.INDEXn`) when an index pulse of the channel
    /// passes.
    MCC_EnableENCIndexTrigger,
    /// Index pulses no longer call the encoder routine.
    MCC_DisableENCIndexTrigger(wChannel: WORD, wCardIndex: WORD)
        = |on| index_trigger(wChannel, wCardIndex, on);
}

/// 1 when an index pulse of the channel passed since the last read (the read clears it).
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetENCIndexStatus(
    pwStatus: *mut WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let ch = channel(wChannel)?;
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(pwStatus, || {
                with_triggers(Card(wCardIndex), |t, _| Ok(WORD::from(t.take_index_status(ch.0))))
            })
        }
    }
}

/// Adds a compare value to the channel's stock: when the count reaches it the encoder
/// routine is called (`ENCINT.COMPn`, if the compare trigger is on), trigger-outs and DAC
/// triggers from this channel fire, and the next value of the stock is armed.
#[no_mangle]
pub extern "C" fn MCC_SetENCCompValue(lValue: c_long, wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        let ch = channel(wChannel)?;
        // `long` is 32-bit on Windows, 64-bit on Linux: convert portably.
        #[allow(clippy::useless_conversion)]
        let v = crate::config::range::enc_count(i64::from(lValue))?;
        with_triggers(Card(wCardIndex), |t, _| {
            t.push_compare(ch.0, v).map(|()| c::NO_ERR)
        })
    }
}

/// Adds the compare values start, start + delta, ... up to end (inclusive) to the stock.
#[no_mangle]
pub extern "C" fn MCC_SetENCCompValueTab(
    lStartValue: c_long,
    lEndValue: c_long,
    lDeltaValue: c_long,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let ch = channel(wChannel)?;
        #[allow(clippy::useless_conversion)]
        let (a, b, d) = (
            crate::config::range::enc_count(i64::from(lStartValue))?,
            crate::config::range::enc_count(i64::from(lEndValue))?,
            crate::config::range::enc_count(i64::from(lDeltaValue))?,
        );
        let table = CompareTable::new(a, b, d)?;
        with_triggers(Card(wCardIndex), |t, _| {
            t.push_compare_table(ch.0, &table).map(|()| c::NO_ERR)
        })
    }
}

/// The armed compare value of a channel (0 when the stock is empty).
///
/// # Safety
/// `lValue` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetENCCompValue(
    lValue: *mut c_long,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let ch = channel(wChannel)?;
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(lValue, || {
                with_triggers(Card(wCardIndex), |t, _| Ok(t.armed_compare(ch.0) as c_long))
            })
        }
    }
}

/// How many compare values of the channel are waiting (the armed one included).
///
/// # Safety
/// `wCount` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetENCCompStockCount(
    wCount: *mut WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let ch = channel(wChannel)?;
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(wCount, || {
                with_triggers(Card(wCardIndex), |t, _| Ok(word_count(t.stock_count(ch.0))))
            })
        }
    }
}

fn comp_trigger(wChannel: WORD, wCardIndex: WORD, on: bool) -> McclResult<c_int> {
    let ch = channel(wChannel)?;
    with_triggers(Card(wCardIndex), |t, chans| {
        t.set_compare_trigger(ch.0, on, chans);
        Ok(c::NO_ERR)
    })
}

on_off! {
    /// The channel's compare stock is active: values fire as the count reaches them.
    MCC_EnableENCCompTrigger,
    /// The channel's compare stock stops firing (the values stay).
    MCC_DisableENCCompTrigger(wChannel: WORD, wCardIndex: WORD)
        = |on| comp_trigger(wChannel, wCardIndex, on);
}

/// Removes every compare value of the channel.
#[no_mangle]
pub extern "C" fn MCC_EraseENCCompValue(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        let ch = channel(wChannel)?;
        with_triggers(Card(wCardIndex), |t, _| {
            t.stock[ch.0].clear();
            Ok(c::NO_ERR)
        })
    }
}

/// Channels compared together (bit n: channel n): with two or more, their armed values
/// fire together when every one of them is reached within the 3-D tolerance.
#[no_mangle]
pub extern "C" fn MCC_Enable3DCompareChannel(wCompareAxisMask: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        bits(wCompareAxisMask, 0xFF)?;
        with_triggers(Card(wCardIndex), |t, _| {
            t.compare_mask = wCompareAxisMask;
            Ok(c::NO_ERR)
        })
    }
}

/// Tolerance (counts) of the 3-D compare.
#[no_mangle]
pub extern "C" fn MCC_Set3DCompareTolerance(wTolerance: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        with_triggers(Card(wCardIndex), |t, _| {
            t.compare_tol = wTolerance;
            Ok(c::NO_ERR)
        })
    }
}
