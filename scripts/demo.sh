#!/usr/bin/env bash
# The embedded default: builds Athlos, makes a demo project from ../shared/data (a BROAD trial with
# its optical reference and the gaitmap walk), runs the processors on it, and then opens the GUI
# on it — or, without a display, prints a summary and writes screenshots.
#
# Against an installed copy (the .deb) instead of the build tree, nothing is built:
#   ATHLOS_BIN=/usr/bin/athlos bash scripts/demo.sh
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -n "${ATHLOS_BIN:-}" ]; then
  ATHLOS="$ATHLOS_BIN"
else
  bash scripts/setup.sh
  ATHLOS="${ATHLOS_BUILD_DIR:-build}/bin/athlos"
fi
# The pipelines (an installed copy also has them in <prefix>/share/athlos/demo).
DEMO_DIR=resources/demo
SHARED="${ATHLOS_SHARED_DIR:-$(cd .. && pwd)/shared}"
OUT="${ATHLOS_DEMO_DIR:-out}"
mkdir -p "$OUT"
P="$OUT/demo.athlos"

"$ATHLOS" new "$P" --sport "lab" --force
"$ATHLOS" import "$P" "$SHARED/data/broad/07_undisturbed_fast_rotation_B.hdf5" --as broad07 --format broad
"$ATHLOS" import "$P" "$SHARED/data/gaitmap/imu_sample_ic_stride.csv" --as walk --format gaitmap
"$ATHLOS" pipeline "$P" "$DEMO_DIR/pipeline.json"
# Each topic adds its own steps (team match, joint angles, gait events…) in pipeline-<topic>.json.
for extra in "$DEMO_DIR"/pipeline-*.json; do
  [ -e "$extra" ] || continue
  "$ATHLOS" pipeline "$P" "$extra"
done
# The walk's gait report (stride tables of pipeline-gait.json): summary, strides over time, every stride.
"$ATHLOS" report "$P" --gait walk --to "$OUT/demo-gait-report.pdf"
# A synthetic clip (each frame shows its index) attached to the walk, so the video dock has footage.
"$ATHLOS" video --write-pattern "$OUT/demo-pattern.avi" --frames 300 --fps 30
"$ATHLOS" video "$P" walk "$OUT/demo-pattern.avi" --offset 2
"$ATHLOS" info "$P"
for view in $("$ATHLOS" screenshot --list); do
  "$ATHLOS" screenshot "$P" --view "$view" --to "$OUT/demo-$view.png"
  echo "screenshot: $OUT/demo-$view.png"
done
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -z "${CI:-}" ]; then
  exec "$ATHLOS" "$P"
fi
echo "demo project: $P (open it with: $ATHLOS $P)"
