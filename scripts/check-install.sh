#!/usr/bin/env bash
# Checks the installed package the way a user sees it: installs ./build (or $BUILD_DIR) into a
# temporary prefix, builds examples/odometry_from_rawlog against that prefix alone (separate build
# dir, CMAKE_PREFIX_PATH) and runs it on rawlogs/desk_near.rawlog, which must give one TUM pose
# line per frame. Exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
RAWLOG=rawlogs/desk_near.rawlog
FRAMES=20  # frames in $RAWLOG
APPS="hybrid-rgbd-odometry rgbd-eval tum2rawlog rgbd-simulate rgbd-benchmark rgbd-live rgbd-vocabulary"

fail() {
  echo "check-install: $*" >&2
  exit 1
}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
cmake --install "$BUILD_DIR" --prefix "$prefix" > /dev/null

for app in $APPS; do
  [ -x "$prefix/bin/$app" ] || fail "bin/$app not installed"
done
[ -f "$prefix/share/hrgbd/config.ini" ] || fail "share/hrgbd/config.ini not installed"
[ -f "$prefix/share/hrgbd/orb_vocabulary.txt" ] || fail "share/hrgbd/orb_vocabulary.txt not installed"
# The package must not point back into the source or build tree.
if grep -rqF "$PWD" "$prefix/lib/cmake/hrgbd"; then
  fail "lib/cmake/hrgbd refers to $PWD"
fi

cmake -S examples/odometry_from_rawlog -B "$work/build" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release > /dev/null
grep -qx "hrgbd_DIR:PATH=$prefix/lib/cmake/hrgbd" "$work/build/CMakeCache.txt" ||
  fail "the example did not find hrgbd in $prefix"
cmake --build "$work/build" -j"$(nproc)" > /dev/null

"$work/build/odometry_from_rawlog" "$RAWLOG" > "$work/poses.txt"
number='-?[0-9]+\.[0-9]+'
poses=$(grep -cE "^$number( $number){7}$" "$work/poses.txt" || true)
lines=$(wc -l < "$work/poses.txt")
if [ "$poses" -ne "$FRAMES" ] || [ "$lines" -ne "$FRAMES" ]; then
  fail "expected $FRAMES pose lines for $RAWLOG, got $poses pose lines in $lines lines"
fi
echo "check-install: OK ($FRAMES poses from the example built against $prefix)"
