#!/usr/bin/env bash
# No silent wrong answers (issue #13 item 8): a run that produces nothing, or a calibration whose result
# is physically implausible, fails with a one-line reason naming the item, the parameter and the
# values, and leaves the project byte-identical; the override stores the result flagged, with a
# warning. Also: annotations export to ELAN .eaf and import back with the same intervals (item 7).
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P"

# --- lps-positioning with too few beacons per instant: an error, not an empty stream and exit 0.
S="$WORK/sim.athlos"
expect_ok "new sim" "$ATHLOS" new "$S"
expect_ok "simulate" "$ATHLOS" run "$S" simulate-lps --output sim/w --param laps=0.1
expect_ok "export tdoa" "$ATHLOS" export "$S" sim/w --to "$WORK/tdoa.csv"
expect_ok "export beacons" "$ATHLOS" export "$S" sim/w-beacons --to "$WORK/beacons.csv"
# Keep two readings per instant (long form t,beacon,dt).
awk -F, 'NR == 1 { print; next } { if (++n[$1] <= 2) print }' "$WORK/tdoa.csv" > "$WORK/few.csv"
expect_ok "import few" "$ATHLOS" import "$P" "$WORK/few.csv" --as few --kind lps-tdoa
expect_ok "import beacons" "$ATHLOS" import "$P" "$WORK/beacons.csv" --as venue --kind beacons
cp "$P" "$WORK/before.athlos"
expect_fail "no fix" "^athlos: lps-positioning: no fix: no instant of TDoA stream 'few/tdoa' had enough beacons: need ≥4 \(min_beacons, 2d\), the most was 2" \
  "$ATHLOS" run "$P" lps-positioning --input few/tdoa,venue/beacons --output few/lps --param dimension=2d
cmp -s "$P" "$WORK/before.athlos" || fail "no fix: the project changed"

# --- any processor: an output of only NaN is refused by the run contract (core OutputChecks).
printf 't,acc_x\n0,nan\n0.01,nan\n0.02,nan\n0.03,nan\n0.05,nan\n' > "$WORK/nan.csv"
expect_ok "import nan" "$ATHLOS" import "$P" "$WORK/nan.csv" --as blank --kind imu
cp "$P" "$WORK/before.athlos"
expect_fail "all NaN" "^athlos: resample: output 'blank/rs': every value of its 6 rows × 1 columns is NaN or infinite" \
  "$ATHLOS" run "$P" resample --input blank/imu --output blank/rs --param rate=100
cmp -s "$P" "$WORK/before.athlos" || fail "all NaN: the project changed"

# --- imu-calibration of a magnetometer whose numbers are milligauss read as µT: 48 µT becomes
# 480 "µT", outside the geomagnetic range. The sensor turns through every direction (Fibonacci
# spiral over the sphere) so that the ellipsoid fit itself succeeds.
awk 'BEGIN { n = 2000; print "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,mag_x,mag_y,mag_z"
  for (k = 0; k < n; k++) { z = 1 - 2 * (k + 0.5) / n; r = sqrt(1 - z * z); p = 2.399963229728653 * k
    x = r * cos(p); y = r * sin(p)
    printf "%.2f,%.5f,%.5f,%.5f,1,-0.5,0.8,%.3f,%.3f,%.3f\n", k / 100, 0, -9.81 * z / sqrt(y*y + z*z + 1e-12), \
      9.81 * y / sqrt(y*y + z*z + 1e-12), 10 * (48 * x + 8), 10 * (48 * y - 5), 10 * (48 * z + 3) } }' > "$WORK/mag.csv"
expect_ok "import imu" "$ATHLOS" import "$P" "$WORK/mag.csv" --as turn --kind imu
cp "$P" "$WORK/before.athlos"
expect_fail "implausible field" "^athlos: imu-calibration: implausible calibration of 'turn/imu': the magnetic field after calibration is 480 µT \(median \|m\|\), outside mag_field_min … mag_field_max = 22 … 67 µT.*accept_implausible=true" \
  "$ATHLOS" run "$P" imu-calibration --input turn/imu --output turn/cal
cmp -s "$P" "$WORK/before.athlos" || fail "implausible field: the project changed"
# The override is a declared parameter (listed by `processors`, recorded in provenance).
expect_ok "processors" "$ATHLOS" processors --json
grep -q '"name": "accept_implausible"' "$WORK/out" || fail "accept_implausible is not in the parameter schema"
expect_ok "accept implausible" "$ATHLOS" run "$P" imu-calibration --input turn/imu --output turn/cal --param accept_implausible=true
grep -q "warning: turn/cal is implausible: the magnetic field after calibration is 480 µT" "$WORK/err" \
  || fail "accepted implausible calibration without a warning: $(cat "$WORK/err")"

# --- ELAN export: annotations → .eaf (one tier per label) → import → the same intervals to 1 ms.
printf 'start,end,label,confidence,source,annotator\n0,1.5,walk,1,import,coach\n1.5,3.2504,sprint,1,import,coach\n5.1234,9,walk,1,import,coach\n6,7,walk,0.8,model,analyst\n' > "$WORK/ann.csv"
expect_ok "import annotations" "$ATHLOS" import "$P" "$WORK/ann.csv" --as turn
expect_ok "export eaf" "$ATHLOS" export "$P" turn/annotations --to "$WORK/ann.eaf"
grep -q 'TIME_UNITS="milliseconds"' "$WORK/ann.eaf" || fail "eaf: no TIME_UNITS"
[ "$(grep -c '<TIER ' "$WORK/ann.eaf")" = 3 ] || fail "eaf: expected tiers walk, walk (2), sprint: $(grep '<TIER ' "$WORK/ann.eaf")"
expect_ok "import eaf" "$ATHLOS" import "$P" "$WORK/ann.eaf" --as elan
expect_ok "export back" "$ATHLOS" export "$P" elan/annotations --to "$WORK/back.csv"
intervals() { awk -F, 'NR > 1 { printf "%s %.3f %.3f\n", $3, $1, $2 }' "$1" | sort; }
[ "$(intervals "$WORK/ann.csv")" = "$(intervals "$WORK/back.csv")" ] \
  || fail "eaf round trip: $(intervals "$WORK/ann.csv" | tr '\n' ';') became $(intervals "$WORK/back.csv" | tr '\n' ';')"
expect_fail "eaf of a stream" "\.eaf" "$ATHLOS" export "$P" turn/imu --to "$WORK/imu.eaf"
finish
