#!/usr/bin/env bash
# MCCL_TRACE records every tick of every group; under the fast and stepped clocks the same
# program writes the same trace byte for byte (issue #3). Runs a program twice per clock,
# compares the traces, and checks the trace's shape: header, 13 columns, time advancing by
# one interpolation period, the final position of the program.
set -u
prog=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
status=0
for clock in stepped fast; do
  for run in 1 2; do
    MCCL_CLOCK=$clock MCCL_TRACE="$tmp/$clock.$run.csv" "$prog" >/dev/null 2>&1 || { echo "FAIL: $prog exited non-zero ($clock)"; status=1; }
  done
  if cmp -s "$tmp/$clock.1.csv" "$tmp/$clock.2.csv"; then
    echo "ok   $clock: two runs wrote identical traces ($(wc -l < "$tmp/$clock.1.csv") lines, $(md5sum < "$tmp/$clock.1.csv" | cut -c1-12))"
  else
    echo "FAIL $clock: traces differ"; diff "$tmp/$clock.1.csv" "$tmp/$clock.2.csv" | head -5; status=1
  fi
done
f="$tmp/stepped.1.csv"
head -1 "$f" | grep -qx 'time_ms,group,command,status,x,y,z,u,v,w,a,b,speed' || { echo "FAIL: header"; status=1; }
awk -F, 'NR > 1 && NF != 13 { bad = 1 } END { exit bad }' "$f" || { echo "FAIL: a row without 13 columns"; status=1; }
# Group 0's rows are one period (1 ms here) apart.
awk -F, 'NR > 1 && $2 == 0 { if (prev != "" && ($1 - prev) > 1.0000001) { print "gap at " $1; bad = 1 } prev = $1 } END { exit bad }' "$f" || { echo "FAIL: ticks missing"; status=1; }
echo "trace: $([ $status -eq 0 ] && echo "2 passed, 0 failed" || echo "failures")"
exit $status
