#!/usr/bin/env bash
# Builds the sanitizer build (scripts/build-asan.sh) and runs the unit, CLI and fuzz-replay tests
# under ASan + UBSan. --families also builds and runs the plugin family tests (longer; not in CI).
# Further arguments go to ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${ATHLOS_ASAN_BUILD_DIR:-build-asan}
labels='unit|cli|fuzz'
# Tests to leave out (a ctest -E regex), e.g. 'cli\.position_filter', the longest (docs/FUZZING.md).
exclude=${ATHLOS_SANITIZE_EXCLUDE:-}
targets=()
if [ "${1:-}" = --families ]; then
  shift
  labels='' # every label the build has (no GUI tests in it)
  exclude=''
  targets=(all)
fi
start=$(date +%s)
bash scripts/build-asan.sh "${targets[@]}"
built=$(date +%s)
source scripts/sanitizer-env.sh
export QT_QPA_PLATFORM=offscreen
ctest --test-dir "$BUILD_DIR" --output-on-failure -j"$(nproc)" ${labels:+-L "$labels"} ${exclude:+-E "$exclude"} "$@"
echo "sanitize: build $((built - start)) s, tests $(($(date +%s) - built)) s"
