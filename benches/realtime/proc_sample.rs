//! What `/proc` shows while a chunk runs: the host's steal time and the guest's interrupt
//! time per CPU, the measured thread's CPU time, run-queue wait and page faults; sampled
//! by the main thread at every poll.

use crate::{POLL, Z};
use std::sync::atomic::{AtomicI32, AtomicU64, Ordering};
use MCCLPCI_IMP::clock::monotonic_ns as mono_ns;

/// The thread a chunk measures (the reference loop or the engine), for `/proc`.
pub(crate) static MEASURED_TID: AtomicI32 = AtomicI32::new(0);

/// One `/proc` sample: when, the host's steal time per CPU (10 ms units), the measured
/// thread's run-queue wait (ns) and its page faults (minor, major).
#[derive(Clone, Copy, Default)]
pub(crate) struct Sample {
    pub(crate) t: u64,
    pub(crate) steal: [u64; 8],
    pub(crate) irq: [u64; 8],
    pub(crate) tid: i32,
    pub(crate) cpu_ns: u64,
    pub(crate) run_delay: u64,
    pub(crate) faults: (u64, u64),
}

fn sample() -> Sample {
    let mut s = Sample {
        t: mono_ns(),
        ..Default::default()
    };
    if let Ok(stat) = std::fs::read_to_string("/proc/stat") {
        for l in stat.lines() {
            let mut f = l.split_whitespace();
            let Some(name) = f.next() else { continue };
            let Some(i) = name
                .strip_prefix("cpu")
                .and_then(|n| n.parse::<usize>().ok())
            else {
                continue;
            };
            // user nice system idle iowait irq softirq steal
            let v: Vec<u64> = f.take(8).map(|v| v.parse().unwrap_or(0)).collect();
            if let (Some(st), Some(irq), true) =
                (s.steal.get_mut(i), s.irq.get_mut(i), v.len() == 8)
            {
                *st = v[7];
                *irq = v[5] + v[6];
            }
        }
    }
    let tid = MEASURED_TID.load(Ordering::Acquire);
    if tid != 0 {
        s.tid = tid;
        if let Ok(st) = std::fs::read_to_string(format!("/proc/self/task/{tid}/schedstat")) {
            let mut f = st.split_whitespace().map(|v| v.parse().unwrap_or(0));
            s.cpu_ns = f.next().unwrap_or(0);
            s.run_delay = f.next().unwrap_or(0);
        }
        if let Ok(st) = std::fs::read_to_string(format!("/proc/self/task/{tid}/stat")) {
            // After the command's closing parenthesis: state is field 3, minflt 10,
            // majflt 12.
            if let Some(rest) = st.rsplit_once(')').map(|(_, r)| r) {
                let f: Vec<u64> = rest
                    .split_whitespace()
                    .map(|v| v.parse().unwrap_or(0))
                    .collect();
                if f.len() > 9 {
                    s.faults = (f[7], f[9]);
                }
            }
        }
    }
    s
}

/// Per kind of chunk (0 reference, 1 engine): the measured thread's CPU time, its
/// run-queue wait and the time they were sampled over, ns.
pub(crate) static USE: [[AtomicU64; 3]; 2] = [Z3, Z3];
#[allow(clippy::declare_interior_mutable_const)]
const Z3: [AtomicU64; 3] = [Z, Z, Z];

/// Polls every [`POLL`] until `done`, sampling `/proc` into `samples`; adds what the
/// measured thread used between the first and the last sample that saw it to
/// `USE[kind]`.
pub(crate) fn poll(kind: usize, samples: &mut Vec<Sample>, done: &dyn Fn() -> bool) {
    let from = samples.len();
    while !done() {
        samples.push(sample());
        std::thread::sleep(POLL);
    }
    samples.push(sample());
    // The first and the last sample that could read the thread (a reference thread
    // has ended by the last poll).
    let seen = |s: &&Sample| s.tid != 0 && s.cpu_ns != 0;
    let (Some(a), Some(b)) = (
        samples[from..].iter().find(seen),
        samples[from..].iter().rev().find(seen),
    ) else {
        return;
    };
    if a.tid == b.tid {
        for (u, v) in
            USE[kind]
                .iter()
                .zip([b.cpu_ns - a.cpu_ns, b.run_delay - a.run_delay, b.t - a.t])
        {
            u.fetch_add(v, Ordering::Relaxed);
        }
    }
}
