//! The card's ADC through the C entry points: its comparator on the DAC wired to it, its
//! conversion and tag interrupts, single conversions. On the stepped clock: 1 ms ticks,
//! `MCC_TimeDelay(n)` runs exactly n ticks.

mod common;

use common::periph::with_periph;
use common::{fresh, init_ms};
use std::sync::atomic::{AtomicU32, Ordering::SeqCst};
use MCCLPCI_IMP::card::adc::AdcSource;
use MCCLPCI_IMP::ffi::adc::*;
use MCCLPCI_IMP::ffi::dac::*;
use MCCLPCI_IMP::ffi::isr::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::*;

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
