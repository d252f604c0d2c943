//! Timer and watchdog (user manual §2.13; examples manual §31–32; vendor header "Timer &
//! Watch Dog Control"). Units: the timer counts system clocks of 10 ns; the watchdog
//! counts timer periods (see `crate::card::timer` and docs/compatibility.md).

use super::card_do;
use crate::vendor::{DWORD, WORD};
use std::os::raw::c_int;

/// Sets the timer's period in system clocks of 10 ns (1..=2^32-1; 0 is `PARAMETER_ERR`).
/// Counting restarts. Before any call the period is 100 (1 µs).
#[no_mangle]
pub extern "system" fn MCC_SetTimer(dwValue: DWORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.timer_mut().set_period(dwValue)) }
}

/// Starts the timer (counting from 0).
#[no_mangle]
pub extern "system" fn MCC_EnableTimer(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.timer_mut().set_enabled(true)) }
}

/// Stops the timer (and with it the watchdog's time base).
#[no_mangle]
pub extern "system" fn MCC_DisableTimer(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.timer_mut().set_enabled(false)) }
}

/// The timer's expirations call the TMR routine (`TMRINT.TIMER` = expirations in the
/// tick).
#[no_mangle]
pub extern "system" fn MCC_EnableTimerTrigger(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.timer_mut().set_trigger(true)) }
}

/// The timer's expirations no longer call the TMR routine.
#[no_mangle]
pub extern "system" fn MCC_DisableTimerTrigger(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.timer_mut().set_trigger(false)) }
}

/// Sets the watchdog's compare value in timer periods (1..=2^32-1): with the timer at its
/// default 1 µs, microseconds.
#[no_mangle]
pub extern "system" fn MCC_SetWatchDogTimer(wValue: DWORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.watchdog_mut().set_compare(wValue)) }
}

/// Sets the length of the watchdog's reset signal in system clocks (1..=2^32-1).
#[no_mangle]
pub extern "system" fn MCC_SetWatchDogResetPeriod(dwValue: DWORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.watchdog_mut().set_reset_period(dwValue)) }
}

/// Starts the watchdog (counting from 0). It counts while the timer runs; when the count
/// reaches the compare value the card is reset: its groups abort and record 0xF103
/// (`MCC_GetErrorCode`), servo-on and position-ready go off, DAC outputs go to 0 V,
/// remote outputs to 0, and the watchdog disables itself.
#[no_mangle]
pub extern "system" fn MCC_EnableWatchDogTimer(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.watchdog_mut().set_enabled(true)) }
}

/// Stops the watchdog.
#[no_mangle]
pub extern "system" fn MCC_DisableWatchDogTimer(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.watchdog_mut().set_enabled(false)) }
}

/// Clears the watchdog's count.
#[no_mangle]
pub extern "system" fn MCC_RefreshWatchDogTimer(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.watchdog_mut().refresh()) }
}
