#!/usr/bin/env bash
# A real Slurm job array renders a 16-frame animation, one shard per task,
# and every frame must match a single-process render bit for bit.
#
#   tests/slurm/run_slurm_test.sh MARCHSTUDIO_BINARY
#
# Starts its own single-node cluster on localhost: munged, slurmctld and
# slurmd as root, with every key, socket, state, spool, log and pid file in
# a temporary directory and random ports, so it touches no system Slurm or
# munge set-up. Installs nothing: it expects Debian's slurm-wlm and munge
# (tools/install-deps.sh). Exit 0: passed; 1: failed; 77: skipped (ctest's
# SKIP_RETURN_CODE) because Slurm cannot run here, with the reason printed.
set -uo pipefail

BIN=${1:?usage: $0 MARCHSTUDIO_BINARY}
BIN=$(cd "$(dirname "$BIN")" && pwd)/$(basename "$BIN")
SRC=$(cd "$(dirname "$0")/../.." && pwd)
FRAMES=0..15
NFRAMES=16
TASKS=4
WAIT_S=120

# Debian installs the daemons in /usr/sbin, which a non-login PATH may lack.
PATH=$PATH:/usr/sbin:/sbin

skip() { echo "SKIP: $*"; exit 77; }
fail() { echo "FAIL: $*"; show_logs; exit 1; }

[ -x "$BIN" ] || { echo "FAIL: $BIN is not an executable"; exit 1; }
[ "$(id -u)" = 0 ] || skip "needs root: slurmd must be able to start jobs as the submitting user and switch to it"
for prog in munged munge slurmctld slurmd sbatch squeue scontrol sinfo idiff; do
  command -v "$prog" >/dev/null ||
    skip "'$prog' is not on PATH (Debian packages: slurm-wlm munge openimageio-tools; see tools/install-deps.sh)"
done

WORK=$(mktemp -d /tmp/marchslurm-XXXXXX)
# munged insists that everyone may traverse its socket's directory.
chmod 755 "$WORK"
PIDS=()
show_logs() {
  for f in "$WORK"/munged.log "$WORK"/slurmctld.log "$WORK"/slurmd.log "$WORK"/job/slurm-*.out; do
    [ -f "$f" ] && { echo "--- $f (last 15 lines)"; tail -n 15 "$f"; }
  done
}
stop_daemons() {
  # Newest first: slurmd, then slurmctld, then munged. Only our own pids.
  for ((i = ${#PIDS[@]} - 1; i >= 0; i--)); do kill "${PIDS[i]}" 2>/dev/null; done
  for pid in "${PIDS[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null
  done
  PIDS=()
}
cleanup() { stop_daemons; rm -rf "$WORK"; }
trap cleanup EXIT

# wait_for SECONDS COMMAND...: poll until COMMAND succeeds.
wait_for() {
  local limit=$1; shift
  for _ in $(seq $((limit * 5))); do "$@" >/dev/null 2>&1 && return 0; sleep 0.2; done
  return 1
}

# --- munge, with its own key and socket
dd if=/dev/urandom of="$WORK/munge.key" bs=1024 count=1 status=none
chmod 400 "$WORK/munge.key"
munged -F --key-file="$WORK/munge.key" --socket="$WORK/munge.sock" --pid-file="$WORK/munged.pid" \
  --log-file="$WORK/munged.log" --seed-file="$WORK/munge.seed" >>"$WORK/munged.log" 2>&1 &
PIDS+=($!)
wait_for 10 bash -c "echo x | munge -S '$WORK/munge.sock' | unmunge -S '$WORK/munge.sock'" ||
  { show_logs; skip "munged did not start or cannot encode/decode a credential (log above)"; }

# --- slurm.conf: one node, this host, no cgroups, no accounting
HOST=$(hostname -s)
PORT=$((20000 + RANDOM % 20000))
mkdir -p "$WORK/state" "$WORK/spool" "$WORK/job/frames" "$WORK/ref"
cat >"$WORK/slurm.conf" <<EOF
ClusterName=marchtest
SlurmctldHost=$HOST(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$PORT
SlurmdPort=$((PORT + 1))
AuthType=auth/munge
AuthInfo=socket=$WORK/munge.sock
CredType=cred/munge
StateSaveLocation=$WORK/state
SlurmdSpoolDir=$WORK/spool
SlurmctldPidFile=$WORK/slurmctld.pid
SlurmdPidFile=$WORK/slurmd.pid
SlurmctldLogFile=$WORK/slurmctld.log
SlurmdLogFile=$WORK/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
NodeName=$HOST NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=march Nodes=$HOST Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$WORK/slurm.conf"

slurmctld -D -c -f "$SLURM_CONF" >>"$WORK/slurmctld.out" 2>&1 &
PIDS+=($!)
wait_for 20 bash -c "scontrol ping | grep -q UP" ||
  { show_logs; cat "$WORK/slurmctld.out"; skip "slurmctld did not come up on port $PORT (log above)"; }
slurmd -D -N "$HOST" -f "$SLURM_CONF" >>"$WORK/slurmd.out" 2>&1 &
PIDS+=($!)
wait_for 30 bash -c "sinfo -h -N -o %T | grep -qx idle" ||
  { show_logs; cat "$WORK/slurmd.out"; skip "slurmd did not register its node as idle (state: $(sinfo -h -N -o %T 2>&1))"; }
echo "slurm: controller and node up on $HOST, ports $PORT-$((PORT + 1))"

# --- the array: 4 tasks, one shard each, 16 frames of a keyframed scene
SCENE="$SRC/tests/data/anim/orbit.toml"
FLAGS=(--size 96x54 --fps 8)
start=$(date +%s%N)
JOB=$(sbatch --parsable --array=0-$((TASKS - 1)) --cpus-per-task=1 --chdir="$WORK/job" \
  --output="$WORK/job/slurm-%A_%a.out" --export=ALL,MARCHSTUDIO="$BIN" \
  "$SRC/tools/slurm/render_array.sh" "$SCENE" "$FRAMES" "$WORK/job/frames/f_%02d.png" "${FLAGS[@]}") ||
  fail "sbatch refused the job array"
echo "slurm: submitted array job $JOB ($TASKS tasks)"
wait_for "$WAIT_S" bash -c "[ -z \"\$(squeue -h -j $JOB 2>/dev/null)\" ]" ||
  fail "job $JOB still queued or running after ${WAIT_S}s: $(squeue -h -j "$JOB" 2>&1)"
elapsed=$(( ($(date +%s%N) - start) / 1000000 ))
states=$(scontrol -o show job "$JOB" | grep -o 'JobState=[A-Z_]*' | sort | uniq -c | tr -s ' ')
echo "slurm: job $JOB finished in ${elapsed} ms after submission; task states:$states"
[ "$(scontrol -o show job "$JOB" | grep -c 'JobState=COMPLETED')" = "$TASKS" ] || fail "not every task completed"

# --- each frame written by exactly one task, and all of them there
written=$(cat "$WORK"/job/slurm-*.out | grep -c '/frames/f_.*\.png$')
unique=$(cat "$WORK"/job/slurm-*.out | grep '/frames/f_.*\.png$' | sort -u | wc -l)
[ "$written" = "$NFRAMES" ] && [ "$unique" = "$NFRAMES" ] ||
  fail "tasks wrote $written frames ($unique distinct), expected $NFRAMES, each once"

# --- bit for bit against one process rendering the whole range
"$BIN" render "$SCENE" --frames "$FRAMES" -o "$WORK/ref/f_%02d.png" "${FLAGS[@]}" >/dev/null 2>"$WORK/ref.log" ||
  fail "the single-process reference render failed: $(tail -n 1 "$WORK/ref.log")"
for i in $(seq 0 $((NFRAMES - 1))); do
  name=$(printf 'f_%02d.png' "$i")
  [ -f "$WORK/job/frames/$name" ] || fail "frame $name is missing"
  idiff -fail 0 -failpercent 0 -warn 0 "$WORK/ref/$name" "$WORK/job/frames/$name" >"$WORK/idiff.txt" 2>&1 ||
    fail "frame $name differs from the single-process render: $(tr '\n' ' ' <"$WORK/idiff.txt")"
done
echo "PASS: $TASKS Slurm array tasks rendered all $NFRAMES frames once each, identical to a single-process render"
