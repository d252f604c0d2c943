#!/usr/bin/env bash
# Every example program prints the same and exits the same with cruise ticks (the default)
# and without (MCCL_CRUISE=0), on the fast and the stepped clock: cruise ticks only skip
# work (src/engine/cruise.rs). The examples assert positions, statuses and times of their
# own, so what they print covers what they see.
#   cruise_same.sh <c-tests build dir> <c-tests source dir>
set -u
bin=$1; src=$2
fails=0; runs=0
for example in "$src"/examples/*.cpp; do
  name=$(basename "$example" .cpp)
  prog="$bin/$name"
  [ -x "$prog" ] || continue
  # The machines CTest runs these programs on.
  case $name in
    GoHome) sim=$src/sim/home_x.toml ;;
    InPosCheck|PCLControl) sim=$src/sim/lag_x.toml ;;
    *) sim= ;;
  esac
  for clock in fast stepped; do
    without=$(MCCL_SIM=$sim MCCL_CLOCK=$clock MCCL_CRUISE=0 timeout 120 "$prog" 2>&1; echo "exit=$?")
    with=$(MCCL_SIM=$sim MCCL_CLOCK=$clock MCCL_CRUISE=1 timeout 120 "$prog" 2>&1; echo "exit=$?")
    runs=$((runs + 1))
    if [ "$without" != "$with" ]; then
      echo "DIFFERENT: $name ($clock)"
      diff <(echo "$without") <(echo "$with") | head -20
      fails=$((fails + 1))
    fi
  done
done
echo "$runs runs compared, $fails different"
[ "$runs" -gt 40 ] && [ "$fails" -eq 0 ]
