//! Encoder counters (user manual §2.10.1; INTERFACE.md "Encoder Control"). The simulated
//! encoder follows the motor: one count per pulse at x4, half at x2, a quarter at x1,
//! reversed by A/B swap or a single inverted phase, scaled by `MCC_SetENCGearRate`.

use super::{card, channel, finite, guard, out_ok, write_out};
use crate::error::{McclError, McclResult};
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::{c_int, c_long, c_longlong};

fn with_channel<R>(
    wChannel: WORD,
    wCardIndex: WORD,
    f: impl FnOnce(&mut crate::machine::Channel) -> McclResult<R>,
) -> McclResult<R> {
    let (cd, ch) = (card(wCardIndex)?, channel(wChannel)?);
    let shared = system::active()?;
    let cd = shared.card(cd)?;
    let mut m = shared.machine.lock();
    f(m.channel_mut(cd, ch.0).ok_or(McclError::Parameter)?)
}

/// The encoder count of a channel.
///
/// # Safety
/// `plValue` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetENCValue(
    plValue: *mut c_long,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    guard(|| {
        out_ok(plValue)?;
        let v = with_channel(wChannel, wCardIndex, |ch| Ok(ch.encoder()))?;
        // SAFETY: checked non-null; the caller passes a writable long.
        unsafe { write_out(plValue, v as c_long) };
        Ok(c::NO_ERR)
    })
}

/// The encoder count of a channel, 64-bit.
///
/// # Safety
/// `pllValue` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetENCValueEx(
    pllValue: *mut c_longlong,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    guard(|| {
        out_ok(pllValue)?;
        let v = with_channel(wChannel, wCardIndex, |ch| Ok(ch.encoder()))?;
        // SAFETY: checked non-null; the caller passes a writable long long.
        unsafe { write_out(pllValue, v) };
        Ok(c::NO_ERR)
    })
}

/// Sets the encoder count of a channel to `lValue` (the motor does not move).
#[no_mangle]
pub extern "C" fn MCC_SetENCValue(lValue: c_long, wChannel: WORD, wCardIndex: WORD) -> c_int {
    guard(|| {
        with_channel(wChannel, wCardIndex, |ch| {
            // `long` is 32-bit on Windows, 64-bit on Linux: convert portably.
            #[allow(clippy::useless_conversion)]
            ch.set_encoder(i64::from(lValue));
            Ok(c::NO_ERR)
        })
    })
}

/// Sets the encoder count of a channel to 0.
#[no_mangle]
pub extern "C" fn MCC_ClearENCCounter(wChannel: WORD, wCardIndex: WORD) -> c_int {
    MCC_SetENCValue(0, wChannel, wCardIndex)
}

/// Counts per encoder cycle: 1, 2 or 4 (3, `ENC_RATE_X4`, also means x4). The count
/// keeps its value at the change.
#[no_mangle]
pub extern "C" fn MCC_SetENCInputRate(wInputRate: WORD, wChannel: WORD, wCardIndex: WORD) -> c_int {
    guard(|| {
        if !(1..=4).contains(&wInputRate) {
            return Err(McclError::Parameter);
        }
        with_channel(wChannel, wCardIndex, |ch| {
            let v = ch.encoder();
            ch.input_rate = Some(wInputRate);
            ch.set_encoder(v);
            Ok(c::NO_ERR)
        })
    })
}

/// Scales the encoder's counting (finite, > 0). The count keeps its value at the change.
#[no_mangle]
pub extern "C" fn MCC_SetENCGearRate(dfGearRate: f64, wChannel: WORD, wCardIndex: WORD) -> c_int {
    guard(|| {
        let r = finite(dfGearRate)?;
        if r <= 0.0 {
            return Err(McclError::Parameter);
        }
        with_channel(wChannel, wCardIndex, |ch| {
            let v = ch.encoder();
            ch.gear_rate = r;
            ch.set_encoder(v);
            Ok(c::NO_ERR)
        })
    })
}
