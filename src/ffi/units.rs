//! The unit of a group's lengths (vendor header, obsolete functions; the manuals do not
//! describe them): `MCC_SetUnit(UNIT_MM or UNIT_INCH, group)`, `MCC_GetUnit(group)`.
//!
//! Read here as: the mechanism parameters (`dfPitch`, the work zone) are in mm, and a
//! group in `UNIT_INCH` takes and reports every length and speed in inches (25.4 mm):
//! targets, centers, positions, feed and PtP speeds, tolerances, the work zone it is
//! checked against ([`crate::config::unit_scale`]). Channel-level settings (go home,
//! `MCC_GetConvFactor`, the simulated machine) stay in the mechanism's mm. Like the
//! mechanism parameters, a new unit takes effect when the group starts from position 0:
//! at `MCC_InitSystem`, `MCC_UpdateParam` (`MCC_UpdateMachParam`) and
//! `MCC_ResetMotion`; so no position is ever converted under a running motion.

use super::with_group;
use crate::error::{McclError, McclResult};
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::c_int;

/// Sets the unit of a group's lengths: `UNIT_MM` (1) or `UNIT_INCH` (2), else
/// `PARAMETER_ERR`; a group that does not exist (or will not, before init) is
/// `GROUP_PARAMETER_ERR`. Takes effect at the next `MCC_InitSystem`, `MCC_UpdateParam`
/// or `MCC_ResetMotion`; `MCC_GetUnit` reads it at once.
#[no_mangle]
pub extern "system" fn MCC_SetUnit(nUnitMode: c_int, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        if nUnitMode != c::UNIT_MM && nUnitMode != c::UNIT_INCH {
            return Err(McclError::Parameter);
        }
        system::with(|s| s.group_def(wGroupIndex))?;
        if system::active().is_ok() {
            // The running group rebuilds its axes from its definition at the next reset.
            with_group(wGroupIndex, |g| {
                g.set_unit(nUnitMode);
                Ok(())
            })?;
        }
        system::with(|s| {
            let u = s.config.units.get_mut(usize::from(wGroupIndex)).ok_or(McclError::Group)?;
            *u = nUnitMode;
            Ok(c::NO_ERR)
        })
    }
}

/// The unit last set for a group (`UNIT_MM` until `MCC_SetUnit`); `GROUP_PARAMETER_ERR`
/// for a group that does not exist (or will not, before init).
#[no_mangle]
pub extern "system" fn MCC_GetUnit(wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        system::with(|s| -> McclResult<c_int> {
            s.group_def(wGroupIndex)?;
            s.config.units.get(usize::from(wGroupIndex)).copied().ok_or(McclError::Group)
        })
    }
}
