#!/usr/bin/env bash
# Runs every odometry method on the bundled rawlogs and the real folders in ../shared/data/real/
# and writes the trajectories plus their md5 sums to OUT_DIR (default: trajectory-digest/).
# A refactor that must not change behaviour is checked by diffing the digests before and after:
#   bash scripts/trajectory-digest.sh /tmp/before   (old build)
#   bash scripts/trajectory-digest.sh /tmp/after    (new build)
#   diff /tmp/before/md5.txt /tmp/after/md5.txt
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${1:-trajectory-digest}
BIN=${BIN:-build/apps/hybrid-rgbd-odometry}
METHODS=${METHODS:-"hybrid rgb_only depth_only ransac ransac_icp opencv_rgbd opencv_icp opencv_rgbd_icp open3d_color open3d_hybrid"}
# Open3D sums its OpenMP threads' partial results in whatever order they finish: repeatable on one
# thread only.
export OMP_NUM_THREADS=1
mkdir -p "$OUT"
inputs=(rawlogs/*.rawlog)
if [ -d ../shared/data/real ]; then
  for d in ../shared/data/real/*/; do inputs+=("${d%/}"); done
else
  echo "trajectory-digest: ../shared/data/real not found; bundled rawlogs only" >&2
fi
# An empty INI: built-in defaults, no [Playback] outputs written next to config.ini.
: > "$OUT/empty.ini"
for in in "${inputs[@]}"; do
  name=$(basename "$in" .rawlog)
  for m in $METHODS; do
    if ! "$BIN" -c "$OUT/empty.ini" -i "$in" -t "$OUT/$name.$m.txt" --method "$m" -q \
      > "$OUT/$name.$m.log" 2>&1; then
      echo "exit $?" >> "$OUT/$name.$m.log"
    fi
  done
done
(cd "$OUT" && md5sum -- *.txt) > "$OUT/md5.txt"
echo "trajectory-digest: $(wc -l < "$OUT/md5.txt") trajectories in $OUT/md5.txt"
