#!/usr/bin/env bash
# make mc3b-demo: mc3b-app against mc3b-emu (an emulated MC3B) on a pseudo-terminal.
# Prints the page's address. Lines typed here go to the emulator's control channel
# (`input 0 1` puts limit input 0 at +5 V; `pos` shows its step counters; see
# mc3b-emu --help). Ctrl-C (or end of input) ends both: the application first turns the
# motors off.
#   scripts/mc3b-demo.sh BIN_DIR    (BIN_DIR holds mc3b-app and mc3b-emu)
set -euo pipefail
bin=${1:-build/cargo/release}
for exe in mc3b-app mc3b-emu; do
  [ -x "$bin/$exe" ] || { echo "mc3b-demo: $bin/$exe missing (make build)"; exit 1; }
done
dir=$(mktemp -d)
mkfifo "$dir/ctl" "$dir/out"
emu="" app="" answers=""
cleanup() {
  [ -n "$app" ] && kill -TERM "$app" 2>/dev/null && wait "$app" 2>/dev/null
  [ -n "$emu" ] && kill "$emu" 2>/dev/null
  [ -n "$answers" ] && kill "$answers" 2>/dev/null
  rm -rf "$dir"
}
trap cleanup EXIT
trap 'exit 130' INT TERM
# Background jobs of a script ignore Ctrl-C: the emulator outlives the application,
# which catches it and turns the motors off first.
"$bin/mc3b-emu" <"$dir/ctl" >"$dir/out" &
emu=$!
exec 3>"$dir/ctl"              # the emulator's control channel, open while we run
exec 4<"$dir/out"
read -r path <&4
cat <&4 &                      # the emulator's answers
answers=$!
echo "mc3b-demo: an emulated MC3B is on $path"
"$bin/mc3b-app" --port "$path" &
app=$!
echo "mc3b-demo: type emulator commands here (input 0 1, inputs 37, pos, velocity; mc3b-emu --help); Ctrl-C ends"
if [ -t 0 ]; then
  while IFS= read -r line; do printf '%s\n' "$line" >&3; done
else
  wait "$app"
fi
