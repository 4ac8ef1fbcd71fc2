#!/usr/bin/env bash
# Team and history (issue #15 item 2): an athlete's sessions in three projects, dated by their import
# (--start), against the rolling 4-week baseline; a session at twice the baseline distance is flagged.
source "$(dirname "$0")/lib/common.bash" "$@"
# 300 s of walking-pace laps (speed m/s given) on a 30-m circle, 10 Hz, no noise.
circle() { awk -v v="$1" 'BEGIN { print "t,x,y"; for (k = 0; k <= 3000; k++) { s = v * k / 10
  printf "%.1f,%.4f,%.4f\n", k / 10, 30 * sin(s / 30), 30 * (1 - cos(s / 30)) } }' > "$2"; }
day=0
for v in 2 2 4; do
  day=$((day + 7))
  circle "$v" "$WORK/s$day.csv"
  expect_ok "new $day" "$ATHLOS" new "$WORK/p$day.athlos"
  expect_ok "import $day" "$ATHLOS" import "$WORK/p$day.athlos" "$WORK/s$day.csv" --as s --kind lps-position \
    --start "2026-10-$(printf %02d $day)T10:00:00Z" --athlete Anna
  expect_ok "metrics $day" "$ATHLOS" run "$WORK/p$day.athlos" session-metrics --input s/lps --output s/metrics
done
expect_ok "history" "$ATHLOS" history "$WORK/p7.athlos" "$WORK/p14.athlos" "$WORK/p21.athlos" --to "$WORK/h.csv" \
  --metrics distance,max_speed
grep -q "wrote .*h.csv (3 sessions, 1 flagged)" "$WORK/out" || fail "history: $(cat "$WORK/out")"
grep -q "2026-10-21.*Anna.*distance high; max_speed high" "$WORK/out" || fail "history flags: $(cat "$WORK/out")"
[ "$(wc -l < "$WORK/h.csv")" -eq 4 ] || fail "h.csv: $(cat "$WORK/h.csv")"
head -1 "$WORK/h.csv" | grep -q '^athlete,session,date,distance,distance_baseline,distance_ratio' || fail "header: $(head -1 "$WORK/h.csv")"
expect_fail "unknown metric" "metric 'tackles'" "$ATHLOS" history "$WORK/p7.athlos" --to "$WORK/x.csv" --metrics tackles
# A session without a date cannot be placed in time: refused, naming it.
expect_ok "new undated" "$ATHLOS" new "$WORK/undated.athlos"
expect_ok "import undated" "$ATHLOS" import "$WORK/undated.athlos" "$WORK/s7.csv" --as u --kind lps-position
expect_ok "metrics undated" "$ATHLOS" run "$WORK/undated.athlos" session-metrics --input u/lps --output u/metrics
expect_fail "no date" "undated.athlos: u/metrics: the session has no date" "$ATHLOS" history "$WORK/undated.athlos" --to "$WORK/x.csv"
finish
