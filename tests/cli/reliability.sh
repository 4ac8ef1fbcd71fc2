#!/usr/bin/env bash
# Issue #11: damaged project files never crash or hang a command and are never changed; one writer
# per project (a second is refused with the reason); stale saves of a killed process are dealt with;
# kill -9 during a pipeline leaves the project readable and either old or new.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
make_imu_csv "$WORK/imu.csv" 3000
expect_ok "new" "$ATHLOS" new "$P"
expect_ok "import" "$ATHLOS" import "$P" "$WORK/imu.csv" --as rec --kind imu
expect_ok "filter" "$ATHLOS" run "$P" butterworth --input rec/imu --output rec/lp --param cutoff=5
expect_ok "beacons" "$ATHLOS" import "$P" "$TEST_DATA/beacons.csv" --as rec --kind beacons

# --- Damaged files: mutate 1–16 bytes at random offsets (seeded), run info/export/run on each.
size=$(stat -c %s "$P")
RANDOM=1124
crashes=0; refused=0
for trial in $(seq 1 40); do
  M="$WORK/m$trial.athlos"; cp "$P" "$M"
  n=$((RANDOM % 16 + 1))
  for _ in $(seq 1 "$n"); do
    # Half the trials hit the first 4 KiB (superblock and root metadata), half anywhere.
    if [ $((trial % 2)) -eq 0 ]; then off=$((RANDOM % 4096)); else off=$(( (RANDOM * 32768 + RANDOM) % size )); fi
    printf "\\x$(printf %02x $((RANDOM % 256)))" | dd of="$M" bs=1 seek="$off" conv=notrunc status=none
  done
  cp "$M" "$WORK/m.before"
  for cmd in info export run; do
    case $cmd in
      info) args=(info "$M") ;;
      export) args=(export "$M" rec/imu --to "$WORK/x.csv") ;;
      run) args=(run "$M" resample --input rec/imu --output rec/r --param rate=50) ;;
    esac
    timeout 60 "$ATHLOS" "${args[@]}" >"$WORK/out" 2>"$WORK/err"; rc=$?
    if [ "$rc" -ge 124 ]; then crashes=$((crashes + 1)); fail "mutant $trial: '$cmd' exited $rc (crash or hang)"; continue; fi
    if [ "$rc" -ne 0 ]; then
      refused=$((refused + 1))
      grep -q "athlos: " "$WORK/err" || fail "mutant $trial: '$cmd' failed without a reason"
      cmp -s "$M" "$WORK/m.before" || fail "mutant $trial: failed '$cmd' changed the file"
    fi
  done
done
echo "damaged files: $refused refusals, $crashes crashes or hangs"
[ "$refused" -gt 20 ] || fail "only $refused of 120 commands refused damaged files: is the mutation working?"

# --- One writer: a long pipeline holds the lock; a second writer is refused, a reader is not.
cat > "$WORK/hold.json" <<'JSON'
{"name": "hold", "steps": [
  {"processor": "simulate-imu-gnss", "output": "hold/imu", "params": {"duration": 1800}},
  {"processor": "butterworth", "input": "hold/imu", "output": "hold/a", "params": {"cutoff": 5}},
  {"processor": "butterworth", "input": "hold/imu", "output": "hold/b", "params": {"cutoff": 4}},
  {"processor": "butterworth", "input": "hold/imu", "output": "hold/c", "params": {"cutoff": 3}},
  {"processor": "butterworth", "input": "hold/imu", "output": "hold/d", "params": {"cutoff": 2}},
  {"processor": "butterworth", "input": "hold/imu", "output": "hold/e", "params": {"cutoff": 1}}]}
JSON
cp "$P" "$WORK/before.athlos"
"$ATHLOS" pipeline "$P" "$WORK/hold.json" >/dev/null 2>&1 &
writer=$!
for _ in $(seq 1 100); do [ -e "$WORK/.p.athlos.lock" ] && break; sleep 0.05; done
if [ -e "$WORK/.p.athlos.lock" ]; then
  expect_fail "second writer" "being changed by another Athlos process" \
    "$ATHLOS" run "$P" resample --input rec/imu --output rec/r2 --param rate=50
  expect_ok "reader beside a writer" "$ATHLOS" info "$P"
else
  fail "the pipeline did not take the project's lock"
fi
# Killed while holding the lock: the file is as before, and the lock is stale, not a dead end.
kill -9 "$writer" 2>/dev/null; wait "$writer" 2>/dev/null
cmp -s "$P" "$WORK/before.athlos" || "$ATHLOS" info "$P" | grep -q "hold/e" || fail "kill -9 of the writer left a mixed project"
expect_ok "writer after the holder was killed" "$ATHLOS" run "$P" resample --input rec/imu --output rec/r2 --param rate=50

# --- Stale saves: an unfinished one is removed, a complete one kept, each with a note.
head -c 5000 "$P" > "$WORK/.p.athlos.tmp-00000000deadbeef"
expect_ok "open after a killed save" "$ATHLOS" run "$P" resample --input rec/imu --output rec/r3 --param rate=25
grep -q "removed '.p.athlos.tmp-00000000deadbeef'" "$WORK/err" || fail "no note about the removed temporary file: $(cat "$WORK/err")"
[ -e "$WORK/.p.athlos.tmp-00000000deadbeef" ] && fail "the unfinished save is still there"
cp "$P" "$WORK/.p.athlos.tmp-0000000012345678"
expect_ok "open after a save killed before its rename" "$ATHLOS" run "$P" resample --input rec/imu --output rec/r4 --param rate=20
grep -q "kept as 'p.recovered-" "$WORK/err" || fail "no note about the recovered save: $(cat "$WORK/err")"
ls "$WORK"/p.recovered-*.athlos >/dev/null 2>&1 || fail "the complete save was not kept"

# --- kill -9 during a pipeline, at several moments: the file is the old one or the new one.
cat > "$WORK/long.json" <<'JSON'
{"name": "long", "steps": [
  {"processor": "simulate-imu-gnss", "output": "sim/imu", "params": {"duration": 1800}},
  {"processor": "butterworth", "input": "sim/imu", "output": "sim/lp", "params": {"cutoff": 5}}]}
JSON
for delay in 0.2 0.6 1.0 1.5 2.5; do
  cp "$P" "$WORK/old.athlos"
  "$ATHLOS" pipeline "$P" "$WORK/long.json" >/dev/null 2>&1 &
  pid=$!
  sleep "$delay"; kill -9 "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
  if ! "$ATHLOS" info "$P" >"$WORK/info" 2>"$WORK/err"; then
    fail "kill -9 after ${delay}s left an unreadable project: $(cat "$WORK/err")"
  elif ! cmp -s "$P" "$WORK/old.athlos" && ! grep -q "sim/lp" "$WORK/info"; then
    fail "kill -9 after ${delay}s left a project that is neither the old nor the new one"
  fi
  # The killed writer's lock is stale: the next writer takes it over.
  expect_ok "writer after kill -9 at ${delay}s" "$ATHLOS" run "$P" resample --input rec/imu --output rec/r5 --param rate=10
done
finish
