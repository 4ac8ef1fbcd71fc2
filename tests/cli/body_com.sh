#!/usr/bin/env bash
# Body model and centre of mass end to end through `athlos run` (issue #18): simulate-body (a 30 s skiing run) →
# orientation (6D) per sensor → drift-reduction → body-model (the corrected streams on their segments, boots and
# helmet) → body-com with the true mounts and sensor-to-joint vectors, and with drift-reduction's own vectors.
# Checks the outputs' shape and plausibility (the judged accuracy is in tests/plugins/body and
# athlos-eval-body-com) and that every refusal names what is wrong and leaves the project byte-identical.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P"
expect_ok "simulate-body" "$ATHLOS" run "$P" simulate-body --output ski/imu --param motion_duration=30 --param seed=4

segments="sacrum sternum right-thigh right-shank right-foot left-thigh left-shank left-foot"
inputs=""
for s in $segments; do
  imu="ski/imu"; q="ski/q"
  [ "$s" = sacrum ] || { imu="ski/imu-$s"; q="ski/q-$s"; }
  expect_ok "orientation $s" "$ATHLOS" run "$P" orientation --input "$imu" --output "$q" --param mode=6d
  inputs="$inputs,$q,$imu"
done
expect_ok "drift-reduction" "$ATHLOS" run "$P" drift-reduction --input "${inputs#,}" --output ski/dr

sensors="pelvis:ski/dr,thorax:ski/dr-sternum"
for s in right-thigh right-shank right-foot left-thigh left-shank left-foot; do sensors="$sensors,$s:ski/dr-$s"; done
expect_ok "body-model" "$ATHLOS" run "$P" body-model --output ski/body --param height=1.78 --param mass=75 \
  --param sensors="$sensors" --param equipment="right-foot:2.5,left-foot:2.5,head:0.5"
expect_ok "body-com" "$ATHLOS" run "$P" body-com \
  --input ski/body,ski/imu-right-mounts,ski/imu-left-mounts,ski/imu-joint-vectors --output ski/com
expect_ok "body-com (drift-reduction's vectors)" "$ATHLOS" run "$P" body-com \
  --input ski/body,ski/imu-right-mounts,ski/imu-left-mounts --output ski/com-dr --param vectors=attributes

# Uncorrected 6D orientations: unrelated headings, aligned over the first 2 s of standing.
raw="pelvis:ski/q,thorax:ski/q-sternum"
for s in right-thigh right-shank right-foot left-thigh left-shank left-foot; do raw="$raw,$s:ski/q-$s"; done
expect_ok "body-model (6D)" "$ATHLOS" run "$P" body-model --output ski/body-6d --param height=1.78 --param mass=75 \
  --param sensors="$raw"
expect_ok "body-com heading=align-start" "$ATHLOS" run "$P" body-com \
  --input ski/body-6d,ski/imu-right-mounts,ski/imu-left-mounts,ski/imu-joint-vectors --output ski/com-6d \
  --param heading=align-start

expect_ok "export com" "$ATHLOS" export "$P" ski/com --to "$WORK/com.csv"
expect_ok "export joints" "$ATHLOS" export "$P" ski/com-joints --to "$WORK/joints.csv"
expect_ok "export q" "$ATHLOS" export "$P" ski/q --to "$WORK/q.csv"
[ "$(head -1 "$WORK/com.csv")" = "t,com_x [m],com_y [m],com_z [m],fore_aft [m],above_ankles [m]" ] || fail "columns: $(head -1 "$WORK/com.csv")"
[ "$(wc -l < "$WORK/com.csv")" = "$(wc -l < "$WORK/q.csv")" ] || fail "body-com changed the row count"
head -1 "$WORK/joints.csv" | grep -q "right-knee_x" || fail "joint columns: $(head -1 "$WORK/joints.csv")"
# Plausible everywhere: the CoM within 0.4 m of the lumbar joint centre, at most 0.25 m above it, and 0.5–1.2 m
# above the ankles.
plausible() {
  awk -F, 'NR > 1 { r = sqrt($2*$2 + $3*$3 + $4*$4); if (r > 0.4 || $4 > 0.25 || $6 < 0.5 || $6 > 1.2) bad++ }
           END { exit bad > 0 }' "$1"
}
plausible "$WORK/com.csv" || fail "implausible CoM rows in ski/com"
expect_ok "export com-6d" "$ATHLOS" export "$P" ski/com-6d --to "$WORK/com-6d.csv"
plausible "$WORK/com-6d.csv" || fail "implausible CoM rows in ski/com-6d (heading=align-start)"

# Refusals: each names the culprit and leaves the file byte-identical.
before=$(sha256sum "$P" | cut -d' ' -f1)
expect_fail "unknown segment" "tail" "$ATHLOS" run "$P" body-model --output ski/x --param sensors=tail:ski/dr
expect_fail "stream not found" "ski/nothing" "$ATHLOS" run "$P" body-model --output ski/x --param sensors=pelvis:ski/nothing
expect_fail "imu is no orientation" "orientation" "$ATHLOS" run "$P" body-model --output ski/x --param sensors=pelvis:ski/imu
expect_fail "height out of range" "height" "$ATHLOS" run "$P" body-model --output ski/x --param height=3.1
expect_fail "mass out of range" "mass" "$ATHLOS" run "$P" body-model --output ski/x --param mass=5
expect_fail "bad equipment" "equipment" "$ATHLOS" run "$P" body-model --output ski/x --param equipment=skis:4
expect_fail "no model" "body-model" "$ATHLOS" run "$P" body-com --input ski/imu-joint-vectors --output ski/x
expect_fail "vectors=table without table" "joint-vectors" "$ATHLOS" run "$P" body-com --input ski/body --output ski/x \
  --param vectors=table
after=$(sha256sum "$P" | cut -d' ' -f1)
[ "$before" = "$after" ] || fail "a refused run changed the project"
# A model whose legs carry no sensor: body-com names the missing segment.
expect_ok "legless model" "$ATHLOS" run "$P" body-model --output ski/legless --param sensors=pelvis:ski/dr,thorax:ski/dr-sternum
before=$(sha256sum "$P" | cut -d' ' -f1)
expect_fail "segment without sensor" "right-thigh" "$ATHLOS" run "$P" body-com --input ski/legless --output ski/x
after=$(sha256sum "$P" | cut -d' ' -f1)
[ "$before" = "$after" ] || fail "a refused body-com changed the project"
finish
