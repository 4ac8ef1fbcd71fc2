#!/usr/bin/env bash
# `athlos import` with a column mapping: --column SRC=CHANNEL[:UNIT], --skip, --time-column COL[:UNIT]
# and --athlete. Values arrive in SI; bad mappings fail naming the option and leave the project as it was.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
printf 'Date;Time [ms];AccX [g];Gyro Z;Load\n2024-05-01;0;0.5;180;1\n2024-05-01;10;1;90;2\n2024-05-01;20;-1;0;3\n' > "$WORK/watch.csv"
expect_ok "new" "$ATHLOS" new "$P"
cp "$P" "$WORK/before.athlos"

# Without a mapping 'Time' is taken as the time column, and the text column stops the import.
expect_fail "text column" "watch\.csv:2:1 \(column 'Date'\): '2024-05-01' is not a number" \
  "$ATHLOS" import "$P" "$WORK/watch.csv" --as anna --kind imu
expect_fail "unknown unit" "column mapping for 'AccX': unknown unit 'furlong'" \
  "$ATHLOS" import "$P" "$WORK/watch.csv" --as anna --kind imu --time-column Time --skip Date --column AccX=acc_x:furlong
expect_fail "duplicate channel" "duplicate channel 'acc_x'" \
  "$ATHLOS" import "$P" "$WORK/watch.csv" --as anna --kind imu --time-column Time --skip Date --column AccX=acc_x --column Load=acc_x
expect_fail "missing time column" "time column 'Zeit' is not in the file" \
  "$ATHLOS" import "$P" "$WORK/watch.csv" --as anna --kind imu --time-column Zeit
expect_fail "text cell" "watch\.csv:2:1 \(column 'Date'\)" \
  "$ATHLOS" import "$P" "$WORK/watch.csv" --as anna --kind imu --time-column Time
expect_fail "bad --column" "--column 'AccX'" "$ATHLOS" import "$P" "$WORK/watch.csv" --as anna --column AccX
cmp -s "$P" "$WORK/before.athlos" || fail "failed imports changed the project file"

expect_ok "mapped import" "$ATHLOS" import "$P" "$WORK/watch.csv" --as anna/wrist --kind imu \
  --time-column Time --column AccX=acc_x --column "Gyro Z=gyr_z:deg/s" --skip Date --athlete "Anna Berg"
expect_ok "export" "$ATHLOS" export "$P" anna/wrist --to "$WORK/out.csv"
[ "$(head -1 "$WORK/out.csv")" = "t,acc_x,gyr_z,Load" ] || fail "header: $(head -1 "$WORK/out.csv")"
# t from ms, acc from g (9.80665 m/s^2), gyr from deg/s (pi rad/s at 180 deg/s).
awk -F, 'NR==2 { if ($1 != 0 || $2 != 4.903325 || ($3 - 3.141592653589793)^2 > 1e-24 || $4 != 1) exit 1 }
         NR==3 { if ($1 != 0.01 || $2 != 9.80665 || ($3 - 1.5707963267948966)^2 > 1e-24) exit 1 }' "$WORK/out.csv" \
  || fail "values not in SI: $(cat "$WORK/out.csv")"
"$ATHLOS" info "$P" --json > "$WORK/info.json" 2>/dev/null || fail "info --json"
grep -q '"athlete": *"Anna Berg"' "$WORK/info.json" || fail "athlete not in the recording metadata"
grep -q '"time_column": *"Time"' "$WORK/info.json" || fail "mapping not in the provenance"
finish
