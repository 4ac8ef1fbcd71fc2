#!/usr/bin/env bash
# Installs what is missing (Debian 12, as root) and builds Athlos into ./build.
# Idempotent: apt-get runs only when a package is missing; the build is incremental (ccache).
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(build-essential cmake ccache pkg-config
  qt6-base-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n qt6-svg-dev libgl-dev
  libeigen3-dev libceres-dev libopencv-dev libhdf5-dev libqcustomplot-dev libsleef-dev
  libgtest-dev libgmock-dev libbenchmark-dev libssl-dev
  slurmd slurmctld slurm-client munge)  # a single-node Slurm for tests/cli/batch_slurm.sh

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
# scripts/sanitize.sh needs the packages but builds elsewhere.
[ -n "${ATHLOS_SETUP_PACKAGES_ONLY:-}" ] && exit 0

BUILD_DIR=${ATHLOS_BUILD_DIR:-build}
# ccache: paths relative to the checkout and no working-directory hash, so a fresh clone (CI) or a
# second work tree reuses the objects another checkout compiled.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(pwd)}" CCACHE_NOHASHDIR=1
# CI treats warnings as errors; elsewhere the cached choice stays (so demo after test does not rebuild).
WERROR_ARG=(); [ -n "${CI:-}" ] && WERROR_ARG=(-DATHLOS_WERROR=ON)
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${WERROR_ARG[@]}" \
      -DATHLOS_SHARED_DIR="${ATHLOS_SHARED_DIR:-$(cd .. && pwd)/shared}" ${ATHLOS_CMAKE_ARGS:-} >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)"
