#!/usr/bin/env bash
# Scrum detection on the command line (seed 000 §5.1.2): simulate-rugby writes a rugby sevens match
# (IMU and positions of 14 players in one recording, the true scrums and tackles as annotations),
# detect-scrums finds the scrums from the top-6 torso pitch of all players; both exported as CSV.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"

expect_ok "new" "$ATHLOS" new "$P"
cp "$P" "$WORK/before.athlos"
expect_fail "too short" "parameter 'duration' .100 s. is too short for 24 events" \
  "$ATHLOS" run "$P" simulate-rugby --output m/sim --param duration=100
cmp -s "$P" "$WORK/before.athlos" || fail "a refused command changed the project"

expect_ok "simulate" "$ATHLOS" run "$P" simulate-rugby --output match/sim --param seed=3 --param duration=240 \
  --param scrums=2 --param tackles=3 --param contacts=1 --param falls=1
expect_ok "detect" "$ATHLOS" run "$P" detect-scrums --input match/sim-imu-away-07 --output match/scrums
expect_ok "export" "$ATHLOS" export "$P" match/annotations --to "$WORK/x.csv"
truth=$(awk -F, '$3 == "scrum" && $5 == "simulate-rugby"' "$WORK/x.csv" | wc -l)
found=$(awk -F, '$3 == "scrum" && $5 == "detect-scrums"' "$WORK/x.csv" | wc -l)
[ "$truth" -eq 2 ] || fail "expected 2 true scrums, got $truth: $(cat "$WORK/x.csv")"
[ "$found" -eq 2 ] || fail "expected 2 detected scrums, got $found: $(cat "$WORK/x.csv")"
# Each detection overlaps its true scrum, its ends within a second.
awk -F, '$3 == "scrum" && $5 == "simulate-rugby" { ts[n] = $1; te[n++] = $2 }
  $3 == "scrum" && $5 == "detect-scrums" { ds[m] = $1; de[m++] = $2 }
  END { for (i = 0; i < n; i++) { d = ds[i] - ts[i]; e = de[i] - te[i];
          if (d < -1 || d > 1 || e < -1 || e > 1) { print "scrum " i ": " ds[i] "-" de[i] " vs " ts[i] "-" te[i]; exit 1 } } }' \
  "$WORK/x.csv" > "$WORK/cmp" || fail "$(cat "$WORK/cmp")"

expect_fail "too many players" "players" \
  "$ATHLOS" run "$P" detect-scrums --input match/sim-imu-away-07 --output match/scrums --param players=20
finish
