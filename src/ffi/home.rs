//! Go home (user manual §2.8; vendor header "Go Home"): `MCC_Home`, `MCC_GetGoHomeStatus`,
//! `MCC_AbortGoHome`. The parameters come from `MCC_SetHomeConfig` (src/ffi/system.rs);
//! the homing itself runs on the engine (src/engine/homing.rs).

use super::card;
use crate::engine::homing::ORDER_SKIP;
use crate::error::McclError;
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::c_int;

/// Homes the channels of card `wCardIndex` (user manual §2.8.2): `nOrder0..7` is the
/// order of channel 0..7, 0..7 (lower orders first, equal orders together) or 255 to
/// leave the channel out. Returns at once; `MCC_GetGoHomeStatus` says when it is done.
/// One card at a time: `COMMAND_NOTFINISHED_ERR` while a homing runs, or while a group
/// driving one of the channels has motion to do.
#[no_mangle]
#[allow(clippy::too_many_arguments)] // the vendor's signature
pub extern "C" fn MCC_Home(
    nOrder0: c_int,
    nOrder1: c_int,
    nOrder2: c_int,
    nOrder3: c_int,
    nOrder4: c_int,
    nOrder5: c_int,
    nOrder6: c_int,
    nOrder7: c_int,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let cd = card(wCardIndex)?;
        let orders = [
            nOrder0, nOrder1, nOrder2, nOrder3, nOrder4, nOrder5, nOrder6, nOrder7,
        ];
        if orders
            .iter()
            .any(|&o| !(0..=7).contains(&o) && o != ORDER_SKIP)
        {
            return Err(McclError::Parameter);
        }
        let cfgs = system::config(|c| c.home[cd.0]);
        let shared = system::active()?;
        let cd = shared.card(cd)?;
        shared.start_homing(cd, orders, &cfgs)?;
        Ok(c::NO_ERR)
    }
}

/// 1 when the last `MCC_Home` has completed, 0 while it runs (user manual §2.8.2), and
/// `HOME_COMMAND_NOTCALLED_ERR` when there is no homing to report: `MCC_Home` was never
/// called, or its homing was aborted (`MCC_AbortGoHome`), stopped by the emergency-stop
/// input or failed on a limit switch.
#[no_mangle]
pub extern "C" fn MCC_GetGoHomeStatus() -> c_int {
    ffi_boundary! { Ok(system::active()?.home_status()) }
}

/// Stops the homing in progress: every homing channel decelerates over its `dfDecTime`
/// and the homing ends without completing. `NO_ERR` also after a homing completed;
/// `HOME_COMMAND_NOTCALLED_ERR` when no homing was started.
#[no_mangle]
pub extern "C" fn MCC_AbortGoHome() -> c_int {
    ffi_boundary! {
        system::active()?.abort_homing()?;
        Ok(c::NO_ERR)
    }
}
