#!/usr/bin/env bash
# athlos batch, local engine (issue #15, item 5): 8 projects with --jobs 1 and --jobs 2 give identical
# results; a project without the input stream fails with its reason while the others succeed and stays
# byte-identical; a re-run skips every done project and changes nothing; --summary stacks the tables;
# a worker killed with SIGKILL mid-run, and a batch cancelled with Ctrl-C, leave their projects as they were.
source "$(dirname "$0")/lib/common.bash" "$@"
cd "$WORK" || exit 1
cat > pipe.json <<'JSON'
{"name": "batch-test", "steps": [
  {"processor": "gait-events", "input": "limb/sim-shank", "output": "limb/events"},
  {"processor": "butterworth", "input": "limb/sim", "output": "limb/smooth", "params": {"cutoff": 5}}]}
JSON
mkdir base j1 j2 j3
for i in 1 2 3 4 5 6 7 8; do
  expect_ok "new p$i" "$ATHLOS" new "base/p$i.athlos"
  expect_ok "simulate p$i" "$ATHLOS" run "base/p$i.athlos" simulate-limb --output limb/sim --param seed="$i" \
    --param walk_duration=$((10 + i))
done
cp base/*.athlos j1/; cp base/*.athlos j2/; cp base/*.athlos j3/

expect_ok "batch --jobs 1" "$ATHLOS" batch pipe.json j1/p{1..8}.athlos --jobs 1
cp "$WORK/out" jobs1.out
[ "$(grep -c ': done (' jobs1.out)" = 8 ] || fail "--jobs 1: not 8 projects done: $(cat jobs1.out)"
expect_ok "batch --jobs 2" "$ATHLOS" batch pipe.json j2/p{1..8}.athlos --jobs 2 --summary summary.csv \
  --summary-table gait-events
cp "$WORK/out" jobs2.out
[ "$(grep -c ': done (' jobs2.out)" = 8 ] || fail "--jobs 2: not 8 projects done: $(cat jobs2.out)"
grep -q '^batch: 8 done, 0 skipped, 0 failed' jobs2.out || fail "--jobs 2: no totals line: $(tail -2 jobs2.out)"
rows=0
for i in 1 2 3 4 5 6 7 8; do
  for item in limb/events limb/smooth; do
    n=${item#limb/}
    expect_ok "export j1 p$i $n" "$ATHLOS" export "j1/p$i.athlos" "$item" --to "j1-p$i-$n.csv"
    expect_ok "export j2 p$i $n" "$ATHLOS" export "j2/p$i.athlos" "$item" --to "j2-p$i-$n.csv"
    cmp -s "j1-p$i-$n.csv" "j2-p$i-$n.csv" || fail "p$i $item differs between --jobs 1 and --jobs 2"
  done
  [ "$(wc -l < "j1-p$i-events.csv")" -gt 5 ] || fail "p$i: gait-events found almost nothing"
  rows=$((rows + $(wc -l < "j2-p$i-events.csv") - 1))
done

# --summary: one row per event of every project, leading columns project and recording, then the table's.
head -1 summary.csv | grep -q '^project,recording,t \[s\],type,foot$' || fail "summary header: $(head -1 summary.csv)"
[ "$(($(wc -l < summary.csv) - 1))" = "$rows" ] || fail "summary has $(($(wc -l < summary.csv) - 1)) rows, expected $rows"
for i in 1 8; do
  tail -n +2 "j2-p$i-events.csv" | sed "s|^|j2/p$i.athlos,limb,|" > "expect-p$i.csv"
  grep "^j2/p$i.athlos," summary.csv | cmp -s - "expect-p$i.csv" || fail "summary rows of p$i differ from its export"
done

# A re-run skips every project (provenance: same processor versions, parameters and input hashes).
cp -r j1 j1-after
expect_ok "re-run" "$ATHLOS" batch pipe.json j1/p{1..8}.athlos --jobs 2
[ "$(grep -c 'skipped (done)' "$WORK/out")" = 8 ] || fail "re-run did not skip all 8: $(cat "$WORK/out")"
for i in 1 2 3 4 5 6 7 8; do cmp -s "j1/p$i.athlos" "j1-after/p$i.athlos" || fail "re-run changed p$i"; done
# Another parameter is not the same run: that project is computed again.
sed 's/"cutoff": 5/"cutoff": 6/' pipe.json > pipe6.json
expect_ok "changed parameter" "$ATHLOS" batch pipe6.json j1/p1.athlos
grep -q 'p1.athlos: done' "$WORK/out" || fail "changed parameter was skipped: $(cat "$WORK/out")"

# A project without the input fails with the runner's reason; the others succeed; exit code 1.
expect_ok "new bad" "$ATHLOS" new j3/bad.athlos
cp j3/bad.athlos bad.copy
if "$ATHLOS" batch pipe.json j3/p1.athlos j3/bad.athlos j3/p2.athlos --jobs 2 > fail.out 2> fail.err; then
  fail "batch with a failing project exited 0"
fi
grep -qE "j3/bad.athlos: failed: .*limb/sim-shank.*no stream" fail.out || fail "no reason for bad.athlos: $(cat fail.out)"
[ "$(grep -c ': done (' fail.out)" = 2 ] || fail "the good projects did not succeed: $(cat fail.out)"
grep -q "1 of 3 project(s) failed" fail.err || fail "stderr: $(cat fail.err)"
cmp -s j3/bad.athlos bad.copy || fail "the failed project changed"

# A worker killed with SIGKILL mid-run leaves its project byte-identical (atomic save).
expect_ok "new slow" "$ATHLOS" new slow.athlos
expect_ok "simulate slow" "$ATHLOS" run slow.athlos simulate-track-run --output sim/run --param distance=3000 \
  --param top_speed=5
cp slow.athlos slow.copy
cat > slow.json <<'JSON'
{"steps": [{"processor": "position-filter", "input": "sim/run", "output": "sim/filtered"}]}
JSON
"$ATHLOS" batch slow.json slow.athlos --jobs 1 > killed.out 2> killed.err &
BATCH=$!
worker=""
for _ in $(seq 100); do
  worker=$(pgrep -P "$BATCH" | head -1)
  [ -n "$worker" ] && break
  sleep 0.1
done
if [ -n "$worker" ]; then
  sleep 1
  kill -9 "$worker"
  wait "$BATCH"; rc=$?
  [ "$rc" = 1 ] || fail "batch with a killed worker exited $rc"
  grep -q "slow.athlos: failed: the worker process was killed" killed.out || fail "killed worker: $(cat killed.out)"
  cmp -s slow.athlos slow.copy || fail "the killed worker's project changed"
else
  wait "$BATCH"; fail "no worker process appeared"
fi

# Ctrl-C (SIGINT to batch) stops the workers; exit code 130; their projects stay as they were.
cp slow.copy slow2.athlos; cp slow.copy slow3.athlos
"$ATHLOS" batch slow.json slow2.athlos slow3.athlos --jobs 2 > int.out 2> int.err &
BATCH=$!
for _ in $(seq 100); do [ "$(pgrep -P "$BATCH" | wc -l)" = 2 ] && break; sleep 0.1; done
sleep 1
kill -INT "$BATCH"
wait "$BATCH"; rc=$?
[ "$rc" = 130 ] || fail "cancelled batch exited $rc: $(cat int.out int.err)"
grep -q "cancelled" int.err || fail "cancelled batch: stderr $(cat int.err)"
cmp -s slow2.athlos slow.copy || fail "cancelled: slow2 changed"
cmp -s slow3.athlos slow.copy || fail "cancelled: slow3 changed"

expect_fail "unknown engine" "--engine 'pbs'" "$ATHLOS" batch pipe.json j1/p1.athlos --engine pbs
expect_fail "bad jobs" "--jobs '0'" "$ATHLOS" batch pipe.json j1/p1.athlos --jobs 0
expect_fail "no pipeline" "nope.json" "$ATHLOS" batch nope.json j1/p1.athlos
finish
