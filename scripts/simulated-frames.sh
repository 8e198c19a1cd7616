#!/usr/bin/env bash
# The picture in doc/simulator.md: colour and depth of one frame (the 10th of a sweep) of
# every scene type. Needs ImageMagick. Usage: scripts/simulated-frames.sh [BUILD_DIR] [OUT.jpg]
set -euo pipefail
cd "$(dirname "$0")/.."
SIM=${1:-build}/apps/rgbd-simulate
OUT=${2:-doc/simulated_frames.jpg}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cells=()
for scene in texture structure structure_texture desk wall object; do
  "$SIM" --scene $scene --frames 10 --seed 1 --tum "$TMP/$scene" > /dev/null
  frame=$(ls "$TMP/$scene/rgb" | tail -1)
  # Depth: brighter is farther, black is no depth.
  convert "$TMP/$scene/rgb/$frame" \( "$TMP/$scene/depth/$frame" -auto-level \) +append \
    -resize 50% -font DejaVu-Sans -fill white -undercolor '#00000080' -pointsize 16 -gravity northwest \
    -annotate +6+4 "$scene" "$TMP/cell_$scene.png"
  cells+=("$TMP/cell_$scene.png")
done
convert \( "${cells[0]}" "${cells[1]}" +append \) \( "${cells[2]}" "${cells[3]}" +append \) \
  \( "${cells[4]}" "${cells[5]}" +append \) -append -quality 85 "$OUT"
echo "wrote $OUT"
