#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The accessibility goal measured on the shipped rooms: for each scene and
seed, one plain `hrspace design` and one with `--access-goal N`; prints a
Markdown table (ADA pass, failed checks, interior cost terms, preferences
met, tours found, time) and the totals. Results go to docs/BENCHMARKS.md.

usage: scripts/access_goal.py [--seeds 1,2] [--tries 4] [--rules ada] [--out DIR]
"""
import argparse
import json
import pathlib
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent


def run(scene, out, seed, rules, tries):
    args = [str(ROOT / "build/cli/hrspace"), "design", str(scene), "--out", str(out), "--seed",
            str(seed), "--rules", rules, "--threads", "2"]
    if tries > 1:
        args += ["--access-goal", str(tries)]
    start = time.monotonic()
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.monotonic() - start
    report = json.loads((out / "report.json").read_text())
    access = json.loads((out / "accessibility.json").read_text())
    terms = {k: v["final"] for k, v in report["cost"]["terms"].items()}
    return {
        "pass": access["pass"],
        "interior": terms["interior"],
        "total": terms["total"],
        "prefs": (report["preferences"]["met"], report["preferences"]["total"]),
        "tours": (terms["tours_found"], terms["tours_total"]),
        "wall": wall,
        "tries": report.get("access_goal", {}).get("tries", 1),
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seeds", default="1,2")
    parser.add_argument("--tries", type=int, default=4)
    parser.add_argument("--rules", default="ada")
    parser.add_argument("--out", default="out/access_goal")
    args = parser.parse_args()
    seeds = [int(s) for s in args.seeds.split(",")]
    out = ROOT / args.out
    print("| scene | seed | plain: pass | interior | prefs | tours | s | goal: pass | tries | interior | prefs | tours | s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    totals = {"plain": 0, "goal": 0, "n": 0, "plain_interior": 0.0, "goal_interior": 0.0,
              "plain_s": 0.0, "goal_s": 0.0}
    for scene in sorted((ROOT / "scenes").glob("*.json")):
        for seed in seeds:
            a = run(scene, out / scene.stem / f"plain-{seed}", seed, args.rules, 1)
            b = run(scene, out / scene.stem / f"goal-{seed}", seed, args.rules, args.tries)
            totals["n"] += 1
            totals["plain"] += a["pass"]
            totals["goal"] += b["pass"]
            totals["plain_interior"] += a["interior"]
            totals["goal_interior"] += b["interior"]
            totals["plain_s"] += a["wall"]
            totals["goal_s"] += b["wall"]
            cell = lambda r: (f"{'pass' if r['pass'] else 'fail'}", f"{r['interior']:.2f}",
                              f"{r['prefs'][0]}/{r['prefs'][1]}", f"{r['tours'][0]}/{r['tours'][1]}",
                              f"{r['wall']:.1f}")
            pa, ia, fa, ta, sa = cell(a)
            pb, ib, fb, tb, sb = cell(b)
            print(f"| {scene.stem} | {seed} | {pa} | {ia} | {fa} | {ta} | {sa} | {pb} | {b['tries']} | {ib} | {fb} | {tb} | {sb} |",
                  flush=True)
    n = totals["n"]
    print(f"\nplain: {totals['plain']}/{n} pass, interior cost sum {totals['plain_interior']:.2f}, "
          f"{totals['plain_s']:.0f} s; goal (--access-goal {args.tries}): {totals['goal']}/{n} pass, "
          f"interior cost sum {totals['goal_interior']:.2f}, {totals['goal_s']:.0f} s")


if __name__ == "__main__":
    sys.exit(main())
