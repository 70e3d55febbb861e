#!/usr/bin/env bash
# Sets everything up on a fresh Debian 12 machine: installs the Debian packages the build
# needs (only those missing), configures and builds. Idempotent: a second run only rebuilds
# what changed.
set -euo pipefail
cd "$(dirname "$0")"

packages=(
  build-essential cmake pkg-config
  libglm-dev libstb-dev libtinyobjloader-dev libtbb-dev doctest-dev libcli11-dev nlohmann-json3-dev libssl-dev
  libopenexr-dev openexr   # OpenEXR dumps, and exrheader (the cli tests read the dumps with it)
  libosmesa6-dev mesa-common-dev libgl-dev
  python3-matplotlib
  python3-distributed        # bench/dask_sweep.py: sweeps sharded on a Dask cluster
  chromium chromium-driver python3-selenium   # the report_chromium test opens `raster report` in a browser
  libbenchmark-dev           # bench/micro: the microbenchmarks (raster_micro)
  clang libclang-rt-14-dev   # libFuzzer and the sanitizer runtimes for clang (tests/configs/fuzz.sh)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j"$(nproc)"
