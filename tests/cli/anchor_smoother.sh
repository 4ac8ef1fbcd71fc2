#!/usr/bin/env bash
# anchor-smoother end to end (issue #18 item 3): simulate-gates → orientation → anchor-smoother, export,
# position RMSE and speed error against the exported truth between the first and the last gate
# (awk; the judged bounds: RMSE ≤ 0.25 m, speed SD ≤ 0.2 m/s), the same without anchors (passes=0)
# far worse, and refused runs (no gate found, no magnetometer, malformed gates table, bad parameter)
# that leave the project byte-identical.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P"
expect_ok "processors" "$ATHLOS" processors --json
for id in anchor-smoother simulate-gates; do grep -q "\"id\": \"$id\"" "$WORK/out" || fail "processor $id not listed"; done

expect_ok "simulate" "$ATHLOS" run "$P" simulate-gates --output gs/imu --param seed=11
expect_ok "orientation" "$ATHLOS" run "$P" orientation --input gs/imu --output gs/q
expect_ok "anchor-smoother" "$ATHLOS" run "$P" anchor-smoother --input gs/imu,gs/q,gs/imu-gates --output gs/anchored
expect_ok "zupt only" "$ATHLOS" run "$P" anchor-smoother --input gs/imu,gs/q,gs/imu-gates --output gs/free \
  --param passes=0 --param start=12,-30,2
for item in imu-truth anchored free anchored-crossings imu-gates; do
  expect_ok "export $item" "$ATHLOS" export "$P" "gs/$item" --to "$WORK/$item.csv"
done
[ "$(($(wc -l < "$WORK/anchored-crossings.csv") - 1))" = "24" ] || fail "expected 24 gate crossings"

# Scores between the first and the last detected crossing: "rmse speed_mean speed_sd". The truth is
# at 200 Hz, the estimate at 100 Hz on block centres (t = k/100 + 0.0025): nearest truth sample.
score() {
  awk -F, -v t0="$2" -v t1="$3" 'NR==FNR { if (FNR > 1) { k = int($1 * 200 + 0.5); x[k] = $2; y[k] = $3; z[k] = $4; s[k] = $8 }; next }
    FNR > 1 && $1 >= t0 && $1 <= t1 { k = int($1 * 200 + 0.5); if (!(k in x)) next
      d2 += ($2 - x[k])^2 + ($3 - y[k])^2 + ($4 - z[k])^2; e = $8 - s[k]; se += e; se2 += e * e; n++ }
    END { if (n < 2) { print "nan nan nan"; exit }; m = se / n; printf "%.4f %.4f %.4f\n", sqrt(d2 / n), m, sqrt(se2 / n - m * m) }' \
    "$WORK/imu-truth.csv" "$1"
}
t0=$(awk -F, 'NR == 2 { print $1 }' "$WORK/anchored-crossings.csv")
t1=$(awk -F, 'END { print $1 }' "$WORK/anchored-crossings.csv")
read -r rmse mu sd < <(score "$WORK/anchored.csv" "$t0" "$t1")
read -r rmse_free _ _ < <(score "$WORK/free.csv" "$t0" "$t1")
echo "anchors: position RMSE $rmse m, speed error $mu ± $sd m/s; ZUPT only: $rmse_free m"
awk -v a="$rmse" 'BEGIN { exit !(a + 0 <= 0.25) }' || fail "position RMSE $rmse m > 0.25 m"
awk -v a="$sd" 'BEGIN { exit !(a + 0 <= 0.2) }' || fail "speed error SD $sd m/s > 0.2 m/s"
awk -v a="$rmse" -v b="$rmse_free" 'BEGIN { exit !(b + 0 > 5 * a) }' || fail "without anchors ($rmse_free m) not much worse than with ($rmse m)"

# GNSS-free gates (ch. 10): three runs on one course, ZUPT-only gate estimates averaged, then a run
# smoothed against the averaged gates (their frame is the runs' mean frame, not the survey's).
for r in 1 2 3; do
  expect_ok "simulate course run $r" "$ATHLOS" run "$P" simulate-gates --output "c$r/imu" --param seed=$((20 + r)) --param course_seed=5
  expect_ok "orientation run $r" "$ATHLOS" run "$P" orientation --input "c$r/imu" --output "c$r/q"
  expect_ok "zupt-only run $r" "$ATHLOS" run "$P" anchor-smoother --input "c$r/imu,c$r/q,c$r/imu-gates" --output "c$r/free" --param passes=0
done
expect_ok "gate average" "$ATHLOS" run "$P" anchor-gate-average --input c1/free-crossings,c2/free-crossings,c3/free-crossings --output course/gates
expect_ok "smooth on averaged gates" "$ATHLOS" run "$P" anchor-smoother --input c1/imu,c1/q,course/gates --output c1/anchored
expect_ok "info" "$ATHLOS" info "$P"
grep -q "course/gates .* 24 rows" "$WORK/out" || fail "averaged gates table does not have 24 rows"

# Refusals: one-line reasons, nothing stored, the file byte-identical.
before=$(sha256sum "$P" | cut -d' ' -f1)
expect_fail "no gates" "recording 'gs'.*no gate crossing found.*threshold 40" \
  "$ATHLOS" run "$P" anchor-smoother --input gs/imu,gs/q,gs/imu-gates --output gs/none --param mag_threshold=40
expect_fail "truth as imu" "input 'gs/imu-truth'" \
  "$ATHLOS" run "$P" anchor-smoother --input gs/imu-truth,gs/q,gs/imu-gates --output gs/none
expect_fail "bad start" "parameter 'start'" \
  "$ATHLOS" run "$P" anchor-smoother --input gs/imu,gs/q,gs/imu-gates --output gs/none --param start=1,2
expect_fail "crossings as gates" "gates table 'gs/anchored-crossings'" \
  "$ATHLOS" run "$P" anchor-smoother --input gs/imu,gs/q,gs/anchored-crossings --output gs/none
# An IMU without magnetometer (imported from CSV): refused, naming the input and the mag columns.
expect_ok "export imu" "$ATHLOS" export "$P" gs/imu --to "$WORK/imu.csv"
cut -d, -f1-7 "$WORK/imu.csv" > "$WORK/imu6.csv"
Q="$WORK/q.athlos"
expect_ok "new q" "$ATHLOS" new "$Q"
expect_ok "import imu6" "$ATHLOS" import "$Q" "$WORK/imu6.csv" --as r --kind imu
expect_ok "orientation imu6" "$ATHLOS" run "$Q" orientation --input r/imu --output r/q
expect_ok "gates csv" "$ATHLOS" run "$Q" simulate-gates --output s/imu --param seed=11
qbefore=$(sha256sum "$Q" | cut -d' ' -f1)
expect_fail "no magnetometer" "input 'r/imu'.*mag_x" \
  "$ATHLOS" run "$Q" anchor-smoother --input r/imu,r/q,s/imu-gates --output r/none
[ "$(sha256sum "$Q" | cut -d' ' -f1)" = "$qbefore" ] || fail "a refused run changed the second project"
expect_fail "average of one run" "run2" \
  "$ATHLOS" run "$P" anchor-gate-average --input c1/free-crossings --output course/one
[ "$(sha256sum "$P" | cut -d' ' -f1)" = "$before" ] || fail "a refused run changed the project"
finish
