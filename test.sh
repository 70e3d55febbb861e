#!/usr/bin/env bash
# Sets everything up (./setup.sh), then runs the whole test suite through ctest, then each
# extra configuration CI checks (tests/configs/*.sh: each builds its own folder and runs
# its part of the suite there).
set -euo pipefail
cd "$(dirname "$0")"
./setup.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
for config in tests/configs/*.sh; do
  echo "== configuration $(basename "$config" .sh)"
  "$config"
done
