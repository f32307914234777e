#!/usr/bin/python3
"""Folds `perf script -F comm,ip,sym` output (call graphs, innermost frame
first) into the components of a design, and prints a Markdown table with
the share of samples of each and the design's counts of work from its
report.json. Used by scripts/profile.sh."""

import argparse
import json
import re
import sys
from collections import Counter

# (component, pattern on the demangled function name): the first match wins,
# tried on the innermost frame of hrspace's own code.
COMPONENTS = [
    ("RS-decomposition look-up (§V-A)", r"hrs::rs::(Decomposition|PoseGrid|KdTree)|DecompositionSampler|decomposition_hooks"),
    ("Reeds–Shepp queries", r"hrs::rs::"),
    ("nearest neighbours (RRT)", r"PoseNearest|hrs::planning::.*nearest"),
    ("continuous collision checks", r"CSpace::(arc|straight|hits|points_free|is_free|path|segment|pose_free|clearance)|MotionValidator|recheck|path_free|swept"),
    ("C-space updates (moves)", r"CSpace::(move_object|CSpace|rebuild|update|slice)|CGAL::|polygon_ops|cover"),
    ("grid fills (refusal gate, escape)", r"FreeGrid|ReachableSet|ReachGate|free_grid|reach_gate"),
    ("goal poses", r"goal_poses|clear_offset|side_of"),
    ("path database, tree store, repair", r"PathDatabase|TreeStore|ReusePlanner|path_shortening|repair|LegMeasures"),
    ("RRT (other)", r"hrs::planning::(Rrt|LegPlanner|RrtTree)|rrt"),
    ("tour search", r"TourPlanner|tour"),
    ("annealing, costs, preferences, polish", r"hrs::optimize::"),
    ("other hrspace code", r"hrs::"),
]


def classify(frames):
    for fn in frames:
        if "hrs::" not in fn:
            continue
        for name, pattern in COMPONENTS:
            if re.search(pattern, fn):
                return name
    return "outside hrspace (start-up, libc, kernel)"


def samples(lines):
    """Yields the list of function names of each sample, innermost first."""
    frames = []
    for line in lines:
        if not line.strip():
            if frames:
                yield frames
            frames = []
            continue
        if line.startswith((" ", "\t")):
            parts = line.strip().split(None, 1)
            frames.append(parts[1] if len(parts) > 1 else "?")
    if frames:
        yield frames


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--report", help="the design's report.json (counts of work)")
    ap.add_argument("--title", default="design")
    a = ap.parse_args()
    counts = Counter(classify(f) for f in samples(sys.stdin))
    total = sum(counts.values())
    if not total:
        print("profile_fold.py: no samples (is perf allowed? kernel.perf_event_paranoid)", file=sys.stderr)
        return 1
    print(f"### {a.title}\n")
    print("| component | share of samples |")
    print("|---|---|")
    for name, n in counts.most_common():
        print(f"| {name} | {100 * n / total:.1f} % |")
    print(f"\n{total} samples at 499 Hz.")
    if a.report:
        r = json.load(open(a.report))
        t = r.get("time_s", {})
        work = [("annealing iterations", r.get("iterations_run")),
                ("valid proposals", r.get("valid_proposals")),
                ("tours planned", r.get("tours_planned")),
                ("legs refused by the gate", (r.get("refused_legs") or {}).get("legs")),
                ("grid fills", (r.get("refused_legs") or {}).get("reachability_fills")),
                ("proposals rejected early", (r.get("early_rejection") or {}).get("proposals")),
                ("design time, s", t.get("total")),
                ("planning share", t.get("planning_share"))]
        reuse = r.get("reuse") or {}
        for k in ("leg_requests", "legs_database", "legs_repaired", "legs_planned", "legs_failed",
                  "trees_reused"):
            if k in reuse:
                work.append((k.replace("_", " "), reuse[k]))
        hist = reuse.get("rrt_iterations_histogram")
        if isinstance(hist, list):
            work.append(("RRT iterations of fresh legs found",
                         sum(h.get("iterations", 0) * h.get("legs", 0) for h in hist)))
        print("\n| work per design | count |\n|---|---|")
        for k, v in work:
            if v is not None:
                print(f"| {k} | {v:.3g} |" if isinstance(v, float) else f"| {k} | {v} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
