#!/usr/bin/env bash
# Submits an hrspace study to Slurm: a job array with one shard per task
# (hrspace-array.sbatch) and a merge job (hrspace-merge.sbatch) that starts
# when every task succeeded. See README.md in this directory.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
prog=submit.sh

usage() {
  cat <<EOF
usage: $prog [options] STUDY OUT

Runs 'hrspace experiment STUDY' as N shards, array task i writing
OUT/shards/shard-i, then merges them into OUT (OUT/STUDY/runs.csv, ...).
Logs go to OUT/logs/. STUDY is a study name or 'all' (hrspace experiment list).
OUT, like the hrspace binary, must be on a filesystem the compute nodes share.

hrspace:
  --hrspace PATH     the binary (default: \$HRSPACE, else the source tree's
                     build/cli/hrspace, else hrspace on PATH)
  --seeds N, --iterations N, --quick, --rooms LIST, --scenes DIR
                     the study's options, given to every shard and the merge
  --jobs J           designs run at once in a task (default 1; use with --cpus)
sharding:
  --shards N         number of shards = array tasks (default 4)
  --array LIST       submit only these tasks of 1..N, e.g. 3,7 to rerun failed
                     ones (default 1-N); stored runs are skipped anyway
  --max-running K    at most K tasks at once (sbatch --array=...%K)
  --no-merge         submit the array only
Slurm:
  --cpus C           CPUs per task (default 1); hrspace --threads follows it
  --partition P, --account A, --qos Q
  --time T           time limit of a task (sbatch --time), e.g. 02:00:00
  --mem M            memory of a task (sbatch --mem), e.g. 4G
  --merge-time T     time limit of the merge job (default: --time)
  --sbatch ARG       another sbatch option for both jobs (repeatable),
                     e.g. --sbatch=--mail-type=END
other:
  --parsable         print only "ARRAY_JOB_ID MERGE_JOB_ID" (merge id: - if none)
  --dry-run          print the sbatch commands instead of running them
  -h, --help         this text

Exit status: 0 submitted, 1 sbatch failed, 2 usage error.
EOF
}
die() { echo "$prog: $*" >&2; exit 2; }
need() { [ $# -ge 2 ] && [ -n "$2" ] || die "$1 needs a value"; }
posint() { [[ "$2" =~ ^[1-9][0-9]*$ ]] || die "$1 '$2': expected a positive integer"; }

bin=${HRSPACE:-} shards=4 array="" max_running="" merge=1 cpus=1
task_time="" task_mem="" merge_time="" parsable=0 dry_run=0
study_opts=() task_opts=() sbatch_opts=() positional=()
while [ $# -gt 0 ]; do
  # --opt=value is --opt value
  if [[ "$1" == --*=* ]]; then set -- "${1%%=*}" "${1#*=}" "${@:2}"; fi
  case "$1" in
    -h | --help) usage; exit 0 ;;
    --hrspace) need "$@"; bin=$2; shift ;;
    --seeds | --iterations) need "$@"; posint "$1" "$2"; study_opts+=("$1" "$2"); shift ;;
    --rooms) need "$@"; study_opts+=("$1" "$2"); shift ;;
    --scenes) need "$@"; study_opts+=("$1" "$(realpath -m "$2")"); shift ;;
    --quick) study_opts+=(--quick) ;;
    --jobs) need "$@"; posint "$1" "$2"; task_opts+=(--jobs "$2"); shift ;;
    --shards) need "$@"; posint "$1" "$2"; shards=$2; shift ;;
    --array) need "$@"; [[ "$2" =~ ^[0-9,-]+$ ]] || die "--array '$2': expected a list like 1-4 or 3,7"
      array=$2; shift ;;
    --max-running) need "$@"; posint "$1" "$2"; max_running=$2; shift ;;
    --no-merge) merge=0 ;;
    --cpus) need "$@"; posint "$1" "$2"; cpus=$2; shift ;;
    --partition | --account | --qos) need "$@"; sbatch_opts+=("$1=$2"); shift ;;
    --time) need "$@"; task_time=$2; shift ;;
    --mem) need "$@"; task_mem=$2; shift ;;
    --merge-time) need "$@"; merge_time=$2; shift ;;
    --sbatch) need "$@"; sbatch_opts+=("$2"); shift ;;
    --parsable) parsable=1 ;;
    --dry-run) dry_run=1 ;;
    --) shift; positional+=("$@"); break ;;
    -*) die "unknown option '$1' (see --help)" ;;
    *) positional+=("$1") ;;
  esac
  shift
done
[ ${#positional[@]} -eq 2 ] || die "expected STUDY OUT, got ${#positional[@]} argument(s) (see --help)"
study=${positional[0]} out=${positional[1]}

# The binary, as an absolute path: jobs do not start in this directory.
if [ -z "$bin" ]; then
  if [ -x "$here/../../build/cli/hrspace" ]; then bin="$here/../../build/cli/hrspace"
  else bin=$(command -v hrspace || true); fi
fi
[ -n "$bin" ] || die "no hrspace binary: build it (scripts/build.sh hrspace) or pass --hrspace PATH"
[ -x "$bin" ] && [ -f "$bin" ] || die "$bin: not an executable file"
bin=$(realpath "$bin")
# The study must exist (the login node can run the binary it built).
if [ "$study" != all ] && ! "$bin" experiment list | cut -f1 | grep -qx -- "$study"; then
  die "unknown study '$study'; studies: all $("$bin" experiment list | cut -f1 | tr '\n' ' ')"
fi
[ $dry_run = 1 ] || command -v sbatch >/dev/null || die "sbatch not found: run this on a Slurm login node"

# Outputs: Slurm does not create the log directory and fails jobs silently
# without it, so create it here.
[ $dry_run = 1 ] || mkdir -p "$out/logs" "$out/shards" || die "$out: cannot create"
out=$(realpath -m "$out")

run_sbatch() {  # run_sbatch ARGS...: prints the job id
  if [ $dry_run = 1 ]; then
    printf '%q ' sbatch "$@" >&2; echo >&2
    echo "DRYRUN"
    return
  fi
  local id
  id=$(sbatch --parsable "$@") || { echo "$prog: sbatch failed: sbatch $*" >&2; exit 1; }
  echo "${id%%;*}"  # --parsable prints ID or ID;CLUSTER
}

# The array: one task per shard.
spec=${array:-1-$shards}${max_running:+%$max_running}
args=(--array="$spec" --cpus-per-task="$cpus" --chdir="$out"
      --output="$out/logs/%x-%A_%a.out" "${sbatch_opts[@]}")
[ -n "$task_time" ] && args+=(--time="$task_time")
[ -n "$task_mem" ] && args+=(--mem="$task_mem")
array_id=$(run_sbatch "${args[@]}" "$here/hrspace-array.sbatch" \
  "$bin" "$study" "$out" "$shards" "${study_opts[@]}" "${task_opts[@]}")

# The merge: after every task succeeded; cancelled by Slurm if one fails
# (--kill-on-invalid-dep), then resubmit the failed tasks with --array.
merge_id=-
if [ $merge = 1 ]; then
  merge_time=${merge_time:-$task_time}
  args=(--dependency="afterok:$array_id" --kill-on-invalid-dep=yes --chdir="$out"
        --output="$out/logs/%x-%j.out" "${sbatch_opts[@]}")
  [ -n "$merge_time" ] && args+=(--time="$merge_time")
  merge_id=$(run_sbatch "${args[@]}" "$here/hrspace-merge.sbatch" \
    "$bin" "$study" "$out" "$shards" "${study_opts[@]}") ||
    { echo "$prog: array job $array_id is submitted, the merge is not (merge by hand, see README.md)" >&2; exit 1; }
fi

if [ $parsable = 1 ]; then
  echo "$array_id $merge_id"
else
  echo "array job $array_id: $study, tasks $spec of $shards shards -> $out/shards/shard-i"
  jobs=$array_id
  if [ $merge = 1 ]; then
    echo "merge job $merge_id: -> $out/$study (after every task succeeded)"
    jobs+=",$merge_id"
  fi
  echo "logs: $out/logs/   status: squeue -j $jobs"
fi
