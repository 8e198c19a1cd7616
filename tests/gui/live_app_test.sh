#!/bin/bash
# Drives rgbd-live over the bundled desk sequence under Xvfb, takes a screenshot of the real
# window (xwd; MRPT's own capture is black under Xvfb) and checks that the map, the image inset
# and the saved map are there. Exit 77 = skipped (no Xvfb).
# Usage: live_app_test.sh <rgbd-live> <source dir> <output dir>
set -euo pipefail
app=$1 src=$2 out=$3
for tool in xvfb-run xwd convert; do
  command -v $tool > /dev/null || { echo "SKIP: $tool not installed (scripts/install-deps.sh)"; exit 77; }
done
rm -rf "$out" && mkdir -p "$out"
cat > "$out/inner.sh" <<INNER
set -e
"$app" -c "$src/config.ini" -i "$src/rawlogs/desk_near.rawlog" --rate 0 --hold 4 \
  --save-prefix "$out/live_" > "$out/live.log" 2>&1 &
pid=\$!
for i in \$(seq 1 120); do grep -q '^finished' "$out/live.log" && break; sleep 0.5; done
sleep 1.5
xwd -root -silent | convert xwd:- "$out/screenshot.png"
wait \$pid
INNER
xvfb-run -a -s "-screen 0 1280x800x24" bash "$out/inner.sh"
cat "$out/live.log"
grep -q '^finished: 20 frames' "$out/live.log" || { echo "FAIL: the app did not process 20 frames"; exit 1; }
# Its log in a file: whole lines, no carriage returns; the SLAM mode's last steps timed.
if grep -q $'\r' "$out/live.log"; then echo "FAIL: carriage returns in the log file"; exit 1; fi
grep -Eq '^SLAM: last loop searches and final optimisation \.\.\. [0-9.]+ s$' "$out/live.log" ||
  { echo "FAIL: no timed line for the SLAM mode's last steps"; exit 1; }
# The 3D view right of the image inset and below the text: a drawn coloured map has thousands
# of colours (measured 5,163); the empty grid has about 150.
view=$(convert "$out/screenshot.png" -crop 690x400+330+70 +repage -format "%k" info:)
inset=$(convert "$out/screenshot.png" -crop 300x220+12+495 +repage -format "%k" info:)
echo "colours: 3D view $view, image inset $inset"
[ "$view" -gt 1000 ] || { echo "FAIL: no map drawn in the 3D view"; exit 1; }
[ "$inset" -gt 1000 ] || { echo "FAIL: no colour image in the inset"; exit 1; }
points=$(grep -a -m1 '^element vertex' "$out/live_map.ply" | cut -d' ' -f3)
[ "$points" -gt 5000 ] || { echo "FAIL: saved map has $points points"; exit 1; }
echo "PASS: map drawn, inset drawn, $points points saved"

# The recording played as a sensor: every frame either tracked or counted as dropped.
cat > "$out/realtime.sh" <<INNER
"$app" -c "$src/config.ini" -i "$src/rawlogs/desk_near.rawlog" --realtime --no-slam --hold 0 \
  --save-prefix "$out/realtime_" > "$out/realtime.log" 2>&1
INNER
xvfb-run -a -s "-screen 0 1280x800x24" bash "$out/realtime.sh"
cat "$out/realtime.log"
tracked=$(sed -n 's/^finished: \([0-9]*\) frames.*/\1/p' "$out/realtime.log")
dropped=$(sed -n 's/^finished: .*, \([0-9]*\) dropped.*/\1/p' "$out/realtime.log")
[ "$((${tracked:-0} + ${dropped:-99}))" -eq 20 ] ||
  { echo "FAIL: played as a sensor, $tracked tracked + $dropped dropped is not 20"; exit 1; }
echo "PASS: played as a sensor, $tracked frames tracked, $dropped dropped"

# SLAM mode on real frames that revisit (skipped without ../shared/data): loops are found, shown
# and saved with the map.
teddy="$src/../shared/data/real/tum_fr3_teddy_200frames"
if [ ! -d "$teddy" ]; then echo "SKIP (SLAM part): $teddy not found"; exit 0; fi
cat > "$out/slam.sh" <<INNER
"$app" -c "$src/config.ini" -i "$teddy" --slam -n 60 --rate 0 --hold 1 \
  --save-prefix "$out/slam_" > "$out/slam.log" 2>&1
INNER
xvfb-run -a -s "-screen 0 1280x800x24" bash "$out/slam.sh"
cat "$out/slam.log"
loops=$(sed -n 's/.* \([0-9]*\) loops accepted.*/\1/p' "$out/slam.log")
[ "${loops:-0}" -gt 0 ] || { echo "FAIL: no loop accepted in SLAM mode"; exit 1; }
zcat -f "$out/slam_map.3Dscene" | grep -aq "loop closures" ||
  { echo "FAIL: the saved .3Dscene has no loop closures"; exit 1; }
echo "PASS: SLAM mode, $loops loops accepted and saved"
