//! What the board reports (§4.18, §4.19): a motor's status, the limit switches.

use std::os::raw::c_int;

use super::call::{motor, with_client};
use super::*;

/// The body of [`crate::ffi::mcl::mcl_get_motor_status`] (its documentation says what it does):
/// a §4 status.
///
/// # Safety
/// `motor_status` must be null or valid for writing one `int`.
pub unsafe fn get_motor_status(
    controller_id: c_int,
    motor_id: c_int,
    motor_status: *mut c_int,
) -> c_int {
    let check = || {
        motor(motor_id)?;
        if motor_status.is_null() {
            return Err(MCL_PARAMETER_OUT_OF_RANGE_ERROR);
        }
        Ok(())
    };
    with_client(controller_id, check, |client, id| {
        let st = client.query_status(id, u32::try_from(motor_id).unwrap_or(u32::MAX))?;
        // SAFETY: non-null (checked), writable per the caller's contract.
        unsafe { motor_status.write(st.bits()) };
        Ok(())
    })
}

/// The body of [`crate::ffi::mcl::mcl_get_limit_switches`] (its documentation says what it does):
/// a §4 status.
///
/// # Safety
/// `limits` must be null or valid for writing one `int`.
pub unsafe fn get_limit_switches(controller_id: c_int, limits: *mut c_int) -> c_int {
    let check = || {
        if limits.is_null() {
            return Err(MCL_PARAMETER_OUT_OF_RANGE_ERROR);
        }
        Ok(())
    };
    with_client(controller_id, check, |client, id| {
        let bits = client.query_limits(id)?;
        // SAFETY: non-null (checked), writable per the caller's contract.
        unsafe { limits.write(c_int::from(bits & 0x3f)) };
        Ok(())
    })
}
