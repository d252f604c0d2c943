//! Motion status (user manual §2.6.5; INTERFACE.md "Motion Status").

use super::guard;
use crate::error::McclError;
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::c_int;
use std::sync::atomic::Ordering;

/// The group's motion status (`GMS_*`). Reads the engine's published snapshot; under the
/// stepped clock a poll that finds the group busy runs one tick.
#[no_mangle]
pub extern "C" fn MCC_GetMotionStatus(wGroupIndex: WORD) -> c_int {
    guard(|| {
        let shared = system::active()?;
        let slot = shared
            .status
            .get(usize::from(wGroupIndex))
            .ok_or(McclError::Group)?;
        let status = slot.load(Ordering::Acquire);
        if status < 0 {
            return Err(McclError::Group);
        }
        if status != c::GMS_STOP {
            shared.clock.poll();
            return Ok(slot.load(Ordering::Acquire));
        }
        Ok(status)
    })
}
