#!/usr/bin/env bash
# Functional calibration protocol end to end through `athlos run` (issue #17 item 4): simulate-body with the
# whole protocol (upright, squats, trunk rotations, hip ab/adduction per leg) → functional-calibration on the
# eight IMUs → every mount within 3° of the simulator's true mounts, the quality and movements tables filled,
# and joint-angles reads the per-side table. Refusals (no squats, bad intervals, unknown segment, an arm
# sensor without arm swings) name the reason and leave the project byte-identical.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P"
expect_ok "simulate-body" "$ATHLOS" run "$P" simulate-body --output cal/imu --param scenario=squats \
  --param motion_duration=4 --param trunk_rotations=3 --param hip_abductions=3 --param seed=11

segments="sacrum sternum right-thigh right-shank right-foot left-thigh left-shank left-foot"
inputs=""
for s in $segments; do
  imu="cal/imu"
  [ "$s" = sacrum ] || imu="cal/imu-$s"
  inputs="$inputs,$imu"
done
inputs="${inputs#,}"
expect_ok "functional-calibration" "$ATHLOS" run "$P" functional-calibration --input "$inputs" --output cal/fc
for t in fc fc-right fc-quality fc-movements imu-right-mounts imu-left-mounts; do
  expect_ok "export $t" "$ATHLOS" export "$P" "cal/$t" --to "$WORK/$t.csv"
done
head -1 "$WORK/fc-quality.csv" | grep -q "dispersion" || fail "quality columns: $(head -1 "$WORK/fc-quality.csv")"
[ "$(wc -l < "$WORK/fc-quality.csv")" = 9 ] || fail "quality table: $(wc -l < "$WORK/fc-quality.csv") lines, expected 9"
for m in upright squats trunk-rotations right-abduction left-abduction; do
  grep -q "^$m," "$WORK/fc-movements.csv" || fail "movement $m not found: $(cat "$WORK/fc-movements.csv")"
done

# angle <estimated.csv> <true.csv> <segment as in the estimate> <segment as in the truth> → degrees
angle() {
  awk -F, -v a="$3" -v b="$4" 'NR==FNR { if ($1 == a) { w=$2; x=$3; y=$4; z=$5 } next }
       $1 == b { d = w*$2 + x*$3 + y*$4 + z*$5; if (d < 0) d = -d; if (d > 1) d = 1;
                 printf "%.3f\n", 2 * atan2(sqrt(1 - d*d), d) * 180 / 3.141592653589793 }' "$1" "$2"
}
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 < b + 0) }'; }
for side in right left; do
  for pair in sacrum:pelvis sternum:thorax $side-thigh:thigh $side-shank:shank $side-foot:foot; do
    e=$(angle "$WORK/fc.csv" "$WORK/imu-$side-mounts.csv" "${pair%%:*}" "${pair##*:}")
    echo "${pair%%:*} mount error: $e deg"
    [ -n "$e" ] && below "$e" 3 || fail "${pair%%:*}: mount error '$e' deg (bound 3)"
  done
done
# The per-side table is what joint-angles reads.
expect_ok "orientation thigh" "$ATHLOS" run "$P" orientation --input cal/imu-right-thigh --output cal/q-thigh --param mode=6d
expect_ok "orientation shank" "$ATHLOS" run "$P" orientation --input cal/imu-right-shank --output cal/q-shank --param mode=6d
expect_ok "joint-angles" "$ATHLOS" run "$P" joint-angles --input cal/q-thigh,cal/q-shank,cal/fc-right \
  --output cal/knee --param joint=knee

# Refusals: each names the culprit and leaves the file byte-identical.
expect_ok "simulate-body without squats" "$ATHLOS" run "$P" simulate-body --output nosq/imu --param scenario=squats \
  --param motion_duration=4 --param squats=0 --param trunk_rotations=3 --param hip_abductions=3
before=$(sha256sum "$P" | cut -d' ' -f1)
expect_fail "no squats" "no squats" "$ATHLOS" run "$P" functional-calibration \
  --input nosq/imu,nosq/imu-right-thigh --output nosq/fc --param segments=sacrum,right-thigh
expect_fail "bad intervals" "intervals" "$ATHLOS" run "$P" functional-calibration --input cal/imu --output cal/x \
  --param segments=sacrum --param intervals="squats=12"
expect_fail "names do not match the inputs" "segments: 8 name" "$ATHLOS" run "$P" functional-calibration \
  --input cal/imu,cal/imu-sternum --output cal/x
expect_fail "unknown segment" "tail" "$ATHLOS" run "$P" functional-calibration --input cal/imu --output cal/x \
  --param segments=tail
# An arm sensor needs the optional arm swings (here the right foot's IMU stands in for an upper arm).
expect_fail "arm without arm swings" "right-upper-arm.*no arm-swings" "$ATHLOS" run "$P" functional-calibration \
  --input cal/imu,cal/imu-right-thigh,cal/imu-left-thigh,cal/imu-right-foot --output cal/x \
  --param segments=sacrum,right-thigh,left-thigh,right-upper-arm
expect_fail "bad interval name" "arm-swings" "$ATHLOS" run "$P" functional-calibration --input cal/imu --output cal/x \
  --param segments=sacrum --param intervals="arm-swing=70-80"
after=$(sha256sum "$P" | cut -d' ' -f1)
[ "$before" = "$after" ] || fail "a refused run changed the project"
finish
