//! Helpers shared by the integration tests that drive the C ABI: one process per test
//! file, so each file owns the library's one process-wide system.
//!
//! The `#[test]`s of one file still share that process and run on several threads:
//! a file whose tests start the system takes [`fresh`] first in every test. Its lock is
//! this file's own (every test binary compiles its own copy of this module), so files
//! never wait for each other, and within a file the environment (`MCCL_CLOCK`,
//! `MCCL_SIM`, `MCCL_TRACE`) is changed only by the test holding the lock; the library
//! reads it only in `MCC_InitSystem` (and `…Ex`, `MCC_InitSimulation`), which only that
//! test calls: no other thread reads it meanwhile. A file with a single `#[test]`
//! (`lifecycle_*.rs`) sets `MCCL_CLOCK` once, before it starts a system.
#![allow(dead_code)]

pub mod emu;
pub mod order_log;
pub mod periph;

use parking_lot::{Mutex, MutexGuard};
use std::sync::mpsc;
use std::time::Duration;
use MCCLPCI_IMP::vendor::consts::IMP_III_8_AXIS_PCI_CARD;
use MCCLPCI_IMP::vendor::SYS_CARD_CONFIG;

/// The encoder count of channel `ch` of card 0 (`MCC_GetENCValue`), which must succeed.
pub fn enc(ch: u16) -> i64 {
    let mut v: std::os::raw::c_long = 0;
    // SAFETY: a valid pointer.
    let r = unsafe { MCCLPCI_IMP::ffi::encoder::MCC_GetENCValue(&mut v, ch, 0) };
    assert_eq!(r, MCCLPCI_IMP::vendor::consts::NO_ERR);
    #[allow(clippy::useless_conversion)] // `long` is 32-bit on Windows
    i64::from(v)
}

/// The library has one process-wide system: the tests of a file that use it run one at a
/// time.
static SERIAL: Mutex<()> = Mutex::new(());

/// Locks the system for one test and starts from a closed system with the default
/// configuration and `MCCL_CLOCK=stepped`, set while the lock is held and the system is
/// closed (a test that wants another clock sets it after this, under the same lock).
/// `parking_lot`'s lock is not poisoned by a failed test, so the next test still runs.
pub fn fresh() -> MutexGuard<'static, ()> {
    let g = SERIAL.lock();
    let _ = MCCLPCI_IMP::ffi::system::MCC_CloseSystem();
    MCCLPCI_IMP::system::with(|s| s.config = MCCLPCI_IMP::config::Config::default());
    std::env::set_var("MCCL_CLOCK", "stepped");
    g
}

/// `n` IMP-III cards, as a program's `SYS_CARD_CONFIG[n]`.
pub fn cards(n: usize) -> Vec<SYS_CARD_CONFIG> {
    vec![
        SYS_CARD_CONFIG {
            wCardType: IMP_III_8_AXIS_PCI_CARD,
            ..Default::default()
        };
        n
    ]
}

/// Starts the system with `n` cards and an interpolation period of `ms`.
pub fn init_ms(n: usize, ms: i32) -> i32 {
    let mut c = cards(n);
    // SAFETY: c holds n valid SYS_CARD_CONFIG.
    unsafe { MCCLPCI_IMP::ffi::system::MCC_InitSystem(ms, c.as_mut_ptr(), n as u16) }
}

/// One IMP-III card, as a program's `SYS_CARD_CONFIG[1]`.
pub fn one_card() -> [SYS_CARD_CONFIG; 1] {
    [SYS_CARD_CONFIG {
        wCardType: IMP_III_8_AXIS_PCI_CARD,
        ..Default::default()
    }]
}

/// `MCC_InitSystem(ms, one card)`.
pub fn init(ms: i32) -> i32 {
    let mut cards = one_card();
    // SAFETY: `cards` is a valid one-element SYS_CARD_CONFIG array.
    unsafe { MCCLPCI_IMP::ffi::system::MCC_InitSystem(ms, cards.as_mut_ptr(), 1) }
}

/// Threads of this process (entries of /proc/self/task).
pub fn threads() -> usize {
    std::fs::read_dir("/proc/self/task").map_or(0, |d| d.count())
}

/// Threads of this process once it has settled at `expected` or after 2 s: a thread
/// that `pthread_join` already returned for can stay listed for a moment while the
/// kernel reaps it, so a count taken right after a join may be one too high.
pub fn threads_settled(expected: usize) -> usize {
    let deadline = std::time::Instant::now() + Duration::from_secs(2);
    loop {
        let n = threads();
        if n == expected || std::time::Instant::now() >= deadline {
            return n;
        }
        std::thread::sleep(Duration::from_millis(1));
    }
}

/// Runs `f` on its own thread and fails the test fast — the whole process exits with a
/// message — if it has not finished after `limit`: a deadlock must fail, never hang.
pub fn within<R: Send + 'static>(
    what: &str,
    limit: Duration,
    f: impl FnOnce() -> R + Send + 'static,
) -> R {
    let (tx, rx) = mpsc::channel();
    std::thread::Builder::new()
        .name(what.into())
        .spawn(move || {
            let _ = tx.send(f());
        })
        .expect("spawn the test's worker");
    match rx.recv_timeout(limit) {
        Ok(r) => r,
        Err(_) => {
            eprintln!("FAIL: {what} did not finish within {limit:?} (deadlock?)");
            std::process::exit(101);
        }
    }
}

/// Ends the process with a message when the test holding it runs longer than `limit`: a
/// test that hangs (a realtime test on a loaded host, a device that stops answering) must
/// fail, not wait for the harness's timeout. Dropping it disarms it.
pub struct Watchdog(Option<mpsc::Sender<()>>);

impl Watchdog {
    /// Arms a watchdog for `what` (named in the message).
    pub fn new(what: &str, limit: Duration) -> Watchdog {
        let (tx, rx) = mpsc::channel::<()>();
        let what = what.to_string();
        std::thread::spawn(move || {
            if let Err(mpsc::RecvTimeoutError::Timeout) = rx.recv_timeout(limit) {
                eprintln!("{what}: still running after {limit:?} (hung?), giving up");
                std::process::exit(3);
            }
        });
        Watchdog(Some(tx))
    }

    /// Arms a watchdog named after the current test.
    pub fn for_this_test(limit: Duration) -> Watchdog {
        Watchdog::new(std::thread::current().name().unwrap_or("?"), limit)
    }
}

impl Drop for Watchdog {
    fn drop(&mut self) {
        if let Some(tx) = self.0.take() {
            let _ = tx.send(());
        }
    }
}
