#!/usr/bin/env bash
# Noise profiles end to end (issue #16 item 6, thesis §4.4 deployment): estimate Q, R and α once on two
# training recordings of LPS fixes with noise-profile, apply them to a new recording with
# position-filter noise=profile:PATH, and compare with noise=auto on the new recording itself against
# the exported truth. Refusals (missing profile, profile of another model, raw ranges) name the problem
# and leave the project byte-identical.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P"
for spec in train1:8301 train2:8302 new:8303; do
  IFS=: read -r name seed <<< "$spec"
  expect_ok "simulate $name" "$ATHLOS" run "$P" simulate-track-run --output "$name/run" --param seed="$seed" \
    --param distance=400
done
expect_ok "profile" "$ATHLOS" run "$P" noise-profile --input train1/run,train2/run --output train1/noise
expect_ok "export profile" "$ATHLOS" export "$P" train1/noise --to "$WORK/noise.csv"
grep -q '^r_x,' "$WORK/noise.csv" || fail "profile has no r_x row: $(head -3 "$WORK/noise.csv")"
expect_ok "filter with profile" "$ATHLOS" run "$P" position-filter --input new/run --output new/profiled \
  --param noise=profile:train1/noise --param output_rate=10
expect_ok "filter auto" "$ATHLOS" run "$P" position-filter --input new/run --output new/auto \
  --param noise=auto --param output_rate=10
for s in profiled auto run-truth; do expect_ok "export $s" "$ATHLOS" export "$P" "new/$s" --to "$WORK/$s.csv"; done
rmse() {
  awk -F, 'FNR == 1 { next }
           NR == FNR { key = sprintf("%.2f", $1); tx[key] = $2; ty[key] = $3; next }
           { key = sprintf("%.2f", $1); if (key in tx) { dx = $2 - tx[key]; dy = $3 - ty[key]; s += dx*dx + dy*dy; n++ } }
           END { if (n == 0) print "nan"; else printf "%.4f\n", sqrt(s / n) }' "$1" "$2"
}
RP=$(rmse "$WORK/run-truth.csv" "$WORK/profiled.csv"); RA=$(rmse "$WORK/run-truth.csv" "$WORK/auto.csv")
echo "RMSE on the new run: profile $RP m, noise=auto $RA m"
awk -v p="$RP" -v a="$RA" 'BEGIN { exit !(p != "nan" && p <= 1.15 * a) }' || fail "profile RMSE $RP m > 1.15 x auto $RA m"
expect_ok "info" "$ATHLOS" info "$P" --json
grep -q '"noise_profile": "train1/noise"' "$WORK/out" || fail "the filtered stream does not name its profile"

# The profile is an input of the filter run: athlos batch skips the step while the profile is unchanged and
# runs it again once the profile is estimated anew (from other training runs).
cat > "$WORK/pipe.json" <<'JSON'
{"name": "profiled", "steps": [{"processor": "position-filter", "input": "new/run", "output": "new/batch",
  "params": {"noise": "profile:train1/noise", "output_rate": 10}}]}
JSON
expect_ok "batch-task runs" "$ATHLOS" batch-task "$WORK/pipe.json" "$P"
grep -q 'wrote new/batch' "$WORK/out" || fail "batch-task did not run the filter: $(cat "$WORK/out")"
expect_ok "batch-task skips" "$ATHLOS" batch-task "$WORK/pipe.json" "$P"
grep -q 'skipped (done)' "$WORK/out" || fail "unchanged profile, yet not skipped: $(cat "$WORK/out")"
expect_ok "profile again" "$ATHLOS" run "$P" noise-profile --input train1/run --output train1/noise
expect_ok "batch-task after a new profile" "$ATHLOS" batch-task "$WORK/pipe.json" "$P"
grep -q 'wrote new/batch' "$WORK/out" || fail "the profile changed, yet the filter was skipped: $(cat "$WORK/out")"

# Refusals leave the project byte-identical.
before=$(sha256sum "$P" | cut -d' ' -f1)
expect_fail "missing profile" "train1/none" "$ATHLOS" run "$P" position-filter --input new/run --output new/x \
  --param noise=profile:train1/none
expect_fail "other model" "model=augmented" "$ATHLOS" run "$P" position-filter --input new/run --output new/x \
  --param noise=profile:train1/noise --param model=unconstrained
expect_fail "empty argument" "noise" "$ATHLOS" run "$P" position-filter --input new/run --output new/x \
  --param noise=profile:
[ "$(sha256sum "$P" | cut -d' ' -f1)" = "$before" ] || fail "a refused run changed the project"
finish
