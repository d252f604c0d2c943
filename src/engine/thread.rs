//! Real-time settings of the engine thread under the realtime clock.
//!
//! Always: the thread's timer slack is set to 1 ns (`PR_SET_TIMERSLACK`), so the kernel
//! does not defer its wake-up by the default 50 µs a normal thread may be kept waiting.
//!
//! Optional, off unless the environment asks (read at each `MCC_InitSystem`):
//!
//! * `MCCL_RT_PRIORITY=N` (1..=99): the engine thread runs `SCHED_FIFO` at priority N.
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

use std::sync::atomic::{AtomicBool, Ordering};

/// What the `MCCL_RT_*` variables ask for (after dropping bad values).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct RtSettings {
    /// `SCHED_FIFO` priority.
    pub priority: Option<i32>,
    /// The only CPU to run on.
    pub cpu: Option<usize>,
    /// Lock the process's memory.
    pub lock: bool,
    /// Spin before each deadline, µs (applied by the clock).
    pub spin_us: Option<u64>,
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
                    .filter(|&c| c < libc::CPU_SETSIZE as usize)
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
        (
            RtSettings {
                priority,
                cpu,
                lock,
                spin_us,
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

fn os_error() -> String {
    std::io::Error::last_os_error().to_string()
}

/// `mlockall` once per process.
static LOCKED: AtomicBool = AtomicBool::new(false);

/// Applies `s` to the calling thread (and `mlockall` to the process); returns a message
/// per setting the system refused.
pub fn apply(s: &RtSettings) -> Vec<String> {
    let mut msgs = Vec::new();
    #[cfg(any(target_os = "linux", target_os = "android"))]
    // SAFETY: PR_SET_TIMERSLACK takes an unsigned long and changes only this thread.
    unsafe {
        libc::prctl(libc::PR_SET_TIMERSLACK, 1 as libc::c_ulong, 0, 0, 0);
    }
    if let Some(cpu) = s.cpu {
        #[cfg(any(target_os = "linux", target_os = "android"))]
        {
            // SAFETY: a zeroed cpu_set_t is a valid empty set; `cpu` < CPU_SETSIZE
            // (checked when parsed); pid 0 is the calling thread.
            let r = unsafe {
                let mut set: libc::cpu_set_t = std::mem::zeroed();
                libc::CPU_SET(cpu, &mut set);
                libc::sched_setaffinity(0, std::mem::size_of::<libc::cpu_set_t>(), &set)
            };
            if r != 0 {
                msgs.push(format!(
                    "MCCL: MCCL_RT_CPU={cpu} refused ({}): the engine thread runs on any CPU",
                    os_error()
                ));
            }
        }
    }
    if let Some(prio) = s.priority {
        let p = libc::sched_param {
            sched_priority: prio,
        };
        // SAFETY: the calling thread's handle and a valid sched_param.
        let r = unsafe { libc::pthread_setschedparam(libc::pthread_self(), libc::SCHED_FIFO, &p) };
        if r != 0 {
            msgs.push(format!(
                "MCCL: MCCL_RT_PRIORITY={prio} refused ({}): the engine thread runs with normal scheduling",
                std::io::Error::from_raw_os_error(r)
            ));
        }
    }
    if s.lock && !LOCKED.swap(true, Ordering::AcqRel) {
        // SAFETY: mlockall has no memory-safety preconditions.
        if unsafe { libc::mlockall(libc::MCL_CURRENT | libc::MCL_FUTURE) } != 0 {
            msgs.push(format!(
                "MCCL: MCCL_RT_LOCK=1 refused ({}): memory is not locked",
                os_error()
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
            }
        );
        assert!(m.is_empty());
        let (s, m) = RtSettings::parse(&env(&[
            ("MCCL_RT_PRIORITY", "100"),
            ("MCCL_RT_CPU", "-1"),
            ("MCCL_RT_LOCK", "yes"),
            ("MCCL_RT_SPIN_US", "5000"),
        ]));
        assert_eq!(s, RtSettings::default());
        assert_eq!(m.len(), 4, "{m:?}");
        assert!(m[0].contains("MCCL_RT_PRIORITY=\"100\""), "{m:?}");
        let (s, m) = RtSettings::parse(&env(&[("MCCL_RT_PRIORITY", "0"), ("MCCL_RT_LOCK", "0")]));
        assert_eq!(s, RtSettings::default());
        assert_eq!(m.len(), 1, "priority 0 is not a SCHED_FIFO priority");
    }

    #[test]
    fn a_refused_setting_is_reported_and_the_thread_runs_on() {
        // CPU_SETSIZE - 1 exists on no machine this runs on: refused with a message,
        // and the thread keeps running (the call returns).
        let cpu = libc::CPU_SETSIZE as usize - 1;
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
