#!/usr/bin/env bash
# MCCL_SIM: a good file is honoured; a malformed one makes MCC_InitSystem fail with a
# message naming the file, the line and the key.
set -u
prog=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
status=0
cat > "$tmp/good.toml" <<'TOML'
[[card]]
index = 0
[[card.channel]]
index = 0
limit_plus = 3.0
[[card.channel]]
index = 1
home = [-1.0, 1.0]
[[card.channel]]
index = 2
plant = { lag_ms = 20.0 }
TOML
MCCL_SIM="$tmp/good.toml" "$prog" good || status=1
cat > "$tmp/machine.toml" <<'TOML'
[[card]]
index = 0
[[card.channel]]
index = 0
lmit_plus = 3.0
TOML
out=$(MCCL_SIM="$tmp/machine.toml" "$prog" bad 2>&1) || status=1
echo "$out"
echo "$out" | grep -q 'machine.toml:5: unknown key "lmit_plus"' || { echo "FAIL: message does not name file, line and key"; status=1; }
cat > "$tmp/machine.toml" <<'TOML'
[[card]]
index = 0
[[card.channel]]
index = 0
limit_plus = 3.0
limit_minus = 5.0
TOML
out=$(MCCL_SIM="$tmp/machine.toml" "$prog" bad 2>&1) || status=1
echo "$out" | grep -q 'machine.toml:6: card\[0\].channel\[0\].limit_minus' || { echo "FAIL: impossible value not named"; echo "$out"; status=1; }
out=$(MCCL_SIM="$tmp/missing.toml" "$prog" bad 2>&1) || status=1
echo "$out" | grep -q 'missing.toml' || { echo "FAIL: missing file not named"; status=1; }
echo "sim_config: $([ $status -eq 0 ] && echo "4 passed, 0 failed" || echo failures)"
exit $status
