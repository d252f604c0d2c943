//! Where the measured threads run: each pair of chunks pinned to one of the CPUs the
//! process may use, in turn, unless the program or `MCCL_RT_BENCH_PIN=0` says otherwise.

/// How the measured threads are placed: `None` when each pair is pinned by
/// [`pair_cpu`]; `Some(why)` when they are not (the program's own `MCCL_RT_CPU`, or
/// `MCCL_RT_BENCH_PIN=0`).
pub(crate) fn placement() -> &'static Option<String> {
    static P: std::sync::OnceLock<Option<String>> = std::sync::OnceLock::new();
    P.get_or_init(|| {
        if let Ok(cpu) = std::env::var("MCCL_RT_CPU") {
            Some(format!("MCCL_RT_CPU={cpu} set: every chunk runs there"))
        } else if std::env::var("MCCL_RT_BENCH_PIN").as_deref() == Ok("0") {
            Some("MCCL_RT_BENCH_PIN=0: the threads run where the kernel puts them".into())
        } else {
            None
        }
    })
}

/// The CPUs this process may run on, read before any thread is pinned.
pub(crate) fn allowed_cpus() -> &'static [usize] {
    static CPUS_ALLOWED: std::sync::OnceLock<Vec<usize>> = std::sync::OnceLock::new();
    CPUS_ALLOWED.get_or_init(|| {
        // SAFETY: a zeroed cpu_set_t is a valid empty set; pid 0 is the calling thread,
        // and the set is only read after the call filled it.
        let v: Vec<usize> = unsafe {
            let mut set: libc::cpu_set_t = std::mem::zeroed();
            if libc::sched_getaffinity(0, std::mem::size_of::<libc::cpu_set_t>(), &mut set) != 0 {
                return Vec::new();
            }
            (0..libc::CPU_SETSIZE as usize)
                .filter(|&c| libc::CPU_ISSET(c, &set))
                .collect()
        };
        v
    })
}

/// The CPU both chunks of `pair` are pinned to (`MCCL_RT_CPU`, which the reference
/// thread and the engine thread both apply), or `None` when the bench does not pin.
/// Pairs 0 and 1 run on the first allowed CPU, 2 and 3 on the next, and so on around:
/// each CPU gets as many reference-first pairs as engine-first ones, and every engine
/// chunk is compared with reference chunks on the same CPU within a second of it.
pub(crate) fn pair_cpu(pair: usize) -> Option<usize> {
    if placement().is_some() {
        return None;
    }
    let cpus = allowed_cpus();
    cpus.get((pair / 2) % cpus.len().max(1)).copied()
}
