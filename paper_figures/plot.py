#!/usr/bin/python3
"""Figures and REPRODUCTION.md from the experiments harness's outputs.

    python3 paper_figures/plot.py OUT_DIR [--publish]

OUT_DIR is the root `hrspace experiment --out` (or scripts/reproduce.sh)
wrote. Figures go to OUT_DIR/figures/ as SVG and PNG, the paper-vs-ours
table to OUT_DIR/REPRODUCTION.md. With --publish, the figures, each study's
summary.csv and REPRODUCTION.md are also copied into paper_figures/ (the
small outputs README and docs embed). A study that was not run is skipped
with a note; nothing here runs an experiment.
"""

import argparse
import math
import os
import shutil
import sys
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import draw  # noqa: E402
from draw import num, plt, read_csv, save  # noqa: E402

PLANNER_LABELS = {
    "literal": "baseline (paper, literal)",
    "baseline": "baseline (ours)",
    "paper": "proposed (paper's techniques)",
    "all": "proposed (all techniques)",
    "samples_steering": "RS-decomposition only",
}
PLANNER_ORDER = ["literal", "baseline", "paper", "all"]


def mean_sd(values):
    v = [x for x in values if not math.isnan(x)]
    if not v:
        return float("nan"), float("nan"), 0
    m = sum(v) / len(v)
    sd = math.sqrt(sum((x - m) ** 2 for x in v) / (len(v) - 1)) if len(v) > 1 else 0.0
    return m, sd, len(v)


def fmt(m, sd=None, n=None, digits=2, unit=""):
    if m is None or (isinstance(m, float) and math.isnan(m)):
        return "—"
    s = f"{m:.{digits}f}{unit}"
    if sd is not None and not math.isnan(sd):
        s += f" ± {sd:.{digits}f}{unit}"
    if n is not None:
        s += f" (n={n})"
    return s


def by(rows, **match):
    return [r for r in rows if all(r.get(k) == v for k, v in match.items())]


def rooms_of(rows):
    seen = []
    for r in rows:
        if r.get("room") and r["room"] not in seen:
            seen.append(r["room"])
    return seen


# --- figures ----------------------------------------------------------------


def planner_pair_bars(rows, planners, ylabel, log):
    """Bars of mean ± sd planning time per room for two planners."""
    rooms = rooms_of(rows)
    fig, ax = plt.subplots(figsize=(5.5, 3.2))
    for k, planner in enumerate(planners):
        ms, sds = [], []
        for room in rooms:
            m, sd, _ = mean_sd([num(r, "planning_s") for r in by(rows, room=room, planner=planner)])
            ms.append(m)
            sds.append(sd)
        ax.bar([i + (k - 0.5) * 0.35 for i in range(len(rooms))], ms, 0.35, yerr=sds, capsize=2,
               label=PLANNER_LABELS[planner])
    ax.set_xticks(range(len(rooms)))
    ax.set_xticklabels(rooms)
    if log:
        ax.set_yscale("log")
    ax.set_ylabel(ylabel)
    ax.legend(fontsize=7)
    return fig


def fig_timing(root, figs):
    runs = read_csv(os.path.join(root, "timing", "runs.csv"))
    if not runs:
        return []
    rooms = rooms_of(runs)
    out = []
    fig, axes = plt.subplots(1, 2, figsize=(11, 3.8))
    for ax, mode, title in (
        (axes[0], "design", "whole designs (planning time)"),
        (axes[1], "replay", "replay of the baseline's layouts (planning time)"),
    ):
        width = 0.2
        for k, planner in enumerate(PLANNER_ORDER):
            xs, ms, sds, shares = [], [], [], []
            for i, room in enumerate(rooms):
                rs = by(runs, mode=mode, room=room, planner=planner)
                if not rs:
                    continue
                m, sd, _ = mean_sd([num(r, "planning_s") for r in rs])
                xs.append(i + (k - 1.5) * width)
                ms.append(m)
                sds.append(sd)
                share = mean_sd([num(r, "planning_share") for r in rs])[0]
                shares.append(share)
            if not xs:
                continue
            bars = ax.bar(xs, ms, width, yerr=sds, capsize=2, label=PLANNER_LABELS[planner])
            if mode == "design":
                for b, s in zip(bars, shares):
                    if not math.isnan(s):
                        ax.text(b.get_x() + b.get_width() / 2, b.get_height(), f"{100 * s:.0f}%",
                                ha="center", va="bottom", fontsize=6)
        ax.set_xticks(range(len(rooms)))
        ax.set_xticklabels(rooms)
        ax.set_ylabel("planning time per design (s)")
        ax.set_yscale("log")
        ax.set_title(title, fontsize=9)
    axes[0].legend(fontsize=7)
    fig.suptitle("Planning time, mean ± sd over seeds (labels: planning share of total time)",
                 fontsize=9)
    out += save(fig, figs, "timing")
    return out


def fig_rs_decomposition(root, figs):
    samples = read_csv(os.path.join(root, "rs_decomposition", "samples.csv"))
    runs = read_csv(os.path.join(root, "rs_decomposition", "runs.csv"))
    out = []
    if samples:
        radii = sorted({r["radius"] for r in samples}, key=lambda x: (x != "3", x))
        slices = [0.0, math.pi / 2, math.pi]
        fig, axes = plt.subplots(len(radii), len(slices), figsize=(10, 3.3 * len(radii)),
                                 squeeze=False)
        words = sorted({r["word"] for r in samples})
        cmap = plt.get_cmap("tab20", max(len(words), 1))
        color = {w: cmap(i % 20) for i, w in enumerate(words)}
        for i, radius in enumerate(radii):
            rs = [r for r in samples if r["radius"] == radius]
            reg = by(runs, kind="regions", radius=radius)
            regions = reg[0].get("regions", "?") if reg else "?"
            radius_m = reg[0].get("radius_m", radius) if reg else radius
            for j, h in enumerate(slices):
                ax = axes[i][j]
                pick = [r for r in rs
                        if abs(math.remainder(num(r, "theta") - h, 2 * math.pi)) < math.radians(10)]
                ax.scatter([num(r, "x") for r in pick], [num(r, "y") for r in pick], s=2,
                           c=[color[r["word"]] for r in pick], rasterized=True)
                ax.set_aspect("equal")
                ax.set_title(f"r = {float(radius_m):.2f} m, heading {math.degrees(h):.0f}° ± 10°"
                             f" ({regions} words)", fontsize=8)
                ax.tick_params(labelsize=6)
        fig.suptitle("RS-decomposition: samples coloured by their shortest word", fontsize=9)
        out += save(fig, figs, "rs_partition")
    rep = by(runs, kind="replay")
    if rep:
        fig = planner_pair_bars(rep, ["baseline", "samples_steering"],
                                "planning time (s), same layouts", log=False)
        out += save(fig, figs, "rs_decomposition_time")
    return out


def fig_rrt_iterations(root, figs):
    hist = read_csv(os.path.join(root, "rrt_iterations", "histogram.csv"))
    runs = read_csv(os.path.join(root, "rrt_iterations", "runs.csv"))
    out = []
    if hist:
        rooms = rooms_of(hist)
        fig, ax = plt.subplots(figsize=(6, 3.4))
        edges = [1, 2, 5, 10, 20, 30, 50, 100, 200, 500, 1000, 3001]
        for room in rooms:
            counts = [0] * (len(edges) - 1)
            for r in by(hist, room=room):
                it, n = num(r, "rrt_iterations"), num(r, "legs")
                for b in range(len(edges) - 1):
                    if edges[b] <= it < edges[b + 1]:
                        counts[b] += n
            total = sum(counts) or 1
            ax.step(range(len(counts)), [c / total for c in counts], where="mid", label=room)
        ax.set_xticks(range(len(edges) - 1))
        ax.set_xticklabels([f"{edges[b]}–{edges[b + 1] - 1}" for b in range(len(edges) - 1)],
                           rotation=45, fontsize=6)
        ax.axvline(4.5, color="gray", ls=":", lw=1)
        ax.set_xlabel("RRT iterations to find a leg")
        ax.set_ylabel("share of found legs")
        ax.legend(fontsize=7)
        ax.set_title("RRT iterations per found leg (baseline RRT, all seeds)", fontsize=9)
        out += save(fig, figs, "rrt_iterations")
    sweep = by(runs, kind="threshold")
    if sweep:
        rooms = rooms_of(sweep)
        fig, axes = plt.subplots(1, 2, figsize=(9, 3.2))
        for room in rooms:
            ts = sorted({int(r["tree_max_nodes"]) for r in by(sweep, room=room)})
            pt = [mean_sd([num(r, "planning_s") for r in by(sweep, room=room, tree_max_nodes=str(t))])
                  for t in ts]
            tf = [mean_sd([num(r, "tours_found") for r in by(sweep, room=room, tree_max_nodes=str(t))])
                  for t in ts]
            axes[0].errorbar(ts, [p[0] for p in pt], yerr=[p[1] for p in pt], marker="o",
                             capsize=2, label=room)
            axes[1].errorbar(ts, [p[0] for p in tf], yerr=[p[1] for p in tf], marker="o",
                             capsize=2, label=room)
        axes[0].set_xlabel("tree rebuild threshold (nodes)")
        axes[0].set_ylabel("planning time per design (s)")
        axes[1].set_xlabel("tree rebuild threshold (nodes)")
        axes[1].set_ylabel("tours found (of 10)")
        axes[0].legend(fontsize=7)
        fig.suptitle("Rebuild threshold of reused RRT trees (paper's techniques)", fontsize=9)
        out += save(fig, figs, "rrt_threshold")
    return out


def design_dirs(root, study):
    d = os.path.join(root, study, "designs")
    return sorted(os.listdir(d)) if os.path.isdir(d) else []


def fig_small_room(root, figs):
    runs = read_csv(os.path.join(root, "small_room", "runs.csv"))
    out = []
    if runs:
        fig = planner_pair_bars(runs, ["baseline", "all"], "planning time per design (s)",
                                log=True)
        out += save(fig, figs, "small_room_time")
    dirs = [d for d in design_dirs(root, "small_room") if "small" in d] or design_dirs(root, "small_room")
    if dirs:
        dirs = dirs[-2:]
        fig, axes = plt.subplots(1, len(dirs), figsize=(4 * len(dirs), 3.6), squeeze=False)
        for ax, d in zip(axes[0], dirs):
            draw.draw_design(ax, os.path.join(root, "small_room", "designs", d), title=d)
        out += save(fig, figs, "small_room_designs")
    return out


def fig_generalization(root, figs):
    """Zoo rooms: success share and design time against the object count."""
    runs = read_csv(os.path.join(root, "generalization", "runs.csv"))
    if not runs:
        return []
    buckets = []
    for r in runs:
        if r["bucket"] not in buckets:
            buckets.append(r["bucket"])
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.6))
    for planner in ["baseline", "all"]:
        rows = by(runs, planner=planner)
        if not rows:
            continue
        label = PLANNER_LABELS.get(planner, planner)
        xs, ys = [], []
        for b in buckets:
            rb = by(rows, bucket=b)
            if rb:
                xs.append(mean_sd([num(r, "objects") for r in rb])[0])
                ys.append(100 * mean_sd([num(r, "success") for r in rb])[0])
        ax1.plot(xs, ys, marker="o", label=label)
        ax2.scatter([num(r, "objects") for r in rows], [num(r, "total_s") for r in rows],
                    s=14, label=label)
    ax1.set_xlabel("objects in the room (bucket mean)")
    ax1.set_ylabel("designs with >= 90 % of tours found (%)")
    ax1.set_ylim(-5, 105)
    ax1.legend(fontsize=8)
    ax2.set_xlabel("objects in the room")
    ax2.set_ylabel("design time (s)")
    ax2.set_yscale("log")
    ax2.legend(fontsize=8)
    fig.suptitle("Room zoo: rooms tourable by construction")
    fig.tight_layout()
    return save(fig, figs, "generalization")


def fig_ao_graph(root, figs):
    dirs = design_dirs(root, "ao_graph")
    out = []
    firsts = {}
    for d in dirs:
        room = d.split("-s")[0]
        firsts.setdefault(room, d)
    if firsts:
        rows = read_csv(os.path.join(root, "ao_graph", "runs.csv"))
        fig, axes = plt.subplots(1, len(firsts), figsize=(4.5 * len(firsts), 4), squeeze=False)
        for ax, (room, d) in zip(axes[0], firsts.items()):
            key = d
            r = by(rows, key=key)
            note = ""
            if r and r[0].get("obj1"):
                r = r[0]
                note = (f"\nα {r['obj1']} = {num(r, 'obj1_alpha'):.3f}, "
                        f"α {r['obj2']} = {num(r, 'obj2_alpha'):.3f}")
            draw.draw_design(ax, os.path.join(root, "ao_graph", "designs", d), title=d + note)
        out += save(fig, figs, "ao_graph_designs")
    return out


def fig_designs(root, figs):
    dirs = design_dirs(root, "designs")
    out = []
    cover = [d for d in dirs if "-cover-" in d]
    if cover:
        rooms = []
        for d in cover:
            room = d.split("-design-")[1].rsplit("-s", 1)[0]
            if room not in rooms:
                rooms.append(room)
        cols = max(sum(1 for d in cover if f"-design-{room}-s" in d) for room in rooms)
        fig, axes = plt.subplots(len(rooms), cols, figsize=(3.2 * cols, 3 * len(rooms)),
                                 squeeze=False)
        for i, room in enumerate(rooms):
            mine = [d for d in cover if f"-design-{room}-s" in d]
            for j in range(cols):
                ax = axes[i][j]
                if j < len(mine):
                    draw.draw_design(ax, os.path.join(root, "designs", "designs", mine[j]),
                                     title=mine[j].replace("designs-cover-design-", ""))
                else:
                    ax.axis("off")
        fig.suptitle("Designs (proposed planner); red: the most likely sequence's tour", fontsize=9)
        out += save(fig, figs, "designs_cover")
    fig1 = [d for d in dirs if "-fig1-" in d]
    if fig1:
        fig, axes = plt.subplots(1, len(fig1), figsize=(4.5 * len(fig1), 4), squeeze=False)
        for ax, d in zip(axes[0], fig1):
            label = "path weights 0 (no wheelchair)" if d.endswith("-0") else "the scene's path weights"
            draw.draw_design(ax, os.path.join(root, "designs", "designs", d), title=label,
                             all_tours=True)
        fig.suptitle("Fig. 1: the same seed without and with the wheelchair's path costs", fontsize=9)
        out += save(fig, figs, "fig1_weights")
    return out


def fig_method(root, figs):
    out = []
    edges = read_csv(os.path.join(root, "method", "ao_edges.csv"))
    if edges:
        graphs = []
        for e in edges:
            if e["graph"] not in graphs:
                graphs.append(e["graph"])
        fig, axes = plt.subplots(1, len(graphs), figsize=(3.6 * len(graphs), 3.6), squeeze=False)
        for ax, g in zip(axes[0], graphs):
            es = by(edges, graph=g)
            nodes = ["door"] + sorted({e["from"] for e in es} | {e["to"] for e in es} - {"door"})
            pos = {n: (math.cos(2 * math.pi * i / len(nodes)), math.sin(2 * math.pi * i / len(nodes)))
                   for i, n in enumerate(nodes)}
            for e in es:
                p = num(e, "p")
                if p <= 0 or e["from"] == e["to"]:
                    continue
                (x0, y0), (x1, y1) = pos[e["from"]], pos[e["to"]]
                ax.annotate("", xy=(x1, y1), xytext=(x0, y0),
                            arrowprops=dict(arrowstyle="-|>", lw=0.5 + 5 * p, alpha=0.6,
                                            color="tab:blue", shrinkA=12, shrinkB=12,
                                            connectionstyle="arc3,rad=0.12"))
            for n, (x, y) in pos.items():
                ax.text(x, y, n, ha="center", va="center", fontsize=7,
                        bbox=dict(boxstyle="round", fc="white", ec="gray"))
            ax.set_xlim(-1.4, 1.4)
            ax.set_ylim(-1.4, 1.4)
            ax.set_aspect("equal")
            ax.axis("off")
            ax.set_title(g, fontsize=9)
        fig.suptitle("AO graphs (edge width ∝ transition probability)", fontsize=9)
        out += save(fig, figs, "ao_graphs")
    goals = read_csv(os.path.join(root, "method", "goals.csv"))
    leg = read_csv(os.path.join(root, "method", "leg.csv"))
    dirs = design_dirs(root, "method")
    if goals and dirs:
        fig, axes = plt.subplots(1, 2, figsize=(9, 4))
        objs = []
        for g in goals:
            if g["object"] not in objs:
                objs.append(g["object"])
        for ax, show in zip(axes, [objs[:1], objs[:2]]):
            draw.draw_design(ax, os.path.join(root, "method", "designs", dirs[0]),
                             mark_unreachable=False)
            for g in goals:
                if g["object"] not in show:
                    continue
                x, y, t = num(g, "x"), num(g, "y"), num(g, "theta")
                ax.plot([x], [y], "o", color="tab:red", ms=3)
                ax.arrow(x, y, 0.18 * math.cos(t), 0.18 * math.sin(t), head_width=0.05,
                         color="tab:blue", lw=0.6)
            if len(show) == 2 and leg:
                ax.plot([num(w, "x") for w in leg], [num(w, "y") for w in leg], color="tab:blue",
                        lw=1.6)
        axes[0].set_title(f"goal poses around {objs[0]}", fontsize=9)
        if len(objs) > 1:
            axes[1].set_title(f"goal poses of {objs[0]} and {objs[1]}, one leg between them",
                              fontsize=9)
        out += save(fig, figs, "goal_poses")
    return out


# --- REPRODUCTION.md ---------------------------------------------------------


def claims(root):
    """Rows (claim, paper, ours, same experiment?, verdict)."""
    out = []
    t = read_csv(os.path.join(root, "timing", "runs.csv"))
    if t:
        rooms = rooms_of(t)
        # Abstract: minutes per design.
        parts = []
        for room in rooms:
            b = mean_sd([num(r, "total_s") for r in by(t, mode="design", room=room, planner="literal")])
            p = mean_sd([num(r, "total_s") for r in by(t, mode="design", room=room, planner="paper")])
            parts.append(f"{room}: {fmt(b[0] / 60, b[1] / 60, b[2], 2)} min literal baseline, "
                         f"{fmt(p[0] / 60, p[1] / 60, p[2], 2)} min proposed")
        out.append(("Abstract: a design takes 3–5 min with the proposed planner, 10–20 min "
                    "without it", "3–5 / 10–20 min", "; ".join(parts),
                    "partly (700 iterations, C++ on this machine vs C# in Unity on a 2.2 GHz i7)",
                    "faster in absolute terms; the ratio is the comparable claim (below)"))
        # Planning share.
        parts, shares = [], []
        for planner in ("literal", "baseline", "paper", "all"):
            s = mean_sd([num(r, "planning_share") for r in by(t, mode="design", planner=planner)])
            if s[2]:
                parts.append(f"{planner}: {fmt(100 * s[0], 100 * s[1], s[2], 1, '%')}")
                shares.append((planner, s[0]))
        base = dict(shares).get("literal", float("nan"))
        out.append(("§VI-A: motion planning is 96.06 % of the total time", "96.06 %",
                    "; ".join(parts), "yes (share of wall time per design, all rooms)",
                    "reproduced for the baselines" if base >= 0.9 else "not reproduced"))
        # 65–70 % reduction, on whole designs and on identical layouts.
        for mode, what in (("design", "whole designs (different layouts per planner)"),
                           ("replay", "identical layouts (replay of the baseline's)")):
            parts, reductions = [], []
            for room in rooms:
                b = mean_sd([num(r, "planning_s") for r in by(t, mode=mode, room=room, planner="literal")])
                p = mean_sd([num(r, "planning_s") for r in by(t, mode=mode, room=room, planner="paper")])
                a = mean_sd([num(r, "planning_s") for r in by(t, mode=mode, room=room, planner="all")])
                if b[2] and p[2]:
                    red = 1 - p[0] / b[0]
                    reductions.append(red)
                    parts.append(f"{room}: −{100 * red:.0f} % (paper's set; {b[0] / p[0]:.1f}×), "
                                 f"all: {b[0] / a[0]:.1f}×")
            ok = reductions and min(reductions) >= 0.65
            out.append((f"§VI-A: the proposed planner cuts planning time by 65–70 % — {what}",
                        "−65 to −70 %", "; ".join(parts),
                        "yes" if mode == "design" else "ours is stricter (same planning problems)",
                        "reproduced (at least as large)" if ok else "not reproduced in every room"))
    rsd = read_csv(os.path.join(root, "rs_decomposition", "runs.csv"))
    if rsd:
        rep = by(rsd, kind="replay")
        parts, reds, dl = [], [], []
        for room in rooms_of(rep):
            b = mean_sd([num(r, "planning_s") for r in by(rep, room=room, planner="baseline")])
            s = mean_sd([num(r, "planning_s") for r in by(rep, room=room, planner="samples_steering")])
            lb = mean_sd([num(r, "mean_tour_m") for r in by(rep, room=room, planner="baseline")])
            ls = mean_sd([num(r, "mean_tour_m") for r in by(rep, room=room, planner="samples_steering")])
            if b[2] and s[2]:
                reds.append(1 - s[0] / b[0])
                dl.append(ls[0] / lb[0] - 1)
                parts.append(f"{room}: {-100 * (1 - s[0] / b[0]):+.0f} % time, tour length "
                             f"{100 * (ls[0] / lb[0] - 1):+.1f} %")
        if parts:
            ok = min(reds) >= 0.3 and max(abs(x) for x in dl) < 0.05
            out.append(("§V-A: samples and steering from the RS-decomposition cut planning time by "
                        "about 40 % without noticeable differences in the paths", "−40 %, same paths",
                        "; ".join(parts), "yes, on identical layouts",
                        "reproduced" if ok else "not reproduced (see docs/planner.md)"))
        reg = by(rsd, kind="regions")
        if reg:
            parts = [f"r = {num(r, 'radius_m'):.2f} m: {r['regions']} words, "
                     f"{r['samples']} samples, word accuracy {100 * num(r, 'word_accuracy'):.1f} %"
                     for r in reg]
            three = [r for r in reg if r["radius"] == "3"]
            n3 = int(num(three[0], "regions")) if three else -1
            out.append(("Fig. \"partition\": 48 regions at r = 3 m", "48",
                        "; ".join(parts), "yes (room twice the first room's size, K = 1000, "
                        "stop after 100 agreeing samples)",
                        "reproduced" if n3 == 48 else
                        f"differs: {n3} of the 48 words are shortest somewhere in the sampled box"))
    rrt = read_csv(os.path.join(root, "rrt_iterations", "runs.csv"))
    if rrt:
        h = by(rrt, kind="histogram")
        s = mean_sd([num(r, "share_within_30") for r in h])
        if s[2]:
            out.append(("Fig. \"rrt-it\": the RRT iterations needed to find a path are generally small",
                        "small (the 30-node rule)",
                        f"{fmt(100 * s[0], 100 * s[1], s[2], 1, '%')} of found legs need ≤ 30 iterations",
                        "yes (baseline RRT, every found leg of every design)",
                        "reproduced" if s[0] >= 0.5 else "not reproduced"))
        sw = by(rrt, kind="threshold")
        if sw:
            best = {}
            for room in rooms_of(sw):
                ts = sorted({int(r["tree_max_nodes"]) for r in by(sw, room=room)})
                pt = {tt: mean_sd([num(r, "planning_s") for r in by(sw, room=room, tree_max_nodes=str(tt))])[0]
                      for tt in ts}
                best[room] = (min(pt, key=pt.get), pt)
            parts = [f"{room}: fastest at {b} nodes ("
                     + ", ".join(f"{k}: {v:.2f} s" for k, v in pt.items()) + ")"
                     for room, (b, pt) in best.items()]
            out.append(("§V-C: rebuild a reused tree past 30 nodes", "30", "; ".join(parts),
                        "yes (paper's techniques, planning time per design)",
                        "reproduced" if all(b == 30 for b, _ in best.values()) else
                        "the best threshold differs by room; see rrt_threshold.svg"))
    sm = read_csv(os.path.join(root, "small_room", "runs.csv"))
    if sm:
        rooms = rooms_of(sm)
        if len(rooms) >= 2:
            big, small = rooms[0], rooms[1]
            parts, ratios = [], []
            for planner in ("baseline", "all"):
                b = mean_sd([num(r, "planning_s") for r in by(sm, room=big, planner=planner)])
                s = mean_sd([num(r, "planning_s") for r in by(sm, room=small, planner=planner)])
                fb = mean_sd([num(r, "tours_found") for r in by(sm, room=big, planner=planner)])
                fs = mean_sd([num(r, "tours_found") for r in by(sm, room=small, planner=planner)])
                if b[2] and s[2]:
                    ratios.append(s[0] / b[0])
                    parts.append(f"{planner}: {100 * (s[0] / b[0] - 1):+.0f} % "
                                 f"(tours found {fs[0]:.1f} vs {fb[0]:.1f})")
            out.append(("§VI-B: planning takes 30 % longer in the small bedroom", "+30 %",
                        "; ".join(parts), "yes",
                        "reproduced (longer)" if ratios and min(ratios) > 1 else
                        "not reproduced: see the tours found (a blocked small room is cheap to "
                        "give up on)"))
    ao = read_csv(os.path.join(root, "ao_graph", "runs.csv"))
    if ao:
        parts, verdicts = [], []
        for room in rooms_of(ao):
            rs = [r for r in by(ao, room=room) if r.get("heavier_nearer") not in (None, "")]
            if not rs:
                continue
            k = sum(int(num(r, "heavier_nearer")) for r in rs)
            parts.append(f"{room}: heavier ({rs[0].get('heavier')}) nearer in {k}/{len(rs)} seeds")
            verdicts.append(k / len(rs))
        if parts:
            out.append(("§VI-C: the object with the larger path weight sits nearer the door",
                        "observed in the two designs shown", "; ".join(parts),
                        "yes (distance from the door's start pose to the object's centre)",
                        "reproduced" if min(verdicts) > 0.5 else
                        "not reproduced in most seeds" if max(verdicts) <= 0.5 else "mixed"))
    ds = read_csv(os.path.join(root, "designs", "runs.csv"))
    f1 = [r for r in ds if r.get("figure") == "fig1"]
    if f1:
        w0 = [r for r in f1 if r.get("path_weights") == "0"]
        ws = [r for r in f1 if r.get("path_weights") == "scene"]
        if w0 and ws:
            d0 = os.path.join(root, "designs", "designs", w0[0]["key"])
            unreach = []
            try:
                import json
                with open(os.path.join(d0, "tours.json")) as f:
                    unreach = draw.unreachable_objects(json.load(f)["tours"])
            except OSError:
                pass
            out.append(("Fig. 1: designed without the wheelchair, some object cannot be reached",
                        "an object unreachable",
                        f"path weights 0: {w0[0]['tours_found']}/{w0[0]['tours_total']} tours, "
                        f"unreachable: {', '.join(unreach) or 'none'}; scene weights: "
                        f"{ws[0]['tours_found']}/{ws[0]['tours_total']} tours",
                        "yes (same seed, weights 0 vs the scene's)",
                        "reproduced" if unreach and int(num(ws[0], "tours_found")) >
                        int(num(w0[0], "tours_found")) else "not reproduced"))
    return out


def environment(root):
    for study in ("timing", "designs", "method", "small_room"):
        rows = read_csv(os.path.join(root, study, "runs.csv"))
        if rows:
            r = rows[0]
            return r.get("commit", "?"), r.get("cpu", "?"), r.get("threads", "?")
    return "?", "?", "?"


def write_reproduction(root, path, command):
    rows = claims(root)
    commit, cpu, threads = environment(root)
    lines = [
        "# Reproduction: the paper's claims, measured",
        "",
        "Generated by `paper_figures/plot.py` from the experiments harness's tables; "
        "do not edit by hand.",
        f"Command: `{command}`. Code: commit `{commit}`; machine: {cpu}; "
        f"{threads} tour-planning thread(s) per design.",
        "Paper: *Designing Human-Robot Coexistence Space* (docs/paper.md). "
        "Planners: *literal* is the paper's baseline RRT read literally, *baseline* ours "
        "(tried goal nodes skipped), *paper* the proposed planner with the paper's techniques "
        "(RS-decomposition samples and steering, path database, tree reuse), *all* with every "
        "technique. Values are mean ± sd over seeds (n runs).",
        "",
        "| claim | paper | ours | same experiment? | verdict |",
        "|---|---|---|---|---|",
    ]
    for c in rows:
        lines.append("| " + " | ".join(x.replace("|", "/") for x in c) + " |")
    if not rows:
        lines.append("| (no study outputs found) | | | | |")
    lines.append("")
    with open(path, "w") as f:
        f.write("\n".join(lines))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", help="root directory the harness wrote")
    ap.add_argument("--publish", action="store_true",
                    help="copy figures, summaries and REPRODUCTION.md into paper_figures/")
    ap.add_argument("--command", default="scripts/reproduce.sh",
                    help="the command that made OUT (written into REPRODUCTION.md)")
    a = ap.parse_args()
    if not os.path.isdir(a.out):
        print(f"plot.py: {a.out}: not a directory (run scripts/reproduce.sh first)", file=sys.stderr)
        return 2
    figs = os.path.join(a.out, "figures")
    written = []
    for f in (fig_timing, fig_rs_decomposition, fig_rrt_iterations, fig_small_room, fig_ao_graph,
              fig_designs, fig_method, fig_generalization):
        written += f(a.out, figs)
    rep = os.path.join(a.out, "REPRODUCTION.md")
    rows = write_reproduction(a.out, rep, a.command)
    print(f"plot.py: {len(written)} figure files in {figs}, {len(rows)} claims in {rep}")
    if a.publish:
        here = os.path.dirname(os.path.abspath(__file__))
        for p in written:
            shutil.copy(p, os.path.join(here, "figures", os.path.basename(p))
                        if os.makedirs(os.path.join(here, "figures"), exist_ok=True) is None else p)
        os.makedirs(os.path.join(here, "tables"), exist_ok=True)
        for study in sorted(os.listdir(a.out)):
            s = os.path.join(a.out, study, "summary.csv")
            if os.path.exists(s):
                shutil.copy(s, os.path.join(here, "tables", f"{study}_summary.csv"))
        shutil.copy(rep, os.path.join(here, "REPRODUCTION.md"))
        print(f"plot.py: published into {here}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
