#!/usr/bin/env python3
"""The Python side of the bindings benchmark (docs/BENCHMARKS.md, "Python
bindings"): hrspace.CSpace.is_free on 10^6 poses in one call, against the
same loop in C++ (bench/batch_bench.cpp, BM_IsFreeMillion).

Poses: uniform over the bedroom's bounding box, heading uniform in
[-pi, pi), one (N, 3) float64 array. Prints the best and median of
--repeats calls, and with --cpp BINARY runs the C++ benchmark too and prints
the ratio. Run from the repository root:

    PYTHONPATH=build/python /usr/bin/python3 bench/python_is_free.py --cpp build/bench/batch_bench
"""

import argparse
import json
import pathlib
import statistics
import subprocess
import time

import numpy as np

import hrspace

ROOT = pathlib.Path(__file__).resolve().parents[1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--poses", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--cpp", help="path of build/bench/batch_bench, to print the ratio")
    args = parser.parse_args()

    scene = hrspace.Scene(ROOT / "scenes" / "bedroom.json")
    cspace = hrspace.CSpace(scene)
    rng = np.random.default_rng(1)
    lo, hi = scene.room.min(axis=0), scene.room.max(axis=0)
    poses = np.column_stack([rng.uniform(lo[0], hi[0], args.poses), rng.uniform(lo[1], hi[1], args.poses),
                             rng.uniform(-np.pi, np.pi, args.poses)])
    cspace.is_free(poses[:1000])  # warm up
    times = []
    for _ in range(args.repeats):
        t0 = time.perf_counter()
        free = cspace.is_free(poses)
        times.append(time.perf_counter() - t0)
    best, median = min(times), statistics.median(times)
    print(f"python is_free: {args.poses} poses, best {best * 1e3:.1f} ms, median {median * 1e3:.1f} ms "
          f"({best / args.poses * 1e9:.1f} ns/pose), free fraction {free.mean():.4f}")
    if args.cpp:
        out = subprocess.run([args.cpp, "--benchmark_repetitions=%d" % args.repeats, "--benchmark_format=json"],
                             capture_output=True, text=True, check=True).stdout
        runs = [b for b in json.loads(out)["benchmarks"] if b.get("run_type") == "iteration"]
        cpp = [b["real_time"] / 1e3 for b in runs]  # milliseconds -> seconds
        cpp_best, cpp_median = min(cpp), statistics.median(cpp)
        print(f"c++ loop:       {args.poses} poses, best {cpp_best * 1e3:.1f} ms, median {cpp_median * 1e3:.1f} ms")
        print(f"ratio python / c++: best {best / cpp_best:.3f}, median {median / cpp_median:.3f}")


if __name__ == "__main__":
    main()
