#!/usr/bin/env bash
# Regenerates the bundled sequences in rawlogs/ with the project's own simulator (deterministic:
# fixed seeds). Usage: scripts/make-rawlogs.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
SIM=${1:-build}/apps/rgbd-simulate
rm -rf rawlogs/*.rawlog rawlogs/*_Images rawlogs/*_groundtruth.txt
# desk_near: textured office corner, the default job of config.ini. Realistic disparity noise
# barely compresses (~0.13 MB of depth per frame), so only this one sequence is bundled; the
# other scene types are rendered on demand: rgbd-simulate --scene TYPE --rawlog OUT.rawlog.
"$SIM" --scene desk --frames 20 --seed 1 --rawlog rawlogs/desk_near.rawlog --images jpg
du -sh rawlogs
