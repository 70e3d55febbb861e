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
# One line for all of it, from the compare.json beside each scene's images.
python3 - demo $(./build/raster scenes) <<'SUMMARY'
import json, os, sys
folder, scenes = sys.argv[1], sys.argv[2:]
targets = [(scene, t) for scene in scenes
           for t in json.load(open(os.path.join(folder, scene, "compare.json")))["targets"]]
differing = [f"{scene} {t['name']} (max {t['max_in_unit']} {t['unit']})" for scene, t in targets if t["max_in_unit"]]
print(f"demo: {len(targets) - len(differing)} of {len(targets)} targets of {len(scenes)} scenes bit-identical to llvmpipe"
      + (f"; differing: {', '.join(differing)}" if differing else "") + f"; images in {folder}/SCENE/")
SUMMARY
