#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Outcome digests of the shipped designs: the check that a refactoring step
# keeps behaviour. For every scene in scenes/ and every planner named, runs
# `hrspace design SCENE --seed 1` and prints one line per design:
#   SCENE PLANNER DIGEST
# where DIGEST is the SHA-256 of layout.json, tours.json, design.svg and
# report.json with every timing removed (keys ending in _s or _ms, "time_s",
# "planning_saved_estimate_s", "reachability_ms", "threads", and the work
# count "reachability_fills", which depends on which thread fills a shared
# grid first; the planner
# key too, a name that a step may change), so two commits
# that make the same designs print the same lines.
#
# Usage: scripts/outcome-digests.sh [--iterations N] [--planners 'P1 P2'] [--bin HRSPACE]
#                                    [--drop-keys 'K1 K2']
#   defaults: 150 iterations, planners "baseline default", build/cli/hrspace.
#   --drop-keys: report.json keys left out as well (at any depth), for a
#   step that adds a report field and otherwise keeps behaviour.
# Compare two commits: run it at each (building in between) and diff:
#   scripts/outcome-digests.sh > /tmp/a; git checkout B; scripts/build.sh hrspace
#   scripts/outcome-digests.sh > /tmp/b; diff /tmp/a /tmp/b && echo equal
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
iterations=150
planners="baseline default"
bin="$root/build/cli/hrspace"
drop=""
while [ $# -gt 0 ]; do
  case "$1" in
    --iterations) iterations="$2"; shift 2 ;;
    --planners) planners="$2"; shift 2 ;;
    --bin) bin="$2"; shift 2 ;;
    --drop-keys) drop="$2"; shift 2 ;;
    -h|--help) sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "outcome-digests: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[ -x "$bin" ] || { echo "outcome-digests: no binary at $bin (scripts/build.sh hrspace)" >&2; exit 2; }
# One annealing chain per design (hrspace design defaults to two restarts):
# the digests follow the engine, and commits before --restarts existed
# print the same lines.
single=()
case "$("$bin" design --help 2>/dev/null || true)" in *--restarts*) single=(--restarts 1) ;; esac
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for scene in "$root"/scenes/*.json; do
  name="$(basename "$scene" .json)"
  for planner in $planners; do
    out="$work/$name-$planner"
    "$bin" design "$scene" --out "$out" --seed 1 --iterations "$iterations" --threads 2 \
      --planner "$planner" "${single[@]}" >/dev/null
    digest="$(python3 - "$out" "$drop" <<'EOF'
import hashlib, json, sys, pathlib
d = pathlib.Path(sys.argv[1])
dropped = set(sys.argv[2].split())
def strip(v):
    if isinstance(v, dict):
        return {k: strip(x) for k, x in v.items()
                if not (k.endswith("_s") or k.endswith("_ms") or k in ("threads", "version", "commit", "planner", "reachability_fills") or k in dropped)}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v
h = hashlib.sha256()
for f in ("layout.json", "tours.json", "design.svg"):
    h.update((d / f).read_bytes())
report = strip(json.loads((d / "report.json").read_text()))
h.update(json.dumps(report, sort_keys=True).encode())
print(h.hexdigest()[:16])
EOF
)"
    echo "$name $planner $digest"
  done
done
