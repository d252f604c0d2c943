//! Regression (hostile-use review, defect 1): two program threads calling `MCC_InitSystem`
//! and `MCC_CloseSystem` under the realtime clock while a timer routine calls into the
//! library must never deadlock (before the fix this hung like `lifecycle_routine_reinit`).

mod common;

use std::sync::atomic::{AtomicU32, Ordering};
use std::time::{Duration, Instant};
use MCCLPCI_IMP::ffi::isr::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::timer::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::TMRINT;

static CALLS: AtomicU32 = AtomicU32::new(0);

unsafe extern "system" fn routine(_: *mut TMRINT) {
    CALLS.fetch_add(1, Ordering::Relaxed);
    let _ = MCC_GetConvFactor(0, 0);
}

fn program_loop(run_for: Duration) -> u32 {
    let start = Instant::now();
    let mut cycles = 0;
    while start.elapsed() < run_for {
        // The other thread's system may run: an init is then refused (RUN_TIME_ERR), as
        // the vendor's library refuses an init while a system runs; this thread closes
        // what runs every other cycle, so both keep starting systems.
        let r = common::init(1);
        assert!(r == NO_ERR || r == RUN_TIME_ERR, "init: {r}");
        let _ = MCC_SetTMRRoutine(Some(routine), 0);
        let _ = MCC_SetTimer(50_000, 0);
        let _ = MCC_EnableTimer(0);
        let _ = MCC_EnableTimerTrigger(0);
        std::thread::sleep(Duration::from_micros(500 + 700 * u64::from(cycles % 4)));
        if cycles % 2 == 1 {
            assert_eq!(MCC_CloseSystem(), NO_ERR);
        }
        cycles += 1;
    }
    cycles
}

#[test]
fn two_program_threads_initialising_never_deadlock() {
    std::env::set_var("MCCL_CLOCK", "realtime");
    let (a, b, before, after) =
        common::within("two threads initialising", Duration::from_secs(60), || {
            let before = common::threads();
            let other = std::thread::spawn(|| program_loop(Duration::from_secs(3)));
            let mine = program_loop(Duration::from_secs(3));
            let theirs = other.join().expect("the other program thread");
            assert_eq!(MCC_CloseSystem(), NO_ERR);
            (mine, theirs, before, common::threads_settled(before))
        });
    eprintln!(
        "{a} + {b} cycles, {} routine calls",
        CALLS.load(Ordering::Relaxed)
    );
    assert!(a > 20 && b > 20, "both threads ran ({a}, {b} cycles)");
    assert!(CALLS.load(Ordering::Relaxed) > 20, "the routine ran");
    // Every engine thread has been joined: the process has its threads of before.
    assert_eq!(after, before, "no engine thread is left");
}
