//! The MC3B motor control library of §4 of the User's Guide, talking to the board
//! through [`::mc3b::client`]: the bodies of the `mcl_*` exports, which `src/ffi/mcl.rs`
//! puts behind the library's one panic boundary.
//!
//! Every function returns one of the §4 status codes (`MCL_*` constants, 0..7). A panic
//! inside one (a defect) is reported as [`MCL_SERIAL_PORT_ERROR`], the guide's
//! "low-level" error, after [`after_panic`] has stopped the board's motors and released
//! the port.
//!
//! # COM port numbering
//! `com_port` N (1 = COM1, §4.2) names the device given by the environment
//! variable `MCL_COM<N>` when it is set (e.g. `MCL_COM1=/dev/pts/7`), and
//! otherwise the system's name for it ([`::mc3b::serial::com_port_device`]):
//! `/dev/ttyS<N-1>` on Linux (COM1 = `/dev/ttyS0`, the usual numbering),
//! `COM<N>` on Windows. `com_port` < 1 is a SERIAL PORT ERROR (no such port). The port
//! is opened at 19200 baud, 8N1, no flow control.
//!
//! # Decisions
//! * Status checks run in this order: NOT INITIALIZED, then parameter
//!   ranges (PARAMETER OUT-OF-RANGE, checked here before anything is sent,
//!   null pointers included), then the device's own answer.
//! * `mcl_get_library_version` works before `mcl_initialize` (§4.2 says
//!   "most of the other" functions need initialization; the version is a
//!   property of the library). Every other function, `mcl_deinitialize`
//!   included, returns NOT INITIALIZED before it.
//! * `controller_id` must be below the number of controllers found (always
//!   1 for the MC3B: no daisy chaining, §4.2), else PARAMETER OUT-OF-RANGE.
//! * No reply within the timeout (counted as [`::mc3b::client`] says: only time
//!   in which the reply could have been read) is a TIMEOUT ERROR: the board did
//!   not answer (§4: "a problem with the connection").
//! * A reply that cannot be read (garbage, a line longer than any reply), one
//!   from another controller ID, or one that does not fit the command returns
//!   at once, without waiting for the timeout, as INVALID COMMAND ERROR: §4
//!   names that code for "data corruption in the serial communications", and
//!   the guide has no code of its own for a corrupt reply. Device errors
//!   `E0`..`E3` map to 4..7.
//! * The port itself failing — a hang-up (the device side of a pty closed, a
//!   USB adapter unplugged: end of file, `EIO`, `EPIPE`) or failing to open or
//!   configure it — is a SERIAL PORT ERROR, returned at once: §4 names that
//!   code for low-level serial port errors, and waiting cannot help; every
//!   later call returns it too until `mcl_deinitialize` releases the port.
//!   (A pulled cable on a real RS-232 port gives no such error, only
//!   silence: TIMEOUT.)
//! * After a failure that may have left a reply outstanding, the next call
//!   first brings the line back in step (`<id>P`, see [`::mc3b::client`]); if
//!   the board does not answer that, the call fails with that status before
//!   its own command is sent.
//! * Chained-move buffer (§6.12: stored moves run at the next execute). A
//!   chain needs all three motors idle (§4.16): `mcl_chained_synchronous_move_motor`
//!   first queries them (`Q`) and returns MOTOR RUNNING, storing nothing, if
//!   one runs. When a chain or a synchronous move (either `execute`) fails once
//!   it has reached the line (not a parameter refused here, which sends
//!   nothing), the buffer may hold moves nobody will ask for (§6.12:
//!   they would run at the next execute): before the next chain or
//!   synchronous move the library discards it with a plain `<id>Y0,0,0,0,0,0`
//!   (§6.12: a `Y` without `<execute>` discards the buffer and runs itself, here
//!   no steps). That also discards moves the program stored before the failure
//!   with `execute` = false. If the discard fails (a motor runs: MOTOR RUNNING),
//!   the call fails with its status and sends nothing else; the discard is
//!   tried again at the next such call.
//! * `mcl_initialize` sends `0I` and needs its acknowledgement; if that
//!   fails the port is released and the library stays uninitialized.
//! * `mcl_deinitialize` sends `0I` (motors off, §4.3), then releases the port
//!   and returns to the uninitialized state even if that command failed; it
//!   returns the command's status.
//! * `mcl_synchronous_move_motor(.., execute)` sends `Y...,1` for `true`
//!   (runs the chained-move buffer with this move appended; with an empty
//!   buffer that is just this move) and `Y...,0` for `false` (stores it).
//! * `mcl_chained_synchronous_move_motor` sends moves 1..n-1 with execute 0
//!   and move n with execute 1 (moves stored earlier with execute=false run
//!   first, as on the device). All parameters are checked before sending.
//!   A chain of 100 moves is 99 stored and the executing one (§2.2(i), §4.17).
//! * The reply timeout is 500 ms, or `MCL_TIMEOUT_MS` milliseconds if that
//!   environment variable holds a positive integer when `mcl_initialize` runs.

use std::os::raw::c_int;

mod call;
mod chain;
mod motion;
mod session;
mod settings;
mod status;

pub use call::after_panic;
pub use chain::{chained_synchronous_move_motor, synchronous_move_motor};
pub use motion::{home_motor, move_motor, run_motor, stop_motor};
pub use session::{
    com_port_path, deinitialize, get_library_version, initialize, initialize_with, is_initialized,
};
pub use settings::{
    limit_masks, set_limit_switch_debounce, set_motor_acceleration, set_motor_current_limits,
    set_motor_deceleration, set_motor_half_steps_control, set_motor_holding_current_control,
    set_motor_limits, set_motor_maximum_velocity,
};
pub use status::{get_limit_switches, get_motor_status};

/// Status: the call completed.
pub const MCL_NO_ERROR: c_int = 0;
/// Status: low-level serial port error (port missing or in use).
pub const MCL_SERIAL_PORT_ERROR: c_int = 1;
/// Status: `mcl_initialize` has not been called.
pub const MCL_NOT_INITIALIZED_ERROR: c_int = 2;
/// Status: the board did not answer.
pub const MCL_TIMEOUT_ERROR: c_int = 3;
/// Status: the board did not recognize a command.
pub const MCL_INVALID_COMMAND_ERROR: c_int = 4;
/// Status: the board rejected a command because the motor is running.
pub const MCL_MOTOR_RUNNING_ERROR: c_int = 5;
/// Status: the board got a command with the wrong number of parameters.
pub const MCL_WRONG_NUMBER_OF_PARAMETERS_ERROR: c_int = 6;
/// Status: a parameter is out of range.
pub const MCL_PARAMETER_OUT_OF_RANGE_ERROR: c_int = 7;

/// Library version: major*100 + minor (1.00).
pub const MCL_LIBRARY_VERSION: c_int = 100;

/// Largest number of moves in one chained synchronous move (§4.17).
pub const MCL_MAX_CHAINED_MOVES: c_int = 100;

#[cfg(test)]
mod tests;
