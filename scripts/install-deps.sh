#!/usr/bin/env bash
# Installs the Debian 12 packages this project needs. Idempotent; safe to re-run.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
PKGS=(
  build-essential cmake pkg-config git
  libmrpt-dev mrpt-apps mrpt-common libjpeg-dev zlib1g-dev
  libopencv-dev libopencv-contrib-dev libopen3d-dev
  libeigen3-dev libnanoflann-dev libopenni2-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libplplot-dev plplot-driver-cairo fonts-dejavu-core
  clang clang-format libclang-rt-dev
  xvfb x11-apps imagemagick
)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PKGS[@]} packages already installed"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
