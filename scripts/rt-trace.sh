#!/usr/bin/env bash
# Runs cases of the realtime benchmark while the kernel traces scheduling and timer
# events, then shows the kernel's side of every measured wake-up (scripts/rt-wakeups.py).
#
#   scripts/rt-trace.sh [CASE] [OUT]     e.g. scripts/rt-trace.sh fifo-1ms-load /tmp/rt
#
# Needs root and tracefs (mounted here if it is not). Writes OUT/bench.txt (the
# benchmark's output), OUT/trace.txt (the raw trace, ~40 MB a case) and prints the
# summary. Tracing adds ~1-2 us to each wake-up, to both kinds of thread alike.
set -euo pipefail
case_name="${1:-fifo-1ms-load}"
out="${2:-/tmp/mccl-rt-trace}"
here="$(cd "$(dirname "$0")/.." && pwd)"
tr=/sys/kernel/tracing
[ -e "$tr/trace" ] || mount -t tracefs nodev "$tr"
mkdir -p "$out"
(cd "$here" && cargo bench --bench realtime --no-run -q)
bench="$(ls -t "$here"/target/release/deps/realtime-* | grep -v '\.d$' | head -1)"

echo 0 >"$tr/tracing_on"
echo mono >"$tr/trace_clock"
echo 65536 >"$tr/buffer_size_kb"
: >"$tr/set_event"
for e in sched:sched_switch sched:sched_waking sched:sched_wakeup \
    timer:hrtimer_start timer:hrtimer_expire_entry \
    irq_vectors:local_timer_entry irq_vectors:local_timer_exit; do
    echo "$e" >>"$tr/set_event"
done
: >"$tr/trace"
echo 1 >"$tr/tracing_on"
status=0
"$bench" --bench "$case_name" >"$out/bench.txt" 2>&1 || status=$?
echo 0 >"$tr/tracing_on"
cat "$tr/trace" >"$out/trace.txt"
: >"$tr/set_event"
: >"$tr/trace"
grep -E "ratio p99:|each block|by CPU" "$out/bench.txt" || true
python3 "$here/scripts/rt-wakeups.py" "$out/trace.txt"
exit "$status"
