//! One motor's motion (§4.12 to §4.15): run, move, home, stop.

use std::os::raw::c_int;

use super::call::{as_u32, dir, motor, range, send};
use ::mc3b::codec::Command;

/// The body of [`crate::ffi::mcl::mcl_run_motor`] (its documentation says what it does):
/// a §4 status.
pub fn run_motor(controller_id: c_int, motor_id: c_int, direction: c_int) -> c_int {
    send(
        controller_id,
        || motor(motor_id).and(dir(direction)),
        |id| {
            Ok(Command::Run {
                id,
                motor: as_u32(motor_id)?,
                direction: as_u32(direction)?,
            })
        },
    )
}

/// The body of [`crate::ffi::mcl::mcl_move_motor`] (its documentation says what it does):
/// a §4 status.
pub fn move_motor(controller_id: c_int, motor_id: c_int, direction: c_int, steps: c_int) -> c_int {
    send(
        controller_id,
        || {
            motor(motor_id)
                .and(dir(direction))
                .and(range(steps, 0, c_int::MAX))
        },
        |id| {
            Ok(Command::Move {
                id,
                motor: as_u32(motor_id)?,
                steps: as_u32(steps)?,
                direction: as_u32(direction)?,
            })
        },
    )
}

/// The body of [`crate::ffi::mcl::mcl_home_motor`] (its documentation says what it does):
/// a §4 status.
pub fn home_motor(controller_id: c_int, motor_id: c_int, direction: c_int) -> c_int {
    send(
        controller_id,
        || motor(motor_id).and(dir(direction)),
        |id| {
            Ok(Command::Home {
                id,
                motor: as_u32(motor_id)?,
                direction: as_u32(direction)?,
            })
        },
    )
}

/// The body of [`crate::ffi::mcl::mcl_stop_motor`] (its documentation says what it does):
/// a §4 status.
pub fn stop_motor(controller_id: c_int, motor_id: c_int) -> c_int {
    send(
        controller_id,
        || motor(motor_id),
        |id| {
            Ok(Command::Stop {
                id,
                motor: as_u32(motor_id)?,
            })
        },
    )
}
