#!/usr/bin/env python3
"""Design sweep: how the tracer twist a3 shapes the curve, at carrier twist a2 = 60 deg.

For n = 2 and n = 5/2, sweep a3 over (0, pi) with the root-count census (classify_a3_range:
Eigen only, no sampling), print the class intervals, and plot the node count against a3 into a
PNG when Matplotlib is installed (Debian python3-matplotlib).

    PYTHONPATH=build/python python3 examples/design_sweep.py [--png data/figures/design_sweep.png] [--count 721]
"""
import argparse
import math

import sphtroch

A2 = "60deg"
RATIOS = ["2", "5/2"]


def sweep(n, count):
    """Class intervals of a3 in [0.01, pi - 0.01] (radians) for a2 = 60 deg and gear ratio n."""
    return sphtroch.classify_a3_range(A2, n, (0.01, math.pi - 0.01), count=count)


def print_intervals(n, runs):
    a_p = math.degrees(sphtroch.GearTrain(A2, "pi/2", n).planet_cone)
    print(f"n = {n}, a2 = {A2}: {len(runs)} interval(s) of a3; cusps on the pitch cones a3 = {a_p:.3f}"
          f" and {180 - a_p:.3f} deg")
    for r in runs:
        lo, hi = math.degrees(r["a3_first"]), math.degrees(r["a3_last"])
        print(f"  a3 {lo:8.3f} .. {hi:8.3f} deg  {r['class']:<16} nodes {r['nodes']:>2}  cusps {r['cusps']}"
              f"  ({r['samples']} samples)")


def plot(results, path):
    """Node counts against a3 (a step per interval), one line per n; the pitch cones dashed."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not installed (apt-get install python3-matplotlib): no picture")
        return
    fig, ax = plt.subplots(figsize=(7, 3.6))
    for n, runs in results.items():
        xs, ys = [], []
        for r in runs:
            xs += [math.degrees(r["a3_first"]), math.degrees(r["a3_last"])]
            ys += [r["nodes"], r["nodes"]]
        ax.plot(xs, ys, drawstyle="steps-post", label=f"n = {n}")
        # Cusps only exactly on the pitch cones a3 = a_p, pi - a_p (no sample hits them): dashed.
        a_p = math.degrees(sphtroch.GearTrain(A2, "pi/2", n).planet_cone)
        for x in (a_p, 180 - a_p):
            ax.axvline(x, color=ax.lines[-1].get_color(), linestyle="--", linewidth=0.8)
    ax.set_xlabel("tracer twist a3 (deg)")
    ax.set_ylabel("nodes")
    ax.set_title("Nodes of the trajectory against a3, a2 = 60 deg (root-count census)")
    ax.set_xlim(0, 180)
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    print(f"wrote {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--png", default="design_sweep.png", help="picture to write (default design_sweep.png)")
    parser.add_argument("--count", type=int, default=721, help="a3 samples per sweep (default 721)")
    args = parser.parse_args()
    results = {n: sweep(n, args.count) for n in RATIOS}
    for n, runs in results.items():
        print_intervals(n, runs)
    plot(results, args.png)


if __name__ == "__main__":
    main()
