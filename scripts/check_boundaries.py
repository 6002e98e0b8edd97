#!/usr/bin/env python3
"""`sphtroch boundaries` against `sphtroch classify`, over random a2 (a sweep beyond the tests):
for every event, classify at a3 -+ 1e-7 (--literal: the doubles as given) must count the node
points and cusps the event states below and above, with both censuses agreeing; classify AT
every tangency value (default reading) must report tangencies with both censuses agreeing.

  python3 scripts/check_boundaries.py build/bin/sphtroch [SEED] [RATIO,RATIO,...]

Prints every mismatch and "checked N, bad K"; exits 1 when K > 0."""
import json, subprocess, sys, math, random
exe = sys.argv[1]  # the tool, e.g. build/bin/sphtroch
def run(args):
    r = subprocess.run([exe] + args, capture_output=True, text=True)
    if r.returncode != 0:
        return None, r.stderr.strip()
    return json.loads(r.stdout), None
random.seed(int(sys.argv[2]) if len(sys.argv) > 2 else 1)
ratios = sys.argv[3].split(",") if len(sys.argv) > 3 else ["5/2", "-5/2", "7/3", "3/2", "-3", "5", "4/3", "-7/5", "6/7", "2/3", "-1/2", "7/2"]
bad = 0; checked = 0
for n in ratios:
    for a2 in [round(random.uniform(0.15, 3.0), 6) for _ in range(2)]:
        b, err = run(["boundaries", "--n", n, "--a2", repr(a2), "--json"])
        if b is None:
            print("boundaries failed", n, a2, err); bad += 1; continue
        for e in b["events"]:
            a3 = e["a3"]
            for side, d in (("below", -1e-7), ("above", 1e-7)):
                x = a3 + d
                if not (0 < x < math.pi): continue
                c, err = run(["classify", "--n", n, "--a2", repr(a2), "--a3", repr(x), "--literal", "--json"])
                checked += 1
                if c is None:
                    print("classify failed", n, a2, x, err); bad += 1; continue
                got = (c["counts"]["nodes"], c["counts"]["cusps"])
                exp = (e["nodes_" + side], e["cusps_" + side])
                if got != exp or not c["agreement"]["ok"]:
                    bad += 1
                    print(f"MISMATCH n={n} a2={a2} {e['kind']} a3={a3} {side}: boundaries {exp} classify {got} agree={c['agreement']['ok']}")
            if e["kind"] == "tangency":
                c, err = run(["classify", "--n", n, "--a2", repr(a2), "--a3", repr(a3), "--json"])
                checked += 1
                if c is None or not c["agreement"]["ok"] or c["counts"]["tangencies"] == 0:
                    bad += 1
                    print(f"AT-TANGENCY n={n} a2={a2} a3={a3}: {err or (c['counts'], c['agreement'])}")
print(f"checked {checked}, bad {bad}")
sys.exit(1 if bad else 0)
