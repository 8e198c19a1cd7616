#!/usr/bin/env bash
# Long run for memory stability: renders N simulated desk frames (default 3000, 100 s
# of hand-held sweep at 30 Hz) into a rawlog, plays it through hybrid odometry (--no-slam: the
# SLAM mode's keyframes grow memory by design, see doc/robustness.md) with the coloured map on,
# samples the player's resident memory every second and reports peak RSS and RSS at each
# quarter of the run. Usage: scripts/long-run.sh [frames] [work dir] [build dir]
set -euo pipefail
frames=${1:-3000}
work=${2:-/tmp/hrgbd-long-run}
build=${3:-build}
mkdir -p "$work"
rawlog=$work/desk_long.rawlog
if [[ ! -s $rawlog ]]; then
  echo "rendering $frames frames to $rawlog"
  "$build/apps/rgbd-simulate" -s desk -n "$frames" --images jpg -o "$rawlog"
fi
"$build/apps/hybrid-rgbd-odometry" -i "$rawlog" -q --no-slam --map-ply "$work/map.ply" \
  -t "$work/trajectory.txt" --csv "$work/frames.csv" >"$work/player.log" 2>&1 &
pid=$!
: >"$work/rss.txt"
while kill -0 "$pid" 2>/dev/null; do
  rss=$(awk '/VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)
  done_frames=$(($( { wc -l <"$work/frames.csv"; } 2>/dev/null || echo 1) - 1))
  [[ -n $rss ]] && echo "$done_frames $rss" >>"$work/rss.txt"
  sleep 1
done
wait "$pid"
tail -n 4 "$work/player.log"
awk -v n="$frames" '
  { f[NR] = $1; r[NR] = $2; if ($2 > peak) { peak = $2; at = $1 } }
  END {
    printf "peak RSS %.0f MiB at frame %d of %d (%d samples)\n", peak / 1024, at, n, NR;
    for (q = 1; q <= 4; ++q) {
      target = n * q / 4; best = 1;
      for (i = 1; i <= NR; ++i) if (f[i] <= target) best = i;
      printf "  frame %5d: RSS %.0f MiB\n", f[best], r[best] / 1024;
    }
  }' "$work/rss.txt"
