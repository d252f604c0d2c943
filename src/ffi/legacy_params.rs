//! The older machine-parameter calls (vendor header, "Obsolete functions"; the manuals do
//! not describe them): `SYS_MACH_PARAM` holds the mechanism parameters, an old
//! `HOME_CONFIG` and an `ENCODER_CONFIG`; setting it is setting the three newer
//! configurations ([`crate::config::legacy`] says how the old home fields map), and
//! `MCC_UpdateMachParam` is `MCC_UpdateParam`. See docs/undocumented-functions.md.

use super::{read_channel_config, set_channel_config};
use crate::config::legacy;
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::{SYS_MACH_PARAM, WORD};
use std::os::raw::c_int;

/// Sets the mechanism, go-home and encoder parameters of one channel at once, checked as
/// `MCC_SetMacParam`, `MCC_SetHomeConfig` and `MCC_SetEncoderConfig` check them; a
/// refused struct changes none of the three. After `MCC_InitSystem` they take effect at
/// `MCC_UpdateMachParam` (or `MCC_UpdateParam`).
///
/// # Safety
/// `pstMachParam` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `SYS_MACH_PARAM`.
#[no_mangle]
pub unsafe extern "system" fn MCC_SetMachParam(
    pstMachParam: *mut SYS_MACH_PARAM,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            set_channel_config(pstMachParam, wChannel, wCardIndex, |c, cd, ch, p| {
                let (mac, home, enc) = legacy::split(&p, &c.home[cd.0][ch.0])?;
                c.mac[cd.0][ch.0] = mac;
                c.home[cd.0][ch.0] = home;
                c.encoder[cd.0][ch.0] = enc;
                Ok(())
            })
        }
    }
}

/// Reads the parameters last set for one channel (by either generation of setters) as
/// the old struct: `stHome.wType` reads the go-home mode (3..16), `wLeaveDir` the
/// direction opposite the approach.
///
/// # Safety
/// `pstMachParam` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `SYS_MACH_PARAM`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetMachParam(
    pstMachParam: *mut SYS_MACH_PARAM,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            read_channel_config(pstMachParam, wChannel, wCardIndex, |c, cd, ch| {
                legacy::join(
                    &c.mac[cd.0][ch.0],
                    &c.home[cd.0][ch.0],
                    &c.encoder[cd.0][ch.0],
                )
            })
        }
    }
}

/// Applies the parameters set since init and resets motion: `MCC_UpdateParam`.
#[no_mangle]
pub extern "system" fn MCC_UpdateMachParam() -> c_int {
    ffi_boundary! { system::update_param().map(|()| c::NO_ERR) }
}
