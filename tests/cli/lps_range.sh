#!/usr/bin/env bash
# Real UWB recordings in with one command: the four per-anchor ROS range files of a case become one
# lps-range stream (auto-detected ROS CSV, ns stamps), the same files with --kind beacons the beacon
# table, and the range stream exports back in long form. A folder imports one stream per athlete.
source "$(dirname "$0")/lib/common.bash" "$@"
need_shared uwb-outdoor/NLOS_Trajectory_B_Case_3
P="$WORK/p.athlos"
CASE="$SHARED_DATA/uwb-outdoor/NLOS_Trajectory_B_Case_3"
expect_ok "new" "$ATHLOS" new "$P"
cp "$P" "$WORK/before.athlos"

expect_fail "mixed kinds" "is of kind" "$ATHLOS" import "$P" "$CASE/A3.csv" "$CASE/gnss.csv" --as uwb/range
cmp -s "$P" "$WORK/before.athlos" || fail "a failed import changed the project"

expect_ok "ranges" "$ATHLOS" import "$P" "$CASE"/A3.csv "$CASE"/A5.csv "$CASE"/A9.csv "$CASE"/A12.csv --as uwb --kind lps-range
grep -q "imported uwb/range" "$WORK/out" || fail "stream name: $(cat "$WORK/out")"
expect_ok "beacons" "$ATHLOS" import "$P" "$CASE"/A3.csv "$CASE"/A5.csv "$CASE"/A9.csv "$CASE"/A12.csv --as uwb --kind beacons
"$ATHLOS" info "$P" --json > "$WORK/info.json" 2>/dev/null || fail "info --json"
grep -q '"kind": *"lps-range"' "$WORK/info.json" || fail "no lps-range stream"
rows=$(awk 'FNR > 1 && NF' "$CASE"/A3.csv "$CASE"/A5.csv "$CASE"/A9.csv "$CASE"/A12.csv | wc -l)
expect_ok "export ranges" "$ATHLOS" export "$P" uwb/range --to "$WORK/range.csv"
[ "$(head -1 "$WORK/range.csv")" = "t,beacon,range" ] || fail "long header: $(head -1 "$WORK/range.csv")"
[ "$(awk 'NR > 1 && NF' "$WORK/range.csv" | wc -l)" = "$rows" ] || fail "measurements: $(wc -l < "$WORK/range.csv") lines for $rows"
[ "$(cut -d, -f2 "$WORK/range.csv" | sort -u | tr '\n' ' ')" = "12 3 5 9 beacon " ] || fail "beacon ids"
expect_ok "export beacons" "$ATHLOS" export "$P" uwb/beacons --to "$WORK/beacons.csv"
[ "$(wc -l < "$WORK/beacons.csv")" = 5 ] || fail "beacon table: $(cat "$WORK/beacons.csv")"
grep -q '^12,-0.05,0.87,0.5$' "$WORK/beacons.csv" || fail "anchor 12: $(cat "$WORK/beacons.csv")"

# A folder: one stream per file, the athletes from a roster.
mkdir "$WORK/team"
printf 't,x,y\n0,1,2\n1,2,3\n' > "$WORK/team/p07.csv"
printf 't,x,y\n0,5,5\n1,6,6\n' > "$WORK/team/p09.csv"
printf 'file,athlete,number,team,position,mass_kg\np07.csv,Anna Berg,7,home,FW,61.5\np09,Ben Lee,9,away,GK,80\n' > "$WORK/roster.csv"
expect_ok "folder" "$ATHLOS" import "$P" "$WORK/team" --as match --kind lps-position --roster "$WORK/roster.csv"
"$ATHLOS" info "$P" --json > "$WORK/info.json" 2>/dev/null
grep -q '"path": *"match/p07"' "$WORK/info.json" || fail "folder stream names"
grep -q '"athlete": *"Ben Lee"' "$WORK/info.json" || fail "roster athlete"
grep -q '"mass_kg": *61.5' "$WORK/info.json" || fail "roster mass"
expect_fail "roster without folder" "--roster applies to a folder import" \
  "$ATHLOS" import "$P" "$WORK/team/p07.csv" --as x --roster "$WORK/roster.csv"
finish
