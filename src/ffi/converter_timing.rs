//! Timing of the D/A and A/D converters and the RIO sets (vendor header, "Obsolete
//! functions"; the manuals do not describe them): a clock divider (system clocks of 10 ns
//! per serial bit) and an update rate (Hz, the least time between cycles), read as the
//! ARIO setters are ([`crate::card::cadence`], docs/undocumented-functions.md). An update
//! rate is finite, > 0, its period `1 / rate` at most the longest time of "Ranges"
//! (2³² − 1 ms), as `MCC_SetARIOUpdateRate` checks it
//! ([`crate::card::cadence::update_period_ns`]).
//!
//! Each setter is `INITIAL_MOTION_ERR` before init whatever the arguments, then
//! `PARAMETER_ERR` for a card not initialised, a bad set, divider or rate (nothing
//! changed).

use super::card_do;
use crate::vendor::WORD;
use std::os::raw::c_int;

/// D/A clock: one bit every `wDivider` system clocks (1..65535, default 10); a channel's
/// update (16 bits) lasts `16 × wDivider × 10 ns`, and its output changes at most once
/// per update.
#[no_mangle]
pub extern "system" fn MCC_SetDACClockDivider(wDivider: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.dac_mut().set_clock_divider(wDivider)) }
}

/// At most `dfUpdateRate` updates per second (Hz, > 0) on each D/A channel: a value
/// written sooner than `1 / rate` after the channel's last change waits for it.
#[no_mangle]
pub extern "system" fn MCC_SetDACUpdateRate(dfUpdateRate: f64, wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.dac_mut().set_update_rate(dfUpdateRate)) }
}

/// A/D clock: one conversion clock every `wDivider` system clocks (1..65535, default
/// 50); a free-running scan lasts `16 × enabled channels × wDivider × 10 ns`. The scan
/// count restarts at the call.
#[no_mangle]
pub extern "system" fn MCC_SetADCClockDivider(wDivider: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.adc_mut().set_clock_divider(wDivider)) }
}

/// At most `dfUpdateRate` free-running scans per second (Hz, > 0). The scan count
/// restarts at the call.
#[no_mangle]
pub extern "system" fn MCC_SetADCUpdateRate(dfUpdateRate: f64, wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.adc_mut().set_update_rate(dfUpdateRate)) }
}

/// Serial clock of a RIO set: one bit every `wDivider` system clocks (1..65535, default
/// 10); a transfer cycle lasts `32 × transmitting slaves (at least 1) × wDivider × 10 ns`.
/// The cycle count restarts at the call.
#[no_mangle]
pub extern "system" fn MCC_SetRIOClockDivider(
    wDivider: WORD,
    wSet: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        card_do(wCardIndex, |p| {
            p.remote_io_mut().set_rio_clock_divider(usize::from(wSet), wDivider)
        })
    }
}

/// At most `dfUpdateRate` transfer cycles per second (Hz, > 0) for a RIO set. The cycle
/// count restarts at the call.
#[no_mangle]
pub extern "system" fn MCC_SetRIOUpdateRate(
    dfUpdateRate: f64,
    wSet: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        card_do(wCardIndex, |p| {
            p.remote_io_mut().set_rio_update_rate(usize::from(wSet), dfUpdateRate)
        })
    }
}
