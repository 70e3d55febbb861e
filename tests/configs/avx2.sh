#!/usr/bin/env bash
# The AVX2 build without AVX-512 (-DRASTER_AVX512=OFF), on a host that has AVX-512: what a
# machine without it (most desktops, AMD before Zen 4) runs. The default build asks the CPU
# (RASTER_AVX512=AUTO, CMakeLists.txt), so on an AVX-512 host every other configuration
# here compiles the *_avx512 siblings and Float8x2 in one 512-bit register, and the AVX2
# forms they replace would go unchecked; this one holds those forms' bytes to llvmpipe's.
# On a host without AVX-512 the default build already is this one, and on one without AVX2
# it cannot run: either way it is skipped.
#
# The suites whose bytes depend on the lane code: the four scenes' (every target against
# llvmpipe), the feature and method suites, the SIMD and math suites (not determinism's: how
# a frame is split over threads is the same code under every lane type, and the release and
# sanitizer configurations run it). Only their sources are compiled
# (RASTER_TEST_SUITES_ONLY), at -O1 as in the SIMD-off configuration (the same bits at any
# level). The command line is not built, and the cases of these suites that run it are left
# out (below): what they check does not depend on the lane code. They are softpipe's renders
# of each scene, for scale (13 of the suites' 23 seconds on two cores; the distance to
# llvmpipe they bound is zero in the cases kept), and the refusals of bad assets and
# options; the release and sanitizer configurations run both. A case added to these suites
# that runs the program fails here on the missing program, not silently. About a minute and
# a half on two cores.
set -euo pipefail
cd "$(dirname "$0")/../.."
flags=$(grep -m1 '^flags' /proc/cpuinfo 2>/dev/null || true)
if ! grep -qw avx2 <<< "$flags"; then
  echo "skipped: this CPU has no AVX2"
  exit 0
fi
for subset in avx512f avx512vl avx512bw avx512dq; do   # what RASTER_AVX512=AUTO asks for
  if ! grep -qw "$subset" <<< "$flags"; then
    echo "skipped: this CPU has no ${subset}, so the default build (release) already runs the AVX2 forms"
    exit 0
  fi
done
cmake -S . -B build-avx2 -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -DNDEBUG" -DRASTER_AVX512=OFF \
  -DRASTER_TEST_SUITES_ONLY="scene_shadow;scene_deferred;scene_hdr;scene_pbr;raster_vs_gl;hdr_features;shadow_compare;clears;texture;format;derivatives;geometry;shaders;simd;gl_math;math_methods;methods;shading_rate" \
  > /dev/null
cmake --build build-avx2 -j"$(nproc)" --target raster_tests
export RASTER_TEST_CASE_EXCLUDE="*softpipe*,a missing or corrupt asset stops the render*,a split order that cannot work*"
ctest --test-dir build-avx2 --output-on-failure -j"$(nproc)"
