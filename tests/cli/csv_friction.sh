#!/usr/bin/env bash
# CSV as people write it: a pandas index column, channel names in any case, --drop-unmapped, units
# of sports devices; an unknown unit lists the accepted ones.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P"
printf ',t,ACC_X,Acc_Y,Load,Comment\n0,0,1,2,3,ok\n1,0.01,4,5,6,fine\n' > "$WORK/pandas.csv"
expect_fail "text column" "pandas\.csv:2:6 \(column 'Comment'\): 'ok' is not a number" \
  "$ATHLOS" import "$P" "$WORK/pandas.csv" --as a --kind imu
expect_ok "drop unmapped" "$ATHLOS" import "$P" "$WORK/pandas.csv" --as a --kind imu --drop-unmapped
expect_ok "export" "$ATHLOS" export "$P" a/imu --to "$WORK/a.csv"
[ "$(head -1 "$WORK/a.csv")" = "t,acc_x,acc_y" ] || fail "columns: $(head -1 "$WORK/a.csv")"
printf 't,Speed (km/h),Baro\n0,36,1013.25\n1,18,1013\n' > "$WORK/units.csv"
expect_ok "units" "$ATHLOS" import "$P" "$WORK/units.csv" --as u --kind custom --column 'Speed=speed:km/h' --column Baro=pressure:hPa
expect_ok "export units" "$ATHLOS" export "$P" u/custom --to "$WORK/u.csv"
awk -F, 'NR==2 { if (($2 - 10)^2 > 1e-20 || $3 != 101325) exit 1 }' "$WORK/u.csv" || fail "SI values: $(cat "$WORK/u.csv")"
expect_fail "unknown unit" "unknown unit 'furlong' \(accepted: " \
  "$ATHLOS" import "$P" "$WORK/units.csv" --as v --kind custom --column Baro=pressure:furlong
finish
