#!/usr/bin/env bash
# Held-out evaluation of position-filter through the judged command-line path (issue #3): for each
# run NAME:SEED:DISTANCE:LANE, simulate-track-run → export CSV → import --kind lps-position into a
# fresh project → position-filter filter=ekf noise=auto output_rate=10 for the unconstrained, pseudo
# and augmented models → export → RMSE against the simulator's truth on the 10 Hz grid. Prints one
# line per run and the means with the three criteria (augmented ≤ 0.6 × unconstrained, < pseudo, ≤ 1 m).
# Usage: scripts/position-filter-heldout.sh [build/bin/athlos] [NAME:SEED:DISTANCE:LANE ...]
set -euo pipefail
ATHLOS=${1:-build/bin/athlos}; shift || true
SPECS=("$@")
[ ${#SPECS[@]} -eq 0 ] && SPECS=(r1:5001:400:1 r2:5002:800:1 r3:5003:400:3 r4:5004:800:2 r5:5005:400:4
  r6:5006:800:3 r7:5007:400:2 r8:5008:800:1 r9:5009:400:1 r10:5010:800:4 r11:5011:400:3 r12:5012:800:2)
export QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-offscreen}
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
"$ATHLOS" new "$W/sim.athlos" >/dev/null; "$ATHLOS" new "$W/p.athlos" >/dev/null
rmse() {
  awk -F, 'FNR == 1 { next }
           NR == FNR { k = sprintf("%.2f", $1); tx[k] = $2; ty[k] = $3; next }
           { k = sprintf("%.2f", $1); if (k in tx) { dx = $2 - tx[k]; dy = $3 - ty[k]; s += dx*dx + dy*dy; n++ } }
           END { printf "%.3f", sqrt(s / n) }' "$1" "$2"
}
MODELS=(unconstrained pseudo augmented)
declare -A SUM=([unconstrained]=0 [pseudo]=0 [augmented]=0)
for spec in "${SPECS[@]}"; do
  IFS=: read -r n seed dist lane <<< "$spec"
  "$ATHLOS" run "$W/sim.athlos" simulate-track-run --output "sim/$n" --param seed="$seed" --param distance="$dist" \
    --param lane="$lane" >/dev/null
  "$ATHLOS" export "$W/sim.athlos" "sim/$n" --to "$W/$n.csv" >/dev/null
  "$ATHLOS" export "$W/sim.athlos" "sim/$n-truth" --to "$W/$n-truth.csv" >/dev/null
  "$ATHLOS" import "$W/p.athlos" "$W/$n.csv" --as "$n" --kind lps-position >/dev/null
  line="$n seed=$seed ${dist}m lane=$lane:"
  for m in "${MODELS[@]}"; do
    "$ATHLOS" run "$W/p.athlos" position-filter --input "$n/lps" --output "$n/$m" --param filter=ekf --param noise=auto \
      --param output_rate=10 --param model="$m" >/dev/null
    "$ATHLOS" export "$W/p.athlos" "$n/$m" --to "$W/$n-$m.csv" >/dev/null
    r=$(rmse "$W/$n-truth.csv" "$W/$n-$m.csv")
    SUM[$m]=$(awk -v a="${SUM[$m]}" -v b="$r" 'BEGIN { print a + b }')
    line="$line $m=$r"
  done
  echo "$line"
done
count=${#SPECS[@]}
awk -v u="${SUM[unconstrained]}" -v p="${SUM[pseudo]}" -v m="${SUM[augmented]}" -v n="$count" 'BEGIN {
  u /= n; p /= n; m /= n
  printf "mean RMSE over %d runs: unconstrained %.3f m, pseudo %.3f m, augmented %.3f m\n", n, u, p, m
  printf "augmented <= 0.6 x unconstrained: %s; augmented < pseudo: %s; augmented <= 1.0 m: %s\n",
         (m <= 0.6 * u ? "yes" : "NO"), (m < p ? "yes" : "NO"), (m <= 1.0 ? "yes" : "NO") }'
