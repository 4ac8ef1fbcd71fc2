#!/usr/bin/env bash
# Wrist walking end to end (issue #18 item 4): simulate walkers, move the test walker through CSV
# (IMU as exported, barometer rewritten in hPa with a bare 'pressure' header, as the interchange
# format has it), wrist-cadence on every walker, wrist-speed-train chained over the training
# walkers, wrist-speed on the held-out walker; cadence scored against the exported truth (median
# relative error ≤ 1 %, the issue's criterion) and speed against it; bad inputs refused with a
# one-line reason and the project left byte-identical.
source "$(dirname "$0")/lib/common.bash" "$@"
SIM="$WORK/sim.athlos"; P="$WORK/p.athlos"
expect_ok "new sim" "$ATHLOS" new "$SIM"
expect_ok "new project" "$ATHLOS" new "$P"
expect_ok "processors" "$ATHLOS" processors --json
for id in simulate-wrist-walk wrist-cadence wrist-speed-train wrist-speed; do
  grep -q "\"id\": \"$id\"" "$WORK/out" || fail "processor $id not listed"
done

# Training walkers straight in the project; the held-out walker via CSV.
for spec in a:71:1.62 b:72:1.70 d:74:1.78 e:75:1.86; do
  IFS=: read -r name seed height <<< "$spec"
  expect_ok "simulate $name" "$ATHLOS" run "$P" simulate-wrist-walk --output "$name/wrist" \
    --param seed="$seed" --param height="$height" --param duration=600
  expect_ok "cadence $name" "$ATHLOS" run "$P" wrist-cadence --input "$name/wrist" --output "$name/cadence"
done
expect_ok "simulate c" "$ATHLOS" run "$SIM" simulate-wrist-walk --output c/wrist --param seed=73 --param height=1.75 \
  --param duration=600
expect_ok "export imu" "$ATHLOS" export "$SIM" c/wrist --to "$WORK/imu.csv"
expect_ok "export baro" "$ATHLOS" export "$SIM" c/wrist-barometer --to "$WORK/baro-pa.csv"
expect_ok "export truth" "$ATHLOS" export "$SIM" c/wrist-truth --to "$WORK/truth.csv"
head -1 "$WORK/baro-pa.csv" | grep -q "pressure \[Pa\]" || fail "barometer export lacks 'pressure [Pa]': $(head -1 "$WORK/baro-pa.csv")"
awk -F, 'NR == 1 { print "t,pressure"; next } { printf "%s,%.4f\n", $1, $2 / 100 }' "$WORK/baro-pa.csv" > "$WORK/baro.csv"
expect_ok "import imu" "$ATHLOS" import "$P" "$WORK/imu.csv" --as c --kind imu
expect_ok "import baro (hPa)" "$ATHLOS" import "$P" "$WORK/baro.csv" --as c --kind barometer
expect_ok "export baro again" "$ATHLOS" export "$P" c/barometer --to "$WORK/baro-back.csv"
awk -F, 'FNR == 1 { next } NR == FNR { p[FNR] = $2; next } { d = $2 - p[FNR]; if (d < 0) d = -d; if (d > 0.01) bad++ }
         END { exit bad > 0 }' "$WORK/baro-pa.csv" "$WORK/baro-back.csv" || fail "hPa import does not give back the pressure in Pa"
expect_ok "cadence c" "$ATHLOS" run "$P" wrist-cadence --input c/imu --output c/cadence

expect_ok "train a" "$ATHLOS" run "$P" wrist-speed-train --input a/cadence,a/wrist-barometer,a/wrist-truth \
  --output a/speed-model --param height=1.62
prev=a/speed-model
for spec in b:1.70 d:1.78 e:1.86; do
  IFS=: read -r name height <<< "$spec"
  expect_ok "train $name" "$ATHLOS" run "$P" wrist-speed-train \
    --input "$name/cadence,$name/wrist-barometer,$name/wrist-truth,$prev" --output "$name/speed-model" \
    --param height="$height"
  prev="$name/speed-model"
done
expect_ok "speed c" "$ATHLOS" run "$P" wrist-speed --input c/cadence,c/barometer,e/speed-model --output c/speed \
  --param height=1.75
expect_ok "export cadence" "$ATHLOS" export "$P" c/cadence --to "$WORK/cadence.csv"
expect_ok "export speed" "$ATHLOS" export "$P" c/speed --to "$WORK/speed.csv"

# Median relative error (%) of column $3 of an estimate CSV against truth column $4 (truth at 10 Hz,
# joined on t to 0.1 s), over windows the estimate calls walking (column $5 of the estimate, or all
# finite rows) and the truth calls walking.
median_error() {
  awk -F, -v col="$3" -v tcol="$4" 'FNR == 1 { next }
       NR == FNR { key = sprintf("%.1f", $1); truth[key] = $tcol; walk[key] = $6; next }
       { key = sprintf("%.1f", $1); v = $col; if (v == "nan" || v == "" || !(key in truth) || walk[key] < 0.5) next;
         if (truth[key] <= 0.2) next; printf "%.6f\n", 100 * (v - truth[key]) / truth[key] }' "$1" "$2" |
    sort -g | awk '{ e[NR] = $1 } END { if (NR == 0) { print "nan"; exit } print (NR % 2 ? e[(NR + 1) / 2] : (e[NR / 2] + e[NR / 2 + 1]) / 2), NR }'
}
read -r cad_med cad_n <<< "$(median_error "$WORK/truth.csv" "$WORK/cadence.csv" 2 2)"
read -r spd_med spd_n <<< "$(median_error "$WORK/truth.csv" "$WORK/speed.csv" 2 3)"
echo "held-out walker: cadence median error $cad_med % over $cad_n windows, speed median error $spd_med % over $spd_n"
[ "$cad_med" = "nan" ] && fail "no cadence window matched the truth"
[ "$spd_med" = "nan" ] && fail "no speed window matched the truth"
awk -v m="$cad_med" -v n="$cad_n" 'BEGIN { exit !(m <= 1.0 && m >= -1.0 && n >= 300) }' ||
  fail "cadence median error $cad_med % (n $cad_n) not within ±1 %"
awk -v m="$spd_med" 'BEGIN { exit !(m <= 5.0 && m >= -5.0) }' || fail "speed median error $spd_med % not within ±5 %"

# Bad inputs: one-line reasons, the project byte-identical.
cp "$P" "$WORK/before.athlos"
expect_fail "speed without height" "height" "$ATHLOS" run "$P" wrist-speed --input c/cadence,c/barometer,e/speed-model \
  --output c/speed2
expect_fail "speed without model" "wrist-speed takes" "$ATHLOS" run "$P" wrist-speed --input c/cadence,c/barometer \
  --output c/speed2 --param height=1.75
expect_fail "cadence on a barometer" "barometer" "$ATHLOS" run "$P" wrist-cadence --input c/barometer --output c/x
expect_fail "train without speed" "speed" "$ATHLOS" run "$P" wrist-speed-train --input c/cadence,c/barometer,c/imu \
  --output c/m --param height=1.75
cmp -s "$P" "$WORK/before.athlos" || fail "a refused run changed the project"
printf 't,pressure [m]\n0,1\n1,2\n' > "$WORK/badbaro.csv"
expect_fail "barometer in metres" "pressure" "$ATHLOS" import "$P" "$WORK/badbaro.csv" --as c2 --kind barometer
cmp -s "$P" "$WORK/before.athlos" || fail "a refused import changed the project"
finish
