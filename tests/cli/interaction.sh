#!/usr/bin/env bash
# Tackle classification with multi-athlete interaction features on the command line (seed 000 §5.1.2,
# issue #14 item 2): simulate-rugby writes three training matches and a test match (IMU and positions of
# 14 players per recording, athlete and team attributes, the true tackles as annotations); athlos train
# learns from every player's IMU stream (--input 'sim-imu-*') on tackle candidates with the torso pitch
# and the 3 nearest opponents; classify-actions gathers the same session at prediction time, and refuses
# a stream without one.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"

expect_ok "new" "$ATHLOS" new "$P"
for m in 1 2 3 4; do
  expect_ok "simulate m$m" "$ATHLOS" run "$P" simulate-rugby --output "m$m/sim" --param seed=$((20 + m)) \
    --param duration=255 --param scrums=0 --param tackles=4 --param contacts=3 --param falls=2 \
    --param imu_rate=100 --param position_rate=20
done
cp "$P" "$WORK/before.athlos"
expect_fail "interaction needs events" "--interaction goes with event segmentation" \
  "$ATHLOS" train "$P" --model t --input 'sim-imu-*' --interaction k=3
expect_fail "interaction needs k" "--interaction 'n=3': unknown key 'n'" \
  "$ATHLOS" train "$P" --model t --input 'sim-imu-*' --segmentation events:tackle --interaction n=3
cmp -s "$P" "$WORK/before.athlos" || fail "a refused command changed the project"

expect_ok "train" "$ATHLOS" train "$P" --model t --input 'sim-imu-*' --recordings m1,m2,m3 --window 4 \
  --segmentation events:tackle --classes tackle,null --interaction k=3 --trees 50
grep -q "interaction features: torso pitch and speed of the player, distance, speed and torso pitch of the 3 nearest opponents" \
  "$WORK/out" || fail "no interaction features: $(head -3 "$WORK/out")"
grep -q "from 42 streams of 3 recordings, 253 features" "$WORK/out" || fail "sources or features: $(grep windows "$WORK/out")"
grep -q "cross-validation (leave-one-athlete-out, random-forest, 10 folds)" "$WORK/out" || fail "no cross-validation: $(cat "$WORK/out")"
grep -qE "^stored model 't' \(random-forest, 2 classes" "$WORK/out" || fail "model not stored: $(tail -1 "$WORK/out")"
cv=$(awk '/^balanced accuracy/ {print $3; exit}' "$WORK/out" | tr -d ,)
awk -v a="$cv" 'BEGIN { exit !(a >= 0.8) }' || fail "cross-validated balanced accuracy $cv < 0.8"

for player in home-01 home-02 home-03 home-04 home-05 home-06 home-07 away-01 away-02 away-03 away-04 away-05 away-06 away-07; do
  expect_ok "classify $player" "$ATHLOS" run "$P" classify-actions --input "m4/sim-imu-$player" \
    --output "m4/tackles-$player" --param model=t
done
expect_ok "export" "$ATHLOS" export "$P" m4/annotations --to "$WORK/x.csv"
# Each true tackle (2 players) should be found on its players; the predictions lie within 1 s of one
# (two false alarms tolerated).
truth=$(awk -F, '$3 == "tackle" && $5 == "simulate-rugby"' "$WORK/x.csv" | wc -l)
found=$(awk -F, '$3 == "tackle" && $5 == "classify-actions"' "$WORK/x.csv" | wc -l)
[ "$truth" -eq 4 ] || fail "expected 4 true tackles, got $truth"
[ "$found" -ge 5 ] && [ "$found" -le 11 ] || fail "expected about 8 classified player tackles, got $found: $(cat "$WORK/x.csv")"
awk -F, '$3 == "tackle" && $5 == "simulate-rugby" { ts[n] = $1; te[n++] = $2 }
  $3 == "tackle" && $5 == "classify-actions" { c = ($1 + $2) / 2; ok = 0
    for (i = 0; i < n; i++) if (c >= ts[i] - 1 && c <= te[i] + 1) ok = 1
    if (!ok) { bad++; print "classified tackle at " c " is no true tackle" } }
  END { exit bad > 2 }' "$WORK/x.csv" > "$WORK/cmp" || fail "$(cat "$WORK/cmp")"

# A stream outside a team session: refused, naming the stream.
make_imu_csv "$WORK/solo.csv" 3000
expect_ok "import solo" "$ATHLOS" import "$P" "$WORK/solo.csv" --as solo --kind imu
expect_fail "no session" "solo/imu.*athlete" \
  "$ATHLOS" run "$P" classify-actions --input solo/imu --output solo/tackles --param model=t
finish
