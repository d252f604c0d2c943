//! Without `MCCL_PANEL` nothing of the panel starts: no thread, no port (the thread count
//! says so); with it one more thread serves, and `MCC_CloseSystem` leaves neither
//! the thread nor the listening socket. One test, so no other test's threads are counted.
#![cfg(feature = "panel")]

mod common;

use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::vendor::consts::NO_ERR;

/// The names of this process's threads (a new thread names itself once it runs, so only
/// their number is compared while threads start).
fn threads() -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir("/proc/self/task")
        .expect("/proc/self/task")
        .filter_map(|e| std::fs::read_to_string(e.ok()?.path().join("comm")).ok())
        .map(|s| s.trim().to_string())
        .collect();
    v.sort();
    v
}

/// This process's threads once those that were joined have left `/proc`
/// ([`common::threads_settled`]: `pthread_join` returns a moment before the kernel takes
/// the joined thread's entry out; read at once, it could still be listed).
fn threads_after_joins(expected: &[String]) -> Vec<String> {
    common::threads_settled(expected.len());
    threads()
}

#[test]
fn the_panel_thread_exists_only_when_asked_for_and_ends_with_the_system() {
    std::env::set_var("MCCL_CLOCK", "stepped");
    std::env::remove_var("MCCL_PANEL");
    let base = threads();

    // Unset: the engine thread and nothing else.
    assert_eq!(common::init_ms(1, 1), NO_ERR);
    let on = threads();
    assert_eq!(on.len(), base.len() + 1, "{on:?} vs {base:?}");
    assert!(MCCLPCI_IMP::panel::url().is_none());
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    assert_eq!(threads_after_joins(&base), base);

    // "0" and "" mean off too.
    for off in ["0", ""] {
        std::env::set_var("MCCL_PANEL", off);
        assert_eq!(common::init_ms(1, 1), NO_ERR);
        assert_eq!(threads().len(), base.len() + 1);
        assert_eq!(MCC_CloseSystem(), NO_ERR);
        assert_eq!(threads_after_joins(&base), base);
    }

    // Set: one more thread, serving; after close none, and the port is closed.
    std::env::set_var("MCCL_PANEL", "127.0.0.1:0");
    for _ in 0..3 {
        assert_eq!(common::init_ms(1, 1), NO_ERR);
        let on = threads();
        assert_eq!(on.len(), base.len() + 2, "{on:?}");
        let url = MCCLPCI_IMP::panel::url().expect("a panel runs");
        let addr = url
            .strip_prefix("http://")
            .and_then(|r| r.split('/').next())
            .unwrap()
            .to_string();
        assert!(std::net::TcpStream::connect(&addr).is_ok(), "it listens");
        assert_eq!(MCC_CloseSystem(), NO_ERR);
        assert_eq!(threads_after_joins(&base), base, "no thread left");
        assert!(MCCLPCI_IMP::panel::url().is_none());
        assert!(
            std::net::TcpStream::connect(&addr).is_err(),
            "no socket left listening"
        );
    }

    // A bad address is a message and no panel; the system runs.
    std::env::set_var("MCCL_PANEL", "not-an-address");
    assert_eq!(common::init_ms(1, 1), NO_ERR);
    assert_eq!(threads().len(), base.len() + 1);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    assert_eq!(threads_after_joins(&base), base);
    std::env::remove_var("MCCL_PANEL");
}
