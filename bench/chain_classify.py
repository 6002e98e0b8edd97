#!/usr/bin/env python3
"""Times `sphtroch chain classify` on random k = 3 chains whose rates have height <= 5 (|p|, q <= 5;
twists in (0.05, 3.09), phases in (-3, 3); seed 5), one whole process each: prints the median and
the largest wall time, and any chain that is not certified. A benchmark, not a test.

    /usr/bin/python3 bench/chain_classify.py build/bin/sphtroch [COUNT]
"""
import json
import random
import subprocess
import sys
import time


def rate(rng):
    while True:
        p, q = rng.randint(-5, 5), rng.randint(1, 5)
        if p:
            return f"{p}/{q}"


def main():
    exe = sys.argv[1]
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 150
    rng = random.Random(5)
    times, worst = [], None
    for _ in range(count):
        twists = ",".join(f"{rng.uniform(0.05, 3.09):.6f}" for _ in range(3))
        rates = ",".join(rate(rng) for _ in range(3))
        phases = ",".join(f"{rng.uniform(-3, 3):.6f}" for _ in range(3))
        args = [exe, "chain", "classify", "--twists", twists, "--rates", rates, "--phases", phases, "--json"]
        start = time.perf_counter()
        r = subprocess.run(args, capture_output=True, text=True)
        seconds = time.perf_counter() - start
        times.append(seconds)
        if r.returncode != 0:
            print("exit", r.returncode, " ".join(args[2:]), r.stderr.strip())
        if worst is None or seconds > worst[0]:
            worst = (seconds, " ".join(args[2:]), json.loads(r.stdout)["counts"] if r.stdout else None)
    times.sort()
    print(f"{count} chains: median {times[len(times) // 2]:.3f} s, max {times[-1]:.3f} s")
    print(f"slowest: {worst[1]} -> {worst[2]}")


if __name__ == "__main__":
    main()
