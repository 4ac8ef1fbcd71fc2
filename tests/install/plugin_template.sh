#!/usr/bin/env bash
# An installed copy works on its own and the SDK builds a plugin outside the tree:
#   - the installed `athlos` finds its libraries (RUNPATH, not the build tree) and its plugins;
#   - examples/plugin-template configures with find_package(Athlos) against the installed SDK,
#     builds, and `ATHLOS_PLUGIN_PATH=<its build folder> athlos processors` lists example-scale
#     (no plugin refused); the processor runs on a project; `cmake --install` of the plugin puts
#     it where the installed copy finds it without ATHLOS_PLUGIN_PATH.
#
# Usage: plugin_template.sh <source-dir> <build-dir>   installs <build-dir> into a temporary prefix
#        plugin_template.sh <source-dir> - <prefix>    uses an existing installation (e.g. /usr from
#                                                      the .deb); the plugin is not installed there
set -uo pipefail
SRC=$(cd "$1" && pwd); BUILD="$2"; PREFIX="${3:-}"
WORK=$(mktemp -d); trap 'rm -rf "$WORK"' EXIT
FAILURES=0
fail() { echo "FAIL: $*" >&2; FAILURES=$((FAILURES + 1)); }
step() { echo "== $*"; }
unset ATHLOS_PLUGIN_PATH

if [ -z "$PREFIX" ]; then
  PREFIX="$WORK/prefix"
  step "cmake --install $BUILD --prefix $PREFIX"
  cmake --install "$BUILD" --prefix "$PREFIX" >"$WORK/install.log" 2>&1 || { cat "$WORK/install.log"; echo "FAIL: install"; exit 1; }
  TEMP_PREFIX=1
else
  TEMP_PREFIX=0
fi
ATHLOS="$PREFIX/bin/athlos"
[ -x "$ATHLOS" ] || { echo "FAIL: no $ATHLOS"; exit 1; }

step "the installed athlos: version, libraries, plugins"
"$ATHLOS" --version >"$WORK/version" 2>&1 || fail "athlos --version: $(cat "$WORK/version")"
head -1 "$WORK/version"
if [ "$TEMP_PREFIX" = 1 ]; then
  # Every Athlos library resolves inside the prefix, none from the build tree.
  ldd "$ATHLOS" | grep athlos_ >"$WORK/ldd"
  grep -q "libathlos_core.*$PREFIX" "$WORK/ldd" || fail "libathlos_core not from $PREFIX: $(cat "$WORK/ldd")"
  grep -q "libathlos_ui.*$PREFIX" "$WORK/ldd" || fail "libathlos_ui not from $PREFIX: $(cat "$WORK/ldd")"
  if grep -rqs --binary-files=text "$(cd "$BUILD" && pwd)" "$PREFIX/lib"*/cmake; then fail "the CMake package names the build tree"; fi
fi
"$ATHLOS" processors >"$WORK/builtin" 2>"$WORK/builtin.err" || fail "athlos processors: $(cat "$WORK/builtin.err")"
[ ! -s "$WORK/builtin.err" ] || fail "athlos processors warns: $(cat "$WORK/builtin.err")"
grep -q "^butterworth" "$WORK/builtin" || fail "the installed plugins are not found (no butterworth): $(head -5 "$WORK/builtin")"

step "build examples/plugin-template against $PREFIX"
LAUNCHER=(); command -v ccache >/dev/null && LAUNCHER=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
if ! cmake -S "$SRC/examples/plugin-template" -B "$WORK/plugin" -DCMAKE_PREFIX_PATH="$PREFIX" \
     -DCMAKE_BUILD_TYPE=Release "${LAUNCHER[@]}" >"$WORK/configure.log" 2>&1; then
  cat "$WORK/configure.log"; echo "FAIL: configure the template"; exit 1
fi
if ! cmake --build "$WORK/plugin" >"$WORK/build.log" 2>&1; then
  cat "$WORK/build.log"; echo "FAIL: build the template"; exit 1
fi
ls "$WORK/plugin"/athlos_plugin_example.so

step "ATHLOS_PLUGIN_PATH=<template build> athlos processors"
ATHLOS_PLUGIN_PATH="$WORK/plugin" "$ATHLOS" processors >"$WORK/list" 2>"$WORK/list.err" || fail "processors with the template"
[ ! -s "$WORK/list.err" ] || fail "a plugin was refused: $(cat "$WORK/list.err")"
grep -q "^example-scale" "$WORK/list" || fail "example-scale is not listed"
grep -q "^butterworth" "$WORK/list" || fail "the installed plugins disappeared next to the template"
grep -A4 "^example-scale" "$WORK/list"

step "run example-scale on a project"
awk 'BEGIN{print "t,acc_x,acc_y,acc_z"; for(i=0;i<50;i++) printf "%.2f,%d,1,-2\n", i/100, i}' >"$WORK/imu.csv"
P="$WORK/p.athlos"
export ATHLOS_PLUGIN_PATH="$WORK/plugin"
"$ATHLOS" new "$P" >/dev/null && "$ATHLOS" import "$P" "$WORK/imu.csv" --as rec --kind imu >/dev/null \
  || fail "new/import"
"$ATHLOS" run "$P" example-scale --input rec/imu --output rec/scaled --param factor=2.5 >"$WORK/run" 2>&1 \
  || fail "run example-scale: $(cat "$WORK/run")"
"$ATHLOS" export "$P" rec/scaled --to "$WORK/scaled.csv" >/dev/null 2>&1 || fail "export"
# Row 11 (t = 0.10): acc_x 10 → 25, acc_y 1 → 2.5, acc_z -2 → -5.
awk -F, 'NR==12 && !($2==25 && $3==2.5 && $4==-5) {print "row:", $0; exit 1}' "$WORK/scaled.csv" \
  || fail "example-scale did not scale by 2.5: $(sed -n 12p "$WORK/scaled.csv")"
"$ATHLOS" info "$P" | grep "example-scale" >/dev/null || fail "provenance does not name example-scale"
unset ATHLOS_PLUGIN_PATH

if [ "$TEMP_PREFIX" = 1 ]; then
  step "cmake --install the template into the installed copy"
  cmake --install "$WORK/plugin" >"$WORK/plugin-install.log" 2>&1 || fail "install the template: $(cat "$WORK/plugin-install.log")"
  "$ATHLOS" processors >"$WORK/list2" 2>&1
  grep -q "^example-scale" "$WORK/list2" \
    || fail "installed template not found without ATHLOS_PLUGIN_PATH: $(cat "$WORK/plugin-install.log") $(grep -v "^ " "$WORK/list2" | tr '\n' ' ')"
fi

if [ "$FAILURES" -gt 0 ]; then echo "$FAILURES check(s) failed"; exit 1; fi
echo "all checks passed"
