#!/usr/bin/env bash
# Sets everything up (./setup.sh), then runs the whole test suite through ctest, then each
# extra configuration CI checks (tests/configs/*.sh: each builds its own folder and runs
# its part of the suite there). Each step's minutes are printed as it ends, and all of them,
# with the run's total, at the end (CONTRIBUTING.md quotes them).
set -euo pipefail
cd "$(dirname "$0")"
timings=()
step() {   # step NAME COMMAND...: runs it and records its minutes
  local name=$1 start=$SECONDS
  shift
  echo "== $name"
  "$@"
  timings+=("$name $(( (SECONDS - start) / 60 )) min $(( (SECONDS - start) % 60 )) s")
  echo "== $name took ${timings[-1]#"$name "}"
}
step setup ./setup.sh
# The configurations' build folders are Ninja's where a new one is made (setup.sh says why).
if [ -z "${CMAKE_GENERATOR:-}" ] && command -v ninja > /dev/null; then export CMAKE_GENERATOR=Ninja; fi
step release ctest --test-dir build --output-on-failure -j"$(nproc)"
for config in tests/configs/*.sh; do
  step "$(basename "$config" .sh)" "$config"
done
echo "== minutes per step:"
printf '   %s\n' "${timings[@]}"
echo "   total $(( SECONDS / 60 )) min $(( SECONDS % 60 )) s"
