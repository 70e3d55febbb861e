#!/usr/bin/env bash
# Sets everything up on a fresh Debian 12 machine: installs the Debian packages the build
# needs (only those missing), configures and builds. Idempotent: a second run only rebuilds
# what changed.
set -euo pipefail
cd "$(dirname "$0")"

packages=(
  build-essential cmake pkg-config
  ninja-build   # the generator of new build folders (below)
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

# New build folders are Ninja's (an existing one keeps the generator it was made with: CMake
# reads CMAKE_GENERATOR only when it creates a folder). Ninja starts an object as soon as
# what it needs is there, where Make waits for each library to finish before the next
# one's objects: the SIMD-off build 132 -> 123 s (docs/notes/2026-12-02-ci-minutes.md).
# test.sh sets the same for the configurations' folders.
if [ -z "${CMAKE_GENERATOR:-}" ] && command -v ninja > /dev/null; then export CMAKE_GENERATOR=Ninja; fi

# RASTER_PGO=1 makes the build profile-guided (GCC; CMakeLists.txt, RASTER_PGO_*): an
# instrumented build renders each scene at two sizes and two times, and once more per size
# with the `fast` method set (whose paths, never run in training, had been laid out as cold
# code), and the release build is compiled by those counts. The profile is made again only
# when a source it was made from has changed. Not the default: on the AMD EPYC Zen 4 host
# the plain build ran every scene as fast or faster (shadow and deferred 4-7% faster
# without it at 640x480: docs/notes/2026-11-30-profile-guided-build.md).
pgo=(-DRASTER_PGO_USE=) renewed=0
if [ "${RASTER_PGO:-0}" = 1 ] && "${CXX:-c++}" -v 2>&1 | grep -q "^gcc version"; then
  profile="$PWD/build-pgo/profile"
  sources=$(find raster scenes shaders_cpp apps cmake CMakeLists.txt setup.sh -type f | LC_ALL=C sort | xargs sha256sum | sha256sum)
  if [ "$(cat "$profile.sources" 2>/dev/null)" != "$sources" ]; then
    echo "setup: profiling an instrumented build (build-pgo/) for the optimized one"
    cmake -S . -B build-pgo/instrumented -DCMAKE_BUILD_TYPE=Release -DRASTER_PGO_GENERATE="$profile" > /dev/null
    cmake --build build-pgo/instrumented -j"$(nproc)" --target raster_cli
    rm -rf "$profile" build-pgo/train && mkdir -p build-pgo/train
    for scene in $(build-pgo/instrumented/raster scenes); do
      for size in 640x480 1920x1080; do
        for time in 1 7.3; do
          build-pgo/instrumented/raster render "$scene" --size "$size" --time "$time" --threads 2 --quiet \
            --out "build-pgo/train/$scene-$size-$time.png" > /dev/null
        done
        build-pgo/instrumented/raster render "$scene" --size "$size" --time 1 --threads 2 --preset fast --quiet \
          --out "build-pgo/train/$scene-$size-fast.png" > /dev/null
      done
    done
    # The objects that take the profile are compiled again, by the new counts.
    find build/CMakeFiles/raster.dir build/CMakeFiles/scenes.dir build/CMakeFiles/cli.dir build/CMakeFiles/raster_cli.dir \
      -name '*.o' -delete 2>/dev/null || true
    renewed=1
  fi
  pgo=(-DRASTER_PGO_USE="$profile")
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${pgo[@]}" > /dev/null
cmake --build build -j"$(nproc)"
# Marked current only once the build made from it is whole: an interrupted run starts over.
if [ "$renewed" = 1 ]; then echo "$sources" > "$profile.sources"; fi
