//! Local I/O outputs (user manual §2.9.2; INTERFACE.md "Local I/O Control"): the servo-on
//! signal of each channel and the card's position-ready signal. The virtual card keeps
//! the state of each output; the simulated machine reads it.

use super::{card, channel, guard};
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::c_int;
use std::sync::atomic::Ordering;

fn servo(wChannel: WORD, wCardIndex: WORD, on: bool) -> c_int {
    guard(|| {
        let (cd, ch) = (card(wCardIndex)?, channel(wChannel)?);
        let shared = system::active()?;
        let cd = shared.card(cd)?;
        let bit = 1u32 << ch.0;
        if on {
            shared.servo_on[cd].fetch_or(bit, Ordering::AcqRel);
        } else {
            shared.servo_on[cd].fetch_and(!bit, Ordering::AcqRel);
        }
        Ok(c::NO_ERR)
    })
}

/// Turns the servo-on output of one channel on (at once, not queued: user manual §2.3).
#[no_mangle]
pub extern "C" fn MCC_SetServoOn(wChannel: WORD, wCardIndex: WORD) -> c_int {
    servo(wChannel, wCardIndex, true)
}

/// Turns the servo-on output of one channel off.
#[no_mangle]
pub extern "C" fn MCC_SetServoOff(wChannel: WORD, wCardIndex: WORD) -> c_int {
    servo(wChannel, wCardIndex, false)
}

fn pos_ready(wCardIndex: WORD, on: bool) -> c_int {
    guard(|| {
        let shared = system::active()?;
        let cd = shared.card(card(wCardIndex)?)?;
        shared.pos_ready[cd].store(on, Ordering::Release);
        Ok(c::NO_ERR)
    })
}

/// Turns the card's position-ready output on.
#[no_mangle]
pub extern "C" fn MCC_EnablePosReady(wCardIndex: WORD) -> c_int {
    pos_ready(wCardIndex, true)
}

/// Turns the card's position-ready output off.
#[no_mangle]
pub extern "C" fn MCC_DisablePosReady(wCardIndex: WORD) -> c_int {
    pos_ready(wCardIndex, false)
}
