//! Regression (hostile-use review, defect 1): a timer routine that calls
//! `MCC_CloseSystem` and `MCC_InitSystem` while the program thread keeps initialising and
//! closing must never deadlock.
//!
//! Before the fix an init between its two locked phases could overwrite an engine that
//! another init had installed meanwhile, and dropping it joined the engine thread with the
//! system lock held while that thread sat in a routine waiting for the same lock: this
//! test hung within seconds (it now fails fast instead, see `common::within`).

mod common;

use std::sync::atomic::{AtomicU32, Ordering};
use std::time::{Duration, Instant};
use MCCLPCI_IMP::ffi::isr::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::timer::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::TMRINT;

static CALLS: AtomicU32 = AtomicU32::new(0);
static REINITS: AtomicU32 = AtomicU32::new(0);

/// Every 5th call closes the system from the engine thread and tries to start another
/// (an init while a system runs is refused by the vendor's library, `RUN_TIME_ERR`, and a
/// routine of a system being closed starts none: `COMMAND_NOTACCEPTED_ERR`); the others
/// read a conversion factor (a call that takes the system lock).
unsafe extern "system" fn routine(_: *mut TMRINT) {
    if CALLS.fetch_add(1, Ordering::Relaxed) % 5 == 4 {
        if MCC_CloseSystem() == NO_ERR {
            REINITS.fetch_add(1, Ordering::Relaxed);
        }
        let r = common::init(1);
        assert!(
            r == RUN_TIME_ERR || r == COMMAND_NOTACCEPTED_ERR,
            "a routine's init: {r}"
        );
    } else {
        let _ = MCC_GetConvFactor(0, 0);
    }
}

fn program_loop(run_for: Duration) -> u32 {
    let start = Instant::now();
    let mut cycles = 0u32;
    while start.elapsed() < run_for {
        // A routine may have started a system meanwhile: then this init is refused with
        // RUN_TIME_ERR, as the vendor's library refuses an init while a system runs.
        let r = common::init(1);
        assert!(r == NO_ERR || r == RUN_TIME_ERR, "init: {r}");
        // The routine may have replaced the system already: these may then fail with
        // nothing registered, which is fine; what matters is that nothing hangs.
        let _ = MCC_SetTMRRoutine(Some(routine), 0);
        let _ = MCC_SetTimer(50_000, 0); // 0.5 ms: expires in every 1 ms tick
        let _ = MCC_EnableTimer(0);
        let _ = MCC_EnableTimerTrigger(0);
        MCC_TimeDelay(1 + cycles % 3);
        if cycles % 4 == 3 {
            let _ = MCC_CloseSystem();
        }
        cycles += 1;
    }
    let _ = MCC_CloseSystem();
    cycles
}

#[test]
fn a_routine_that_reinits_never_deadlocks_the_program() {
    std::env::set_var("MCCL_CLOCK", "fast");
    let cycles = common::within(
        "init/close with re-initialising routines",
        Duration::from_secs(60),
        || program_loop(Duration::from_secs(3)),
    );
    let calls = CALLS.load(Ordering::Relaxed);
    eprintln!(
        "{cycles} program cycles, {calls} routine calls, {} closes from a routine",
        REINITS.load(Ordering::Relaxed)
    );
    assert!(cycles > 50, "the loop ran ({cycles} cycles)");
    assert!(calls > 50, "the routine ran ({calls} calls)");
    assert!(
        REINITS.load(Ordering::Relaxed) > 0,
        "some routine closed its system"
    );
    assert_eq!(
        MCCLPCI_IMP::ffi::status::MCC_GetMotionStatus(0),
        INITIAL_MOTION_ERR,
        "nothing runs at the end"
    );
}
