#!/usr/bin/env bash
# athlos video: attach a video to a recording (relative path, offset), --info, change the offset,
# detach, and bad input (garbage file, missing file, unknown recording, usage) with one-line
# reasons and the project left unchanged. The video is a YUV4MPEG2 file written here (FFmpeg reads
# it without any codec library).
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
make_imu_csv "$WORK/imu.csv" 1000
expect_ok "new" "$ATHLOS" new "$P"
expect_ok "import" "$ATHLOS" import "$P" "$WORK/imu.csv" --as rec --kind imu

# make_y4m <file> <frames>: 64×48, 25 fps, grey level 5·i in frame i.
make_y4m() {
  local f="$1" n="$2" i
  { printf 'YUV4MPEG2 W64 H48 F25:1 Ip A1:1 C420jpeg\n'
    for ((i = 0; i < n; i++)); do
      printf 'FRAME\n'
      head -c $((64 * 48)) /dev/zero | tr '\0' "\\$(printf '%03o' $((i * 5 % 256)))"
      head -c $((64 * 48 / 2)) /dev/zero | tr '\0' '\200'
    done; } > "$f"
}
mkdir -p "$WORK/clips"
make_y4m "$WORK/clips/jump.y4m" 50

expect_ok "attach" "$ATHLOS" video "$P" rec "$WORK/clips/jump.y4m" --offset 1.5
expect_ok "info" "$ATHLOS" video "$P" rec --info
grep -q "jump.y4m" "$WORK/out" || fail "info does not name the file: $(cat "$WORK/out")"
grep -qE "stored as: +clips/jump\.y4m" "$WORK/out" || fail "path not stored relative to the project: $(cat "$WORK/out")"
grep -qE "fps: +25" "$WORK/out" || fail "info fps: $(cat "$WORK/out")"
grep -qE "frames: +50" "$WORK/out" || fail "info frames: $(cat "$WORK/out")"
grep -qE "duration: +2\.000 s" "$WORK/out" || fail "info duration: $(cat "$WORK/out")"
grep -qE "offset: +1\.500 s" "$WORK/out" || fail "info offset: $(cat "$WORK/out")"
grep -qE "covers: +1\.500 \.\. 3\.500 s" "$WORK/out" || fail "info span: $(cat "$WORK/out")"
grep -qE "codec: +[A-Za-z0-9]+" "$WORK/out" || fail "info codec: $(cat "$WORK/out")"
expect_ok "info json of the project keeps the link" "$ATHLOS" info "$P" --json
grep -q '"offset_s": 1.5' "$WORK/out" || fail "metadata has no video offset"

expect_ok "change offset" "$ATHLOS" video "$P" rec --offset -0.25
expect_ok "info" "$ATHLOS" video "$P" rec --info --seek-test 20
grep -qE "offset: +-0\.250 s" "$WORK/out" || fail "offset not changed: $(cat "$WORK/out")"
grep -qE "seek test: +20 random frames" "$WORK/out" || fail "seek test: $(cat "$WORK/out")"

# The project moves with its clips folder: the relative link still resolves.
mkdir -p "$WORK/moved"
mv "$P" "$WORK/moved/p.athlos"; mv "$WORK/clips" "$WORK/moved/clips"; P="$WORK/moved/p.athlos"
expect_ok "info after moving" "$ATHLOS" video "$P" rec --info
# The video disappears: a clear message, the link stays.
mv "$WORK/moved/clips/jump.y4m" "$WORK/moved/clips/elsewhere.y4m"
expect_fail "missing video" "jump\.y4m.*(missing|moved)|missing.*jump\.y4m" "$ATHLOS" video "$P" rec --info
mv "$WORK/moved/clips/elsewhere.y4m" "$WORK/moved/clips/jump.y4m"

cp "$P" "$WORK/before.athlos"
head -c 20000 /dev/urandom > "$WORK/garbage.mp4"
expect_fail "garbage video" "garbage\.mp4.*not a video" "$ATHLOS" video "$P" rec "$WORK/garbage.mp4"
expect_fail "missing file" "nope\.mp4" "$ATHLOS" video "$P" rec "$WORK/nope.mp4"
expect_fail "unknown recording" "no recording 'other'" "$ATHLOS" video "$P" other "$WORK/moved/clips/jump.y4m"
expect_fail "bad offset" "--offset" "$ATHLOS" video "$P" rec --offset abc
expect_fail "file and detach" "either" "$ATHLOS" video "$P" rec "$WORK/moved/clips/jump.y4m" --detach
cmp -s "$P" "$WORK/before.athlos" || fail "failed video commands changed the project file"
code=0; "$ATHLOS" video "$P" rec "$WORK/garbage.mp4" 2>/dev/null || code=$?
[ "$code" -eq 1 ] || fail "bad file: exit code $code, expected 1"
code=0; "$ATHLOS" video "$P" 2>/dev/null || code=$?
[ "$code" -eq 2 ] || fail "usage error: exit code $code, expected 2"

# A frame-index test pattern written by athlos itself (MJPG).
expect_ok "write pattern" "$ATHLOS" video --write-pattern "$WORK/pattern.avi" --frames 60 --fps 30
expect_ok "attach pattern" "$ATHLOS" video "$P" rec "$WORK/pattern.avi" --offset 0.5
expect_ok "pattern info" "$ATHLOS" video "$P" rec --info
grep -qE "frames: +60" "$WORK/out" || fail "pattern frames: $(cat "$WORK/out")"
grep -qE "codec: +MJPG" "$WORK/out" || fail "pattern codec: $(cat "$WORK/out")"
grep -qE "offset: +0\.500 s" "$WORK/out" || fail "pattern offset: $(cat "$WORK/out")"

expect_ok "detach" "$ATHLOS" video "$P" rec --detach
expect_fail "info without video" "has no video" "$ATHLOS" video "$P" rec --info
expect_fail "detach twice" "has no video" "$ATHLOS" video "$P" rec --detach
expect_ok "video --help" "$ATHLOS" video --help
grep -q "Usage: athlos video" "$WORK/out" || fail "video --help has no usage line"
finish
