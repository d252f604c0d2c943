//! The interrupt framework and the card peripherals through the C entry points, on the
//! stepped clock (1 ms ticks: `MCC_TimeDelay(n)` runs exactly n ticks).

mod common;

use common::{fresh, init_ms};
use parking_lot::Mutex;
use std::ptr::null_mut;
use std::sync::atomic::{AtomicBool, AtomicU32, AtomicU64, Ordering::SeqCst};
use MCCLPCI_IMP::card::adc::AdcSource;
use MCCLPCI_IMP::card::Peripherals;
use MCCLPCI_IMP::engine::isr::{Interrupt, ERR_WATCHDOG_RESET};
use MCCLPCI_IMP::ffi::adc::*;
use MCCLPCI_IMP::ffi::coordinate::*;
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

fn periph(card: usize) -> Peripherals {
    MCCLPCI_IMP::system::active()
        .unwrap()
        .periph(card)
        .unwrap()
        .lock()
        .clone()
}

fn with_periph<R>(card: usize, f: impl FnOnce(&mut Peripherals) -> R) -> R {
    f(&mut MCCLPCI_IMP::system::active()
        .unwrap()
        .periph(card)
        .unwrap()
        .lock())
}

fn status(g: u16) -> i32 {
    MCCLPCI_IMP::system::active()
        .unwrap()
        .snapshot(g)
        .unwrap()
        .status
}

fn x_pos(g: u16) -> f64 {
    let mut p = [0.0; 8];
    let [a, b, c, d, e, f, h, i] = &mut p;
    // SAFETY: eight valid pointers.
    assert_eq!(unsafe { MCC_GetCurPos(a, b, c, d, e, f, h, i, g) }, NO_ERR);
    p[0]
}

// ---- argument checks ----

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

use MCCLPCI_IMP::engine::isr::ORDER;

// ---- delivery order ----

static ORDER_LOG: Mutex<Vec<(u8, char, Vec<u8>)>> = Mutex::new(Vec::new());

macro_rules! order_cb {
    ($name:ident, $t:ty, $card:expr, $tag:expr) => {
        unsafe extern "system" fn $name(p: *mut $t) {
            // SAFETY: the library passes a valid struct for the call's duration.
            let s = unsafe { *p };
            let bytes = (0..std::mem::size_of::<$t>())
                // SAFETY: reading the struct's own bytes (all BYTE fields).
                .map(|i| unsafe { *(std::ptr::addr_of!(s) as *const u8).add(i) })
                .collect();
            ORDER_LOG.lock().push(($card, $tag, bytes));
        }
    };
}

order_cb!(lio_order0, LIOINT, 0, 'L');
order_cb!(enc_order0, ENCINT, 0, 'E');
order_cb!(pcl_order0, PCLINT, 0, 'P');
order_cb!(adc_order0, ADCINT, 0, 'A');
order_cb!(tmr_order0, TMRINT, 0, 'T');
order_cb!(rio_order0, RIOINT, 0, 'R');
order_cb!(hsk_order0, HSKINT, 0, 'H');
order_cb!(lio_order1, LIOINT, 1, 'L');
order_cb!(enc_order1, ENCINT, 1, 'E');
order_cb!(pcl_order1, PCLINT, 1, 'P');
order_cb!(adc_order1, ADCINT, 1, 'A');
order_cb!(tmr_order1, TMRINT, 1, 'T');
order_cb!(rio_order1, RIOINT, 1, 'R');
order_cb!(hsk_order1, HSKINT, 1, 'H');

#[test]
fn delivery_order_is_card_then_lio_enc_pcl_adc_tmr_rio_hsk() {
    let _g = fresh();
    assert_eq!(init_ms(2, 1), NO_ERR);
    ORDER_LOG.lock().clear();
    for (card, l, e, p, a, t, r, h) in [
        (
            0,
            lio_order0 as _,
            enc_order0 as _,
            pcl_order0 as _,
            adc_order0 as _,
            tmr_order0 as _,
            rio_order0 as _,
            hsk_order0 as _,
        ),
        (
            1,
            lio_order1 as _,
            enc_order1 as _,
            pcl_order1 as _,
            adc_order1 as _,
            tmr_order1 as _,
            rio_order1 as _,
            hsk_order1 as _,
        ),
    ] {
        let (l, e, p, a, t, r, h): (
            unsafe extern "system" fn(*mut LIOINT),
            unsafe extern "system" fn(*mut ENCINT),
            unsafe extern "system" fn(*mut PCLINT),
            unsafe extern "system" fn(*mut ADCINT),
            unsafe extern "system" fn(*mut TMRINT),
            unsafe extern "system" fn(*mut RIOINT),
            unsafe extern "system" fn(*mut HSKINT),
        ) = (l, e, p, a, t, r, h);
        assert_eq!(MCC_SetLIORoutineEx(Some(l), card), NO_ERR);
        assert_eq!(MCC_SetENCRoutine(Some(e), card), NO_ERR);
        assert_eq!(MCC_SetPCLRoutine(Some(p), card), NO_ERR);
        assert_eq!(MCC_SetADCRoutine(Some(a), card), NO_ERR);
        assert_eq!(MCC_SetTMRRoutine(Some(t), card), NO_ERR);
        assert_eq!(MCC_SetRIORoutine(Some(r), card), NO_ERR);
        assert_eq!(MCC_SetHSKRoutine(Some(h), card), NO_ERR);
    }
    let shared = MCCLPCI_IMP::system::active().unwrap();
    // Raised in reverse order, card 1 first, between ticks: delivered after the next one.
    for card in [1, 0] {
        shared.raise(card, Interrupt::Handshake);
        shared.raise(card, Interrupt::RioInput(3));
        shared.raise(card, Interrupt::Timer(2));
        shared.raise(card, Interrupt::AdcTag);
        shared.raise(card, Interrupt::AdcComp(1));
        shared.raise(card, Interrupt::PclOvn(0));
        shared.raise(card, Interrupt::EncComp(7));
        shared.raise(card, Interrupt::EncIndex(7));
        shared.raise(card, Interrupt::LioHome(7));
        shared.raise(card, Interrupt::LioOtn(2));
    }
    MCC_TimeDelay(1);
    let log = ORDER_LOG.lock().clone();
    let seq: Vec<(u8, char)> = log.iter().map(|(c, t, _)| (*c, *t)).collect();
    let mut want = Vec::new();
    for c in 0..2 {
        for t in ['L', 'E', 'P', 'A', 'T', 'R', 'H'] {
            want.push((c, t));
        }
    }
    assert_eq!(seq, want);
    // Several causes in one struct.
    let lio = &log[0].2;
    assert_eq!(lio.len(), 24);
    assert_eq!((lio[10], lio[23]), (1, 1));
    assert_eq!(lio.iter().map(|&b| u32::from(b)).sum::<u32>(), 2);
    assert_eq!(log[1].2[7], 1, "ENC INDEX7");
    assert_eq!(log[1].2[15], 1, "ENC COMP7");
    assert_eq!(log[2].2[8], 1, "PCL OVN0");
    assert_eq!(
        log[3].2,
        vec![0, 1, 0, 0, 0, 0, 0, 0, 0, 1],
        "ADC COMP1 + TAG"
    );
    assert_eq!(log[4].2, vec![2], "TIMER counts");
    assert_eq!(log[5].2[3], 1, "RDI3");
    assert_eq!(log[6].2, vec![1]);

    // Nothing raised: nothing called. NULL unregisters.
    MCC_TimeDelay(3);
    assert_eq!(ORDER_LOG.lock().len(), 14);
    assert_eq!(MCC_SetHSKRoutine(None, 0), NO_ERR);
    assert_eq!(MCC_SetLIORoutine(None, 1), NO_ERR);
    shared.raise(0, Interrupt::Handshake);
    shared.raise(0, Interrupt::LioOtp(0));
    shared.raise(1, Interrupt::LioOtp(0));
    MCC_TimeDelay(1);
    let seq: Vec<(u8, char)> = ORDER_LOG.lock()[14..]
        .iter()
        .map(|(c, t, _)| (*c, *t))
        .collect();
    assert_eq!(seq, vec![(0, 'L')]);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

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
        periph(0).watchdog.enabled(),
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
    assert_eq!(p.dac.output(4), 0.0);
    assert_eq!(p.rio.ario[0].output(2), Ok(0));
    assert_eq!(p.rio.rio[1].output(3), Ok(0));
    assert!(!p.watchdog.enabled());
    assert_eq!(p.watchdog.resets, 1);
    let x = x_pos(0);
    MCC_TimeDelay(5);
    assert_eq!(x_pos(0), x, "stopped where it was");
    assert_eq!(MCC_ClearError(0), NO_ERR);
    assert_eq!(MCC_GetErrorCode(0), 0);
    assert_eq!(MCC_DisableWatchDogTimer(0), NO_ERR);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

// ---- DAC ----

#[test]
fn dac_output_stop_trigger_and_voltage_channels() {
    let _g = fresh();
    let mut m = SYS_MAC_PARAM::default();
    // SAFETY: valid pointers.
    unsafe {
        assert_eq!(MCC_GetMacParam(&mut m, 2, 0), NO_ERR);
        m.wCommandMode = OCM_VOLTAGE;
        assert_eq!(MCC_SetMacParam(&mut m, 2, 0), NO_ERR);
    }
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetDACOutput(1.0, 2, 0), VOLTAGE_COMMAND_CHANNEL_ERR);
    assert_eq!(
        MCC_SetDACTriggerOutput(1.0, 2, 0),
        VOLTAGE_COMMAND_CHANNEL_ERR
    );
    assert_eq!(
        MCC_SetDACTriggerSource(1, 2, 0),
        VOLTAGE_COMMAND_CHANNEL_ERR
    );
    assert_eq!(MCC_EnableDACTriggerMode(2, 0), VOLTAGE_COMMAND_CHANNEL_ERR);
    assert_eq!(MCC_DisableDACTriggerMode(2, 0), VOLTAGE_COMMAND_CHANNEL_ERR);
    assert_eq!(periph(0).dac.value(2), 0.0);

    assert_eq!(MCC_SetDACOutput(-2.5, 1, 0), NO_ERR);
    assert_eq!(periph(0).dac.output(1), -2.5);
    assert_eq!(MCC_StopDACConv(0), NO_ERR);
    assert_eq!(periph(0).dac.output(1), 0.0);
    assert_eq!(MCC_StartDACConv(0), NO_ERR);
    assert_eq!(periph(0).dac.output(1), -2.5);

    assert_eq!(MCC_SetDACTriggerOutput(2.0, 0, 0), NO_ERR);
    assert_eq!(
        MCC_SetDACTriggerSource(DAC_TRIG_ENC0 | DAC_TRIG_ENC5, 0, 0),
        NO_ERR
    );
    assert_eq!(MCC_EnableDACTriggerMode(0, 0), NO_ERR);
    with_periph(0, |p| p.dac_trigger(1));
    assert_eq!(periph(0).dac.output(0), 0.0, "not a source");
    with_periph(0, |p| p.dac_trigger(5));
    assert_eq!(periph(0).dac.output(0), 2.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

// ---- ADC ----

static ADC_COMP0: AtomicU32 = AtomicU32::new(0);
static ADC_CONV: AtomicU32 = AtomicU32::new(0);
static ADC_TAG: AtomicU32 = AtomicU32::new(0);

unsafe extern "system" fn adc_count(p: *mut ADCINT) {
    // SAFETY: valid for the call.
    let s = unsafe { *p };
    if s.COMP0 != 0 {
        ADC_COMP0.fetch_add(1, SeqCst);
    }
    if s.CONV != 0 {
        ADC_CONV.fetch_add(1, SeqCst);
    }
    if s.TAG != 0 {
        ADC_TAG.fetch_add(1, SeqCst);
    }
}

fn adc_reset_counts() {
    for a in [&ADC_COMP0, &ADC_CONV, &ADC_TAG] {
        a.store(0, SeqCst);
    }
}

/// Steps DAC 0 through `volts`, one tick each; returns the COMP0 callbacks.
fn step_dac(volts: &[f32]) -> u32 {
    let n0 = ADC_COMP0.load(SeqCst);
    for &v in volts {
        assert_eq!(MCC_SetDACOutput(v, 0, 0), NO_ERR);
        MCC_TimeDelay(1);
    }
    ADC_COMP0.load(SeqCst) - n0
}

#[test]
fn adc_comparator_counts_crossings_of_the_dac_wired_to_it() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    adc_reset_counts();
    assert_eq!(MCC_SetADCRoutine(Some(adc_count), 0), NO_ERR);
    assert_eq!(MCC_SetADCConvType(ADC_TYPE_BIP_DIFF, 0, 0), NO_ERR);
    assert_eq!(MCC_SetADCCompValue(2.0, 0, 0), NO_ERR);
    assert_eq!(MCC_SetADCCompType(ADC_COMP_LEVEL, 0, 0), NO_ERR);
    assert_eq!(MCC_EnableADCCompTrigger(0, 0), NO_ERR);
    assert_eq!(MCC_EnableADCConvChannel(0, 0), NO_ERR);
    assert_eq!(MCC_StartADCConv(0), NO_ERR);
    let mut w: WORD = 9;
    let mut f: f32 = 0.0;
    // SAFETY: valid pointers.
    unsafe {
        assert_eq!(MCC_GetADCWorkStatus(&mut w, 0), NO_ERR);
        assert_eq!(w, 1);
        assert_eq!(MCC_GetADCCompValue(&mut f, 0, 0), NO_ERR);
        assert_eq!(f, 2.0);
    }
    // 0 -> 1 -> 3 (up) -> 1 (down) -> 3 (up) -> 3 -> 0 (down)
    assert_eq!(step_dac(&[0.0, 1.0, 3.0, 1.0, 3.0, 3.0, 0.0]), 4);
    // SAFETY: valid pointer.
    unsafe { assert_eq!(MCC_GetADCInput(&mut f, 0, 0), NO_ERR) };
    assert_eq!(f, 0.0);
    assert_eq!(MCC_SetADCCompType(ADC_COMP_RISE, 0, 0), NO_ERR);
    assert_eq!(step_dac(&[0.0, 3.0, 0.0, 4.0, 1.0]), 2);
    assert_eq!(MCC_SetADCCompType(ADC_COMP_FALL, 0, 0), NO_ERR);
    assert_eq!(step_dac(&[0.0, 3.0, 0.0, 4.0, 1.0]), 2);
    assert_eq!(MCC_DisableADCCompTrigger(0, 0), NO_ERR);
    assert_eq!(step_dac(&[3.0, 0.0]), 0);
    assert_eq!((ADC_CONV.load(SeqCst), ADC_TAG.load(SeqCst)), (0, 0));

    // Conversion-done and tag triggers, and a constant input source from Rust.
    assert_eq!(MCC_EnableADCConvTrigger(0), NO_ERR);
    assert_eq!(MCC_SetADCTagChannel(3, 0), NO_ERR);
    assert_eq!(MCC_EnableADCTagTrigger(0), NO_ERR);
    MCC_TimeDelay(3);
    assert_eq!(
        (ADC_CONV.load(SeqCst), ADC_TAG.load(SeqCst)),
        (3, 0),
        "channel 3 off"
    );
    with_periph(0, |p| p.set_adc_source(3, AdcSource::Constant(7.5)));
    assert_eq!(MCC_EnableADCConvChannel(3, 0), NO_ERR);
    assert_eq!(MCC_SetADCConvType(ADC_TYPE_UNI_SING, 3, 0), NO_ERR);
    MCC_TimeDelay(2);
    assert_eq!((ADC_CONV.load(SeqCst), ADC_TAG.load(SeqCst)), (5, 2));
    // SAFETY: valid pointers.
    unsafe {
        assert_eq!(MCC_GetADCInput(&mut f, 3, 0), NO_ERR);
        assert_eq!(f, 7.5);
        assert_eq!(MCC_GetADCConvType(&mut w, 3, 0), NO_ERR);
        assert_eq!(w, ADC_TYPE_UNI_SING);
    }
    assert_eq!(MCC_StopADCConv(0), NO_ERR);
    MCC_TimeDelay(2);
    assert_eq!(ADC_CONV.load(SeqCst), 5, "stopped");

    // Single mode: one conversion at MCC_StartADCConv, its interrupt after the next tick.
    assert_eq!(MCC_SetADCConvMode(ADC_MODE_SINGLE, 0), NO_ERR);
    assert_eq!(MCC_SetADCSingleChannel(1, 0), NO_ERR);
    assert_eq!(MCC_SetDACOutput(-4.25, 1, 0), NO_ERR);
    assert_eq!(MCC_StartADCConv(0), NO_ERR);
    // SAFETY: valid pointers.
    unsafe {
        assert_eq!(MCC_GetADCWorkStatus(&mut w, 0), NO_ERR);
        assert_eq!(w, 0, "complete");
        assert_eq!(MCC_GetADCInput(&mut f, 1, 0), NO_ERR);
        assert_eq!(f, -4.25);
    }
    assert_eq!(MCC_SetDACOutput(1.0, 1, 0), NO_ERR);
    MCC_TimeDelay(3);
    assert_eq!(ADC_CONV.load(SeqCst), 6, "one conversion");
    // SAFETY: valid pointer.
    unsafe { assert_eq!(MCC_GetADCInput(&mut f, 1, 0), NO_ERR) };
    assert_eq!(f, -4.25, "no new conversion without MCC_StartADCConv");
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

// ---- remote I/O ----

static RIO_BYTES: Mutex<Vec<[u8; 9]>> = Mutex::new(Vec::new());

unsafe extern "system" fn rio_log(p: *mut RIOINT) {
    // SAFETY: the library passes 9 bytes (RIOINT and the driver's FAIL byte).
    let b: [u8; 9] = unsafe { *(p as *const [u8; 9]) };
    RIO_BYTES.lock().push(b);
}

#[test]
fn remote_io_loopback_status_and_triggers() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    RIO_BYTES.lock().clear();
    let (mut w, mut d): (WORD, DWORD) = (0, 0);
    // ARIO: examples manual §33-34.
    assert_eq!(MCC_EnableARIOSlaveControl(RIO_SET0, RIO_SLAVE0, 0), NO_ERR);
    assert_eq!(
        MCC_SetARIOOutputValue(0x1234, RIO_SET0, RIO_SLAVE0, 0),
        NO_ERR
    );
    assert_eq!(
        MCC_SetARIOOutputValue(0x5678, RIO_SET0, RIO_SLAVE1, 0),
        NO_ERR
    );
    MCC_TimeDelay(1);
    // SAFETY: valid pointers throughout.
    unsafe {
        assert_eq!(
            MCC_GetARIOInputValue(&mut w, RIO_SET0, RIO_SLAVE0, 0),
            NO_ERR
        );
        assert_eq!(w, 0x1234, "loops back");
        assert_eq!(
            MCC_GetARIOInputValue(&mut w, RIO_SET0, RIO_SLAVE1, 0),
            NO_ERR
        );
        assert_eq!(w, 0, "slave 1 not transmitting");
        assert_eq!(MCC_GetARIOTransStatus(&mut w, RIO_SET0, 0), NO_ERR);
        assert_eq!(w, 1);
        with_periph(0, |p| p.rio.set_slave_failed(true, 0, 0, true));
        assert_eq!(MCC_GetARIOTransStatus(&mut w, RIO_SET0, 0), NO_ERR);
        assert_eq!(w, 1, "noticed at the next transfer");
        MCC_TimeDelay(1);
        assert_eq!(MCC_GetARIOTransStatus(&mut w, RIO_SET0, 0), NO_ERR);
        assert_eq!(w, 0, "the first failed transfer (tolerance 0)");
        assert_eq!(MCC_GetARIOSlaveStatus(&mut w, RIO_SET0, 0), NO_ERR);
        assert_eq!(w, 0);
        assert_eq!(MCC_GetARIOMasterStatus(&mut w, RIO_SET0, 0), NO_ERR);
        assert_eq!(w, 1);
        assert_eq!(MCC_GetARIOSlaveFail(&mut d, RIO_SET0, 0), NO_ERR);
        assert_eq!(d, 1);
        assert_eq!(
            MCC_SetARIOOutputValue(0x9999, RIO_SET0, RIO_SLAVE0, 0),
            NO_ERR
        );
        MCC_TimeDelay(1);
        assert_eq!(
            MCC_GetARIOInputValue(&mut w, RIO_SET0, RIO_SLAVE0, 0),
            NO_ERR
        );
        assert_eq!(w, 0x1234, "a failed slave does not transfer");
        assert_eq!(MCC_DisableARIOSlaveControl(RIO_SET0, RIO_SLAVE0, 0), NO_ERR);
        assert_eq!(MCC_GetARIOSlaveFail(&mut d, RIO_SET0, 0), NO_ERR);
        assert_eq!(d, 0, "only transmitting slaves count");
        assert_eq!(
            MCC_GetARIOOutputValue(&mut w, RIO_SET0, RIO_SLAVE0, 0),
            NO_ERR
        );
        assert_eq!(w, 0x9999);

        // RIO: set and slave control, DI triggers through the RIO routine.
        assert_eq!(MCC_SetRIORoutine(Some(rio_log), 0), NO_ERR);
        assert_eq!(MCC_EnableRIOSlaveControl(RIO_SET1, 0, 0), NO_ERR);
        assert_eq!(
            MCC_SetRIOTriggerType(RIO_INT_RISE, RIO_SET1, RIO_DI1, 0),
            NO_ERR
        );
        assert_eq!(
            MCC_SetRIOTriggerType(RIO_INT_LEVEL, RIO_SET1, RIO_DI2, 0),
            NO_ERR
        );
        assert_eq!(MCC_EnableRIOInputTrigger(RIO_SET1, RIO_DI1, 0), NO_ERR);
        assert_eq!(MCC_EnableRIOInputTrigger(RIO_SET1, RIO_DI2, 0), NO_ERR);
        assert_eq!(MCC_SetRIOOutputValue(0b110, RIO_SET1, RIO_PORT0, 0), NO_ERR);
        MCC_TimeDelay(2);
        assert_eq!(MCC_GetRIOInputValue(&mut w, RIO_SET1, RIO_PORT0, 0), NO_ERR);
        assert_eq!(w, 0, "set control off");
        assert_eq!(MCC_EnableRIOSetControl(RIO_SET1, 0), NO_ERR);
        MCC_TimeDelay(1);
        assert_eq!(MCC_GetRIOInputValue(&mut w, RIO_SET1, RIO_PORT0, 0), NO_ERR);
        assert_eq!(w, 0b110);
        assert!(
            RIO_BYTES.lock().is_empty(),
            "first transfer is the reference"
        );
        assert_eq!(MCC_SetRIOOutputValue(0b000, RIO_SET1, RIO_PORT0, 0), NO_ERR);
        MCC_TimeDelay(1);
        assert_eq!(MCC_SetRIOOutputValue(0b110, RIO_SET1, RIO_PORT0, 0), NO_ERR);
        MCC_TimeDelay(1);
        let log = RIO_BYTES.lock().clone();
        assert_eq!(log.len(), 2);
        assert_eq!(
            &log[0][..3],
            &[0, 0, 1],
            "DI1 fell (RISE ignores), DI2 changed"
        );
        assert_eq!(&log[1][..3], &[0, 1, 1], "DI1 rose, DI2 changed");
        // Transmission failure: FAIL byte once.
        assert_eq!(MCC_EnableRIOTransTrigger(RIO_SET1, 0), NO_ERR);
        with_periph(0, |p| p.rio.set_master_failed(false, 1, true));
        MCC_TimeDelay(3);
        let log = RIO_BYTES.lock().clone();
        assert_eq!(log.len(), 3);
        assert_eq!(log[2], [0, 0, 0, 0, 0, 0, 0, 0, 1]);
        assert_eq!(MCC_GetRIOMasterStatus(&mut w, RIO_SET1, 0), NO_ERR);
        assert_eq!(w, 0);
        assert_eq!(MCC_GetRIOTransStatus(&mut w, RIO_SET1, 0), NO_ERR);
        assert_eq!(w, 0);
        assert_eq!(MCC_GetRIOSlaveStatus(&mut w, RIO_SET1, 0), NO_ERR);
        assert_eq!(w, 1);
        assert_eq!(MCC_GetRIOSlaveFail(&mut d, RIO_SET1, 0), NO_ERR);
        assert_eq!(d, 0);
        assert_eq!(
            MCC_GetRIOOutputValue(&mut w, RIO_SET1, RIO_PORT0, 0),
            NO_ERR
        );
        assert_eq!(w, 0b110);
    }
    assert_eq!(MCC_DisableRIOTransTrigger(RIO_SET1, 0), NO_ERR);
    assert_eq!(MCC_DisableRIOInputTrigger(RIO_SET1, RIO_DI1, 0), NO_ERR);
    assert_eq!(MCC_DisableRIOSlaveControl(RIO_SET1, 0, 0), NO_ERR);
    assert_eq!(MCC_DisableRIOSetControl(RIO_SET1, 0), NO_ERR);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn rio_trans_error_reports_after_the_tolerated_failed_transfers() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    RIO_BYTES.lock().clear();
    let (mut w, mut d): (WORD, DWORD) = (0, 0);
    assert_eq!(MCC_SetRIORoutine(Some(rio_log), 0), NO_ERR);
    assert_eq!(MCC_EnableRIOSetControl(RIO_SET1, 0), NO_ERR);
    assert_eq!(MCC_EnableRIOSlaveControl(RIO_SET1, 2, 0), NO_ERR);
    assert_eq!(MCC_EnableRIOTransTrigger(RIO_SET1, 0), NO_ERR);
    // The vendor test's value: 5 failed transfers tolerated, the 6th reported.
    assert_eq!(MCC_SetRIOTransError(5, RIO_SET1, 0), NO_ERR);
    assert_eq!(periph(0).rio.rio[1].tolerance(), 5);
    assert_eq!(periph(0).rio.rio[0].tolerance(), 0, "per set");
    MCC_TimeDelay(1);
    with_periph(0, |p| p.rio.set_slave_failed(false, 1, 2, true));
    // SAFETY: valid pointers throughout.
    unsafe {
        // One transfer per 1 ms tick: ticks 1..5 fail and are tolerated.
        for n in 1..=5u32 {
            MCC_TimeDelay(1);
            assert_eq!(MCC_GetRIOTransStatus(&mut w, RIO_SET1, 0), NO_ERR);
            assert_eq!(w, 1, "failed transfer {n} tolerated");
            assert_eq!(MCC_GetRIOSlaveFail(&mut d, RIO_SET1, 0), NO_ERR);
            assert_eq!(d, 0);
            assert_eq!(periph(0).rio.rio[1].failed_transfers(2), n);
        }
        assert!(RIO_BYTES.lock().is_empty(), "no FAIL yet");
        MCC_TimeDelay(1);
        assert_eq!(MCC_GetRIOTransStatus(&mut w, RIO_SET1, 0), NO_ERR);
        assert_eq!(w, 0, "6th failed transfer");
        assert_eq!(MCC_GetRIOSlaveStatus(&mut w, RIO_SET1, 0), NO_ERR);
        assert_eq!(w, 0);
        assert_eq!(MCC_GetRIOMasterStatus(&mut w, RIO_SET1, 0), NO_ERR);
        assert_eq!(w, 1);
        assert_eq!(MCC_GetRIOSlaveFail(&mut d, RIO_SET1, 0), NO_ERR);
        assert_eq!(d, 1 << 2);
        assert_eq!(*RIO_BYTES.lock(), [[0, 0, 0, 0, 0, 0, 0, 0, 1]]);
        // Set 0 keeps its own tolerance (0): a failure there is reported at once.
        assert_eq!(MCC_EnableRIOSetControl(RIO_SET0, 0), NO_ERR);
        assert_eq!(MCC_EnableRIOSlaveControl(RIO_SET0, 0, 0), NO_ERR);
        with_periph(0, |p| p.rio.set_slave_failed(false, 0, 0, true));
        MCC_TimeDelay(1);
        assert_eq!(MCC_GetRIOSlaveFail(&mut d, RIO_SET0, 0), NO_ERR);
        assert_eq!(d, 1);
        // Recovery: the next transfer clears the report.
        with_periph(0, |p| p.rio.set_slave_failed(false, 1, 2, false));
        MCC_TimeDelay(1);
        assert_eq!(MCC_GetRIOTransStatus(&mut w, RIO_SET1, 0), NO_ERR);
        assert_eq!(w, 1);
    }
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

/// The inputs last latched from ARIO slave `slave` of `set` (its outputs looped back).
fn ario_in(set: WORD, slave: WORD) -> WORD {
    let mut w: WORD = 0;
    assert_eq!(
        // SAFETY: valid pointer.
        unsafe { MCC_GetARIOInputValue(&mut w, set, slave, 0) },
        NO_ERR
    );
    w
}

#[test]
fn ario_transfers_follow_the_update_rate_divider_and_node_delay() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR); // 1 ms ticks on the stepped clock
    assert_eq!(MCC_EnableARIOSlaveControl(RIO_SET1, RIO_SLAVE4, 0), NO_ERR);
    assert_eq!(MCC_EnableARIOSlaveControl(RIO_SET0, RIO_SLAVE0, 0), NO_ERR);
    // Default timing: 32 bits x 10 clocks x 10 ns = 3.2 us per cycle: every tick.
    assert_eq!(MCC_SetARIOOutputValue(1, RIO_SET1, RIO_SLAVE4, 0), NO_ERR);
    MCC_TimeDelay(1);
    assert_eq!(ario_in(RIO_SET1, RIO_SLAVE4), 1);
    // 50 Hz: one cycle every 20 ms, counted from the call.
    assert_eq!(MCC_SetARIOUpdateRate(50.0, RIO_SET1, 0), NO_ERR);
    assert_eq!(MCC_SetARIOOutputValue(2, RIO_SET1, RIO_SLAVE4, 0), NO_ERR);
    MCC_TimeDelay(19);
    assert_eq!(ario_in(RIO_SET1, RIO_SLAVE4), 1, "19 ms: no cycle yet");
    MCC_TimeDelay(1);
    assert_eq!(ario_in(RIO_SET1, RIO_SLAVE4), 2, "20 ms");
    // Divider 65535 and a node-to-node delay of 902880 clocks: one slave's cycle is
    // (32 x 65535 + 902880) x 10 ns = 3000000 x 10 ns = 30 ms, longer than 20 ms.
    assert_eq!(MCC_SetARIOClockDivider(65535, RIO_SET1, 0), NO_ERR);
    assert_eq!(MCC_SetARIONode2NodeDelay(902_880, 0), NO_ERR);
    // The delay is the card's: set 0 (divider 10) now takes (320 + 902880) x 10 ns =
    // 9.032 ms per cycle, so it transfers at 10 ms.
    assert_eq!(MCC_SetARIOOutputValue(3, RIO_SET1, RIO_SLAVE4, 0), NO_ERR);
    assert_eq!(MCC_SetARIOOutputValue(7, RIO_SET0, RIO_SLAVE0, 0), NO_ERR);
    MCC_TimeDelay(9);
    assert_eq!(ario_in(RIO_SET0, RIO_SLAVE0), 0, "9 ms < 9.032 ms");
    MCC_TimeDelay(1);
    assert_eq!(ario_in(RIO_SET0, RIO_SLAVE0), 7, "10 ms");
    MCC_TimeDelay(19);
    assert_eq!(ario_in(RIO_SET1, RIO_SLAVE4), 2, "29 ms");
    MCC_TimeDelay(1);
    assert_eq!(ario_in(RIO_SET1, RIO_SLAVE4), 3, "30 ms");
    // A failed call changes nothing: the next cycle is still at 60 ms.
    assert_eq!(MCC_SetARIOUpdateRate(f64::NAN, RIO_SET1, 0), PARAMETER_ERR);
    assert_eq!(MCC_SetARIOClockDivider(0, RIO_SET1, 0), PARAMETER_ERR);
    assert_eq!(MCC_SetARIOOutputValue(4, RIO_SET1, RIO_SLAVE4, 0), NO_ERR);
    MCC_TimeDelay(29);
    assert_eq!(ario_in(RIO_SET1, RIO_SLAVE4), 3, "59 ms");
    MCC_TimeDelay(1);
    assert_eq!(ario_in(RIO_SET1, RIO_SLAVE4), 4, "60 ms");
    // A second transmitting slave doubles the bus time: 60 ms per cycle.
    assert_eq!(MCC_EnableARIOSlaveControl(RIO_SET1, RIO_SLAVE5, 0), NO_ERR);
    assert_eq!(periph(0).rio.ario_timing.cycle_ns(1, 0b11_0000), 60_000_000);
    // RIO sets are not ARIO: they still transfer every tick.
    assert_eq!(MCC_EnableRIOSetControl(RIO_SET1, 0), NO_ERR);
    assert_eq!(MCC_EnableRIOSlaveControl(RIO_SET1, 1, 0), NO_ERR);
    assert_eq!(MCC_SetRIOOutputValue(0x55, RIO_SET1, RIO_PORT1, 0), NO_ERR);
    MCC_TimeDelay(1);
    let mut w: WORD = 0;
    assert_eq!(
        // SAFETY: valid pointer.
        unsafe { MCC_GetRIOInputValue(&mut w, RIO_SET1, RIO_PORT1, 0) },
        NO_ERR
    );
    assert_eq!(w, 0x55);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

// ---- callbacks calling into the library ----

static CB_TICKS: AtomicU32 = AtomicU32::new(0);
static CB_X: AtomicU64 = AtomicU64::new(0);
static CB_X_AT_ABORT: AtomicU64 = AtomicU64::new(0);
static CB_ABORT_RET: AtomicU32 = AtomicU32::new(99);
static CB_CLOSE_RET: AtomicU32 = AtomicU32::new(99);
static CB_AFTER_CLOSE: AtomicBool = AtomicBool::new(false);

unsafe extern "system" fn tmr_calls_in(_: *mut TMRINT) {
    if CB_AFTER_CLOSE.load(SeqCst) {
        // A tick after MCC_CloseSystem must not deliver.
        CB_TICKS.store(1_000_000, SeqCst);
        return;
    }
    let n = CB_TICKS.fetch_add(1, SeqCst) + 1;
    CB_X.store(x_pos(0).to_bits(), SeqCst);
    if n == 50 {
        CB_X_AT_ABORT.store(x_pos(0).to_bits(), SeqCst);
        CB_ABORT_RET.store(MCC_AbortMotionEx(0.0, 0) as u32, SeqCst);
    }
    if n == 60 {
        CB_CLOSE_RET.store(MCC_CloseSystem() as u32, SeqCst);
        CB_AFTER_CLOSE.store(true, SeqCst);
    }
}

static HSK_AFTER_CLOSE: AtomicU32 = AtomicU32::new(0);

unsafe extern "system" fn hsk_after_close(_: *mut HSKINT) {
    HSK_AFTER_CLOSE.fetch_add(1, SeqCst);
}

#[test]
fn callbacks_read_positions_abort_and_close_the_system() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    CB_TICKS.store(0, SeqCst);
    CB_AFTER_CLOSE.store(false, SeqCst);
    HSK_AFTER_CLOSE.store(0, SeqCst);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    assert!(MCC_Line(100.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL) >= 0);
    assert_eq!(MCC_SetTMRRoutine(Some(tmr_calls_in), 0), NO_ERR);
    assert_eq!(MCC_SetHSKRoutine(Some(hsk_after_close), 0), NO_ERR);
    assert_eq!(MCC_SetTimer(100_000, 0), NO_ERR);
    assert_eq!(MCC_EnableTimerTrigger(0), NO_ERR);
    assert_eq!(MCC_EnableTimer(0), NO_ERR);
    MCC_TimeDelay(55);
    assert_eq!(CB_TICKS.load(SeqCst), 55);
    assert_eq!(CB_ABORT_RET.load(SeqCst), NO_ERR as u32);
    assert_eq!(status(0), GMS_STOP, "aborted from the callback");
    let x_abort = f64::from_bits(CB_X_AT_ABORT.load(SeqCst));
    assert!(x_abort > 0.0);
    assert_eq!(
        f64::from_bits(CB_X.load(SeqCst)),
        x_abort,
        "no motion after abort"
    );
    // The handshake raised now is delivered in the same tick as the closing timer call,
    // after it (TMR before HSK): it must not run once the system is closed.
    let shared = MCCLPCI_IMP::system::active().unwrap();
    MCC_TimeDelay(4);
    shared.raise(0, Interrupt::Handshake);
    MCC_TimeDelay(100); // returns when the clock stops
                        // The clock stops inside MCC_CloseSystem: wait for the callback to finish.
    let t0 = std::time::Instant::now();
    while !CB_AFTER_CLOSE.load(SeqCst) {
        assert!(t0.elapsed().as_secs() < 10, "callback did not finish");
        std::thread::yield_now();
    }
    std::thread::sleep(std::time::Duration::from_millis(50));
    assert_eq!(CB_CLOSE_RET.load(SeqCst), NO_ERR as u32);
    assert_eq!(CB_TICKS.load(SeqCst), 60);
    assert_eq!(HSK_AFTER_CLOSE.load(SeqCst), 0);
    assert!(MCCLPCI_IMP::system::active().is_err(), "closed");
    assert_eq!(MCC_GetMotionStatus(0), INITIAL_MOTION_ERR);
    drop(shared);
    // A new system starts cleanly, with no routine registered.
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(
        MCCLPCI_IMP::system::active()
            .unwrap()
            .interrupt_routine(0, MCCLPCI_IMP::engine::isr::Kind::Tmr),
        0
    );
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
