#!/usr/bin/env python3
"""The tool's start-up against another build of it (A/B, whole processes): calls that do little
work, so that loading the executable and its shared libraries is what is timed: `--version`,
`trace` of 10 samples, `classify` of the report's Fig. 5(f), `chain trace` of 10 samples. The two
builds run in turn (A B A B ..., REPS pairs after a warm-up pair); each process is timed by the
parent (time.perf_counter around spawn and os.wait4), os.wait4's rusage gives its cpu time, and a
second run under /usr/bin/time its peak RSS. Per command: the medians of A's and B's wall time (ms), cpu time (ms) and peak RSS (MiB),
and the median of the pair-by-pair wall ratios A/B. Writes data/bench/i_startup_ab.csv.

  BASELINE=/tmp/old/build/bin/sphtroch python3 bench/startup_ab.py     # A = build/bin/sphtroch

Environment: BASELINE (B, required), A (default build/bin/sphtroch), REPS (default 21), OUT
(default data/bench/i_startup_ab.csv). Exit 2: bad arguments.
"""
import datetime
import os
import pathlib
import socket
import statistics
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
CASES = [("version", ["--version"]), ("trace", ["trace", "--a2", "1", "--a3", "2", "--n", "2", "--samples", "10"]),
         ("classify", ["classify", "--a2", "pi/3", "--a3", "pi/2", "--n", "2"]),
         ("chain_trace", ["chain", "trace", "--twists", "1,2,0.5", "--rates", "1,2,-1", "--samples", "10"])]


def one(exe, args):
    """(wall ms, cpu ms, peak RSS MiB) of one run: wall and cpu time of the process itself, its
    peak RSS from a second run under /usr/bin/time (a child's own rusage counts the parent's pages
    it was forked with)."""
    start = time.perf_counter()
    p = subprocess.Popen([exe, *args], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(p.pid, 0)
    wall = (time.perf_counter() - start) * 1e3
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"bench/startup_ab.py: {exe} {' '.join(args)} failed")
    timed = subprocess.run(["/usr/bin/time", "-f", "%M", exe, *args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    return wall, (usage.ru_utime + usage.ru_stime) * 1e3, int(timed.stderr.strip().splitlines()[-1]) / 1024


def main():
    a = os.path.realpath(os.environ.get("A", ROOT / "build" / "bin" / "sphtroch"))
    b = os.environ.get("BASELINE", "")
    reps = int(os.environ.get("REPS", "21"))
    out = pathlib.Path(os.environ.get("OUT", ROOT / "data" / "bench" / "i_startup_ab.csv"))
    for name, exe in (("A", a), ("BASELINE", b)):
        if not exe or not os.access(exe, os.X_OK):
            print(f"bench/startup_ab.py: {name} must name a sphtroch executable", file=sys.stderr)
            sys.exit(2)
    b = os.path.realpath(b)
    load_before = open("/proc/loadavg").read().split()[:3]
    rows = ["case,command,a_wall_ms,b_wall_ms,wall_ratio,a_cpu_ms,b_cpu_ms,a_rss_mib,b_rss_mib,pairs"]
    for name, args in CASES:
        runs = {"a": [], "b": []}
        for i in range(reps + 1):
            ra, rb = one(a, args), one(b, args)
            if i > 0:
                runs["a"].append(ra)
                runs["b"].append(rb)
        med = lambda who, k: statistics.median(r[k] for r in runs[who])
        ratio = statistics.median(x[0] / y[0] for x, y in zip(runs["a"], runs["b"]))
        rows.append(f'{name},"sphtroch {" ".join(args)}",{med("a", 0):.2f},{med("b", 0):.2f},{ratio:.3f},'
                    f'{med("a", 1):.2f},{med("b", 1):.2f},{med("a", 2):.1f},{med("b", 2):.1f},{reps}')
    version = lambda exe: subprocess.run([exe, "--version"], capture_output=True, text=True).stdout.strip()
    rows.append(f"# A = {a} ({version(a)}); B = {b} ({version(b)})")
    rows.append(f"# {datetime.datetime.utcnow():%Y-%m-%dT%H:%MZ}, {socket.gethostname()}, {os.cpu_count()} cpus, "
                f"load average before {' '.join(load_before)}, after {' '.join(open('/proc/loadavg').read().split()[:3])}")
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text("\n".join(rows) + "\n")
    print("\n".join(rows))
    print(f"bench/startup_ab.py: wrote {out}")


if __name__ == "__main__":
    main()
