//! `MCCL_TRACE` when the system closes while a command runs: what the program did just
//! before the close (an abort) and the end of every command the close cuts short are in
//! the events file, so that no command is left without an end (a trace report would show
//! it "open").
//!
//! Timing (stepped clock, 1 ms period): a line queued at 0 ms starts in the first tick,
//! whose row is at 1 ms; `MCC_TimeDelay(100)` runs ticks 1..=100, so the program calls
//! what follows at 100 ms. Events of calls made between ticks are written with the next
//! tick; no tick follows a close, so the close writes them at the time it happens: the
//! end of the last tick, 100 ms.

mod common;

use MCCLPCI_IMP::ffi::motion::{MCC_Line, MCC_SetFeedSpeed};
use MCCLPCI_IMP::ffi::system::MCC_CloseSystem;
use MCCLPCI_IMP::ffi::trajectory::{MCC_AbortMotionEx, MCC_TimeDelay};
use MCCLPCI_IMP::vendor::consts::{IMP_AXIS_ALL, NO_ERR};

/// Runs `program` on a traced system (stepped clock, 1 ms) and returns the events file.
fn traced(name: &str, program: impl FnOnce()) -> String {
    let _g = common::fresh();
    let dir = std::env::temp_dir();
    let path = dir.join(format!(
        "mccl_trace_close_{}_{name}.csv",
        std::process::id()
    ));
    let events = dir.join(format!(
        "mccl_trace_close_{}_{name}.events.csv",
        std::process::id()
    ));
    std::env::set_var("MCCL_TRACE", &path);
    let r = common::init(1);
    std::env::remove_var("MCCL_TRACE");
    assert_eq!(r, NO_ERR);
    program();
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    let text = std::fs::read_to_string(&events).expect("the events file");
    let _ = std::fs::remove_file(&path);
    let _ = std::fs::remove_file(&events);
    text
}

/// A 10 UU line at 10 UU/s (1 s: still running at 100 ms), index 0.
fn line_then_100ms() {
    MCC_SetFeedSpeed(10.0, 0);
    assert_eq!(
        MCC_Line(10.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL),
        0
    );
    MCC_TimeDelay(100);
}

#[test]
fn abort_then_close_records_the_abort_and_the_end() {
    let ev = traced("abort", || {
        line_then_100ms();
        // A 50 ms stop, cut short by the close that follows at once.
        assert_eq!(MCC_AbortMotionEx(50.0, 0), NO_ERR);
    });
    assert!(
        ev.contains("1.000000,0,0,cmd_start,index=0 type=LINE\n"),
        "{ev}"
    );
    assert!(
        ev.contains("100.000000,0,0,abort,dec_ms=50.000 block_end=0\n100.000000,0,0,cmd_end,index=0 type=LINE end=stopped\n"),
        "{ev}"
    );
}

#[test]
fn close_while_running_ends_the_command() {
    let ev = traced("running", line_then_100ms);
    assert!(
        ev.ends_with("100.000000,0,0,cmd_end,index=0 type=LINE end=stopped\n"),
        "{ev}"
    );
    assert_eq!(ev.matches("cmd_end").count(), 1, "{ev}");
}

#[test]
fn close_after_the_end_adds_nothing() {
    // The line ends by itself (1 s + ramps); the close then cuts nothing short.
    let ev = traced("stopped", || {
        line_then_100ms();
        MCC_TimeDelay(2000);
    });
    assert_eq!(ev.matches("cmd_end").count(), 1, "{ev}");
    assert!(ev.contains("end=done"), "{ev}");
    assert!(!ev.contains("end=stopped"), "{ev}");
}
