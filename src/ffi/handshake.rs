//! The handshake interrupt between host and card (vendor header, "System Management";
//! the manuals do not describe it): which side raises what is in
//! [`crate::card::handshake`] and docs/undocumented-functions.md. The HSK routine is
//! registered with `MCC_SetHSKRoutine` (src/ffi/isr.rs).

use super::with_card;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::c_int;

/// The host interrupts the card: the card acknowledges it in its next tick with a
/// handshake interrupt to the host (the HSK routine runs after that tick, `HANDSHAKE`
/// counting the requests acknowledged). `INITIAL_MOTION_ERR` before init,
/// `PARAMETER_ERR` for a card not initialised.
#[no_mangle]
pub extern "system" fn MCC_HostInterrupt(wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        with_card(wCardIndex, |p| {
            p.host_interrupt();
            Ok(c::NO_ERR)
        })
    }
}

/// The card (the slave) interrupts the host: one `HANDSHAKE` cause, delivered to the
/// card's HSK routine after the next tick. `INITIAL_MOTION_ERR` before init,
/// `PARAMETER_ERR` for a card not initialised.
#[no_mangle]
pub extern "system" fn MCC_SlaveInterrupt(wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        with_card(wCardIndex, |p| {
            p.slave_interrupt();
            Ok(c::NO_ERR)
        })
    }
}
