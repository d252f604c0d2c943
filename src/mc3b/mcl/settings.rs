//! A motor's and the board's settings (§4.4 to §4.11): ramps, velocity, stepping,
//! currents, limit switches and their debounce.

use std::os::raw::c_int;

use super::call::{as_u32, dir, motor, range, send};
use super::*;
use ::mc3b::codec::Command;

/// The body of [`crate::ffi::mcl::mcl_set_motor_acceleration`] (its documentation says what it does):
/// a §4 status.
pub fn set_motor_acceleration(controller_id: c_int, motor_id: c_int, acceleration: c_int) -> c_int {
    send(
        controller_id,
        || motor(motor_id).and(range(acceleration, 100, 100_000)),
        |id| {
            Ok(Command::SetAcceleration {
                id,
                motor: as_u32(motor_id)?,
                value: as_u32(acceleration)?,
            })
        },
    )
}

/// The body of [`crate::ffi::mcl::mcl_set_motor_deceleration`] (its documentation says what it does):
/// a §4 status.
pub fn set_motor_deceleration(controller_id: c_int, motor_id: c_int, deceleration: c_int) -> c_int {
    send(
        controller_id,
        || motor(motor_id).and(range(deceleration, 100, 100_000)),
        |id| {
            Ok(Command::SetDeceleration {
                id,
                motor: as_u32(motor_id)?,
                value: as_u32(deceleration)?,
            })
        },
    )
}

/// The body of [`crate::ffi::mcl::mcl_set_motor_maximum_velocity`] (its documentation says what it does):
/// a §4 status.
pub fn set_motor_maximum_velocity(
    controller_id: c_int,
    motor_id: c_int,
    maximum_velocity: c_int,
    direction_modifier: c_int,
) -> c_int {
    send(
        controller_id,
        || {
            motor(motor_id)
                .and(range(maximum_velocity, 1, 5000))
                .and(dir(direction_modifier))
        },
        |id| {
            Ok(Command::SetMaxVelocity {
                id,
                motor: as_u32(motor_id)?,
                value: as_u32(maximum_velocity)?,
                direction_modifier: Some(as_u32(direction_modifier)?),
            })
        },
    )
}

/// The body of [`crate::ffi::mcl::mcl_set_motor_half_steps_control`] (its documentation says what it does):
/// a §4 status.
pub fn set_motor_half_steps_control(
    controller_id: c_int,
    motor_id: c_int,
    half_steps: bool,
) -> c_int {
    send(
        controller_id,
        || motor(motor_id),
        |id| {
            Ok(Command::SetHalfStep {
                id,
                motor: as_u32(motor_id)?,
                half: u32::from(half_steps),
            })
        },
    )
}

/// The body of [`crate::ffi::mcl::mcl_set_motor_holding_current_control`] (its documentation says what it does):
/// a §4 status.
pub fn set_motor_holding_current_control(
    controller_id: c_int,
    motor_id: c_int,
    holding_current: bool,
) -> c_int {
    send(
        controller_id,
        || motor(motor_id),
        |id| {
            Ok(Command::SetHoldingCurrent {
                id,
                motor: as_u32(motor_id)?,
                enable: u32::from(holding_current),
            })
        },
    )
}

/// `(AND mask, XOR mask)` of §6.5 for one limit bit/level pair of §4.9:
/// bit -1 disables the limit (0, 0); bit 0..5 with level `true` (input
/// pulled to +5 V at the limit) gives `(1<<bit, 0)`, with level `false`
/// (pulled to 0 V) gives `(1<<bit, 1<<bit)`. Other bits are out of range.
pub fn limit_masks(bit: c_int, level: bool) -> Option<(u32, u32)> {
    match bit {
        -1 => Some((0, 0)),
        0..=5 => {
            let m = 1u32 << bit;
            Some((m, if level { 0 } else { m }))
        }
        _ => None,
    }
}

/// The body of [`crate::ffi::mcl::mcl_set_motor_limits`] (its documentation says what it does):
/// a §4 status.
pub fn set_motor_limits(
    controller_id: c_int,
    motor_id: c_int,
    direction_0_limit_bit: c_int,
    direction_0_limit_level: bool,
    direction_1_limit_bit: c_int,
    direction_1_limit_level: bool,
) -> c_int {
    let m0 = limit_masks(direction_0_limit_bit, direction_0_limit_level);
    let m1 = limit_masks(direction_1_limit_bit, direction_1_limit_level);
    send(
        controller_id,
        || {
            motor(motor_id)?;
            if m0.is_none() || m1.is_none() {
                return Err(MCL_PARAMETER_OUT_OF_RANGE_ERROR);
            }
            Ok(())
        },
        |id| {
            let ((a0, x0), (a1, x1)) = m0.zip(m1).ok_or(MCL_PARAMETER_OUT_OF_RANGE_ERROR)?;
            Ok(Command::SetLimits {
                id,
                motor: as_u32(motor_id)?,
                h0_and: a0,
                h0_xor: x0,
                h1_and: a1,
                h1_xor: x1,
            })
        },
    )
}

/// The body of [`crate::ffi::mcl::mcl_set_limit_switch_debounce`] (its documentation says what it does):
/// a §4 status.
pub fn set_limit_switch_debounce(controller_id: c_int, debounce_count: c_int) -> c_int {
    send(
        controller_id,
        || range(debounce_count, 1, 100),
        |id| {
            Ok(Command::SetDebounce {
                id,
                count: as_u32(debounce_count)?,
            })
        },
    )
}

/// The body of [`crate::ffi::mcl::mcl_set_motor_current_limits`] (its documentation says what it does):
/// a §4 status.
pub fn set_motor_current_limits(
    controller_id: c_int,
    motor_id: c_int,
    holding_current_limit: c_int,
    running_current_limit: c_int,
) -> c_int {
    send(
        controller_id,
        || {
            motor(motor_id)
                .and(range(holding_current_limit, 0, 2000))
                .and(range(running_current_limit, 0, 2000))
        },
        |id| {
            Ok(Command::SetCurrentLimits {
                id,
                motor: as_u32(motor_id)?,
                holding: as_u32(holding_current_limit)?,
                running: as_u32(running_current_limit)?,
            })
        },
    )
}
