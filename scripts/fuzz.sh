#!/usr/bin/env bash
# libFuzzer runs of the readers (docs/hardening.md, "Fuzzing the readers"):
# builds the `fuzz` preset (clang-14, libFuzzer, ASan + UBSan, into
# build-fuzz/) and runs fuzz_scene (geometry::parse_scene) and fuzz_csv
# (the CSV reader of collide and rs), one after the other, over their seed
# corpora: scenes/*.json and tests/fuzz/corpus/csv/. Not part of CI (the
# CGAL-heavy build takes minutes with clang); CI runs the seeded GoogleTest
# fuzzer tests/cli/fuzz_readers_test.cpp instead.
#
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]
#   SECONDS  total fuzzing time, split evenly between the targets (default 60)
#   TARGET   fuzz_scene and/or fuzz_csv (default both)
# Each target keeps its growing corpus, log and any crash input in
# build-fuzz/fuzz-runs/TARGET/. Exit status 1 when a target found something.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
[ $# -gt 0 ] && shift
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_scene fuzz_csv)
case "$seconds" in '' | *[!0-9]*) echo "usage: scripts/fuzz.sh [SECONDS] [TARGET...]" >&2; exit 2 ;; esac

# clang and libFuzzer's runtime: not needed by the normal build (scripts/setup.sh).
missing=()
for p in clang-14 libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "hrspace fuzz: installing ${missing[*]}" >&2
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq >/dev/null
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

HRSPACE_PRESET=fuzz "$root/scripts/build.sh" "${targets[@]}"

# Short allocation stacks and a small quarantine: CGAL allocates a lot, and
# the default ASan bookkeeping halves the rate (rerun a crash input with the
# defaults for full allocation stacks).
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:malloc_context_size=4:quarantine_size_mb=32"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
per=$((seconds / ${#targets[@]}))
[ "$per" -ge 1 ] || per=1
status=0
for t in "${targets[@]}"; do
  case "$t" in
    fuzz_scene) seeds=("$root/scenes") extra=(-dict="$root/tests/fuzz/scene.dict" -max_len=16384) ;;
    fuzz_csv) seeds=("$root/tests/fuzz/corpus/csv") extra=(-max_len=4096) ;;
    *) echo "hrspace fuzz: unknown target $t (fuzz_scene, fuzz_csv)" >&2; exit 2 ;;
  esac
  work="$root/build-fuzz/fuzz-runs/$t"
  mkdir -p "$work/corpus"
  echo "== $t: ${per} s over ${seeds[*]#$root/} (corpus, log and crashes in ${work#$root/})"
  # The first directory receives the new inputs; the seeds are only read.
  if "$root/build-fuzz/tests/fuzz/$t" -max_total_time="$per" -timeout=10 -print_final_stats=1 \
      -artifact_prefix="$work/" "${extra[@]}" "$work/corpus" "${seeds[@]}" >"$work/log.txt" 2>&1; then
    result="no finding"
  else
    result="FINDING (see $work/log.txt and the crash-*/timeout-* input there)"
    status=1
  fi
  last="$(grep -E '^#[0-9]+' "$work/log.txt" | tail -n 1 || true)"
  execs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/log.txt")"
  rate="$(sed -n 's/^stat::average_exec_per_sec: *//p' "$work/log.txt")"
  echo "   ${execs:-?} executions, ${rate:-?}/s; last status: ${last:-?}"
  echo "   $result"
done
exit "$status"
