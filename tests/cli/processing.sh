#!/usr/bin/env bash
# processors are discovered as plugins; run and pipeline store results with provenance.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
make_imu_csv "$WORK/imu.csv" 1000
expect_ok "new" "$ATHLOS" new "$P"
expect_ok "import" "$ATHLOS" import "$P" "$WORK/imu.csv" --as rec --kind imu
expect_ok "processors" "$ATHLOS" processors --json
for id in resample butterworth; do grep -q "\"id\": \"$id\"" "$WORK/out" || fail "processor $id not listed"; done
expect_ok "run butterworth" "$ATHLOS" run "$P" butterworth --input rec/imu --output rec/imu-lp --param cutoff=5 --param order=4
expect_ok "run resample" "$ATHLOS" run "$P" resample --input rec/imu --output rec/imu-50 --param rate=50
expect_ok "info" "$ATHLOS" info "$P" --json
grep -q '"path": "rec/imu-lp"' "$WORK/out" || fail "filtered stream missing"
grep -q '"processor": "butterworth"' "$WORK/out" || fail "provenance of the filter missing"
grep -q '"samples": 500' "$WORK/out" || fail "resampled stream should have 500 samples at 50 Hz over 10 s"
echo '{"name": "lp-then-resample", "steps": [
  {"processor": "butterworth", "input": "rec/imu", "output": "rec/p-lp", "params": {"cutoff": 8}},
  {"processor": "resample", "input": ["rec/p-lp"], "output": "rec/p-25", "params": {"rate": 25}}]}' > "$WORK/pipe.json"
expect_ok "pipeline" "$ATHLOS" pipeline "$P" "$WORK/pipe.json"
expect_ok "info after pipeline" "$ATHLOS" info "$P" --json
grep -q '"name": "lp-then-resample"' "$WORK/out" || fail "pipeline not recorded in the project"
grep -q '"path": "rec/p-25"' "$WORK/out" || fail "pipeline output missing"
# Re-running with the same inputs and parameters reproduces the result exactly.
expect_ok "export 1" "$ATHLOS" export "$P" rec/imu-lp --to "$WORK/a.csv"
expect_ok "rerun" "$ATHLOS" run "$P" butterworth --input rec/imu --output rec/imu-lp --param cutoff=5 --param order=4
expect_ok "export 2" "$ATHLOS" export "$P" rec/imu-lp --to "$WORK/b.csv"
cmp -s "$WORK/a.csv" "$WORK/b.csv" || fail "re-run is not reproducible"
finish
