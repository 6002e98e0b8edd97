#!/usr/bin/env python3
"""bench/python_speed.py — the Python module against the C++ library for the same calls (a
benchmark, not a test): trace(samples=10**6) vs sample_period(curve, 10**6), and crossings() on
that 1e6-vertex trace vs find_self_crossings. Medians of --reps runs, in-process on both sides
(bench/python_speed_cpp.cpp times the C++ calls), in --rounds alternating rounds. Targets (issue 12): ratios <= 1.5 and <= 1.2.

    cmake --build build -j2 --target sphtroch_python sphtroch_python_speed_cpp
    PYTHONPATH=build/python /usr/bin/python3 bench/python_speed.py [--build build] [--reps 15] [--rounds 5]
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time

import numpy as np
import sphtroch

TRAIN = ("pi/3", "pi/2", "7/3")  # a2, a3, n: 63 nodes (63 polyline crossings at 1e6 samples)


def median_seconds(reps, call):
    times = []
    for _ in range(reps):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def cpp(build, *args):
    exe = os.path.join(build, "bin", "sphtroch_python_speed_cpp")
    out = subprocess.run([exe, *map(str, args)], capture_output=True, check=True, text=True).stdout
    return json.loads(out)["median_seconds"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="the build directory (default build)")
    parser.add_argument("--reps", type=int, default=15, help="runs per measurement (default 15)")
    parser.add_argument("--rounds", type=int, default=5, help="alternating rounds of both sides (default 5)")
    parser.add_argument("--samples", type=int, default=10**6, help="trace samples / polyline vertices (default 1e6)")
    args = parser.parse_args()

    tr = sphtroch.GearTrain(*TRAIN)
    _, points = tr.trace(samples=args.samples)
    rounds = {"py_trace": [], "cpp_trace": [], "py_cross": [], "cpp_cross": []}
    load = os.getloadavg()
    with tempfile.NamedTemporaryFile(suffix=".f64") as f:
        np.ascontiguousarray(points).tofile(f.name)
        for _ in range(args.rounds):  # alternate the sides, so that a change of machine load hits both
            rounds["py_trace"].append(median_seconds(args.reps, lambda: tr.trace(samples=args.samples)))
            rounds["cpp_trace"].append(cpp(args.build, "trace", *TRAIN, args.samples, args.reps))
            rounds["py_cross"].append(median_seconds(args.reps, lambda: sphtroch.crossings(points)))
            rounds["cpp_cross"].append(cpp(args.build, "crossings", f.name, 1, args.reps))
    py_trace, cpp_trace, py_cross, cpp_cross = (statistics.median(rounds[k]) for k in rounds)

    print(f"train a2={TRAIN[0]} a3={TRAIN[1]} n={TRAIN[2]}, {args.samples} samples, median over {args.rounds} rounds"
          f" of the median of {args.reps} runs; load average before: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    print(f"{'call':<34}{'python s':>10}{'c++ s':>10}{'ratio':>8}{'target':>8}")
    for name, p, c, target in [(f"trace(samples={args.samples})", py_trace, cpp_trace, 1.5),
                               (f"crossings({args.samples} x 3)", py_cross, cpp_cross, 1.2)]:
        print(f"{name:<34}{p:>10.4f}{c:>10.4f}{p / c:>8.2f}{target:>8.1f}")


if __name__ == "__main__":
    main()
