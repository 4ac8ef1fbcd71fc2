#!/usr/bin/env bash
# The CNN path on the command line: labelled raw windows exported for scripts/train_cnn.py (NumPy
# files), the committed tiny ONNX network imported with --classifier cnn --onnx, classify-actions with
# it on a new person, and refusals (no network, a damaged one, one above the size limit) that leave
# the project untouched. PyTorch is not needed: the network in tests/data/activity was made with it.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
source <(sed -n '/^make_wrist_csv() {/,/^}/p' "$(dirname "$0")/activity.sh")
source <(sed -n '/^sample_balanced_accuracy() {/,/^}/p' "$(dirname "$0")/activity.sh")

expect_ok "new" "$ATHLOS" new "$P"
for person in 11 12 13; do
  make_wrist_csv "$WORK/train$person.csv" "$person"
  expect_ok "import train$person" "$ATHLOS" import "$P" "$WORK/train$person.csv" --as "train$person" --kind imu --labels label
done
make_wrist_csv "$WORK/test.csv" 111
expect_ok "import test" "$ATHLOS" import "$P" "$WORK/test.csv" --as test --kind imu --skip label

cp "$P" "$WORK/before.athlos"
expect_ok "export windows" "$ATHLOS" train "$P" --model c --input imu --sensors acc --window 3 --step 1 \
  --window-samples 32 --export-windows "$WORK/win"
grep -qE "^exported [0-9]+ windows \(3 channels × 32 samples, 3 s, step 1 s\) of 3 subjects" "$WORK/out" \
  || fail "export summary: $(cat "$WORK/out")"
n=$(awk '{print $2; exit}' "$WORK/out")
for f in windows labels groups; do [ -s "$WORK/win/$f.npy" ] || fail "no $f.npy"; done
head -c 128 "$WORK/win/windows.npy" | grep -qa "'descr': '<f4', 'fortran_order': False, 'shape': ($n, 3, 32)" \
  || fail "windows.npy header: $(head -c 128 "$WORK/win/windows.npy" | tr -d '\0')"
expected=$((128 + n * 3 * 32 * 4)); actual=$(stat -c %s "$WORK/win/windows.npy")
[ "$actual" -eq "$expected" ] || fail "windows.npy is $actual bytes, expected $expected"
grep -q '"format": "athlos-windows-1"' "$WORK/win/meta.json" || fail "meta.json: $(head -c 300 "$WORK/win/meta.json")"
cmp -s "$P" "$WORK/before.athlos" || fail "exporting windows changed the project"

expect_fail "cnn needs a network" "--classifier cnn: the network is trained outside Athlos" \
  "$ATHLOS" train "$P" --model c --input imu --classifier cnn
printf 'not a network' > "$WORK/bad.onnx"; cp "$TEST_DATA/activity/tiny_cnn.json" "$WORK/bad.json"
expect_fail "damaged network" "bad.onnx: cv::dnn cannot read the ONNX network" \
  "$ATHLOS" train "$P" --model c --input imu --classifier cnn --onnx "$WORK/bad.onnx"
truncate -s 40M "$WORK/big.onnx"
expect_fail "too large" "--onnx .*big.onnx: 41.9 MB, above the limit of 34 MB" \
  "$ATHLOS" train "$P" --model c --input imu --classifier cnn --onnx "$WORK/big.onnx" --onnx-description "$WORK/bad.json"
cmp -s "$P" "$WORK/before.athlos" || fail "a refused import changed the project"

expect_ok "import cnn" "$ATHLOS" train "$P" --model c --input imu --classifier cnn --onnx "$TEST_DATA/activity/tiny_cnn.onnx"
grep -qE "^stored model 'c' \(cnn, 7 classes, 5.6 kB ONNX\)" "$WORK/out" || fail "cnn not stored: $(tail -3 "$WORK/out")"
ba=$(awk '/^balanced accuracy/ {print $3; exit}' "$WORK/out" | tr -d ,)
awk -v a="$ba" 'BEGIN { exit !(a >= 0.6) }' || fail "balanced accuracy on the project's windows $ba < 0.6"
expect_ok "classify" "$ATHLOS" run "$P" classify-actions --input test/imu --output test/actions --param model=c
expect_ok "export" "$ATHLOS" export "$P" test/annotations --to "$WORK/x.csv"
score=$(sample_balanced_accuracy "$WORK/test.csv" "$WORK/x.csv")
echo "cnn on a new person: sample-wise balanced accuracy $score"
awk -v a="$score" 'BEGIN { exit !(a >= 0.6) }' || fail "cnn: sample-wise balanced accuracy $score < 0.6"
finish
