#!/usr/bin/env bash
# Drift reduction end to end through `athlos run`: simulate-body (a 40 s skiing run, 8 IMUs with
# gyroscope drift) → orientation (6D) per sensor → drift-reduction → joint-angles, scored against the
# simulator's reference knee and hip angles; the same chain without drift-reduction must be worse.
# Bounds are generous (tests/plugins/inertial/DriftReductionTest.cpp and athlos-eval-drift-reduction
# hold the judged ones). Also: input and parameter errors name what is wrong.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P"
expect_ok "simulate-body" "$ATHLOS" run "$P" simulate-body --output ski/imu --param motion_duration=40 --param seed=2

segments="sacrum sternum right-thigh right-shank right-foot left-thigh left-shank left-foot"
inputs=""
for s in $segments; do
  imu="ski/imu"; q="ski/q"
  [ "$s" = sacrum ] || { imu="ski/imu-$s"; q="ski/q-$s"; }
  expect_ok "orientation $s" "$ATHLOS" run "$P" orientation --input "$imu" --output "$q" --param mode=6d
  inputs="$inputs,$q,$imu"
done
inputs="${inputs#,}"
expect_ok "drift-reduction" "$ATHLOS" run "$P" drift-reduction --input "$inputs" --output ski/dr

# The corrected streams keep the orientation layout.
expect_ok "export dr thigh" "$ATHLOS" export "$P" ski/dr-right-thigh --to "$WORK/dr-thigh.csv"
expect_ok "export q thigh" "$ATHLOS" export "$P" ski/q-right-thigh --to "$WORK/q-thigh.csv"
[ "$(head -1 "$WORK/dr-thigh.csv")" = "$(head -1 "$WORK/q-thigh.csv")" ] ||
  fail "drift-reduction changed the columns: $(head -1 "$WORK/dr-thigh.csv")"
[ "$(wc -l < "$WORK/dr-thigh.csv")" = "$(wc -l < "$WORK/q-thigh.csv")" ] || fail "drift-reduction changed the row count"

# rmse <estimate.csv> <reference.csv> <from s> <to s> → flexion RMSE in degrees
rmse() {
  awk -F, -v a="$3" -v b="$4" 'NR==FNR { if (FNR > 1) e[FNR] = $2; next }
       FNR > 1 && $1 >= a && $1 <= b { d = e[FNR] - $2; s += d*d; m++ }
       END { if (m == 0) { print "nan"; exit } printf "%.3f\n", sqrt(s/m) * 180 / 3.141592653589793 }' "$1" "$2"
}
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 < b + 0) }'; }
# The motion phase of the simulation: after the calibration block (10 s upright, 3 squats of 4 s, 3 s
# standing) for 40 s.
from=25; to=65
for side in right left; do
  for joint in knee hip; do
    if [ $joint = knee ]; then prox="$side-thigh"; dist="$side-shank"; else prox=sacrum; dist="$side-thigh"; fi
    pq="ski/q"; pd="ski/dr"
    [ "$prox" = sacrum ] || { pq="ski/q-$prox"; pd="ski/dr-$prox"; }
    expect_ok "$side $joint without" "$ATHLOS" run "$P" joint-angles --input "$pq,ski/q-$dist,ski/imu-$side-mounts" \
      --output "ski/$side-$joint-raw" --param joint=$joint --param side=$side
    expect_ok "$side $joint with" "$ATHLOS" run "$P" joint-angles --input "$pd,ski/dr-$dist,ski/imu-$side-mounts" \
      --output "ski/$side-$joint-dr" --param joint=$joint --param side=$side --param heading=none
    for v in raw dr; do
      expect_ok "export $side $joint $v" "$ATHLOS" export "$P" "ski/$side-$joint-$v" --to "$WORK/$side-$joint-$v.csv"
    done
    expect_ok "export reference" "$ATHLOS" export "$P" "ski/imu-$side-$joint-reference" --to "$WORK/$side-$joint-ref.csv"
    raw=$(rmse "$WORK/$side-$joint-raw.csv" "$WORK/$side-$joint-ref.csv" $from $to)
    dr=$(rmse "$WORK/$side-$joint-dr.csv" "$WORK/$side-$joint-ref.csv" $from $to)
    echo "$side $joint flexion RMSE: without $raw deg, with drift-reduction $dr deg"
    below "$dr" 3 || fail "$side $joint flexion RMSE with drift-reduction $dr deg (bound 3)"
    below "$dr" "$raw" || fail "$side $joint: drift-reduction ($dr deg) is not better than without ($raw deg)"
  done
done

# A joint whose heading is unobservable (here forced: no coherence is ever 1) is left uncorrected and says why.
expect_ok "info" "$ATHLOS" info "$P" --json
grep -q '"heading_aligned": true' "$WORK/out" || fail "no heading_aligned attribute after drift-reduction"
# static_correction=auto: the inputs come from VQF (a filter), so the static correction is off and says why.
grep -q '"static_correction": false' "$WORK/out" || fail "static_correction=auto did not turn it off for VQF input"
grep -q '"static_correction_reason": "auto: .ski/q. is from vqf, not a gyroscope integration"' "$WORK/out" ||
  fail "no reason for the static correction: $(grep -o '"static_correction_reason": "[^"]*"' "$WORK/out" | head -1)"
expect_ok "drift-reduction unobservable heading" "$ATHLOS" run "$P" drift-reduction \
  --input "ski/q,ski/imu,ski/q-sternum,ski/imu-sternum,ski/q-right-thigh,ski/imu-right-thigh" \
  --output ski/dr1 --param segments=sacrum,sternum,right-thigh --param min_heading_coherence=1
expect_ok "info after" "$ATHLOS" info "$P" --json
grep -q '"heading_aligned": false' "$WORK/out" || fail "heading_aligned=false missing for an unobservable heading"
grep -q '"heading_unobservable": "joint sacrum → right-thigh: the heading differences' "$WORK/out" ||
  fail "no reason for the unobservable heading: $(grep -o '"heading_unobservable": "[^"]*"' "$WORK/out" | head -2)"

expect_fail "odd input count" "pairs" "$ATHLOS" run "$P" drift-reduction \
  --input "ski/q,ski/imu,ski/q-sternum,ski/imu-sternum,ski/q-right-thigh" --output ski/x
expect_fail "root first" "sacrum" "$ATHLOS" run "$P" drift-reduction --input "ski/q-sternum,ski/imu-sternum,ski/q,ski/imu" \
  --output ski/x --param segments=sternum,sacrum
expect_fail "unknown segment" "segments" "$ATHLOS" run "$P" drift-reduction --input "ski/q,ski/imu,ski/q-sternum,ski/imu-sternum" \
  --output ski/x --param segments=sacrum,neck
expect_fail "estimation rate too low" "estimation_rate" "$ATHLOS" run "$P" drift-reduction \
  --input "ski/q,ski/imu,ski/q-sternum,ski/imu-sternum" --output ski/x --param estimation_rate=5
expect_fail "missing parent" "right-thigh" "$ATHLOS" run "$P" drift-reduction --input "ski/q,ski/imu,ski/q-right-shank,ski/imu-right-shank" \
  --output ski/x --param segments=sacrum,right-shank
expect_fail "imu as orientation" "orientation" "$ATHLOS" run "$P" drift-reduction --input "ski/imu,ski/imu,ski/q-sternum,ski/imu-sternum" \
  --output ski/x
finish
