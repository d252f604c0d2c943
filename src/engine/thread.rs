//! Real-time settings of the engine thread under the realtime clock.
//!
//! Always: the thread's timer slack is set to 1 ns (`PR_SET_TIMERSLACK`), so the kernel
//! does not defer its wake-up by the default 50 µs a normal thread may be kept waiting.
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
    if let (Some(us), asked) = s.slice_us {
        if let Err(e) = request_slice(us) {
            if asked {
                msgs.push(format!(
                    "MCCL: MCCL_RT_SLICE_US={us} refused ({e}): the engine thread keeps the kernel's time slice"
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

/// `struct sched_attr` of `sched_setattr(2)` (the first version, 48 bytes), which the
/// `libc` crate does not declare.
#[cfg(any(target_os = "linux", target_os = "android"))]
#[repr(C)]
#[derive(Debug, Default)]
struct SchedAttr {
    size: u32,
    sched_policy: u32,
    sched_flags: u64,
    sched_nice: i32,
    sched_priority: u32,
    sched_runtime: u64,
    sched_deadline: u64,
    sched_period: u64,
}

/// The calling thread's scheduling attributes (`sched_getattr(2)`).
#[cfg(any(target_os = "linux", target_os = "android"))]
fn own_sched_attr() -> std::io::Result<SchedAttr> {
    let mut a = SchedAttr::default();
    let size = std::mem::size_of::<SchedAttr>() as u32;
    // SAFETY: `a` is a writable sched_attr of `size` bytes; pid 0 is this thread.
    let r = unsafe {
        libc::syscall(
            libc::SYS_sched_getattr,
            0,
            &mut a as *mut SchedAttr,
            size,
            0,
        )
    };
    if r != 0 {
        return Err(std::io::Error::last_os_error());
    }
    a.size = size;
    Ok(a)
}

/// Asks for a time slice of `us` µs for the calling thread under its normal scheduling
/// policy, keeping its policy and nice value (read first: a nice value written back
/// unchanged needs no privilege). A thread under `SCHED_FIFO` or `SCHED_RR` is left as it
/// is (`Ok`).
fn request_slice(us: u64) -> std::io::Result<()> {
    #[cfg(any(target_os = "linux", target_os = "android"))]
    {
        let mut a = own_sched_attr()?;
        let normal = [libc::SCHED_OTHER, libc::SCHED_BATCH];
        if !normal.iter().any(|&p| p as u32 == a.sched_policy) {
            return Ok(());
        }
        a.sched_flags = 0;
        a.sched_runtime = us.saturating_mul(1000);
        // SAFETY: `a` is a valid sched_attr of `a.size` bytes; pid 0 is this thread.
        let r = unsafe { libc::syscall(libc::SYS_sched_setattr, 0, &a as *const SchedAttr, 0) };
        if r != 0 {
            return Err(std::io::Error::last_os_error());
        }
        Ok(())
    }
    #[cfg(not(any(target_os = "linux", target_os = "android")))]
    {
        let _ = us;
        Err(std::io::Error::from(std::io::ErrorKind::Unsupported))
    }
}

/// The calling thread's time slice under normal scheduling, ns, as the kernel reports it
/// (`sched_getattr`'s `sched_runtime`; 0 on a kernel without custom slices), or `None`
/// where the call is not allowed (a seccomp filter).
#[cfg(test)]
fn current_slice_ns() -> Option<u64> {
    own_sched_attr().ok().map(|a| a.sched_runtime)
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

    /// Whether the running kernel grants custom time slices to normal threads (Linux
    /// 6.12 and later).
    fn kernel_has_custom_slices() -> bool {
        let release = std::fs::read_to_string("/proc/sys/kernel/osrelease").unwrap_or_default();
        let mut v = release
            .split(|c: char| !c.is_ascii_digit())
            .filter_map(|n| n.parse::<u32>().ok());
        let (major, minor) = (v.next().unwrap_or(0), v.next().unwrap_or(0));
        (major, minor) >= (6, 12)
    }

    #[test]
    fn the_default_asks_for_a_short_slice_and_keeps_the_nice_value() {
        // On a thread niced to 5 or more (raising the nice value needs no privilege), the
        // default settings ask for a 100 µs slice: the kernel reports 100,000 ns where it
        // grants custom slices, and the nice value is still the one set (written back as
        // read: asking for 0 would need privilege and fail).
        let (msgs, slice, nice) = std::thread::spawn(|| {
            // SAFETY: setpriority/getpriority on the calling thread (tid) only.
            unsafe {
                let tid = libc::gettid() as libc::id_t;
                // 5, or more if the tests already run niced (lowering it would need
                // privilege).
                let nice = (libc::getpriority(libc::PRIO_PROCESS, tid) + 1).clamp(5, 19);
                assert_eq!(libc::setpriority(libc::PRIO_PROCESS, tid, nice), 0);
                let msgs = apply(&RtSettings::default());
                let now = libc::getpriority(libc::PRIO_PROCESS, tid);
                (msgs, current_slice_ns(), (nice, now))
            }
        })
        .join()
        .unwrap();
        assert!(msgs.is_empty(), "{msgs:?}");
        assert_eq!(nice.1, nice.0, "the nice value set before");
        if let (Some(slice), true) = (slice, kernel_has_custom_slices()) {
            assert_eq!(slice, DEFAULT_SLICE_US * 1000);
        }
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
