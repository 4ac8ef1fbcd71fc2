#!/usr/bin/env bash
# athlos batch --engine slurm against a real single-node Slurm that this script starts and stops
# (issue #15, item 5): munged (as user munge, private socket), slurmctld and slurmd from Debian's
# packages, configured in a temporary folder (non-default ports, linuxproc/none plugins, root), one
# node with this machine's CPUs. The batch runs as one job array; its projects must end identical to a
# --engine local run; a failing project is reported with its reason; a re-run skips everything.
# Without root or the Slurm/munge programs the test prints why and is skipped (exit 77).
source "$(dirname "$0")/lib/common.bash" "$@"
SKIP=77
skip() { echo "SKIP: $*"; exit $SKIP; }
[ "$(id -u)" = 0 ] || skip "needs root to run slurmd/slurmctld (SlurmUser=root)"
for tool in munged slurmctld slurmd sbatch squeue sinfo scontrol scancel setpriv; do
  command -v "$tool" >/dev/null 2>&1 || skip "'$tool' is not installed (apt-get install slurmd slurmctld slurm-client munge)"
done
id munge >/dev/null 2>&1 || skip "no user 'munge'"

# Daemons live in a folder of their own (the common WORK is removed by its trap; ours stops them first).
S=$(mktemp -d /tmp/athlos-slurm.XXXXXX); chmod 755 "$S"
mkdir -p "$S/munge" "$S/state" "$S/spool" "$S/log"
PIDS=()
stop_all() {
  local pid
  for pid in "${PIDS[@]}"; do kill "$pid" 2>/dev/null; done
  for pid in "${PIDS[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null
  done
  rm -rf "$S" "$WORK"
}
trap stop_all EXIT
dump_logs() { for f in "$S"/log/* "$S"/munge/munged.log; do [ -f "$f" ] && { echo "--- $f"; tail -20 "$f"; }; done; }

# munge: the installed key, or a fresh one in our folder; munged as user munge on a private socket.
KEY=/etc/munge/munge.key
if [ ! -r "$KEY" ]; then
  KEY="$S/munge/munge.key"
  dd if=/dev/urandom of="$KEY" bs=1 count=1024 2>/dev/null
fi
cp "$KEY" "$S/munge/key"; KEY="$S/munge/key"
chown -R munge:munge "$S/munge"; chmod 700 "$S/munge"; chmod 400 "$KEY"; chmod 755 "$S/munge"
SOCKET="$S/munge/munge.socket"
setpriv --reuid=munge --regid=munge --init-groups munged -F --socket="$SOCKET" --key-file="$KEY" \
  --pid-file="$S/munge/munged.pid" --log-file="$S/munge/munged.log" --seed-file="$S/munge/seed" \
  > "$S/log/munged.out" 2>&1 &
PIDS+=($!)
for _ in $(seq 50); do [ -S "$SOCKET" ] && break; sleep 0.1; done
[ -S "$SOCKET" ] || { dump_logs; skip "munged did not start"; }

HOST=$(hostname -s)
PORT=$((20000 + RANDOM % 20000))
export SLURM_CONF="$S/slurm.conf"
cat > "$SLURM_CONF" <<CONF
ClusterName=athlostest
SlurmctldHost=$HOST
SlurmctldPort=$PORT
SlurmdPort=$((PORT + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$SOCKET
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
StateSaveLocation=$S/state
SlurmdSpoolDir=$S/spool
SlurmctldLogFile=$S/log/slurmctld.log
SlurmdLogFile=$S/log/slurmd.log
SlurmctldPidFile=$S/slurmctld.pid
SlurmdPidFile=$S/slurmd.pid
NodeName=$HOST CPUs=$(nproc) RealMemory=1000 State=UNKNOWN
PartitionName=athlos Nodes=$HOST Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -D -f "$SLURM_CONF" > "$S/log/slurmctld.out" 2>&1 &
PIDS+=($!)
sleep 1
slurmd -D -f "$SLURM_CONF" > "$S/log/slurmd.out" 2>&1 &
PIDS+=($!)
state=""
for _ in $(seq 120); do
  state=$(sinfo -h -n "$HOST" -o %T 2>/dev/null | head -1)
  [ "$state" = idle ] && break
  sleep 0.5
done
[ "$state" = idle ] || { dump_logs; skip "the Slurm node did not become idle within 60 s (state '$state')"; }
echo "slurm up: node $HOST idle, ports $PORT/$((PORT + 1))"

cd "$WORK" || exit 1
cat > pipe.json <<'JSON'
{"name": "batch-slurm", "steps": [
  {"processor": "gait-events", "input": "limb/sim-shank", "output": "limb/events"},
  {"processor": "butterworth", "input": "limb/sim", "output": "limb/smooth", "params": {"cutoff": 5}}]}
JSON
mkdir base local slurm
for i in 1 2 3 4 5; do
  expect_ok "new p$i" "$ATHLOS" new "base/p$i.athlos"
  expect_ok "simulate p$i" "$ATHLOS" run "base/p$i.athlos" simulate-limb --output limb/sim --param seed="$i" \
    --param walk_duration=$((10 + i))
done
expect_ok "new bad" "$ATHLOS" new base/bad.athlos
cp base/*.athlos local/; cp base/*.athlos slurm/

expect_ok "batch local" "$ATHLOS" batch pipe.json local/p{1..5}.athlos --jobs 2
"$ATHLOS" batch pipe.json slurm/p{1..5}.athlos slurm/bad.athlos --engine slurm --chunk 2 --poll 0.5 \
  --slurm-args "--time=10 --job-name=athlos-ci" --work-dir "$WORK/wd" --summary summary.csv \
  --summary-table gait-events > slurm.out 2> slurm.err
rc=$?
cat slurm.out
[ "$rc" = 1 ] || { dump_logs; fail "slurm batch with a failing project exited $rc: $(cat slurm.err)"; }
grep -q "submitted Slurm job array" slurm.out || fail "no job array submitted"
[ "$(grep -c ': done (' slurm.out)" = 5 ] || fail "slurm: not 5 projects done"
grep -qE "slurm/bad.athlos: failed: .*limb/sim-shank.*no stream" slurm.out || fail "slurm: no reason for bad.athlos"
cmp -s slurm/bad.athlos base/bad.athlos || fail "slurm: the failed project changed"
[ -f "$WORK/wd/job.sh" ] || fail "slurm: the work folder was not kept after a failure"
for i in 1 2 3 4 5; do
  for item in limb/events limb/smooth; do
    n=${item#limb/}
    expect_ok "export local p$i $n" "$ATHLOS" export "local/p$i.athlos" "$item" --to "local-p$i-$n.csv"
    expect_ok "export slurm p$i $n" "$ATHLOS" export "slurm/p$i.athlos" "$item" --to "slurm-p$i-$n.csv"
    cmp -s "local-p$i-$n.csv" "slurm-p$i-$n.csv" || fail "p$i $item: slurm and local results differ"
  done
done
[ "$(grep -c '^slurm/p' summary.csv)" -gt 20 ] || fail "summary: too few rows: $(wc -l < summary.csv)"

# A re-run through Slurm skips every done project; the work folder goes when nothing failed.
cp -r slurm slurm-after
expect_ok "slurm re-run" "$ATHLOS" batch pipe.json slurm/p{1..5}.athlos --engine slurm --poll 0.5 --work-dir "$WORK/wd2"
[ "$(grep -c 'skipped (done)' "$WORK/out")" = 5 ] || fail "slurm re-run did not skip all 5: $(cat "$WORK/out")"
for i in 1 2 3 4 5; do cmp -s "slurm/p$i.athlos" "slurm-after/p$i.athlos" || fail "slurm re-run changed p$i"; done
[ -e "$WORK/wd2" ] && fail "the work folder of a successful run was not removed"

# Ctrl-C while the array runs: scancel, exit code 130, the project as it was, no task left in the queue.
expect_ok "new slow" "$ATHLOS" new slow.athlos
expect_ok "simulate slow" "$ATHLOS" run slow.athlos simulate-track-run --output sim/run --param distance=3000 \
  --param top_speed=5
cp slow.athlos slow.copy
echo '{"steps": [{"processor": "position-filter", "input": "sim/run", "output": "sim/filtered"}]}' > slow.json
"$ATHLOS" batch slow.json slow.athlos --engine slurm --poll 0.5 --work-dir "$WORK/wd4" > int.out 2> int.err &
BATCH=$!
running=""
for _ in $(seq 100); do
  running=$(squeue -h -o %T 2>/dev/null | grep -c RUNNING)
  [ "$running" -gt 0 ] && break
  sleep 0.2
done
sleep 1
kill -INT "$BATCH"
wait "$BATCH"; rc=$?
[ "$rc" = 130 ] || fail "cancelled slurm batch exited $rc: $(cat int.out int.err)"
cmp -s slow.athlos slow.copy || fail "cancelled slurm batch: the project changed"
for _ in $(seq 50); do [ -z "$(squeue -h 2>/dev/null)" ] && break; sleep 0.2; done
[ -z "$(squeue -h 2>/dev/null)" ] || fail "tasks left in the queue after cancelling: $(squeue -h)"

# sbatch refusing the job (an unknown partition) is one line naming sbatch.
expect_fail "bad partition" "sbatch refused" "$ATHLOS" batch pipe.json slurm/p1.athlos --engine slurm \
  --slurm-args "--partition=nosuchpartition" --work-dir "$WORK/wd3"
finish
