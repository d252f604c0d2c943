//! What the tests of the C entry points that stay inside the crate share: the panic tests
//! (`tests_panic.rs`, which arm the `cfg(test)` fault points) and the clock-statistics
//! tests beside `MCCL_SimGetClockStats` (`sim.rs`, which use its private helpers). Every
//! other test of the C entry points is an integration test under `tests/`, one process
//! per file (see `tests/common`).
//!
//! These are the only tests of the library's unit-test binary that start the system, and
//! they run one at a time on the lock below: while one of them holds it, no other test of
//! this process reads `MCCL_CLOCK`, so setting it there races nothing.

use super::system::*;
use crate::vendor::consts::*;
use crate::vendor::*;
use parking_lot::Mutex;

/// The library has one process-wide system: tests that use it run one at a time.
static SERIAL: Mutex<()> = Mutex::new(());

/// Locks the system for one test and starts from a closed system with default config.
pub(super) fn fresh() -> parking_lot::MutexGuard<'static, ()> {
    let g = SERIAL.lock();
    let _ = MCC_CloseSystem();
    crate::system::with(|s| s.config = crate::config::Config::default());
    std::env::set_var("MCCL_CLOCK", "stepped");
    g
}

/// Starts the system with `n` cards and an interpolation period of `ms`.
pub(super) fn init_ms(n: usize, ms: i32) -> i32 {
    let mut c = vec![
        SYS_CARD_CONFIG {
            wCardType: IMP_III_8_AXIS_PCI_CARD,
            ..Default::default()
        };
        n
    ];
    // SAFETY: c holds n valid SYS_CARD_CONFIG.
    unsafe { MCC_InitSystem(ms, c.as_mut_ptr(), n as u16) }
}
