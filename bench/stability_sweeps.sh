#!/usr/bin/env bash
# The sweeps STABILITY.md shows: every parameter of every scene driven toward where methods
# fail, each method set and softpipe against llvmpipe. Writes docs/stability/SCENE-PARAM/
# (sweep.json, sweep.md, sweep.png, sweep.svg). About 9 minutes on 2 cores.
# Usage: bench/stability_sweeps.sh [RASTER_BINARY] [ONLY_SCENE]
set -euo pipefail
cd "$(dirname "$0")/.."
raster=${1:-build/raster}
only=${2:-}
common=(--methods gl,fast,precise --size 320x240 --threads 2 --quiet)
sweeps=(
  "shadow light_elevation=1:80:12:log"
  "shadow offset_scale=0:4:9"
  "shadow near=0.1:1e-6:11:log"
  "shadow world_offset=1:1e7:15:log"
  "shadow time=1:1e10:11:log"
  "shadow size=1:8192:10:log --no-softpipe"
  "deferred light_elevation=1:80:10:log"
  "deferred near=0.1:1e-6:11:log"
  "deferred world_offset=1:1e6:13:log"
  "deferred time=1:1e10:11:log"
  "deferred size=1:8192:10:log --no-softpipe"
  "hdr intensity=1:1e6:13:log"
  "hdr instances=1:200000:10:log"
  "hdr near=0.1:1e-6:11:log"
  "hdr world_offset=1:1e7:15:log"
  "hdr time=1:1e10:11:log"
  "hdr size=1:8192:10:log --no-softpipe"
)
mkdir -p docs/stability
for entry in "${sweeps[@]}"; do
  set -- $entry
  scene=$1 param=$2; shift 2
  [ -n "$only" ] && [ "$scene" != "$only" ] && continue
  out="docs/stability/$scene-${param%%=*}"
  echo "== $scene $param $* -> $out" >&2
  start=$SECONDS
  "$raster" sweep "$scene" --param "$param" "${common[@]}" "$@" --out "$out" > /dev/null
  echo "   $((SECONDS - start)) s" >&2
done
