#!/usr/bin/env python3
"""The kernel's side of the realtime benchmark's wake-ups, from an ftrace text dump.

Reads the trace `scripts/rt-trace.sh` records (sched and timer events, `mono` trace
clock) while `cargo bench --bench realtime` runs, and follows every wake-up of the two
measured threads (`mccl-engine`, the engine; `reference`, the bare loop) from the
expiry of its sleep's timer to the context switch that runs it:

    expires   the deadline the thread slept to (hrtimer_start's expires)
    irq       the timer interrupt began (local_timer_entry)
    waking    try_to_wake_up began (sched_waking)
    wakeup    the thread is on the run queue (sched_wakeup)
    switch    the CPU switches to it (sched_switch)

Prints, per kind of thread and CPU, the p50/p99 of expires -> switch (the kernel's
share of the lateness the benchmark measures) and of each step; then each chunk (one
thread = one chunk of the benchmark) in time order as <kind><median us>@<cpus>, which
shows the stretches in which one vCPU is served slower than the other.

Usage: scripts/rt-wakeups.py TRACE.txt
"""

import collections
import re
import sys

LINE = re.compile(r"^\s*(.+?)-(\d+)\s+\[(\d+)\]\s+\S+\s+([\d.]+): (\w+): (.*)$")
FIELD = {
    name: re.compile(name + r"=(\S+)")
    for name in ("hrtimer", "expires", "pid", "next_pid")
}
KINDS = {"mccl-engine": "engine", "reference": "reference"}


def kind_of(comm):
    for prefix, kind in KINDS.items():
        if comm.startswith(prefix):
            return kind
    return None


def field(name, rest):
    m = FIELD[name].search(rest)
    return m.group(1) if m else None


def quantile(values, q):
    if not values:
        return 0.0
    v = sorted(values)
    return v[min(len(v) - 1, int(q * len(v)))]


def wakeups(path):
    """Yields (tid, kind, cpu, {step: ns}) for every wake-up of a measured thread."""
    armed = {}  # timer -> (tid, kind, expires ns)
    pending = {}  # tid -> (kind, cpu, steps)
    irq_at = {}  # cpu -> ns of the last timer interrupt
    with open(path, errors="replace") as f:
        for line in f:
            m = LINE.match(line)
            if not m:
                continue
            comm, pid, cpu, ts, event, rest = m.groups()
            t, cpu = round(float(ts) * 1e9), int(cpu)
            if event == "local_timer_entry":
                irq_at[cpu] = t
            elif event == "hrtimer_start" and "function=hrtimer_wakeup" in rest:
                kind = kind_of(comm)
                if kind:
                    armed[field("hrtimer", rest)] = (int(pid), kind, int(field("expires", rest)))
            elif event == "hrtimer_expire_entry":
                timer = armed.pop(field("hrtimer", rest), None)
                if timer:
                    tid, kind, expires = timer
                    steps = {"expires": expires, "irq": irq_at.get(cpu, t)}
                    pending[tid] = (kind, cpu, steps)
            elif event in ("sched_waking", "sched_wakeup"):
                p = pending.get(int(field("pid", rest)))
                if p:
                    p[2][event[len("sched_"):]] = t
            elif event == "sched_switch":
                tid = int(field("next_pid", rest))
                p = pending.pop(tid, None)
                if p:
                    kind, _timer_cpu, steps = p
                    steps["switch"] = t
                    yield tid, kind, cpu, steps


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    per_cpu = collections.defaultdict(lambda: collections.defaultdict(list))
    chunks = collections.OrderedDict()
    order = ["expires", "irq", "waking", "wakeup", "switch"]
    for tid, kind, cpu, steps in wakeups(sys.argv[1]):
        if not all(s in steps for s in order):
            continue
        d = per_cpu[(kind, cpu)]
        d["total"].append((steps["switch"] - steps["expires"]) / 1e3)
        for a, b in zip(order, order[1:]):
            d[f"{a}->{b}"].append((steps[b] - steps[a]) / 1e3)
        chunks.setdefault((tid, kind), []).append((d["total"][-1], cpu))
    print("expires -> switch per kind and CPU, us (p50/p99), and each step of it:")
    for (kind, cpu), d in sorted(per_cpu.items()):
        steps = "  ".join(
            f"{name} {quantile(v, 0.5):.1f}/{quantile(v, 0.99):.1f}"
            for name, v in d.items()
            if name != "total"
        )
        t = d["total"]
        print(
            f"  {kind:9} cpu{cpu} n {len(t):6}  total {quantile(t, 0.5):.1f}/{quantile(t, 0.99):.1f}"
            f"  p99.9 {quantile(t, 0.999):.1f}   {steps}"
        )
    print("chunks in time order (e = engine, r = reference), median us @ CPU:")
    line = []
    for (tid, kind), v in chunks.items():
        if len(v) < 50:
            continue
        cpus = collections.Counter(c for _, c in v).most_common()
        where = "".join(str(c) for c, _ in cpus)
        line.append(f"{kind[0]}{quantile([x for x, _ in v], 0.5):.0f}@{where}")
    for i in range(0, len(line), 12):
        print("  " + " ".join(line[i : i + 12]))


if __name__ == "__main__":
    main()
