#!/usr/bin/env bash
# The real recordings import through their formats, and the screenshot shows them.
source "$(dirname "$0")/lib/common.bash" "$@"
need_shared broad/02_undisturbed_slow_rotation_B.hdf5 broad/24_disturbed_tapping_A.hdf5 gaitmap/imu_sample_ic_stride.csv
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P"
expect_ok "import broad" "$ATHLOS" import "$P" "$SHARED_DATA/broad/02_undisturbed_slow_rotation_B.hdf5" --as trial02 --format broad
expect_ok "import broad (auto)" "$ATHLOS" import "$P" "$SHARED_DATA/broad/24_disturbed_tapping_A.hdf5" --as trial24
expect_ok "import gaitmap" "$ATHLOS" import "$P" "$SHARED_DATA/gaitmap/imu_sample_ic_stride.csv" --as walk --format gaitmap
expect_ok "info" "$ATHLOS" info "$P" --json
for s in trial02/imu trial02/reference trial24/imu walk/left-foot walk/right-foot; do
  grep -q "\"path\": \"$s\"" "$WORK/out" || fail "$s missing after import"
done
expect_ok "screenshot" "$ATHLOS" screenshot "$P" --view main --to "$WORK/main.png"
[ ! -s "$WORK/err" ] || fail "screenshot printed on stderr: $(head -c 300 "$WORK/err")"
[ "$(png_size "$WORK/main.png")" = "1280x800" ] || fail "screenshot is $(png_size "$WORK/main.png"), not 1280x800"
[ "$(stat -c %s "$WORK/main.png")" -gt 20000 ] || fail "screenshot is suspiciously small (blank?)"
expect_fail "unknown view" "view" "$ATHLOS" screenshot "$P" --view nope --to "$WORK/x.png"
finish
