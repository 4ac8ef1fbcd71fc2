#!/usr/bin/env bash
# Issue #17 item 3(a), velocity resets: simulate-skiing (cross-country) → orientation (6D) →
# velocity-reset mode=xc-ski → CSV: one zero-velocity phase per true thrust (the first merges with the
# initial stand), the distance travelled (∫|v| dt) within 1 % of the true track length, units in the
# header; refusals (unknown mode, inputs swapped, a sensor that never stops) are one line naming the
# parameter or input and leave the project byte-identical.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P"
expect_ok "simulate xc" "$ATHLOS" run "$P" simulate-skiing --output xc/ski --param scenario=xc --param count=20 --param seed=5
expect_ok "orientation" "$ATHLOS" run "$P" orientation --input xc/ski --output xc/q --param mode=6d
expect_ok "velocity-reset" "$ATHLOS" run "$P" velocity-reset --input xc/q,xc/ski --output xc/v --param mode=xc-ski
expect_ok "export trajectory" "$ATHLOS" export "$P" xc/v --to "$WORK/v.csv"
expect_ok "export phases" "$ATHLOS" export "$P" xc/v-zero-velocity --to "$WORK/z.csv"
expect_ok "export truth" "$ATHLOS" export "$P" xc/ski-truth --to "$WORK/t.csv"
head -1 "$WORK/z.csv" | grep -q '^start \[s\],end \[s\],duration \[s\],drift_x \[m/s\]' || fail "phases header: $(head -1 "$WORK/z.csv")"
head -1 "$WORK/v.csv" | grep -q '^t.*,x.*,y.*,z.*,vx.*,vy.*,vz.*,zero_velocity' || fail "trajectory header: $(head -1 "$WORK/v.csv")"
# Every true thrust but the first holds the centre of exactly one phase.
result=$(awk -F, 'NR == FNR { if (FNR > 2) { s[++n] = $1; e[n] = $2 } next }
  FNR > 1 { c = ($1 + $2) / 2; for (i = 1; i <= n; ++i) if (c >= s[i] - 0.005 && c <= e[i] + 0.005) hit[i]++ }
  END { for (i = 1; i <= n; ++i) if (hit[i] != 1) bad = bad sprintf("thrust at %.2f s holds %d phases; ", s[i], hit[i]);
        print bad == "" ? "ok" : bad }' "$WORK/t.csv" "$WORK/z.csv")
[ "$result" = "ok" ] || fail "thrusts: $result"
# Distance: ∫|v| dt over the anchored span against the sum of the true cycle lengths.
result=$(awk -F, 'NR == FNR { if (FNR > 1) truth += $7; next }
  FNR > 1 && $5 != "" && $5 != "nan" { v = sqrt($5 * $5 + $6 * $6 + $7 * $7); if (have) d += 0.5 * ($1 - t0) * (v + v0); t0 = $1; v0 = v; have = 1 }
  END { e = (d - truth) / truth; if (e < 0) e = -e; print (e < 0.01 && truth > 50) ? "ok" : sprintf("%.2f m vs %.2f m", d, truth) }' \
  "$WORK/t.csv" "$WORK/v.csv")
[ "$result" = "ok" ] || fail "distance: $result"

# Refusals: one line naming the parameter or input, the project unchanged.
expect_ok "simulate alpine" "$ATHLOS" run "$P" simulate-skiing --output gs/imu --param scenario=alpine --param count=6
expect_ok "orientation alpine" "$ATHLOS" run "$P" orientation --input gs/imu --output gs/q --param mode=6d
before=$(cd "$WORK" && find p.athlos -type f -exec md5sum {} + | sort)
expect_fail "unknown mode" "mode" "$ATHLOS" run "$P" velocity-reset --input xc/q,xc/ski --output xc/bad --param mode=skate
expect_fail "inputs swapped" "xc/ski" "$ATHLOS" run "$P" velocity-reset --input xc/ski,xc/q --output xc/bad
expect_fail "never still" "zero-velocity phase" "$ATHLOS" run "$P" velocity-reset --input gs/q,gs/imu --output gs/bad --param mode=xc-ski
after=$(cd "$WORK" && find p.athlos -type f -exec md5sum {} + | sort)
[ "$before" = "$after" ] || fail "a refused run changed the project"
finish
