//! The card's timer and watchdog through the C entry points, on the stepped clock: 1 ms
//! ticks, `MCC_TimeDelay(n)` runs exactly n ticks.

mod common;

use common::periph::{periph, status, x_pos};
use common::{fresh, init_ms};
use std::sync::atomic::{AtomicU32, Ordering::SeqCst};
use MCCLPCI_IMP::engine::isr::ERR_WATCHDOG_RESET;
use MCCLPCI_IMP::ffi::dac::*;
use MCCLPCI_IMP::ffi::isr::*;
use MCCLPCI_IMP::ffi::local_io::*;
use MCCLPCI_IMP::ffi::motion::*;
use MCCLPCI_IMP::ffi::rio::*;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::timer::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::*;

// ---- timer ----

static TMR_CALLS: AtomicU32 = AtomicU32::new(0);
static TMR_SUM: AtomicU32 = AtomicU32::new(0);

unsafe extern "system" fn tmr_count(p: *mut TMRINT) {
    TMR_CALLS.fetch_add(1, SeqCst);
    // SAFETY: valid for the call.
    TMR_SUM.fetch_add(u32::from(unsafe { (*p).TIMER }), SeqCst);
}

#[test]
fn timer_fires_every_period_on_the_stepped_clock() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    TMR_CALLS.store(0, SeqCst);
    TMR_SUM.store(0, SeqCst);
    assert_eq!(MCC_SetTMRRoutine(Some(tmr_count), 0), NO_ERR);
    assert_eq!(MCC_SetTimer(300_000, 0), NO_ERR); // 3 ms in 10 ns clocks
    assert_eq!(MCC_EnableTimerTrigger(0), NO_ERR);
    MCC_TimeDelay(10);
    assert_eq!(TMR_CALLS.load(SeqCst), 0, "timer not enabled");
    assert_eq!(MCC_EnableTimer(0), NO_ERR);
    MCC_TimeDelay(2);
    assert_eq!(TMR_CALLS.load(SeqCst), 0);
    MCC_TimeDelay(1);
    assert_eq!(
        TMR_CALLS.load(SeqCst),
        1,
        "fires in the tick where 3 ms elapsed"
    );
    MCC_TimeDelay(27);
    assert_eq!((TMR_CALLS.load(SeqCst), TMR_SUM.load(SeqCst)), (10, 10));
    assert_eq!(MCC_DisableTimerTrigger(0), NO_ERR);
    MCC_TimeDelay(9);
    assert_eq!(TMR_CALLS.load(SeqCst), 10, "trigger off");
    assert_eq!(MCC_EnableTimerTrigger(0), NO_ERR);
    // Shorter than a tick: once per tick, TIMER = expirations (saturated at 255).
    assert_eq!(MCC_SetTimer(50_000, 0), NO_ERR); // 0.5 ms
    MCC_TimeDelay(4);
    assert_eq!((TMR_CALLS.load(SeqCst), TMR_SUM.load(SeqCst)), (14, 18));
    assert_eq!(MCC_SetTimer(100, 0), NO_ERR); // 1 us: 1000 per tick
    MCC_TimeDelay(2);
    assert_eq!(
        (TMR_CALLS.load(SeqCst), TMR_SUM.load(SeqCst)),
        (16, 18 + 510)
    );
    assert_eq!(MCC_DisableTimer(0), NO_ERR);
    MCC_TimeDelay(5);
    assert_eq!(TMR_CALLS.load(SeqCst), 16);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

// ---- watchdog ----

#[test]
fn watchdog_expiry_resets_the_card() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetServoOn(0, 0), NO_ERR);
    assert_eq!(MCC_SetServoOn(3, 0), NO_ERR);
    assert_eq!(MCC_EnablePosReady(0), NO_ERR);
    assert_eq!(MCC_SetDACOutput(3.0, 4, 0), NO_ERR);
    assert_eq!(MCC_SetARIOOutputValue(0xF0F0, 0, 2, 0), NO_ERR);
    assert_eq!(MCC_SetRIOOutputValue(0x0F0F, 1, 3, 0), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    assert!(MCC_Line(100.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL) >= 0);

    assert_eq!(MCC_SetTimer(100_000, 0), NO_ERR); // 1 ms
    assert_eq!(MCC_SetWatchDogTimer(10, 0), NO_ERR); // 10 timer periods = 10 ms
    assert_eq!(MCC_SetWatchDogResetPeriod(10_000, 0), NO_ERR);
    assert_eq!(MCC_EnableWatchDogTimer(0), NO_ERR);
    MCC_TimeDelay(20);
    assert!(
        periph(0).watchdog().enabled(),
        "counts only while the timer runs"
    );
    assert_eq!(MCC_EnableTimer(0), NO_ERR);
    MCC_TimeDelay(9);
    assert_eq!(MCC_RefreshWatchDogTimer(0), NO_ERR);
    MCC_TimeDelay(9);
    assert_eq!(status(0), GMS_RUNNING, "refreshed in time");
    assert_eq!(MCC_GetErrorCode(0), 0);
    MCC_TimeDelay(1);
    // Expired: the card was reset. Its motion stops at once, as an abort at once: the
    // status reads running for that period and STOP the period after (as the vendor's
    // library shows an abort; nothing is held, so never GMS_HOLD).
    assert_eq!(MCC_GetErrorCode(0), ERR_WATCHDOG_RESET);
    let x = x_pos(0);
    assert_eq!(status(0), GMS_RUNNING);
    MCC_TimeDelay(1);
    assert_eq!(status(0), GMS_STOP);
    assert_eq!(x_pos(0), x);
    let shared = MCCLPCI_IMP::system::active().unwrap();
    assert_eq!(shared.servo_on(0), 0);
    assert!(!shared.pos_ready(0));
    let p = periph(0);
    assert_eq!(p.dac().output(4), 0.0);
    assert_eq!(p.remote_io().ario_sets()[0].output(2), Ok(0));
    assert_eq!(p.remote_io().rio_sets()[1].output(3), Ok(0));
    assert!(!p.watchdog().enabled());
    assert_eq!(p.watchdog().resets(), 1);
    let x = x_pos(0);
    MCC_TimeDelay(5);
    assert_eq!(x_pos(0), x, "stopped where it was");
    assert_eq!(MCC_ClearError(0), NO_ERR);
    assert_eq!(MCC_GetErrorCode(0), 0);
    assert_eq!(MCC_DisableWatchDogTimer(0), NO_ERR);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
