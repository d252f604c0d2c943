#!/usr/bin/env bash
# mccl-trace on a real trace: the GeneralMotion program's trace under the fast
# clock is plotted (SVG, PNG) and reported (HTML) twice with identical bytes; the SVG
# equals the committed picture docs/GeneralMotion.svg (drift check, like the headers);
# diff agrees with itself and finds a 1e-6 UU change; bad input exits 2 with a message.
set -u
prog=$1 tool=$2 committed=$3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
status=0
fail() { echo "FAIL: $*"; status=1; }
MCCL_CLOCK=fast MCCL_TRACE="$tmp/gm.csv" "$prog" >/dev/null 2>&1 || fail "$prog exited non-zero"
for run in 1 2; do
  "$tool" plot "$tmp/gm.csv" -o "$tmp/gm$run.svg" || fail "plot svg"
  "$tool" plot "$tmp/gm.csv" -o "$tmp/gm$run.png" || fail "plot png"
  "$tool" report "$tmp/gm.csv" -o "$tmp/gm$run.html" || fail "report"
done
for f in svg png html; do
  cmp -s "$tmp/gm1.$f" "$tmp/gm2.$f" && echo "ok   $f: same bytes twice" || fail "$f differs between runs"
done
if cmp -s "$tmp/gm1.svg" "$committed"; then
  echo "ok   docs/GeneralMotion.svg is up to date"
else
  fail "docs/GeneralMotion.svg differs from a fresh plot: run 'make docs-image' and commit it"
fi
grep -q '<svg' "$tmp/gm1.html" && ! grep -q 'src="http' "$tmp/gm1.html" || fail "report is not self-contained"
"$tool" diff "$tmp/gm.csv" "$tmp/gm.csv" >/dev/null && echo "ok   diff: a trace agrees with itself" || fail "diff with itself"
# Row 5000 of the trace (group 0), x + 1e-6.
awk -F, 'BEGIN { OFS = "," } NR == 5001 { $5 = sprintf("%.9f", $5 + 0.000001) } { print }' "$tmp/gm.csv" > "$tmp/b.csv"
t=$(awk -F, 'NR == 5001 { print $1 }' "$tmp/gm.csv")
out=$("$tool" diff "$tmp/gm.csv" "$tmp/b.csv"); rc=$?
[ $rc -eq 1 ] && grep -q "first difference: $t ms, group 0, axis x" <<<"$out" \
  && echo "ok   diff: a 1e-6 UU change found at $t ms" || { fail "diff of a changed trace (rc $rc)"; echo "$out"; }
head -c 1000 "$tmp/gm.csv" > "$tmp/trunc.csv"
out=$("$tool" plot "$tmp/trunc.csv" -o "$tmp/x.svg" 2>&1); rc=$?
[ $rc -eq 2 ] && grep -q "truncated line" <<<"$out" && echo "ok   truncated trace: exit 2, $out" || fail "truncated trace: rc $rc: $out"
echo "trace_tool: $([ $status -eq 0 ] && echo "passed" || echo "failures")"
exit $status
