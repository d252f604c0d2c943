//! The interrupt framework through the C entry points: the order in which the routines of
//! the cards are called, and routines that call into the library (read positions, abort
//! the motion, close the system). On the stepped clock: 1 ms ticks, `MCC_TimeDelay(n)`
//! runs exactly n ticks.

mod common;

use common::order_log::*;
use common::periph::{status, x_pos};
use common::{fresh, init_ms};
use std::sync::atomic::{AtomicBool, AtomicU32, AtomicU64, Ordering::SeqCst};
use MCCLPCI_IMP::engine::isr::Interrupt;
use MCCLPCI_IMP::ffi::isr::*;
use MCCLPCI_IMP::ffi::motion::*;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::timer::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::*;

// ---- delivery order ----

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
