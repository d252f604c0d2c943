//! Motion status (user manual §2.6.5; INTERFACE.md "Motion Status").

use super::guard;
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::c_int;

/// The group's motion status (`GMS_*`). Reads the engine's published snapshot; under the
/// stepped clock a poll that finds the group busy runs one tick.
#[no_mangle]
pub extern "C" fn MCC_GetMotionStatus(wGroupIndex: WORD) -> c_int {
    guard(|| {
        let shared = system::active()?;
        let status = shared.snapshot(wGroupIndex)?.status;
        if status != c::GMS_STOP {
            shared.clock.poll();
            return Ok(shared.snapshot(wGroupIndex)?.status);
        }
        Ok(status)
    })
}
