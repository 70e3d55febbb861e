#!/usr/bin/env bash
# Sets everything up (./setup.sh), then runs the whole test suite through ctest.
set -euo pipefail
cd "$(dirname "$0")"
./setup.sh
ctest --test-dir build --output-on-failure
