//! The card peripherals' entry points and the interrupt routines' registration through
//! the C entry points: each refuses a bad argument before init and after, and a refused
//! call changes nothing (on the stepped clock: 1 ms ticks, `MCC_TimeDelay(n)` runs
//! exactly n ticks).

mod common;

use common::order_log::*;
use common::periph::periph;
use common::{fresh, init_ms};
use std::ptr::null_mut;
use MCCLPCI_IMP::engine::isr::ORDER;
use MCCLPCI_IMP::ffi::adc::*;
use MCCLPCI_IMP::ffi::dac::*;
use MCCLPCI_IMP::ffi::isr::*;
use MCCLPCI_IMP::ffi::rio::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::timer::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::*;

/// Addresses of a WORD, a DWORD and a float, each holding its sentinel (0x5555, 0x5555,
/// 7.0), allocated once.
fn out_bufs() -> (usize, usize, usize) {
    static BUFS: std::sync::OnceLock<(usize, usize, usize)> = std::sync::OnceLock::new();
    *BUFS.get_or_init(|| {
        (
            Box::leak(Box::new(0x5555 as WORD)) as *mut WORD as usize,
            Box::leak(Box::new(0x5555 as DWORD)) as *mut DWORD as usize,
            Box::leak(Box::new(7.0f32)) as *mut f32 as usize,
        )
    })
}

/// The sentinels of [`out_bufs`] are still there.
fn out_bufs_untouched() -> bool {
    let (w, d, f) = out_bufs();
    // SAFETY: leaked, live, aligned buffers of these types.
    unsafe {
        *(w as *const WORD) == 0x5555 && *(d as *const DWORD) == 0x5555 && *(f as *const f32) == 7.0
    }
}

type Call = Box<dyn Fn() -> i32>;

/// Every entry point with arguments that are all good except the one named.
fn bad_calls() -> Vec<(&'static str, Call)> {
    // Output buffers that outlive the calls (leaked: a few bytes per test run).
    let (wp, dwp, fp) = out_bufs();
    let w = move || wp as *mut WORD;
    let d = move || dwp as *mut DWORD;
    let fl = move || fp as *mut f32;
    // SAFETY (the unsafe calls below): every pointer is NULL or one of the leaked buffers.
    vec![
        ("SetTimer card", Box::new(|| MCC_SetTimer(100, 2))),
        ("SetTimer 0", Box::new(|| MCC_SetTimer(0, 0))),
        ("EnableTimer card", Box::new(|| MCC_EnableTimer(12))),
        ("DisableTimer card", Box::new(|| MCC_DisableTimer(2))),
        (
            "EnableTimerTrigger card",
            Box::new(|| MCC_EnableTimerTrigger(2)),
        ),
        (
            "DisableTimerTrigger card",
            Box::new(|| MCC_DisableTimerTrigger(2)),
        ),
        (
            "SetWatchDogTimer 0",
            Box::new(|| MCC_SetWatchDogTimer(0, 0)),
        ),
        (
            "SetWatchDogTimer card",
            Box::new(|| MCC_SetWatchDogTimer(5, 2)),
        ),
        (
            "SetWatchDogResetPeriod 0",
            Box::new(|| MCC_SetWatchDogResetPeriod(0, 0)),
        ),
        (
            "SetWatchDogResetPeriod card",
            Box::new(|| MCC_SetWatchDogResetPeriod(5, 2)),
        ),
        (
            "EnableWatchDogTimer card",
            Box::new(|| MCC_EnableWatchDogTimer(2)),
        ),
        (
            "DisableWatchDogTimer card",
            Box::new(|| MCC_DisableWatchDogTimer(2)),
        ),
        (
            "RefreshWatchDogTimer card",
            Box::new(|| MCC_RefreshWatchDogTimer(2)),
        ),
        (
            "SetDACOutput range",
            Box::new(|| MCC_SetDACOutput(10.5, 0, 0)),
        ),
        (
            "SetDACOutput NaN",
            Box::new(|| MCC_SetDACOutput(f32::NAN, 0, 0)),
        ),
        (
            "SetDACOutput inf",
            Box::new(|| MCC_SetDACOutput(f32::NEG_INFINITY, 0, 0)),
        ),
        (
            "SetDACOutput channel",
            Box::new(|| MCC_SetDACOutput(1.0, 8, 0)),
        ),
        (
            "SetDACOutput card",
            Box::new(|| MCC_SetDACOutput(1.0, 0, 2)),
        ),
        (
            "SetDACTriggerOutput range",
            Box::new(|| MCC_SetDACTriggerOutput(-11.0, 0, 0)),
        ),
        (
            "SetDACTriggerOutput NaN",
            Box::new(|| MCC_SetDACTriggerOutput(f32::NAN, 0, 0)),
        ),
        (
            "SetDACTriggerOutput channel",
            Box::new(|| MCC_SetDACTriggerOutput(1.0, 8, 0)),
        ),
        (
            "SetDACTriggerSource bits",
            Box::new(|| MCC_SetDACTriggerSource(0x100, 0, 0)),
        ),
        (
            "SetDACTriggerSource card",
            Box::new(|| MCC_SetDACTriggerSource(1, 0, 12)),
        ),
        (
            "EnableDACTriggerMode channel",
            Box::new(|| MCC_EnableDACTriggerMode(8, 0)),
        ),
        (
            "DisableDACTriggerMode card",
            Box::new(|| MCC_DisableDACTriggerMode(0, 2)),
        ),
        ("StartDACConv card", Box::new(|| MCC_StartDACConv(2))),
        ("StopDACConv card", Box::new(|| MCC_StopDACConv(2))),
        (
            "SetADCConvType type",
            Box::new(|| MCC_SetADCConvType(4, 0, 0)),
        ),
        (
            "SetADCConvType channel",
            Box::new(|| MCC_SetADCConvType(0, 8, 0)),
        ),
        (
            "GetADCConvType NULL",
            // SAFETY: NULL, which the entry point refuses.
            Box::new(|| unsafe { MCC_GetADCConvType(null_mut(), 0, 0) }),
        ),
        (
            "GetADCConvType channel",
            // SAFETY: a pointer to the test's own WORD.
            Box::new(move || unsafe { MCC_GetADCConvType(w(), 8, 0) }),
        ),
        ("SetADCConvMode mode", Box::new(|| MCC_SetADCConvMode(2, 0))),
        ("SetADCConvMode card", Box::new(|| MCC_SetADCConvMode(0, 2))),
        (
            "GetADCInput NULL",
            // SAFETY: NULL, which the entry point refuses.
            Box::new(|| unsafe { MCC_GetADCInput(null_mut(), 0, 0) }),
        ),
        (
            "GetADCInput card",
            // SAFETY: a pointer to the test's own WORD.
            Box::new(move || unsafe { MCC_GetADCInput(fl(), 0, 2) }),
        ),
        (
            "SetADCSingleChannel channel",
            Box::new(|| MCC_SetADCSingleChannel(8, 0)),
        ),
        (
            "GetADCWorkStatus NULL",
            // SAFETY: NULL, which the entry point refuses.
            Box::new(|| unsafe { MCC_GetADCWorkStatus(null_mut(), 0) }),
        ),
        (
            "GetADCWorkStatus card",
            // SAFETY: a pointer to the test's own WORD.
            Box::new(move || unsafe { MCC_GetADCWorkStatus(w(), 2) }),
        ),
        (
            "EnableADCConvTrigger card",
            Box::new(|| MCC_EnableADCConvTrigger(2)),
        ),
        (
            "DisableADCConvTrigger card",
            Box::new(|| MCC_DisableADCConvTrigger(2)),
        ),
        (
            "SetADCTagChannel channel",
            Box::new(|| MCC_SetADCTagChannel(8, 0)),
        ),
        (
            "EnableADCTagTrigger card",
            Box::new(|| MCC_EnableADCTagTrigger(2)),
        ),
        (
            "DisableADCTagTrigger card",
            Box::new(|| MCC_DisableADCTagTrigger(2)),
        ),
        ("SetADCCompMask mask", Box::new(|| MCC_SetADCCompMask(4, 0))),
        (
            "SetADCCompType type",
            Box::new(|| MCC_SetADCCompType(3, 0, 0)),
        ),
        (
            "SetADCCompType channel",
            Box::new(|| MCC_SetADCCompType(0, 8, 0)),
        ),
        (
            "SetADCCompValue NaN",
            Box::new(|| MCC_SetADCCompValue(f32::NAN, 0, 0)),
        ),
        (
            "SetADCCompValue range",
            Box::new(|| MCC_SetADCCompValue(12.0, 0, 0)),
        ),
        (
            "SetADCCompValue card",
            Box::new(|| MCC_SetADCCompValue(1.0, 0, 2)),
        ),
        (
            "GetADCCompValue NULL",
            // SAFETY: NULL, which the entry point refuses.
            Box::new(|| unsafe { MCC_GetADCCompValue(null_mut(), 0, 0) }),
        ),
        (
            "GetADCCompValue channel",
            // SAFETY: a pointer to the test's own WORD.
            Box::new(move || unsafe { MCC_GetADCCompValue(fl(), 8, 0) }),
        ),
        (
            "EnableADCCompTrigger channel",
            Box::new(|| MCC_EnableADCCompTrigger(8, 0)),
        ),
        (
            "DisableADCCompTrigger card",
            Box::new(|| MCC_DisableADCCompTrigger(0, 2)),
        ),
        (
            "EnableADCConvChannel channel",
            Box::new(|| MCC_EnableADCConvChannel(8, 0)),
        ),
        (
            "DisableADCConvChannel card",
            Box::new(|| MCC_DisableADCConvChannel(0, 2)),
        ),
        ("StartADCConv card", Box::new(|| MCC_StartADCConv(2))),
        ("StopADCConv card", Box::new(|| MCC_StopADCConv(2))),
        (
            "EnableRIOSetControl set",
            Box::new(|| MCC_EnableRIOSetControl(2, 0)),
        ),
        (
            "DisableRIOSetControl card",
            Box::new(|| MCC_DisableRIOSetControl(0, 2)),
        ),
        (
            "EnableRIOSlaveControl slave",
            Box::new(|| MCC_EnableRIOSlaveControl(0, 4, 0)),
        ),
        (
            "DisableRIOSlaveControl set",
            Box::new(|| MCC_DisableRIOSlaveControl(2, 0, 0)),
        ),
        (
            "GetRIOTransStatus NULL",
            // SAFETY: NULL, which the entry point refuses.
            Box::new(|| unsafe { MCC_GetRIOTransStatus(null_mut(), 0, 0) }),
        ),
        (
            "GetRIOTransStatus set",
            // SAFETY: a pointer to the test's own WORD.
            Box::new(move || unsafe { MCC_GetRIOTransStatus(w(), 2, 0) }),
        ),
        (
            "GetRIOMasterStatus card",
            // SAFETY: a pointer to the test's own WORD.
            Box::new(move || unsafe { MCC_GetRIOMasterStatus(w(), 0, 2) }),
        ),
        (
            "GetRIOSlaveStatus NULL",
            // SAFETY: NULL, which the entry point refuses.
            Box::new(|| unsafe { MCC_GetRIOSlaveStatus(null_mut(), 0, 0) }),
        ),
        (
            "GetRIOSlaveFail NULL",
            // SAFETY: NULL, which the entry point refuses.
            Box::new(|| unsafe { MCC_GetRIOSlaveFail(null_mut(), 0, 0) }),
        ),
        (
            "GetRIOSlaveFail set",
            // SAFETY: a pointer to the test's own WORD.
            Box::new(move || unsafe { MCC_GetRIOSlaveFail(d(), 2, 0) }),
        ),
        (
            "GetRIOInputValue port",
            // SAFETY: a pointer to the test's own WORD.
            Box::new(move || unsafe { MCC_GetRIOInputValue(w(), 0, 4, 0) }),
        ),
        (
            "GetRIOInputValue NULL",
            // SAFETY: NULL, which the entry point refuses.
            Box::new(|| unsafe { MCC_GetRIOInputValue(null_mut(), 0, 0, 0) }),
        ),
        (
            "SetRIOOutputValue port",
            Box::new(|| MCC_SetRIOOutputValue(1, 0, 4, 0)),
        ),
        (
            "SetRIOOutputValue set",
            Box::new(|| MCC_SetRIOOutputValue(1, 2, 0, 0)),
        ),
        (
            "SetRIOOutputValue card",
            Box::new(|| MCC_SetRIOOutputValue(1, 0, 0, 2)),
        ),
        (
            "GetRIOOutputValue NULL",
            // SAFETY: NULL, which the entry point refuses.
            Box::new(|| unsafe { MCC_GetRIOOutputValue(null_mut(), 0, 0, 0) }),
        ),
        (
            "GetRIOOutputValue port",
            // SAFETY: a pointer to the test's own WORD.
            Box::new(move || unsafe { MCC_GetRIOOutputValue(w(), 0, 4, 0) }),
        ),
        (
            "SetRIOTriggerType type",
            Box::new(|| MCC_SetRIOTriggerType(4, 0, 0, 0)),
        ),
        (
            "SetRIOTriggerType input",
            Box::new(|| MCC_SetRIOTriggerType(1, 0, 8, 0)),
        ),
        (
            "EnableRIOInputTrigger input",
            Box::new(|| MCC_EnableRIOInputTrigger(0, 8, 0)),
        ),
        (
            "DisableRIOInputTrigger set",
            Box::new(|| MCC_DisableRIOInputTrigger(2, 0, 0)),
        ),
        (
            "EnableRIOTransTrigger set",
            Box::new(|| MCC_EnableRIOTransTrigger(2, 0)),
        ),
        (
            "DisableRIOTransTrigger card",
            Box::new(|| MCC_DisableRIOTransTrigger(0, 2)),
        ),
        (
            "SetRIOTransError set",
            Box::new(|| MCC_SetRIOTransError(5, 2, 0)),
        ),
        (
            "SetRIOTransError card",
            Box::new(|| MCC_SetRIOTransError(5, 0, 2)),
        ),
        (
            "SetARIOUpdateRate 0",
            Box::new(|| MCC_SetARIOUpdateRate(0.0, 0, 0)),
        ),
        (
            "SetARIOUpdateRate negative",
            Box::new(|| MCC_SetARIOUpdateRate(-100.0, 0, 0)),
        ),
        (
            "SetARIOUpdateRate NaN",
            Box::new(|| MCC_SetARIOUpdateRate(f64::NAN, 0, 0)),
        ),
        (
            "SetARIOUpdateRate inf",
            Box::new(|| MCC_SetARIOUpdateRate(f64::INFINITY, 0, 0)),
        ),
        (
            "SetARIOUpdateRate set",
            Box::new(|| MCC_SetARIOUpdateRate(100.0, 2, 0)),
        ),
        (
            "SetARIOUpdateRate card",
            Box::new(|| MCC_SetARIOUpdateRate(100.0, 0, 2)),
        ),
        (
            "SetARIOClockDivider 0",
            Box::new(|| MCC_SetARIOClockDivider(0, 0, 0)),
        ),
        (
            "SetARIOClockDivider set",
            Box::new(|| MCC_SetARIOClockDivider(10, 2, 0)),
        ),
        (
            "SetARIOClockDivider card",
            Box::new(|| MCC_SetARIOClockDivider(10, 0, 12)),
        ),
        (
            "SetARIONode2NodeDelay card",
            Box::new(|| MCC_SetARIONode2NodeDelay(5, 2)),
        ),
        (
            "EnableARIOSlaveControl slave",
            Box::new(|| MCC_EnableARIOSlaveControl(0, 32, 0)),
        ),
        (
            "DisableARIOSlaveControl set",
            Box::new(|| MCC_DisableARIOSlaveControl(2, 0, 0)),
        ),
        (
            "GetARIOTransStatus NULL",
            // SAFETY: NULL, which the entry point refuses.
            Box::new(|| unsafe { MCC_GetARIOTransStatus(null_mut(), 0, 0) }),
        ),
        (
            "GetARIOMasterStatus set",
            // SAFETY: a pointer to the test's own WORD.
            Box::new(move || unsafe { MCC_GetARIOMasterStatus(w(), 2, 0) }),
        ),
        (
            "GetARIOSlaveStatus card",
            // SAFETY: a pointer to the test's own WORD.
            Box::new(move || unsafe { MCC_GetARIOSlaveStatus(w(), 0, 2) }),
        ),
        (
            "GetARIOSlaveFail NULL",
            // SAFETY: NULL, which the entry point refuses.
            Box::new(|| unsafe { MCC_GetARIOSlaveFail(null_mut(), 0, 0) }),
        ),
        (
            "GetARIOInputValue slave",
            // SAFETY: a pointer to the test's own WORD.
            Box::new(move || unsafe { MCC_GetARIOInputValue(w(), 0, 32, 0) }),
        ),
        (
            "GetARIOInputValue NULL",
            // SAFETY: NULL, which the entry point refuses.
            Box::new(|| unsafe { MCC_GetARIOInputValue(null_mut(), 0, 0, 0) }),
        ),
        (
            "SetARIOOutputValue slave",
            Box::new(|| MCC_SetARIOOutputValue(1, 0, 32, 0)),
        ),
        (
            "SetARIOOutputValue set",
            Box::new(|| MCC_SetARIOOutputValue(1, 2, 0, 0)),
        ),
        (
            "GetARIOOutputValue NULL",
            // SAFETY: NULL, which the entry point refuses.
            Box::new(|| unsafe { MCC_GetARIOOutputValue(null_mut(), 0, 0, 0) }),
        ),
        (
            "GetARIOOutputValue card",
            // SAFETY: a pointer to the test's own WORD.
            Box::new(move || unsafe { MCC_GetARIOOutputValue(w(), 0, 0, 12) }),
        ),
        (
            "SetLIORoutine card",
            Box::new(|| MCC_SetLIORoutine(Some(lio_order0), 2)),
        ),
        (
            "SetLIORoutineEx card",
            Box::new(|| MCC_SetLIORoutineEx(Some(lio_order0), 12)),
        ),
        (
            "SetENCRoutine card",
            Box::new(|| MCC_SetENCRoutine(Some(enc_order0), 2)),
        ),
        (
            "SetPCLRoutine card",
            Box::new(|| MCC_SetPCLRoutine(Some(pcl_order0), 2)),
        ),
        (
            "SetADCRoutine card",
            Box::new(|| MCC_SetADCRoutine(Some(adc_order0), 2)),
        ),
        (
            "SetTMRRoutine card",
            Box::new(|| MCC_SetTMRRoutine(Some(tmr_order0), 2)),
        ),
        (
            "SetRIORoutine card",
            Box::new(|| MCC_SetRIORoutine(Some(rio_order0), 2)),
        ),
        (
            "SetHSKRoutine card",
            Box::new(|| MCC_SetHSKRoutine(Some(hsk_order0), 2)),
        ),
    ]
}

#[test]
fn every_entry_point_checks_its_arguments_and_changes_nothing() {
    let _g = fresh();
    let mut w: WORD = 0x5555;
    let mut f: f32 = 7.0;
    let mut d: DWORD = 0x5555;
    // Before init: INITIAL_MOTION_ERR, also with otherwise good arguments.
    assert_eq!(MCC_SetTimer(100, 0), INITIAL_MOTION_ERR);
    assert_eq!(MCC_SetDACOutput(1.0, 0, 0), INITIAL_MOTION_ERR);
    assert_eq!(MCC_StartADCConv(0), INITIAL_MOTION_ERR);
    assert_eq!(MCC_SetTMRRoutine(None, 0), INITIAL_MOTION_ERR);
    assert_eq!(MCC_SetARIOOutputValue(1, 0, 0, 0), INITIAL_MOTION_ERR);
    // SAFETY: valid pointers.
    unsafe {
        assert_eq!(MCC_GetADCInput(&mut f, 0, 0), INITIAL_MOTION_ERR);
        assert_eq!(MCC_GetARIOInputValue(&mut w, 0, 0, 0), INITIAL_MOTION_ERR);
        assert_eq!(MCC_GetRIOSlaveFail(&mut d, 0, 0), INITIAL_MOTION_ERR);
    }
    for (name, call) in bad_calls() {
        assert_eq!(call(), INITIAL_MOTION_ERR, "{name} before init");
    }

    assert_eq!(init_ms(2, 1), NO_ERR);
    let before = (periph(0), periph(1));
    let isr_before: Vec<usize> = (0..7)
        .map(|k| {
            MCCLPCI_IMP::system::active()
                .unwrap()
                .interrupt_routine(0, ORDER[k])
        })
        .collect();
    for (name, call) in bad_calls() {
        assert_eq!(call(), PARAMETER_ERR, "{name}");
        assert_eq!((periph(0), periph(1)), before, "{name} changed something");
    }
    let isr_after: Vec<usize> = (0..7)
        .map(|k| {
            MCCLPCI_IMP::system::active()
                .unwrap()
                .interrupt_routine(0, ORDER[k])
        })
        .collect();
    assert_eq!(isr_before, isr_after);
    assert!(out_bufs_untouched(), "nothing written");
    // Card 1 exists: good calls work there.
    assert_eq!(MCC_SetDACOutput(-10.0, 7, 1), NO_ERR);
    assert_eq!(MCC_SetDACOutput(10.0, 6, 1), NO_ERR);
    assert_eq!(MCC_SetARIOOutputValue(0xABCD, 1, 31, 1), NO_ERR);
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetARIOOutputValue(&mut w, 1, 31, 1) }, NO_ERR);
    assert_eq!(w, 0xABCD);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
