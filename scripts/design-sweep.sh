#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Designs a set of scenes with several seeds and planner presets, one design
# at a time, and prints a Markdown table per scene and planner: tours found
# per seed, final cost (mean ± sd), preferences met, the worst angle
# preference, and the time per design (mean, max). The numbers in the dated
# log of docs/BENCHMARKS.md come from it.
#
# Usage: scripts/design-sweep.sh [--seeds N] [--planners 'P1 P2'] [--iterations N]
#                                [--threads T] [--out DIR] [--summary-only] SCENE...
#   defaults: 3 seeds, planners "baseline default", 700 iterations, 2 threads,
#   out/design-sweep. A scene may be a zoo room (hrspace generate).
#   --summary-only prints the table of designs already in DIR (DIR/PLANNER/
#   SCENE-SEED/report.json, as `hrspace design --out` writes them).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seeds=3 planners="baseline default" iterations=700 threads=2 out="$root/out/design-sweep" run=1
bin="${HRSPACE_BIN:-$root/build/cli/hrspace}"
scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seeds) seeds="$2"; shift 2 ;;
    --planners) planners="$2"; shift 2 ;;
    --iterations) iterations="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --summary-only) run=0; shift ;;
    -h|--help) sed -n '3,14p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "design-sweep: unknown option '$1' (see --help)" >&2; exit 2 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
[ ${#scenes[@]} -gt 0 ] || { echo "design-sweep: name at least one scene (see --help)" >&2; exit 2; }
[ "$run" = 0 ] || [ -x "$bin" ] || "$root/scripts/build.sh" hrspace
for scene in "${scenes[@]}"; do
  [ "$run" = 1 ] || break
  name="$(basename "$scene" .json)"
  for planner in $planners; do
    for seed in $(seq 1 "$seeds"); do
      "$bin" design "$scene" --out "$out/$planner/$name-$seed" --seed "$seed" \
        --iterations "$iterations" --threads "$threads" --planner "$planner" >/dev/null
    done
  done
done
python3 - "$out" "$planners" "${scenes[@]}" <<'EOF'
import json, os, statistics as st, sys
out, planners, scenes = sys.argv[1], sys.argv[2].split(), sys.argv[3:]
print("| scene | planner | tours found per seed | final cost | preferences met | worst angle | time per design, mean (max) |")
print("|---|---|---|---|---|---|---|")
totals = {}
for scene in scenes:
    name = os.path.basename(scene)[:-5] if scene.endswith(".json") else os.path.basename(scene)
    for p in planners:
        runs = []
        d = 1
        while os.path.exists(f"{out}/{p}/{name}-{d}/report.json"):
            runs.append(json.load(open(f"{out}/{p}/{name}-{d}/report.json")))
            d += 1
        if not runs:
            continue
        tours = [r["cost"]["terms"]["tours_found"]["final"] for r in runs]
        cost = [r["cost"]["final"] for r in runs]
        met = sum(r["preferences"]["met"] for r in runs)
        total = sum(r["preferences"]["total"] for r in runs)
        worst = max(r["preferences"]["worst_angle_deg"] for r in runs)
        time = [r["time_s"]["total"] for r in runs]
        sd = st.stdev(cost) if len(cost) > 1 else 0.0
        print(f"| {name} | {p} | {'/'.join(map(str, tours))} | {st.mean(cost):.2f} ± {sd:.2f} | "
              f"{met}/{total} | {worst:.0f}° | {st.mean(time):.1f} s ({max(time):.1f} s) |")
        t = totals.setdefault(p, [0, 0, 0, 0, [], 0.0, 0])
        t[0] += sum(tours); t[1] += sum(r["cost"]["terms"]["tours_total"]["final"] for r in runs)
        t[2] += met; t[3] += total; t[4] += time; t[5] = max(t[5], worst)
        t[6] += sum(1 for r in runs if r["cost"]["terms"]["tours_found"]["final"] >= 0.9 * r["cost"]["terms"]["tours_total"]["final"])
for p, t in totals.items():
    print(f"\n{p}: {len(t[4])} designs, {t[6]} with >= 90 % of tours; tours {t[0]}/{t[1]}; "
          f"preferences {t[2]}/{t[3]} ({100 * t[2] / max(1, t[3]):.0f} %); worst angle {t[5]:.0f}°; "
          f"time per design mean {st.mean(t[4]):.1f} s, max {max(t[4]):.1f} s")
EOF
