//! The library's one state (the board's client while initialized) and how every call
//! reaches it: the checks, the controller ID, the status a failure becomes; and what
//! is left to do after a panic.

use std::os::raw::c_int;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::Duration;

use once_cell::sync::Lazy;
use parking_lot::Mutex;

use super::*;
use ::mc3b::client::{Client, ClientError, Transport};
use ::mc3b::codec::{Command, ErrorCode};

/// The initialized library: the board's client.
pub(super) struct State {
    pub(super) client: Client<Box<dyn Transport + Send>>,
    pub(super) controllers: c_int,
    /// The chained-move buffer may hold moves of a failed call (the `mcl` module's
    /// docs).
    pub(super) chain_dirty: bool,
}

/// The library's state; `None` while it is not initialized.
pub(super) static STATE: Lazy<Mutex<Option<State>>> = Lazy::new(|| Mutex::new(None));

/// The §4 status of a failed command.
pub(super) fn status_of(e: &ClientError) -> c_int {
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

/// A check of a call's arguments: `Err` holds the status it returns.
pub(super) type Check = Result<(), c_int>;

pub(super) fn range(v: c_int, lo: c_int, hi: c_int) -> Check {
    if (lo..=hi).contains(&v) {
        Ok(())
    } else {
        Err(MCL_PARAMETER_OUT_OF_RANGE_ERROR)
    }
}

pub(super) fn motor(m: c_int) -> Check {
    range(m, 0, 2)
}

pub(super) fn dir(d: c_int) -> Check {
    range(d, 0, 1)
}

pub(super) fn as_u32(v: c_int) -> Result<u32, c_int> {
    u32::try_from(v).map_err(|_| MCL_PARAMETER_OUT_OF_RANGE_ERROR)
}

/// Run `f` with the initialized client and the controller ID as a wire ID.
/// `check` runs after the initialization test and before `f`.
pub(super) fn with_client(
    controller_id: c_int,
    check: impl FnOnce() -> Check,
    f: impl FnOnce(&mut Client<Box<dyn Transport + Send>>, u8) -> Result<(), ClientError>,
) -> c_int {
    with_state(controller_id, check, |state, id| f(&mut state.client, id))
}

/// [`with_client`] with the whole state (the chained-move buffer's flag).
pub(super) fn with_state(
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
pub(super) fn send(
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
