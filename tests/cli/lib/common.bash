# Shared helpers for the CLI end-to-end tests. Usage in a test: source "$(dirname "$0")/lib/common.bash" "$@"
set -uo pipefail
ATHLOS="$1"; SHARED_DATA="$2"; TEST_DATA="$3"
WORK=$(mktemp -d); trap 'rm -rf "$WORK"' EXIT
FAILURES=0

fail() { echo "FAIL: $*" >&2; FAILURES=$((FAILURES + 1)); }
# expect_ok <description> <command…>: the command exits 0
expect_ok() { local d="$1"; shift; if ! "$@" >"$WORK/out" 2>"$WORK/err"; then fail "$d: exit $? ($(head -c 400 "$WORK/err"))"; fi; }
# expect_fail <description> <pattern> <command…>: non-zero exit, a one-line stderr matching pattern
expect_fail() {
  local d="$1" pattern="$2"; shift 2
  if "$@" >"$WORK/out" 2>"$WORK/err"; then fail "$d: succeeded but should fail"; return; fi
  grep -qE -- "$pattern" "$WORK/err" || fail "$d: stderr '$(head -c 400 "$WORK/err")' does not match /$pattern/"
  [ "$(grep -c . "$WORK/err")" -le 1 ] || fail "$d: reason is not one line: $(cat "$WORK/err")"
}
finish() { if [ "$FAILURES" -gt 0 ]; then echo "$FAILURES check(s) failed"; exit 1; fi; echo "all checks passed"; }
# Width and height of a PNG from its IHDR chunk.
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{printf "%dx%d\n", $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}'; }
# Writes a CSV IMU file with n rows (t at 100 Hz, 9 columns of smooth signals).
make_imu_csv() {
  awk -v n="$2" 'BEGIN{print "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,mag_x,mag_y,mag_z";
    for(i=0;i<n;i++){t=i/100; printf "%.2f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.4f,%.4f,%.4f\n",
      t, sin(t), cos(t), 9.81+0.1*sin(3*t), 0.5*sin(2*t), 0.2*cos(t), 0.1, 20+sin(t), -5, 40}}' > "$1"
}
# need_shared <path under shared/data…>: skip the whole script (exit 77, ctest's SKIP_RETURN_CODE) when a
# shared recording is missing, naming it, rather than failing on it.
need_shared() {
  local f; for f in "$@"; do
    [ -e "$SHARED_DATA/$f" ] || { echo "SKIP: shared recording not found: $SHARED_DATA/$f"; exit 77; }
  done
}
