//! D/A converter (user manual §2.11; examples manual §35–36; vendor header "D/A Converter
//! Control"). A channel whose mechanism parameters in effect say `OCM_VOLTAGE` belongs
//! to its axis: every DAC call on it returns `VOLTAGE_COMMAND_CHANNEL_ERR`.

use super::{card_do, channel, with_card, Done};
use crate::error::McclResult;
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::{DWORD, WORD};
use std::os::raw::c_int;

/// Checks the card and channel and that the channel is free for the DAC calls.
fn dac_channel(wChannel: WORD, wCardIndex: WORD) -> McclResult<usize> {
    let ch = channel(wChannel)?.0;
    let cd = system::active()?.card(super::card(wCardIndex)?)?;
    system::with(|s| s.dac_channel_free(cd, ch))?;
    Ok(ch)
}

fn on_channel<D: Done>(
    wChannel: WORD,
    wCardIndex: WORD,
    f: impl FnOnce(&mut crate::card::dac::Dac, usize) -> D,
) -> McclResult<c_int> {
    super::initialised()?;
    let ch = dac_channel(wChannel, wCardIndex)?;
    with_card(wCardIndex, |p| f(p.dac_mut(), ch).done())?;
    Ok(c::NO_ERR)
}

/// Outputs `fVoltage` (−10..10 V) on a DAC channel.
#[no_mangle]
pub extern "system" fn MCC_SetDACOutput(fVoltage: f32, wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { on_channel(wChannel, wCardIndex, |d, ch| d.set_output(ch, fVoltage)) }
}

/// Presets the voltage (−10..10 V) a channel outputs when its trigger source fires.
#[no_mangle]
pub extern "system" fn MCC_SetDACTriggerOutput(
    fVoltage: f32,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        on_channel(wChannel, wCardIndex, |d, ch| {
            d.set_trigger_output(ch, fVoltage)
        })
    }
}

/// Sets a channel's trigger sources: a mask of `DAC_TRIG_ENC0..7` (encoder compare of
/// channel n of the same card); other bits are `PARAMETER_ERR`.
#[no_mangle]
pub extern "system" fn MCC_SetDACTriggerSource(
    dwSource: DWORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        on_channel(wChannel, wCardIndex, |d, ch| {
            d.set_trigger_source(ch, dwSource)
        })
    }
}

/// Turns a channel's trigger mode on.
#[no_mangle]
pub extern "system" fn MCC_EnableDACTriggerMode(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { on_channel(wChannel, wCardIndex, |d, ch| d.set_trigger_mode(ch, true)) }
}

/// Turns a channel's trigger mode off.
#[no_mangle]
pub extern "system" fn MCC_DisableDACTriggerMode(wChannel: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { on_channel(wChannel, wCardIndex, |d, ch| d.set_trigger_mode(ch, false)) }
}

/// (Re)starts D/A conversion: the set voltages appear on the outputs. Conversion runs
/// from `MCC_InitSystem` on.
#[no_mangle]
pub extern "system" fn MCC_StartDACConv(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.dac_mut().set_running(true)) }
}

/// Stops D/A conversion: every output is 0 V until `MCC_StartDACConv` (set voltages are
/// kept).
#[no_mangle]
pub extern "system" fn MCC_StopDACConv(wCardIndex: WORD) -> c_int {
    ffi_boundary! { card_do(wCardIndex, |p| p.dac_mut().set_running(false)) }
}
