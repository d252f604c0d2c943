#!/usr/bin/env bash
# MCCL_TRACE records every tick of every group; under the fast and stepped clocks the same
# program writes the same trace byte for byte. Runs a program twice per clock,
# compares the traces, and checks the trace's shape: header, 13 columns, time advancing by
# one interpolation period, the final position of the program; and the same for the events
# file beside it (path.events.csv), whose command events must match the trace's rows.
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
  if cmp -s "$tmp/$clock.1.events.csv" "$tmp/$clock.2.events.csv"; then
    echo "ok   $clock: two runs wrote identical events ($(wc -l < "$tmp/$clock.1.events.csv") lines)"
  else
    echo "FAIL $clock: events differ"; diff "$tmp/$clock.1.events.csv" "$tmp/$clock.2.events.csv" | head -5; status=1
  fi
done
f="$tmp/stepped.1.csv"
head -1 "$f" | grep -qx 'time_ms,group,command,status,x,y,z,u,v,w,a,b,speed' || { echo "FAIL: header"; status=1; }
awk -F, 'NR > 1 && NF != 13 { bad = 1 } END { exit bad }' "$f" || { echo "FAIL: a row without 13 columns"; status=1; }
# Group 0's rows are one period (1 ms here) apart.
awk -F, 'NR > 1 && $2 == 0 { if (prev != "" && ($1 - prev) > 1.0000001) { print "gap at " $1; bad = 1 } prev = $1 } END { exit bad }' "$f" || { echo "FAIL: ticks missing"; status=1; }
e="$tmp/stepped.1.events.csv"
head -1 "$e" | grep -qx 'time_ms,card,group,kind,detail' || { echo "FAIL: events header"; status=1; }
awk -F, 'NR > 1 && NF != 5 { bad = 1 } END { exit bad }' "$e" || { echo "FAIL: an event without 5 columns"; status=1; }
# Every cmd_start is at a tick whose trace row of that group runs that command.
awk -F, 'FNR == 1 { file++ ; next }
  file == 1 { cmd[$1 "," $2] = $3; next }
  $4 == "cmd_start" { split($5, kv, /[ =]/); k = $1 "," $3
    if (cmd[k] != kv[2]) { print "event " $0 " but the trace runs " cmd[k]; bad = 1 } n++ }
  END { if (n < 7) { print "only " n " command events"; bad = 1 } exit bad }' "$f" "$e" \
  || { echo "FAIL: command events do not match the trace"; status=1; }
echo "trace: $([ $status -eq 0 ] && echo "5 passed, 0 failed" || echo "failures")"
exit $status
