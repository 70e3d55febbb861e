#!/usr/bin/env bash
# Sets everything up (./setup.sh), then renders every scene with this pipeline and with
# real GL (llvmpipe through OSMesa) and compares them target by target. Images land in
# demo/<scene>/: NAME_ours.png, NAME_gl.png and NAME_diff.png for every target, and the
# numbers in compare.json.
set -euo pipefail
cd "$(dirname "$0")"
./setup.sh
mkdir -p demo
for scene in $(./build/raster scenes); do
  ./build/raster compare "$scene" --out "demo/$scene"
done
