//! Under a virtual clock the engine thread keeps the machine's and the groups' locks from
//! one tick to the next while nothing between ticks needs them (src/engine/running.rs).
//! Another thread of the program that wants one during a long run gets it at the next
//! tick: it is never made to wait for the run to end.

mod common;

use std::time::Duration;
use MCCLPCI_IMP::ffi::position::MCC_SetPGain;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::{MCC_OverrideSpeed, MCC_TimeDelay};
use MCCLPCI_IMP::vendor::consts::*;

#[test]
fn another_thread_gets_the_locks_during_a_long_virtual_run() {
    std::env::set_var("MCCL_CLOCK", "fast");
    let (ticks_at_start, ticks_at_close) = common::within(
        "a thread locking a group and the machine during a run",
        Duration::from_secs(120),
        || {
            assert_eq!(common::init(1), NO_ERR);
            let shared = MCCLPCI_IMP::system::active().expect("running");
            let start = shared.clock().ticks();
            let other = std::thread::spawn(move || {
                let shared = MCCLPCI_IMP::system::active().expect("running");
                // Into the run: the ticks move.
                while shared.clock().ticks() < start + 1_000 {
                    std::thread::yield_now();
                }
                for i in 0..100u16 {
                    // The group's lock (the override is stored on the group) ...
                    MCC_OverrideSpeed(50.0 + f64::from(i), 0);
                    // ... and the machine's (the gains are the card's).
                    assert_eq!(MCC_SetPGain(i, i, i, i, i, i, i, i, 0), NO_ERR);
                }
                let at = shared.clock().ticks();
                // The only way the run below ends: 2^32 - 1 ms is 49 days of virtual time.
                assert_eq!(MCC_CloseSystem(), NO_ERR);
                at
            });
            MCC_TimeDelay(u32::MAX);
            let at = other.join().expect("the other thread");
            (start, at)
        },
    );
    // The other thread's 200 calls ran while the run went on (it ended the run itself,
    // so they could not have waited for its end).
    assert!(ticks_at_close > ticks_at_start + 1_000);
}
