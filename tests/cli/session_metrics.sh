#!/usr/bin/env bash
# Coach sessions (issue #15): session-metrics on GNSS lat/lon as a vendor exports it (distance within 3 %,
# max speed within 0.5 m/s of the truth), and `athlos report` over a folder of player CSVs: metrics
# computed for every player, the project saved with them, a team page plus a page per player, the team
# table as CSV; a second report computes nothing; bad input is refused and changes nothing.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P"

# --- GNSS: 60 s standing, 600 s around a 40-m circle at 4.5 m/s (2700 m), 60 s standing; 10 Hz fixes
# with 0.15 m white noise and a slowly wandering offset, as lat/lon with 7 decimals (1 cm).
awk 'BEGIN { srand(7); print "t,lat,lon"; pi = 3.141592653589793; R = 6378137; lat0 = 48.137; lon0 = 11.575
  ox = 0; oy = 0
  for (k = 0; k <= 7200; k++) { t = k / 10; s = 4.5 * (t < 60 ? 0 : (t > 660 ? 600 : t - 60))
    x = 40 * sin(s / 40); y = 40 * (1 - cos(s / 40))
    u1 = rand(); u2 = rand(); g1 = sqrt(-2 * log(u1 + 1e-12)) * cos(2 * pi * u2); g2 = sqrt(-2 * log(u1 + 1e-12)) * sin(2 * pi * u2)
    ox = 0.999 * ox + 0.004 * (rand() - 0.5); oy = 0.999 * oy + 0.004 * (rand() - 0.5)
    x += 0.15 * g1 + ox; y += 0.15 * g2 + oy
    printf "%.1f,%.7f,%.7f\n", t, lat0 + y / R * 180 / pi, lon0 + x / (R * cos(lat0 * pi / 180)) * 180 / pi } }' > "$WORK/gnss.csv"
expect_ok "import gnss" "$ATHLOS" import "$P" "$WORK/gnss.csv" --as s1 --kind gnss
expect_ok "session-metrics" "$ATHLOS" run "$P" session-metrics --input s1/gnss --output s1/metrics
expect_ok "export metrics" "$ATHLOS" export "$P" s1/metrics --to "$WORK/metrics.csv"
head -1 "$WORK/metrics.csv" | grep -q '^period,start \[s\],end \[s\],duration \[s\],distance \[m\],max_speed \[m/s\],distance_zone1 \[m\]' \
  || fail "metrics header: $(head -1 "$WORK/metrics.csv")"
grep -q 'hsr_distance \[m\],sprint_count \[1\],acceleration_count \[1\],deceleration_count \[1\],peak_distance_1min \[m\],peak_distance_3min \[m\],peak_distance_5min \[m\],metabolic_energy \[J/kg\],metabolic_power \[W/kg\]' "$WORK/metrics.csv" \
  || fail "metrics columns: $(head -1 "$WORK/metrics.csv")"
awk -F, '$1 == "whole" { d = $5; v = $6 } END {
  if (d < 2700 * 0.97 || d > 2700 * 1.03) { print "distance " d " m, truth 2700 m"; exit 1 }
  if (v < 4.0 || v > 5.0) { print "max speed " v " m/s, truth 4.5 m/s"; exit 1 } }' "$WORK/metrics.csv" > "$WORK/check" \
  || fail "gnss metrics: $(cat "$WORK/check")"
# Raw fixes overstate the distance: the comparison the validation page shows.
expect_ok "session-metrics raw" "$ATHLOS" run "$P" session-metrics --input s1/gnss --output s1/raw --param filter=none
expect_ok "export raw" "$ATHLOS" export "$P" s1/raw --to "$WORK/raw.csv"
awk -F, '$1 == "whole" && $5 < 2700 * 1.1 { exit 1 }' "$WORK/raw.csv" || fail "raw distance not overstated"

# --- Parameters are checked and name themselves; nothing is written.
cp "$P" "$WORK/before.athlos"
expect_fail "bad zones" "zones" "$ATHLOS" run "$P" session-metrics --input s1/gnss --output s1/m2 --param zones=0,20,10
cmp -s "$P" "$WORK/before.athlos" || fail "bad zones: the project changed"

# --- Report: a 5-min simulated match, 22 players exported as t,x,y with noise, imported as a folder.
T="$WORK/team.athlos"
expect_ok "new team" "$ATHLOS" new "$T"
expect_ok "simulate" "$ATHLOS" run "$T" simulate-team --output sim/player --param duration=300
mkdir -p "$WORK/players"
for side in home away; do for n in 01 02 03 04 05 06 07 08 09 10 11; do
  "$ATHLOS" export "$T" "sim/player-$side-$n" --to "$WORK/truth.csv" >/dev/null || fail "export $side-$n"
  awk -F, -v seed="$n" 'BEGIN { srand(seed) } NR == 1 { print "t,x,y"; next }
    { printf "%s,%.3f,%.3f\n", $1, $2 + 0.1 * (rand() + rand() + rand() - 1.5) * 2, $3 + 0.1 * (rand() + rand() + rand() - 1.5) * 2 }' \
    "$WORK/truth.csv" > "$WORK/players/$side-$n.csv"
done; done
M="$WORK/match.athlos"
expect_ok "new match" "$ATHLOS" new "$M"
expect_ok "import folder" "$ATHLOS" import "$M" "$WORK/players" --as match --kind lps-position
expect_ok "report" "$ATHLOS" report "$M" --to "$WORK/report.pdf" --csv "$WORK/team.csv"
grep -q "computed session metrics for 22 of 22 athletes" "$WORK/out" || fail "report: $(cat "$WORK/out")"
head -c 5 "$WORK/report.pdf" | grep -q '%PDF-' || fail "report.pdf is not a PDF"
pages=$(grep -a -o '/Type */Page\b' "$WORK/report.pdf" | wc -l)
[ "$pages" -eq 23 ] || fail "report.pdf has $pages pages, expected 23 (team + 22 players)"
[ "$(wc -l < "$WORK/team.csv")" -eq 23 ] || fail "team.csv has $(wc -l < "$WORK/team.csv") lines"
head -1 "$WORK/team.csv" | grep -q '^athlete,team,positions,start \[s\]' || fail "team.csv header: $(head -1 "$WORK/team.csv")"
"$ATHLOS" info "$M" > "$WORK/info"; grep -q 'match/home-01-metrics ' "$WORK/info" || fail "metrics not saved in the project"
# Up to date: a second report computes nothing and leaves the project as it is.
cp "$M" "$WORK/match-before.athlos"
expect_ok "report again" "$ATHLOS" report "$M" --to "$WORK/report2.pdf"
grep -q "computed session metrics for 0 of 22 athletes" "$WORK/out" || fail "report again: $(cat "$WORK/out")"
cmp -s "$M" "$WORK/match-before.athlos" || fail "report again: the project changed"

# --- No athletes: a clear error, the project untouched, no PDF.
cp "$P" "$WORK/before.athlos"
expect_fail "no athletes" "recording 'nothing'|no such recording" "$ATHLOS" report "$P" --to "$WORK/none.pdf" --recording nothing
[ ! -e "$WORK/none.pdf" ] || fail "a PDF was written for a failed report"
cmp -s "$P" "$WORK/before.athlos" || fail "no athletes: the project changed"
finish
