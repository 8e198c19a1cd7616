#!/usr/bin/env bash
# Configures and builds (Release unless BUILD_TYPE is set) into ./build (or $BUILD_DIR); every
# target, or the one named by $TARGET.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" "$@" > /dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)" ${TARGET:+--target "$TARGET"}
