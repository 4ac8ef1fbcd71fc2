#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (unit, GUI offscreen, CLI end-to-end).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export QT_QPA_PLATFORM=offscreen
ctest --test-dir "${ATHLOS_BUILD_DIR:-build}" --output-on-failure -j"$(nproc)" "$@"
