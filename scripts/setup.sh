#!/usr/bin/env bash
# Fresh Debian 12 machine -> installed, built, and the default job run on the bundled sequence.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/apps/hybrid-rgbd-odometry --config config.ini
