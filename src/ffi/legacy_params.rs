//! The older machine-parameter calls (vendor header, "Obsolete functions"; the manuals do
//! not describe them): `SYS_MACH_PARAM` holds the mechanism parameters, an old
//! `HOME_CONFIG` and an `ENCODER_CONFIG`; setting it is setting the three newer
//! configurations ([`crate::config::legacy`] says how the old home fields map), and
//! `MCC_UpdateMachParam` is `MCC_UpdateParam`. See docs/undocumented-functions.md.

use super::{card, channel, read_in, Out};
use crate::config::legacy;
use crate::error::McclResult;
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
/// Every pointer argument must be NULL (refused with `PARAMETER_ERR`) or point to
/// valid memory of the declared C type, as in the vendor library.
#[no_mangle]
pub unsafe extern "C" fn MCC_SetMachParam(
    pstMachParam: *mut SYS_MACH_PARAM,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let (cd, ch) = (card(wCardIndex)?, channel(wChannel)?);
        // SAFETY: NULL is rejected; otherwise the caller passes a SYS_MACH_PARAM.
        let p = unsafe { read_in(pstMachParam) }?;
        system::with(|s| -> McclResult<c_int> {
            let (mac, home, enc) = legacy::split(&p, &s.config.home[cd.0][ch.0])?;
            s.config.mac[cd.0][ch.0] = mac;
            s.config.home[cd.0][ch.0] = home;
            s.config.encoder[cd.0][ch.0] = enc;
            Ok(c::NO_ERR)
        })
    }
}

/// Reads the parameters last set for one channel (by either generation of setters) as
/// the old struct: `stHome.wType` reads the go-home mode (3..16), `wLeaveDir` the
/// direction opposite the approach.
///
/// # Safety
/// Every pointer argument must be NULL (refused with `PARAMETER_ERR`) or point to
/// valid memory of the declared C type, as in the vendor library.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetMachParam(
    pstMachParam: *mut SYS_MACH_PARAM,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let (cd, ch) = (card(wCardIndex)?, channel(wChannel)?);
        // SAFETY: NULL or writable, as this function's contract requires.
        let out = unsafe { Out::new(pstMachParam) }?;
        let p = system::with(|s| {
            legacy::join(
                &s.config.mac[cd.0][ch.0],
                &s.config.home[cd.0][ch.0],
                &s.config.encoder[cd.0][ch.0],
            )
        });
        out.write(p);
        Ok(c::NO_ERR)
    }
}

/// Applies the parameters set since init and resets motion: `MCC_UpdateParam`.
#[no_mangle]
pub extern "C" fn MCC_UpdateMachParam() -> c_int {
    ffi_boundary! { system::update_param().map(|()| c::NO_ERR) }
}
