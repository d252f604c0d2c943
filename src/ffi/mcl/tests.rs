//! The `mcl_*` entry points over an in-process emulator, and a panic inside one (injected
//! with `crate::fault`). These are the only unit tests touching the MC3B library's global
//! state (the integration tests run in processes of their own); they take the lock of
//! `src/ffi/tests.rs`, which also keeps the fault points to one test at a time.

use super::super::tests::fresh;
use super::*;
use crate::mc3b::mcl::*;
use ::mc3b::client::{EmulatorLink, Transport};
use ::mc3b::codec::CommandCode;
use std::io;
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// An emulator link the test can still look at once the library has dropped its client.
#[derive(Clone, Default)]
struct SharedLink(Arc<Mutex<EmulatorLink>>);

impl SharedLink {
    fn with<R>(&self, f: impl FnOnce(&mut EmulatorLink) -> R) -> R {
        f(&mut self.0.lock().expect("the link's lock"))
    }
}

impl Transport for SharedLink {
    fn send(&mut self, data: &[u8]) -> io::Result<()> {
        self.with(|l| l.send(data))
    }
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        self.with(|l| l.recv(buf, timeout))
    }
}

const TIMEOUT: Duration = Duration::from_millis(50);

#[test]
fn library_over_an_in_process_emulator() {
    let _g = fresh();
    assert_eq!(mcl_stop_motor(0, 0), MCL_NOT_INITIALIZED_ERROR);
    let link: Box<dyn Transport + Send> = Box::new(EmulatorLink::new());
    assert_eq!(initialize_with(link, TIMEOUT), MCL_NO_ERROR);
    assert_eq!(
        mcl_set_motor_acceleration(0, 0, 99),
        MCL_PARAMETER_OUT_OF_RANGE_ERROR
    );
    assert_eq!(
        mcl_set_motor_acceleration(1, 0, 100),
        MCL_PARAMETER_OUT_OF_RANGE_ERROR
    );
    assert_eq!(mcl_move_motor(0, 0, 0, 1000), MCL_NO_ERROR);
    assert_eq!(mcl_move_motor(0, 0, 0, 1000), MCL_MOTOR_RUNNING_ERROR);
    let mut st = -1;
    // SAFETY: valid pointer to a local.
    assert_eq!(unsafe { mcl_get_motor_status(0, 0, &mut st) }, MCL_NO_ERROR);
    assert_eq!(st, 1);
    assert_eq!(mcl_deinitialize(), MCL_NO_ERROR);
    assert_eq!(mcl_deinitialize(), MCL_NOT_INITIALIZED_ERROR);
}

/// A panic in the middle of a call (after the library's state is taken, before the
/// command goes out) returns the guide's low-level error, stops the motor that was
/// free-running, and leaves the library uninitialized, so that nothing the interrupted
/// call left half done can run later: every call is NOT INITIALIZED until
/// `mcl_initialize`.
#[test]
fn a_panic_inside_a_call_stops_the_motors_and_needs_a_new_initialize() {
    let _g = fresh();
    let link = SharedLink::default();
    assert_eq!(
        initialize_with(Box::new(link.clone()), TIMEOUT),
        MCL_NO_ERROR
    );
    assert_eq!(mcl_run_motor(0, 1, 0), MCL_NO_ERROR);
    assert!(link.with(|l| l.emulator.is_running(1)));
    let stops_before = link.with(|l| l.emulator.received(CommandCode::Stop));

    crate::fault::arm("mcl call");
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let status = mcl_set_motor_acceleration(0, 1, 1000);
    std::panic::set_hook(hook);
    assert!(crate::fault::fired(), "the fault point was not reached");
    assert_eq!(status, MCL_SERIAL_PORT_ERROR);

    // A stop for each of the three motors went out; the running one ramps down.
    assert_eq!(
        link.with(|l| l.emulator.received(CommandCode::Stop)),
        stops_before + 3
    );
    link.with(|l| l.emulator.advance(Duration::from_secs(5)));
    assert!(!link.with(|l| l.emulator.is_running(1)));

    assert!(!is_initialized());
    assert_eq!(mcl_run_motor(0, 1, 0), MCL_NOT_INITIALIZED_ERROR);
    let mut st = -1;
    // SAFETY: valid pointer to a local.
    let refused = unsafe { mcl_get_motor_status(0, 1, &mut st) };
    assert_eq!(refused, MCL_NOT_INITIALIZED_ERROR);
    assert_eq!(st, -1);

    // A new initialize starts over.
    assert_eq!(
        initialize_with(Box::new(link.clone()), TIMEOUT),
        MCL_NO_ERROR
    );
    assert_eq!(mcl_deinitialize(), MCL_NO_ERROR);
}
