//! A program that asks for the largest queue in every group must get an error code or
//! work, never be killed by the library.
//!
//! The work runs in a child process (this test binary run again with
//! `MCCL_QUEUE_MEMORY_CHILD=1`) whose address space is limited with `setrlimit(RLIMIT_AS)`
//! to what it uses at start plus 768 MiB. Numbers: a queued command takes
//! `size_of::<Command>()` bytes (464 on x86-64), so 96 groups of 1,000,000 commands are
//! 96 × 1e6 × 464 B = 44.5 GB if reserved up front — far above the limit, and the
//! reservation failing inside `MCC_InitSystem` aborted the whole program. Growing as it
//! fills (capacity 16, 32, … doubling, the last step capped at the queue size), one
//! group's 1,000,000 commands take 464 MB, so 768 MiB (805 MB) hold one full queue but not
//! two: filling groups one after the other, the second meets the limit when a doubling
//! fails — after a power of two of commands (measured: group 1 at 2^19 = 524,288, whose
//! next step would add 464 MB to the 464 + 243 MB held) — and there `MCC_Line` returns
//! `COMMAND_BUFFER_FULL_ERR`; the library goes on working (abort, status, a new line,
//! close all `NO_ERR`) and the process exits normally.

use std::os::raw::c_int;
use std::process::Command;

use MCCLPCI_IMP::ffi::motion::MCC_Line;
use MCCLPCI_IMP::ffi::status::MCC_GetMotionStatus;
use MCCLPCI_IMP::ffi::system::{
    MCC_CloseAllGroups, MCC_CloseSystem, MCC_CreateGroupEx, MCC_InitSystem,
};
use MCCLPCI_IMP::ffi::trajectory::MCC_AbortMotion;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::SYS_CARD_CONFIG;

const CHILD: &str = "MCCL_QUEUE_MEMORY_CHILD";
const QUEUE: c_int = 1_000_000;
const GROUPS: c_int = 96;

/// Address space the child is allowed beyond what it maps at start.
const HEADROOM: u64 = 768 << 20;

fn vm_size_bytes() -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").expect("/proc/self/status");
    let kb: u64 = status
        .lines()
        .find_map(|l| l.strip_prefix("VmSize:"))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        .expect("VmSize");
    kb * 1024
}

fn limit_address_space(bytes: u64) {
    let lim = libc::rlimit {
        rlim_cur: bytes,
        rlim_max: bytes,
    };
    // SAFETY: setrlimit reads the struct we pass; it changes only this process's limit.
    let r = unsafe { libc::setrlimit(libc::RLIMIT_AS, &lim) };
    assert_eq!(r, 0, "setrlimit(RLIMIT_AS)");
}

/// The child: the largest queue in every group, then fill them under the limit.
fn child() {
    limit_address_space(vm_size_bytes() + HEADROOM);
    assert_eq!(MCC_CloseAllGroups(), NO_ERR);
    for g in 0..GROUPS {
        // A channel belongs to one group only: group g maps X to channel g % 8 of card
        // g / 8, 12 cards of 8 channels.
        assert_eq!(
            MCC_CreateGroupEx(g % 8, -1, -1, -1, -1, -1, -1, -1, g / 8, QUEUE),
            g,
            "group {g}"
        );
    }
    let mut cards = [SYS_CARD_CONFIG {
        wCardType: IMP_III_8_AXIS_PCI_CARD,
        ..Default::default()
    }; 12];
    // SAFETY: twelve valid SYS_CARD_CONFIG.
    let r = unsafe { MCC_InitSystem(1, cards.as_mut_ptr(), 12) };
    assert_eq!(r, NO_ERR, "MCC_InitSystem with 96 queues of 1,000,000");
    let mut limited = None;
    'groups: for g in 0..GROUPS as u16 {
        for n in 0..QUEUE {
            // Alternate between X = 1 and X = 0: every line has length 1 UU.
            let x = f64::from(1 - n % 2);
            let r = MCC_Line(x, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, g, IMP_AXIS_X);
            if r < 0 {
                assert_eq!(r, COMMAND_BUFFER_FULL_ERR, "group {g} after {n} commands");
                limited = Some((g, n));
                break 'groups;
            }
        }
        println!("group {g}: 1000000 commands queued");
    }
    let (g, n) = limited.expect("the memory limit was never met");
    println!("group {g}: COMMAND_BUFFER_FULL_ERR after {n} commands");
    assert!(n < QUEUE, "met the limit before its queue was full");
    assert!(
        n.count_ones() == 1 && n >= 16,
        "{n}: refused only when a doubling fails"
    );
    for g in 0..=g {
        assert_eq!(MCC_AbortMotion(g, 0), NO_ERR);
        assert_eq!(MCC_GetMotionStatus(g), GMS_STOP);
    }
    // After the abort the memory serves again.
    assert!(MCC_Line(2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, g, IMP_AXIS_X) >= 0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    println!("child done");
}

#[test]
fn largest_queue_everywhere_under_a_memory_limit() {
    if std::env::var_os(CHILD).is_some() {
        return child();
    }
    let out = Command::new(std::env::current_exe().expect("test binary"))
        .args([
            "--exact",
            "largest_queue_everywhere_under_a_memory_limit",
            "--nocapture",
            "--test-threads=1",
        ])
        .env(CHILD, "1")
        .env("MCCL_CLOCK", "stepped")
        .output()
        .expect("run the child");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success() && stdout.contains("child done"),
        "child failed ({:?}):\n{stdout}\n{stderr}",
        out.status
    );
    print!("{stdout}");
}
