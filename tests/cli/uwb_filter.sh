#!/usr/bin/env bash
# Tightly coupled range filtering on the real outdoor UWB recordings (issue #16, the judged flow): each
# case converted to `t,beacon,range` and `id,x,y,z`, imported, `position-filter` with noise=auto at
# 10 Hz and tag_height 1.0, exported, and scored like the dataset authors score their tracks
# (athlos-eval-uwb: 2D RMSE over one lap). Each case must beat the authors' ESKF by 25 %, the mean
# must be ≤ 0.6 × the ESKF mean; per-instant ToA fixes from lps-positioning must beat the authors' LS. Then the refusals: ranges without beacons, unknown beacon ids,
# model=pseudo, filter=ukf — each naming the cause and leaving the project unchanged.
source "$(dirname "$0")/lib/common.bash" "$@"
need_shared uwb-outdoor/LOS_Trajectory_A_Case_1 uwb-outdoor/NLOS_Trajectory_B_Case_3
EVAL="$(dirname "$ATHLOS")/athlos-eval-uwb"
[ -x "$EVAL" ] || { echo "athlos-eval-uwb not built"; exit 77; }
sum_ours=0; sum_eskf=0
for spec in LOS_Trajectory_A_Case_1:A NLOS_Trajectory_B_Case_3:B; do
  name=${spec%%:*}; lap=${spec##*:}; CASE="$SHARED_DATA/uwb-outdoor/$name"; P="$WORK/$name.athlos"
  [ -d "$CASE" ] || { fail "$CASE missing"; continue; }
  { echo t,beacon,range; for f in "$CASE"/A*.csv; do awk -F, 'NR > 1 { printf "%.9f,%s,%s\n", $2 / 1e9, $3, $7 }' "$f"; done |
      sort -t, -k1,1g; } > "$WORK/ranges.csv"
  { echo id,x,y,z; for f in "$CASE"/A*.csv; do awk -F, 'NR == 2 { print $3 "," $4 "," $5 "," $6 }' "$f"; done; } > "$WORK/beacons.csv"
  expect_ok "new" "$ATHLOS" new "$P"
  expect_ok "import ranges" "$ATHLOS" import "$P" "$WORK/ranges.csv" --as case/ranges --kind lps-range
  expect_ok "import beacons" "$ATHLOS" import "$P" "$WORK/beacons.csv" --as case/beacons --kind beacons
  cp "$P" "$WORK/before.athlos"
  expect_fail "ranges without beacons" "beacon table" \
    "$ATHLOS" run "$P" position-filter --input case/ranges --output case/track
  expect_fail "pseudo" "model=pseudo" "$ATHLOS" run "$P" position-filter --input case/ranges,case/beacons \
    --output case/track --param model=pseudo
  expect_fail "ukf" "EKF only" "$ATHLOS" run "$P" position-filter --input case/ranges,case/beacons \
    --output case/track --param filter=ukf
  expect_fail "profile" "noise of position fixes" "$ATHLOS" run "$P" position-filter \
    --input case/ranges,case/beacons --output case/track --param noise=profile:case/beacons
  cmp -s "$P" "$WORK/before.athlos" || fail "$name: a refused run changed the project"
  expect_ok "filter" "$ATHLOS" run "$P" position-filter --input case/ranges,case/beacons --output case/track \
    --param noise=auto --param output_rate=10 --param tag_height=1.0
  expect_ok "export" "$ATHLOS" export "$P" case/track --to "$WORK/track.csv"
  head -1 "$WORK/track.csv" | grep -q "sd_x" || fail "$name: no per-fix uncertainty: $(head -1 "$WORK/track.csv")"
  "$EVAL" --reference "$CASE/trajectory.csv" --lap "$lap" "$WORK/track.csv" "$CASE/ESKF.csv" > "$WORK/score" ||
    fail "$name: scoring failed"
  cat "$WORK/score"
  ours=$(awk 'NR == 1 { print $5 }' "$WORK/score"); eskf=$(awk 'NR == 2 { print $5 }' "$WORK/score")
  awk -v a="$ours" -v b="$eskf" 'BEGIN { exit !(a <= 0.75 * b) }' || fail "$name: RMSE $ours m is not 25 % below the ESKF's $eskf m"
  # Per-instant ToA fixes (lps-positioning on ranges) beat the authors' per-epoch least squares.
  expect_ok "toa fixes" "$ATHLOS" run "$P" lps-positioning --input case/ranges,case/beacons --output case/toa \
    --param tag_height=1.0
  expect_ok "export fixes" "$ATHLOS" export "$P" case/toa --to "$WORK/toa.csv"
  "$EVAL" --reference "$CASE/trajectory.csv" --lap "$lap" "$WORK/toa.csv" "$CASE/LS.csv" > "$WORK/score" ||
    fail "$name: scoring the fixes failed"
  cat "$WORK/score"
  awk 'NR == 1 { a = $5 } NR == 2 { b = $5 } END { exit !(a < b) }' "$WORK/score" || fail "$name: ToA fixes not better than LS"
  expect_fail "toa selection" "applies to TDoA" "$ATHLOS" run "$P" lps-positioning --input case/ranges,case/beacons \
    --output case/toa2 --param selection=field-of-view
  sum_ours=$(awk -v s="$sum_ours" -v a="$ours" 'BEGIN { print s + a }')
  sum_eskf=$(awk -v s="$sum_eskf" -v a="$eskf" 'BEGIN { print s + a }')
done
awk -v a="$sum_ours" -v b="$sum_eskf" 'BEGIN { exit !(a <= 0.6 * b) }' || fail "mean RMSE $sum_ours/2 m is above 0.6 × the ESKF mean $sum_eskf/2 m"

# Ids the beacon table does not have.
P="$WORK/ids.athlos"
printf 't,beacon,range\n0,A,5\n0.1,B,6\n0.2,C,7\n' > "$WORK/r.csv"
printf 'id,x,y,z\nA,0,0,1\nB,5,0,1\nD,0,5,1\n' > "$WORK/b.csv"
expect_ok "new" "$ATHLOS" new "$P"
expect_ok "import" "$ATHLOS" import "$P" "$WORK/r.csv" --as r/ranges --kind lps-range
expect_ok "import" "$ATHLOS" import "$P" "$WORK/b.csv" --as r/beacons --kind beacons
expect_fail "unknown id" "beacon id\(s\) C" "$ATHLOS" run "$P" position-filter --input r/ranges,r/beacons --output r/track
finish
