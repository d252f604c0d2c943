//! A/D converter (user manual §2.12; examples manual §37–38; vendor header "A/D
//! Converter Control"). Behaviour in `crate::card::adc`; inputs come from the DAC
//! channel of the same number unless set otherwise from Rust
//! (`Peripherals::set_adc_source`). The routine is registered with `MCC_SetADCRoutine`.

use super::{card_do, channel, with_card, write_out, Done};
use crate::card::adc::Adc;
use crate::error::McclResult;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::c_int;

fn ch_op<D: Done>(
    wChannel: WORD,
    wCardIndex: WORD,
    f: impl FnOnce(&mut Adc, usize) -> D,
) -> McclResult<c_int> {
    super::initialised()?;
    let ch = channel(wChannel)?.0;
    with_card(wCardIndex, |p| f(p.adc_mut(), ch).done())?;
    Ok(c::NO_ERR)
}

/// Reads one value through `p` after all checks (NULL is `PARAMETER_ERR`).
///
/// # Safety
/// `p` must be NULL or point to a writable `T`.
unsafe fn ch_read<T>(
    p: *mut T,
    wChannel: WORD,
    wCardIndex: WORD,
    f: impl FnOnce(&Adc, usize) -> T,
) -> McclResult<c_int> {
    super::initialised()?;
    let ch = channel(wChannel)?.0;
    // SAFETY: forwarded under this function's contract.
    unsafe { write_out(p, || with_card(wCardIndex, |per| Ok(f(per.adc(), ch)))) }
}

/// Sets a channel's conversion type: `ADC_TYPE_BIP_DIFF`/`_BIP_SING` (−5..5 V) or
/// `ADC_TYPE_UNI_DIFF`/`_UNI_SING` (0..10 V). Default `ADC_TYPE_BIP_DIFF`.
#[no_mangle]
pub extern "system" fn MCC_SetADCConvType(
    wConvType: WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! { ch_op(wChannel, wCardIndex, |a, ch| a.set_conv_type(ch, wConvType)) }
}

/// Reads a channel's conversion type.
///
/// # Safety
/// `pwConvType` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetADCConvType(
    pwConvType: *mut WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { ch_read(pwConvType, wChannel, wCardIndex, |a, ch| a.conv_type(ch)) }
    }
}

/// Sets a channel's compare value (finite, −10..10 V).
#[no_mangle]
pub extern "system" fn MCC_SetADCCompValue(fValue: f32, wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { ch_op(wChannel, wCardIndex, |a, ch| a.set_comp_value(ch, fValue)) }
}

/// Reads a channel's compare value.
///
/// # Safety
/// `pfValue` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `f32`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetADCCompValue(
    pfValue: *mut f32,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { ch_read(pfValue, wChannel, wCardIndex, |a, ch| a.comp_value(ch)) }
    }
}

/// Reads the last converted voltage of a channel (0 before its first conversion).
///
/// # Safety
/// `pfInput` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `f32`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetADCInput(
    pfInput: *mut f32,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { ch_read(pfInput, wChannel, wCardIndex, |a, ch| a.input(ch)) }
    }
}

/// Writes 1 while conversion runs (free mode started), 0 otherwise (a single conversion
/// is complete when `MCC_StartADCConv` returns).
///
/// # Safety
/// `pwSTatus` must be NULL (refused with `PARAMETER_ERR`) or point to a writable WORD.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetADCWorkStatus(pwSTatus: *mut WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        super::initialised()?;
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(pwSTatus, || {
                with_card(wCardIndex, |p| Ok(p.adc().work_status()))
            })
        }
    }
}

/// Sets the conversion mode: `ADC_MODE_FREE` (default) or `ADC_MODE_SINGLE` (which stops
/// free-running conversion).
#[no_mangle]
pub extern "system" fn MCC_SetADCConvMode(wConvMode: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.adc_mut().set_mode(wConvMode)) }
}

/// Chooses the channel `ADC_MODE_SINGLE` converts.
#[no_mangle]
pub extern "system" fn MCC_SetADCSingleChannel(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { ch_op(wChannel, wCardIndex, |a, ch| a.set_single_channel(ch)) }
}

/// Chooses the tagged channel (one at a time).
#[no_mangle]
pub extern "system" fn MCC_SetADCTagChannel(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { ch_op(wChannel, wCardIndex, |a, ch| a.set_tag_channel(ch)) }
}

/// Ignores the 0..3 lowest bits of the 12-bit codes in every comparator
/// (`ADC_MASK_NO`..`ADC_MASK_BIT3`).
#[no_mangle]
pub extern "system" fn MCC_SetADCCompMask(wMask: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.adc_mut().set_comp_mask(wMask)) }
}

/// Sets a channel's comparator type: `ADC_COMP_RISE` (0), `ADC_COMP_FALL` (1) or
/// `ADC_COMP_LEVEL` (2). Default `ADC_COMP_RISE`.
#[no_mangle]
pub extern "system" fn MCC_SetADCCompType(
    wCompType: WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! { ch_op(wChannel, wCardIndex, |a, ch| a.set_comp_type(ch, wCompType)) }
}

/// Starts conversion: free mode converts every enabled channel once per tick from the
/// next tick on; single mode converts the single channel now (its interrupts follow the
/// next tick).
#[no_mangle]
pub extern "system" fn MCC_StartADCConv(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.start_adc()) }
}

/// Stops free-running conversion (the last values stay readable).
#[no_mangle]
pub extern "system" fn MCC_StopADCConv(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.adc_mut().stop()) }
}

/// Every completed conversion calls the ADC routine with `CONV` set.
#[no_mangle]
pub extern "system" fn MCC_EnableADCConvTrigger(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.adc_mut().set_conv_trigger(true)) }
}

/// Completed conversions no longer call the ADC routine.
#[no_mangle]
pub extern "system" fn MCC_DisableADCConvTrigger(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.adc_mut().set_conv_trigger(false)) }
}

/// Each conversion of the tagged channel calls the ADC routine with `TAG` set.
#[no_mangle]
pub extern "system" fn MCC_EnableADCTagTrigger(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.adc_mut().set_tag_trigger(true)) }
}

/// Conversions of the tagged channel no longer call the ADC routine.
#[no_mangle]
pub extern "system" fn MCC_DisableADCTagTrigger(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.adc_mut().set_tag_trigger(false)) }
}

/// A comparator crossing of the channel calls the ADC routine with `COMPn` set.
#[no_mangle]
pub extern "system" fn MCC_EnableADCCompTrigger(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { ch_op(wChannel, wCardIndex, |a, ch| a.set_comp_trigger(ch, true)) }
}

/// The channel's comparator no longer calls the ADC routine.
#[no_mangle]
pub extern "system" fn MCC_DisableADCCompTrigger(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { ch_op(wChannel, wCardIndex, |a, ch| a.set_comp_trigger(ch, false)) }
}

/// Lets a channel convert in free mode.
#[no_mangle]
pub extern "system" fn MCC_EnableADCConvChannel(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { ch_op(wChannel, wCardIndex, |a, ch| a.set_channel(ch, true)) }
}

/// Stops a channel converting in free mode.
#[no_mangle]
pub extern "system" fn MCC_DisableADCConvChannel(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { ch_op(wChannel, wCardIndex, |a, ch| a.set_channel(ch, false)) }
}
