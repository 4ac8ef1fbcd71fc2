#!/usr/bin/env bash
# Builds Athlos (scripts/setup.sh) and the Debian package build/athlos_<version>_<arch>.deb with
# CPack: the application, its plugins, the SDK (headers, CMake package Athlos), the desktop file,
# the MIME type application/x-athlos-project (*.athlos) and the icons; binaries stripped, library
# dependencies from dpkg-shlibdeps. Install it with: apt-get install ./build/athlos_*.deb
set -euo pipefail
cd "$(dirname "$0")/.."
# dpkg-shlibdeps (dpkg-dev) computes the dependencies; only installed when missing.
if ! dpkg-query -W -f='${Status}' dpkg-dev 2>/dev/null | grep -q "install ok installed"; then
  echo "package: installing dpkg-dev"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends dpkg-dev >/dev/null
fi
bash scripts/setup.sh
BUILD_DIR=${ATHLOS_BUILD_DIR:-build}
rm -f "$BUILD_DIR"/athlos_*.deb
(cd "$BUILD_DIR" && cpack -G DEB)
ls -l "$BUILD_DIR"/athlos_*.deb
