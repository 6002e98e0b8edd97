"""The stub's TypedDicts (read with ast from __init__.pyi, independently of the module) have
exactly the keys the calls return at runtime: required keys always present, NotRequired ones
allowed, no other key."""
import numpy as np
import pytest

import sphtroch
from stub_info import typed_dicts

TD = typed_dicts()


def check(value, name):
    """value (a dict) against TypedDict `name`, recursing into fields typed by another TypedDict
    (also List[T] and Optional[T] of one)."""
    fields = TD[name]
    required = {k for k, t in fields.items() if not t.startswith("NotRequired[")}
    assert required <= set(value) <= set(fields), (name, set(value) ^ set(fields))
    for key, ann in fields.items():
        if key not in value or value[key] is None:
            assert key not in value or ann.startswith("Optional["), (name, key)
            continue
        inner = ann.removeprefix("NotRequired[").removeprefix("Optional[").removeprefix("List[").rstrip("]")
        if inner in TD:
            for v in value[key] if ann.startswith("List[") or "[List[" in ann else [value[key]]:
                check(v, inner)


TRAINS = [sphtroch.GearTrain("pi/3", "pi/2", 2), sphtroch.GearTrain(1.0, "ap", "5/2", phase=0.3),
          sphtroch.GearTrain("pi/3", 1.2, teeth="39:15"), sphtroch.GearTrain(2.0, 0.7, -3)]


def test_the_stub_declares_the_result_types():
    assert {"Classification", "Node", "Cusp", "Margin", "Tolerance", "PointsResult", "FitResult", "Identified",
            "WorstWindowMean", "TimeToEpsilon", "CoverageSummary", "ClinostatTrainMap"} <= set(TD)
    assert "class" in TD["Classification"] and TD["Counts"] == {"nodes": "int", "crossings": "int", "tangencies": "int",
                                                                "cusps": "int"}


@pytest.mark.parametrize("train", TRAINS, ids=repr)
def test_classify_nodes_cusps_and_margin_have_the_declared_keys(train):
    rep = train.classify()
    check(rep, "Classification")
    assert ("teeth" in rep["inputs"]) == (train.teeth is not None)
    for node in train.nodes():
        check(node, "Node")
    for cusp in train.cusps():
        check(cusp, "Cusp")
    check(train.margin(), "Margin")


def test_tolerance_has_the_declared_keys_with_and_without_monte_carlo():
    tr = TRAINS[0]
    check(tr.tolerance(da2=0.01, da3=0.01), "Tolerance")
    rep = tr.tolerance(da2=0.01, da3=0.01, samples=3)
    check(rep, "Tolerance")
    assert rep["monte_carlo"] is not None and rep["nodes"]


def test_synthesis_results_have_the_declared_keys():
    tr = sphtroch.GearTrain(1.0, 2.0, "1/2", phase=0.3)
    t, P = tr.trace(samples=400)
    check(sphtroch.identify(t, P), "Identified")
    pts = sphtroch.synth_points(P[[7, 111, 290]], teeth="12:24")
    check(pts, "PointsResult")
    assert pts["solutions"] and "teeth" in pts["solutions"][0]
    fit = sphtroch.fit(P[::10], n="1/2", candidates=2)
    check(fit, "FitResult")
    assert fit["candidates"]
    at = sphtroch.fit(P[::10], n="1/2", candidates=1, node_at=np.array(tr.nodes()[0]["position"]) if tr.nodes() else None)
    check(at, "FitResult")


def test_clinostat_results_have_the_declared_keys():
    for c in (sphtroch.Clinostat(1.33, 2), sphtroch.Clinostat("4/3", -2, tilt=60, offset=(0.05, 0, 0))):
        check(c.worst_window_mean(600), "WorstWindowMean")
        check(c.time_to(0.05, 10), "TimeToEpsilon")
        check(c.coverage_summary(600, 4), "CoverageSummary")
        check(c.train_map, "ClinostatTrainMap")
        check(c.report(), "ClinostatReport")
        check(c.report(window=600, epsilon=0.05, resolution=10, coverage=600, nside=4), "ClinostatReport")
        check(c.report(window=600, band=True, target_g=0.1, tolerance=0.05), "ClinostatReport")
    far = sphtroch.Clinostat(3, 0, tilt=80).time_to(0.01)  # the mean over a period is above: no window
    check(far, "TimeToEpsilon")
    assert far["first_s"] is None and far["reason"]
