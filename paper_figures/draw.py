"""Drawing helpers for the paper figures: a designed room from its
layout.json and tours.json (the files `hrspace design` writes), and small
table utilities over the harness's CSV files."""

import csv
import json
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Polygon as PolygonPatch  # noqa: E402


def read_csv(path):
    """Rows of a CSV file as dicts, [] when the file is missing or empty."""
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def num(row, key, default=float("nan")):
    """A cell as a float, `default` when absent or empty."""
    v = row.get(key, "")
    try:
        return float(v) if v not in ("", None) else default
    except ValueError:
        return default


def save(fig, out_dir, name):
    """Writes NAME.svg and NAME.png into out_dir; returns their paths."""
    os.makedirs(out_dir, exist_ok=True)
    paths = []
    for ext in ("svg", "png"):
        p = os.path.join(out_dir, f"{name}.{ext}")
        # SVG without embedded dates, so a re-run writes the same bytes.
        meta = {"Date": None} if ext == "svg" else {"Software": None}
        fig.savefig(p, dpi=110, bbox_inches="tight", metadata=meta)
        paths.append(p)
    plt.close(fig)
    return paths


def object_outline(obj):
    """World footprint of a scene object (size = [depth, width] centred on
    the pose, or a polygon in the object frame)."""
    x, y, t = obj["pose"]
    if "size" in obj:
        d, w = obj["size"]
        local = [(d / 2, w / 2), (-d / 2, w / 2), (-d / 2, -w / 2), (d / 2, -w / 2)]
    else:
        local = [tuple(p) for p in obj["polygon"]]
    c, s = math.cos(t), math.sin(t)
    return [(x + c * px - s * py, y + s * px + c * py) for px, py in local]


def unreachable_objects(tours):
    """Objects of the sequences that no found tour reaches."""
    wanted, reached = set(), set()
    for t in tours:
        wanted.update(t["sequence"][1:])
        if t["found"]:
            reached.update(t["sequence"][1:])
    return sorted(wanted - reached)


def chair_outline(pose, length, width):
    """World corners of the chair's length x width rectangle centred on `pose`."""
    x, y, t = pose
    c, s = math.cos(t), math.sin(t)
    local = [(length / 2, width / 2), (-length / 2, width / 2), (-length / 2, -width / 2),
             (length / 2, -width / 2)]
    return [(x + c * px - s * py, y + s * px + c * py) for px, py in local]


def front_edge(obj):
    """The object's front (local +x side) as a segment in world coordinates,
    for rectangles; for polygons the extent of the footprint along +x."""
    x, y, t = obj["pose"]
    if "size" in obj:
        d, w = obj["size"]
        ends = [(d / 2, w / 2), (d / 2, -w / 2)]
    else:
        pts = obj["polygon"]
        xmax = max(p[0] for p in pts)
        ys = [p[1] for p in pts if abs(p[0] - xmax) < 1e-9] or [0.0]
        ends = [(xmax, min(ys)), (xmax, max(ys))] if len(ys) > 1 else [(xmax, -0.1), (xmax, 0.1)]
    c, s = math.cos(t), math.sin(t)
    return [(x + c * px - s * py, y + s * px + c * py) for px, py in ends]


def draw_design(ax, design_dir, title=None, all_tours=False, mark_unreachable=True,
                footprints=True, every=0.35):
    """Draws a design directory as the paper draws its designs: room, door,
    objects with their fronts marked (thick dark edge), unreachable stops
    flagged, the most likely found tour (bold) with the wheelchair's
    footprint every `every` metres along it, and with all_tours the other
    found tours (faint)."""
    with open(os.path.join(design_dir, "layout.json")) as f:
        scene = json.load(f)
    tours = []
    tours_path = os.path.join(design_dir, "tours.json")
    if os.path.exists(tours_path):
        with open(tours_path) as f:
            tours = json.load(f)["tours"]
    room = scene["room"].get("polygon")
    if room is None:
        w, d = scene["room"]["size"]
        room = [[0, 0], [w, 0], [w, d], [0, d]]
    ax.add_patch(PolygonPatch(room, closed=True, fill=False, lw=2, ec="black"))
    # Door: a gap marker on the wall at its centre.
    door = scene["door"]
    cx, cy = door["center"]
    ax.plot([cx], [cy], marker="s", ms=6, color="tab:green")
    bad = set(unreachable_objects(tours)) if mark_unreachable else set()
    for obj in scene["objects"]:
        pts = object_outline(obj)
        hit = obj["id"] in bad
        ax.add_patch(
            PolygonPatch(
                pts,
                closed=True,
                fc="#f4cccc" if hit else ("#dddddd" if obj.get("fixed") else "#cfe2f3"),
                ec="red" if hit else "#444444",
                lw=1.8 if hit else 0.8,
                ls="--" if hit else "-",
            )
        )
        (fx0, fy0), (fx1, fy1) = front_edge(obj)
        ax.plot([fx0, fx1], [fy0, fy1], color="#1f3b57", lw=2.2, solid_capstyle="butt")
        x, y, _ = obj["pose"]
        label = obj["id"] + (" (unreachable)" if hit else "")
        ax.text(x, y, label, ha="center", va="center", fontsize=6)
    found = [t for t in tours if t["found"]]
    if all_tours:
        for t in found[1:]:
            for leg in t["legs"]:
                wp = leg["waypoints"]
                ax.plot([p[0] for p in wp], [p[1] for p in wp], color="tab:red", lw=0.5, alpha=0.25)
    if tours and tours[0]["found"]:
        chair = scene["wheelchair"]
        along, last = 0.0, None
        for leg in tours[0]["legs"]:
            wp = leg["waypoints"]
            ax.plot([p[0] for p in wp], [p[1] for p in wp], color="tab:red", lw=1.6)
            if not footprints:
                continue
            for p in wp:
                if last is not None:
                    along += math.hypot(p[0] - last[0], p[1] - last[1])
                if last is None or along >= every:
                    ax.add_patch(PolygonPatch(chair_outline(p, chair["length"], chair["width"]),
                                              closed=True, fill=False, ec="tab:red", lw=0.4,
                                              alpha=0.55))
                    along = 0.0
                last = p
    xs = [p[0] for p in room]
    ys = [p[1] for p in room]
    ax.set_xlim(min(xs) - 0.2, max(xs) + 0.2)
    ax.set_ylim(min(ys) - 0.2, max(ys) + 0.2)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    if title:
        ax.set_title(title, fontsize=8)
    return scene, tours
