#!/usr/bin/env bash
# Long run: time per frame and memory over a long sequence.
#   scripts/long-run.sh [frames] [work dir] [build dir]
#     renders N simulated desk frames (default 3000, 100 s of hand-held sweep at 30 Hz) into a
#     rawlog and plays it with the odometry alone (--no-slam) and the map on.
#   scripts/long-run.sh --tum FOLDER REPS [work dir] [build dir] [player options...]
#     plays a real TUM folder REPS times over, forwards and backwards (scripts/palindrome-tum.py),
#     in the default (SLAM) mode unless the player options say otherwise (e.g. --no-slam).
# Samples the player's resident memory and frame count every second, then reports peak RSS, RSS
# at each quarter of the run, and the wall-clock frames per second over the first and the last
# 10 % of the frames (a back end whose work grows with the map slows the last ones).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
if [[ ${1:-} == --tum ]]; then
  folder=$2 reps=$3
  work=${4:-/tmp/hrgbd-long-run-tum}
  build=${5:-build}
  shift $(($# < 5 ? $# : 5))
  mkdir -p "$work"
  # the camera's name (fr1, fr3, ...) stays in the folder's name: it chooses the intrinsics
  input=$work/$(basename "$folder")_x$reps
  if [[ ! -d $input ]]; then  # made whole, then moved into place
    rm -rf "$input.partial"
    python3 "$here/palindrome-tum.py" "$folder" "$input.partial" "$reps"
    mv "$input.partial" "$input"
  fi
  options=("$@")
else
  frames=${1:-3000}
  work=${2:-/tmp/hrgbd-long-run}
  build=${3:-build}
  mkdir -p "$work"
  input=$work/desk_long.rawlog
  if [[ ! -s $input ]]; then
    echo "rendering $frames frames to $input"
    "$build/apps/rgbd-simulate" -s desk -n "$frames" --images jpg -o "$input"
  fi
  options=(--no-slam)
fi
"$build/apps/hybrid-rgbd-odometry" -i "$input" -q "${options[@]}" --map-ply "$work/map.ply" \
  -t "$work/trajectory.txt" --csv "$work/frames.csv" >"$work/player.log" 2>&1 &
pid=$!
start=$(date +%s.%N)
: >"$work/rss.txt"
while kill -0 "$pid" 2>/dev/null; do
  rss=$(awk '/VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)
  # the CSV is written under a temporary name until the run ends (OutputFile.h)
  csv=$(ls "$work"/.frames.csv.*.tmp "$work/frames.csv" 2>/dev/null | head -n 1 || true)
  done_frames=$(($( { wc -l <"$csv"; } 2>/dev/null || echo 1) - 1))
  now=$(date +%s.%N)
  [[ -n $rss ]] && echo "$(awk -v a="$now" -v b="$start" 'BEGIN { print a - b }') $done_frames $rss" >>"$work/rss.txt"
  sleep 1
done
wait "$pid"
grep -E "^SLAM:|^frames:|time per frame|ATE RMSE \(aligned\)" "$work/player.log" || tail -n 4 "$work/player.log"
awk '
  { t[NR] = $1; f[NR] = $2; r[NR] = $3; if ($3 > peak) { peak = $3; at = $2 } }
  END {
    n = f[NR];
    printf "peak RSS %.0f MiB at frame %d of %d (%d samples)\n", peak / 1024, at, n, NR;
    for (q = 1; q <= 4; ++q) {
      target = n * q / 4; best = 1;
      for (i = 1; i <= NR; ++i) if (f[i] <= target) best = i;
      printf "  frame %5d: RSS %.0f MiB\n", f[best], r[best] / 1024;
    }
    # wall-clock rate over the first and the last 10 % of the frames, from the samples
    a = 1; b = 1; c = 1;
    for (i = 1; i <= NR; ++i) { if (f[i] <= n * 0.1) a = i; if (f[i] <= n * 0.9) b = i; }
    first = (f[a] - f[1]) / (t[a] - t[1] + 1e-9);
    last = (f[NR] - f[b]) / (t[NR] - t[b] + 1e-9);
    printf "frames per second: first 10 %% %.1f, last 10 %% %.1f (last/first %.2f)\n", first,
           last, last / first;
  }' "$work/rss.txt"
