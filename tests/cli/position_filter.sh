#!/usr/bin/env bash
# position-filter end to end (issue #3, judged set-up): simulate runs, export them, import the LPS fixes
# into a fresh project with --kind lps-position, filter with filter=ekf noise=auto output_rate=10 for
# the three models, export, and compare with the exported truth (RMSE on the 10 Hz grid, awk).
# Criteria: mean RMSE(augmented) ≤ 0.6 · RMSE(unconstrained), < RMSE(pseudo), ≤ 1.0 m.
source "$(dirname "$0")/lib/common.bash" "$@"
SIM="$WORK/sim.athlos"; P="$WORK/p.athlos"
expect_ok "new sim" "$ATHLOS" new "$SIM"
expect_ok "new project" "$ATHLOS" new "$P"
expect_ok "processors" "$ATHLOS" processors --json
for id in position-filter simulate-track-run; do grep -q "\"id\": \"$id\"" "$WORK/out" || fail "processor $id not listed"; done

# Held-out seeds (not used while developing the filter): one 400 m and one 800 m run.
RUNS="run1:4001:400 run2:4002:800"
for spec in $RUNS; do
  IFS=: read -r name seed distance <<< "$spec"
  expect_ok "simulate $name" "$ATHLOS" run "$SIM" simulate-track-run --output "sim/$name" \
    --param seed="$seed" --param distance="$distance" --param lane=2
  expect_ok "export $name" "$ATHLOS" export "$SIM" "sim/$name" --to "$WORK/$name.csv"
  expect_ok "export $name truth" "$ATHLOS" export "$SIM" "sim/$name-truth" --to "$WORK/$name-truth.csv"
  expect_ok "import $name" "$ATHLOS" import "$P" "$WORK/$name.csv" --as "$name" --kind lps-position
  for model in unconstrained pseudo augmented; do
    expect_ok "filter $name $model" "$ATHLOS" run "$P" position-filter --input "$name/lps" --output "$name/$model" \
      --param filter=ekf --param noise=auto --param output_rate=10 --param model="$model"
    expect_ok "export $name $model" "$ATHLOS" export "$P" "$name/$model" --to "$WORK/$name-$model.csv"
  done
done

# RMSE of a filtered CSV against the truth CSV (truth at 100 Hz on multiples of 0.01 s: join on t).
rmse() {
  awk -F, 'FNR == 1 { next }
           NR == FNR { key = sprintf("%.2f", $1); tx[key] = $2; ty[key] = $3; next }
           { key = sprintf("%.2f", $1); if (key in tx) { dx = $2 - tx[key]; dy = $3 - ty[key]; s += dx*dx + dy*dy; n++ } }
           END { if (n == 0) print "nan"; else printf "%.4f\n", sqrt(s / n) }' "$1" "$2"
}
declare -A SUM
for model in unconstrained pseudo augmented; do SUM[$model]=0; done
count=0
for spec in $RUNS; do
  IFS=: read -r name seed distance <<< "$spec"
  count=$((count + 1))
  line="$name:"
  for model in unconstrained pseudo augmented; do
    r=$(rmse "$WORK/$name-truth.csv" "$WORK/$name-$model.csv")
    [ "$r" = "nan" ] && fail "$name $model: no output samples matched the truth grid"
    SUM[$model]=$(awk -v a="${SUM[$model]}" -v b="$r" 'BEGIN { print a + b }')
    line="$line $model=$r"
  done
  echo "$line"
done
U=$(awk -v s="${SUM[unconstrained]}" -v n=$count 'BEGIN { print s / n }')
Ps=$(awk -v s="${SUM[pseudo]}" -v n=$count 'BEGIN { print s / n }')
M=$(awk -v s="${SUM[augmented]}" -v n=$count 'BEGIN { print s / n }')
echo "mean RMSE: unconstrained $U m, pseudo $Ps m, augmented $M m"
awk -v m="$M" -v u="$U" 'BEGIN { exit !(m <= 0.6 * u) }' || fail "augmented $M m is not <= 0.6 x unconstrained $U m"
awk -v m="$M" -v p="$Ps" 'BEGIN { exit !(m < p) }' || fail "augmented $M m is not below pseudo $Ps m"
awk -v m="$M" 'BEGIN { exit !(m <= 1.0) }' || fail "augmented $M m is above 1.0 m"

# Outlier flags: a second output per input sample; parameter errors name the parameter.
expect_ok "info" "$ATHLOS" info "$P" --json
grep -q '"path": "run1/augmented-outliers"' "$WORK/out" || fail "outlier output missing"
expect_fail "bad track" "track" "$ATHLOS" run "$P" position-filter --input run1/lps --output run1/bad --param track=nowhere
finish
