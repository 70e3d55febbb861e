#!/usr/bin/env bash
# The sweeps STABILITY.md shows: every parameter of every scene driven toward where methods
# fail, each method set and softpipe against llvmpipe, and where coarse shading fails, its
# rates against llvmpipe. Both are columns of each scene's registry row (`raster scenes
# --json`: `sweeps`, `coarse_sweeps`). Writes docs/stability/SCENE-PARAM/ and
# docs/stability/coarse-SCENE-PARAM/ (sweep.json, sweep.md, sweep.png, sweep.svg). About 25
# minutes on 2 cores for the four scenes of today.
# Usage: bench/stability_sweeps.sh [--dry-run] [RASTER_BINARY] [ONLY_SCENE]
#   --dry-run prints the `raster sweep` command lines and runs none.
set -euo pipefail
cd "$(dirname "$0")/.."
dry=0
if [ "${1:-}" = --dry-run ]; then dry=1; shift; fi
raster=${1:-build/raster}
only=${2:-}
# One line per sweep: KIND SCENE PARAM=RANGE [OPTIONS...], read from the registry.
sweeps=$("$raster" scenes --json | /usr/bin/python3 -c '
import json, sys
for row in json.load(sys.stdin):
    for kind, column in (("methods", "sweeps"), ("coarse", "coarse_sweeps")):
        for sweep in row[column]:
            print(kind, row["name"], sweep)')
if [ -n "$only" ] && ! grep -q "^[a-z]* $only " <<< "$sweeps"; then
  echo "stability_sweeps: no sweeps for scene '$only' (scenes: $("$raster" scenes | tr '\n' ' '))" >&2
  exit 2
fi
[ "$dry" = 1 ] || mkdir -p docs/stability
while read -r kind scene param options; do
  [ -n "$only" ] && [ "$scene" != "$only" ] && continue
  if [ "$kind" = coarse ]; then
    # Each coarse sweep names its rates (--methods in its options); softpipe has no coarse
    # shading to compare, so it is left out.
    out="docs/stability/coarse-$scene-${param%%=*}"
    common=(--size 320x240 --threads 2 --quiet --no-softpipe)
  else
    out="docs/stability/$scene-${param%%=*}"
    common=(--methods gl,fast,precise,draft --size 320x240 --threads 2 --quiet)
  fi
  # shellcheck disable=SC2086  # the options are words
  command=("$raster" sweep "$scene" --param "$param" "${common[@]}" $options --out "$out")
  if [ "$dry" = 1 ]; then
    echo "${command[*]}"
    continue
  fi
  echo "== $kind: $scene $param $options -> $out" >&2
  start=$SECONDS
  "${command[@]}" > /dev/null
  echo "   $((SECONDS - start)) s" >&2
done <<< "$sweeps"
