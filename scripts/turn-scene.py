#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes a scene as drawn on a plan turned by DEGREES about the origin.

usage: scripts/turn-scene.py SCENE DEGREES OUT

The room (a `size` becomes its polygon), the door's centre and start pose,
and every object's pose are turned; sizes, footprints, preferences, the AO
graph and the weights stay as they were. A design of the turned scene
answers whether the search depends on walls lying on the axes
(docs/BENCHMARKS.md, 2026-11-30, "plans drawn at an angle").
"""
import json
import math
import os
import sys


def main(argv):
    if len(argv) == 2 and argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0
    if len(argv) != 4:
        print("usage: scripts/turn-scene.py SCENE DEGREES OUT (see --help)", file=sys.stderr)
        return 2
    src, out = argv[1], argv[3]
    try:
        angle = math.radians(float(argv[2]))
    except ValueError:
        print(f"turn-scene: DEGREES: not a number: '{argv[2]}'", file=sys.stderr)
        return 2
    try:
        with open(src) as f:
            scene = json.load(f)
    except (OSError, json.JSONDecodeError) as e:
        print(f"turn-scene: {src}: {e}", file=sys.stderr)
        return 2
    try:
        turn_scene(scene, angle, argv[2])
    except (KeyError, TypeError, IndexError, ValueError) as e:
        print(f"turn-scene: {src}: not a scene this script can turn ({type(e).__name__}: {e}); "
              f"see `hrspace validate {src}`", file=sys.stderr)
        return 2
    # Written beside OUT, then renamed over it: OUT is whole or as it was.
    tmp = f"{out}.tmp{os.getpid()}"
    try:
        with open(tmp, "w") as f:
            json.dump(scene, f, indent=1)
        os.replace(tmp, out)
    except OSError as e:
        print(f"turn-scene: {out}: {e}", file=sys.stderr)
        if os.path.exists(tmp):
            os.remove(tmp)
        return 1
    return 0


def turn_scene(scene, angle, degrees):
    """Turns `scene` in place by `angle` radians; `degrees` names it."""
    c, s = math.cos(angle), math.sin(angle)

    def turn(p):
        return [round(c * p[0] - s * p[1], 9), round(s * p[0] + c * p[1], 9)]

    room = scene["room"]
    if "size" in room:
        w, h = room.pop("size")
        room["polygon"] = [[0, 0], [w, 0], [w, h], [0, h]]
    room["polygon"] = [turn(p) for p in room["polygon"]]
    door = scene["door"]
    door["center"] = turn(door["center"])
    if "start" in door:
        door["start"] = turn(door["start"][:2]) + [door["start"][2] + angle]
    for o in scene["objects"]:
        o["pose"] = turn(o["pose"][:2]) + [o["pose"][2] + angle]
    scene["name"] = scene.get("name", "") + f"_turned{degrees}"


if __name__ == "__main__":
    sys.exit(main(sys.argv))
