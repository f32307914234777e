#!/usr/bin/env bash
# Where a design's time goes: runs one `hrspace design` under `perf record`
# (call graphs through frame pointers, from the `profile` build preset) and
# prints the share of CPU samples per component of the planner and the design
# loop, and the design's own counts of the work (calls per design).
#
#   scripts/profile.sh SCENE [--planner P] [--iterations N] [--seed S] [--out DIR]
#
# A sample is charged to the innermost frame of hrspace's code on its stack
# (a libm or libstdc++ leaf goes to the hrspace function that called it),
# and that frame's function to a component by its name (scripts/profile_fold.py).
# Inlined functions count as their caller. Needs perf (linux-perf, installed
# by scripts/setup.sh) and kernel.perf_event_paranoid <= 2.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
usage() { sed -n '2,13p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
scene=""; planner=default; iterations=700; seed=1; out=""
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --planner) planner="$2"; shift ;;
    --iterations) iterations="$2"; shift ;;
    --seed) seed="$2"; shift ;;
    --out) out="$2"; shift ;;
    -*) echo "profile.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) [ -z "$scene" ] || { echo "profile.sh: one SCENE only" >&2; exit 2; }; scene="$1" ;;
  esac
  shift
done
[ -n "$scene" ] || { usage >&2; exit 2; }
[ -f "$scene" ] || { echo "profile.sh: $scene: no such scene file" >&2; exit 2; }
command -v perf >/dev/null || { echo "profile.sh: perf is missing (scripts/setup.sh installs linux-perf)" >&2; exit 2; }
out="${out:-$root/out/profile/$(basename "$scene" .json)-$planner}"
mkdir -p "$out"
cmake --preset profile -S "$root" >/dev/null
cmake --build "$root/build-profile" --target hrspace >/dev/null
bin="$root/build-profile/cli/hrspace"
perf record -q -F 499 --call-graph fp -o "$out/perf.data" -- \
  "$bin" design "$scene" --out "$out/design" --planner "$planner" --iterations "$iterations" \
  --seed "$seed" --threads 1 >"$out/design.log" 2>&1
perf script -i "$out/perf.data" -F comm,ip,sym 2>/dev/null |
  /usr/bin/python3 "$root/scripts/profile_fold.py" --report "$out/design/report.json" \
  --title "$(basename "$scene") — planner $planner, $iterations iterations, seed $seed, 1 thread"
