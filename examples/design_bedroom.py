#!/usr/bin/env python3
"""Design the bedroom from Python and plot the result.

Loads scenes/bedroom.json, runs a layout design (progress printed every few
iterations), saves the command's four files and draws two panels with
matplotlib: the annealing cost trace, and the designed layout with the most
likely wheelchair tour.

    PYTHONPATH=build/python /usr/bin/python3 examples/design_bedroom.py --iterations 100 --out out/py_bedroom

Ctrl-C stops the design at the end of its iteration; the best layout so far
is then saved and plotted.
"""

import argparse
import pathlib
import sys

import matplotlib

if "MPLBACKEND" not in __import__("os").environ:
    matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import hrspace  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]


def main(argv=None):
    """Runs the design, saves its files and the plot; returns the exit status."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=str(ROOT / "scenes" / "bedroom.json"))
    parser.add_argument("--iterations", type=int, default=200)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--planner", default="proposed", choices=["baseline", "proposed"])
    parser.add_argument("--out", default="out/py_bedroom")
    args = parser.parse_args(argv)

    scene = hrspace.Scene(args.scene)
    print(f"{scene.name}: {len(scene.objects)} objects, {args.iterations} iterations")

    def progress(step):
        """Prints the best cost every 25 iterations."""
        if step["iteration"] % 25 == 0 or step["iteration"] == step["iterations"]:
            print(f"  iteration {step['iteration']:4d}/{step['iterations']}  best cost {step['best']:.3f}")

    try:
        result = hrspace.design(scene, seed=args.seed, iterations=args.iterations,
                                planner=args.planner, progress=progress)
    except KeyboardInterrupt as stop:
        print("interrupted: keeping the best layout so far")
        result = stop.design

    out = pathlib.Path(args.out)
    result.save(out)
    print(f"cost {result.initial_cost:.3f} -> {result.cost:.3f}; files in {out}")

    fig, (trace_ax, room_ax) = plt.subplots(1, 2, figsize=(11, 4.5))
    trace = result.report["trace"]
    iterations = [t["iteration"] for t in trace]
    trace_ax.plot(iterations, [t["best"] for t in trace], lw=2.5, color="tab:orange", label="best")
    trace_ax.plot(iterations, [t["current"] for t in trace], lw=0.8, color="tab:blue", label="current")
    trace_ax.set(xlabel="iteration", ylabel="cost", title="annealing")
    trace_ax.legend()

    layout = result.layout
    room = np.vstack([layout.room, layout.room[:1]])
    room_ax.plot(room[:, 0], room[:, 1], "k-", lw=2)
    zone = np.vstack([layout.door["clear_zone"], layout.door["clear_zone"][:1]])
    room_ax.fill(zone[:, 0], zone[:, 1], color="0.9")
    for obj in layout.objects:
        outline = obj.world_footprint
        room_ax.fill(outline[:, 0], outline[:, 1], alpha=0.5, color="0.5" if obj.fixed else "tab:blue")
        x, y, _ = obj.pose
        room_ax.annotate(obj.id, (x, y), ha="center", va="center", fontsize=8)
    best = next((t for t in result.tours if t["found"]), None)
    if best is not None:
        points = np.array([w for leg in best["legs"] for w in leg["waypoints"]])
        room_ax.plot(points[:, 0], points[:, 1], "r-", lw=1.5,
                     label=" → ".join(best["sequence"]))
        room_ax.legend(loc="upper right", fontsize=7)
    room_ax.set_aspect("equal")
    room_ax.set_title(f"{layout.name}, seed {args.seed}")
    fig.tight_layout()
    fig.savefig(out / "design.png", dpi=120)
    print(f"plot: {out / 'design.png'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
