#!/usr/bin/env bash
# Issue #18 item 4: skiing events end to end through `athlos run`. simulate-skiing (xc with a pole
# IMU, skimo, alpine) → xc-skiing-cycles / skimo-phases / alpine-turns → CSV: the cycle speeds within
# 1 % of the truth, pole plants within 11 ms, the skimo elevation gain within 2 %, the alpine turns
# alternating left/right at the true switches (±0.15 s), and annotations with the processor as source.
# alpine-turns also on simulate-body's skiing run. Refusals are one line and leave the project
# byte-identical.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P"
expect_ok "simulate xc" "$ATHLOS" run "$P" simulate-skiing --output xc/ski --param scenario=xc --param count=20 --param seed=5
expect_ok "xc cycles" "$ATHLOS" run "$P" xc-skiing-cycles --input xc/ski,xc/ski-pole --output xc/cycles
expect_ok "export xc" "$ATHLOS" export "$P" xc/cycles --to "$WORK/xc.csv"
expect_ok "export xc truth" "$ATHLOS" export "$P" xc/ski-truth --to "$WORK/xc-truth.csv"
head -1 "$WORK/xc.csv" | grep -q '^cycle \[1\],thrust_start \[s\],thrust_end \[s\],glide_start \[s\],end \[s\],duration \[s\],speed \[m/s\],length \[m\]' \
  || fail "xc header: $(head -1 "$WORK/xc.csv")"
# Every true cycle but the first (merged with the initial stand) matched by thrust start within 0.1 s.
result=$(awk -F, 'NR == FNR { if (FNR > 2) { s[++n] = $1; v[n] = $6; pp[n] = $10 } next }
  FNR > 1 { for (i = 1; i <= n; ++i) if ($2 - s[i] < 0.1 && s[i] - $2 < 0.1) { hit[i]++; e = ($7 - v[i]) / v[i];
              if (e < 0) e = -e; if (e > 0.01) bad = bad sprintf("cycle at %.2f s speed %.3f vs %.3f; ", s[i], $7, v[i]);
              d = $11 - pp[i]; if (d < 0) d = -d; if (d > 0.011) bad = bad sprintf("pole plant %.3f vs %.3f; ", $11, pp[i]) } }
  END { for (i = 1; i <= n; ++i) if (hit[i] != 1) bad = bad sprintf("true cycle %d matched %d times; ", i, hit[i]);
        print bad == "" ? "ok" : bad }' "$WORK/xc-truth.csv" "$WORK/xc.csv")
[ "$result" = "ok" ] || fail "xc: $result"
expect_ok "export xc annotations" "$ATHLOS" export "$P" xc/annotations --to "$WORK/xc-ann.csv"
[ "$(grep -c 'xc cycle' "$WORK/xc-ann.csv")" -eq $(($(wc -l < "$WORK/xc.csv") - 1)) ] || fail "one 'xc cycle' annotation per cycle"
[ "$(grep -c 'pole push' "$WORK/xc-ann.csv")" -eq 20 ] || fail "20 'pole push' annotations expected"
grep -q 'xc-skiing-cycles' "$WORK/xc-ann.csv" || fail "annotation source is not xc-skiing-cycles"

expect_ok "simulate skimo" "$ATHLOS" run "$P" simulate-skiing --output up/ski --param scenario=skimo --param count=20
expect_ok "skimo phases" "$ATHLOS" run "$P" skimo-phases --input up/ski --output up/cycles
expect_ok "export skimo" "$ATHLOS" export "$P" up/cycles --to "$WORK/up.csv"
head -1 "$WORK/up.csv" | grep -q '^cycle \[1\],still_start \[s\],still_end \[s\],end \[s\],duration \[s\],speed \[m/s\],length \[m\],elevation \[m\],slope \[rad\]$' \
  || fail "skimo header: $(head -1 "$WORK/up.csv")"
expect_ok "export skimo truth" "$ATHLOS" export "$P" up/ski-truth --to "$WORK/up-truth.csv"
gain=$(awk -F, 'FNR > 1 && $8 > 0 { g += $8 } END { printf "%.3f", g }' "$WORK/up.csv")
true_gain=$(awk -F, 'FNR > 2 { g += $8 } END { printf "%.3f", g }' "$WORK/up-truth.csv")
awk -v a="$gain" -v b="$true_gain" 'BEGIN { e = (a - b) / b; exit !(e < 0.02 && e > -0.02 && b > 5) }' \
  || fail "skimo elevation gain $gain m vs $true_gain m"

expect_ok "simulate alpine" "$ATHLOS" run "$P" simulate-skiing --output gs/imu --param scenario=alpine --param count=20
expect_ok "alpine turns" "$ATHLOS" run "$P" alpine-turns --input gs/imu --output gs/turns
expect_ok "export alpine" "$ATHLOS" export "$P" gs/turns --to "$WORK/gs.csv"
expect_ok "export alpine truth" "$ATHLOS" export "$P" gs/imu-truth --to "$WORK/gs-truth.csv"
result=$(awk -F, 'NR == FNR { if (FNR > 2) { s[++n] = $1; side[n] = $3 } next }
  FNR > 1 { k = FNR - 1; d = $2 - s[k]; if (d < 0) d = -d;
            if (d > 0.15 || $5 != side[k]) bad = bad sprintf("turn %d at %.2f s %s vs %.2f s %s; ", k, $2, $5, s[k], side[k]) }
  END { if (FNR != n) bad = bad sprintf("%d turns for %d complete true turns; ", FNR - 1, n - 1); print bad == "" ? "ok" : bad }' \
  "$WORK/gs-truth.csv" "$WORK/gs.csv")
[ "$result" = "ok" ] || fail "alpine: $result"

# BodySimulator's skiing run (sacrum IMU with a misaligned mount): alternating turns of plausible length.
expect_ok "simulate-body" "$ATHLOS" run "$P" simulate-body --output body/imu --param motion_duration=40 --param seed=2
expect_ok "alpine turns body" "$ATHLOS" run "$P" alpine-turns --input body/imu --output body/turns
expect_ok "export body turns" "$ATHLOS" export "$P" body/turns --to "$WORK/body.csv"
result=$(awk -F, 'FNR > 1 { n++; if ($4 < 1.0 || $4 > 2.0) bad = bad sprintf("turn %d lasts %.2f s; ", n, $4);
                            if ($5 == prev) bad = bad sprintf("turn %d same side as before; ", n); prev = $5 }
  END { if (n < 15) bad = bad sprintf("only %d turns; ", n); print bad == "" ? "ok" : bad }' "$WORK/body.csv")
[ "$result" = "ok" ] || fail "body: $result"

# Refusals: one line naming the stream or parameter, the project unchanged.
before=$(cd "$WORK" && find p.athlos -type f -exec md5sum {} + | sort)
expect_fail "table as ski" "xc/ski-truth" "$ATHLOS" run "$P" xc-skiing-cycles --input xc/ski-truth --output xc/bad
expect_fail "same axes" "ml_axis" "$ATHLOS" run "$P" xc-skiing-cycles --input xc/ski --output xc/bad --param forward_axis=y
expect_fail "no turns on a straight ascent" "no turn switch found" "$ATHLOS" run "$P" alpine-turns --input up/ski --output up/bad
expect_fail "no cycles on the sacrum" "no (cross-country cycle|motionless phase) found|not still" \
  "$ATHLOS" run "$P" skimo-phases --input gs/imu --output gs/bad
after=$(cd "$WORK" && find p.athlos -type f -exec md5sum {} + | sort)
[ "$before" = "$after" ] || fail "a refused run changed the project"
finish
