//! The MC3B motor control library's C entry points (`mcl_*`, MC3B User's Guide §4; header
//! `include/mcl.h`). Each is one `ffi_boundary! { @mcl ... }` around its body in
//! [`crate::mc3b::mcl`]: the library's one panic boundary, with the MCL convention (a
//! panic is `MCL_SERIAL_PORT_ERROR`, after [`crate::mc3b::mcl::after_panic`] has stopped
//! the board's motors and released the port).

use crate::mc3b::mcl;
use std::os::raw::c_int;

/// §4.1: store the library version (major*100 + minor) in `*version`.
///
/// # Safety
/// `version` must be null or valid for writing one `int`.
#[no_mangle]
pub unsafe extern "C" fn mcl_get_library_version(version: *mut c_int) -> c_int {
    ffi_boundary! { @mcl
        // SAFETY: forwarded under this function's contract.
        unsafe { mcl::get_library_version(version) }
    }
}

/// §4.2: open COM port `com_port` (see [`crate::mc3b::mcl`] for the device-path
/// rule), initialize the board and store the number of controllers (1) in
/// `*number_of_controllers`. A second call without `mcl_deinitialize` only
/// returns NO ERROR.
///
/// # Safety
/// `number_of_controllers` must be null or valid for writing one `int`.
#[no_mangle]
pub unsafe extern "C" fn mcl_initialize(
    com_port: c_int,
    number_of_controllers: *mut c_int,
) -> c_int {
    ffi_boundary! { @mcl
        // SAFETY: forwarded under this function's contract.
        unsafe { mcl::initialize(com_port, number_of_controllers) }
    }
}

/// §4.3: re-initialize the board (all motors off), release the port and
/// return to the uninitialized state.
#[no_mangle]
pub extern "C" fn mcl_deinitialize() -> c_int {
    ffi_boundary! { @mcl mcl::deinitialize() }
}

/// §4.4: acceleration 100..100000 steps/s² (allowed while free-running).
#[no_mangle]
pub extern "C" fn mcl_set_motor_acceleration(
    controller_id: c_int,
    motor_id: c_int,
    acceleration: c_int,
) -> c_int {
    ffi_boundary! { @mcl mcl::set_motor_acceleration(controller_id, motor_id, acceleration) }
}

/// §4.5: deceleration 100..100000 steps/s² (allowed while free-running).
#[no_mangle]
pub extern "C" fn mcl_set_motor_deceleration(
    controller_id: c_int,
    motor_id: c_int,
    deceleration: c_int,
) -> c_int {
    ffi_boundary! { @mcl mcl::set_motor_deceleration(controller_id, motor_id, deceleration) }
}

/// §4.6: maximum velocity 1..5000 steps/s; `direction_modifier` 0 or 1
/// (the C++ default argument of the guide is 0; C callers pass it).
#[no_mangle]
pub extern "C" fn mcl_set_motor_maximum_velocity(
    controller_id: c_int,
    motor_id: c_int,
    maximum_velocity: c_int,
    direction_modifier: c_int,
) -> c_int {
    ffi_boundary! { @mcl
        mcl::set_motor_maximum_velocity(
            controller_id,
            motor_id,
            maximum_velocity,
            direction_modifier,
        )
    }
}

/// §4.7: half steps (`true`) or full steps (`false`).
#[no_mangle]
pub extern "C" fn mcl_set_motor_half_steps_control(
    controller_id: c_int,
    motor_id: c_int,
    half_steps: bool,
) -> c_int {
    ffi_boundary! { @mcl mcl::set_motor_half_steps_control(controller_id, motor_id, half_steps) }
}

/// §4.8: apply the holding current when idle (`true`) or not.
#[no_mangle]
pub extern "C" fn mcl_set_motor_holding_current_control(
    controller_id: c_int,
    motor_id: c_int,
    holding_current: bool,
) -> c_int {
    ffi_boundary! { @mcl
        mcl::set_motor_holding_current_control(
            controller_id,
            motor_id,
            holding_current,
        )
    }
}

/// §4.9: limit switch bit (0..5, or -1 for none) and active level (`true`
/// = +5 V) for each direction, sent as the AND/XOR masks of §6.5.
#[no_mangle]
pub extern "C" fn mcl_set_motor_limits(
    controller_id: c_int,
    motor_id: c_int,
    direction_0_limit_bit: c_int,
    direction_0_limit_level: bool,
    direction_1_limit_bit: c_int,
    direction_1_limit_level: bool,
) -> c_int {
    ffi_boundary! { @mcl
        mcl::set_motor_limits(
            controller_id,
            motor_id,
            direction_0_limit_bit,
            direction_0_limit_level,
            direction_1_limit_bit,
            direction_1_limit_level,
        )
    }
}

/// §4.10: limit switch debounce count 1..100 (1 kHz samples).
#[no_mangle]
pub extern "C" fn mcl_set_limit_switch_debounce(
    controller_id: c_int,
    debounce_count: c_int,
) -> c_int {
    ffi_boundary! { @mcl mcl::set_limit_switch_debounce(controller_id, debounce_count) }
}

/// §4.11: holding and running current limits, 0..2000 mA each.
#[no_mangle]
pub extern "C" fn mcl_set_motor_current_limits(
    controller_id: c_int,
    motor_id: c_int,
    holding_current_limit: c_int,
    running_current_limit: c_int,
) -> c_int {
    ffi_boundary! { @mcl
        mcl::set_motor_current_limits(
            controller_id,
            motor_id,
            holding_current_limit,
            running_current_limit,
        )
    }
}

/// §4.12: free-run the motor in `direction` (0/1).
#[no_mangle]
pub extern "C" fn mcl_run_motor(controller_id: c_int, motor_id: c_int, direction: c_int) -> c_int {
    ffi_boundary! { @mcl mcl::run_motor(controller_id, motor_id, direction) }
}

/// §4.13: move `steps` (>= 0) steps in `direction` (0/1).
#[no_mangle]
pub extern "C" fn mcl_move_motor(
    controller_id: c_int,
    motor_id: c_int,
    direction: c_int,
    steps: c_int,
) -> c_int {
    ffi_boundary! { @mcl mcl::move_motor(controller_id, motor_id, direction, steps) }
}

/// §4.14: home the motor toward `direction` (0/1).
#[no_mangle]
pub extern "C" fn mcl_home_motor(controller_id: c_int, motor_id: c_int, direction: c_int) -> c_int {
    ffi_boundary! { @mcl mcl::home_motor(controller_id, motor_id, direction) }
}

/// §4.15: stop the motor at once.
#[no_mangle]
pub extern "C" fn mcl_stop_motor(controller_id: c_int, motor_id: c_int) -> c_int {
    ffi_boundary! { @mcl mcl::stop_motor(controller_id, motor_id) }
}

/// §4.16: synchronous linear move of all three motors (steps >= 0,
/// directions 0/1); `execute` false stores it in the chained-move buffer.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn mcl_synchronous_move_motor(
    controller_id: c_int,
    motor_0_steps: c_int,
    motor_0_direction: c_int,
    motor_1_steps: c_int,
    motor_1_direction: c_int,
    motor_2_steps: c_int,
    motor_2_direction: c_int,
    execute: bool,
) -> c_int {
    ffi_boundary! { @mcl
        mcl::synchronous_move_motor(
            controller_id,
            motor_0_steps,
            motor_0_direction,
            motor_1_steps,
            motor_1_direction,
            motor_2_steps,
            motor_2_direction,
            execute,
        )
    }
}

/// §4.17: chained synchronous move of `number_of_moves` (1..100) moves given
/// as six arrays of that length.
///
/// # Safety
/// Each pointer must be null or valid for reading `number_of_moves` ints.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn mcl_chained_synchronous_move_motor(
    controller_id: c_int,
    number_of_moves: c_int,
    motor_0_steps: *const c_int,
    motor_0_direction: *const c_int,
    motor_1_steps: *const c_int,
    motor_1_direction: *const c_int,
    motor_2_steps: *const c_int,
    motor_2_direction: *const c_int,
) -> c_int {
    ffi_boundary! { @mcl
        // SAFETY: forwarded under this function's contract.
        unsafe {
            mcl::chained_synchronous_move_motor(
                controller_id,
                number_of_moves,
                motor_0_steps,
                motor_0_direction,
                motor_1_steps,
                motor_1_direction,
                motor_2_steps,
                motor_2_direction,
            )
        }
    }
}

/// §4.18: motor status bits in `*motor_status`: bit 0 running, bit 1 at the
/// direction 0 limit, bit 2 at the direction 1 limit.
///
/// # Safety
/// `motor_status` must be null or valid for writing one `int`.
#[no_mangle]
pub unsafe extern "C" fn mcl_get_motor_status(
    controller_id: c_int,
    motor_id: c_int,
    motor_status: *mut c_int,
) -> c_int {
    ffi_boundary! { @mcl
        // SAFETY: forwarded under this function's contract.
        unsafe { mcl::get_motor_status(controller_id, motor_id, motor_status) }
    }
}

/// §4.19: debounced limit switch bits (bits 0..5) in `*limits`.
///
/// # Safety
/// `limits` must be null or valid for writing one `int`.
#[no_mangle]
pub unsafe extern "C" fn mcl_get_limit_switches(controller_id: c_int, limits: *mut c_int) -> c_int {
    ffi_boundary! { @mcl
        // SAFETY: forwarded under this function's contract.
        unsafe { mcl::get_limit_switches(controller_id, limits) }
    }
}

#[cfg(test)]
mod tests;
