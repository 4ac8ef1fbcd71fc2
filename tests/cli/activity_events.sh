#!/usr/bin/env bash
# Event segmentation on the command line (seed 000 §5.2): wrist accelerometer CSVs at 39 Hz with ball
# contacts of two kinds (a decaying ring-down along x: "spike", along z: "dig") and claps between
# them, annotated per contact; athlos train --segmentation events:impact, classify-actions on a new
# player (one annotation per detected contact, none for the claps), and the refusals.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"

# make_hits_csv <file> <seed> <labels 1|0>: 30 contacts 4–7 s apart, a clap before some of them.
make_hits_csv() {
  awk -v seed="$2" -v labels="$3" 'function gauss() { return sqrt(-2*log(1-rand()))*cos(6.283185307*rand()) }
  BEGIN { srand(seed); rate = 39; t0 = 3; n = 0;
    for (k = 0; k < 30; k++) { t0 += 4 + 3*rand(); T[k] = t0; K[k] = (rand() < 0.5) ? "spike" : "dig"; A[k] = 80 + 40*rand();
      C[k] = (rand() < 0.5) ? t0 - 1.5 : -100 }
    print (labels ? "timestamp,acc_x,acc_y,acc_z,label" : "timestamp,acc_x,acc_y,acc_z");
    for (i = 0; i / rate < t0 + 3; i++) { t = i / rate; ax = 0; ay = 0; az = 9.81; lab = "none";
      for (k = 0; k < 30; k++) { d = t - T[k];
        if (d >= 0 && d < 1) { r = A[k]*exp(-d/0.06)*cos(6.283185307*12*d); if (K[k] == "spike") ax -= r; else az += r }
        if (d > -0.5 && d < 0.5) lab = K[k];
        c = t - C[k]; if (c >= 0 && c < 1) ay += 60*exp(-c/0.04)*cos(6.283185307*12*c) }
      printf "%.4f,%.3f,%.3f,%.3f", t, ax + 0.3*gauss(), ay + 0.3*gauss(), az + 0.3*gauss();
      if (labels) printf ",%s", lab; printf "\n" } }' > "$1"
}

expect_ok "new" "$ATHLOS" new "$P"
for player in 1 2 3; do
  make_hits_csv "$WORK/train$player.csv" "$player" 1
  expect_ok "import train$player" "$ATHLOS" import "$P" "$WORK/train$player.csv" --as "train$player" --kind imu --labels label
done
make_hits_csv "$WORK/test.csv" 9 0
expect_ok "import test" "$ATHLOS" import "$P" "$WORK/test.csv" --as test --kind imu

cp "$P" "$WORK/before.athlos"
expect_fail "bad segmentation" "--segmentation 'events:serve': use one of sliding, events:impact, events:tackle" \
  "$ATHLOS" train "$P" --model e --input imu --sensors acc --segmentation events:serve
expect_fail "bad recall" "--tackle-recall: a share above 0, at most 1" \
  "$ATHLOS" train "$P" --model e --input imu --sensors acc --segmentation events:tackle --tackle-recall 1.5
expect_fail "bad detection recall" "--detection-recall: a share from 0 .no detection tree. to 1" \
  "$ATHLOS" train "$P" --model e --input imu --sensors acc --segmentation events:impact --detection-recall 2
cmp -s "$P" "$WORK/before.athlos" || fail "a refused command changed the project"

expect_ok "train events:impact" "$ATHLOS" train "$P" --model e --input imu --sensors acc --window 4 \
  --segmentation events:impact --classes spike,dig,null --cv leave-one-recording-out --trees 50
grep -q "^segmentation events:impact: windows of 4 s centred on detected events (threshold 5.1 m/s²)" "$WORK/out" \
  || fail "no segmentation line: $(head -3 "$WORK/out")"
grep -qE "^detection tree \(impact, swing\): FN:FP cost [0-9.e+]+, [0-9]+ folds by athlete: keeps" "$WORK/out" \
  || fail "no detection tree line: $(head -4 "$WORK/out")"
grep -qE "^stored model 'e' \(random-forest, [23] classes" "$WORK/out" || fail "not stored: $(tail -1 "$WORK/out")"
ba=$(awk '/^balanced accuracy/ {print $3; exit}' "$WORK/out" | tr -d ,)
awk -v a="$ba" 'BEGIN { exit !(a >= 0.9) }' || fail "cross-validated balanced accuracy $ba < 0.9"

expect_ok "classify" "$ATHLOS" run "$P" classify-actions --input test/imu --output test/actions --param model=e
expect_ok "export" "$ATHLOS" export "$P" test/annotations --to "$WORK/x.csv"
n=$(awk -F, 'NR > 1 && ($3 == "spike" || $3 == "dig")' "$WORK/x.csv" | wc -l)
[ "$n" -ge 29 ] && [ "$n" -le 31 ] || fail "expected 30 classified contacts, got $n: $(head -5 "$WORK/x.csv")"
grep -q ",null," "$WORK/x.csv" && fail "a null event was written as an annotation"
finish
