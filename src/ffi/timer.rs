//! Timer and watchdog (user manual §2.13; examples manual §31–32; vendor header "Timer &
//! Watch Dog Control"). Units: the timer counts system clocks of 10 ns; the watchdog
//! counts timer periods (see `crate::card::timer` and docs/compatibility.md).

use super::card_do;
use crate::vendor::{DWORD, WORD};

value_fns! {
    /// Sets the timer's period in system clocks of 10 ns (1..=2^32-1; 0 is `PARAMETER_ERR`).
    /// Counting restarts. Before any call the period is 100 (1 µs).
    MCC_SetTimer(dwValue: DWORD; wCardIndex) = card_do(wCardIndex, |p| p.timer.set_period(dwValue));
}

on_off! {
    /// Starts the timer (counting from 0).
    MCC_EnableTimer,
    /// Stops the timer (and with it the watchdog's time base).
    MCC_DisableTimer(wCardIndex: WORD)
        = |enable| card_do(wCardIndex, |p| p.timer.set_enabled(enable));
}

on_off! {
    /// The timer's expirations call the TMR routine (`TMRINT.TIMER` = expirations in the
    /// tick).
    MCC_EnableTimerTrigger,
    /// The timer's expirations no longer call the TMR routine.
    MCC_DisableTimerTrigger(wCardIndex: WORD)
        = |enable| card_do(wCardIndex, |p| p.timer.trigger = enable);
}

value_fns! {
    /// Sets the watchdog's compare value in timer periods (1..=2^32-1): with the timer at its
    /// default 1 µs, microseconds.
    MCC_SetWatchDogTimer(wValue: DWORD; wCardIndex)
        = card_do(wCardIndex, |p| p.watchdog.set_compare(wValue));
    /// Sets the length of the watchdog's reset signal in system clocks (1..=2^32-1).
    MCC_SetWatchDogResetPeriod(dwValue: DWORD; wCardIndex)
        = card_do(wCardIndex, |p| p.watchdog.set_reset_period(dwValue));
}

on_off! {
    /// Starts the watchdog (counting from 0). It counts while the timer runs; when the count
    /// reaches the compare value the card is reset: its groups abort and record 0xF103
    /// (`MCC_GetErrorCode`), servo-on and position-ready go off, DAC outputs go to 0 V,
    /// remote outputs to 0, and the watchdog disables itself.
    MCC_EnableWatchDogTimer,
    /// Stops the watchdog.
    MCC_DisableWatchDogTimer(wCardIndex: WORD)
        = |enable| card_do(wCardIndex, |p| p.watchdog.set_enabled(enable));
}

value_fns! {
    /// Clears the watchdog's count.
    MCC_RefreshWatchDogTimer(wCardIndex) = card_do(wCardIndex, |p| p.watchdog.refresh());
}
