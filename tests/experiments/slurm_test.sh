#!/usr/bin/env bash
# End-to-end test of experiments/slurm/ on a real Slurm: starts munged, a
# slurmctld and a slurmd for a one-node cluster on localhost (private key,
# socket, ports, state and spool under a temporary directory; nothing in
# /etc is touched), submits a quick study as a 2-task job array plus its
# merge job with submit.sh, waits for them, and checks that the merged
# runs.csv equals a local unsharded run's, timing and environment columns
# aside.
#
# Usage: slurm_test.sh HRSPACE_BIN SOURCE_DIR
# Needs root and the Debian packages slurm-wlm (slurmctld, slurmd,
# slurm-client) and munge; installs nothing.
# Exit status: 0 pass, 1 fail, 2 usage, 77 skip (packages missing, not
# root, or the daemons cannot start here: the reason is printed).
set -u
[ $# -eq 2 ] || { echo "usage: slurm_test.sh HRSPACE_BIN SOURCE_DIR" >&2; exit 2; }
bin=$(realpath "$1") src=$(realpath "$2")
submit="$src/experiments/slurm/submit.sh"
[ -x "$bin" ] || { echo "slurm_test: $bin: not an executable" >&2; exit 2; }
[ -f "$submit" ] || { echo "slurm_test: $submit: missing" >&2; exit 2; }

# The study: cheap (about 3 s) and 4 runs, so each of the 2 shards has some.
study=designs shards=2 opts=(--quick --seeds 2 --iterations 30)
start=$SECONDS

skip() { echo "SKIP: $*"; exit 77; }
for tool in munged munge unmunge slurmctld slurmd sbatch sinfo squeue scontrol scancel python3; do
  command -v "$tool" >/dev/null || skip "$tool not found (install munge slurm-wlm slurm-client)"
done
[ "$(id -u)" = 0 ] || skip "needs root (slurmd runs jobs as their user)"
# A test run inside a Slurm job must not talk to that job's cluster.
for v in $(compgen -e | grep -E '^(SLURM|SBATCH|SALLOC|SQUEUE|SINFO|SCONTROL)_'); do unset "$v"; done

tmp=$(mktemp -d /tmp/hrspace-slurm.XXXXXX)
chmod 755 "$tmp"  # munged wants its socket's directories traversable by all
pids=() jobs=""
show_logs() {  # the daemons' and jobs' logs, for a failure or a skip
  for f in "$tmp"/log/* "$tmp"/out/logs/*; do
    [ -s "$f" ] || continue
    echo "--- $f"; tail -n 25 "$f"
  done
}
cleanup() {
  local job_ids
  IFS=, read -ra job_ids <<<"$jobs"
  [ ${#job_ids[@]} -gt 0 ] && scancel "${job_ids[@]}" 2>/dev/null
  # Jobs end before the daemons go, so that no hrspace outlives the test.
  for _ in $(seq 20); do
    [ -z "$jobs" ] || ! squeue -h -j "$jobs" -t PD,R,CG,CF,S -o %i 2>/dev/null | grep -q . && break
    sleep 0.5
  done
  # Daemons, newest first, by the pids this script started.
  for ((k = ${#pids[@]} - 1; k >= 0; k--)); do kill "${pids[k]}" 2>/dev/null; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 40); do kill -0 "$pid" 2>/dev/null || break; sleep 0.25; done
    kill -9 "$pid" 2>/dev/null
  done
  wait 2>/dev/null
  rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP
fail() { echo "FAIL: $*"; show_logs; exit 1; }
skip_daemons() { show_logs; skip "$*"; }
alive() { kill -0 "$1" 2>/dev/null; }
mkdir -p "$tmp"/{munge,state,spool,log}

# --- munge: a private key and daemon, so a system munged (if any) is left alone.
key=$tmp/munge/munge.key
if ! mungekey --create --keyfile="$key" 2>"$tmp/log/mungekey.out"; then
  dd if=/dev/urandom of="$key" bs=1024 count=1 status=none && chmod 600 "$key"
fi
sock=$tmp/munge/munge.socket
munged --foreground --key-file="$key" --socket="$sock" --pid-file="$tmp/munge/munged.pid" \
  --seed-file="$tmp/munge/munged.seed" --log-file="$tmp/log/munged.log" >"$tmp/log/munged.out" 2>&1 &
pids+=($!)
for _ in $(seq 40); do [ -S "$sock" ] && break; alive "${pids[0]}" || break; sleep 0.25; done
munge -S "$sock" -n 2>"$tmp/log/munge-check.out" | unmunge -S "$sock" >>"$tmp/log/munge-check.out" 2>&1 ||
  skip_daemons "munged does not work here (see its log above)"

# --- Slurm: one node, this host, on free ports; jobs run as root without cgroups.
node=$(hostname -s 2>/dev/null || uname -n | cut -d. -f1)
cpus=$(nproc); [ "$cpus" -gt 2 ] && cpus=2
read -r ctld_port slurmd_port < <(python3 -c '
import socket
ss = [socket.socket() for _ in range(2)]
for s in ss: s.bind(("127.0.0.1", 0))
print(*(s.getsockname()[1] for s in ss))')
export SLURM_CONF=$tmp/slurm.conf
cat >"$SLURM_CONF" <<EOF
ClusterName=hrspacetest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$sock
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
MpiDefault=none
ReturnToService=2
# Finished jobs stay visible to scontrol for 10 minutes.
MinJobAge=600
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld -D -c >"$tmp/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -N "$node" >"$tmp/log/slurmd.out" 2>&1 &
pids+=($!)
state=""
for _ in $(seq 120); do  # up to 30 s
  state=$(sinfo -h -n "$node" -o %t 2>/dev/null)
  [ "$state" = idle ] && break
  alive "${pids[1]}" || skip_daemons "slurmctld exited (see its log above)"
  alive "${pids[2]}" || skip_daemons "slurmd exited (see its log above)"
  sleep 0.25
done
[ "$state" = idle ] || skip_daemons "node $node is not idle after 30 s (state '${state:-none}')"
echo "slurm: node $node idle after $((SECONDS - start)) s (ports $ctld_port, $slurmd_port)"

# --- The study on Slurm: 2 array tasks, then the dependent merge job.
ids=$("$submit" --hrspace "$bin" --shards "$shards" --partition test --time 10:00 --parsable \
  "${opts[@]}" "$study" "$tmp/out") || fail "submit.sh failed"
read -r array_id merge_id <<<"$ids"
jobs=$array_id,$merge_id
echo "slurm: array job $array_id, merge job $merge_id"

# --- Meanwhile the same study locally, unsharded (it is 3 s of CPU).
"$bin" experiment "$study" "${opts[@]}" --out "$tmp/local" >"$tmp/log/local.out" 2>&1 ||
  fail "local run failed: $(cat "$tmp/log/local.out")"

job_state() { scontrol -o show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2 | sort -u | paste -sd,; }
merge_state=""
for _ in $(seq 480); do  # up to 240 s
  merge_state=$(job_state "$merge_id")
  case "$merge_state" in PENDING* | RUNNING* | CONFIGURING* | COMPLETING* | "") sleep 0.5 ;; *) break ;; esac
done
array_state=$(job_state "$array_id")
echo "slurm: array tasks $array_state, merge $merge_state after $((SECONDS - start)) s"
[ "$array_state" = COMPLETED ] || fail "array tasks ended ${array_state:-unknown}"
[ "$merge_state" = COMPLETED ] || fail "merge job ${merge_state:-unknown} (failed, or not done in 240 s)"
for i in $(seq "$shards"); do
  [ -n "$(ls "$tmp/out/shards/shard-$i/$study/runs")" ] || fail "shard $i stored no run"
done

# --- Merged == local, apart from timing (_s, _ms) and environment columns.
python3 - "$tmp/out/$study/runs.csv" "$tmp/local/$study/runs.csv" <<'EOF' || fail "merged runs.csv differs from the local run's"
import csv, sys

# Timing columns end in _s or _ms; planning_share (planning_s / total_s) is
# one too although its name does not say so. Environment: commit, cpu, cores.
IGNORED = {"planning_share", "commit", "cpu", "cores"}

def rows(path):
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        keep = [c for c in reader.fieldnames
                if not (c.endswith("_s") or c.endswith("_ms") or c in IGNORED)]
        return keep, sorted((tuple(r[c] for c in keep) for r in reader))

(cols_a, a), (cols_b, b) = rows(sys.argv[1]), rows(sys.argv[2])
if cols_a != cols_b:
    sys.exit(f"columns differ:\n  merged {cols_a}\n  local  {cols_b}")
if not a:
    sys.exit("no rows")
if a != b:
    for ra, rb in zip(a, b):
        for c, x, y in zip(cols_a, ra, rb):
            if x != y:
                print(f"  {c}: merged {x!r}, local {y!r}")
    sys.exit(f"{len(a)} merged rows vs {len(b)} local rows, contents differ")
print(f"runs.csv: {len(a)} rows equal over {len(cols_a)} columns")
EOF
echo "PASS: slurm array + merge of '$study' equals the local run ($((SECONDS - start)) s)"
