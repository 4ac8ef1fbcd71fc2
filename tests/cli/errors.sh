#!/usr/bin/env bash
# Bad input fails with a one-line reason naming file/line/parameter, and leaves the project
# byte-identical.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
make_imu_csv "$WORK/imu.csv" 200
expect_ok "new" "$ATHLOS" new "$P"
expect_ok "import" "$ATHLOS" import "$P" "$WORK/imu.csv" --as rec --kind imu
cp "$P" "$WORK/before.athlos"

# A non-numeric cell on line 58 (line 1 is the header).
awk -F, 'BEGIN{OFS=","} NR==58{$3="abc"} {print}' "$WORK/imu.csv" > "$WORK/bad.csv"
expect_fail "non-numeric cell" "bad\.csv:58" "$ATHLOS" import "$P" "$WORK/bad.csv" --as bad --kind imu
cmp -s "$P" "$WORK/before.athlos" || fail "failed import changed the project file"

# Times going backwards on line 100.
awk -F, 'BEGIN{OFS=","} NR==100{$1="0.05"} {print}' "$WORK/imu.csv" > "$WORK/back.csv"
expect_fail "non-increasing time" "back\.csv:100" "$ATHLOS" import "$P" "$WORK/back.csv" --as back --kind imu
cmp -s "$P" "$WORK/before.athlos" || fail "rejected import changed the project file"
expect_ok "time repair drop" "$ATHLOS" import "$P" "$WORK/back.csv" --as back --kind imu --time-repair drop
cp "$P" "$WORK/before.athlos"

expect_fail "existing name" "exist" "$ATHLOS" import "$P" "$WORK/imu.csv" --as rec --kind imu
expect_fail "missing file" "nope\.csv" "$ATHLOS" import "$P" "$WORK/nope.csv" --as x --kind imu
expect_fail "missing project" "missing\.athlos" "$ATHLOS" info "$WORK/missing.athlos"
# import creates a missing project, but only when the import succeeds.
expect_fail "import into a missing project, bad file" "bad\.csv:58" "$ATHLOS" import "$WORK/fresh.athlos" "$WORK/bad.csv" --as r --kind imu
[ -e "$WORK/fresh.athlos" ] && fail "a failed import created the project file"
expect_fail "import into a missing folder" "folder .*nodir.* does not exist" "$ATHLOS" import "$WORK/nodir/p.athlos" "$WORK/imu.csv" --as r --kind imu
expect_ok "import creates the project" "$ATHLOS" import "$WORK/fresh.athlos" "$WORK/imu.csv" --as r --kind imu
grep -q "created project" "$WORK/out" || fail "import did not say it created the project"
expect_ok "created project opens" "$ATHLOS" info "$WORK/fresh.athlos"
grep -q "r/imu" "$WORK/out" || fail "created project lacks r/imu"
echo "this is not HDF5" > "$WORK/garbage.athlos"
expect_fail "garbage project" "garbage\.athlos" "$ATHLOS" info "$WORK/garbage.athlos"
head -c 3000 "$P" > "$WORK/truncated.athlos"
expect_fail "truncated project" "truncated\.athlos" "$ATHLOS" info "$WORK/truncated.athlos"
expect_fail "unknown processor" "unknown processor 'nope'" "$ATHLOS" run "$P" nope --input rec/imu --output rec/x
expect_fail "bad parameter value" "cutoff" "$ATHLOS" run "$P" butterworth --input rec/imu --output rec/lp --param cutoff=500
expect_fail "unknown parameter" "unknown parameter 'bogus'" "$ATHLOS" run "$P" butterworth --input rec/imu --output rec/lp --param bogus=1
expect_fail "missing input" "no stream of that name in the project \(rec has: imu" "$ATHLOS" run "$P" butterworth --input rec/nothing --output rec/lp --param cutoff=5
expect_fail "missing recording" "\(recordings: " "$ATHLOS" run "$P" butterworth --input nothing/imu --output rec/lp --param cutoff=5
expect_fail "overwrite imported data" "imported" "$ATHLOS" run "$P" butterworth --input rec/imu --output rec/imu --param cutoff=5
cmp -s "$P" "$WORK/before.athlos" || fail "failed runs changed the project file"
echo '{"steps": [' > "$WORK/broken.json"
expect_fail "broken pipeline JSON" "broken\.json:2" "$ATHLOS" pipeline "$P" "$WORK/broken.json"
echo '{"steps": [{"processor": "resample", "input": "rec/imu", "output": "rec/r", "params": {"rate": 50}},
                 {"processor": "butterworth", "input": "rec/imu", "output": "rec/lp", "params": {"cutoff": 900}}]}' > "$WORK/half.json"
expect_fail "failing pipeline step" "step 2" "$ATHLOS" pipeline "$P" "$WORK/half.json"
cmp -s "$P" "$WORK/before.athlos" || fail "failed pipeline changed the project file"
expect_fail "unknown command" "unknown command" "$ATHLOS" frobnicate
for c in new import info processors run export pipeline screenshot video; do
  expect_ok "$c --help" "$ATHLOS" "$c" --help
  grep -q "Usage: athlos $c" "$WORK/out" || fail "$c --help has no usage line"
done
# Scripts (the demo) take the view names from --list, one per line.
expect_ok "screenshot --list" "$ATHLOS" screenshot --list
for v in main trajectory annotate actions joint-angles; do
  grep -qx "$v" "$WORK/out" || fail "screenshot --list lacks $v"
done
expect_fail "screenshot without project" "needs a project" "$ATHLOS" screenshot --view main --to "$WORK/x.png"
finish
