#!/usr/bin/env python3
"""Times `sphtroch tolerance` on random trains (|p|, q <= 7, both signs; a2, a3 in [0.1, 3.04]),
tolerance +-1e-3 rad on a2, a3 and the phase, one process per train (what a user waits for:
classify, the certified margin, the box topology, every node's enclosure).

    python3 bench/tolerance_sweep.py build/bin/sphtroch [N]    # N trains, default 100, seeded

Prints the median, the 90th percentile and the slowest, in milliseconds (wall clock around each
process, time.perf_counter), and how many runs ended with each exit status."""
import collections
import random
import statistics
import subprocess
import sys
import time


def main() -> None:
    exe = sys.argv[1]
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 100
    rng = random.Random(2026)
    times, statuses = [], collections.Counter()
    for _ in range(count):
        p, q = rng.randint(1, 7) * rng.choice([1, -1]), rng.randint(1, 7)
        a2, a3 = rng.uniform(0.1, 3.04), rng.uniform(0.1, 3.04)
        args = [exe, "tolerance", "--a2", repr(a2), "--a3", repr(a3), "--n", f"{p}/{q}",
                "--tol-a2", "1e-3", "--tol-a3", "1e-3", "--tol-phase", "1e-3", "--json"]
        start = time.perf_counter()
        status = subprocess.run(args, capture_output=True).returncode
        times.append(time.perf_counter() - start)
        statuses[status] += 1
    times.sort()
    print(f"{count} trains: median {statistics.median(times) * 1e3:.1f} ms, "
          f"90th percentile {times[int(0.9 * count)] * 1e3:.1f} ms, slowest {times[-1] * 1e3:.1f} ms; "
          f"exit statuses {dict(sorted(statuses.items()))}")


if __name__ == "__main__":
    main()
