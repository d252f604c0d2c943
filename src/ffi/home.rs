//! Go home (user manual §2.8; vendor header "Go Home"): `MCC_Home`, `MCC_GetGoHomeStatus`,
//! `MCC_AbortGoHome`. The parameters come from `MCC_SetHomeConfig` (src/ffi/system.rs);
//! the homing itself runs on the engine (src/engine/homing.rs).

use super::card;
use crate::config::HOME_MODES_RUN;
use crate::engine::homing::{home_orders, ORDER_SKIP};
use crate::error::{McclError, McclResult};
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::c_int;

/// Starts homing the channels of card `wCardIndex` in the go-home orders `orders`
/// (checked by `engine::homing::home_orders`) with the go-home parameters set for them.
/// A homed channel whose mode is one `MCC_SetHomeConfig` keeps but the manual does not
/// describe (0..2, 17..19) is `PARAMETER_ERR` and nothing moves: how the vendor's card
/// homes in those modes cannot be known from its simulation (it homes nothing there), and
/// a motor must not move in a way the program cannot know.
fn home(orders: [c_int; 8], wCardIndex: WORD) -> McclResult<c_int> {
    let cd = card(wCardIndex)?;
    let orders = home_orders(orders)?;
    let cfgs = system::config(|c| c.home[cd.0]);
    let unknown_mode = orders
        .iter()
        .zip(&cfgs)
        .any(|(&o, h)| o != ORDER_SKIP && !HOME_MODES_RUN.contains(&h.wMode));
    if unknown_mode {
        return Err(McclError::Parameter);
    }
    let shared = system::active()?;
    let cd = shared.card(cd)?;
    shared.start_homing(cd, orders, &cfgs)?;
    Ok(c::NO_ERR)
}

/// Homes the channels of card `wCardIndex` (user manual §2.8.2): `nOrder0..7` is the
/// order of channel 0..7, 0..7 (lower orders first, equal orders together) or 255 to
/// leave the channel out. Returns at once; `MCC_GetGoHomeStatus` says when it is done.
/// One card at a time: `COMMAND_NOTFINISHED_ERR` while a homing runs, or while a group
/// driving one of the channels has motion to do.
#[no_mangle]
pub extern "system" fn MCC_Home(
    v0: c_int,
    v1: c_int,
    v2: c_int,
    v3: c_int,
    v4: c_int,
    v5: c_int,
    v6: c_int,
    v7: c_int,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let v = [v0, v1, v2, v3, v4, v5, v6, v7];
        home(v, wCardIndex)
    }
}

/// 1 when the last `MCC_Home` has completed, 0 while it runs (user manual §2.8.2), and
/// `HOME_COMMAND_NOTCALLED_ERR` when there is no homing to report: `MCC_Home` was never
/// called, or its homing was aborted (`MCC_AbortGoHome`), stopped by the emergency-stop
/// input or failed on a limit switch.
#[no_mangle]
pub extern "system" fn MCC_GetGoHomeStatus() -> c_int {
    ffi_boundary! { Ok(system::active()?.home_status()) }
}

/// Stops the homing in progress: every homing channel decelerates over its `dfDecTime`
/// and the homing ends without completing. `NO_ERR` also after a homing completed;
/// `HOME_COMMAND_NOTCALLED_ERR` when no homing was started.
#[no_mangle]
pub extern "system" fn MCC_AbortGoHome() -> c_int {
    ffi_boundary! {
        system::active()?.abort_homing()?;
        Ok(c::NO_ERR)
    }
}
