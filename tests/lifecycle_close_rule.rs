//! Regression (hostile-use review, defect 2): `MCC_CloseSystem` returning `NO_ERR` means
//! no system is left running, even while a routine of the system being closed calls
//! `MCC_InitSystem`. The rule (docs/compatibility.md, "Init and close from several
//! threads and routines"): init and close take effect in the order they take hold of the
//! system; a routine of a system that is being closed or replaced can no longer start or
//! close one (`COMMAND_NOTACCEPTED_ERR`).
//!
//! Before the fix the routine's init started a new, idle system after the program's close
//! had taken the old one, in about 970 of 1000 cycles.

mod common;

use std::sync::atomic::{AtomicU32, Ordering};
use std::time::Duration;
use MCCLPCI_IMP::ffi::isr::*;
use MCCLPCI_IMP::ffi::status::MCC_GetMotionStatus;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::timer::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::TMRINT;

static REINITS: AtomicU32 = AtomicU32::new(0);
static REFUSED: AtomicU32 = AtomicU32::new(0);

/// Re-initialises the system from the engine thread, on every call.
unsafe extern "system" fn routine(_: *mut TMRINT) {
    match common::init(1) {
        NO_ERR => REINITS.fetch_add(1, Ordering::Relaxed),
        _ => REFUSED.fetch_add(1, Ordering::Relaxed),
    };
}

#[test]
fn close_wins_over_a_routine_that_reinits() {
    std::env::set_var("MCCL_CLOCK", "realtime");
    let left_running = common::within(
        "init + close against re-initialising routines",
        Duration::from_secs(120),
        move || {
            // Counted on this thread, which lives through the whole loop.
            let before = common::threads();
            let mut left = Vec::new();
            for cycle in 0..300u32 {
                assert_eq!(common::init(1), NO_ERR);
                let _ = MCC_SetTMRRoutine(Some(routine), 0);
                let _ = MCC_SetTimer(50_000, 0);
                let _ = MCC_EnableTimer(0);
                let _ = MCC_EnableTimerTrigger(0);
                std::thread::sleep(Duration::from_micros(200 * u64::from(cycle % 10)));
                assert_eq!(MCC_CloseSystem(), NO_ERR, "cycle {cycle}");
                // No system may be running now: a status read finds none
                // (INITIAL_MOTION_ERR; a second close would answer NO_ERR either way, as
                // the vendor's library answers a close without a system), and every
                // engine thread (also one a routine started) has ended.
                let (status, threads) = (MCC_GetMotionStatus(0), common::threads_settled(before));
                if status != INITIAL_MOTION_ERR || threads != before {
                    left.push((cycle, status, threads));
                }
            }
            (before, left)
        },
    );
    let (before, left) = left_running;
    eprintln!(
        "routine re-inits: {} succeeded, {} refused",
        REINITS.load(Ordering::Relaxed),
        REFUSED.load(Ordering::Relaxed)
    );
    assert!(
        REINITS.load(Ordering::Relaxed) + REFUSED.load(Ordering::Relaxed) > 30,
        "the routine ran"
    );
    assert!(
        left.is_empty(),
        "after MCC_CloseSystem returned NO_ERR, a system (status not -1) or an engine \
         thread (threads != {before}) was left in {} of 300 cycles; (cycle, status, \
         threads): {:?}",
        left.len(),
        &left[..left.len().min(20)]
    );
}
