#!/usr/bin/env bash
# Per-sample labels become annotations with one command (--labels, --label-names); annotations export
# to CSV and JSON and import back onto a recording.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P"
printf 't,acc_x,acc_y,acc_z,activity\n0,0,0,9.8,walk\n0.5,0,0,9.8,walk\n1,0,0,9.8,\n1.5,1,0,9.8,run\n2,1,0,9.8,run\n' > "$WORK/watch.csv"
expect_ok "labels" "$ATHLOS" import "$P" "$WORK/watch.csv" --as w --kind imu --labels activity
grep -q "2 annotations onto w" "$WORK/out" || fail "annotation count: $(cat "$WORK/out")"
expect_ok "export csv" "$ATHLOS" export "$P" w/annotations --to "$WORK/a.csv"
[ "$(cat "$WORK/a.csv")" = "$(printf 'start,end,label,confidence,source,annotator\n0,1,walk,1,import,watch.csv\n1.5,2,run,1,import,watch.csv')" ] \
  || fail "annotations csv: $(cat "$WORK/a.csv")"
expect_ok "export json" "$ATHLOS" export "$P" w/annotations --to "$WORK/a.json"
grep -q '"label": "run"' "$WORK/a.json" || fail "annotations json"
expect_ok "export imu" "$ATHLOS" export "$P" w/imu --to "$WORK/imu.csv"
[ "$(head -1 "$WORK/imu.csv")" = "t,acc_x,acc_y,acc_z" ] || fail "the label column became data: $(head -1 "$WORK/imu.csv")"
expect_ok "import annotations" "$ATHLOS" import "$P" "$WORK/a.json" --as other
expect_fail "again" "already has annotations from watch.csv" "$ATHLOS" import "$P" "$WORK/a.csv" --as other

printf 't,acc_x,state\n0,1,0\n1,1,1\n2,1,2\n' > "$WORK/num.csv"
expect_fail "unnamed number" "num\.csv:4:3 \(column 'state'\): label '2' has no name" \
  "$ATHLOS" import "$P" "$WORK/num.csv" --as n --kind imu --labels state --label-names 0=rest,1=run
expect_ok "named numbers" "$ATHLOS" import "$P" "$WORK/num.csv" --as n --kind imu --labels state --label-names 0=rest,1=run,2=jump
expect_fail "bad names" "--label-names: 'x' is not VALUE=NAME" \
  "$ATHLOS" import "$P" "$WORK/num.csv" --as m --kind imu --labels state --label-names x
finish
