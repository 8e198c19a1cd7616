#!/usr/bin/env bash
# Realism check of the simulator: OpenCV's dense peers and our hybrid odometry, frame to frame,
# on the real TUM fr3/teddy frames and on simulated sequences that replay the same real
# motion: the desk scene and the teddy-like "object" scene; and the 9 real fr1/desk frames against
# the desk scene replaying fr1/desk's motion. Prints the aligned ATE and RPE tables.
# Usage: scripts/realism-check.sh [BUILD_DIR] [WORK_DIR]   (~4 min on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=$(realpath "${1:-build}")
WORK=$(realpath -m "${2:-realism}")
TEDDY=$(realpath -m ../shared/data/real/tum_fr3_teddy_200frames)
DESK=$(realpath -m ../shared/data/real/tum_fr1_desk_9frames)
DESK_MOTION=$(realpath -m ../shared/data/trajectories/fr1_desk_groundtruth_per_rgb_frame.txt)
if [ ! -f "$TEDDY/groundtruth.txt" ]; then
  echo "realism-check: $TEDDY is missing (the real TUM frames in ../shared/data); nothing to compare" >&2
  exit 2
fi
mkdir -p "$WORK"
# 193 frames: the teddy frames that have ground truth (the first 4 precede it).
for scene in desk object; do
  "$BUILD/apps/rgbd-simulate" --scene $scene --frames 193 --seed 1 --motion "$TEDDY/groundtruth.txt" \
    --rawlog "$WORK/${scene}_teddy_motion.rawlog" --images png
done
"$BUILD/apps/rgbd-simulate" --scene desk --frames 9 --seed 1 --motion "$DESK_MOTION" \
  --rawlog "$WORK/desk_fr1_desk_motion.rawlog" --images png
cat > "$WORK/realism.ini" <<EOT
[Benchmark]
methods = hybrid opencv_rgbd opencv_icp opencv_rgbd_icp
sim_scenes =
sim_far = false
sim_motions = sweep
sim_frames = 30
sim_seed = 1
real_sequences = $TEDDY $WORK/desk_teddy_motion.rawlog $WORK/object_teddy_motion.rawlog $DESK $WORK/desk_fr1_desk_motion.rawlog
max_frames = 0
cache_folder = $WORK/cache
output_folder = $WORK/results
EOT
"$BUILD/apps/rgbd-benchmark" -c "$WORK/realism.ini" > "$WORK/benchmark.log"
awk '/^## /{show = /after rigid alignment|RPE rotation/} show && !/average/' "$WORK/results/results.md"
echo "full tables: $WORK/results/results.md"
