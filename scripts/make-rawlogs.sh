#!/usr/bin/env bash
# Regenerates the bundled sequences in rawlogs/ with the project's own simulator (deterministic:
# fixed seeds). Usage: scripts/make-rawlogs.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
SIM=${1:-build}/apps/rgbd-simulate
rm -rf rawlogs/*.rawlog rawlogs/*_Images rawlogs/*_groundtruth.txt
# Realistic disparity noise barely compresses (~0.13 MB of depth per frame), so two sequences are
# bundled; the other scene types are rendered on demand (about 8 frames/s):
#   rgbd-simulate --scene TYPE [--far] --rawlog OUT.rawlog
# desk_near: textured office corner, the default job of config.ini.
"$SIM" --scene desk --frames 20 --seed 1 --rawlog rawlogs/desk_near.rawlog --images jpg
# structure_near: plain zig-zag panels (fr3 structure_notexture): the geometric path's case.
"$SIM" --scene structure --frames 15 --seed 1 --rawlog rawlogs/structure_near.rawlog --images jpg
du -sh rawlogs
