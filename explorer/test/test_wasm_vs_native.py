"""The explorer's WebAssembly module against the native library (the Python module) on 1,000
random trains (|p|, q <= 7, both signs, random a2, a3, phase): the same root-census counts and
class, the same certificate as `sphtroch classify` (GearTrain.classify(): certified or not, the
node count) on every tenth train and report Fig. 3 (on a pole boundary), node points within 1e-12, the same boundary events at each a2 (kinds, counts, a3 within
1e-12), the same refusals, and trace points within the issue's 4e-16 (measured: 0, the same
bits), their velocities dP/dtheta2 within 4e-16 (1 + |n|) (|omega| <= 1 + |n|; measured: 0). The module's libm is musl, whose sin and cos differ from glibc's by an ulp on ~3% of
arguments (and one ulp in sin theta2 moved a coordinate by 2 ulp, 4.44e-16): the curve takes its
sines from sphtroch/core/portable_trig.hpp, the same bits on both, and TracerCurve::point does
not go through Eigen's vectorised products (SSE2 natively, scalar in the module: their
summation orders differ). Everything before the sines (the parsed texts, the reduced phase) is
equal bit for bit too: a libm-dependent phase reduction gave 5e-15 here and fails this test.

    python3 test_wasm_vs_native.py BUILD_DIR    (BUILD_DIR/web/sphtroch.js, BUILD_DIR/python)
"""
import json
import math
import random
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

build = Path(sys.argv[1]).resolve()
sys.path.insert(0, str(build / "python"))
import numpy as np  # noqa: E402
import sphtroch  # noqa: E402

TRAINS = 1000
SAMPLES = 64


def random_trains(rng):
    trains = []
    while len(trains) < TRAINS:
        n = Fraction(rng.randint(1, 7), rng.randint(1, 7)) * rng.choice((1, -1))
        text = lambda v: repr(round(v, 6))
        trains.append({"a2": text(rng.uniform(0.02, math.pi - 0.02)), "a3": text(rng.uniform(0.02, math.pi - 0.02)),
                       "n": str(n), "phase": text(rng.uniform(0, 2 * math.pi)), "samples": SAMPLES})
    trains += [{"a2": "pi/3", "a3": "ap", "n": "2", "phase": "0", "samples": SAMPLES},   # cusps
               {"a2": "7", "a3": "pi/2", "n": "-1", "phase": "0", "samples": SAMPLES},     # refused
               {"a2": "1", "a3": "pi-1", "n": "1", "phase": "0", "samples": SAMPLES},     # a pole
               {"a2": "pi/2", "a3": "pi/2", "n": "1", "phase": "0", "samples": SAMPLES}]  # report Fig. 3
    for i, t in enumerate(trains):
        t["certify"] = i % 10 == 0 or i >= TRAINS
    return trains


def native(t):
    try:
        train = sphtroch.GearTrain(t["a2"], t["a3"], t["n"], t["phase"])
        roots = train.classify_roots()
        _, points, velocities = train.trace(samples=t["samples"], velocity=True)
        classified = train.classify() if t["certify"] else None
    except sphtroch.InvalidInput as e:
        return {"error": str(e)}
    return {"roots": roots, "points": points, "velocities": velocities, "classified": classified}


def compare_events(t, wasm_events, failures):
    """The ruler's events against sphtroch.boundaries at the train's a2: the same kinds and counts,
    a3 within the events' accuracy (1e-12; the module's long double is quad, the native one x87).
    Returns the largest a3 difference."""
    native = sphtroch.boundaries(t["n"], t["a2"])["events"]
    if len(native) != len(wasm_events):
        failures.append((t, "events", len(native), len(wasm_events)))
        return 0.0
    worst = 0.0
    for e, w in zip(native, wasm_events):
        if (e["kind"], e["nodes_below"], e["nodes_above"]) != (w["kind"], w["below"], w["above"]):
            failures.append((t, "event", e, w))
        worst = max(worst, abs(e["a3"] - w["a3"]))
    return worst


def main():
    rng = random.Random(20261125)
    trains = random_trains(rng)
    run = subprocess.run(["node", str(Path(__file__).with_name("wasm_dump.js")), str(build / "web" / "sphtroch.js")],
                         input=json.dumps(trains), capture_output=True, text=True, check=True)
    wasm = json.loads(run.stdout)
    assert len(wasm) == len(trains)
    failures, worst_point, worst_velocity, worst_node, worst_event, refused, certified = [], 0.0, 0.0, 0.0, 0.0, 0, 0
    for t, w in zip(trains, wasm):
        n = native(t)
        if "error" in n or "error" in w:
            refused += 1
            if ("error" in n) != ("error" in w):
                failures.append((t, "refused by one side only", n.get("error"), w.get("error")))
            continue
        r = n["roots"]
        for key in ("nodes", "crossings", "tangencies", "cusps", "class"):
            if r[key] != w[key]:
                failures.append((t, key, r[key], w[key]))
        if n["classified"] is not None:
            certified += 1
            c = n["classified"]
            if (c["certified"], c["counts"]["nodes"]) != (w["certificate"]["certified"], w["certificate"]["rootNodes"]):
                failures.append((t, "certificate", c["certified"], c["counts"]["nodes"], w["certificate"]))
        if w["events"] is not None:
            worst_event = max(worst_event, compare_events(t, w["events"], failures))
        worst_point = max(worst_point, float(np.max(np.abs(n["points"] - np.array(w["points"]).reshape(-1, 3)))))
        speed_bound = 1 + abs(float(Fraction(t["n"])))  # |omega| <= 1 + |n| (Eq. 47a)
        worst_velocity = max(worst_velocity, float(np.max(np.abs(n["velocities"] - np.array(w["velocities"]).reshape(-1, 3)))) / speed_bound)
        native_nodes = np.array([p["position"] for p in r["node_points"]]).reshape(-1, 3)
        wasm_nodes = np.array(w["nodePositions"]).reshape(-1, 3)
        if len(native_nodes) == len(wasm_nodes) and len(native_nodes):
            gaps = np.min(np.linalg.norm(native_nodes[:, None, :] - wasm_nodes[None, :, :], axis=2), axis=1)
            worst_node = max(worst_node, float(np.max(gaps)))
    print(f"{len(trains)} trains, {refused} refused by both, {certified} certificates compared; largest trace difference {worst_point:.3g}, "
          f"velocity difference / (1 + |n|) {worst_velocity:.3g}, "
          f"largest node-point difference {worst_node:.3g}, largest event a3 difference {worst_event:.3g}")
    for f in failures[:10]:
        print("MISMATCH", f)
    ok = not failures and worst_point <= 4e-16 and worst_velocity <= 4e-16 and worst_event <= 1e-12 and worst_node <= 1e-12 and refused < len(trains) // 2 and certified > TRAINS // 10
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
