#!/usr/bin/env bash
# The sweeps STABILITY.md shows: every parameter of every scene driven toward where methods
# fail, each method set and softpipe against llvmpipe. The sweeps are the `sweeps` column of
# each scene's registry row (`raster scenes --json`). Writes docs/stability/SCENE-PARAM/
# (sweep.json, sweep.md, sweep.png, sweep.svg). About 9 minutes on 2 cores for the three
# scenes of today.
# Usage: bench/stability_sweeps.sh [--dry-run] [RASTER_BINARY] [ONLY_SCENE]
#   --dry-run prints the `raster sweep` command lines and runs none.
set -euo pipefail
cd "$(dirname "$0")/.."
dry=0
if [ "${1:-}" = --dry-run ]; then dry=1; shift; fi
raster=${1:-build/raster}
only=${2:-}
common=(--methods gl,fast,precise --size 320x240 --threads 2 --quiet)
# One line per sweep: SCENE PARAM=RANGE [OPTIONS...], read from the registry.
sweeps=$("$raster" scenes --json | /usr/bin/python3 -c '
import json, sys
for row in json.load(sys.stdin):
    for sweep in row["sweeps"]:
        print(row["name"], sweep)')
if [ -n "$only" ] && ! grep -q "^$only " <<< "$sweeps"; then
  echo "stability_sweeps: no sweeps for scene '$only' (scenes: $("$raster" scenes | tr '\n' ' '))" >&2
  exit 2
fi
[ "$dry" = 1 ] || mkdir -p docs/stability
while read -r scene param options; do
  [ -n "$only" ] && [ "$scene" != "$only" ] && continue
  out="docs/stability/$scene-${param%%=*}"
  # shellcheck disable=SC2086  # the options are words
  command=("$raster" sweep "$scene" --param "$param" "${common[@]}" $options --out "$out")
  if [ "$dry" = 1 ]; then
    echo "${command[*]}"
    continue
  fi
  echo "== $scene $param $options -> $out" >&2
  start=$SECONDS
  "${command[@]}" > /dev/null
  echo "   $((SECONDS - start)) s" >&2
done <<< "$sweeps"
# Where coarse shading fails (issue 68; STABILITY.md, "Coarse shading"): the rates against
# llvmpipe, into docs/stability/coarse-SCENE-PARAM/. Edges: hdr's cubes under a coarse
# bright pass and bloom chain; texture frequency: deferred's cat under a coarse G-buffer.
coarse_sweeps="hdr instances=10:100000:5:log --methods gl,shading=2x1,shading=1x2,shading=2x2
deferred uv_scale=0.25:64:5:log --methods gl,shading=2x2,shading=2x2-all"
while read -r scene param options; do
  [ -n "$only" ] && [ "$scene" != "$only" ] && continue
  out="docs/stability/coarse-$scene-${param%%=*}"
  # shellcheck disable=SC2086  # the options are words
  command=("$raster" sweep "$scene" --param "$param" --size 320x240 --threads 2 --quiet --no-softpipe $options --out "$out")
  if [ "$dry" = 1 ]; then
    echo "${command[*]}"
    continue
  fi
  echo "== coarse: $scene $param $options -> $out" >&2
  start=$SECONDS
  "${command[@]}" > /dev/null
  echo "   $((SECONDS - start)) s" >&2
done <<< "$coarse_sweeps"
