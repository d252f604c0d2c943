//! The calling thread: the CPU it runs on, its id, its scheduling policy.

/// The CPU the calling thread runs on (vDSO, no system call on x86-64).
pub(crate) fn cpu() -> i32 {
    // SAFETY: no arguments, no memory touched.
    unsafe { libc::sched_getcpu() }
}

pub(crate) fn gettid() -> i32 {
    // SAFETY: no arguments.
    unsafe { libc::gettid() }
}

/// Sets the calling thread's scheduling policy; whether it was allowed.
pub(crate) fn set_policy(policy: libc::c_int, prio: libc::c_int) -> bool {
    let p = libc::sched_param {
        sched_priority: prio,
    };
    // SAFETY: the calling thread and a valid sched_param.
    unsafe { libc::pthread_setschedparam(libc::pthread_self(), policy, &p) == 0 }
}
