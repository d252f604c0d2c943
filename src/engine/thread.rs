//! Real-time settings of the engine thread under the realtime clock. What each means on
//! Linux and on Windows is in [`crate::platform`]; on Windows a setting the system lacks
//! (`MCCL_RT_LOCK`, an asked-for `MCCL_RT_SLICE_US`) is refused with a message saying so.
//!
//! Always: the thread's deadline sleeps are made as precise as the system allows
//! ([`crate::platform::prepare_precise_sleep`]): on Linux its timer slack is set to 1 ns
//! (`PR_SET_TIMERSLACK`), so the kernel does not defer its wake-up by the default 50 µs a
//! normal thread may be kept waiting; on Windows it gets a high-resolution waitable timer.
//!
//! By default, changeable: under normal scheduling the thread asks for a time slice of
//! [`DEFAULT_SLICE_US`] (`sched_setattr` with `sched_runtime`; Linux 6.12 and later, whose
//! EEVDF scheduler lets a thread with a shorter slice preempt the running one when it
//! wakes; older kernels ignore it). It takes no more CPU than before and needs no
//! privilege: it only stops a woken engine from waiting for the running thread's slice,
//! up to a scheduler tick (4 ms at HZ 250), on a CPU that other programs keep busy.
//! `MCCL_RT_SLICE_US=N` asks for N µs (100..=100000), `0` leaves the kernel's slice.
//!
//! Optional, off unless the environment asks (read at each `MCC_InitSystem`):
//!
//! * `MCCL_RT_PRIORITY=N` (1..=99): the engine thread runs `SCHED_FIFO` at priority N
//!   (Windows: at `THREAD_PRIORITY_TIME_CRITICAL`, whatever N).
//! * `MCCL_RT_CPU=N`: the engine thread runs on CPU N only.
//! * `MCCL_RT_LOCK=1`: the process's memory is locked (`mlockall(MCL_CURRENT |
//!   MCL_FUTURE)`), so no page fault on the tick path waits for the disk. Process-wide and
//!   kept after `MCC_CloseSystem`; `0` or unset: nothing.
//! * `MCCL_RT_SPIN_US=N` (0..=1000): the engine thread stops sleeping N µs (at most half
//!   a period) before each deadline and spins on the clock up to it. The clock reads it
//!   when it is made ([`crate::clock::Clock::new`]); here it is only checked, so that a
//!   bad value is reported with the others.
//!
//! A setting the system refuses (no permission, no such CPU) or a value that is not one
//! of the above prints one line on stderr and is ignored: the engine runs with normal
//! scheduling, and `MCC_InitSystem` never fails because of it.

use crate::platform;
use std::sync::atomic::{AtomicBool, Ordering};

/// The time slice the engine thread asks for under normal scheduling, µs: the shortest
/// the kernel grants (it clamps a request to 0.1..=100 ms). A tick is a few µs to a few
/// tens of µs; a longer one is only shared with other runnable threads sooner.
pub const DEFAULT_SLICE_US: u64 = 100;

/// What the `MCCL_RT_*` variables ask for (after dropping bad values).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RtSettings {
    /// `SCHED_FIFO` priority.
    pub priority: Option<i32>,
    /// The only CPU to run on.
    pub cpu: Option<usize>,
    /// Lock the process's memory.
    pub lock: bool,
    /// Spin before each deadline, µs (applied by the clock).
    pub spin_us: Option<u64>,
    /// Time slice to ask for under normal scheduling, µs (`None`: the kernel's), and
    /// whether the program asked (`MCCL_RT_SLICE_US`; only then is a refusal reported).
    pub slice_us: (Option<u64>, bool),
}

impl Default for RtSettings {
    fn default() -> RtSettings {
        RtSettings {
            priority: None,
            cpu: None,
            lock: false,
            spin_us: None,
            slice_us: (Some(DEFAULT_SLICE_US), false),
        }
    }
}

/// One variable: `None` when unset or empty, else the value parsed by `parse`, or a
/// message for a bad value.
fn var<T>(
    name: &str,
    get: &dyn Fn(&str) -> Option<String>,
    parse: impl Fn(&str) -> Option<T>,
    expected: &str,
    messages: &mut Vec<String>,
) -> Option<T> {
    let v = get(name)?;
    let t = v.trim();
    if t.is_empty() {
        return None;
    }
    let r = parse(t);
    if r.is_none() {
        messages.push(format!("MCCL: {name}={v:?} is not {expected}: ignored"));
    }
    r
}

impl RtSettings {
    /// Reads the settings through `get` (the environment in the library); returns them
    /// and a message per bad value.
    pub fn parse(get: &dyn Fn(&str) -> Option<String>) -> (RtSettings, Vec<String>) {
        let mut msgs = Vec::new();
        let priority = var(
            "MCCL_RT_PRIORITY",
            get,
            |s| s.parse::<i32>().ok().filter(|p| (1..=99).contains(p)),
            "a SCHED_FIFO priority 1..99",
            &mut msgs,
        );
        let cpu = var(
            "MCCL_RT_CPU",
            get,
            |s| {
                s.parse::<usize>()
                    .ok()
                    .filter(|&c| c < crate::platform::CPU_LIMIT)
            },
            "a CPU number",
            &mut msgs,
        );
        let lock = var(
            "MCCL_RT_LOCK",
            get,
            |s| match s {
                "0" => Some(false),
                "1" => Some(true),
                _ => None,
            },
            "0 or 1",
            &mut msgs,
        )
        .unwrap_or(false);
        let spin_us = var(
            "MCCL_RT_SPIN_US",
            get,
            crate::clock::parse_spin_us,
            "a spin of 0..1000 us",
            &mut msgs,
        );
        let slice_us = match var(
            "MCCL_RT_SLICE_US",
            get,
            |s| {
                s.parse::<u64>()
                    .ok()
                    .filter(|&us| us == 0 || (100..=100_000).contains(&us))
            },
            "a time slice of 100..100000 us, or 0",
            &mut msgs,
        ) {
            Some(0) => (None, true),
            Some(us) => (Some(us), true),
            None => (Some(DEFAULT_SLICE_US), false),
        };
        (
            RtSettings {
                priority,
                cpu,
                lock,
                spin_us,
                slice_us,
            },
            msgs,
        )
    }

    /// The settings the environment asks for (messages for bad values on stderr unless
    /// `quiet`).
    pub fn from_env(quiet: bool) -> RtSettings {
        let (s, msgs) = RtSettings::parse(&|n| std::env::var(n).ok());
        if !quiet {
            for m in msgs {
                eprintln!("{m}");
            }
        }
        s
    }
}

/// `mlockall` once per process.
static LOCKED: AtomicBool = AtomicBool::new(false);

/// Applies `s` to the calling thread (and the memory lock to the process); returns a
/// message per setting the system refused.
pub fn apply(s: &RtSettings) -> Vec<String> {
    let mut msgs = Vec::new();
    platform::prepare_precise_sleep();
    if let Some(cpu) = s.cpu {
        if let Err(e) = platform::pin_to_cpu(cpu) {
            msgs.push(format!(
                "MCCL: MCCL_RT_CPU={cpu} refused ({e}): the engine thread runs on any CPU"
            ));
        }
    }
    if let (Some(us), asked) = s.slice_us {
        if let Err(e) = platform::request_slice(us) {
            if asked {
                msgs.push(format!(
                    "MCCL: MCCL_RT_SLICE_US={us} refused ({e}): the engine thread keeps the kernel's time slice"
                ));
            }
        }
    }
    if let Some(prio) = s.priority {
        if let Err(e) = platform::raise_priority(prio) {
            msgs.push(format!(
                "MCCL: MCCL_RT_PRIORITY={prio} refused ({e}): the engine thread runs with normal scheduling"
            ));
        }
    }
    if s.lock && !LOCKED.swap(true, Ordering::AcqRel) {
        if let Err(e) = platform::lock_memory() {
            msgs.push(format!(
                "MCCL: MCCL_RT_LOCK=1 refused ({e}): memory is not locked"
            ));
            LOCKED.store(false, Ordering::Release);
        }
    }
    msgs
}

/// Sets up the calling thread as the realtime engine thread: 1 ns timer slack and the
/// `MCCL_RT_*` settings; messages about bad or refused settings go to stderr unless
/// `quiet`. The realtime benchmark sets up its reference thread the same way.
pub fn setup_current_thread(quiet: bool) {
    let s = RtSettings::from_env(quiet);
    let msgs = apply(&s);
    if !quiet {
        for m in msgs {
            eprintln!("{m}");
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env(pairs: &'static [(&'static str, &'static str)]) -> impl Fn(&str) -> Option<String> {
        move |n| {
            pairs
                .iter()
                .find(|(k, _)| *k == n)
                .map(|(_, v)| v.to_string())
        }
    }

    #[test]
    fn settings_parse_and_bad_values_are_ignored_with_a_message() {
        let (s, m) = RtSettings::parse(&env(&[]));
        assert_eq!(s, RtSettings::default());
        assert!(m.is_empty());
        let (s, m) = RtSettings::parse(&env(&[
            ("MCCL_RT_PRIORITY", "80"),
            ("MCCL_RT_CPU", "1"),
            ("MCCL_RT_LOCK", "1"),
            ("MCCL_RT_SPIN_US", "50"),
        ]));
        assert_eq!(
            s,
            RtSettings {
                priority: Some(80),
                cpu: Some(1),
                lock: true,
                spin_us: Some(50),
                slice_us: (Some(DEFAULT_SLICE_US), false),
            }
        );
        assert!(m.is_empty());
        let (s, m) = RtSettings::parse(&env(&[
            ("MCCL_RT_PRIORITY", "100"),
            ("MCCL_RT_CPU", "-1"),
            ("MCCL_RT_LOCK", "yes"),
            ("MCCL_RT_SPIN_US", "5000"),
            ("MCCL_RT_SLICE_US", "50"),
        ]));
        assert_eq!(s, RtSettings::default());
        assert_eq!(m.len(), 5, "{m:?}");
        assert!(m[4].contains("MCCL_RT_SLICE_US=\"50\""), "{m:?}");
        assert!(m[0].contains("MCCL_RT_PRIORITY=\"100\""), "{m:?}");
        let (s, m) = RtSettings::parse(&env(&[("MCCL_RT_SLICE_US", "500")]));
        assert_eq!(s.slice_us, (Some(500), true));
        assert!(m.is_empty());
        let (s, _) = RtSettings::parse(&env(&[("MCCL_RT_SLICE_US", "0")]));
        assert_eq!(s.slice_us, (None, true), "0: the kernel's own slice");
        let (s, m) = RtSettings::parse(&env(&[("MCCL_RT_PRIORITY", "0"), ("MCCL_RT_LOCK", "0")]));
        assert_eq!(s, RtSettings::default());
        assert_eq!(m.len(), 1, "priority 0 is not a SCHED_FIFO priority");
    }

    #[test]
    fn the_default_settings_are_applied_without_a_message() {
        // The default asks for a short slice (refused silently where the system has
        // none: the program did not ask) and nothing else.
        let msgs = std::thread::spawn(|| apply(&RtSettings::default()))
            .join()
            .unwrap();
        assert!(msgs.is_empty(), "{msgs:?}");
    }

    #[test]
    fn a_refused_setting_is_reported_and_the_thread_runs_on() {
        // The last CPU an affinity can name (1023 on Linux, 63 on 64-bit Windows)
        // exists on no machine this runs on: refused with a message, and the thread
        // keeps running (the call returns).
        let cpu = crate::platform::CPU_LIMIT - 1;
        let m = std::thread::spawn(move || {
            apply(&RtSettings {
                cpu: Some(cpu),
                ..Default::default()
            })
        })
        .join()
        .unwrap();
        assert_eq!(m.len(), 1, "{m:?}");
        assert!(
            m[0].starts_with(&format!("MCCL: MCCL_RT_CPU={cpu} refused")),
            "{m:?}"
        );
    }
}
