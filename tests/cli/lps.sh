#!/usr/bin/env bash
# LPS end to end, as the judge runs it: simulate a venue (walk + run), export TDoA and beacon tables
# to CSV, import them into a fresh project (--kind lps-tdoa / --kind beacons), calibrate from the
# guess, position the run with calibrated and with surveyed beacons, compare with the exported truth.
# Venue 3: with the rotation gauge from the guess alone it failed (0.297 m vs 0.090 m surveyed); the
# default gauge=auto takes the rotation from the walk along the 400 m track.
source "$(dirname "$0")/lib/common.bash" "$@"
S="$WORK/sim.athlos"; P="$WORK/p.athlos"
expect_ok "new sim" "$ATHLOS" new "$S"
expect_ok "simulate walk" "$ATHLOS" run "$S" simulate-lps --output sim/walk --param scenario=walk --param venue_seed=3 --param seed=1
expect_ok "simulate run" "$ATHLOS" run "$S" simulate-lps --output sim/test --param scenario=run --param venue_seed=3 --param seed=2 --param lane=3
for item in walk walk-guess test test-beacons test-truth; do
  expect_ok "export $item" "$ATHLOS" export "$S" "sim/$item" --to "$WORK/$item.csv"
done
head -1 "$WORK/walk.csv" | grep -q '^t,beacon,dt' || fail "TDoA export is not the long t,beacon,dt form"

expect_ok "new" "$ATHLOS" new "$P"
expect_ok "import walk" "$ATHLOS" import "$P" "$WORK/walk.csv" --as walk --kind lps-tdoa
expect_ok "import guess" "$ATHLOS" import "$P" "$WORK/walk-guess.csv" --as guess --kind beacons
expect_ok "import test" "$ATHLOS" import "$P" "$WORK/test.csv" --as test --kind lps-tdoa
expect_ok "import survey" "$ATHLOS" import "$P" "$WORK/test-beacons.csv" --as survey --kind beacons
expect_ok "calibrate" "$ATHLOS" run "$P" lps-calibration --input walk/tdoa,guess/beacons --output walk/beacons
expect_ok "position calibrated" "$ATHLOS" run "$P" lps-positioning --input test/tdoa,walk/beacons --output test/cal --param tag_height=1.2
expect_ok "position surveyed" "$ATHLOS" run "$P" lps-positioning --input test/tdoa,survey/beacons --output test/ref --param tag_height=1.2
expect_ok "export cal" "$ATHLOS" export "$P" test/cal --to "$WORK/cal.csv"
expect_ok "export ref" "$ATHLOS" export "$P" test/ref --to "$WORK/ref.csv"

# Horizontal RMSE against the truth at equal time stamps (first column t, then x, y).
rmse() { awk -F, 'NR==FNR{if(FNR>1){x[$1]=$2;y[$1]=$3};next} FNR>1&&($1 in x){s+=($2-x[$1])^2+($3-y[$1])^2;n++}
  END{if(n<100) print "nan"; else printf "%.4f\n", sqrt(s/n)}' "$WORK/test-truth.csv" "$1"; }
CAL=$(rmse "$WORK/cal.csv"); REF=$(rmse "$WORK/ref.csv")
echo "tag RMSE: surveyed $REF m, calibrated $CAL m"
awk -v r="$REF" 'BEGIN{exit !(r < 0.15)}' || fail "RMSE with surveyed beacons $REF m (expected < 0.15 m)"
# The judged criterion: calibrated at most 0.10 m above surveyed.
awk -v c="$CAL" -v r="$REF" 'BEGIN{exit !(c <= r + 0.10)}' || fail "calibrated RMSE $CAL m exceeds surveyed $REF m + 0.10 m"

# gauge=guess is still available (it fails the criterion on this venue; only checked to run).
expect_ok "calibrate gauge=guess" "$ATHLOS" run "$P" lps-calibration --input walk/tdoa,guess/beacons --output walk/beacons-guess --param gauge=guess
expect_ok "position gauge=guess" "$ATHLOS" run "$P" lps-positioning --input test/tdoa,walk/beacons-guess --output test/cal-guess --param tag_height=1.2
expect_ok "export gauge=guess" "$ATHLOS" export "$P" test/cal-guess --to "$WORK/cal-guess.csv"
echo "tag RMSE with gauge=guess: $(rmse "$WORK/cal-guess.csv") m (for comparison; not judged)"

# From a rough guess (σ 20 m horizontal, 10 m vertical, as from an aerial image) the same criterion
# holds (issue #16 item 5), with default parameters: the prior is widened to the guess error found.
expect_ok "simulate rough guess" "$ATHLOS" run "$S" simulate-lps --output sim/rough --param scenario=walk --param venue_seed=3 --param seed=1 --param sigma_xy=20 --param sigma_z=10
expect_ok "export rough guess" "$ATHLOS" export "$S" sim/rough-guess --to "$WORK/rough-guess.csv"
expect_ok "import rough guess" "$ATHLOS" import "$P" "$WORK/rough-guess.csv" --as rough --kind beacons
expect_ok "calibrate rough" "$ATHLOS" run "$P" lps-calibration --input walk/tdoa,rough/beacons --output walk/beacons-rough
expect_ok "position rough" "$ATHLOS" run "$P" lps-positioning --input test/tdoa,walk/beacons-rough --output test/cal-rough --param tag_height=1.2
expect_ok "export rough" "$ATHLOS" export "$P" test/cal-rough --to "$WORK/cal-rough.csv"
ROUGH=$(rmse "$WORK/cal-rough.csv")
echo "tag RMSE from the rough guess: $ROUGH m"
awk -v c="$ROUGH" -v r="$REF" 'BEGIN{exit !(c <= r + 0.10)}' || fail "rough-guess RMSE $ROUGH m exceeds surveyed $REF m + 0.10 m"

# Geometry awareness (issue #16 item 3): 12 anchors inside a 2 m box are refused with the reason.
{ echo "id,x,y,z"; for i in $(seq 1 12); do echo "$i,$(( 20 + i % 3 )).0,$(( 45 + i % 2 )).5,$(( 3 + i % 2 )).0"; done; } > "$WORK/box.csv"
expect_ok "import box" "$ATHLOS" import "$P" "$WORK/box.csv" --as box --kind beacons
expect_fail "clustered beacons" "clustered" "$ATHLOS" run "$P" lps-calibration --input walk/tdoa,box/beacons --output walk/x

# Invalid parameters are refused with a one-line reason naming the parameter.
expect_fail "bad selection" "selection" "$ATHLOS" run "$P" lps-positioning --input test/tdoa,survey/beacons --output test/x --param selection=magic
expect_fail "bad gauge" "gauge" "$ATHLOS" run "$P" lps-calibration --input walk/tdoa,guess/beacons --output walk/x --param gauge=magic
expect_fail "bad track" "track" "$ATHLOS" run "$P" lps-calibration --input walk/tdoa,guess/beacons --output walk/x --param track=no-such-track
finish
