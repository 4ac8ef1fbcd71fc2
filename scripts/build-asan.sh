#!/usr/bin/env bash
# The sanitizer build (docs/FUZZING.md): clang-14 with AddressSanitizer + UndefinedBehaviorSanitizer
# (ATHLOS_SANITIZE) and the libFuzzer targets (ATHLOS_FUZZ) in one build folder, build-asan (or
# $ATHLOS_ASAN_BUILD_DIR); no GUI tests, no benchmarks. -O1 with line tables keeps it fast to build
# and readable in reports; asserts stay on.
# Usage: scripts/build-asan.sh [cmake target ...]   (default: what scripts/sanitize.sh runs)
set -euo pipefail
cd "$(dirname "$0")/.."
ATHLOS_SETUP_PACKAGES_ONLY=1 bash scripts/setup.sh
bash scripts/ensure-packages.sh clang-14 libclang-rt-14-dev

BUILD_DIR=${ATHLOS_ASAN_BUILD_DIR:-build-asan}
# Objects shared with any other checkout of the same sources (see scripts/setup.sh).
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(pwd)}" CCACHE_NOHASHDIR=1
# gtest_discover_tests runs the test executables while building.
source scripts/sanitizer-env.sh

cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
      -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
      -DATHLOS_SANITIZE=ON -DATHLOS_FUZZ=ON -DATHLOS_BUILD_BENCH=OFF -DATHLOS_BUILD_GUI_TESTS=OFF \
      -DATHLOS_SHARED_DIR="${ATHLOS_SHARED_DIR:-$(cd .. && pwd)/shared}" >/dev/null
# The app (with every plugin) for the CLI tests, the unit tests, the fuzz targets.
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(athlos athlos_unit_tests athlos_fuzzers)
cmake --build "$BUILD_DIR" -j"$(nproc)" --target "${targets[@]}"
