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
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::Duration;

use once_cell::sync::Lazy;
use parking_lot::Mutex;

use ::mc3b::client::{Client, ClientError, Transport};
use ::mc3b::codec::{Command, ErrorCode};
use ::mc3b::serial::open_port;

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

struct State {
    client: Client<Box<dyn Transport + Send>>,
    controllers: c_int,
    /// The chained-move buffer may hold moves of a failed call (module docs).
    chain_dirty: bool,
}

static STATE: Lazy<Mutex<Option<State>>> = Lazy::new(|| Mutex::new(None));

/// Device path for COM port `com_port` (see the module docs), or `None` when
/// `com_port` < 1.
pub fn com_port_path(com_port: c_int) -> Option<String> {
    if com_port < 1 {
        return None;
    }
    match std::env::var(format!("MCL_COM{com_port}")) {
        Ok(p) if !p.is_empty() => Some(p),
        _ => Some(::mc3b::serial::com_port_device(com_port.unsigned_abs())),
    }
}

fn reply_timeout() -> Duration {
    ::mc3b::client::timeout_from_env()
}

fn status_of(e: &ClientError) -> c_int {
    match e {
        ClientError::Timeout => MCL_TIMEOUT_ERROR,
        ClientError::Io(_) => MCL_SERIAL_PORT_ERROR,
        ClientError::Unexpected(_) | ClientError::Garbled(_) => MCL_INVALID_COMMAND_ERROR,
        ClientError::Device(code) => match code {
            ErrorCode::InvalidCommand => MCL_INVALID_COMMAND_ERROR,
            ErrorCode::MotorRunning => MCL_MOTOR_RUNNING_ERROR,
            ErrorCode::WrongParameterCount => MCL_WRONG_NUMBER_OF_PARAMETERS_ERROR,
            ErrorCode::OutOfRange => MCL_PARAMETER_OUT_OF_RANGE_ERROR,
        },
    }
}

/// How long [`after_panic`] waits for the library's state: the panicking call let it go
/// as it unwound, so only another thread's call can hold it, for at most its replies.
const AFTER_PANIC_WAIT: Duration = Duration::from_secs(2);

/// After a panic inside an `mcl_*` call (a defect): the call may have left its work half
/// done (a chain half sent, the chained-move buffer's flag not set), and a later call
/// trusting that state could run moves nobody asked for. So, best effort, every motor
/// is told to stop, and the library returns to the uninitialized state, the port
/// released: every later call returns NOT INITIALIZED until the program calls
/// `mcl_initialize` again, which re-initializes the board (`0I`: motors off, the
/// chained-move buffer empty). Never panics itself.
pub fn after_panic() {
    let taken = catch_unwind(AssertUnwindSafe(|| {
        STATE
            .try_lock_for(AFTER_PANIC_WAIT)
            .and_then(|mut state| state.take())
    }));
    let Ok(Some(mut state)) = taken else {
        return;
    };
    let _ = catch_unwind(AssertUnwindSafe(|| {
        for motor in 0..3 {
            // A board that does not answer cannot be helped from here.
            let _ = state.client.command(&Command::Stop { id: 0, motor });
        }
    }));
}

type Check = Result<(), c_int>;

fn range(v: c_int, lo: c_int, hi: c_int) -> Check {
    if (lo..=hi).contains(&v) {
        Ok(())
    } else {
        Err(MCL_PARAMETER_OUT_OF_RANGE_ERROR)
    }
}

fn motor(m: c_int) -> Check {
    range(m, 0, 2)
}

fn dir(d: c_int) -> Check {
    range(d, 0, 1)
}

fn as_u32(v: c_int) -> Result<u32, c_int> {
    u32::try_from(v).map_err(|_| MCL_PARAMETER_OUT_OF_RANGE_ERROR)
}

/// Run `f` with the initialized client and the controller ID as a wire ID.
/// `check` runs after the initialization test and before `f`.
fn with_client(
    controller_id: c_int,
    check: impl FnOnce() -> Check,
    f: impl FnOnce(&mut Client<Box<dyn Transport + Send>>, u8) -> Result<(), ClientError>,
) -> c_int {
    with_state(controller_id, check, |state, id| f(&mut state.client, id))
}

/// [`with_client`] with the whole state (the chained-move buffer's flag).
fn with_state(
    controller_id: c_int,
    check: impl FnOnce() -> Check,
    f: impl FnOnce(&mut State, u8) -> Result<(), ClientError>,
) -> c_int {
    let mut guard = STATE.lock();
    let Some(state) = guard.as_mut() else {
        return MCL_NOT_INITIALIZED_ERROR;
    };
    crate::fault::point("mcl call");
    if let Err(code) = range(controller_id, 0, state.controllers - 1).and_then(|_| check()) {
        return code;
    }
    let Ok(id) = u8::try_from(controller_id) else {
        return MCL_PARAMETER_OUT_OF_RANGE_ERROR;
    };
    match f(state, id) {
        Ok(()) => MCL_NO_ERROR,
        Err(e) => status_of(&e),
    }
}

/// Send a command built from the wire ID, expecting an acknowledgement.
fn send(
    controller_id: c_int,
    check: impl FnOnce() -> Check,
    build: impl FnOnce(u8) -> Result<Command, c_int>,
) -> c_int {
    let mut built = None;
    let code = with_client(controller_id, check, |client, id| match build(id) {
        Ok(cmd) => client.command(&cmd),
        Err(code) => {
            built = Some(code);
            Ok(())
        }
    });
    built.unwrap_or(code)
}

/// Initialize the library over an already open transport (used by tests
/// and by [`initialize`]). Sends `0I`; returns a §4 status.
pub fn initialize_with(transport: Box<dyn Transport + Send>, timeout: Duration) -> c_int {
    let mut guard = STATE.lock();
    if guard.is_some() {
        return MCL_NO_ERROR;
    }
    let mut client = Client::new(transport, timeout);
    match client.initialize(0) {
        Ok(()) => {
            *guard = Some(State {
                client,
                controllers: 1,
                chain_dirty: false,
            });
            MCL_NO_ERROR
        }
        Err(e) => status_of(&e),
    }
}

/// Whether the library is initialized.
pub fn is_initialized() -> bool {
    STATE.lock().is_some()
}

/// The body of [`crate::ffi::mcl::mcl_get_library_version`] (its documentation says what it does):
/// a §4 status.
///
/// # Safety
/// `version` must be null or valid for writing one `int`.
pub unsafe fn get_library_version(version: *mut c_int) -> c_int {
    if version.is_null() {
        return MCL_PARAMETER_OUT_OF_RANGE_ERROR;
    }
    // SAFETY: non-null, and the caller guarantees it is writable.
    unsafe { version.write(MCL_LIBRARY_VERSION) };
    MCL_NO_ERROR
}

/// The body of [`crate::ffi::mcl::mcl_initialize`] (its documentation says what it does):
/// a §4 status.
///
/// # Safety
/// `number_of_controllers` must be null or valid for writing one `int`.
pub unsafe fn initialize(com_port: c_int, number_of_controllers: *mut c_int) -> c_int {
    if number_of_controllers.is_null() {
        return MCL_PARAMETER_OUT_OF_RANGE_ERROR;
    }
    let write = |n: c_int| {
        // SAFETY: non-null (checked above), writable per the contract.
        unsafe { number_of_controllers.write(n) }
    };
    if let Some(s) = STATE.lock().as_ref() {
        write(s.controllers);
        return MCL_NO_ERROR;
    }
    let Some(path) = com_port_path(com_port) else {
        return MCL_SERIAL_PORT_ERROR;
    };
    let timeout = reply_timeout();
    let port = match open_port(&path, timeout) {
        Ok(p) => p,
        Err(_) => return MCL_SERIAL_PORT_ERROR,
    };
    let code = initialize_with(Box::new(port), timeout);
    if code == MCL_NO_ERROR {
        write(STATE.lock().as_ref().map_or(1, |s| s.controllers));
    }
    code
}

/// The body of [`crate::ffi::mcl::mcl_deinitialize`] (its documentation says what it does):
/// a §4 status.
pub fn deinitialize() -> c_int {
    let Some(mut state) = STATE.lock().take() else {
        return MCL_NOT_INITIALIZED_ERROR;
    };
    match state.client.initialize(0) {
        Ok(()) => MCL_NO_ERROR,
        Err(e) => status_of(&e),
    }
}

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

fn sync_check(s: [c_int; 3], d: [c_int; 3]) -> Check {
    for i in 0..3 {
        range(s[i], 0, c_int::MAX)?;
        dir(d[i])?;
    }
    Ok(())
}

fn sync_cmd(id: u8, s: [c_int; 3], d: [c_int; 3], execute: bool) -> Result<Command, c_int> {
    Ok(Command::SyncMove {
        id,
        steps: [as_u32(s[0])?, as_u32(s[1])?, as_u32(s[2])?],
        directions: [as_u32(d[0])?, as_u32(d[1])?, as_u32(d[2])?],
        execute: Some(u32::from(execute)),
    })
}

/// The body of [`crate::ffi::mcl::mcl_synchronous_move_motor`] (its documentation says what it does):
/// a §4 status.
#[allow(clippy::too_many_arguments)]
pub fn synchronous_move_motor(
    controller_id: c_int,
    motor_0_steps: c_int,
    motor_0_direction: c_int,
    motor_1_steps: c_int,
    motor_1_direction: c_int,
    motor_2_steps: c_int,
    motor_2_direction: c_int,
    execute: bool,
) -> c_int {
    let s = [motor_0_steps, motor_1_steps, motor_2_steps];
    let d = [motor_0_direction, motor_1_direction, motor_2_direction];
    let mut built = None;
    let code = with_state(
        controller_id,
        || sync_check(s, d),
        |state, id| match sync_cmd(id, s, d, execute) {
            Ok(cmd) => with_clean_buffer(state, id, |client| client.command(&cmd)),
            Err(code) => {
                built = Some(code);
                Ok(())
            }
        },
    );
    built.unwrap_or(code)
}

/// Runs `f` (which sends `Y` commands) after discarding a chained-move buffer left
/// by a failed call; if `f` fails, the buffer is marked for discarding (module
/// docs).
fn with_clean_buffer(
    state: &mut State,
    id: u8,
    f: impl FnOnce(&mut Client<Box<dyn Transport + Send>>) -> Result<(), ClientError>,
) -> Result<(), ClientError> {
    if state.chain_dirty {
        state.client.command(&Command::SyncMove {
            id,
            steps: [0; 3],
            directions: [0; 3],
            execute: None,
        })?;
        state.chain_dirty = false;
    }
    let r = f(&mut state.client);
    if r.is_err() {
        state.chain_dirty = true;
    }
    r
}

/// The body of [`crate::ffi::mcl::mcl_chained_synchronous_move_motor`] (its documentation says what it does):
/// a §4 status.
///
/// # Safety
/// Each pointer must be null or valid for reading `number_of_moves` ints.
#[allow(clippy::too_many_arguments)]
pub unsafe fn chained_synchronous_move_motor(
    controller_id: c_int,
    number_of_moves: c_int,
    motor_0_steps: *const c_int,
    motor_0_direction: *const c_int,
    motor_1_steps: *const c_int,
    motor_1_direction: *const c_int,
    motor_2_steps: *const c_int,
    motor_2_direction: *const c_int,
) -> c_int {
    let ptrs = [
        motor_0_steps,
        motor_0_direction,
        motor_1_steps,
        motor_1_direction,
        motor_2_steps,
        motor_2_direction,
    ];
    if !is_initialized() {
        return MCL_NOT_INITIALIZED_ERROR;
    }
    // SAFETY: the pointers are the caller's, under this function's contract.
    let moves = match unsafe { read_moves(number_of_moves, ptrs) } {
        Ok(m) => m,
        Err(code) => return code,
    };
    let mut build_err = None;
    let code = with_state(
        controller_id,
        || Ok(()),
        |state, id| {
            let cmds: Result<Vec<Command>, c_int> = moves
                .iter()
                .enumerate()
                .map(|(k, (s, d))| sync_cmd(id, *s, *d, k + 1 == moves.len()))
                .collect();
            let cmds = match cmds {
                Ok(c) => c,
                Err(c) => {
                    build_err = Some(c);
                    return Ok(());
                }
            };
            // §4.16: all three motors idle, or nothing is stored.
            for m in 0..3 {
                let idle = state.client.query_status(id, m).map(|st| !st.running);
                match idle {
                    Ok(true) => {}
                    Ok(false) => {
                        state.chain_dirty = true;
                        return Err(ClientError::Device(ErrorCode::MotorRunning));
                    }
                    Err(e) => {
                        state.chain_dirty = true;
                        return Err(e);
                    }
                }
            }
            with_clean_buffer(state, id, |client| {
                for cmd in &cmds {
                    client.command(cmd)?;
                }
                Ok(())
            })
        },
    );
    build_err.unwrap_or(code)
}

type Move3 = ([c_int; 3], [c_int; 3]);

/// Read and range-check the six arrays of a chained move.
///
/// # Safety
/// Each non-null pointer must be valid for reading `number_of_moves` ints.
unsafe fn read_moves(number_of_moves: c_int, ptrs: [*const c_int; 6]) -> Result<Vec<Move3>, c_int> {
    range(number_of_moves, 1, MCL_MAX_CHAINED_MOVES)?;
    if ptrs.iter().any(|p| p.is_null()) {
        return Err(MCL_PARAMETER_OUT_OF_RANGE_ERROR);
    }
    let n = usize::try_from(number_of_moves).map_err(|_| MCL_PARAMETER_OUT_OF_RANGE_ERROR)?;
    let mut arrays: Vec<&[c_int]> = Vec::with_capacity(6);
    for p in ptrs {
        // SAFETY: non-null (checked above) and valid for `n` reads per the
        // caller's contract; n is 1..=100.
        arrays.push(unsafe { std::slice::from_raw_parts(p, n) });
    }
    let mut moves = Vec::with_capacity(n);
    for k in 0..n {
        let v = |a: usize| arrays.get(a).and_then(|s| s.get(k)).copied().unwrap_or(-1);
        let s = [v(0), v(2), v(4)];
        let d = [v(1), v(3), v(5)];
        sync_check(s, d)?;
        moves.push((s, d));
    }
    Ok(moves)
}

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn limit_masks_follow_section_6_5() {
        // Guide example: dir 0 on bit 3 high, dir 1 on bit 5 low
        // -> 0L2,8,0,32,32.
        assert_eq!(limit_masks(3, true), Some((8, 0)));
        assert_eq!(limit_masks(5, false), Some((32, 32)));
        assert_eq!(limit_masks(-1, true), Some((0, 0)));
        assert_eq!(limit_masks(6, true), None);
        assert_eq!(limit_masks(-2, false), None);
    }

    #[test]
    fn com_port_rule() {
        assert_eq!(com_port_path(0), None);
        // Use a port number nobody sets.
        assert_eq!(com_port_path(77), Some(::mc3b::serial::com_port_device(77)));
    }
}
