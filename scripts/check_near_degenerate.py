#!/usr/bin/env python3
"""Seeded near-degenerate families (issue 17; S2's habit of seeded degenerate fixtures): classify
on inputs next to the cusp cones and the poles, where loops shrink to the distance from the cone.

  python3 scripts/check_near_degenerate.py build/bin/sphtroch [SEED] [COUNT] [MAX_PQ] [JOBS]

Inputs (from SEED): n = p/q with 1 <= |p|, q <= MAX_PQ (default 60), both signs; a2 uniform in
(0.05, pi - 0.05), or pi/2 -+ 1e-12 (one input in eight); a3 one of ap -+ 1e-9, pi-ap -+ 1e-9,
a2 -+ 1e-12, pi-a2 -+ 1e-12 (a tracer next to a cusp cone or through a pole); phase 0 and a
random phase in [-1e6, 1e6]. Checked, per input (expected values are invariants, not outputs):
  1. exit status 0 means `certified: true` and agreement ok; 3 means `certified: false`; any
     other status (a crash, 1, 2 on legal input) is a failure;
  2. every node has at least 2 branches and as many parameters, all in [0, period);
  3. phase invariance (Eq. 8: the phase only rotates the curve): when both phases are certified,
     the node, crossing, tangency and cusp counts are equal;
  4. `sphtroch nodes` CSV = `classify --json`: the same node and cusp positions and branch counts.
Prints every failure and "checked N inputs, certified C, uncertified U, failures F"; exits 1 when
F > 0. An uncertified result is not a failure (it says so, with its own exit status)."""
import csv, io, json, math, random, subprocess, sys
from concurrent.futures import ThreadPoolExecutor

exe = sys.argv[1]
seed = int(sys.argv[2]) if len(sys.argv) > 2 else 17
count = int(sys.argv[3]) if len(sys.argv) > 3 else 40
max_pq = int(sys.argv[4]) if len(sys.argv) > 4 else 60
jobs = int(sys.argv[5]) if len(sys.argv) > 5 else 2
rng = random.Random(seed)
A3_FORMS = ["ap+1e-9", "ap-1e-9", "pi-ap+1e-9", "pi-ap-1e-9", "a2+1e-12", "a2-1e-12", "pi-a2+1e-12", "pi-a2-1e-12"]


def make_input():
    while True:
        p, q = rng.randint(1, max_pq) * rng.choice([-1, 1]), rng.randint(1, max_pq)
        if math.gcd(abs(p), q) == 1:
            break
    a2 = rng.choice(["pi/2-1e-12", "pi/2+1e-12"]) if rng.random() < 0.125 else repr(rng.uniform(0.05, math.pi - 0.05))
    return {"n": f"{p}/{q}", "a2": a2, "a3": rng.choice(A3_FORMS), "phase": repr(rng.uniform(-1e6, 1e6))}


def run(args):
    r = subprocess.run([exe] + args, capture_output=True, text=True)
    return r.returncode, r.stdout, r.stderr.strip()


def train_args(c, phase):
    return ["--n", c["n"], "--a2", c["a2"], "--a3", c["a3"], f"--phase={phase}"]


def check(c):
    """Returns (certified at both phases, list of failures)."""
    fails, results = [], []
    for phase in ("0", c["phase"]):
        rc, out, err = run(["classify", "--json"] + train_args(c, phase))
        if rc not in (0, 3):
            fails.append(f"classify phase {phase}: exit {rc}: {err}")
            continue
        j = json.loads(out)
        if (rc == 0) != (j["certified"] is True) or (rc == 0) != j["agreement"]["ok"]:
            fails.append(f"phase {phase}: exit {rc} but certified={j['certified']} agreement={j['agreement']['ok']}")
        for k, node in enumerate(j["nodes"]):
            ps = node["params"]
            if node["branches"] < 2 or len(ps) != node["branches"] or not all(0 <= t < j["period"] for t in ps):
                fails.append(f"phase {phase}: node {k} has branches {node['branches']}, params {ps}")
        results.append((rc, j))
        if phase == "0":
            fails += compare_nodes_csv(c, j)
    if len(results) == 2 and all(rc == 0 for rc, _ in results):
        a, b = (r[1]["counts"] for r in results)
        if a != b:
            fails.append(f"phase invariance: counts {a} at phase 0, {b} at phase {c['phase']}")
    return len(results) == 2 and all(rc == 0 for rc, _ in results), fails


def compare_nodes_csv(c, j):
    rc, out, err = run(["nodes"] + train_args(c, "0"))
    want_rc = 0 if j["certified"] else 3
    if rc != want_rc:
        return [f"nodes: exit {rc} (classify certified={j['certified']}): {err}"]
    rows = list(csv.DictReader(io.StringIO(out)))
    nodes = [r for r in rows if r["kind"] != "cusp"]
    cusps = [r for r in rows if r["kind"] == "cusp"]
    if len(nodes) != j["counts"]["nodes"] or len(cusps) != j["counts"]["cusps"]:
        return [f"nodes CSV: {len(nodes)} nodes, {len(cusps)} cusps; classify --json {j['counts']}"]
    want = sorted((tuple(n["position"]), n["kind"], n["branches"]) for n in j["nodes"])
    got = sorted(((float(r["x"]), float(r["y"]), float(r["z"])), r["kind"], int(r["branches"])) for r in nodes)
    return [] if want == got else ["nodes CSV positions, kinds or branches differ from classify --json"]


inputs = [make_input() for _ in range(count)]
with ThreadPoolExecutor(max_workers=jobs) as pool:
    outcomes = list(pool.map(check, inputs))
failures = certified = 0
for c, (ok, fails) in zip(inputs, outcomes):
    certified += ok
    for f in fails:
        failures += 1
        print(f"FAIL n={c['n']} a2={c['a2']} a3={c['a3']} phase={c['phase']}: {f}")
    if not ok and not fails:
        print(f"uncertified (exit 3, both counts printed): n={c['n']} a2={c['a2']} a3={c['a3']} phase={c['phase']}")
print(f"checked {count} inputs, certified {certified}, uncertified {count - certified}, failures {failures}")
sys.exit(1 if failures else 0)
