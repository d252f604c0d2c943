//! Helpers shared by the integration tests that drive the C ABI: one process per test
//! file, so each file owns the library's one process-wide system.
#![allow(dead_code)]

use std::sync::mpsc;
use std::time::Duration;
use MCCLPCI_IMP::vendor::consts::IMP_III_8_AXIS_PCI_CARD;
use MCCLPCI_IMP::vendor::SYS_CARD_CONFIG;

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
