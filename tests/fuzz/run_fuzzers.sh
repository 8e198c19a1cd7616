#!/usr/bin/env bash
# Runs each libFuzzer target for a bounded time. Usage: run_fuzzers.sh <fuzz build dir> [seconds]
# The build dir is configured with -DHRGBD_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ (see .ci/run).
# A crash stops with exit 1 and names the input; keep it as a regression test by copying it to
# tests/fuzz/regressions/<target>/ (the normal build replays that folder), then fix the bug.
set -euo pipefail
build=$(realpath "$1")
seconds=${2:-60}
seed=${FUZZ_SEED:-1}  # fixed: the same inputs are tried in the same order on every run
src=$(cd "$(dirname "$0")" && pwd)
work=$build/fuzz-work
rm -rf "$work" && mkdir -p "$work"
"$build/tests/fuzz/make_rawlog_seeds" "$work/seeds-rawlog" >/dev/null
# Memory: each input has a 256 MiB heap budget for new (throwing_new.cpp), since MRPT trusts
# length fields; malloc-family calls (OpenCV's cv::Mat) over 2 GiB get NULL, as in production
# on a machine without the memory, where OpenCV then throws "Failed to allocate".
export ASAN_OPTIONS=allocator_may_return_null=1:max_allocation_size_mb=2048:detect_leaks=1
status=0
for target in tum_list ini rawlog; do
  corpus=$work/corpus-$target
  mkdir -p "$corpus" "$work/artifacts-$target"
  seeds=("$src/corpus/$target" "$src/regressions/$target")
  [[ $target == ini ]] && cp "$src/../../config.ini" "$corpus/"
  [[ $target == rawlog ]] && seeds=("$work/seeds-rawlog" "$src/regressions/$target")
  echo "== fuzz_$target for ${seconds}s"
  if ! "$build/tests/fuzz/fuzz_$target" -max_total_time="$seconds" -seed="$seed" -timeout=20 -rss_limit_mb=4096 \
      -malloc_limit_mb=8192 -print_final_stats=1 \
      -artifact_prefix="$work/artifacts-$target/" "$corpus" "${seeds[@]}" \
      >"$work/fuzz_$target.log" 2>&1; then
    tail -n 60 "$work/fuzz_$target.log"
    echo "fuzz_$target FAILED; input(s): $(ls "$work/artifacts-$target")"
    echo "keep it: cp $work/artifacts-$target/* $src/regressions/$target/"
    status=1
  else
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$work/fuzz_$target.log" || true
    echo "corpus: $(ls "$corpus" | wc -l) inputs"
  fi
done
exit $status
