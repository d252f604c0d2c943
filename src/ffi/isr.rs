//! Interrupt routine registration (`MCC_Set*Routine`; user manual §2.9.3, §2.10.3,
//! §2.12.4, §2.13.1; docs/vendor-interface.md). One routine per kind and card; NULL
//! unregisters. Routines are called after each tick on the engine thread with no lock
//! held, in the order documented in `crate::engine::isr`; they may call any `MCC_*`
//! function. The registrations live as long as the running system (`MCC_CloseSystem`
//! forgets them).

use super::card;
use crate::engine::isr::Kind;
use crate::error::McclResult;
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::{ADCISR, ENCISR, HSKISR, LIOISR, PCLISR, RIOISR, TMRISR, WORD};
use std::os::raw::c_int;

fn register(kind: Kind, f: usize, wCardIndex: WORD) -> McclResult<c_int> {
    let shared = system::active()?;
    let cd = shared.card(card(wCardIndex)?)?;
    shared.set_interrupt_routine(cd, kind, f);
    Ok(c::NO_ERR)
}

/// Registers the local I/O routine (limit switches, home sensors) of a card.
#[no_mangle]
pub extern "system" fn MCC_SetLIORoutine(pfnLIORoutine: LIOISR, wCardIndex: WORD) -> c_int {
    ffi_boundary! { register(
        Kind::Lio,
        pfnLIORoutine.map_or(0, |f| f as usize),
        wCardIndex,
    ) }
}

/// The name the IMP manuals use for [`MCC_SetLIORoutine`]; the same function.
#[no_mangle]
pub extern "system" fn MCC_SetLIORoutineEx(pfnLIORoutine: LIOISR, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
    Ok(MCC_SetLIORoutine(pfnLIORoutine, wCardIndex))
        }
}

/// Registers the encoder routine (index, compare) of a card.
#[no_mangle]
pub extern "system" fn MCC_SetENCRoutine(pfnEncoderRoutine: ENCISR, wCardIndex: WORD) -> c_int {
    ffi_boundary! { register(
        Kind::Enc,
        pfnEncoderRoutine.map_or(0, |f| f as usize),
        wCardIndex,
    ) }
}

/// Registers the position-control-loop routine of a card.
#[no_mangle]
pub extern "system" fn MCC_SetPCLRoutine(pfnPCLRoutine: PCLISR, wCardIndex: WORD) -> c_int {
    ffi_boundary! { register(
        Kind::Pcl,
        pfnPCLRoutine.map_or(0, |f| f as usize),
        wCardIndex,
    ) }
}

/// Registers the A/D converter routine (comparators, conversion done, tag) of a card.
#[no_mangle]
pub extern "system" fn MCC_SetADCRoutine(pfnADCRoutine: ADCISR, wCardIndex: WORD) -> c_int {
    ffi_boundary! { register(
        Kind::Adc,
        pfnADCRoutine.map_or(0, |f| f as usize),
        wCardIndex,
    ) }
}

/// Registers the timer routine of a card (the vendor names the parameter
/// `pfnLIORoutine`).
#[no_mangle]
pub extern "system" fn MCC_SetTMRRoutine(pfnLIORoutine: TMRISR, wCardIndex: WORD) -> c_int {
    ffi_boundary! { register(
        Kind::Tmr,
        pfnLIORoutine.map_or(0, |f| f as usize),
        wCardIndex,
    ) }
}

/// Registers the remote I/O routine (digital input triggers, transmission errors).
#[no_mangle]
pub extern "system" fn MCC_SetRIORoutine(pfnRIORoutine: RIOISR, wCardIndex: WORD) -> c_int {
    ffi_boundary! { register(
        Kind::Rio,
        pfnRIORoutine.map_or(0, |f| f as usize),
        wCardIndex,
    ) }
}

/// Registers the handshake routine of a card (the vendor names the parameter
/// `pfnLIORoutine`).
#[no_mangle]
pub extern "system" fn MCC_SetHSKRoutine(pfnLIORoutine: HSKISR, wCardIndex: WORD) -> c_int {
    ffi_boundary! { register(
        Kind::Hsk,
        pfnLIORoutine.map_or(0, |f| f as usize),
        wCardIndex,
    ) }
}
