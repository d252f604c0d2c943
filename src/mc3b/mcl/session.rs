//! Opening and closing the library (§4.2, §4.3): the COM port, initializing the board,
//! the library's version.

use std::os::raw::c_int;
use std::time::Duration;

use super::call::{status_of, State, STATE};
use super::*;
use ::mc3b::client::{Client, Transport};
use ::mc3b::serial::open_port;

/// Device path for COM port `com_port` (see the `mcl` module's docs), or `None` when
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
